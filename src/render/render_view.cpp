// Views: the fixed camera directions of render.h and their names.
#include "render_internal.h"

#include <fairsurf/mesh/errors.h>

#include <Eigen/Geometry>

#include <array>
#include <utility>

namespace fairsurf {
namespace {

struct ViewSpec {
  View view;
  const char* name;
  Eigen::Vector3d toward;  ///< from the scene to the camera
  Eigen::Vector3d up_hint;
};

const std::array<ViewSpec, 7>& view_specs() {
  static const std::array<ViewSpec, 7> specs{{
      {View::front, "front", {0, 0, 1}, {0, 1, 0}},
      {View::back, "back", {0, 0, -1}, {0, 1, 0}},
      {View::left, "left", {-1, 0, 0}, {0, 1, 0}},
      {View::right, "right", {1, 0, 0}, {0, 1, 0}},
      {View::top, "top", {0, 1, 0}, {0, 0, -1}},
      {View::bottom, "bottom", {0, -1, 0}, {0, 0, 1}},
      {View::iso, "iso", {1, 1, 1}, {0, 1, 0}},
  }};
  return specs;
}

std::string valid_view_names() {
  std::string names;
  for (const auto& spec : view_specs()) names += (names.empty() ? "" : ", ") + std::string(spec.name);
  return names;
}

}  // namespace

std::string view_name(View view) {
  for (const auto& spec : view_specs())
    if (spec.view == view) return spec.name;
  throw InvalidArgument("view_name: unknown view value");
}

View view_from_name(const std::string& name) {
  for (const auto& spec : view_specs())
    if (name == spec.name) return spec.view;
  throw InvalidArgument("view_from_name: unknown view '" + name + "' (valid: " + valid_view_names() +
                        ")");
}

namespace render_detail {

Eigen::Matrix3d view_rotation(View view) {
  for (const auto& spec : view_specs()) {
    if (spec.view != view) continue;
    const Eigen::Vector3d toward = spec.toward.normalized();
    const Eigen::Vector3d up = (spec.up_hint - spec.up_hint.dot(toward) * toward).normalized();
    Eigen::Matrix3d rotation;
    rotation.row(0) = up.cross(toward);  // right, so that right x up = toward
    rotation.row(1) = up;
    rotation.row(2) = toward;
    return rotation;
  }
  throw InvalidArgument("view_rotation: unknown view value");
}

}  // namespace render_detail
}  // namespace fairsurf
