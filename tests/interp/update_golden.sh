#!/bin/sh
# Regenerates tests/interp/golden/* from the code; review the diff before committing.
# Usage: tests/interp/update_golden.sh [build-dir]   (default: build)
set -e
build=${1:-build}
VOXC_UPDATE_GOLDEN=1 "$build/tests/interp/voxc_interp_tests" --gtest_filter='interp_Slice.MatchesGolden'
