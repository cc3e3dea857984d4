# Headless test of the Blender add-on (editors/blender/voxc_import), run as
#   blender -b --factory-startup --python-exit-code 1 --python import_test.py -- VOXC SOURCE_DIR WORK_DIR
# with VOXC_PYTHONPATH naming the built module. Imports examples/scene.vox and checks its objects,
# materials and vertex and triangle counts against the mesh `voxc run` writes, and the seed, region
# and LOD options likewise; then that a saved edit is imported again by the watch, and that a file
# with errors is reported with file:line.
import shutil
import subprocess
import sys
import time
from pathlib import Path

import bpy
import numpy as np

voxc_command, source_dir, work = sys.argv[sys.argv.index("--") + 1:]
source_dir, work = Path(source_dir), Path(work)
sys.path.insert(0, str(source_dir / "editors" / "blender"))
sys.path.insert(0, str(source_dir / "tests" / "python"))
sys.path.insert(0, str(source_dir / "tests" / "blender"))
import voxc_import  # noqa: E402
from mesh_files import read_ply  # noqa: E402

from blender_checks import check_against_cli, cli_mesh, expect, finish, vertex_count  # noqa: E402

voxc_import.register()


# examples/scene.vox: objects, materials and counts.
scene = work / "scene.vox"
shutil.copy(source_dir / "examples" / "scene.vox", scene)
bpy.ops.import_scene.voxc(filepath=str(scene), device="lavapipe", watch=True)
collection = bpy.data.collections["scene"]
ply = cli_mesh(voxc_command, scene, work / "scene.ply")
check_against_cli(collection, ply)
declared = {"dirt": (0.45, 0.33, 0.22), "bedrock": (0.38, 0.38, 0.40), "sandstone": (0.80, 0.58, 0.40),
            "sand": (0.90, 0.82, 0.58), "grass": (0.33, 0.55, 0.22)}
for obj in collection.objects:
    material = obj.data.materials[0]
    name = material.name.split(".")[-1]
    expect(name in declared and np.allclose(material.diffuse_color[:3], declared[name]),
           f"{obj.name}: material {material.name} in the .vox's colour {tuple(material.diffuse_color[:3])}")

# The options: a region at LOD 1 and another seed, as `voxc run --region --lod 1 --seed` meshes it.
bpy.ops.import_scene.voxc(filepath=str(scene), device="interp", use_seed=True, seed=9, use_region=True,
                          region_min=(8, 0, 8), region_max=(72, 48, 72), lod=1)
subprocess.run([voxc_command, "run", str(scene), "--region", "8,0,8:72,48,72", "--lod", "1", "--seed", "9",
                "-o", str(work / "part.ply")], check=True, capture_output=True)
check_against_cli(collection, read_ply(work / "part.lod1.ply"))

# The watch's check, called here directly (watch_test.py lets Blender's timer call it): a saved
# edit is imported again, replacing the objects.
bpy.ops.import_scene.voxc(filepath=str(scene), device="lavapipe", watch=True)
before = vertex_count(collection)
expect(voxc_import.reimport_changed() == [], "nothing imported again while the file is unchanged")
time.sleep(0.01)
scene.write_text(scene.read_text().replace("peak = 10;", "peak = 6;"))
expect(voxc_import.reimport_changed() == ["scene"], "the saved file imported again")
check_against_cli(collection, cli_mesh(voxc_command, scene, work / "scene2.ply"))
after = vertex_count(collection)
expect(after != before, f"the edit changed the mesh ({before} -> {after} vertices)")

# A file with errors: a Blender error report with file:line:col, and the last good objects stay.
scene.write_text(scene.read_text().replace("field ground = clamp(", "field ground = clam("))
try:
    voxc_import.reimport_changed()
    expect(False, "an error report for the broken file")
except RuntimeError as error:
    expect(f"{scene}:" in str(error) and "error E0" in str(error), f"reported: {str(error).splitlines()[0]}")
expect(vertex_count(collection) == after, "the last good objects stay")

if finish():
    sys.exit(1)
print("blender import test passed")
