# Shared by the Python binding's tests (ctest python_*): the built voxc command to compare with,
# the source tree. Everything missing here (numpy, the environment ctest
# sets, the module) fails the tests instead of skipping them.
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import voxc  # noqa: F401  (an import error fails every test file)

SOURCE_DIR = Path(os.environ["VOXC_SOURCE_DIR"])
VOXC = os.environ["VOXC"]
EXAMPLES = SOURCE_DIR / "examples"


def run_cli(*args):
    """Runs the voxc command line; its output on failure."""
    result = subprocess.run([VOXC, *map(str, args)], capture_output=True, text=True)
    assert result.returncode == 0, f"voxc {' '.join(map(str, args))} failed:\n{result.stderr}"
    return result


@pytest.fixture
def tmp(tmp_path):
    return tmp_path
