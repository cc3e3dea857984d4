# Long calls release the GIL, report progress, and stop on Ctrl+C (SIGINT) with KeyboardInterrupt,
# handing out nothing and leaving the program usable.
import os
import signal
import threading
import time

import numpy as np
import pytest

import voxc
from conftest import EXAMPLES, run_cli

# overhang.vox with many more iterations: a run of seconds with a progress step per iteration
# (the interpreter) or per batch of dispatches (Vulkan).
def program_text(iterations):
    text = (EXAMPLES / "overhang.vox").read_text()
    assert "iterations = 6;" in text
    return text.replace("iterations = 6;", f"iterations = {iterations};")


def long_program(iterations):
    return voxc.Program(text=program_text(iterations), name=str(EXAMPLES / "long.vox"))


def test_gil_is_released_during_a_run():
    program = voxc.Program(EXAMPLES / "scene.vox")
    counter = {"n": 0, "stop": False}

    def count():
        while not counter["stop"]:
            counter["n"] += 1

    worker = threading.Thread(target=count)
    worker.start()
    time.sleep(0.05)
    before = counter["n"]
    start = time.perf_counter()
    program.run(device="interp")
    seconds = time.perf_counter() - start
    during = counter["n"] - before
    counter["stop"] = True
    worker.join()
    assert seconds > 0.2, "the run is too short to tell"
    # With the GIL held the counting thread could not run at all during the call.
    assert during > 10000, f"the other thread counted {during} in {seconds:.2f} s"


def test_progress_reports_phases_and_can_stop_a_run():
    seen = []

    def progress(phase, fraction):
        seen.append((phase, fraction))
        return not (phase == "generate" and fraction > 0.6)

    # Two stages, the start and the grammar: the grammar's iterations report from 0.5 to 1.
    program = long_program(400)
    with pytest.raises(voxc.Cancelled):
        program.run(device="interp", progress=progress)
    generate = [f for p, f in seen if p == "generate"]
    assert generate[0] == 0.0 and generate == sorted(generate)
    assert 0.6 < generate[-1] < 0.61 and len([f for f in generate if 0.5 < f < 0.6]) > 10
    assert len(program.run(region=((0, 0, 0), (8, 8, 8)), device="interp").density) == 8


def test_progress_exception_propagates():
    def progress(phase, fraction):
        raise RuntimeError("from the callback")

    with pytest.raises(RuntimeError, match="from the callback"):
        voxc.Program(EXAMPLES / "lsystem_line.vox").run(device="interp", progress=progress)


@pytest.mark.parametrize("device,iterations", [("interp", 400), ("lavapipe", 2500)])
def test_ctrl_c_interrupts_a_long_run(device, iterations, tmp):
    program = long_program(iterations)
    program.run(region=((0, 0, 0), (8, 8, 8)), device=device)  # the Vulkan device made before the clock starts
    sent = []

    def interrupt():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        program.run(device=device)
    latency = time.perf_counter() - sent[0]
    timer.join()
    # The run was still going when Ctrl+C came (a run that had ended would raise nothing in the
    # block above). Nothing was handed out and the program still works: a region of it, as the
    # command line's.
    grid = program.run(region=((0, 0, 0), (16, 16, 16)), device=device)
    (tmp / "long.vox").write_text(program_text(iterations))
    run_cli("run" if device == "lavapipe" else "interp", tmp / "long.vox", "--region", "0,0,0:16,16,16",
            "--voxels", tmp / "long.npy")
    assert np.array_equal(grid.density, np.load(tmp / "long.npy"))
    # Vulkan batches end about every 50 ms while a progress callback (here: the signal check) is
    # set, two in flight; the interpreter looks between grammar iterations (a few ms each).
    print(f"{device}: stopped {latency:.3f} s after Ctrl+C")
    assert latency < 1.0, f"stopped {latency:.2f} s after Ctrl+C"
