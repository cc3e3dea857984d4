"""voxc from Python: check, generate and mesh .vox files, with NumPy arrays (docs/python.md).

    import voxc
    program = voxc.Program("examples/scene.vox", seed=7, overrides={"height": 20})
    grid = program.run()                      # or run(region=((0, 0, 0), (32, 32, 32)), device="interp")
    grid.density[x, y, z]                     # float32, as `voxc run --voxels` writes it
    mesh = grid.mesh()                        # vertices, normals, triangles, materials
    for d in voxc.check("broken.vox"):        # Diagnostic objects; no exception for the file's errors
        print(d.file, d.line, d.column, d.code, d.message)

The calls run in libvoxc (the C API) with the GIL released; Ctrl+C stops them with
KeyboardInterrupt, and a `progress(phase, fraction)` callback may return False to stop them.
"""
from ._native import (
    Cancelled,
    Diagnostic,
    Error,
    Grid,
    InternalError,
    Mesh,
    Program,
    UserError,
    __version__,
    check,
)

__all__ = [
    "Cancelled",
    "Diagnostic",
    "Error",
    "Grid",
    "InternalError",
    "Mesh",
    "Program",
    "UserError",
    "__version__",
    "check",
]
