#!/usr/bin/env bash
# `mpirun -np 3 voxc world` (rank 0 hands out tiles, two ranks compute them) writes the same bytes
# as one process, on the interpreter and on lavapipe; under mpirun a directory half written by
# one process resumes, keeping its tiles. A missing mpirun fails (scripts/install-deps.sh installs it).
# Usage: mpi_cli_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/expect.sh"
command -v mpirun >/dev/null || { echo "FAIL mpirun is missing (scripts/install-deps.sh installs openmpi-bin)"; exit 1; }
# CI runs as root, which Open MPI refuses unless told; --oversubscribe: 3 ranks on 2 cores.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi() { mpirun -np 3 --oversubscribe "$@"; }
scene=$src/examples/scene.vox

same_dirs() { # NAME A B: every file of A and B byte-identical, the same file names
    if diff -r "$2" "$3" >/dev/null; then pass "$1"; else fail "$1: $(diff -rq "$2" "$3" | head -3)"; fi
}

"$voxc" world "$scene" -o "$work/one" --tile 48 --interpreter 2>/dev/null || fail "one process"
mpi "$voxc" world "$scene" -o "$work/three" --tile 48 --interpreter 2>"$work/three.log" || { fail "mpirun"; cat "$work/three.log"; }
grep -q "^wrote 8 of 8 tiles of 48^3 voxels" "$work/three.log" && pass "rank 0 reports the 8 tiles once" \
    || { fail "report"; cat "$work/three.log"; }
[[ $(grep -c "^wrote" "$work/three.log") -eq 1 ]] || fail "more than one rank reported"
same_dirs "three ranks write one process's bytes (interpreter)" "$work/one" "$work/three"

"$voxc" world "$scene" -o "$work/one_vk" --tile 48 --device lavapipe 2>/dev/null || fail "one process on lavapipe"
mpi "$voxc" world "$scene" -o "$work/three_vk" --tile 48 --device lavapipe 2>/dev/null || fail "mpirun on lavapipe"
same_dirs "three ranks write one process's bytes (lavapipe)" "$work/one_vk" "$work/three_vk"

# A world one process left half done (two tiles listed, one of them altered since) resumes under mpirun.
cp -r "$work/one" "$work/resume"
python3 - "$work/resume/index.json" <<'PY'
import json, sys
path = sys.argv[1]
index = json.load(open(path))
index["tiles"] = index["tiles"][:2]
json.dump(index, open(path, "w"), indent=2)
PY
rm "$work/resume"/tile_0_0_1.vdb "$work/resume"/tile_1_0_1.vdb
printf 'x' >> "$work/resume/tile_1_0_0.vdb"
mpi "$voxc" world "$scene" -o "$work/resume" --tile 48 --interpreter 2>"$work/resume.log" || fail "resume under mpirun"
grep -q "^wrote 7 of 8 tiles .* (1 up to date)" "$work/resume.log" && pass "the resumed run keeps the 1 intact listed tile" \
    || { fail "resume report"; cat "$work/resume.log"; }
same_dirs "the resumed world equals the unbroken one" "$work/one" "$work/resume"

# A user error on every rank stops the run with exit 1.
mpi "$voxc" world "$scene" -o "$work/bad" --tile 4 --interpreter >/dev/null 2>&1
[[ $? -ne 0 ]] && pass "a bad --tile fails under mpirun" || fail "bad --tile accepted"
finish
