#!/usr/bin/env bash
# Usage: bench/compile-cache.sh [VOXC] [FILE.vox] [RUNS]
# Times `voxc run FILE` (lavapipe) with every cache empty, again with voxc's caches and Mesa's
# shader cache warm, and warm with --no-cache (Mesa's cache only), RUNS times each (default 5),
# and prints one JSON record per configuration with the median and the spread, plus the machine.
# A fresh cache directory each first run: VOXC_CACHE_DIR and XDG_CACHE_HOME (Mesa's) point into it.
set -euo pipefail
shopt -s inherit_errexit # a failed run inside $(...) stops the script
root=$(cd "$(dirname "$0")/.." && pwd)
voxc=${1:-$root/build/compiler/driver/voxc}
file=${2:-$root/examples/scene.vox}
runs=${3:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

seconds() { # seconds of one run (a failed run stops the script)
    local start=$EPOCHREALTIME
    "$@" >/dev/null 2>&1
    awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f", b - a }'
}

cold=() warm=() nocache=()
for ((i = 0; i < runs; i++)); do
    rm -rf "$work/cache"
    mkdir -p "$work/cache"
    export VOXC_CACHE_DIR="$work/cache/voxc" XDG_CACHE_HOME="$work/cache/xdg"
    cold+=("$(seconds "$voxc" run "$file" --device lavapipe -o "$work/out.ply")")
    warm+=("$(seconds "$voxc" run "$file" --device lavapipe -o "$work/out.ply")")
    nocache+=("$(seconds "$voxc" run "$file" --device lavapipe -o "$work/out.ply" --no-cache)")
done

python3 - "$file" "${cold[*]}" "${warm[*]}" "${nocache[*]}" <<'PY'
import json, platform, statistics, sys
file, *series = sys.argv[1:]
flags = set()
for line in open('/proc/cpuinfo'):
    if line.startswith('flags'):
        flags = set(line.split(':', 1)[1].split())
        break
simd = [f for f in ('sse4_2', 'avx', 'avx2', 'fma', 'avx512f') if f in flags]
names = ['run_cold_caches', 'run_warm_caches', 'run_warm_no_voxc_cache']
medians = {}
for name, values in zip(names, series):
    seconds = sorted(float(v) for v in values.split())
    medians[name] = statistics.median(seconds)
    print(json.dumps({'case': name, 'file': file, 'runs': len(seconds), 'median_s': round(medians[name], 3),
                      'min_s': round(seconds[0], 3), 'max_s': round(seconds[-1], 3),
                      'machine': platform.machine(), 'simd': simd}))
print(json.dumps({'case': 'run_cold_over_warm', 'ratio': round(medians['run_cold_caches'] / medians['run_warm_caches'], 2),
                  'no_voxc_cache_over_warm': round(medians['run_warm_no_voxc_cache'] / medians['run_warm_caches'], 2)}))
PY
