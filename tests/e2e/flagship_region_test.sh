#!/usr/bin/env bash
# Usage: flagship_region_test.sh VOXC SOURCE_DIR. examples/flagship.vox is larger than lavapipe
# binds as one grid, so it is checked here on a box that holds the cliff, the river, the sea
# stack and the arch: `voxc run --region` (lavapipe) and `voxc interp --region` must write the
# same densities and materials bit for bit. Prints "N passed, N failed" last.
set -u
voxc=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache"
. "$(dirname "$0")/../support/expect.sh"

box=280,0,236:336,160,332
expect run 0 "" -- "$voxc" run "$src/examples/flagship.vox" --region $box --device lavapipe \
    --voxels "$work/run.npy" --materials "$work/run_materials.npy"
expect interp 0 "" -- "$voxc" interp "$src/examples/flagship.vox" --region $box \
    --voxels "$work/interp.npy" --materials "$work/interp_materials.npy"
expect_same densities_equal "$work/run.npy" "$work/interp.npy"
expect_same materials_equal "$work/run_materials.npy" "$work/interp_materials.npy"
finish
