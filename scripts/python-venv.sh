#!/usr/bin/env bash
# Installs the Python module voxc, as built by scripts/build.sh, into a virtual environment (venv/
# at the repository root, or the folder given) with pip, offline: `venv/bin/python`, or `python3`
# after `. venv/bin/activate`, then imports voxc. The environment sees the system's site-packages,
# so Debian's NumPy and Matplotlib (scripts/install-deps.sh) serve it; Debian's own pip refuses
# to install into the system's Python (PEP 668). docs/python.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=${1:-$root/venv}
[ -x "$venv/bin/python" ] || /usr/bin/python3 -m venv --system-site-packages "$venv"
# The extension and libvoxc are copied from build/python/voxc (python/setup.py): nothing compiles.
PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 VOXC_BUILD_DIR=${VOXC_BUILD_DIR:-$root/build} \
    "$venv/bin/pip" install --quiet --no-build-isolation --force-reinstall --no-deps "$root/python"
"$venv/bin/python" -c "import voxc" # fails here, not later in the user's hands
