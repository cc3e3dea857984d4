# The Blender add-on's watch, live: Blender runs its event loop (a window on a virtual display,
# xvfb-run), the add-on's own timer notices each save and imports the file again. Run as
#   xvfb-run -a blender --factory-startup --python-exit-code 1 --python watch_test.py -- VOXC SOURCE_DIR WORK_DIR
# with VOXC_PYTHONPATH naming the built module. The script imports a copy of examples/scene.vox
# with Watch on and returns; a timer of its own then saves edits as an editor does (a new file
# renamed over the old one, and a write in place) and waits for the objects to change, checks
# them against `voxc run`, saves a file with errors and waits for the add-on's located error
# report, the objects left alone; then exits Blender with the result.
import io
import os
import shutil
import sys
import threading
import time
import traceback
from pathlib import Path

import bpy

voxc_command, source_dir, work = sys.argv[sys.argv.index("--") + 1:]
source_dir, work = Path(source_dir), Path(work)
sys.path.insert(0, str(source_dir / "editors" / "blender"))
sys.path.insert(0, str(source_dir / "tests" / "python"))
sys.path.insert(0, str(source_dir / "tests" / "blender"))
import voxc_import  # noqa: E402
from blender_checks import check_against_cli, cli_mesh, expect, finish, vertex_count  # noqa: E402

WAIT_SECONDS = 120  # for one re-import: lavapipe on a loaded machine


def leave(code):
    print(f"blender watch test {'passed' if code == 0 else 'failed'}", flush=True)
    sys.stderr.flush()
    os._exit(code)


# Blender's event loop must keep running the timers; if it does not, nothing else ends the test.
threading.Timer(4 * WAIT_SECONDS, lambda: (print("FAIL the test did not finish", flush=True), leave(2))).start()


class Recorded(io.TextIOBase):
    """sys.stderr, keeping a copy: where the watch prints the import's error reports."""

    def __init__(self, stream):
        self.stream, self.text = stream, ""

    def write(self, text):
        self.text += text
        return self.stream.write(text)

    def flush(self):
        self.stream.flush()


errors = Recorded(sys.stderr)
sys.stderr = errors

voxc_import.register()
scene = work / "scene.vox"
shutil.copy(source_dir / "examples" / "scene.vox", scene)
bpy.ops.import_scene.voxc(filepath=str(scene), device="lavapipe", watch=True)
collection = bpy.data.collections["scene"]
expect(bpy.app.timers.is_registered(voxc_import.watch_files), "Watch on: the add-on's timer is registered")


def save(text, in_place):
    if in_place:
        scene.write_text(text)
    else:  # as most editors save: a new file, renamed over the old one
        (work / "scene.vox.new").write_text(text)
        os.replace(work / "scene.vox.new", scene)


def saved_edits():
    """The steps, as a generator: each yield is the seconds until the timer calls it again."""
    before = vertex_count(collection)
    text = scene.read_text()
    for n, (old, new, in_place) in enumerate([("peak = 10;", "peak = 6;", False), ("peak = 6;", "peak = 8;", True)]):
        assert old in text
        text = text.replace(old, new)
        yield 1.0  # a save within the same mtime tick as the import would not count as a change
        save(text, in_place)
        start = time.monotonic()
        while vertex_count(collection) == before and time.monotonic() - start < WAIT_SECONDS:
            yield 0.2
        after = vertex_count(collection)
        how = "written in place" if in_place else "renamed over the old file"
        expect(after != before, f"the watch imported the saved edit ({how}) after {time.monotonic() - start:.1f} s "
                                f"({before} -> {after} vertices)")
        check_against_cli(collection, cli_mesh(voxc_command, scene, work / f"edit{n}.ply"))
        before = after

    # A file with errors: the watch's report names the file, line and code; the objects stay.
    save(text.replace("field ground = clamp(", "field ground = clam("), in_place=False)
    start = time.monotonic()
    while f"{scene}:" not in errors.text and time.monotonic() - start < WAIT_SECONDS:
        yield 0.2
    located = [line for line in errors.text.splitlines() if f"{scene}:" in line]
    expect(bool(located) and "error E0" in located[0], f"the error reported: {located[:1]}")
    yield 1.5  # three more looks of the watch: the broken file is reported once and imported never
    expect(vertex_count(collection) == before, "the last good objects stay")
    expect(errors.text.count(f"{scene}:") == len(located), "reported once per save")


steps = saved_edits()


def drive():
    try:
        return next(steps)
    except StopIteration:
        leave(finish())
    except Exception:
        traceback.print_exc()
        leave(1)


bpy.app.timers.register(drive, first_interval=0.5)
