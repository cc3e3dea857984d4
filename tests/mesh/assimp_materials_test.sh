#!/usr/bin/env bash
# A voxc .glb opened by assimp (Debian assimp-utils) with its standard post-processing, which merges
# materials equal in everything but their names: examples/scene.vox's five materials must stay
# five, under their own names. A missing assimp fails (scripts/install-deps.sh installs it).
# Usage: assimp_materials_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
source "$src/tests/support/expect.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v assimp >/dev/null || { fail "assimp is missing (scripts/install-deps.sh installs assimp-utils)"; finish; }

expect "voxc run scene.vox" 0 "" -- "$voxc" run "$src/examples/scene.vox" --device lavapipe -o "$work/scene.glb"
assimp info "$work/scene.glb" >"$work/info.txt" 2>&1
expect "assimp keeps the five materials" 0 "^Materials: +5$" -- cat "$work/info.txt"
for name in dirt bedrock sandstone sand grass; do
    expect "assimp names material $name" 0 "^    '$name' \(prop\)" -- cat "$work/info.txt"
done
finish
