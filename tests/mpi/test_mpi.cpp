// The mumps-mpi solver under `mpirun -n 2 --oversubscribe` (2 ranks on this machine): smooth, fill
// and fair give the sequential result to 1e-10; a solver failure ends every rank with exit code 4;
// a rank that dies ends the job; serving ranks end with rank 0 (every run is bounded by `timeout`,
// whose exit code 124 means a hang). Without FAIRSURF_MPI the tests skip, except the one that checks
// the error such a build gives for --solver mumps-mpi.
#include <fairsurf/io/io.h>
#include <fairsurf/solve/distributed.h>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_dir.h"
#include "test_support.h"

namespace fairsurf {
namespace {

#ifdef FAIRSURF_MPIEXEC
constexpr const char* kMpiexec = FAIRSURF_MPIEXEC;
constexpr const char* kProbe = FAIRSURF_MPI_PROBE;
#else
constexpr const char* kMpiexec = "";
constexpr const char* kProbe = "";
#endif
constexpr int kTimeoutSeconds = 240;
constexpr int kTimedOut = 124;  // timeout(1)'s code for a command it had to stop

std::string quoted(const std::string& s) { return "'" + s + "'"; }

struct Outcome {
  int exit_code = -1;
  std::string out;
};

// `command` under timeout(1), stdout and stderr together.
Outcome run(const std::string& command) {
  const std::string bounded =
      std::string("timeout -k 10 ").append(std::to_string(kTimeoutSeconds)).append(" ").append(command).append(" 2>&1");
  Outcome result;
  FILE* pipe = ::popen(bounded.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) result.out += buffer;
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// mpirun with two ranks on this machine; OpenMPI also needs leave to run as root (CI's container).
std::string mpirun_2(const std::string& program) {
  std::string command = std::string(kMpiexec).append(" -n 2 --oversubscribe");
  if (::geteuid() == 0) command += " --allow-run-as-root";
  return command.append(" ").append(program);
}

// max |a − b| over coordinates, relative to max |a|; faces must be equal.
double relative_difference(const std::string& a_path, const std::string& b_path) {
  const Mesh a = read_mesh(a_path), b = read_mesh(b_path);
  EXPECT_EQ(a.F, b.F);
  if (a.V.rows() != b.V.rows()) return 1;
  return (a.V - b.V).cwiseAbs().maxCoeff() / a.V.cwiseAbs().maxCoeff();
}

class MpiTest : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    if (!distributed::built_with_mpi()) GTEST_SKIP() << "built without MPI (FAIRSURF_MPI=OFF): no mumps-mpi to test";
    test::ScratchDirTest::SetUp();
  }

  // Runs `fairsurf COMMAND -o OUT` alone with --solver mumps and under mpirun with --solver mumps-mpi,
  // and returns the outputs' relative difference.
  double two_ranks_against_sequential(const std::string& command) {
    const std::string cli = quoted(test::cli_path()) + " " + command + " --quiet -o ";
    const Outcome sequential = run(cli + quoted(file("sequential.ply")) + " --solver mumps");
    EXPECT_EQ(sequential.exit_code, 0) << sequential.out;
    const Outcome distributed = run(mpirun_2(cli + quoted(file("distributed.ply")) + " --solver mumps-mpi"));
    EXPECT_EQ(distributed.exit_code, 0) << distributed.out;
    if (sequential.exit_code != 0 || distributed.exit_code != 0) return 1;
    const double difference = relative_difference(file("sequential.ply"), file("distributed.ply"));
    std::printf("%s: 2 ranks against sequential: relative difference %.3g\n", command.c_str(), difference);
    return difference;
  }

