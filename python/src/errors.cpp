#include "errors.h"

#include <fairsurf/mesh/errors.h>

namespace fairsurf::python {

namespace py = pybind11;

void register_errors(py::module_& m) {
  // pybind11 tries translators newest first, so each subclass is registered after its base.
  const auto error = py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  py::register_exception<InvalidArgument>(m, "InvalidArgument", error);
  const auto io = py::register_exception<IoError>(m, "IoError", error);
  py::register_exception<ParseError>(m, "ParseError", io);
  const auto invalid_mesh = py::register_exception<InvalidMeshError>(m, "InvalidMeshError", error);
  py::register_exception<RepairableMeshError>(m, "RepairableMeshError", invalid_mesh);
  py::register_exception<NumericalError>(m, "NumericalError", error);
}

}  // namespace fairsurf::python
