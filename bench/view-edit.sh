#!/usr/bin/env bash
# Usage: bench/view-edit.sh [VOXC] [FILE]
# Times the brush edits of `voxc view` after a load: opens FILE (default
# bench/worlds/curves_cliff_256.vox) under Xvfb on lavapipe with a fresh solve and kernel cache,
# waits for the full solve to replace the coarse preview, then carves, adds and carves again where
# a ray down the box's middle meets the surface, and prints the viewer's log line for each edit
# (its time and the chunks whose mesh it can change, then the time for the world's mesh the next
# frame draws) with the load average before. The first edit after a load is the one a per-chunk
# mesher would make every chunk's share of the mesh for. Not part of CI.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
voxc=$(realpath "${1:-$root/build/compiler/driver/voxc}")
file=$(realpath "${2:-$root/bench/worlds/curves_cliff_256.vox}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache"
read -r x y z < <(sed -n 's/.*world *{ *size *= *\[ *\([0-9]*\), *\([0-9]*\), *\([0-9]*\) *\].*/\1 \2 \3/p' "$file" | head -1)
ray="$((x / 2)),$((y + 8)),$((z / 2)) 0,-1,0"
cat >"$work/script.txt" <<SCRIPT
wait-refined 600
set radius 6
carve-ray $ray
add-ray $ray
carve-ray $ray
SCRIPT
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
xvfb-run -a -s "-screen 0 1024x768x24" "$voxc" view "$file" --device lavapipe --size 480x270 \
    --script "$work/script.txt" >"$work/log" 2>&1 || { cat "$work/log" >&2; exit 1; }
grep -E "view: (carve|add) in" "$work/log"