  // The exit code each rank wrote for fairsurf_mpi_probe (-1: none written).
  int rank_exit_code(int rank) const {
    std::ifstream in(file("rank-" + std::to_string(rank) + ".exit"));
    int code = -1;
    in >> code;
    return code;
  }
};

TEST_F(MpiTest, SmoothOnTwoRanksEqualsSequential) {
  EXPECT_LE(two_ranks_against_sequential("smooth " + quoted(test::data_path("sphere_16k.off")) + " --steps 2"), 1e-10);
}

TEST_F(MpiTest, FillOnTwoRanksEqualsSequential) {
  EXPECT_LE(two_ranks_against_sequential("fill " + quoted(test::data_path("hand_lowres.obj"))), 1e-10);
}

TEST_F(MpiTest, FairOnTwoRanksEqualsSequential) {
  EXPECT_LE(two_ranks_against_sequential("fair " + quoted(test::data_path("sphere_16k.off")) +
                                         " --region-sphere 1,0,0,0.4"),
            1e-10);
}

TEST_F(MpiTest, SolverFailureGivesExitCode4OnEveryRank) {
  const Outcome probe = run(mpirun_2(quoted(kProbe) + " singular " + quoted(dir_.string())));
  EXPECT_NE(probe.exit_code, kTimedOut) << probe.out;
  EXPECT_EQ(probe.exit_code, 4) << probe.out;
  EXPECT_NE(probe.out.find("factorize: mumps-mpi: numerically singular matrix (INFOG(1) = -10"), std::string::npos)
      << probe.out;
  EXPECT_EQ(rank_exit_code(0), 4);
  EXPECT_EQ(rank_exit_code(1), 4);
}

TEST_F(MpiTest, RankThatDiesEndsTheJob) {
  const Outcome probe = run(mpirun_2(quoted(kProbe) + " dying " + quoted(dir_.string())));
  EXPECT_NE(probe.exit_code, kTimedOut) << probe.out;
  EXPECT_NE(probe.exit_code, 0) << probe.out;
  EXPECT_EQ(rank_exit_code(0), -1) << "rank 0 went on after its partner died";
}

TEST_F(MpiTest, MumpsControlsPassThroughUnderMpirun) {
  // A parallel analysis on both ranks (ICNTL(28) = 2 with PT-Scotch, set on rank 0 only: MUMPS
  // takes its controls from the host) gives the sequential result.
  const std::string torus = quoted(test::data_path("torus.obj"));
  EXPECT_LE(two_ranks_against_sequential("smooth " + torus + " --steps 2 --mumps-icntl 28=2 --mumps-icntl 29=1"),
            1e-10);
  const std::string cli = quoted(test::cli_path()) + " smooth " + torus + " --steps 1 --quiet --solver mumps-mpi -o ";
  const Outcome refused = run(mpirun_2(cli + quoted(file("refused.ply")) + " --mumps-icntl 4=2"));
  EXPECT_EQ(refused.exit_code, 1) << refused.out;
  EXPECT_NE(refused.out.find("ICNTL(4) = 2: not a MUMPS control to pass through"), std::string::npos) << refused.out;
}

TEST_F(MpiTest, ServingRankEndsWithRankZero) {
  const std::string cli = quoted(test::cli_path());
  Outcome info = run(mpirun_2(cli + " info " + quoted(test::data_path("torus.obj"))));
  EXPECT_EQ(info.exit_code, 0) << info.out;
  Outcome usage = run(mpirun_2(cli + " smooth --no-such-flag"));
  EXPECT_EQ(usage.exit_code, 1) << usage.out;  // rank 0's code on both ranks, not a hang (124)
  const Outcome missing = run(mpirun_2(cli + " smooth /nonexistent.obj -o " + quoted(file("out.ply")) +
                                   " --solver mumps-mpi"));
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_FALSE(std::filesystem::exists(file("out.ply")));
}

using MpiAbsentTest = test::ScratchDirTest;

TEST_F(MpiAbsentTest, MumpsMpiIsAUsageErrorWithoutMpi) {
  if (distributed::built_with_mpi()) GTEST_SKIP() << "built with MPI (FAIRSURF_MPI=ON): mumps-mpi exists";
  const auto run = test::run_cli("smooth " + quoted(test::data_path("torus.obj")) + " -o " + quoted(file("out.ply")) +
                                 " --solver mumps-mpi");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_FALSE(std::filesystem::exists(file("out.ply")));
  EXPECT_NE(run.out.find("--solver mumps-mpi: this fairsurf was built without MPI"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace fairsurf
