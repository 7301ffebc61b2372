// Private to fair_region: choosing between the flow and its linear floor by how well each
// re-predicts the input around the free region (FairRegionOptions::held_out_rings; docs/fill.md,
// "Which fairing a hole gets").
#pragma once

#include <fairsurf/fair_region.h>
#include <fairsurf/submesh.h>

namespace fairsurf::fair_detail {

/// Mean normal distance of the held-out input vertices from where each fairing puts them, in units
/// of the mean edge length at those vertices. ∞ when that fairing failed.
struct HeldOutErrors {
  double flow = 0;
  double linear = 0;
  /// Of the flow's trial on the enlarged region (its report's, or its error's when the flow threw).
  WellPosedness flow_well_posedness;
};

/// Frees the `rings` rings of fixed vertices around the free vertices in a copy of `sub`, fairs that
/// larger region with `fairing` (the flow with its linear floor; held_out_rings ignored) and with its
/// linear ∆^k solution alone, and measures how far each moved the held-out vertices off the input's
/// tangent planes there.
HeldOutErrors held_out_errors(const Submesh& sub, int rings, const FairRegionOptions& fairing);

}  // namespace fairsurf::fair_detail
