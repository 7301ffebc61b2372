#include <fairsurf/flow/flow_kind.h>
#include <fairsurf/mesh/errors.h>

#include <algorithm>

namespace fairsurf {

const char* to_string(FlowKind kind) {
  switch (kind) {
    case FlowKind::sixth_order: return "sixth-order";
    case FlowKind::willmore: return "willmore";
    case FlowKind::surface_diffusion: return "surface-diffusion";
    case FlowKind::mean_curvature: return "mean-curvature";
  }
  return "?";
}

FlowKind parse_flow_kind(const std::string& name) {
  std::string key = name;
  std::replace(key.begin(), key.end(), '_', '-');
  for (FlowKind k : {FlowKind::sixth_order, FlowKind::willmore, FlowKind::surface_diffusion,
                     FlowKind::mean_curvature})
    if (key == to_string(k)) return k;
  throw InvalidArgument("parse_flow_kind: '" + name +
                        "' is not a flow (expected sixth-order, willmore, surface-diffusion or "
                        "mean-curvature)");
}

int flow_order(FlowKind kind) {
  switch (kind) {
    case FlowKind::sixth_order: return 6;
    case FlowKind::willmore:
    case FlowKind::surface_diffusion: return 4;
    case FlowKind::mean_curvature: return 2;
  }
  return 0;
}

}  // namespace fairsurf
