#!/usr/bin/env bash
# voxc run|interp --edits: the same edits file gives the same densities and materials from the
# device's grid (lavapipe) and the interpreter's, at chunk sizes 8 and 32 and for a region; the
# edited mesh is closed and manifold; bad edits files are located errors (exit 1, nothing
# written). Usage: edits_cli_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/expect.sh"
scene=$src/examples/scene.vox

cat >"$work/edits.json" <<'JSON'
[
  {"op": "carve", "center": [48.5, 30.25, 48], "radius": 10, "softness": 2},
  {"op": "add", "center": [20, 40, 20], "radius": 5, "material": "sandstone"},
  {"op": "carve", "center": [500, 0, 0], "radius": 3}
]
JSON

"$voxc" run "$scene" --device lavapipe --voxels "$work/plain.npy" 2>/dev/null || fail "run without edits"
if "$voxc" run "$scene" --device lavapipe --edits "$work/edits.json" --voxels "$work/run.npy" \
        --materials "$work/run_m.npy" -o "$work/run.ply" 2>"$work/run.log"; then
    grep -q "^edits: 3 applied on the host, 2 of them changed voxels$" "$work/run.log" \
        && pass "run reports 3 edits, 2 changing voxels" || { fail "run's edit report"; cat "$work/run.log"; }
    grep -Eq "^wrote $work/run.ply \(marching cubes\): .* 0 boundary edges, 0 non-manifold edges, .*watertight" "$work/run.log" \
        && pass "the edited mesh is watertight" || { fail "edited mesh report"; cat "$work/run.log"; }
else
    fail "run --edits"; cat "$work/run.log"
fi
cmp -s "$work/plain.npy" "$work/run.npy" && fail "the edits changed nothing" || pass "the edits change the grid"
"$voxc" run "$scene" --device lavapipe --chunk 8 --edits "$work/edits.json" --voxels "$work/run8.npy" 2>/dev/null || fail "run --chunk 8"
cmp -s "$work/run.npy" "$work/run8.npy" && pass "chunk 8 == chunk 32" || fail "chunk 8 differs from chunk 32"
"$voxc" interp "$scene" --edits "$work/edits.json" --voxels "$work/interp.npy" --materials "$work/interp_m.npy" 2>/dev/null \
    || fail "interp --edits"
cmp -s "$work/run.npy" "$work/interp.npy" && cmp -s "$work/run_m.npy" "$work/interp_m.npy" \
    && pass "run == interp, densities and materials, bit for bit" || fail "run and interp differ after edits"
# A region's voxels after edits equal the same box of the whole edited world.
region=30,10,30:70,50,66
"$voxc" run "$scene" --device lavapipe --region $region --edits "$work/edits.json" --voxels "$work/region.npy" 2>/dev/null \
    || fail "run --region --edits"
"$voxc" interp "$scene" --region $region --edits "$work/edits.json" --voxels "$work/region_i.npy" 2>/dev/null \
    || fail "interp --region --edits"
python3 - "$work" <<'PY' && pass "region == the whole world's box, run and interp" || fail "region after edits"
import ast, sys
def load(path):  # .npy, float32, C order (x, y, z): raw words and shape
    data = open(path, "rb").read()
    length = int.from_bytes(data[8:10], "little")
    shape = ast.literal_eval(data[10:10 + length].decode())["shape"]
    return data[10 + length:], shape
w = sys.argv[1]
(whole, (sx, sy, sz)), (part, shape), (parti, _) = (load(f"{w}/{n}.npy") for n in ("run", "region", "region_i"))
assert shape == (40, 40, 36) and part == parti
crop = b"".join(whole[4 * (((30 + x) * sy + 10 + y) * sz + 30):][:4 * 36] for x in range(40) for y in range(40))
assert crop == part
PY
expect "--mesh-on device with --edits is refused" 1 "with --edits the edited grid is meshed on the host" -- \
    "$voxc" run "$scene" --device lavapipe --mesh-on device --edits "$work/edits.json" -o "$work/dev.ply"

