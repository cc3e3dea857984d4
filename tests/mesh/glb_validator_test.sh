#!/usr/bin/env bash
# Every .glb voxc writes passes the Khronos validator and loads in three.js (check_glb.mjs): the
# fixtures of spec G1 and every example run through `voxc run` with both meshers; and every
# example's default mesh (marching cubes on the host, the default on lavapipe) is reported closed, manifold and free of
# zero-area triangles and is the CPU mesher's, byte for byte. A missing
# node or missing Node tools fail the test (scripts/install-node-tools.sh installs them).
# Usage: glb_validator_test.sh VOXC_GLB_FIXTURES VOXC SOURCE_DIR
set -uo pipefail
fixtures=$1 voxc=$2 src=$3
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

for example in "$src"/examples/*.vox; do
    name=$(basename "$example" .vox)
    # The L-system examples other than lsystem_cave only declare an lsystem, drawn with
    # `voxc lsystem`; nothing carves them, so `voxc run` gives them an empty mesh (and says so).
    case $name in lsystem_cave) ;; lsystem_*) continue ;; esac
    # The flagship's world is larger than lavapipe binds as one grid: a box of it runs instead.
    region=()
    [ "$name" = flagship ] && region=(--region 280,0,236:336,160,332)
    for mesher in mc surface-nets; do
        if ! "$voxc" run "$example" --device lavapipe "${region[@]}" --mesher "$mesher" -o "$work/${name}_$mesher.glb" 2>"$work/run.log"; then
            echo "FAIL voxc run $name --mesher $mesher"; cat "$work/run.log"; failed=1
        fi
    done
    # The default mesher, as reported by the independent checker: closed, manifold, no zero-area triangle.
    "$voxc" run "$example" --device lavapipe "${region[@]}" -o "$work/${name}_default.ply" 2>"$work/default.log"
    if grep -Eq "\(marching cubes\): [1-9][0-9]* vertices, [1-9][0-9]* triangles, 0 boundary edges, 0 non-manifold edges, 0 zero-area triangles; watertight" "$work/default.log"; then
        echo "ok   $name: the default mesh is closed and manifold without zero-area triangles"
    else
        echo "FAIL $name: the default mesh report is not clean:"; cat "$work/default.log"; failed=1
    fi
    # Marching cubes on the device writes the CPU mesher's (the default's) file, byte for byte
    # (a --region is always meshed on the host, so the flagship has nothing to compare).
    [ ${#region[@]} -eq 0 ] || continue
    "$voxc" run "$example" --device lavapipe --mesh-on device -o "$work/${name}_device.ply" 2>/dev/null
    if cmp -s "$work/${name}_default.ply" "$work/${name}_device.ply"; then
        echo "ok   $name: --mesh-on device and host write the same bytes"
    else
        echo "FAIL $name: --mesh-on device and host write different meshes"; failed=1
    fi
done
check "$work"/*.glb || failed=1
exit $failed
