// fairsurf — the fold rules that fair_region (FairRegionOptions::max_border_angle_ratio,
// refuse_folding_back), fill and blend share: a faired region folds against the linear ∆^k solution
// when it turns the normal across its border by much more than that solution does, and folds back
// when it turns it by more than a right angle.
#pragma once

#include <fairsurf/geometry/continuity_measure.h>

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

// Whether a faired region whose border (or one loop of it) measures `faired` folds against the
// linear solution's `linear` on rough surroundings (fair_region's check of a settled flow against
// its ∆^k start): by folds_against both at its worst border vertex and on average along the border.
// The worst vertex alone is one vertex's one-sided fits, which on a noisy scan's border read the
// noise: there a flow that does not follow the noisy rings turns more at some vertex than the
// linear solution held by them, without folding (docs/real-holes.md, "A fold is a turn along the border").
inline bool border_folds_against(const ContinuityMeasure& faired, const ContinuityMeasure& linear, double ratio) {
  return folds_against(faired.max_normal_angle, linear.max_normal_angle, ratio) &&
         folds_against(faired.mean_normal_angle, linear.mean_normal_angle, ratio);
}

// Whether the largest border normal angle `angle` (radians) folds back against the surface: more than
// a right angle, which no fill of a hole in a smooth surface turns (fill.h's folds_back).
inline bool turns_back(double angle) { return angle > std::numbers::pi / 2; }

}  // namespace fairsurf::detail
