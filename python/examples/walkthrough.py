"""docs/python.md's walk-through as one script: sweep a constant, plot a slice, mesh to arrays.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/walkthrough.py [OUT_DIR]

Writes OUT_DIR/sweep.png and OUT_DIR/slice.png (default: out/) and prints what it measured.
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files, no window; drop this line in a notebook
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import voxc  # noqa: E402

root = Path(__file__).resolve().parents[2]
scene = root / "examples" / "scene.vox"
out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)

# 1. Check first: diagnostics are objects, and a file with errors raises nothing here.
for d in voxc.check(scene):
    print(f"{d.file}:{d.line}:{d.column}: {d.severity} {d.code}: {d.message}")

# 2. Sweep a constant: ROCK is the grammar's rock/air threshold in scene.vox. Each value is
#    checked as if the file said `const ROCK = value;` (what `voxc view`'s sliders do).
values = [0.3, 0.4, 0.5, 0.6, 0.7]
solid = []
for value in values:
    grid = voxc.Program(scene, overrides={"ROCK": value}).run(device="interp")
    solid.append(int((grid.density > 0.5).sum()))
    print(f"ROCK = {value}: {solid[-1]} solid voxels")
fig, ax = plt.subplots(figsize=(5, 3))
ax.plot(values, solid, marker="o")
ax.set_xlabel("ROCK")
ax.set_ylabel("solid voxels")
fig.tight_layout()
fig.savefig(out / "sweep.png", dpi=100)

# 3. A slice: density[x, y, z] as `voxc run --voxels` writes it; a slice at z through the arch.
program = voxc.Program(scene)
grid = program.run()
z = 48
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
axes[0].imshow(grid.density[:, :, z].T, origin="lower", cmap="gray")  # x across, y up
axes[0].set_title(f"density, z = {z}")
names = program.materials
image = axes[1].imshow(grid.material[:, :, z].T, origin="lower", cmap="tab10", vmin=0, vmax=9)
axes[1].set_title("material id")
fig.colorbar(image, ax=axes[1], ticks=sorted(names), format=matplotlib.ticker.FuncFormatter(lambda i, _: names.get(int(i), "")))
fig.tight_layout()
fig.savefig(out / "slice.png", dpi=100)

# 4. Mesh to arrays, trimesh-style: vertices (n, 3), faces (m, 3), a material per face.
mesh = grid.mesh()
vertices, faces, face_materials = mesh.vertices, mesh.triangles, mesh.materials
print(f"mesh: {len(vertices)} vertices, {len(faces)} triangles")
for material_id, count in zip(*np.unique(face_materials, return_counts=True)):
    print(f"  {names.get(int(material_id), 'none')}: {count} triangles")
# e.g. trimesh.Trimesh(vertices=vertices, faces=faces, vertex_normals=mesh.normals), if installed
coarse = grid.mesh(lod=2)
print(f"LOD 2: {len(coarse.triangles)} triangles")
