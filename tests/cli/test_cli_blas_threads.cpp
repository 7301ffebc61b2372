// The CLI's BLAS thread count (apps/fairsurf/blas_threads.h): one OpenBLAS thread, unless the
// environment asks for a number. Driven in-process, with the library's solvers (and so the BLAS that
// MUMPS links) loaded as in the CLI.
#include <fairsurf/solve/linear_solver.h>

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <cstdlib>
#include <initializer_list>

#include "blas_threads.h"

namespace {

using GetThreads = int (*)();
using SetThreads = void (*)(int);

TEST(BlasThreads, OneThreadUnlessTheEnvironmentAsksForANumber) {
  // The CLI's process has the BLAS through the library's solvers (MUMPS); so does this one.
  ASSERT_NE(fairsurf::make_linear_solver(), nullptr);
  const auto get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!get || !set) GTEST_SKIP() << "the BLAS loaded is not OpenBLAS: nothing to set";
  for (const char* variable : {"OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS"}) unsetenv(variable);

  set(2);
  const int before = get();  // 2, or 1 where OpenBLAS started with one thread
  for (const char* variable : {"OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS"}) {
    SCOPED_TRACE(variable);
    setenv(variable, "2", 1);
    fairsurf::cli::use_one_blas_thread_unless_asked();
    EXPECT_EQ(get(), before);  // asked for: left as it is
    unsetenv(variable);
  }
  fairsurf::cli::use_one_blas_thread_unless_asked();
  EXPECT_EQ(get(), 1);
}

}  // namespace
