// fairsurf — when a loop is worth an OpenMP team (private).
//
// Every parallel region wakes a team and ends at a barrier. On a machine with more runnable threads
// than cores (two jobs on two cores, `ctest -j2`), threads that reach the barrier spin for their
// whole spin count waiting for one that was descheduled: a fill of one 177-vertex hole of
// cgal_mech_holes_shark took 50 s of wall time instead of 2 s, nearly all of it in libgomp's spin.
// Hole patches, regions and blends are such small loops, repeated thousands of times; a loop over
// fewer items than this runs on the calling thread alone (the `if` clause of each region).
#pragma once

namespace fairsurf::detail {

inline constexpr long long kMinParallelItems = 4096;

inline bool worth_parallel(long long items) { return items >= kMinParallelItems; }

}  // namespace fairsurf::detail
