#!/usr/bin/env bash
# voxc run --timings shows each phase of meshing on its own line, in the order they run: the
# extraction (mesh), the normals' orientation, the quality check, the .glb encoding; and the
# write (a phase first used by the voxels' files, so listed where they are written); a PLY has no
# encode phase (it is encoded as it is written). Usage: run_timings_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/expect.sh"

phases() { # the phase names of a --timings table, in order, one line
    sed -n '/^timings (ms):$/,$p' "$1" | awk 'NR > 1 { print $1 }' | tr '\n' ' '
}
if "$voxc" run "$src/examples/scene.vox" --device lavapipe -o "$work/scene.glb" --timings 2>"$work/glb.log"; then
    got=$(phases "$work/glb.log")
    if [[ "$got" == *"mesh normals quality encode "* && "$got" == *" write "* ]]; then pass "glb phases: $got"; else fail "glb phases: $got"; fi
else
    fail "voxc run -o scene.glb"; cat "$work/glb.log"
fi
if "$voxc" run "$src/examples/scene.vox" --device lavapipe -o "$work/scene.ply" --timings 2>"$work/ply.log"; then
    got=$(phases "$work/ply.log")
    if [[ "$got" == *"mesh normals quality total "* && "$got" == *" write "* && "$got" != *encode* ]]; then pass "ply phases: $got"; else fail "ply phases: $got"; fi
else
    fail "voxc run -o scene.ply"; cat "$work/ply.log"
fi
finish
