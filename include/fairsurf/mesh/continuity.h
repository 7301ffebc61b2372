// fairsurf — the continuity a fairing reaches across the border of its free region: G0 positions,
// G1 tangent planes, G2 curvatures (region.h: the fixed rings each needs; continuity_measure.h: how
// it is measured on a result).
#pragma once

#include <string>
#include <string_view>

namespace fairsurf {

/// Continuity across the border of a free region: position, tangent plane, curvature.
enum class Continuity { G0 = 0, G1 = 1, G2 = 2 };

/// Fixed rings a flow of the given continuity needs (G0: 1, G1: 2, G2: 3).
constexpr int rings_needed(Continuity c) { return static_cast<int>(c) + 1; }

/// "G0", "G1", "G2".
const char* to_string(Continuity c);
/// What a fairing delivers: "G2" (a flow with three fixed rings) or, for the linear cotangent ∆^k
/// solution on the same rings, "C2 (linear)" — curvature continuous only to the order of the
/// linear operator, not geometrically.
std::string delivered_label(Continuity continuity, bool linear);
/// Parses "G0"/"G1"/"G2" (case-insensitive); throws InvalidArgument otherwise.
Continuity parse_continuity(std::string_view text);

}  // namespace fairsurf
