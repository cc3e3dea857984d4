#!/usr/bin/env bash
# Builds voxc and runs every test (ctest prints the closing summary line).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
# The clang fuzz tree first: configuring build/ registers the fuzz smoke test only where it
# exists, and a missing clang fails here.
"$root/scripts/fuzz.sh" --build
"$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure -j"$(nproc)" --timeout 900
