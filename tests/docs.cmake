# Keeps the documentation's cross-references true: tests/docs/check_references.py fails when a link in
# README.md or docs/ names a missing file or heading, or when a page or a source comment cites a
# section (`NAME.md, "Title"`) that docs/ no longer has. Debian's interpreter, as for the Python tests.
find_program(FAIRSURF_SYSTEM_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(FAIRSURF_SYSTEM_PYTHON3)
  add_test(NAME doc_references
    COMMAND ${FAIRSURF_SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/docs/check_references.py ${PROJECT_SOURCE_DIR})
  set_tests_properties(doc_references PROPERTIES TIMEOUT 60)
else()
  message(STATUS "fairsurf: /usr/bin/python3 not found; the doc_references test is not registered")
endif()
