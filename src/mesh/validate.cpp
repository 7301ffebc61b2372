#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/mesh/validate.h>

#include "validated.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <climits>
#include <numeric>
#include <utility>

namespace fairsurf {
namespace {

enum class FaceStatus { well_formed, out_of_range, repeated_vertex };

FaceStatus face_status(const Faces& F, int f, int num_vertices) {
  for (int k = 0; k < 3; ++k)
    if (F(f, k) < 0 || F(f, k) >= num_vertices) return FaceStatus::out_of_range;
  if (F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 2) == F(f, 0))
    return FaceStatus::repeated_vertex;
  return FaceStatus::well_formed;
}

// Counts an offending element and keeps it as an example while there is room.
class Recorder {
 public:
  explicit Recorder(int max_examples) : max_(std::max(0, max_examples)) {}
  void add(Finding& finding, int index) const {
    if (finding.count++ < max_) finding.examples.push_back(index);
  }
  void add(Finding& finding, int a, int b) const {
    if (finding.count++ < max_) finding.examples.insert(finding.examples.end(), {a, b});
  }

 private:
  int max_;
};

// Whether face f traverses its edge e from the lower to the higher vertex index.
bool traverses_upward(const Faces& F, const Topology& topo, int f, int e) {
  for (int k = 0; k < 3; ++k)
    if (topo.face_edges[3 * f + k] == e) return F(f, k) < F(f, (k + 1) % 3);
  return false;  // unreachable: e is an edge of f
}

// The face across the two-face edge e from face f.
int opposite_face(const Topology& topo, int e, int f) {
  const auto faces = topo.edge_faces.row(e);
  return faces[0] == f ? faces[1] : faces[0];
}

// Zero-area and near-degenerate triangles among the well-formed faces with finite corners.
void check_triangle_shapes(const Vertices& V, const Faces& F, const std::vector<int>& original,
                           const std::vector<char>& finite, const ValidationOptions& options,
                           const Recorder& rec, ValidationReport& r) {
  for (int f = 0; f < F.rows(); ++f) {
    if (!finite[F(f, 0)] || !finite[F(f, 1)] || !finite[F(f, 2)]) continue;
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    if (cross.isZero(0.0)) {
      rec.add(r.degenerate_faces, original[f]);
      continue;
    }
    const double longest_squared =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if (cross.norm() <= options.near_degenerate_tolerance * longest_squared)
      rec.add(r.near_degenerate_faces, original[f]);
  }
}

// Flags, in each group of elements with equal keys, every element but the lowest-indexed one.
// `keyed` holds (key, element index) pairs.
template <class Key>
std::vector<char> flag_repeats(std::vector<std::pair<Key, int>> keyed, int num_elements) {
  std::sort(keyed.begin(), keyed.end());
  std::vector<char> repeat(num_elements, 0);
  for (std::size_t i = 1; i < keyed.size(); ++i)
    if (keyed[i].first == keyed[i - 1].first) repeat[keyed[i].second] = 1;
  return repeat;
}

void check_duplicate_positions(const Vertices& V, const std::vector<char>& finite,
                               const Recorder& rec, ValidationReport& r) {
  std::vector<std::pair<std::array<double, 3>, int>> keyed;
  keyed.reserve(V.rows());
  for (int v = 0; v < V.rows(); ++v)
    if (finite[v]) keyed.push_back({{V(v, 0), V(v, 1), V(v, 2)}, v});
  const auto repeat = flag_repeats(std::move(keyed), static_cast<int>(V.rows()));
  for (int v = 0; v < V.rows(); ++v)
    if (repeat[v]) rec.add(r.duplicate_vertex_positions, v);
}

void check_duplicate_faces(const Faces& F, const std::vector<int>& original, const Recorder& rec,
                           ValidationReport& r) {
  std::vector<std::pair<std::array<int, 3>, int>> keyed(F.rows());
  for (int f = 0; f < F.rows(); ++f) {
    std::array<int, 3> key{F(f, 0), F(f, 1), F(f, 2)};
    std::sort(key.begin(), key.end());
    keyed[f] = {key, f};
  }
  const auto repeat = flag_repeats(std::move(keyed), static_cast<int>(F.rows()));
  for (int f = 0; f < F.rows(); ++f)
    if (repeat[f]) rec.add(r.duplicate_faces, original[f]);
}

// Number of fans around v: its incident faces, connected when they share an edge incident to v.
// `parent` is scratch space reused across vertices.
int count_fans(const Faces& F, const Topology& topo, int v, std::vector<int>& parent) {
  const auto faces = topo.vertex_faces.row(v);
  parent.resize(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  auto local = [&](int f) {
    return static_cast<int>(std::lower_bound(faces.begin(), faces.end(), f) - faces.begin());
  };
  int fans = static_cast<int>(faces.size());
  for (int i = 0; i < static_cast<int>(faces.size()); ++i)
    for (int k = 0; k < 3; ++k) {
      const int f = faces[i];
      if (F(f, k) != v && F(f, (k + 1) % 3) != v) continue;  // the edge opposite v
      for (int g : topo.edge_faces.row(topo.face_edges[3 * f + k])) {
        const int a = find(i), b = find(local(g));
        if (a != b) parent[std::max(a, b)] = std::min(a, b), --fans;
      }
    }
  return fans;
}

void check_manifoldness(const Faces& F, const Topology& topo, const Recorder& rec,
                        ValidationReport& r) {
  for (int e = 0; e < topo.edges.rows(); ++e)
    if (topo.edge_faces.size(e) > 2) rec.add(r.non_manifold_edges, topo.edges(e, 0), topo.edges(e, 1));
  std::vector<int> scratch;
  for (int v = 0; v < topo.num_vertices; ++v) {
    if (topo.vertex_faces.size(v) == 0)
      rec.add(r.unreferenced_vertices, v);
    else if (count_fans(F, topo, v, scratch) > 1)
      rec.add(r.non_manifold_vertices, v);
  }
}

// Inconsistent two-face edges, then orientation propagation across two-face edges: a component is
// non-orientable when a face would have to be flipped and kept at the same time.
void check_orientation(const Faces& F, const Topology& topo, const std::vector<int>& original,
                       const Recorder& rec, ValidationReport& r) {
  std::vector<char> same_direction(topo.edges.rows(), 0);
  for (int e = 0; e < topo.edges.rows(); ++e) {
    if (topo.edge_faces.size(e) != 2) continue;
    const auto faces = topo.edge_faces.row(e);
    same_direction[e] = traverses_upward(F, topo, faces[0], e) == traverses_upward(F, topo, faces[1], e);
    if (same_direction[e]) rec.add(r.inconsistent_orientation_edges, topo.edges(e, 0), topo.edges(e, 1));
  }

  const Components components = connected_components(F, topo);
  std::vector<int> first_conflict(components.count, INT_MAX);
  std::vector<signed char> flip(F.rows(), -1);
  std::vector<int> stack;
  for (int seed = 0; seed < F.rows(); ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int e = topo.face_edges[3 * f + k];
        if (topo.edge_faces.size(e) != 2) continue;
        const int g = opposite_face(topo, e, f);
        const signed char wanted = flip[f] ^ same_direction[e];
        if (flip[g] < 0) {
          flip[g] = wanted;
          stack.push_back(g);
        } else if (flip[g] != wanted) {
          int& first = first_conflict[components.face_component[f]];
          first = std::min({first, f, g});
        }
      }
    }
  }
  std::vector<int> conflict_faces;
  for (int first : first_conflict)
    if (first != INT_MAX) conflict_faces.push_back(original[first]);
  std::sort(conflict_faces.begin(), conflict_faces.end());
  for (int f : conflict_faces) rec.add(r.non_orientable_components, f);
}

