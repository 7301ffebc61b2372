// Private: how the operations that check their result for crossings (fill, blend, fair_region)
// count them in their messages.
#pragma once

#include <fairsurf/mesh/face_intersection.h>

#include <string>
#include <vector>

namespace fairsurf::detail {

/// How many crossings a check searches for before it stops (find_face_intersections' max_results).
inline constexpr int kCrossingsSought = 10;

/// "1 crossing", "4 crossings", or "10+ crossings" where the search stopped at kCrossingsSought.
inline std::string crossing_count(const std::vector<FaceIntersection>& crossings) {
  const std::size_t n = crossings.size();
  return std::to_string(n) + (n >= static_cast<std::size_t>(kCrossingsSought) ? "+" : "") + " crossing" +
         (n == 1 ? "" : "s");
}

}  // namespace fairsurf::detail
