#include "region_energy.h"

#include <fairsurf/energy/energy.h>
#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>

namespace fairsurf::bench {

double region_energy(const Vertices& V, const Faces& F, const Topology& topo, std::span<const int> region,
                     int rings) {
  const QuadraticFits fits = fit_quadratics(V, F, topo);
  const SurfaceOperators ops = compute_operators(fits, V);
  EnergyEvaluation evaluation;
  // f = H has no singularity, so the scale (it only sets ε of singular functions) does not matter.
  evaluate_energy(ops, parse_energy_functions({"H"}), EnergyScale{}, evaluation, false);
  double energy = 0;
  for (const int v : k_ring(topo, region, rings)) energy += ops.geometry.area[v] * evaluation.density[v];
  return energy;
}

}  // namespace fairsurf::bench
