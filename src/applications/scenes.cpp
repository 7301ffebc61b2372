#include <fairsurf/applications/scenes.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/mesh_operations.h>
#include <fairsurf/mesh/topology.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace fairsurf {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Ring spacing of equilateral triangles between rings of points spaced h apart.
const double kRowHeight = std::sqrt(3.0) / 2.0;

/// One ring of a surface of revolution about the z axis: `count` points at radius `radius` and
/// height `z`, at angles 2π(i + offset)/count; a count of 1 is a pole on the axis.
struct Ring {
  double radius = 0, z = 0;
  int count = 1;
  double offset = 0;

  double angle(int i) const { return kTwoPi * (i + offset) / count; }
};

int points_around(double radius, double h) {
  return std::max(6, static_cast<int>(std::lround(kTwoPi * radius / h)));
}

// Joins ring a (first vertex `base_a`) to ring b (`base_b`) by walking both in angle order, each
// step taking the next point of whichever ring comes first: triangles (a_i, a_i+1, b_j) and
// (a_i, b_j+1, b_j), whose normal is t × (b − a) for the counter-clockwise tangent t.
void zip_rings(const Ring& a, int base_a, const Ring& b, int base_b, std::vector<Eigen::Vector3i>& faces) {
  const int na = a.count == 1 ? 0 : a.count, nb = b.count == 1 ? 0 : b.count;
  int i = 0, j = 0;
  while (i < na || j < nb) {
    const bool advance_a = j == nb || (i < na && a.angle(i + 1) < b.angle(j + 1));
    const int ai = base_a + i % a.count, bj = base_b + j % b.count;
    if (advance_a)
      faces.emplace_back(ai, base_a + (i + 1) % a.count, bj), ++i;
    else
      faces.emplace_back(ai, base_b + (j + 1) % b.count, bj), ++j;
  }
}

// The surface through `rings`, consecutive rings joined; `flip` reverses every face.
Mesh revolution_mesh(const std::vector<Ring>& rings, bool flip) {
  std::vector<int> base(rings.size() + 1, 0);
  for (std::size_t k = 0; k < rings.size(); ++k) base[k + 1] = base[k] + rings[k].count;
  Mesh m;
  m.V.resize(base.back(), 3);
  for (std::size_t k = 0; k < rings.size(); ++k)
    for (int i = 0; i < rings[k].count; ++i) {
      const double r = rings[k].count == 1 ? 0.0 : rings[k].radius, t = rings[k].angle(i);
      m.V.row(base[k] + i) << r * std::cos(t), r * std::sin(t), rings[k].z;
    }
  std::vector<Eigen::Vector3i> faces;
  for (std::size_t k = 0; k + 1 < rings.size(); ++k) zip_rings(rings[k], base[k], rings[k + 1], base[k + 1], faces);
  m.F.resize(static_cast<int>(faces.size()), 3);
  for (int f = 0; f < m.F.rows(); ++f)
    m.F.row(f) = flip ? Eigen::RowVector3i(faces[f][0], faces[f][2], faces[f][1]) : faces[f].transpose();
  return m;
}

// Rows alternate by half a point so that neighbouring rows form near-equilateral triangles.
double row_offset(int k) { return 0.5 * (k % 2); }

/// Flat annulus z = 0 between radii r0 < r1, normal +z; its first ring is the inner loop.
Mesh annulus(double r0, double r1, double h) {
  const int rows = std::max(3, static_cast<int>(std::lround((r1 - r0) / (kRowHeight * h))));
  std::vector<Ring> rings;
  for (int k = 0; k <= rows; ++k) {
    const double r = r0 + (r1 - r0) * k / rows;
    rings.push_back({r, 0.0, points_around(r, h), row_offset(k)});
  }
  return revolution_mesh(rings, true);
}

/// The cap of the unit sphere about `center` within polar angle `max_angle` of its pole at
/// center + (0, 0, pole) (pole = ±1), normal outward; its last ring is the rim.
Mesh spherical_cap(const Eigen::Vector3d& center, double pole, double max_angle, double h) {
  const int rows = std::max(3, static_cast<int>(std::lround(max_angle / (kRowHeight * h))));
  std::vector<Ring> rings;
  for (int k = 0; k <= rows; ++k) {
    const double phi = max_angle * k / rows, r = std::sin(phi);
    rings.push_back({r, center.z() + pole * std::cos(phi), k == 0 ? 1 : points_around(r, h), row_offset(k)});
  }
  Mesh m = revolution_mesh(rings, pole > 0);
  m.V.rowwise() += Eigen::RowVector3d(center.x(), center.y(), 0.0);
  return m;
}

/// The boundary loop of `mesh` that contains vertex `v`.
std::vector<int> loop_through(const Mesh& mesh, int v) {
  const Topology topo = build_topology(mesh.F, mesh.num_vertices());
  for (auto& loop : boundary_loops(mesh.F, topo))
    if (std::find(loop.begin(), loop.end(), v) != loop.end()) return loop;
  throw InvalidArgument("make_scene: vertex " + std::to_string(v) + " is on no boundary loop");
}

Scene blend_scene(std::string name, std::string description, const Mesh& first, const Mesh& second,
                  int first_loop_vertex, int second_loop_vertex) {
  Scene s{std::move(name), std::move(description), concatenate_meshes(first, second), {}, {}};
  s.blend_loops = {loop_through(s.mesh, first_loop_vertex),
                   loop_through(s.mesh, first.num_vertices() + second_loop_vertex)};
  return s;
}

