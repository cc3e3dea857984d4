# Program.mesh / Grid.mesh: the arrays of the mesh `voxc run --mesh-on host` writes as .ply, and
# its LOD levels as `voxc run --lod` writes them.
import numpy as np

import voxc
from conftest import EXAMPLES, run_cli
from mesh_files import read_ply


def assert_mesh_equals_ply(mesh, ply):
    assert mesh.vertices.shape == ply["vertices"].shape
    assert np.array_equal(mesh.vertices.view(np.uint32), ply["vertices"].view(np.uint32))
    assert np.array_equal(mesh.normals.view(np.uint32), ply["normals"].view(np.uint32))
    assert np.array_equal(mesh.triangles, ply["triangles"])
    assert np.array_equal(mesh.materials, ply["materials"])


def test_mesh_equals_cli_ply(tmp):
    run_cli("run", EXAMPLES / "scene.vox", "-o", tmp / "scene.ply", "--mesh-on", "host")
    mesh = voxc.Program(EXAMPLES / "scene.vox").mesh(device="lavapipe")
    assert mesh.lod == 0 and len(mesh.triangles) > 1000
    assert mesh.vertices.dtype == np.float32 and mesh.triangles.dtype == np.uint32 and mesh.materials.dtype == np.uint8
    assert_mesh_equals_ply(mesh, read_ply(tmp / "scene.ply"))


def test_lod_levels_equal_cli(tmp):
    run_cli("run", EXAMPLES / "scene.vox", "-o", tmp / "scene.ply", "--lod", "0,1,2")
    grid = voxc.Program(EXAMPLES / "scene.vox").run(device="interp")
    meshes = grid.mesh(lod=[0, 1, 2])
    assert [m.lod for m in meshes] == [0, 1, 2]
    for mesh in meshes:
        assert_mesh_equals_ply(mesh, read_ply(tmp / f"scene.lod{mesh.lod}.ply"))
    assert len(meshes[2].triangles) < len(meshes[1].triangles) < len(meshes[0].triangles)


def test_region_mesh_is_in_world_coordinates(tmp):
    run_cli("run", EXAMPLES / "scene.vox", "--region", "10,3,7:41,40,30", "-o", tmp / "part.ply", "--mesh-on", "host")
    mesh = voxc.Program(EXAMPLES / "scene.vox").mesh(region=((10, 3, 7), (41, 40, 30)), device="interp")
    assert_mesh_equals_ply(mesh, read_ply(tmp / "part.ply"))
