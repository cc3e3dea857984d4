# `pip install --no-build-isolation ./python` into a virtual environment (with the system's
# site-packages for NumPy), offline, from the source tree; the installed module then works from
# anywhere, with its own copy of libvoxc.
import os
import subprocess
import sys

from conftest import EXAMPLES, SOURCE_DIR


def test_venv_install_with_pip(tmp):
    venv = tmp / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv], check=True)
    env = dict(os.environ, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH", None)  # the build tree's module must not be what gets imported
    install = subprocess.run(
        [venv / "bin" / "pip", "install", "--no-build-isolation", SOURCE_DIR / "python"],
        capture_output=True, text=True, env=env,
    )
    assert install.returncode == 0, install.stdout + install.stderr
    script = (
        "import voxc, numpy; print(voxc.__file__); "
        f"g = voxc.Program({str(EXAMPLES / 'scene.vox')!r}).run(device='interp'); "
        "print(g.density.shape, int((g.density > 0.5).sum()))"
    )
    result = subprocess.run([venv / "bin" / "python", "-c", script], capture_output=True, text=True, env=env, cwd=tmp)
    assert result.returncode == 0, result.stderr
    where, shape = result.stdout.splitlines()[:2]
    assert where.startswith(str(venv)), where
    assert shape.startswith("(96, 64, 96)")