std::string describe(const NamedFinding& named) {
  const Finding& f = *named.finding;
  return std::to_string(f.count) + " " + (f.count == 1 ? named.singular : named.plural) +
         " (first: " + format_examples(f, 1) + ")";
}

}  // namespace

bool ValidationReport::manifold() const {
  return out_of_range_indices.count == 0 && repeated_vertex_faces.count == 0 &&
         non_manifold_edges.count == 0 && non_manifold_vertices.count == 0;
}

bool ValidationReport::is_valid() const {
  if (no_faces) return false;
  for (const auto& named : named_findings(*this))
    if (named.finding->count > 0) return false;
  return true;
}

Faces well_formed_faces(const Faces& F, int num_vertices, std::vector<int>* kept) {
  std::vector<int> rows;
  for (int f = 0; f < F.rows(); ++f)
    if (face_status(F, f, num_vertices) == FaceStatus::well_formed) rows.push_back(f);
  Faces out(rows.size(), 3);
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) out.row(i) = F.row(rows[i]);
  if (kept) *kept = std::move(rows);
  return out;
}

namespace {

// validate() on the topology `given` of mesh.F when there is one (all faces are then well formed:
// build_topology accepted them), else on the topology of the well-formed faces, moved into `built`
// (if given) when every face is well formed, so that a caller can keep it instead of rebuilding it.
ValidationReport validate_on(const Mesh& mesh, const ValidationOptions& options, const Topology* given,
                             Topology* built) {
  const Recorder rec(options.max_examples);
  ValidationReport r;
  r.num_vertices = mesh.num_vertices();
  r.num_faces = mesh.num_faces();
  r.no_faces = r.num_faces == 0;
  if (given && (given->num_vertices != r.num_vertices || given->num_faces != r.num_faces))
    throw InvalidArgument("validate: the topology was built for another mesh");

  std::vector<char> finite(r.num_vertices);
  for (int v = 0; v < r.num_vertices; ++v) {
    finite[v] = mesh.V.row(v).allFinite();
    if (!finite[v]) rec.add(r.nan_vertices, v);
  }
  for (int f = 0; f < r.num_faces; ++f) {
    const FaceStatus status = face_status(mesh.F, f, r.num_vertices);
    if (status == FaceStatus::out_of_range) rec.add(r.out_of_range_indices, f);
    if (status == FaceStatus::repeated_vertex) rec.add(r.repeated_vertex_faces, f);
  }

  std::vector<int> original;  // index in mesh.F of each well-formed face
  const Faces F = well_formed_faces(mesh.F, r.num_vertices, &original);
  Topology own;
  if (!given) own = build_topology(F, r.num_vertices);
  const Topology& topo = given ? *given : own;
  r.num_edges = static_cast<int>(topo.edges.rows());

  check_triangle_shapes(mesh.V, F, original, finite, options, rec, r);
  check_duplicate_positions(mesh.V, finite, rec, r);
  check_duplicate_faces(F, original, rec, r);
  check_manifoldness(F, topo, rec, r);
  check_orientation(F, topo, original, rec, r);
  if (built && !given && static_cast<int>(original.size()) == r.num_faces) *built = std::move(own);
  return r;
}

}  // namespace

