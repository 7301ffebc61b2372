// Registration of the module's functions, one group per file (docs/python.md lists them).
#pragma once

#include <pybind11/pybind11.h>

namespace fairsurf::python {

void register_mesh_functions(pybind11::module_& m);    // read_mesh, write_mesh, info, curvature, repair, scene
void register_flow_functions(pybind11::module_& m);    // smooth, fill_holes, fair, blend
void register_render_functions(pybind11::module_& m);  // render

}  // namespace fairsurf::python
