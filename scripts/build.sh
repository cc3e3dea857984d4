#!/usr/bin/env bash
# Configures and builds voxc into build/ (Release): every target, or the TARGETs given
# (scripts/build.sh [TARGET...]). Installs missing Debian packages first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
# VOXC_LIBVOXC: libvoxc, the C API shared library, and its tests (docs/embedding.md).
# A unity build compiles 16 sources of a target as one, so the headers they share (OpenVDB, fmt,
# nlohmann-json, GoogleTest, the compiler's own) are read and their templates compiled once.
# LLVM's lld links a test binary in a third of the CPU time GNU ld takes.
lld=-fuse-ld=lld
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVOXC_LIBVOXC=ON \
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
    -DCMAKE_EXE_LINKER_FLAGS=$lld -DCMAKE_SHARED_LINKER_FLAGS=$lld -DCMAKE_MODULE_LINKER_FLAGS=$lld >/dev/null
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build "$root/build" -j"$(nproc)" "${targets[@]}"
