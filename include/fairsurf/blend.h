// fairsurf — blending two boundary loops with a fair G2 tube (METHOD §7, the paper's Figs 3–4).
//
// Two boundary loops of one mesh — or of two meshes concatenated first (concatenate_meshes) — are
// joined by an initial tube (patch.h's tube_patch: loops aligned, Hermite rings, zipper strips,
// refinement to the surrounding edge length, G0 membrane), and the tube's new vertices are faired
// by fair_region (fair_region.h): by default the sixth-order flow of f = H to a steady state with
// the three rings of each surface around the loops as G2 boundary data.
//
// Loops are numbered in topology.h's boundary_loops order (sorted by their smallest vertex index).
// Both surfaces must be oriented alike across the tube (tube.h): two outward-oriented pieces, or
// two pieces of one consistently oriented mesh.
#pragma once

#include <fairsurf/continuity.h>
#include <fairsurf/fair_region.h>
#include <fairsurf/flow.h>
#include <fairsurf/mesh.h>
#include <fairsurf/patch.h>

#include <vector>

namespace fairsurf {

/// `first`'s vertices and faces, then `second`'s with indices shifted by first's #V. Per-vertex
/// scalars and colours are kept when both meshes have them (same names), dropped otherwise.
Mesh concatenate_meshes(const Mesh& first, const Mesh& second);

struct BlendOptions {
  /// Indices of the two loops to join, into boundary_loops(mesh); both −1: the closest pair
  /// (tube.h's closest_loop_pair).
  int loop_a = -1, loop_b = -1;
  PatchOptions patch;      ///< the initial tube
  FairRegionOptions fair;  ///< continuity (G2 default), f, method, steady-state tolerance
  /// Rings around each loop kept when the continuity is measured at one border (both sides' 2-ring
  /// fits must fit inside; the two loops must be farther apart than this for the figures to
  /// separate).
  int measure_rings = 4;
};

/// One of the two loops that were joined.
struct BlendLoop {
  int index = -1;            ///< into boundary_loops of the input
  int length = 0;            ///< vertices
  ContinuityMeasure border;  ///< measured at this loop after fairing (one-sided fits, continuity.h)
};

struct BlendReport {
  int loops_found = 0;        ///< boundary loops of the input
  bool automatic = false;     ///< the pair was chosen by closest_loop_pair
  double loop_distance = 0;   ///< symmetric mean nearest-vertex distance of the pair (tube.h)
  BlendLoop a, b;
  int tube_vertices = 0;      ///< new vertices (all free)
  int tube_faces = 0;         ///< new faces (after refinement)
  int tube_rings = 0;         ///< intermediate rings of the unrefined tube
  FairRegionReport fair;      ///< requested/supported continuity, steps, final max|V|, whole border
  double seconds = 0;         ///< wall time of the whole call
};

/// Joins two boundary loops of `mesh` and fairs the tube. On return `mesh` holds the input's
/// vertices and faces first (unchanged), then the tube's (per-vertex attributes are dropped, as in
/// patch.h). Throws InvalidMeshError for fewer than two loops; InvalidArgument for an index out of
/// range (the message lists every loop with its length), equal indices or only one index given; what tube_patch and
/// fair_region throw otherwise (NumericalError with `mesh` at the last accepted state of the flow).
BlendReport blend_loops(Mesh& mesh, const BlendOptions& options = {}, const FlowObserver& observer = {});

/// Measures continuity at one loop only: on the faces within `rings` rings of `loop`, with the
/// free vertices among them (continuity.h's measure_continuity).
ContinuityMeasure measure_continuity_at_loop(const Mesh& mesh, const std::vector<int>& loop,
                                             const std::vector<int>& free_vertices, int rings = 4);

}  // namespace fairsurf
