#!/usr/bin/env bash
# voxc world end to end: tiles, their meshes and index.json; a second run writes the same bytes; a
# run killed (SIGKILL) mid-way resumes, keeping the tiles it listed, and ends with the same bytes
# as an unbroken run; lavapipe's tile equals the interpreter's byte for byte, and a second lavapipe
# run reads every kernel from the compile cache; --region writes the tiles meeting a box, which a
# later run of the whole world keeps; an unbounded world runs by region, its tiles those of a
# bounded world's; bad requests exit 1.
# Usage: world_cli_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/expect.sh"
scene=$src/examples/scene.vox

"$voxc" world "$scene" -o "$work/a" --tile 48 --interpreter 2>"$work/a.log" || { fail "voxc world"; cat "$work/a.log"; }
grep -q "^wrote 8 of 8 tiles of 48^3 voxels to $work/a (0 up to date); computed 1.58x their voxels with the halos$" "$work/a.log" \
    && pass "8 tiles written" || { fail "no report"; cat "$work/a.log"; }
[[ $(ls "$work/a"/tile_*.vdb | wc -l) -eq 8 && -s $work/a/index.json ]] && pass "8 .vdb files and index.json" || fail "files"
# The ground crosses the four lower tiles; the upper ones are air above it (no triangles, no file).
meshes=$(cd "$work/a" && ls tile_*.glb | tr '\n' ' ')
[[ $meshes == "tile_0_0_0.glb tile_0_0_1.glb tile_1_0_0.glb tile_1_0_1.glb " && $(grep -c '"mesh"' "$work/a/index.json") -eq 5 ]] \
    && pass "a .glb mesh beside each tile with surface, listed in the index" || fail "meshes: $meshes"
head -c 4 "$work/a/tile_1_0_1.glb" | grep -q "glTF" && pass "meshes are glTF binaries" || fail "not a .glb"
head -c 4 "$work/a/tile_1_0_1.vdb" | grep -q " BDV" && pass "tiles are OpenVDB files" || fail "not a VDB file"

# Killed after two tiles are listed, then resumed: the same bytes as the unbroken run.
"$voxc" world "$scene" -o "$work/b" --tile 48 --interpreter 2>/dev/null &
pid=$!
for _ in $(seq 600); do
    [[ -f $work/b/index.json && $(grep -c '"max"' "$work/b/index.json") -ge 2 ]] && break
    sleep 0.1
done
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
listed=$(grep -c '"max"' "$work/b/index.json")
[[ $listed -ge 2 && $listed -lt 8 ]] && pass "killed with $listed of 8 tiles listed" || fail "killed with $listed tiles listed"
"$voxc" world "$scene" -o "$work/b" --tile 48 --interpreter 2>"$work/b.log" || { fail "resume"; cat "$work/b.log"; }
grep -q "^wrote $((8 - listed)) of 8 tiles .* ($listed up to date)" "$work/b.log" \
    && pass "the resumed run keeps the $listed listed tiles" || { fail "resume report"; cat "$work/b.log"; }
