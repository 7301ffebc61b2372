// fairsurf — the fold rule that fair_region (FairRegionOptions::max_border_angle_ratio) and blend's
// choice between descents share: a faired region folds against the linear ∆^k solution when it
// turns the normal across its border by much more than that solution does.
#pragma once

#include <algorithm>
#include <numbers>

namespace fairsurf::detail {

// The smallest border angle counted as a fold: below it the one-sided fits' own scatter on a
// clean mesh (bench_real_holes' fold rule, issue #11).
inline constexpr double kSmallestFoldAngle = 5 * std::numbers::pi / 180;

// Whether the largest border normal angle `angle` (radians) folds against the linear solution's
// `linear`: above `ratio` times it and above kSmallestFoldAngle.
inline bool folds_against(double angle, double linear, double ratio) {
  return angle > std::max(ratio * linear, kSmallestFoldAngle);
}

}  // namespace fairsurf::detail
