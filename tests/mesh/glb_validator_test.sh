#!/usr/bin/env bash
# The .glb fixtures of spec G1 pass the Khronos validator and load in three.js (check_glb.mjs), and
# the checker rejects a file with a wrong bound; every example's files go through the same checker
# in example_NAME. A missing node or missing Node tools fail the test
# (scripts/install-node-tools.sh installs them).
# Usage: glb_validator_test.sh VOXC_GLB_FIXTURES SOURCE_DIR
set -uo pipefail
fixtures=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() { node "$src/tests/mesh/check_glb.mjs" "$src/.node-tools" "$@"; }
command -v node >/dev/null || { echo "FAIL node is missing (scripts/install-deps.sh installs it)"; exit 1; }
failed=0

"$fixtures" "$work/fixtures" || { echo "FAIL writing the fixtures"; exit 1; }
check "$work"/fixtures/*.glb || failed=1
# The checker must reject a file with a wrong bound, or it is not looking.
if check "$work"/fixtures/bad/wrong_bounds.glb >"$work/bad.log" 2>&1; then
    echo "FAIL the checker accepted a file with a wrong POSITION bound"; failed=1
elif grep -q "ACCESSOR_MAX_MISMATCH" "$work/bad.log"; then
    echo "ok   the checker rejects a wrong POSITION bound (ACCESSOR_MAX_MISMATCH)"
else
    echo "FAIL the checker failed on the wrong bound for another reason:"; cat "$work/bad.log"; failed=1
fi
exit $failed
