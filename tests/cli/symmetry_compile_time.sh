#!/usr/bin/env bash
# Usage: symmetry_compile_time.sh VOXC SOURCE_DIR. A stamp under `symmetry = all` (48 variants)
# must compile and run within a stated multiple of the same stamp under `symmetry = none`: the
# stamp kernel reads the variant from tables instead of holding code per variant, so its size,
# and the driver's compile time, do not grow with the variants (an unrolled kernel took minutes).
# `voxc run` on lavapipe with every cache off (--no-cache, MESA_SHADER_CACHE_DISABLE), so each
# run compiles GLSL, SPIR-V and the driver's code afresh. The figure is the process's CPU time
# (user + system, every thread), not wall time, so the load of other processes does not count;
# the two groups alternate and the least of two runs is taken.
# The bound is generous: a ratio, never an absolute speed.
set -u
voxc=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/../support/expect.sh"
export MESA_SHADER_CACHE_DISABLE=true
bound=4

for group in none all; do
    sed "s/symmetry = none;/symmetry = $group;/" "$src/bench/grammars/stamp_symmetry.vox" > "$work/$group.vox"
done
grep -q "symmetry = all;" "$work/all.vox" && pass "all_variant_written" || fail "all_variant_written"

# CPU seconds of one cold `voxc run` of FILE on lavapipe (exit status checked).
cpu_seconds() { python3 -c '
import resource, subprocess, sys
done = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300)
if done.returncode != 0: sys.exit("voxc run exited %d" % done.returncode)
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print("%.3f" % (usage.ru_utime + usage.ru_stime))
' "$voxc" run "$1" --no-cache --device lavapipe -o "$work/out.glb"; }

declare -A best
for round in 1 2; do
    for group in none all; do
        seconds=$(cpu_seconds "$work/$group.vox") || { fail "run_$group ($round)"; continue; }
        if [[ -z ${best[$group]:-} ]] || python3 -c "import sys; sys.exit(not $seconds < ${best[$group]})"; then
            best[$group]=$seconds
        fi
    done
done
if [[ -n ${best[none]:-} && -n ${best[all]:-} ]]; then
    ratio=$(python3 -c "print('%.2f' % (${best[all]} / ${best[none]}))")
    echo "cold run CPU: symmetry = none ${best[none]} s, all ${best[all]} s, ratio $ratio (bound $bound); load: $(cut -d' ' -f1-3 /proc/loadavg)"
    python3 -c "import sys; sys.exit(not ${best[all]} <= $bound * ${best[none]})" &&
        pass "all_within_${bound}x_of_none (ratio $ratio)" || fail "all_within_${bound}x_of_none: ratio $ratio"
else
    fail "all_within_${bound}x_of_none: a run failed"
fi
finish