ValidationReport validate(const Mesh& mesh, const ValidationOptions& options) {
  return validate_on(mesh, options, nullptr, nullptr);
}

ValidationReport validate(const Mesh& mesh, const Topology& topo, const ValidationOptions& options) {
  return validate_on(mesh, options, &topo, nullptr);
}

namespace detail {

ValidationReport validate_keeping_topology(const Mesh& mesh, Topology& topo) {
  return validate_on(mesh, {}, nullptr, &topo);
}

Topology validated_topology(const Mesh& mesh, const Requirements& requirements, const char* caller) {
  Topology topo;
  require_valid(validate_keeping_topology(mesh, topo), requirements, caller);
  return topo;  // every face is well formed once require_valid passed: the topology of mesh.F
}

std::vector<int> border_edge_counts(const Topology& topo) {
  std::vector<int> count(topo.num_vertices, 0);
  for (int e = 0; e < topo.edges.rows(); ++e)
    if (topo.is_boundary_edge(e)) ++count[topo.edges(e, 0)], ++count[topo.edges(e, 1)];
  return count;
}

void allow_border_pinches(ValidationReport& report, const Topology& topo) {
  const std::vector<int> border = border_edge_counts(topo);
  Finding& vertices = report.non_manifold_vertices;
  vertices.count -= static_cast<int>(std::count_if(border.begin(), border.end(), [](int c) { return c > 2; }));
  std::erase_if(vertices.examples, [&](int v) { return border[v] > 2; });
}

}  // namespace detail

