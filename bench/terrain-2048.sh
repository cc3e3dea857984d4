#!/usr/bin/env bash
# Usage: bench/terrain-2048.sh [VOXC-BENCH] [SIDES]
# The Mountain river preset end to end at 2048^2 (spec B4.12, B5): examples/valley.vox's ridges
# and river scaled to the map, the diffusion cascade on levels 2..11, the preset's erosion
# schedule (2000, 2000, 1000, 500 steps on levels 8..11) and the drain, on the host (erosion on
# two threads); prints voxc-bench's JSON record (ms, erosion_cell_steps, cell_steps_per_second,
# peak_rss_mib). Takes minutes; not part of CI or of voxc-bench's default cases (those run the
# 512^2 map).
# SIDES: a comma list of map sides instead of 2048 (e.g. 256,512,1024,2048).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bench=${1:-$root/build/bench/voxc-bench}
sides=${2:-2048}
exec "$bench" --json --backends host --repetitions 1 --terrain-sides "$sides" \
    --benchmark_filter='^terrain_mountain_river/'
