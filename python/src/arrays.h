// NumPy arrays in and out of the library's mesh type (mesh.h: row-major Eigen matrices, int faces).
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace fairsurf::python {

namespace py = pybind11;

/// V (float64, #V×3) and F (int32, int64, uint32 or uint64, #F×3) as a Mesh. Throws ValueError
/// naming `V` or `F` for any other dtype or shape, or an index that does not fit the library's int.
Mesh to_mesh(const py::handle& V, const py::handle& F);

/// A 1-D integer array or sequence of vertex indices (values are checked by the library).
std::vector<int> to_indices(const py::handle& indices, const char* name);

/// Hands the matrix to NumPy without copying: the array owns it.
py::array to_numpy(Vertices&& V);
py::array to_numpy(Faces&& F);
py::array to_numpy(Eigen::VectorXd&& values);

/// (V, F) of `mesh`, moved out of it.
py::tuple to_tuple(Mesh&& mesh);

}  // namespace fairsurf::python
