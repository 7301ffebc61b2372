// fairsurf._fairsurf: the extension behind `import fairsurf` (python/fairsurf/__init__.py).
#include "errors.h"
#include "functions.h"

PYBIND11_MODULE(_fairsurf, m) {
  m.doc() = "Fair surfaces on triangle meshes with sixth-order geometric flows (docs/python.md)";
  fairsurf::python::register_errors(m);
  fairsurf::python::register_mesh_functions(m);
  fairsurf::python::register_flow_functions(m);
  fairsurf::python::register_render_functions(m);
}