same=1
for file in "$work/a"/*; do cmp -s "$file" "$work/b/$(basename "$file")" || same=0; done
[[ $same -eq 1 ]] && pass "resumed tiles and index equal the unbroken run's bytes" || fail "resumed tiles differ"
"$voxc" world "$scene" -o "$work/b" --tile 48 --interpreter 2>"$work/b.log"
grep -q "^wrote 0 of 8 tiles .* (8 up to date)$" "$work/b.log" && pass "a finished world is up to date" || { fail "rerun"; cat "$work/b.log"; }

# One tile on lavapipe equals the interpreter's, byte for byte.
"$voxc" world "$scene" -o "$work/c" --tile 96 --device lavapipe 2>"$work/c.log" || { fail "lavapipe"; cat "$work/c.log"; }
"$voxc" world "$scene" -o "$work/d" --tile 96 --interpreter 2>/dev/null || fail "interpreter tile"
cmp -s "$work/c/tile_0_0_0.vdb" "$work/d/tile_0_0_0.vdb" && pass "lavapipe's tile equals the interpreter's" || fail "lavapipe tile differs"

# The compile cache: a second lavapipe run compiles no kernel.
VOXC_CACHE_DIR=$work/cache "$voxc" world "$scene" -o "$work/k1" --tile 48 --device lavapipe 2>"$work/k1.log" || { fail "cache run 1"; cat "$work/k1.log"; }
VOXC_CACHE_DIR=$work/cache "$voxc" world "$scene" -o "$work/k2" --tile 48 --device lavapipe 2>"$work/k2.log" || { fail "cache run 2"; cat "$work/k2.log"; }
grep -Eq "^kernels: [1-9][0-9]* from the cache, 0 compiled; " "$work/k2.log" \
    && pass "a second run reads its kernels from the cache ($(grep kernels: "$work/k1.log"), then $(grep kernels: "$work/k2.log"))" \
    || { fail "cache"; cat "$work/k1.log" "$work/k2.log"; }
# Tiles of one size share their kernels: the driver compiles each pipeline once, not once per tile.
read -r created shared < <(sed -nE 's/^kernels: .*; pipelines: ([0-9]+) created, ([0-9]+) shared by tiles$/\1 \2/p' "$work/k1.log")
[[ -n $created && $shared -gt $((3 * created)) ]] \
    && pass "8 tiles create $created pipelines and share them $shared times" || { fail "shared pipelines"; cat "$work/k1.log"; }

# --region: only the tiles meeting the box; the whole world later keeps them.
"$voxc" world "$scene" -o "$work/r" --tile 48 --interpreter --region 50,10,0:60,20,10 2>"$work/r.log" || { fail "region"; cat "$work/r.log"; }
[[ $(ls "$work/r"/tile_*.vdb) == "$work/r/tile_1_0_0.vdb" ]] && pass "--region writes the one tile meeting the box" || fail "region tiles: $(ls "$work/r")"
"$voxc" world "$scene" -o "$work/r" --tile 48 --interpreter 2>"$work/r.log"
grep -q "^wrote 7 of 8 tiles .* (1 up to date)" "$work/r.log" && pass "the whole world keeps the region's tile" || { fail "region resume"; cat "$work/r.log"; }
same=1
for file in "$work/a"/*; do cmp -s "$file" "$work/r/$(basename "$file")" || same=0; done
[[ $same -eq 1 ]] && pass "written box by box, the same bytes as one run" || fail "box by box differs"

# An unbounded world (x and z) runs by region; its voxels are those of a bounded world of the same file.
sed 's/size = \[96, 64, 96\];/size = [unbounded, 64, unbounded];/' "$scene" >"$work/unbounded.vox"
sed 's/size = \[96, 64, 96\];/size = [192, 64, 144];/' "$scene" >"$work/bounded.vox"
"$voxc" world "$work/unbounded.vox" -o "$work/u" --tile 48 --interpreter --region 90,0,90:100,40,100 2>"$work/u.log" \
    || { fail "unbounded world"; cat "$work/u.log"; }
"$voxc" world "$work/bounded.vox" -o "$work/v" --tile 48 --interpreter --region 90,0,90:100,40,100 2>/dev/null || fail "bounded world"
same=1
for file in "$work/v"/tile_*.vdb; do cmp -s "$file" "$work/u/$(basename "$file")" || same=0; done
[[ $same -eq 1 && $(ls "$work/u"/tile_*.vdb | wc -l) -eq 4 ]] && pass "an unbounded world's 4 tiles equal a bounded world's" || fail "unbounded tiles differ"

# Bad requests: exit 1 with a message.
expect_error() {
    local message=$1; shift
    expect "refused: $message" 1 "$message" -- "$@"
}
expect_error "the tile edge must be 8 to 512 voxels" "$voxc" world "$scene" -o "$work/e" --tile 4 --interpreter
expect_error "holds the tiles of another file, world or tile size" "$voxc" world "$scene" -o "$work/a" --tile 32 --interpreter
touch "$work/file"
expect_error "is not a directory" "$voxc" world "$scene" -o "$work/file" --interpreter
expect_error "declares an unbounded world; give the box to write with --region" "$voxc" world "$work/unbounded.vox" -o "$work/w" --interpreter
expect_error "the tiles' meshes are glb, ply or none" "$voxc" world "$scene" -o "$work/w" --mesh stl --interpreter
expect_error "must lie inside" "$voxc" world "$scene" -o "$work/w" --region 90,0,0:100,10,10 --interpreter
finish