std::vector<NamedFinding> named_findings(const ValidationReport& r) {
  return {
      {"nan_vertices", "vertex with a NaN or infinite coordinate",
       "vertices with NaN or infinite coordinates", &r.nan_vertices},
      {"out_of_range_indices", "face with an out-of-range vertex index",
       "faces with out-of-range vertex indices", &r.out_of_range_indices},
      {"repeated_vertex_faces", "face repeating a vertex", "faces repeating a vertex",
       &r.repeated_vertex_faces},
      {"degenerate_faces", "zero-area triangle", "zero-area triangles", &r.degenerate_faces},
      {"near_degenerate_faces", "near-degenerate triangle", "near-degenerate triangles",
       &r.near_degenerate_faces},
      {"duplicate_vertex_positions", "duplicate vertex position", "duplicate vertex positions",
       &r.duplicate_vertex_positions},
      {"duplicate_faces", "duplicate face", "duplicate faces", &r.duplicate_faces},
      {"unreferenced_vertices", "unreferenced vertex", "unreferenced vertices",
       &r.unreferenced_vertices},
      {"non_manifold_edges", "non-manifold edge", "non-manifold edges", &r.non_manifold_edges},
      {"non_manifold_vertices", "non-manifold vertex", "non-manifold vertices",
       &r.non_manifold_vertices},
      {"inconsistent_orientation_edges", "inconsistently oriented edge",
       "inconsistently oriented edges", &r.inconsistent_orientation_edges},
      {"non_orientable_components", "non-orientable component", "non-orientable components",
       &r.non_orientable_components},
  };
}

std::string format_examples(const Finding& finding, int max) {
  const int stride = finding.element == Element::edge ? 2 : 1;
  const int shown = std::min(max, static_cast<int>(finding.examples.size()) / stride);
  std::string out;
  for (int i = 0; i < shown; ++i) {
    if (i > 0) out += ", ";
    out += std::to_string(finding.examples[stride * i]);
    if (stride == 2) out.append("-").append(std::to_string(finding.examples[2 * i + 1]));
  }
  return out;
}

void require_valid(const ValidationReport& report, const Requirements& requirements,
                   const char* caller) {
  const auto all = named_findings(report);
  auto named = [&](const Finding& f) {
    return *std::find_if(all.begin(), all.end(), [&](const auto& n) { return n.finding == &f; });
  };
  std::vector<const Finding*> required{&report.nan_vertices, &report.out_of_range_indices,
                                       &report.repeated_vertex_faces};
  if (requirements.manifold)
    required.insert(required.end(), {&report.non_manifold_edges, &report.non_manifold_vertices});
  if (requirements.oriented)
    required.insert(required.end(),
                    {&report.inconsistent_orientation_edges, &report.non_orientable_components});
  if (requirements.non_degenerate) required.push_back(&report.degenerate_faces);
  if (requirements.no_duplicate_faces) required.push_back(&report.duplicate_faces);

  std::vector<std::string> violations;
  if (report.no_faces) violations.emplace_back("no faces");
  // repair() cannot give a mesh faces or orient a Möbius band; every other violation it removes.
  bool repairable = !report.no_faces;
  for (const Finding* f : required)
    if (f->count > 0) {
      violations.push_back(describe(named(*f)));
      repairable &= f != &report.non_orientable_components;
    }
  if (violations.empty()) return;
  std::string message = std::string(caller) + ": mesh has ";
  for (std::size_t i = 0; i < violations.size(); ++i)
    message += (i > 0 ? ", " : "") + violations[i];
  if (repairable) throw RepairableMeshError(message);
  if (requirements.oriented && report.non_orientable_components.count > 0)
    message += " (a one-sided surface, such as a Möbius band, has no consistent orientation, and no repair gives "
               "it one)";
  throw InvalidMeshError(message);
}

void require_valid(const Mesh& mesh, const Requirements& requirements, const char* caller) {
  require_valid(validate(mesh), requirements, caller);
}

}  // namespace fairsurf
