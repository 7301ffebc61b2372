// fairsurf — the fold rules that fair_region (FairRegionOptions::max_border_angle_ratio,
// refuse_folding_back), fill and blend share: a faired region folds against the linear ∆^k solution
// when it turns the normal across its border by much more than that solution does, and folds back
// when it turns it by more than a right angle.
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

// Whether the largest border normal angle `angle` (radians) folds back against the surface: more than
// a right angle, which no fill of a hole in a smooth surface turns (fill.h's folds_back).
inline bool turns_back(double angle) { return angle > std::numbers::pi / 2; }

}  // namespace fairsurf::detail
