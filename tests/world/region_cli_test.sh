#!/usr/bin/env bash
# voxc run/interp --region and voxc check --explain-halo end to end: the box's voxels and materials
# equal the same box of the whole world's, by the interpreter and on lavapipe; the halo is printed;
# bad boxes exit 1 and write nothing. Usage: region_cli_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/expect.sh"

# Whether the .npy `part` equals the box of `whole` from corner X,Y,Z (C order, shape (x, y, z)).
same_box() {
    python3 - "$@" <<'PY'
import ast, struct, sys
def load(path):
    data = open(path, 'rb').read()
    length = struct.unpack('<H', data[8:10])[0]
    header = ast.literal_eval(data[10:10 + length].decode())
    item = 4 if header['descr'] == '<f4' else 1
    return header['shape'], data[10 + length:], item
(ws, wd, item), (ps, pd, _) = load(sys.argv[1]), load(sys.argv[2])
x0, y0, z0 = (int(v) for v in sys.argv[3].split(','))
for x in range(ps[0]):
    for y in range(ps[1]):
        a = ((x + x0) * ws[1] + y + y0) * ws[2] + z0
        b = (x * ps[1] + y) * ps[2]
        if wd[a * item:(a + ps[2]) * item] != pd[b * item:(b + ps[2]) * item]:
            sys.exit(1)
PY
}

scene=$src/examples/scene.vox
"$voxc" interp "$scene" --voxels "$work/whole.npy" --materials "$work/whole_m.npy" 2>"$work/whole.log" || { fail "interp"; cat "$work/whole.log"; }
"$voxc" interp "$scene" --region 10,3,7:41,40,30 --voxels "$work/part.npy" --materials "$work/part_m.npy" \
    2>"$work/part.log" || { fail "interp --region"; cat "$work/part.log"; }
grep -q "^region 10,3,7:41,40,30 of the world: a 31x54x23 grid at world 10,0,7" "$work/part.log" \
    && pass "interp --region reports the grid it ran" || { fail "no region report"; cat "$work/part.log"; }
same_box "$work/whole.npy" "$work/part.npy" 10,3,7 && same_box "$work/whole_m.npy" "$work/part_m.npy" 10,3,7 \
    && pass "interp --region equals the whole world's box" || fail "interp --region differs from the whole world"
"$voxc" run "$scene" --device lavapipe --chunk 8 --region 10,3,7:41,40,30 --voxels "$work/run.npy" \
    --materials "$work/run_m.npy" -o "$work/part.glb" 2>"$work/run.log" || { fail "run --region"; cat "$work/run.log"; }
same_box "$work/whole.npy" "$work/run.npy" 10,3,7 && same_box "$work/whole_m.npy" "$work/run_m.npy" 10,3,7 \
    && pass "run --region on lavapipe equals the whole world's box" || fail "run --region differs from the whole world"
grep -Eq "^wrote $work/part.glb \(marching cubes\): [1-9][0-9]* vertices.* watertight" "$work/run.log" \
    && pass "the box is meshed, closed" || { fail "no mesh of the box"; cat "$work/run.log"; }

"$voxc" check "$src/examples/speleothems.vox" --explain-halo >"$work/halo.txt" 2>/dev/null || fail "check --explain-halo"
grep -q "^halo: 1 39 1 " "$work/halo.txt" && grep -q "hoodoos: 1 39 1  (the air runs of its whole column and of the columns at x - 1 and z - 1)" "$work/halo.txt" \
    && pass "--explain-halo prints each stage and the halo" || { fail "--explain-halo"; cat "$work/halo.txt"; }

# A world larger than one grid: checked and run for a region; whole, or with a box whose grid is
# too large, it is refused.
sed 's/size = \[96, 64, 96\];/size = [4096, 256, 4096];/' "$scene" >"$work/large.vox"
"$voxc" check "$work/large.vox" >/dev/null 2>&1 && fail "a 4096x256x4096 world checked whole"
"$voxc" check "$work/large.vox" --region 1000,0,1000:1064,256,1064 2>"$work/large.log" \
    && pass "a 4096x256x4096 world checks for a region" || { fail "large world region check"; cat "$work/large.log"; }
"$voxc" run "$work/large.vox" --device lavapipe --region 1000,0,1000:1064,256,1064 --voxels "$work/large.npy" \
    2>"$work/large.log" && [[ -s $work/large.npy ]] && pass "a region of it runs" || { fail "large world run"; cat "$work/large.log"; }
"$voxc" check "$work/large.vox" --region 0,0,0:1024,256,1024 2>"$work/large.log"
[[ $? -eq 1 ]] && grep -q "error E0014: the region 0,0,0:1024,256,1024 alone is a 1024x256x1024 grid" "$work/large.log" \
    && pass "a box too large for one grid is E0014" || { fail "no E0014"; cat "$work/large.log"; }

# A box that misses a curves block's solve box (the tutorial's cliff fills z < 64): the block's
# table is empty there, and the box still runs, the same on both backends.
cliff=$src/examples/tutorial/05_cliff.vox
expect "box beside a curves box (run)" 0 "" -- "$voxc" run "$cliff" --device lavapipe --region 0,0,96:40,64,128 \
    --voxels "$work/beside_run.npy"
expect "box beside a curves box (interp)" 0 "" -- "$voxc" interp "$cliff" --region 0,0,96:40,64,128 \
    --voxels "$work/beside_interp.npy"
expect_same "box beside a curves box: run == interp" "$work/beside_run.npy" "$work/beside_interp.npy"

# Bad requests: exit 1, a message naming --region, nothing written.
expect_error() {
    local message=$1; shift
    rm -f "$work/bad.npy"
    expect "refused: $message" 1 "$message" -- "$@" --voxels "$work/bad.npy"
    expect_no_file "refused without writing: $message" "$work/bad.npy"
}
expect_error "the box must lie inside the world, 0,0,0:96,64,96" "$voxc" interp "$scene" --region -1,0,0:5,5,5
expect_error "the box is empty" "$voxc" interp "$scene" --region 5,5,5:5,6,6
expect_error "expected MINX,MINY,MINZ:MAXX,MAXY,MAXZ" "$voxc" interp "$scene" --region 1,2,3
expect_error "'x' is not an integer" "$voxc" run "$scene" --device lavapipe --region 1,2,x:4,5,6
expect_error "a --region is meshed on the host" "$voxc" run "$scene" --device lavapipe --mesh-on device --region 0,0,0:8,8,8
finish
