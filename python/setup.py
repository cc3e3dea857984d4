"""pip install --no-build-isolation ./python: the module voxc from a voxc build.

The build (scripts/build.sh: VOXC_LIBVOXC=ON, VOXC_PYTHON=ON) already compiled the extension,
build/python/voxc/_native*.so, for the Python it was configured with; installing copies it and
libvoxc.so.0 (with the OpenVDB module libvoxc loads when first needed) instead of compiling the module a second time (seconds instead of a minute or two on
2 cores). The build directory is build/ beside this folder, or the one VOXC_BUILD_DIR names. The
extension finds libvoxc beside itself (rpath $ORIGIN), so the installed package keeps working when
the build tree changes or goes. Only setuptools (Debian's python3-setuptools) is needed, no
network. docs/python.md.
"""
import os
import shutil
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

here = Path(__file__).resolve().parent
root = here.parent
build_dir = Path(os.environ.get("VOXC_BUILD_DIR", root / "build")).resolve()
built_package = build_dir / "python" / "voxc"
# What the extension is compiled from: a newer one means the build is out of date.
sources = [here / "src" / "module.cpp", root / "runtime" / "capi" / "include" / "voxc" / "voxc.h"]


class CopyBuiltExtension(build_ext):
    """Installs the extension the CMake build compiled, and libvoxc.so.0 and libvoxc-openvdb.so beside it."""

    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name))
        built = built_package / target.name
        if not built.exists():
            found = sorted(p.name for p in built_package.glob("_native*.so")) or "none"
            raise SystemExit(
                f"voxc: {built} not found (built there: {found}); build voxc first with scripts/build.sh "
                f"(the CMake option VOXC_PYTHON, for this Python: -DPython3_EXECUTABLE={sys.executable}), "
                "or set VOXC_BUILD_DIR to a build directory that has it"
            )
        stale = [s for s in sources if s.stat().st_mtime > built.stat().st_mtime]
        if stale:
            raise SystemExit(f"voxc: {built} is older than {stale[0]}; build voxc again (cmake --build build)")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)
        for library in ("libvoxc.so.0", "libvoxc-openvdb.so"):  # the symlinks' files
            shutil.copy2(built_package / library, target.parent / library)


setup(
    name="voxc",
    version="0.1.0",
    description="voxc, a voxel grammar compiler, from Python: check, generate and mesh .vox files as NumPy arrays",
    packages=["voxc"],
    package_data={"voxc": ["__init__.pyi", "py.typed"]},
    ext_modules=[
        # Built by CMake (python/CMakeLists.txt); declared so that the wheel is tagged for this
        # platform and Python, and copied by CopyBuiltExtension.
        Extension("voxc._native", ["src/module.cpp"])
    ],
    cmdclass={"build_ext": CopyBuiltExtension},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
)
