#!/usr/bin/env bash
# A tile of `voxc world` opened by OpenVDB's own tools, not voxc's reader: OpenVDB's Python
# module (python3-openvdb) reads every density, and vdb_print (Debian libopenvdb-tools) gives the
# material grid's range, active voxel count and box; both must agree with `voxc interp --region`
# of the tile's box (the whole world's voxels there). A missing tool fails
# (scripts/install-deps.sh installs both).
# Usage: vdb_reader_test.sh VOXC SOURCE_DIR
set -uo pipefail
voxc=$1 src=$2
source "$src/tests/support/expect.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Debian's Python, which python3-openvdb installs the module for (a python3 earlier in PATH may not see it).
python=/usr/bin/python3
command -v vdb_print >/dev/null || { fail "vdb_print is missing (scripts/install-deps.sh installs libopenvdb-tools)"; finish; }
"$python" -c "import pyopenvdb" 2>/dev/null || { fail "pyopenvdb is missing (scripts/install-deps.sh installs python3-openvdb)"; finish; }
scene=$src/examples/scene.vox

expect "voxc world" 0 "" -- "$voxc" world "$scene" -o "$work/world" --tile 48 --mesh none --interpreter
tile=$work/world/tile_1_0_1.vdb
vdb_print -l "$tile" >"$work/print.txt" 2>&1 && pass "vdb_print opens the tile" || { fail "vdb_print"; cat "$work/print.txt"; }
expect "voxc interp --region of the tile's box" 0 "" -- "$voxc" interp "$scene" --region 48,0,48:96,48,96 \
    --voxels "$work/region.npy" --materials "$work/region_materials.npy"
# pyopenvdb's readAll opens the whole tile: both grids are float, the density a fog volume, and the
# material ids come back exactly; vdb_print's statistics agree.
expect "OpenVDB's reader sees the whole world's voxels in the tile" 0 "^same: 110592 voxels" -- "$python" - "$tile" \
    "$work/region.npy" "$work/region_materials.npy" "$work/print.txt" <<'PY'
import re
import sys
import numpy as np
import pyopenvdb as vdb

tile, densities, materials, printed = sys.argv[1], np.load(sys.argv[2]), np.load(sys.argv[3]), open(sys.argv[4]).read()

def grid_stats(name):
    block = printed.split("Name: " + name)[1].split("Name: ")[0]
    number = lambda label: re.search(label + r":\s+([-0-9.,e]+)", block).group(1).replace(",", "")
    box = re.search(r"Bounding box of active voxels: \[(.*?)\] -> \[(.*?)\]", block)
    return float(number("Min value")), float(number("Max value")), int(number("Number of active voxels")), box.groups()

def check(what, got, want):
    if got != want:
        print(f"{what}: vdb_print says {got}, the region run {want}")
        sys.exit(1)

grids, _ = vdb.readAll(tile)
by_name = {g.name: g for g in grids}
if sorted(by_name) != ["density", "material"]:
    print("readAll gives the grids", sorted(by_name))
    sys.exit(1)
if by_name["density"].gridClass != vdb.GridClass.FOG_VOLUME:
    print("the density grid's class is", by_name["density"].gridClass)
    sys.exit(1)
ids = np.zeros(materials.shape, dtype=np.float32)
by_name["material"].copyToArray(ids, ijk=(48, 0, 48))
if ids.tobytes() != materials.astype(np.float32).tobytes():
    print("materials differ at", np.argwhere(ids != materials)[:5].tolist())
    sys.exit(1)
got = np.zeros(densities.shape, dtype=np.float32)
by_name["density"].copyToArray(got, ijk=(48, 0, 48))
if got.tobytes() != densities.astype(np.float32).tobytes():
    print("densities differ at", np.argwhere(got != densities)[:5].tolist())
    sys.exit(1)
solid = materials[materials != 0]
low, high, active, box = grid_stats("material")
check("material min, max, active voxels", (low, high, active), (float(solid.min()), float(solid.max()), solid.size))
used = np.argwhere(materials != 0)
check("material box", box, (", ".join(str(48 * (a != 1) + v) for a, v in enumerate(used.min(0))),
                            ", ".join(str(48 * (a != 1) + v) for a, v in enumerate(used.max(0)))))
check("density active voxels", grid_stats("density")[2], int((densities != 0).sum()))
print(f"same: {got.size} voxels, {solid.size} with a material, ids {solid.min()}..{solid.max()}")
PY
finish
