#include "blas_threads.h"

#include <dlfcn.h>

#include <cstdlib>
#include <initializer_list>

namespace fairsurf::cli {

void use_one_blas_thread_unless_asked() {
  for (const char* variable : {"OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS"})
    if (std::getenv(variable)) return;
  using SetThreads = void (*)(int);
  if (const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
}

}  // namespace fairsurf::cli
