#!/usr/bin/env bash
# One command for a fresh Debian 12 machine: install what is missing, build, and run the
# overhang example on Vulkan (lavapipe unless a GPU is present), writing a mesh and the voxels;
# install the Python module into venv/ (scripts/python-venv.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# What a user runs: the voxc binary, libvoxc and the Python module (scripts/test.sh builds the rest).
"$root/scripts/build.sh" voxc voxc_capi voxc_python
"$root/scripts/python-venv.sh"
mkdir -p "$root/out"
"$root/build/compiler/driver/voxc" run "$root/examples/overhang.vox" \
    -o "$root/out/overhang.ply" --voxels "$root/out/overhang.npy"
echo "setup: done; the mesh is out/overhang.ply, the voxels out/overhang.npy;" \
    "Python: . venv/bin/activate, then import voxc"
