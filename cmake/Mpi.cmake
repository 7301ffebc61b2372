# The distributed solver (`--solver mumps-mpi`, docs/solvers.md): MUMPS's MPI build over OpenMPI.
# FAIRSURF_MPI (OFF by default, below) builds with them. The MUMPS is Debian's PT-Scotch variant
# (libmumps-ptscotch-dev, on top of libmumps-dev): libmumps-dev's own libdmumps links no ordering
# library beyond AMD/QAMD/PORD, so its automatic ordering would not be the SCOTCH nested dissection
# the sequential build uses, and PT-Scotch is also what a parallel analysis needs (docs/scaling.md).
#
# Sequential and MPI MUMPS cannot share a process: libdmumps_seq and libdmumps export the same
# symbols (dmumps_c and ~880 others), and libmpiseq_seq defines MPI_Init, MPI_Comm_rank, ... like
# libmpi itself. So an MPI build links MPI MUMPS only, and its `mumps` back end is that MUMPS on
# MPI_COMM_SELF; a build without MPI links the sequential libraries and the fake mpi.h as before.
find_package(MPI COMPONENTS C)
find_library(DMUMPS_MPI_LIBRARY dmumps_ptscotch)
find_library(MUMPS_MPI_COMMON_LIBRARY mumps_common_ptscotch)
find_library(MUMPS_MPI_PORD_LIBRARY pord_ptscotch)
find_program(MPIEXEC_EXECUTABLE NAMES mpiexec mpirun)
# OFF by default: an MPI build's every solve runs on MPI MUMPS (MPI_COMM_SELF without mpirun, about
# 0.3 s to start MPI once per process), and the sequential build is to have no MPI at run time.
# scripts/test.sh configures a second tree, build-mpi, with it ON and runs the distributed tests there.
option(FAIRSURF_MPI "Build the distributed solver mumps-mpi (OpenMPI, libmumps-ptscotch-dev)" OFF)
if(FAIRSURF_MPI AND NOT (MPI_C_FOUND AND DMUMPS_MPI_LIBRARY AND MUMPS_MPI_COMMON_LIBRARY AND MUMPS_MPI_PORD_LIBRARY
                         AND MPIEXEC_EXECUTABLE))
  message(FATAL_ERROR "FAIRSURF_MPI=ON needs OpenMPI (openmpi-bin, libopenmpi-dev) and Debian's PT-Scotch MUMPS "
                      "(libmumps-dev, libmumps-ptscotch-dev): scripts/install-deps.sh installs them")
endif()
