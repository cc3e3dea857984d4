# docs/python.md's walk-through, python/examples/walkthrough.py, runs and writes its plots.
import subprocess
import sys

from conftest import SOURCE_DIR


def test_walkthrough_plots(tmp):
    result = subprocess.run([sys.executable, SOURCE_DIR / "python" / "examples" / "walkthrough.py", tmp],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    for png in ("sweep.png", "slice.png"):
        assert (tmp / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "ROCK = 0.7:" in result.stdout and "mesh:" in result.stdout and "LOD 2:" in result.stdout
