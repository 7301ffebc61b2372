// The library's exceptions (errors.h) as a Python hierarchy: fairsurf.Error ⊃ InvalidArgument,
// IoError ⊃ ParseError, InvalidMeshError ⊃ RepairableMeshError, NumericalError.
#pragma once

#include <pybind11/pybind11.h>

namespace fairsurf::python {

void register_errors(pybind11::module_& m);

}  // namespace fairsurf::python
