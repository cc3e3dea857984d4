"""What the Python module adds over libvoxc's C API for one 256^3 region (docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/python/region_overhead.py [ROUNDS]

One process, alternating: the C API called directly (ctypes, the grid's densities wrapped as a
NumPy array without a copy) and voxc.Program.run (the same library through the module, the
arrays views of the grid), each on its own program whose Vulkan pipelines were made by a first,
untimed region, taking turns going first; then what a copy of the densities would cost. Prints
medians in milliseconds.
"""
import ctypes
import statistics
import sys
import time

import numpy as np

import voxc

ROUNDS = int(sys.argv[1]) if len(sys.argv) > 1 else 3
TEXT = """
world { size = [288, 288, 288]; chunk = 32; seed = 3; }
field ground = clamp(140 + 40 * fbm(vec3(wx, 0, wz) * 0.01, 5, 2.0, 0.5, 3) - y, 0, 1);
pipeline { start; set ground; }
"""
LO, HI = (16, 16, 16), (272, 272, 272)  # 256^3

capi = ctypes.CDLL("libvoxc.so.0")  # the library the module loaded
capi.voxc_last_error.restype = ctypes.c_char_p
capi.voxc_grid_densities.restype = ctypes.POINTER(ctypes.c_float)
Vec3 = ctypes.c_int32 * 3


def c_program():
    program = ctypes.c_void_p()
    text = TEXT.encode()
    status = capi.voxc_program_load_source(b"bench.vox", text, ctypes.c_size_t(len(text)), None, ctypes.byref(program))
    assert status == 0, capi.voxc_last_error()
    return program


def c_region(program):
    grid = ctypes.c_void_p()
    status = capi.voxc_generate_region(program, Vec3(*LO), Vec3(*HI), 0, ctypes.byref(grid))
    assert status == 0, capi.voxc_last_error()
    size = Vec3()
    capi.voxc_grid_size(grid, size)
    pointer = capi.voxc_grid_densities(grid)
    density = np.ctypeslib.as_array(pointer, shape=(size[2], size[1], size[0])).T  # [x, y, z], no copy
    return grid, density


def timed(call):
    start = time.perf_counter()
    result = call()
    return (time.perf_counter() - start) * 1000, result


c = c_program()
py = voxc.Program(text=TEXT, name="bench.vox")
capi.voxc_grid_free(c_region(c)[0])  # pipelines and SPIR-V made, untimed
py.run(region=(LO, HI), device="auto")
c_ms, py_ms, view_ms, copy_ms = [], [], [], []
for round in range(ROUNDS):
    # Each round starts with no grid alive, and the two take turns going first.
    def c_side():
        ms, (grid, c_density) = timed(lambda: c_region(c))
        c_ms.append(ms)
        total = float(c_density.sum())
        capi.voxc_grid_free(grid)
        return total

    def py_side():
        ms, result = timed(lambda: py.run(region=(LO, HI), device="auto"))
        py_ms.append(ms)
        ms, density = timed(lambda: result.density)
        view_ms.append(ms)
        ms, _ = timed(lambda: np.array(density))
        copy_ms.append(ms)
        return float(density.sum())

    sides = (c_side, py_side) if round % 2 == 0 else (py_side, c_side)
    assert sides[0]() == sides[1]()
med = statistics.median
print(f"256^3 region, {ROUNDS} rounds, medians: C API {med(c_ms):.0f} ms, voxc.Program.run {med(py_ms):.0f} ms "
      f"(ratio {med(py_ms) / med(c_ms):.3f}); .density view {med(view_ms) * 1000:.0f} us; a copy of it {med(copy_ms):.0f} ms")
