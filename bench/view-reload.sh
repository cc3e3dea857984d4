#!/usr/bin/env bash
# Usage: bench/view-reload.sh [VOXC] [FILE] [PARAMETER VALUE]
# Times a reload of `voxc view` (a slider let go) phase by phase: opens FILE (default
# bench/worlds/curves_cliff_256.vox) under Xvfb on lavapipe with a fresh solve and kernel cache,
# sets PARAMETER to VALUE (default cliffs.face.constraint[1].amplitude 8) from a script, and
# prints the viewer's log line for that reload (check, solve, compile, run and mesh
# milliseconds; a large curves block shows its coarse preview) with the load average before.
# Closing the window waits for the background solve the reload started. Not part of CI.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
voxc=$(realpath "${1:-$root/build/compiler/driver/voxc}")
file=$(realpath "${2:-$root/bench/worlds/curves_cliff_256.vox}")
parameter=${3:-cliffs.face.constraint[1].amplitude}
value=${4:-8}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export VOXC_CACHE_DIR="$work/cache"
printf 'set %s %s\nscreenshot %s\n' "$parameter" "$value" "$work/shown.png" >"$work/script.txt"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
xvfb-run -a -s "-screen 0 1024x768x24" "$voxc" view "$file" --device lavapipe --size 480x270 \
    --script "$work/script.txt" >"$work/log" 2>&1 || { cat "$work/log" >&2; exit 1; }
grep "view: reloaded" "$work/log"
