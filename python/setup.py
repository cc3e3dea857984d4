"""pip install --no-build-isolation ./python: the module voxc, built against a built libvoxc.

libvoxc (the C API) comes from a voxc build with VOXC_LIBVOXC=ON, as scripts/build.sh makes it:
build/ beside this folder, or the build directory named by VOXC_BUILD_DIR. The extension links
it, and the installed package carries a copy (voxc/libvoxc.so.0, found through the rpath
$ORIGIN), so the install keeps working when the build tree changes or goes. Only setuptools and
pybind11's headers (Debian's python3-setuptools and pybind11-dev) are needed, no network.
docs/python.md.
"""
import os
import shutil
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

here = Path(__file__).resolve().parent
root = here.parent
build_dir = Path(os.environ.get("VOXC_BUILD_DIR", root / "build")).resolve()
capi_dir = build_dir / "runtime" / "capi"
library = capi_dir / "libvoxc.so.0"


def pybind11_include():
    try:
        import pybind11  # a pip-installed pybind11, if any

        return [pybind11.get_include()]
    except ImportError:
        return []  # Debian's pybind11-dev: /usr/include/pybind11, on the compiler's path


class BuildWithLibvoxc(build_ext):
    """Builds the extension and puts libvoxc.so.0 beside it."""

    def run(self):
        if not library.exists():
            raise SystemExit(
                f"voxc: {library} not found; build voxc first with scripts/build.sh "
                "(cmake -DVOXC_LIBVOXC=ON), or set VOXC_BUILD_DIR to a build directory that has it"
            )
        super().run()
        package_dir = Path(self.build_lib) / "voxc"
        package_dir.mkdir(parents=True, exist_ok=True)
        shutil.copy2(library, package_dir / library.name)
        if self.inplace:
            shutil.copy2(library, here / "voxc" / library.name)


setup(
    name="voxc",
    version="0.1.0",
    description="voxc, a voxel grammar compiler, from Python: check, generate and mesh .vox files as NumPy arrays",
    packages=["voxc"],
    package_data={"voxc": ["__init__.pyi", "py.typed"]},
    ext_modules=[
        Extension(
            "voxc._native",
            ["src/module.cpp"],
            include_dirs=[str(root / "runtime" / "capi" / "include"), *pybind11_include()],
            library_dirs=[str(capi_dir)],
            libraries=["voxc"],
            extra_compile_args=["-std=c++17", "-fvisibility=hidden"],
            extra_link_args=["-Wl,-rpath,$ORIGIN"],
            language="c++",
        )
    ],
    cmdclass={"build_ext": BuildWithLibvoxc},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
)
