# The distributed solver's tests (tests/mpi/test_mpi.cpp): `mpirun -n 2 --oversubscribe` on
# localhost. Built in every configuration; without FAIRSURF_MPI each test skips and says why.
# OpenMPI refuses to run as root (CI's container) unless told: the environment below allows it. In
# containers without ptrace rights its shared-memory transport's single-copy mode (CMA) fails with
# "Read -1, expected ..." errors; copying through the shared buffer instead works everywhere.
add_executable(test_mpi ${CMAKE_CURRENT_SOURCE_DIR}/mpi/test_mpi.cpp)
target_link_libraries(test_mpi PRIVATE fairsurf_test_support GTest::gtest_main fairsurf_warnings)
add_dependencies(test_mpi fairsurf_cli)
if(FAIRSURF_MPI)
  add_executable(fairsurf_mpi_probe ${CMAKE_CURRENT_SOURCE_DIR}/mpi/mpi_probe.cpp)
  target_link_libraries(fairsurf_mpi_probe PRIVATE fairsurf fairsurf_warnings)
  add_dependencies(test_mpi fairsurf_mpi_probe)
  target_compile_definitions(test_mpi PRIVATE FAIRSURF_MPIEXEC="${MPIEXEC_EXECUTABLE}"
                             FAIRSURF_MPI_PROBE="$<TARGET_FILE:fairsurf_mpi_probe>")
endif()
# Each run inside is bounded too (`timeout`, test_mpi.cpp): a hang fails that test with its command.
gtest_discover_tests(test_mpi WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} DISCOVERY_TIMEOUT 60
                     PROPERTIES TIMEOUT 300 PROCESSORS 2
                     ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_btl_vader_single_copy_mechanism=none")
