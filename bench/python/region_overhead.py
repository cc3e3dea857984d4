"""What the Python module adds over libvoxc's C API (docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/python/region_overhead.py [ROUNDS] [region|iterations]

`region` (the default): one 256^3 region of an fbm terrain, a few large dispatches. `iterations`:
examples/overhang.vox with 1000 grammar iterations, 64^3, some 19 000 small dispatches.

One process, three ways in turn, each on its own program whose Vulkan pipelines were made by a
first, untimed run, taking turns going first: the C API called directly (ctypes, the grid's
densities wrapped as a NumPy array without a copy), the same with a progress callback set (as
the module always sets one, to see Ctrl+C: batches then sized to about 50 ms), and
voxc.Program.run (the same library through the module, the arrays views of the grid); then what
a copy of the densities would cost. Prints medians in milliseconds.
"""
import ctypes
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import voxc

ROUNDS = int(sys.argv[1]) if len(sys.argv) > 1 else 3
CASE = sys.argv[2] if len(sys.argv) > 2 else "region"
if CASE == "region":
    TEXT = """
world { size = [288, 288, 288]; chunk = 32; seed = 3; }
field ground = clamp(140 + 40 * fbm(vec3(wx, 0, wz) * 0.01, 5, 2.0, 0.5, 3) - y, 0, 1);
pipeline { start; set ground; }
"""
    BOX = ((16, 16, 16), (272, 272, 272))  # 256^3
else:
    TEXT = (Path(__file__).resolve().parents[2] / "examples" / "overhang.vox").read_text()
    TEXT = TEXT.replace("iterations = 6;", "iterations = 1000;")
    BOX = None  # the whole grid

capi = ctypes.CDLL("libvoxc.so.0")  # the library the module loaded
capi.voxc_last_error.restype = ctypes.c_char_p
capi.voxc_grid_densities.restype = ctypes.POINTER(ctypes.c_float)
Vec3 = ctypes.c_int32 * 3
Progress = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_double)
keep_going = Progress(lambda user, phase, fraction: 0)


def c_program():
    program = ctypes.c_void_p()
    text = TEXT.encode()
    status = capi.voxc_program_load_source(b"bench.vox", text, ctypes.c_size_t(len(text)), None, ctypes.byref(program))
    assert status == 0, capi.voxc_last_error()
    return program


def c_run(program, progress):
    grid = ctypes.c_void_p()
    capi.voxc_set_progress(progress, None)
    if BOX:
        status = capi.voxc_generate_region(program, Vec3(*BOX[0]), Vec3(*BOX[1]), 0, ctypes.byref(grid))
    else:
        status = capi.voxc_generate(program, 0, ctypes.byref(grid))
    capi.voxc_set_progress(None, None)
    assert status == 0, capi.voxc_last_error()
    size = Vec3()
    capi.voxc_grid_size(grid, size)
    pointer = capi.voxc_grid_densities(grid)
    density = np.ctypeslib.as_array(pointer, shape=(size[2], size[1], size[0])).T  # [x, y, z], no copy
    return grid, density


cpu = {}  # the process's CPU time (every thread: lavapipe's too) per way, steadier than wall time on a loaded machine


def timed(call, name=None):
    start, start_cpu = time.perf_counter(), time.process_time()
    result = call()
    if name:
        cpu.setdefault(name, []).append((time.process_time() - start_cpu) * 1000)
    return (time.perf_counter() - start) * 1000, result


ms = {"C API": [], "C API + progress": [], "Program.run": [], "view": [], "copy": []}


def c_side(program, progress, name):
    def side():
        took, (grid, density) = timed(lambda: c_run(program, progress), name)
        ms[name].append(took)
        total = float(density.sum())
        capi.voxc_grid_free(grid)
        return total
    return side


def py_side(program):
    def side():
        took, result = timed(lambda: program.run(region=BOX, device="auto"), "Program.run")
        ms["Program.run"].append(took)
        took, density = timed(lambda: result.density)
        ms["view"].append(took)
        took, _ = timed(lambda: np.array(density))
        ms["copy"].append(took)
        return float(density.sum())
    return side


plain, with_progress = c_program(), c_program()
py = voxc.Program(text=TEXT, name="bench.vox")
sides = [c_side(plain, None, "C API"), c_side(with_progress, keep_going, "C API + progress"), py_side(py)]
for side in sides:  # pipelines and SPIR-V made, untimed
    side()
for values in (*ms.values(), *cpu.values()):
    values.clear()
for turn in range(ROUNDS):
    # Each round starts with no grid alive, and the three take turns going first.
    order = sides[turn % 3:] + sides[:turn % 3]
    totals = [side() for side in order]
    assert totals[0] == totals[1] == totals[2]
med = {key: statistics.median(values) for key, values in ms.items()}
print(f"{CASE}, {ROUNDS} rounds, medians: C API {med['C API']:.0f} ms, with a progress callback "
      f"{med['C API + progress']:.0f} ms ({med['C API + progress'] / med['C API']:.3f}), voxc.Program.run "
      f"{med['Program.run']:.0f} ms ({med['Program.run'] / med['C API']:.3f}); .density view "
      f"{med['view'] * 1000:.0f} us; a copy of it {med['copy']:.0f} ms")
print("CPU time, medians (ms):", {key: round(statistics.median(values)) for key, values in cpu.items()})
print("wall, all rounds (ms):", {key: [round(v) for v in values] for key, values in ms.items() if key not in ("view", "copy")})
