// Noisy and jittered analytic meshes, and distances to the analytic surfaces, for the flow tests
// (method.md §8.3–§8.5); and a flow report to describe.
#pragma once

#include "analytic_meshes.h"

#include <fairsurf/flow/flow.h>
#include <fairsurf/mesh/mesh.h>

namespace fairsurf::test {

/// icosphere(level, radius) with every vertex moved along the sphere's normal by a uniformly random
/// offset in [−amplitude, amplitude] times the mean edge length (fixed seed).
Mesh noisy_sphere(int level, double radius, double amplitude, unsigned seed = 7);

/// torus_grid(n, m, R, r) with every vertex moved along the torus's normal by a uniformly random
/// offset in [−amplitude, amplitude] times the mean edge length (fixed seed).
Mesh noisy_torus(int n, int m, double R, double r, double amplitude, unsigned seed = 7);

/// open_cylinder(around, along, radius, height) with the angle of every vertex and the height of
/// every vertex not on an end moved by a uniformly random offset of at most `jitter` grid spacings
/// (fixed seed); vertices stay on the cylinder.
Mesh jittered_cylinder(int around, int along, double radius, double height, double jitter,
                       unsigned seed = 3);

/// Signed distances of the vertices to the sphere of `radius` about the origin (#V).
Eigen::VectorXd sphere_distances(const Vertices& V, double radius);
/// Signed distances of the vertices to the torus (R, r) about the z axis (#V).
Eigen::VectorXd torus_distances(const Vertices& V, double R, double r);
/// Distances of the vertices to the z axis (#V).
Eigen::VectorXd axis_distances(const Vertices& V);

/// Volume enclosed by a closed, outward-oriented mesh.
double enclosed_volume(const Vertices& V, const Faces& F);

/// The report of a `kind` run stopped at its step limit after two accepted steps (E 10 -> 8 -> 6,
/// one rejected trial at 9 between them), its max|V| risen from 1 to 5: what unsettled_reason and
/// the CLI's summary describe.
FlowReport unsettled_flow_report(FlowStepKind kind);

}  // namespace fairsurf::test
