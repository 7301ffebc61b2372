#include <fairsurf/flow/orientation_guard.h>
#include <fairsurf/mesh/errors.h>

#include "parallel.h"

#include <Eigen/Geometry>

#include <string>

namespace fairsurf {
namespace {

Eigen::RowVector3d direction(const Vertices& X, const Faces& F, int f) {
  const Eigen::RowVector3d a = X.row(F(f, 0)), b = X.row(F(f, 1)), c = X.row(F(f, 2));
  return (b - a).cross(c - a);
}

bool turned_over(const Eigen::RowVector3d& n, std::span<const Eigen::MatrixX3d* const> references, Eigen::Index k) {
  for (const Eigen::MatrixX3d* r : references)
    if (!(n.dot(r->row(k)) > 0)) return true;
  return false;
}

}  // namespace

Eigen::MatrixX3d face_directions(const Vertices& X, const Faces& F, std::span<const int> faces) {
  Eigen::MatrixX3d out(static_cast<Eigen::Index>(faces.size()), 3);
#pragma omp parallel for if (detail::worth_parallel(out.rows())) schedule(static)
  for (Eigen::Index k = 0; k < out.rows(); ++k) out.row(k) = direction(X, F, faces[static_cast<std::size_t>(k)]);
  return out;
}

int hold_back_turned_faces(const Vertices& from, Vertices& to, const Faces& F, std::span<const int> faces,
                           std::span<const Eigen::MatrixX3d* const> references, int max_halvings) {
  const auto count = static_cast<Eigen::Index>(faces.size());
  if (from.rows() != to.rows())
    throw InvalidArgument("hold_back_turned_faces: " + std::to_string(from.rows()) + " and " +
                          std::to_string(to.rows()) + " vertices");
  for (const Eigen::MatrixX3d* r : references)
    if (r->rows() != count)
      throw InvalidArgument("hold_back_turned_faces: a reference has " + std::to_string(r->rows()) +
                            " rows for " + std::to_string(count) + " faces");
  // Faces already turned over where the move starts cannot be fixed by holding vertices back.
  std::vector<char> hopeless(faces.size(), 0), held(static_cast<std::size_t>(from.rows()), 0);
  std::vector<int> last_round(static_cast<std::size_t>(from.rows()), -1);  // one halving a round
  for (Eigen::Index k = 0; k < count; ++k)
    hopeless[k] = turned_over(direction(from, F, faces[k]), references, k);
  int held_count = 0;
  // Each round either halves (the first max_halvings rounds) or undoes the move of at least one
  // vertex of every face still turned over, so the loop ends once no face is.
  for (int round = 0;; ++round) {
    std::vector<int> back;
    for (Eigen::Index k = 0; k < count; ++k) {
      if (hopeless[k] || !turned_over(direction(to, F, faces[k]), references, k)) continue;
      for (int c = 0; c < 3; ++c) back.push_back(F(faces[k], c));
    }
    if (back.empty()) break;
    for (int v : back) {
      if (last_round[v] == round || to.row(v) == from.row(v)) continue;
      last_round[v] = round;
      held_count += !held[v];
      held[v] = 1;
      to.row(v) = round < max_halvings ? Eigen::RowVector3d(0.5 * (to.row(v) + from.row(v))) : from.row(v);
    }
  }
  return held_count;
}

}  // namespace fairsurf
