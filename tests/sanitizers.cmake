# The mesh readers face untrusted bytes: test_io is built a second time, with the io sources compiled
# in directly (not the shared library), under AddressSanitizer and UndefinedBehaviorSanitizer, so
# that any out-of-bounds read, overflow or undefined conversion in a reader fails the suite.
set(FAIRSURF_SANITIZE_FLAGS -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
file(GLOB FAIRSURF_IO_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/io/io*.cpp)
# Only the support file test_io uses: the rest of the support code calls into the whole library.
add_executable(test_io_sanitized ${FAIRSURF_IO_SOURCES} ${CMAKE_CURRENT_SOURCE_DIR}/io/test_io.cpp
               ${CMAKE_CURRENT_SOURCE_DIR}/support/test_support.cpp ${CMAKE_CURRENT_SOURCE_DIR}/support/scratch_dir.cpp)
target_include_directories(test_io_sanitized PRIVATE ${PROJECT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/support)
target_compile_definitions(test_io_sanitized PRIVATE
  FAIRSURF_DATA_DIR="${PROJECT_SOURCE_DIR}/data" FAIRSURF_CLI="$<TARGET_FILE:fairsurf_cli>")
target_compile_options(test_io_sanitized PRIVATE ${FAIRSURF_SANITIZE_FLAGS})
target_link_options(test_io_sanitized PRIVATE ${FAIRSURF_SANITIZE_FLAGS})
target_link_libraries(test_io_sanitized PRIVATE Eigen3::Eigen GTest::gtest GTest::gtest_main fairsurf_warnings)
gtest_discover_tests(test_io_sanitized TEST_PREFIX "sanitized." WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}
                     DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1")
