"""fairsurf: fair surfaces on triangle meshes with sixth-order geometric flows.

NumPy in and out: V is a float64 array of shape (n, 3), F an int32, int64, uint32 or uint64 array of shape (m, 3).
Reports are dicts with the fields of the CLI's JSON logs. See docs/python.md.
"""

from ._fairsurf import (  # noqa: F401  (the public API)
    Error,
    InvalidArgument,
    InvalidMeshError,
    IoError,
    NumericalError,
    ParseError,
    RepairableMeshError,
    blend,
    curvature,
    fair,
    fill_holes,
    info,
    read_mesh,
    render,
    repair,
    scene,
    smooth,
    write_mesh,
)

__all__ = [
    "Error", "InvalidArgument", "InvalidMeshError", "IoError", "NumericalError", "ParseError",
    "RepairableMeshError", "blend", "curvature", "fair", "fill_holes", "info", "read_mesh", "render",
    "repair", "scene", "smooth", "write_mesh",
]
