#include <fairsurf/mesh/mesh_attributes.h>
#include <fairsurf/mesh/mesh_operations.h>

namespace fairsurf {
namespace {

template <class Derived>
Eigen::Index append_rows(Eigen::PlainObjectBase<Derived>& out, const Eigen::PlainObjectBase<Derived>& a,
                         const Eigen::PlainObjectBase<Derived>& b) {
  out.resize(a.rows() + b.rows(), a.cols());
  out.topRows(a.rows()) = a;
  out.bottomRows(b.rows()) = b;
  return a.rows();
}

}  // namespace

Mesh concatenate_meshes(const Mesh& first, const Mesh& second) {
  Mesh out;
  append_rows(out.V, first.V, second.V);
  Faces shifted = second.F.array() + first.num_vertices();
  append_rows(out.F, first.F, shifted);
  for (const auto& [name, values] : first.vertex_scalars) {
    const auto other = second.vertex_scalars.find(name);
    if (other == second.vertex_scalars.end()) continue;
    Eigen::VectorXd joined(values.size() + other->second.size());
    joined << values, other->second;
    out.vertex_scalars[name] = joined;
  }
  if (first.vertex_colors.rows() > 0 && second.vertex_colors.rows() > 0)
    append_rows(out.vertex_colors, first.vertex_colors, second.vertex_colors);
  concatenate_attributes(first, second, out);
  return out;
}

}  // namespace fairsurf
