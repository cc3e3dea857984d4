#!/usr/bin/env bash
# Usage: bench/world.sh [VOXC] [SIZE] [TILE] [RANKS]
# Issue 12's world benchmark: examples/scene.vox with its world enlarged to SIZE (default
# 2048,256,2048) written by `voxc world --tile TILE` (default 256) on lavapipe, once per entry of
# RANKS (default "1 2 3": 1 is one plain process; N > 1 is `mpirun -np N --oversubscribe`, rank 0
# handing out tiles and N-1 ranks computing them). Each run gets a fresh compile cache, so every
# tile compiles its kernels as a first run does. Prints one JSON object: per run the wall and CPU
# (user, system) seconds of the whole process tree, peak RSS of its largest process, voxels per
# wall second and per CPU second, the halo overhead `voxc world` reports, and the load average
# before and after (the machine is shared). The runs' tile directories must be byte-identical,
# else it fails. Takes minutes at the default size; not part of CI.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
voxc=$(realpath "${1:-$root/build/compiler/driver/voxc}")
size=${2:-2048,256,2048}
tile=${3:-256}
ranks=${4:-1 2 3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# scene.vox with only its world size changed.
sed "s/^  size = \[96, 64, 96\];/  size = [${size//,/, }];/" "$root/examples/scene.vox" >"$work/scene.vox"
grep -q "size = \[${size//,/, }\]" "$work/scene.vox" || { echo "bench/world.sh: scene.vox's world block changed" >&2; exit 1; }

records=()
for n in $ranks; do
    command=("$voxc" world "$work/scene.vox" -o "$work/world_$n" --tile "$tile" --device lavapipe)
    # --bind-to none: with no more ranks than cores Open MPI binds each rank to one core, where
    # lavapipe's threads then wait for each other (several times the CPU time and the wall time).
    ((n > 1)) && command=(mpirun -np "$n" --oversubscribe --bind-to none "${command[@]}")
    load_before=$(cut -d' ' -f1-3 /proc/loadavg)
    VOXC_CACHE_DIR="$work/cache_$n" /usr/bin/time -f '%e %U %S %M' -o "$work/time_$n" "${command[@]}" 2>"$work/log_$n" \
        || { cat "$work/log_$n" >&2; exit 1; }
    load_after=$(cut -d' ' -f1-3 /proc/loadavg)
    read -r wall user sys rss_kib <"$work/time_$n"
    summary=$(grep '^wrote ' "$work/log_$n")
    tiles=$(sed -E 's/^wrote ([0-9]+) of.*/\1/' <<<"$summary")
    halo=$(sed -E 's/.*computed ([0-9.]+)x their voxels.*/\1/' <<<"$summary")
    records+=("$(python3 - "$n" "$size" "$wall" "$user" "$sys" "$rss_kib" "$tiles" "$halo" "$load_before" "$load_after" <<'PY'
import json, sys
n, size, wall, user, sys_s, rss, tiles, halo, before, after = sys.argv[1:]
voxels = 1
for extent in size.split(","): voxels *= int(extent)
wall, cpu = float(wall), float(user) + float(sys_s)
print(json.dumps({"processes": int(n), "computing_processes": max(1, int(n) - 1), "tiles": int(tiles),
                  "voxels": voxels, "wall_s": wall, "user_s": float(user), "system_s": float(sys_s),
                  "voxels_per_wall_s": round(voxels / wall), "voxels_per_cpu_s": round(voxels / cpu),
                  "peak_rss_mib": round(int(rss) / 1024, 1), "halo_overhead": float(halo),
                  "load_before": before, "load_after": after}))
PY
)")
done
first=""
for n in $ranks; do
    if [[ -z $first ]]; then first=$n; continue; fi
    diff -r "$work/world_$first" "$work/world_$n" >/dev/null \
        || { echo "bench/world.sh: the $n-process world differs from the $first-process one" >&2; exit 1; }
done
python3 - "$size" "$tile" "$(date -u +%Y-%m-%dT%H:%MZ)" "$(nproc)" "${records[@]}" <<'PY'
import json, sys
size, tile, when, cores, *runs = sys.argv[1:]
print(json.dumps({"benchmark": "world", "example": "examples/scene.vox", "size": [int(v) for v in size.split(",")],
                  "tile": int(tile), "device": "lavapipe", "date": when, "cores": int(cores),
                  "identical_tiles": True, "runs": [json.loads(r) for r in runs]}, indent=2))
PY
