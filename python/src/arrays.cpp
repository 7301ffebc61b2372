#include "arrays.h"

#include <limits>
#include <string>
#include <utility>

namespace fairsurf::python {
namespace {

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d > 0 ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

py::array as_array(const py::handle& object, const char* name) {
  if (!py::isinstance<py::array>(object))
    throw py::value_error(std::string(name) + " must be a NumPy array, got " +
                          std::string(py::str(py::type::of(object).attr("__name__"))));
  return py::reinterpret_borrow<py::array>(object);
}

void check_n_by_3(const py::array& a, const char* name) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(std::string(name) + " must have shape (n, 3), got " + shape_text(a));
}

// The rows of `a` (C-contiguous or not) copied into the library's row-major matrix: the one copy
// every call makes, since the library's functions take owning Eigen matrices (mesh.h).
template <class Matrix, class Scalar>
Matrix copy_rows(const py::array& a) {
  const auto c = py::array_t<Scalar, py::array::c_style>::ensure(a);  // no copy when already C order
  return Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, 3, Eigen::RowMajor>>(c.data(), c.shape(0), 3)
      .template cast<typename Matrix::Scalar>();
}

// Faces from a wider or unsigned index type, each index checked against the library's int.
template <class Index>
Faces faces_checked(const py::array& a) {
  const auto c = py::array_t<Index, py::array::c_style>::ensure(a);
  const Index* data = c.data();
  for (py::ssize_t i = 0; i < c.size(); ++i)
    if (!std::in_range<int>(data[i]))
      throw py::value_error("F: index " + std::to_string(data[i]) + " at face " + std::to_string(i / 3) +
                            " does not fit a 32-bit int");
  return copy_rows<Faces, Index>(c);
}

}  // namespace

Mesh to_mesh(const py::handle& V_object, const py::handle& F_object) {
  const py::array V = as_array(V_object, "V");
  const py::array F = as_array(F_object, "F");
  // NumPy's own equivalence, not the identity of the dtype object: an array that went through
  // pickle (multiprocessing, a saved object) carries an equal float64 that is another object.
  if (!py::isinstance<py::array_t<double>>(V))
    throw py::value_error("V must have dtype float64, got " + std::string(py::str(V.dtype())));
  check_n_by_3(V, "V");
  // Unsigned indices too: PLY readers and VTK hand out uint32 faces.
  const bool int32 = py::isinstance<py::array_t<std::int32_t>>(F);
  const bool int64 = py::isinstance<py::array_t<std::int64_t>>(F);
  const bool uint32 = py::isinstance<py::array_t<std::uint32_t>>(F);
  const bool uint64 = py::isinstance<py::array_t<std::uint64_t>>(F);
  if (!int32 && !int64 && !uint32 && !uint64)
    throw py::value_error("F must have dtype int32, int64, uint32 or uint64, got " + std::string(py::str(F.dtype())));
  check_n_by_3(F, "F");
  Mesh mesh;
  mesh.V = copy_rows<Vertices, double>(V);
  mesh.F = int32    ? copy_rows<Faces, std::int32_t>(F)
           : int64  ? faces_checked<std::int64_t>(F)
           : uint32 ? faces_checked<std::uint32_t>(F)
                    : faces_checked<std::uint64_t>(F);
  return mesh;
}

std::vector<int> to_indices(const py::handle& indices, const char* name) {
  const py::array a = py::array::ensure(indices);
  if (!a || a.ndim() != 1 || (a.size() > 0 && a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
    throw py::value_error(std::string(name) + " must be a 1-D sequence of integer vertex indices");
  const auto values = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  std::vector<int> out;
  out.reserve(values.size());
  for (py::ssize_t i = 0; i < values.size(); ++i) {
    const std::int64_t v = values.data()[i];
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      throw py::value_error(std::string(name) + ": index " + std::to_string(v) + " does not fit a 32-bit int");
    out.push_back(static_cast<int>(v));
  }
  return out;
}

namespace {

template <class Matrix>
py::array owning_array(Matrix&& matrix) {
  auto* owned = new Matrix(std::move(matrix));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<Matrix*>(p); });
  std::vector<py::ssize_t> shape{owned->rows()};
  if (Matrix::ColsAtCompileTime != 1) shape.push_back(owned->cols());
  return py::array_t<typename Matrix::Scalar>(shape, owned->data(), free_when_done);
}

}  // namespace

py::array to_numpy(Vertices&& V) { return owning_array(std::move(V)); }
py::array to_numpy(Faces&& F) { return owning_array(std::move(F)); }
py::array to_numpy(Eigen::VectorXd&& values) { return owning_array(std::move(values)); }

py::tuple to_tuple(Mesh&& mesh) { return py::make_tuple(to_numpy(std::move(mesh.V)), to_numpy(std::move(mesh.F))); }

}  // namespace fairsurf::python
