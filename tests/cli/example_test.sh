#!/usr/bin/env bash
# One example as a user runs it, with every reader of its files checking them. Registered once per
# example (example_NAME), so ctest spreads the examples over the cores and each runs voxc once per
# mesher instead of once per check:
#   - the default run (marching cubes on the host, the default on lavapipe) reports a closed,
#     manifold mesh without zero-area triangles; its .glb passes the Khronos glTF-Validator and
#     loads in three.js (check_glb.mjs); its vertex normals face their triangles, and so do the
#     checker's own meshes of its voxels with both host meshers in .ply, .obj and .glb;
#   - the interpreter writes the same voxels and materials, bit for bit (for the flagship, on the
#     box the run took);
#   - surface nets' .glb passes the validator and three.js (not for the flagship, whose region's
#     generation alone is 13 s of CPU: every other example checks surface nets);
#   - marching cubes on the device writes the host's .glb byte for byte.
# The flagship runs on a box of its world that holds the cliff, the river, the sea stack and the
# arch (its whole grid is more than lavapipe binds as one buffer); a --region is always meshed on
# the host, so it skips the device mesher.
# A missing node or missing Node tools fail the test (scripts/install-node-tools.sh installs them).
# Usage: example_test.sh VOXC VOXC_NORMALS_CHECK SOURCE_DIR EXAMPLE.vox
set -u
voxc=$1 normals_check=$2 src=$3 example=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache" # never the user's cache
. "$src/tests/support/expect.sh"
command -v node >/dev/null || { echo "FAIL node is missing (scripts/install-deps.sh installs it)"; exit 1; }

name=$(basename "$example" .vox)
region=()
[ "$name" = flagship ] && region=(--region 280,0,236:336,160,332)

expect default_run_is_watertight 0 \
    "\(marching cubes\): [1-9][0-9]* vertices, [1-9][0-9]* triangles, 0 boundary edges, 0 non-manifold edges, 0 zero-area triangles; watertight" \
    -- "$voxc" run "$example" --device lavapipe "${region[@]}" -o "$work/default.glb" \
    --voxels "$work/run.npy" --materials "$work/run_materials.npy"
glbs=("$work/default.glb")
if [ "$name" != flagship ]; then
    expect sn_run 0 "" -- "$voxc" run "$example" --device lavapipe --mesher surface-nets -o "$work/sn.glb"
    glbs+=("$work/sn.glb")
fi
expect glb_validator_and_three_js 0 "" -- node "$src/tests/mesh/check_glb.mjs" "$src/.node-tools" "${glbs[@]}"
mkdir -p "$work/normals"
expect normals_face_triangles 0 "" -- "$normals_check" --from-voxels "$work/run.npy" "$work/run_materials.npy" \
    "$work/normals" "$work/default.glb"

expect interp 0 "" -- "$voxc" interp "$example" "${region[@]}" --voxels "$work/interp.npy" --materials "$work/interp_materials.npy"
expect_same interp_densities_equal "$work/run.npy" "$work/interp.npy"
expect_same interp_materials_equal "$work/run_materials.npy" "$work/interp_materials.npy"
if [ ${#region[@]} -eq 0 ]; then
    expect device_mesher 0 "" -- "$voxc" run "$example" --device lavapipe --mesh-on device -o "$work/device.glb"
    expect_same device_mesh_is_the_hosts "$work/default.glb" "$work/device.glb"
fi
finish
