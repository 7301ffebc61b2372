// fairsurf — the geometric flows the library runs, named once for the step assembly, the run and
// the drivers (docs/flow.md).
#pragma once

#include <string>

namespace fairsurf {

/// sixth_order: the flow of the energy ∫ Σ‖∇f_l(H, K)‖² dA (energy_function.h); willmore,
/// surface_diffusion and mean_curvature: the classical baselines.
enum class FlowKind { sixth_order, willmore, surface_diffusion, mean_curvature };

/// "sixth-order", "willmore", "surface-diffusion", "mean-curvature".
const char* to_string(FlowKind kind);
/// Inverse of to_string ('_' accepted for '-'); throws InvalidArgument naming the valid kinds.
FlowKind parse_flow_kind(const std::string& name);
/// The order of the flow's PDE: 6, 4, 4, 2. The flow reaches continuity G(order/2 − 1) across the
/// border of the free region when order/2 fixed rings surround it (region.h).
int flow_order(FlowKind kind);

}  // namespace fairsurf
