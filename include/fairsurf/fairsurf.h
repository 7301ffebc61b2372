// fairsurf — every public header, in the order of the pipeline's stages (docs/architecture.md).
// Include this for the whole library, or the one stage header you need.
#pragma once

// mesh
#include <fairsurf/mesh/continuity.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/mesh_attributes.h>
#include <fairsurf/mesh/mesh_operations.h>
#include <fairsurf/mesh/mesh_quality.h>
#include <fairsurf/mesh/mesh_summary.h>
#include <fairsurf/mesh/region.h>
#include <fairsurf/mesh/region_selection.h>
#include <fairsurf/mesh/submesh.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

// io
#include <fairsurf/io/io.h>

// geometry
#include <fairsurf/geometry/continuity_measure.h>
#include <fairsurf/geometry/curvatures.h>
#include <fairsurf/geometry/operators.h>
#include <fairsurf/geometry/quadratic_fit.h>
#include <fairsurf/geometry/sparse.h>

// energy
#include <fairsurf/energy/energy.h>
#include <fairsurf/energy/energy_function.h>

// solve
#include <fairsurf/solve/distributed.h>
#include <fairsurf/solve/harmonic.h>
#include <fairsurf/solve/linear_solver.h>

// patch
#include <fairsurf/patch/hole_triangulation.h>
#include <fairsurf/patch/membrane.h>
#include <fairsurf/patch/patch.h>
#include <fairsurf/patch/patch_refinement.h>
#include <fairsurf/patch/tube.h>

// flow
#include <fairsurf/flow/flow.h>
#include <fairsurf/flow/flow_kind.h>
#include <fairsurf/flow/orientation_guard.h>
#include <fairsurf/flow/tangential_relaxation.h>

// applications
#include <fairsurf/applications/blend.h>
#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/fill.h>
#include <fairsurf/applications/repair.h>
#include <fairsurf/applications/scenes.h>
#include <fairsurf/applications/smooth.h>

// render
#include <fairsurf/render/render.h>
