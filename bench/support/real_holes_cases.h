// The meshes, ball centres and reference surfaces of bench_real_holes (docs/fill.md, "Real holes
// benchmark"): what every case is cut from and measured against.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

#include "real_holes.h"
#include "smooth_reference.h"
#include "subdivision.h"

namespace fairsurf::bench {

// Butterfly rounds of the smooth stand-in: its faces then cut the chord between the mesh's vertices
// 64 times less deep than the mesh's own (on data/torus.obj it reads a fill's distance to the exact
// torus to 2%).
constexpr int kSmoothLevels = 3;

/// A clean closed mesh of data/ with its ball centres.
struct Loaded {
  std::string name;
  Mesh mesh;
  double h = 0;
  std::vector<int> centres;  // vertex indices
  // The mesh refined kSmoothLevels times by the butterfly scheme (smooth_reference.h); its faces
  // have edges of h/8, and cubes of h/2 hold a few dozen of them.
  GridSurfaceDistance smooth;
};

/// spot, blub, the closed remeshed bunny, airplane, torus and the hammer raw scan (those whose file name contains
/// `filter`, all if empty), with three ball centres each (--quick: one); a missing file is skipped
/// with a printed note.
std::vector<Loaded> load_meshes(const std::string& filter, bool quick);
/// Any closed mesh file (bench_real_holes --mesh-file), named by its file's stem, with the ball
/// centres of a mesh without given ones: the vertices farthest along three fixed skew directions.
/// Throws InvalidArgument where the mesh has a boundary loop or no face.
Loaded load_mesh_file(const std::filesystem::path& path, bool quick);

/// A closed mesh to cut, without ball centres or reference surface (bench_stress).
struct ClosedMesh {
  std::string name;
  Mesh mesh;
  double h = 0;  ///< mean edge length
};
/// The meshes of load_meshes (the same filter and notes), read only.
std::vector<ClosedMesh> read_bundled_meshes(const std::string& filter);
/// A closed mesh file, named by its file's stem. Throws as load_mesh_file.
ClosedMesh read_closed_mesh(const std::filesystem::path& path);

// What a result is measured against: the uncut mesh, as the protocol says, and its butterfly
// refinement, which passes through the same vertices but is not flat between them.
struct Truth {
  SurfaceDistance faceted;
  const GridSurfaceDistance& smooth;
  Eigen::Vector3d centre;
  Vertices removed;  ///< fill: the uncut mesh's vertices that the cut removed (rows)
  Truth(const Loaded& m, const Eigen::Vector3d& centre) : faceted(m.mesh, centre), smooth(m.smooth), centre(centre) {}
};

/// Distances of rows `rows` of V to both surfaces of `truth`, in h.
DistanceStats measure(const Truth& truth, const Vertices& V, const std::vector<int>& rows, double h);
/// Mean distance of truth.removed to the surface of `filled`, in h; NaN where the cut removed no vertex.
double removed_mean(const Truth& truth, const Mesh& filled, double h);

/// A blend case: the plane through `vertex` normal to coordinate axis `axis` (0 x, 1 y, 2 z).
struct Slab {
  int vertex = 0, axis = 0;
};

/// Planes through the vertex at the 50%, 35%, 65%, 20%, 80%, 10%, 90%, 95% quantile of x, y, z
/// whose slab of width 4h (cut_slab) leaves exactly two loops of at most 200 edges; at most one per
/// axis, the first `wanted` of them.
std::vector<Slab> blend_slabs(const Loaded& m, std::size_t wanted);
/// Every such plane, at those quantiles and at 27%, 42%, 58%, 73%, on every axis: a larger sample
/// of blends than the fixed cases (bench_real_holes --all-slabs).
std::vector<Slab> every_blend_slab(const Loaded& m);

}  // namespace fairsurf::bench
