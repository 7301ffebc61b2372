// fairsurf — wall time of a stage, for the reports' `seconds` fields (private).
#pragma once

#include <chrono>

namespace fairsurf::detail {

using Clock = std::chrono::steady_clock;

/// Seconds of wall time from `start` to now.
inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace fairsurf::detail
