// The CLI's BLAS thread count (docs/cli.md, "Threads").
#pragma once

namespace fairsurf::cli {

/// Debian's OpenBLAS (libopenblas0-pthread) starts a thread a core, and its idle threads spin. The
/// BLAS work here is MUMPS's dense fronts, small on hole patches and regions: a second thread gains
/// little on an idle machine, and where other jobs hold the cores the spinning thread costs a
/// multiple (docs/flow.md, "Speed", Threads). So OpenBLAS is set to one thread, unless
/// OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS or OMP_NUM_THREADS asks for a number. Looked up at run
/// time: libblas.so.3 may be another BLAS, which has no such call (then nothing happens).
void use_one_blas_thread_unless_asked();

}  // namespace fairsurf::cli