Scene fig3(double h) {
  const Mesh disk = annulus(1.5, 2.75, h);
  const double angle = std::numbers::pi / 3;
  const Mesh cap = spherical_cap({0, 0, 0.1}, 1.0, angle, h);
  return blend_scene("fig3",
                     "Fig 3: a spherical cap above a disk with a hole; blend the hole with the cap's rim",
                     disk, cap, 0, cap.num_vertices() - 1);
}

Scene fig4(double h) {
  const double angle = std::numbers::pi / 3;
  const Mesh top = spherical_cap({0, 0, 0}, 1.0, angle, h);
  const Mesh bottom = spherical_cap({0, 0, 0}, -1.0, angle, h);
  return blend_scene("fig4", "Fig 4: two caps of the unit sphere facing each other; blend their rims (G2 with f = H recovers the sphere)", top, bottom,
                     top.num_vertices() - 1, bottom.num_vertices() - 1);
}

/// A unit cylinder whose band |z| < half_height is free: the circles z = ±half_height are fixed
/// ring 1, and four more fixed rows lie beyond each (three are needed for G2).
Scene banded_cylinder(std::string name, std::string description, double half_height, double h) {
  const int around = points_around(1.0, h);
  const int m = std::max(2, static_cast<int>(std::lround(half_height / (kRowHeight * kTwoPi / around))));
  const int rows = m + 4;
  std::vector<Ring> rings;
  for (int k = -rows; k <= rows; ++k) rings.push_back({1.0, half_height * k / m, around, row_offset(k + rows)});
  Scene s{std::move(name), std::move(description), revolution_mesh(rings, false), {}, {}};
  for (int k = -(m - 1); k <= m - 1; ++k)
    for (int i = 0; i < around; ++i) s.free_vertices.push_back((k + rows) * around + i);
  return s;
}

void mark_free(Scene& s) {
  Eigen::VectorXd flag = Eigen::VectorXd::Zero(s.mesh.num_vertices());
  for (int v : s.free_vertices) flag[v] = 1.0;
  s.mesh.vertex_scalars["free"] = flag;
}

int icosphere_level(double h) {
  // The unit icosahedron's edge is 1.05; every subdivision halves it.
  return std::clamp(static_cast<int>(std::lround(std::log2(1.05 / h))), 0, 8);
}

// Splits every triangle into four at its edge midpoints (shared midpoints are created once).
Mesh subdivide(const Mesh& in) {
  std::vector<Eigen::RowVector3d> V(in.V.rows());
  for (int v = 0; v < in.V.rows(); ++v) V[v] = in.V.row(v);
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    auto [it, inserted] = midpoint.try_emplace(std::minmax(a, b), static_cast<int>(V.size()));
    if (inserted) V.push_back(0.5 * (V[a] + V[b]));
    return it->second;
  };
  Mesh out;
  out.F.resize(4 * in.F.rows(), 3);
  for (int f = 0; f < in.F.rows(); ++f) {
    const int a = in.F(f, 0), b = in.F(f, 1), c = in.F(f, 2);
    const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.F.row(4 * f) << a, ab, ca;
    out.F.row(4 * f + 1) << b, bc, ab;
    out.F.row(4 * f + 2) << c, ca, bc;
    out.F.row(4 * f + 3) << ab, bc, ca;
  }
  out.V.resize(static_cast<int>(V.size()), 3);
  for (int v = 0; v < out.V.rows(); ++v) out.V.row(v) = V[v];
  return out;
}

}  // namespace

Mesh icosphere(int level, double radius) {
  if (level < 0) throw InvalidArgument("icosphere: level " + std::to_string(level) + " is negative");
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  m.V.resize(12, 3);
  m.V << -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1,
      -t, 0, -1, -t, 0, 1;
  m.F.resize(20, 3);
  m.F << 0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
      3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1;
  for (int l = 0; l < level; ++l) m = subdivide(m);
  m.V.rowwise().normalize();
  m.V *= radius;
  return m;
}

Scene sphere_cap_scene(int level, double z_cut) {
  Scene s{"sphere-cap",
          "method.md §8.6: the unit icosphere with its cap z > 0.5 flattened and free; G2 fairing recovers "
          "the sphere",
          icosphere(level), {}, {}};
  for (int v = 0; v < s.mesh.num_vertices(); ++v)
    if (s.mesh.V(v, 2) > z_cut) {
      s.mesh.V(v, 2) = z_cut;
      s.free_vertices.push_back(v);
    }
  mark_free(s);
  return s;
}

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names{"fig3", "fig4", "fig7", "fig8", "sphere-cap"};
  return names;
}

Scene make_scene(const std::string& name, const SceneOptions& options) {
  const double h = options.edge_length;
  if (!(h > 0) || !std::isfinite(h))
    throw InvalidArgument("make_scene: edge length " + std::to_string(h) + " is not positive and finite");
  if (name == "fig3") return fig3(h);
  if (name == "fig4") return fig4(h);
  if (name == "sphere-cap") return sphere_cap_scene(icosphere_level(h));
  if (name == "fig7" || name == "fig8") {
    Scene s = name == "fig7"
                  ? banded_cylinder(name, "Fig 7: an open unit cylinder with the band |z| < 1 free", 1.0, h)
                  : banded_cylinder(name, "Fig 8: a unit ring between the circles z = ±0.25, free between them",
                                    0.25, h);
    mark_free(s);
    return s;
  }
  std::string list;
  for (const auto& n : scene_names()) list += (list.empty() ? "" : ", ") + n;
  throw InvalidArgument("make_scene: unknown scene '" + name + "' (scenes: " + list + ")");
}

}  // namespace fairsurf
