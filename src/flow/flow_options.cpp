#include <fairsurf/flow/flow.h>
#include <fairsurf/mesh/errors.h>

#include "flow_options.h"

#include <cmath>
#include <string>

namespace fairsurf::flow_detail {

void check_options(const FlowOptions& o) {
  const char* problem = nullptr;
  if (!(o.tau > 0)) problem = "tau must be positive";
  else if (!(o.tau_max >= o.tau)) problem = "tau_max must be at least tau";
  else if (o.max_steps < 0) problem = "max_steps must be non-negative";
  else if (!(o.end_time > 0)) problem = "end_time must be positive";
  else if (!(o.steady_tolerance >= 0)) problem = "steady_tolerance must be non-negative";
  else if (!(o.steady_relative_tolerance >= 0)) problem = "steady_relative_tolerance must be non-negative";
  else if (!(o.relative_epsilon >= 0)) problem = "relative_epsilon must be non-negative";
  else if (!(o.curvature_resolution > 0)) problem = "curvature_resolution must be positive";
  else if (!(o.curvature_scale >= 0)) problem = "curvature_scale must be non-negative";
  else if (!(o.runaway_energy_factor > 1)) problem = "runaway_energy_factor must exceed 1";
  else if (!(o.tangential_relaxation >= 0 && o.tangential_relaxation <= 1))
    problem = "tangential_relaxation must lie in [0, 1]";
  else if (o.refactor_interval < 1) problem = "refactor_interval must be at least 1";
  else if (!(o.steady_energy_tolerance >= 0)) problem = "steady_energy_tolerance must be non-negative";
  else if (!(o.max_displacement_ratio > 0)) problem = "max_displacement_ratio must be positive";
  else if (std::isnan(o.jacobian_dominance)) problem = "jacobian_dominance must not be NaN";
  else if (!(o.max_energy_growth >= 1)) problem = "max_energy_growth must be at least 1";
  else if (!(o.reject_factor > 0 && o.reject_factor < 1)) problem = "reject_factor must lie in (0, 1)";
  else if (!(o.accept_factor >= 1)) problem = "accept_factor must be at least 1";
  else if (o.max_consecutive_rejections < 0) problem = "max_consecutive_rejections must be non-negative";
  if (problem) throw InvalidArgument(std::string("run_flow: ") + problem);
}

}  // namespace fairsurf::flow_detail
