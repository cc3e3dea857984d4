#!/usr/bin/env bash
# Configures and builds voxc into build/ (Release). Installs missing Debian packages first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
# VOXC_LIBVOXC: libvoxc, the C API shared library, and its tests (docs/embedding.md).
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVOXC_LIBVOXC=ON >/dev/null
cmake --build "$root/build" -j"$(nproc)"