# The example edits file: a tunnel through scene.vox's hills and a mound, every edit changing voxels.
if "$voxc" run "$scene" --device lavapipe --edits "$src/examples/scene.edits.json" -o "$work/tunnel.ply" 2>"$work/tunnel.log"; then
    grep -q "^edits: 20 applied on the host, 20 of them changed voxels$" "$work/tunnel.log" &&
        grep -Eq "^wrote $work/tunnel.ply \(marching cubes\): .*watertight" "$work/tunnel.log" &&
        pass "examples/scene.edits.json: 20 edits, watertight" || { fail "scene.edits.json report"; cat "$work/tunnel.log"; }
else
    fail "run with examples/scene.edits.json"; cat "$work/tunnel.log"
fi

# Bad edits files: exit 1, the located diagnostic, no output written.
expect_rejected() {
    local name=$1 text=$2; shift 2
    printf '%s' "$text" >"$work/$name.json"
    if "$voxc" run "$scene" --device lavapipe --edits "$work/$name.json" -o "$work/bad.ply" 2>"$work/$name.log"; then
        fail "$name: accepted"; return
    fi
    for pattern in "$@"; do
        grep -qF -- "$pattern" "$work/$name.log" || { fail "$name: no '$pattern'"; cat "$work/$name.log"; return; }
    done
    [[ -e $work/bad.ply ]] && { fail "$name: wrote the mesh"; return; }
    pass "$name: $1"
}
expect_rejected syntax $'[\n  {"op": "carve", "center": [1, 2, 3], "radius": 4,}\n]\n' "syntax.json:2:52: error E0001: the edits file is not valid JSON"
expect_rejected key $'[\n  {"op": "carve", "center": [1, 2, 3], "radius": 4},\n  {"op": "carve", "centre": [1, 2, 3], "radius": 4}\n]\n' \
    "key.json:3:19: error E0008: edit 2: unknown key 'centre' (keys: op, center, radius, softness, material)" "key.json:3:3: error E0009: edit 2: missing key 'center'"
expect_rejected values $'[{"op": "smash", "center": [1, 2, 3], "radius": 0, "softness": "soft"},\n 7]\n' \
    "values.json:1:3: error E0011: edit 1: unknown op 'smash'" "values.json:1:39: error E0007: edit 1: 'radius' 0 is outside (0, 4096]" \
    "values.json:1:52: error E0010: edit 1: 'softness' must be a number" "values.json:2:2: error E0010: edit 2: an edit is an object"
expect_rejected material $'[{"op": "add", "center": [1, 2, 3], "radius": 1, "material": "granite"},\n {"op": "carve", "center": [1, 2, 3], "radius": 1, "material": "sand"}]' \
    "material.json:1:50: error E0002: edit 1: unknown material 'granite' (declared: " \
    "material.json:2:52: error E0010: edit 2: 'material' is the name of a material, on an add"
expect_rejected notarray $'{"edits": []}\n' "notarray.json:1:1: error E0010: an edits file is a JSON array"
expect_rejected center $'[{"op": "add", "center": [1, 2], "radius": 1}, {"op": "add", "center": [1, 2, 1e30], "radius": 1}]' \
    "center.json:1:16: error E0010: edit 1: 'center' must be three numbers" "center.json:1:62: error E0007: edit 2: 'center' beyond"
python3 -c 'import sys; sys.stdout.write("[" + ",".join(["{\"op\":\"add\",\"center\":[0,0,0],\"radius\":1}"] * 100001) + "]")' >"$work/many.json"
if "$voxc" run "$scene" --device lavapipe --edits "$work/many.json" -o "$work/bad.ply" 2>"$work/many.log"; then
    fail "100001 edits were accepted"
else
    grep -Eq "many.json:1:[0-9]+: error E0012: 100001 edits: at most 100000 per file" "$work/many.log" \
        && pass "100001 edits: E0012 at the first one too many" || { fail "too many edits message"; head -3 "$work/many.log"; }
fi
if "$voxc" interp "$scene" --edits "$work/missing.json" --voxels "$work/bad.npy" 2>"$work/missing.log"; then
    fail "a missing edits file was accepted"
else
    grep -qF "error E0100: cannot read file '$work/missing.json': no such file" "$work/missing.log" \
        && pass "missing file: E0100" || { fail "missing file message"; cat "$work/missing.log"; }
fi
finish
