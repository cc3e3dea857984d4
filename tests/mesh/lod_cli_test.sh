#!/usr/bin/env bash
# voxc run --lod: one mesh per level beside -o, and with --lod-layout a mixed-level mesh at -o,
# each reported closed and manifold by the independent checker and passing the Khronos validator
# and three.js (check_glb.mjs; missing Node tools fail the test); bad requests exit 1 and write
# nothing. Usage: lod_cli_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/expect.sh"

# Chunks of 8 so the ring around the point reaches level 2 inside scene.vox's 96x64x96 grid.
if ! "$voxc" run "$src/examples/scene.vox" --device lavapipe --chunk 8 --lod 0,1,2 --lod-layout 10,20,10 \
        -o "$work/scene.glb" 2>"$work/run.log"; then
    fail "voxc run --lod"; cat "$work/run.log"
fi
for file in scene.lod0.glb scene.lod1.glb scene.lod2.glb scene.glb; do
    if grep -Eq "^wrote $work/$file \(marching cubes, LOD .*\): [1-9][0-9]* vertices, [1-9][0-9]* triangles, 0 boundary edges, 0 non-manifold edges, 0 zero-area triangles; watertight$" "$work/run.log"; then
        pass "$file is reported closed and manifold"
    else
        fail "$file: no clean report"; cat "$work/run.log"
    fi
done
# The mixed mesh has all three levels and transitions between them.
if grep -Eq "chunks [1-9][0-9]* at LOD 0, [1-9][0-9]* at LOD 1, [1-9][0-9]* at LOD 2; [1-9][0-9]* transition faces" "$work/run.log"; then
    pass "the layout mixes levels 0, 1 and 2"
else
    fail "the layout does not mix three levels"; cat "$work/run.log"
fi
# Coarser levels have fewer triangles.
counts=$(grep -Eo "LOD [012], cells [0-9]+ voxels? wide\): [0-9]+ vertices, [0-9]+ triangles" "$work/run.log" | grep -Eo "[0-9]+ triangles" | grep -Eo "[0-9]+" | tr '\n' ' ')
read -r t0 t1 t2 <<<"$counts"
if [[ -n ${t2:-} && $t0 -gt $t1 && $t1 -gt $t2 ]]; then pass "triangles per level $t0 > $t1 > $t2"; else fail "triangles per level: $counts"; fi
node "$src/tests/mesh/check_glb.mjs" "$src/.node-tools" "$work"/scene*.glb || fail "check_glb.mjs on the LOD meshes"

# Bad requests: exit 1, a message naming the flag, no file written.
expect_error() {
    local message=$1; shift
    rm -rf "$work/bad" && mkdir "$work/bad"
    "$voxc" run "$src/examples/scene.vox" --device lavapipe "$@" 2>"$work/bad.log"
    local rc=$?
    if [[ $rc -eq 1 ]] && grep -q -- "$message" "$work/bad.log" && [[ -z $(ls -A "$work/bad") ]]; then
        pass "$* -> $message"
    else
        fail "$* (exit $rc, files: $(ls "$work/bad" | tr '\n' ' '))"; cat "$work/bad.log"
    fi
}
expect_error "level 6 cells are 64 voxels wide" --lod 0,6 -o "$work/bad/x.glb"
expect_error "levels run from 0 to 6" --lod 7 -o "$work/bad/x.glb"
expect_error "needs --lod" --lod-layout 1,2,3 -o "$work/bad/x.glb"
expect_error "give -o" --lod 1 --voxels "$work/bad/x.npy"
expect_error "--mesher surface-nets" --lod 1 --mesher surface-nets -o "$work/bad/x.glb"
finish
