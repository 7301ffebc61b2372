# Install proof: `cmake --install` this build into a temporary prefix, then build and run a tiny
# downstream project (tests/consumer/) that finds it with find_package(fairsurf).
add_test(NAME install_consumer
  COMMAND ${CMAKE_COMMAND}
    -DBUILD_DIR=${PROJECT_BINARY_DIR} -DCONFIG=$<CONFIG>
    -DPREFIX=${CMAKE_CURRENT_BINARY_DIR}/consumer/prefix
    -DCONSUMER_SOURCE=${CMAKE_CURRENT_SOURCE_DIR}/consumer
    -DCONSUMER_BUILD=${CMAKE_CURRENT_BINARY_DIR}/consumer/build
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run_consumer.cmake)
set_tests_properties(install_consumer PROPERTIES TIMEOUT 300)
