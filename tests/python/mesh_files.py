# voxc's binary PLY meshes as NumPy arrays, for the Python and Blender tests.
from pathlib import Path

import numpy as np


def read_ply(path):
    """voxc's binary PLY (runtime/mesh/src/Ply.cpp): positions, normals, triangles, triangle materials."""
    data = Path(path).read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    vertex_count = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    face_count = int(next(l for l in header if l.startswith("element face")).split()[2])
    with_materials = "property uchar material" in header
    vertex_fields = [("p", "<f4", 3), ("n", "<f4", 3)]
    if with_materials:
        vertex_fields += [("material", "u1"), ("rgb", "u1", 3)]
    vertices = np.frombuffer(data, dtype=np.dtype(vertex_fields), count=vertex_count, offset=end)
    face_fields = [("k", "u1"), ("i", "<i4", 3)] + ([("material", "u1")] if with_materials else [])
    faces = np.frombuffer(data, dtype=np.dtype(face_fields), count=face_count, offset=end + vertices.nbytes)
    assert (faces["k"] == 3).all()
    return {
        "vertices": vertices["p"],
        "normals": vertices["n"],
        "triangles": faces["i"].astype(np.uint32),
        "materials": faces["material"] if with_materials else None,
    }
