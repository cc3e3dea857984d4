# Program.run: the same bits as the command line's .npy files, on both backends, whole and as a
# region; the arrays are views of libvoxc's grid, not copies; seeds and overrides as the CLI's.
import numpy as np
import pytest

import voxc
from conftest import EXAMPLES, run_cli

# A field scene with features and a grammar, a pure grammar, and an L-system cave.
THREE = ["scene.vox", "overhang.vox", "lsystem_cave.vox"]
BACKENDS = [("lavapipe", "run"), ("interp", "interp")]


def same_bits(a, b):
    return a.shape == b.shape and a.dtype == b.dtype and np.array_equal(a.view(f"u{a.dtype.itemsize}"), b.view(f"u{b.dtype.itemsize}"))


def cli_grid(tmp, verb, path, *extra):
    run_cli(verb, path, "--voxels", tmp / "d.npy", "--materials", tmp / "m.npy", *extra)
    return np.load(tmp / "d.npy"), np.load(tmp / "m.npy")


@pytest.mark.parametrize("device,verb", BACKENDS)
@pytest.mark.parametrize("example", THREE)
def test_run_equals_cli(tmp, example, device, verb):
    density, material = cli_grid(tmp, verb, EXAMPLES / example)
    grid = voxc.Program(EXAMPLES / example).run(device=device)
    assert grid.density.shape == density.shape == grid.size
    assert same_bits(grid.density, density)
    assert same_bits(grid.material, material)


@pytest.mark.parametrize("device,verb", BACKENDS)
def test_region_equals_cli(tmp, device, verb):
    density, material = cli_grid(tmp, verb, EXAMPLES / "scene.vox", "--region", "10,3,7:41,40,30")
    grid = voxc.Program(EXAMPLES / "scene.vox").run(region=((10, 3, 7), (41, 40, 30)), device=device)
    assert grid.origin == (10, 3, 7) and grid.size == (31, 37, 23)
    assert same_bits(grid.density, density)
    assert same_bits(grid.material, material)


def test_arrays_view_the_grid_without_copying():
    grid = voxc.Program(EXAMPLES / "overhang.vox").run(device="interp")
    density = grid.density
    assert density.dtype == np.float32 and density.flags.f_contiguous and not density.flags.owndata
    # Two reads are views of the same memory, which outlives the Grid object.
    again = grid.density
    assert np.shares_memory(density, again)
    del grid
    assert density.sum() > 0


def test_seed_equals_cli(tmp):
    density, _ = cli_grid(tmp, "interp", EXAMPLES / "scene.vox", "--seed", "9")
    grid = voxc.Program(EXAMPLES / "scene.vox", seed=9).run(device="interp")
    assert same_bits(grid.density, density)


def test_const_and_feature_overrides_equal_edited_text():
    text = (EXAMPLES / "scene.vox").read_text()
    name = str(EXAMPLES / "scene.vox")
    edited = text.replace("const ROCK = 0.5;", "const ROCK = 0.4;").replace("peak = 10;", "peak = 7;")
    assert edited != text
    expected = voxc.Program(text=edited, name=name).run(device="interp")
    overridden = voxc.Program(EXAMPLES / "scene.vox", overrides={"ROCK": 0.4, "bridge.peak": 7}).run(device="interp")
    plain = voxc.Program(EXAMPLES / "scene.vox").run(device="interp")
    assert same_bits(overridden.density, expected.density)
    assert not same_bits(overridden.density, plain.density)


def test_unknown_feature_override_is_a_user_error():
    with pytest.raises(voxc.UserError, match="no feature 'nowhere'"):
        voxc.Program(EXAMPLES / "scene.vox", overrides={"nowhere.peak": 3})


def test_bad_arguments_raise_value_error():
    program = voxc.Program(EXAMPLES / "lsystem_line.vox")
    with pytest.raises(ValueError):
        program.run(device="quantum")
    with pytest.raises(ValueError):
        program.run(region=((0, 0, 0), (0, 4, 4)))


def test_package(tmp):
    run_cli("compile", EXAMPLES / "overhang.vox", "-o", tmp / "pkg")
    program = voxc.Program(package=str(tmp / "pkg"))
    assert same_bits(program.run(device="interp").density, voxc.Program(EXAMPLES / "overhang.vox").run(device="interp").density)
