# The Python bindings (python/, docs/python.md) need pybind11 and NumPy for one interpreter: Debian's
# /usr/bin/python3 by default, since another python3 first on PATH (pyenv, a venv) cannot import
# Debian's python3-numpy. FAIRSURF_PYTHON is ON when both are found for it.
include(CMakeDependentOption)
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The interpreter the Python bindings are for")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy)
if(Python3_FOUND AND Python3_NumPy_FOUND)
  find_package(pybind11 2.10 CONFIG)
endif()
cmake_dependent_option(FAIRSURF_PYTHON "Build the Python bindings (pybind11, NumPy)" ON
  "Python3_NumPy_FOUND;pybind11_FOUND" OFF)
