// fairsurf — mesh validation: named findings about a mesh's content, never an exception.
//
// `validate` inspects any Mesh, however broken (NaN coordinates, indices out of range, faces that
// repeat a vertex), and reports every defect as a count plus the first few offending elements.
// It checks indices first and builds the connectivity (topology.h) only on the faces that
// build_topology accepts, so the connectivity findings stay meaningful on a partly broken mesh.
// Commands that need a clean manifold input call `require_valid`, which throws one precise line.
// Every finding is defined in docs/validation.md.
#pragma once

#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>

#include <string>
#include <vector>

namespace fairsurf {

/// What the example indices of a finding refer to.
enum class Element { vertex, face, edge };

/// One kind of defect: how many elements have it and which ones come first.
struct Finding {
  explicit Finding(Element element) : element(element) {}

  Element element;
  int count = 0;
  /// The first offending elements in index order, at most ValidationOptions::max_examples of
  /// them. Vertex and face findings hold one index per example; edge findings hold two vertex
  /// indices per example (a, b with a < b), so examples.size() is 2 * #examples for them.
  std::vector<int> examples;
};

struct ValidationOptions {
  /// Examples kept per finding.
  int max_examples = 5;
  /// A triangle is near-degenerate (a needle or a cap) when 2*area <= tolerance * (longest edge)^2
  /// but its area is not exactly zero. 2*area / longest^2 is the height over the longest edge
  /// relative to that edge; it is sqrt(3)/2 for an equilateral triangle.
  double near_degenerate_tolerance = 1e-12;
};

/// Every defect `validate` looks for. Counts of "duplicate" findings count the elements beyond the
/// first of each group of equal ones, so removing them would leave one of each.
struct ValidationReport {
  int num_vertices = 0;
  int num_faces = 0;
  int num_edges = 0;  ///< undirected edges of the well-formed faces

  // Content of the arrays (checked before any connectivity is built).
  Finding nan_vertices{Element::vertex};          ///< a coordinate is NaN or infinite
  /// Faces holding an index outside [0, #V) (the count is of faces, not of indices).
  Finding out_of_range_indices{Element::face};
  Finding repeated_vertex_faces{Element::face};   ///< a face uses one vertex twice (in range)
  bool no_faces = false;                          ///< the mesh has no face at all

  // Geometry of the well-formed faces (distinct in-range indices, finite corners).
  Finding degenerate_faces{Element::face};        ///< cross product of two edges exactly zero
  Finding near_degenerate_faces{Element::face};   ///< see near_degenerate_tolerance
  /// Same coordinates (exactly, all three) as a lower-index vertex, as in an unwelded soup.
  Finding duplicate_vertex_positions{Element::vertex};

  // Connectivity of the well-formed faces.
  Finding duplicate_faces{Element::face};         ///< same vertex set as a lower-index face
  Finding unreferenced_vertices{Element::vertex}; ///< used by no well-formed face
  Finding non_manifold_edges{Element::edge};      ///< more than two faces
  Finding non_manifold_vertices{Element::vertex}; ///< incident faces form more than one fan
  /// An edge with exactly two faces that both traverse it in the same direction.
  Finding inconsistent_orientation_edges{Element::edge};
  /// Connected components (faces sharing a vertex) whose faces cannot be oriented consistently
  /// across their two-face edges; the examples are faces where propagation met a conflict.
  Finding non_orientable_components{Element::face};

  /// No non-manifold edge or vertex, and every face well-formed.
  bool manifold() const;
  /// Every component can be oriented consistently (the faces may still need flipping).
  bool orientable() const { return non_orientable_components.count == 0; }
  /// Faces exist and no finding has a non-zero count.
  bool is_valid() const;
};

/// Inspects `mesh` and reports every finding. Never throws on bad content.
ValidationReport validate(const Mesh& mesh, const ValidationOptions& options = {});
/// The same on `topo`, the connectivity of mesh.F (build_topology), instead of building it again.
/// Throws InvalidArgument if `topo` has another vertex or face count.
ValidationReport validate(const Mesh& mesh, const Topology& topo, const ValidationOptions& options = {});

/// The faces of `F` that build_topology accepts (every index in [0, num_vertices), three distinct
/// vertices), in their original order; `kept`, if given, receives their indices in `F`.
Faces well_formed_faces(const Faces& F, int num_vertices, std::vector<int>* kept = nullptr);

/// One named finding of a report, in a fixed order, for callers that list them all.
struct NamedFinding {
  const char* key;          ///< stable snake_case name, used as JSON key ("non_manifold_edges")
  const char* singular;     ///< noun phrase for a count of one ("non-manifold edge")
  const char* plural;       ///< noun phrase for other counts ("non-manifold edges")
  const Finding* finding;
};
/// Every Finding of `report` (the `no_faces` flag is not a Finding), in declaration order.
std::vector<NamedFinding> named_findings(const ValidationReport& report);

/// "12, 40, 41" for vertices or faces, "12-57, 3-8" for edges: the first `max` examples.
std::string format_examples(const Finding& finding, int max);

/// What a command needs from its input mesh. Faces must always exist and be well-formed and
/// coordinates finite; the flags add requirements on top.
struct Requirements {
  bool manifold = true;          ///< no non-manifold edges or vertices
  bool oriented = true;          ///< no inconsistently oriented edge, every component orientable
  bool non_degenerate = true;    ///< no zero-area triangle
  bool no_duplicate_faces = true;
};

/// Throws InvalidMeshError if `report` violates `requirements` (RepairableMeshError, a subclass, when
/// repair() removes every violation: all but "no faces" and non-orientable components), with one
/// line naming `caller` and
/// each violated requirement's count and first example:
/// "fill: mesh has 150 non-manifold edges (first: 12-57)".
void require_valid(const ValidationReport& report, const Requirements& requirements,
                   const char* caller);
/// validate(mesh) followed by the check above.
void require_valid(const Mesh& mesh, const Requirements& requirements, const char* caller);

}  // namespace fairsurf
