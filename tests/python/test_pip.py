# The README's set-up installs the module into a virtual environment with pip, offline, from the
# source tree (scripts/python-venv.sh: `pip install --no-build-isolation ./python`, the system's
# site-packages for NumPy). The installed module then works from anywhere after activating the
# environment, with its own copy of libvoxc, and the install compiled nothing: it copied the
# build's extension.
import filecmp
import os
import subprocess
import time

from conftest import EXAMPLES, SOURCE_DIR


def test_venv_install_with_pip(tmp):
    venv = tmp / "venv"
    env = dict(os.environ)  # VOXC_BUILD_DIR: the build whose module is installed
    env.pop("PYTHONPATH", None)  # the build tree's module must not be what gets imported
    start = time.perf_counter()
    install = subprocess.run([SOURCE_DIR / "scripts" / "python-venv.sh", venv], capture_output=True, text=True, env=env)
    seconds = time.perf_counter() - start
    assert install.returncode == 0, install.stdout + install.stderr
    print(f"venv and install: {seconds:.1f} s")

    site = next((venv / "lib").glob("python3*/site-packages/voxc"))
    built = os.path.join(os.environ["VOXC_BUILD_DIR"], "python", "voxc")
    extension = next(site.glob("_native*.so"))
    assert filecmp.cmp(extension, os.path.join(built, extension.name), shallow=False), "the build's extension, copied"
    assert not (site / "libvoxc.so.0").is_symlink()
    assert (site / "libvoxc-openvdb.so").is_file() and not (site / "libvoxc-openvdb.so").is_symlink()

    # As docs/python.md tells a user: activate, then python3 is the environment's.
    script = (
        "import voxc, numpy; print(voxc.__file__); "
        "print([l.split()[-1] for l in open('/proc/self/maps') if 'libvoxc' in l][0]); "
        f"g = voxc.Program({str(EXAMPLES / 'scene.vox')!r}).run(device='interp'); "
        "print(g.density.shape, int((g.density > 0.5).sum()))"
    )
    result = subprocess.run(["bash", "-c", f". {venv}/bin/activate && python3 -c \"$0\"", script],
                            capture_output=True, text=True, env=env, cwd=tmp)
    assert result.returncode == 0, result.stderr
    where, library, shape = result.stdout.splitlines()[:3]
    assert where == str(site / "__init__.py"), where
    assert library == str(site / "libvoxc.so.0"), library
    assert shape.startswith("(96, 64, 96)") and int(shape.split(")")[1]) > 0, shape
