#!/usr/bin/env bash
# voxc world end to end: tiles and index.json; a second run writes the same bytes; a run killed
# (SIGKILL) mid-way resumes, keeping the tiles it listed, and ends with the same bytes as an
# unbroken run; lavapipe's tile equals the interpreter's byte for byte; bad requests exit 1.
# Usage: world_cli_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL $*"; failed=1; }
scene=$src/examples/scene.vox

"$voxc" world "$scene" -o "$work/a" --tile 48 --interpreter 2>"$work/a.log" || { fail "voxc world"; cat "$work/a.log"; }
grep -q "^wrote 8 of 8 tiles of 48^3 voxels to $work/a (0 up to date); computed 1.44x their voxels with the halos$" "$work/a.log" \
    && echo "ok   8 tiles written" || { fail "no report"; cat "$work/a.log"; }
[[ $(ls "$work/a"/tile_*.vdb | wc -l) -eq 8 && -s $work/a/index.json ]] && echo "ok   8 .vdb files and index.json" || fail "files"
head -c 4 "$work/a/tile_1_0_1.vdb" | grep -q " BDV" && echo "ok   tiles are OpenVDB files" || fail "not a VDB file"

# Killed after two tiles are listed, then resumed: the same bytes as the unbroken run.
"$voxc" world "$scene" -o "$work/b" --tile 48 --interpreter 2>/dev/null &
pid=$!
for _ in $(seq 600); do
    [[ -f $work/b/index.json && $(grep -c '"file"' "$work/b/index.json") -ge 2 ]] && break
    sleep 0.1
done
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
listed=$(grep -c '"file"' "$work/b/index.json")
[[ $listed -ge 2 && $listed -lt 8 ]] && echo "ok   killed with $listed of 8 tiles listed" || fail "killed with $listed tiles listed"
"$voxc" world "$scene" -o "$work/b" --tile 48 --interpreter 2>"$work/b.log" || { fail "resume"; cat "$work/b.log"; }
grep -q "^wrote $((8 - listed)) of 8 tiles .* ($listed up to date)" "$work/b.log" \
    && echo "ok   the resumed run keeps the $listed listed tiles" || { fail "resume report"; cat "$work/b.log"; }
same=1
for file in "$work/a"/*; do cmp -s "$file" "$work/b/$(basename "$file")" || same=0; done
[[ $same -eq 1 ]] && echo "ok   resumed tiles and index equal the unbroken run's bytes" || fail "resumed tiles differ"
"$voxc" world "$scene" -o "$work/b" --tile 48 --interpreter 2>"$work/b.log"
grep -q "^wrote 0 of 8 tiles .* (8 up to date)$" "$work/b.log" && echo "ok   a finished world is up to date" || { fail "rerun"; cat "$work/b.log"; }

# One tile on lavapipe equals the interpreter's, byte for byte.
"$voxc" world "$scene" -o "$work/c" --tile 96 --device lavapipe 2>"$work/c.log" || { fail "lavapipe"; cat "$work/c.log"; }
"$voxc" world "$scene" -o "$work/d" --tile 96 --interpreter 2>/dev/null || fail "interpreter tile"
cmp -s "$work/c/tile_0_0_0.vdb" "$work/d/tile_0_0_0.vdb" && echo "ok   lavapipe's tile equals the interpreter's" || fail "lavapipe tile differs"

# Bad requests: exit 1 with a message.
expect_error() {
    local message=$1; shift
    "$@" >"$work/bad.log" 2>&1
    local status=$?
    [[ $status -eq 1 ]] || fail "exit status $status, not 1: $*"
    grep -q -- "$message" "$work/bad.log" && echo "ok   refused: $message" || { fail "no message '$message'"; cat "$work/bad.log"; }
}
expect_error "the tile edge must be 8 to 512 voxels" "$voxc" world "$scene" -o "$work/e" --tile 4 --interpreter
expect_error "holds the tiles of another file, world or tile size" "$voxc" world "$scene" -o "$work/a" --tile 32 --interpreter
touch "$work/file"
expect_error "is not a directory" "$voxc" world "$scene" -o "$work/file" --interpreter
exit $failed
