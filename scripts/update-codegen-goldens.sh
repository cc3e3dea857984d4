#!/bin/sh
# Regenerates tests/golden/codegen/* (IR text and generated GLSL) from the code.
# Review the diff before committing: every change there is a change in the generated kernels.
# Usage: scripts/update-codegen-goldens.sh [build-dir]   (default: build)
set -e
build=${1:-build}
cmake --build "$build" --target voxc_codegen_tests
VOXC_UPDATE_GOLDENS=1 "$build/tests/codegen/voxc_codegen_tests" --gtest_filter='codegen_Golden.*'
