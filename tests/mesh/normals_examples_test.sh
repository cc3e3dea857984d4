#!/usr/bin/env bash
# Vertex normals face their triangles on every example: no triangle of any mesh voxc writes has a
# vertex normal more than 90 degrees from its geometric normal (voxc_normals_check). Each example
# runs once (marching cubes on the host, the default on lavapipe, to a .glb, with its voxels);
# the checker meshes those voxels again with both host meshers into .ply, .obj and .glb and reads
# every file back; scene.vox also meshes on the device. The flagship runs on a box of its world:
# its whole grid is more than lavapipe binds as one buffer.
# Usage: normals_examples_test.sh VOXC VOXC_NORMALS_CHECK SOURCE_DIR
set -uo pipefail
voxc=$1 check=$2 src=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# One example: voxc's own file, then the checker's meshes of its voxels; the log says ok/FAIL.
check_example() {
    local example=$1 name region=()
    name=$(basename "$example" .vox)
    [ "$name" = flagship ] && region=(--region 280,0,236:336,160,332)
    mkdir -p "$work/$name"
    if ! "$voxc" run "$example" --device lavapipe "${region[@]}" -q -o "$work/$name/voxc.glb" \
        --voxels "$work/$name/d.npy" --materials "$work/$name/m.npy" >"$work/$name/log" 2>&1; then
        echo "FAIL voxc run $name" >>"$work/$name/log"; return
    fi
    "$check" --from-voxels "$work/$name/d.npy" "$work/$name/m.npy" "$work/$name" "$work/$name/voxc.glb" >>"$work/$name/log" 2>&1 ||
        echo "FAIL $name" >>"$work/$name/log"
    rm -f "$work/$name"/*.npy
}
# Two at a time, one per core.
examples=()
for example in "$src"/examples/*.vox; do
    # The L-system examples other than lsystem_cave only declare an lsystem (`voxc lsystem`);
    # `voxc run` gives them an empty mesh.
    case $(basename "$example" .vox) in lsystem_cave) ;; lsystem_*) continue ;; esac
    examples+=("$example")
    check_example "$example" &
    [ $(jobs -r | wc -l) -ge 2 ] && wait -n
done
wait
failed=0
for example in "${examples[@]}"; do
    log="$work/$(basename "$example" .vox)/log"
    cat "$log"
    grep -q '^FAIL' "$log" && failed=1
done
# Marching cubes on the device re-derives the normals as the host does (its .glb is the host's,
# byte for byte, in mesh_glb_validator): one example with thin features through it.
"$voxc" run "$src/examples/scene.vox" --device lavapipe -q --mesh-on device -o "$work/scene/voxc_device.ply" 2>/dev/null ||
    { echo "FAIL voxc run scene --mesh-on device"; failed=1; }
"$check" "$work/scene/voxc_device.ply" || failed=1
# The checker must see a reversed normal, or it is not looking: scene's .ply with every normal negated.
if [ -f "$work/scene/mc.ply" ]; then
    python3 - "$work/scene/mc.ply" "$work/flipped.ply" <<'PY'
import struct, sys
data = open(sys.argv[1], 'rb').read()
end = data.index(b'end_header\n') + len(b'end_header\n')
header = data[:end].decode()
vertices = int(header.split('element vertex ')[1].split('\n')[0])
stride = 24 + (4 if 'property uchar material' in header.split('element face')[0] else 0)
body = bytearray(data[end:])
for v in range(vertices):
    at = v * stride + 12
    n = struct.unpack_from('<3f', body, at)
    struct.pack_into('<3f', body, at, *(-c for c in n))
open(sys.argv[2], 'wb').write(data[:end] + bytes(body))
PY
    if "$check" "$work/flipped.ply" >/dev/null; then echo "FAIL the checker accepted reversed normals"; failed=1
    else echo "ok   the checker rejects reversed normals"; fi
fi
[ "${#examples[@]}" -ge 20 ] || { echo "FAIL only ${#examples[@]} examples checked"; failed=1; }
exit $failed
