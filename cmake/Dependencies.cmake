# Every dependency comes from Debian 12's archive (scripts/install-deps.sh); nothing is vendored.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenMP REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(CLI11 2.1 REQUIRED)
find_package(muparser REQUIRED)
find_package(PNG REQUIRED)
find_package(OpenMesh REQUIRED)
find_package(BLAS REQUIRED)
# qhull's reentrant C library: the 3D Delaunay tetrahedralization of a hole's loop (hole_triangulation.h)
find_package(Qhull REQUIRED)

# MUMPS and UMFPACK ship no CMake package in Debian: locate them directly. MUMPS is the MPI build
# with FAIRSURF_MPI, the sequential one otherwise (cmake/Mpi.cmake says why never both).
include(${CMAKE_CURRENT_LIST_DIR}/Mpi.cmake)
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
add_library(fairsurf_mumps INTERFACE)
if(FAIRSURF_MPI)
  target_link_libraries(fairsurf_mumps INTERFACE
    ${DMUMPS_MPI_LIBRARY} ${MUMPS_MPI_COMMON_LIBRARY} ${MUMPS_MPI_PORD_LIBRARY} MPI::MPI_C)
  # The C API from C++ sources: without these, mpi.h pulls in the deprecated C++ bindings' library.
  target_compile_definitions(fairsurf_mumps INTERFACE OMPI_SKIP_MPICXX MPICH_SKIP_MPICXX)
else()
  find_path(MUMPS_SEQ_MPI_INCLUDE_DIR mpi.h PATHS /usr/include/mumps_seq NO_DEFAULT_PATH REQUIRED)
  find_library(DMUMPS_LIBRARY dmumps_seq REQUIRED)
  find_library(MUMPS_COMMON_LIBRARY mumps_common_seq REQUIRED)
  find_library(MUMPS_PORD_LIBRARY pord_seq REQUIRED)
  find_library(MUMPS_MPISEQ_LIBRARY mpiseq_seq REQUIRED)
  target_include_directories(fairsurf_mumps SYSTEM INTERFACE ${MUMPS_SEQ_MPI_INCLUDE_DIR})
  target_link_libraries(fairsurf_mumps INTERFACE
    ${DMUMPS_LIBRARY} ${MUMPS_COMMON_LIBRARY} ${MUMPS_PORD_LIBRARY} ${MUMPS_MPISEQ_LIBRARY})
endif()
find_path(UMFPACK_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(UMFPACK_LIBRARY umfpack REQUIRED)
find_library(AMD_LIBRARY amd REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
find_library(METIS_LIBRARY metis REQUIRED)

# Dependencies used only inside the library's sources: linked privately, never exported.
add_library(fairsurf_private_deps INTERFACE)
target_include_directories(fairsurf_private_deps SYSTEM INTERFACE
  ${MUMPS_INCLUDE_DIR} ${UMFPACK_INCLUDE_DIR})
target_link_libraries(fairsurf_private_deps INTERFACE
  OpenMP::OpenMP_CXX nlohmann_json::nlohmann_json muparser::muparser PNG::PNG OpenMeshCore Qhull::qhull_r
  fairsurf_mumps
  ${UMFPACK_LIBRARY} ${AMD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY} ${METIS_LIBRARY} BLAS::BLAS)
