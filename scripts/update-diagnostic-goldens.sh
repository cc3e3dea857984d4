#!/usr/bin/env bash
# Regenerates tests/diagnostics/cases/*.expected (and the *.json.expected that exist) from the
# checker's current output.
# The golden test itself does the writing when VOXC_UPDATE_GOLDENS=1 is set.
# Review the result with `git diff tests/diagnostics` before committing it.
#
# Usage: scripts/update-diagnostic-goldens.sh [build-dir]   (default: build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
cmake --build "$build" --target voxc_diagnostics_tests
VOXC_UPDATE_GOLDENS=1 "$build/tests/diagnostics/voxc_diagnostics_tests" --gtest_brief=1 >/dev/null
echo "updated $(ls "$root"/tests/diagnostics/cases/*.expected | wc -l) golden files in tests/diagnostics/cases"
