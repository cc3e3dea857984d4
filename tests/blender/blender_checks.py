# Shared by the Blender add-on's tests (import_test.py, watch_test.py): run inside Blender, they
# compare the add-on's objects with the mesh `voxc run` writes.
import subprocess
import sys

import numpy as np

from mesh_files import read_ply  # tests/python, on sys.path

failures = []


def expect(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def cli_mesh(voxc_command, vox, ply):
    subprocess.run([voxc_command, "run", str(vox), "-o", str(ply), "--mesh-on", "host"], check=True, capture_output=True)
    return read_ply(ply)


def check_against_cli(collection, ply):
    """One object per material present: its triangles, vertices and material as voxc run's mesh."""
    ids = np.unique(ply["materials"])
    expect(len(collection.objects) == len(ids), f"{len(collection.objects)} objects for {len(ids)} materials")
    for material_id in ids:
        triangles = ply["triangles"][ply["materials"] == material_id]
        objects = [o for o in collection.objects if o["voxc_material_id"] == int(material_id)]
        expect(len(objects) == 1, f"one object of material {material_id}")
        if not objects:
            continue
        mesh = objects[0].data
        expect(len(mesh.polygons) == len(triangles), f"{objects[0].name}: {len(mesh.polygons)} triangles == {len(triangles)}")
        used = np.unique(triangles)
        expect(len(mesh.vertices) == len(used), f"{objects[0].name}: {len(mesh.vertices)} vertices == {len(used)}")
        co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        expect(np.array_equal(co.reshape(-1, 3), ply["vertices"][used]), f"{objects[0].name}: positions equal voxc's")


def vertex_count(collection):
    return sum(len(o.data.vertices) for o in collection.objects)


def finish():
    """The exit code: 1 with the failures listed."""
    if failures:
        print(f"{len(failures)} failures", file=sys.stderr, flush=True)
        return 1
    return 0
