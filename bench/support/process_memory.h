// Memory figures of the running process, for benchmarks that report peak memory.
#pragma once

#include <string>

namespace fairsurf::bench {

/// A "VmRSS:" or "VmHWM:" figure of /proc/self/status, in bytes; -1 if it cannot be read.
long long proc_status_bytes(const std::string& key);

/// The process's peak resident memory so far (VmHWM), in bytes.
inline long long peak_bytes() { return proc_status_bytes("VmHWM:"); }

}  // namespace fairsurf::bench
