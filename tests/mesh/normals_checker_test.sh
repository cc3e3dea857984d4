#!/usr/bin/env bash
# voxc_normals_check, which example_NAME runs on every example's meshes, must see a reversed
# normal, or it is not looking: scene.vox's .ply passes, and the same file with every normal
# negated fails.
# Usage: normals_checker_test.sh VOXC VOXC_NORMALS_CHECK SOURCE_DIR
set -u
voxc=$1 check=$2 src=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache"
. "$src/tests/support/expect.sh"

expect run_scene 0 "" -- "$voxc" run "$src/examples/scene.vox" --device lavapipe -o "$work/scene.ply"
expect scene_normals_face_triangles 0 "" -- "$check" "$work/scene.ply"
python3 - "$work/scene.ply" "$work/flipped.ply" <<'PY'
import struct, sys
data = open(sys.argv[1], 'rb').read()
end = data.index(b'end_header\n') + len(b'end_header\n')
header = data[:end].decode()
vertices = int(header.split('element vertex ')[1].split('\n')[0])
sizes = {'float': 4, 'uchar': 1}
properties = header.split('element vertex')[1].split('element face')[0].split('property ')[1:]
stride = sum(sizes[p.split()[0]] for p in properties)
body = bytearray(data[end:])
for v in range(vertices):
    at = v * stride + 12
    n = struct.unpack_from('<3f', body, at)
    struct.pack_into('<3f', body, at, *(-c for c in n))
open(sys.argv[2], 'wb').write(data[:end] + bytes(body))
PY
expect checker_rejects_reversed_normals 1 "" -- "$check" "$work/flipped.ply"
finish
