#!/usr/bin/env bash
# Runs voxc's fuzz targets (docs/fuzzing.md).
#
#   scripts/fuzz.sh TARGET|all SECONDS [--runs N] [--fresh] [--keep-going] [--no-build]
#   scripts/fuzz.sh --build
#
# TARGET is parse, check or lower (libFuzzer, ASan + UBSan, in the clang tree build-fuzz/,
# configured and built here when needed; VOXC_FUZZ_BUILD_DIR overrides it) or diff (the
# differential fuzzer, interpreter vs Vulkan, in the g++ tree build/; VOXC_BUILD_DIR overrides it).
# `all` runs parse, check and lower, SECONDS each. --runs N stops a target after N inputs.
# Inputs come from the seeds (examples/, every .vox under tests/), tests/fuzz/regressions/TARGET,
# the committed corpus tests/fuzz/corpus/TARGET (where there is one) and a working corpus kept in
# the build tree; --fresh uses a temporary one instead, so a run starts from the committed inputs
# only. --keep-going runs libFuzzer in fork mode and carries on past crashes, hangs and OOMs (each
# saved under the build tree's fuzz/artifacts/TARGET/). --no-build runs the targets as built (for
# several runs at once on one tree). Prints executions, coverage and findings per target and
# exits non-zero on any crash, hang (> 1 s per input; VOXC_FUZZ_TIMEOUT=SECONDS on a machine too busy
# for that to mean a hang), OOM or sanitizer report.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fuzz_build=${VOXC_FUZZ_BUILD_DIR:-$root/build-fuzz}
normal_build=${VOXC_BUILD_DIR:-$root/build}
libfuzzer_targets=(parse check lower)

usage() { sed -n '4,5p' "$0" | sed 's/^# *//' >&2; exit 2; }

build_fuzz_tree() {
    command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (scripts/install-deps.sh installs it)" >&2; exit 1; }
    if [ ! -f "$fuzz_build/CMakeCache.txt" ]; then
        CC=clang CXX=clang++ cmake -S "$root" -B "$fuzz_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVOXC_FUZZ=ON \
            -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 >/dev/null
    fi
    cmake --build "$fuzz_build" -j"$(nproc)" --target voxc_fuzz_dictionary "${libfuzzer_targets[@]/#/voxc_fuzz_}"
    "$fuzz_build/tests/fuzz/voxc_fuzz_dictionary" > "$fuzz_build/tests/fuzz/vox.dict"
}

if [ "${1:-}" = "--build" ]; then
    build_fuzz_tree
    exit 0
fi
[ $# -ge 2 ] || usage
target=$1 seconds=$2
shift 2
runs=-1 fresh=0 keep_going=0 build=1
while [ $# -gt 0 ]; do
    case $1 in
        --runs) runs=$2; shift 2 ;;
        --fresh) fresh=1; shift ;;
        --keep-going) keep_going=1; shift ;;
        --no-build) build=0; shift ;;
        *) usage ;;
    esac
done

if [ "$target" = diff ]; then
    [ -f "$normal_build/CMakeCache.txt" ] || cmake -S "$root" -B "$normal_build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$normal_build" -j"$(nproc)" --target voxc_diff_fuzz
    args=(--seconds "$seconds")
    [ "$runs" -lt 0 ] || args=(--programs "$runs")
    exec "$normal_build/tests/fuzz/voxc_diff_fuzz" "${args[@]}" --seed "${VOXC_DIFF_SEED:-$RANDOM}"
fi

case $target in
    all) targets=("${libfuzzer_targets[@]}") ;;
    parse|check|lower) targets=("$target") ;;
    *) usage ;;
esac
[ $build -eq 0 ] || build_fuzz_tree

work=$fuzz_build/fuzz
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
seeds=$scratch/seeds
mkdir -p "$seeds"
# Seeds are named by content so two equal files are one seed.
while IFS= read -r -d '' file; do
    cp "$file" "$seeds/$(sha1sum "$file" | cut -c1-16)"
done < <(find "$root/examples" "$root/tests" -name '*.vox' -not -path "$root/tests/fuzz/regressions/*" -print0)
if [ $fresh -eq 1 ]; then
    corpus_root=$scratch/corpus
else
    corpus_root=$work/corpus
fi

failed=0
for t in "${targets[@]}"; do
    corpus=$corpus_root/$t artifacts=$work/artifacts/$t/ log=$work/$t.log
    [ $fresh -eq 0 ] || log=$work/$t-fresh.log
    mkdir -p "$corpus" "$artifacts"
    options=(-dict="$fuzz_build/tests/fuzz/vox.dict" -timeout="${VOXC_FUZZ_TIMEOUT:-1}" -rss_limit_mb=2048 -max_len=4096
             -max_total_time="$seconds" -runs="$runs" -artifact_prefix="$artifacts" -print_final_stats=1)
    [ $keep_going -eq 0 ] || options+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
    status=0 started=$SECONDS
    # A clean clone has no empty folders, so a target without reproducers or corpus has neither.
    inputs=("$corpus" "$seeds")
    for committed in "$root/tests/fuzz/regressions/$t" "$root/tests/fuzz/corpus/$t"; do
        [ ! -d "$committed" ] || inputs+=("$committed")
    done
    "$fuzz_build/tests/fuzz/voxc_fuzz_$t" "${options[@]}" "${inputs[@]}" > "$log" 2>&1 || status=$?
    elapsed=$((SECONDS - started))
    found=$( (grep -aoE 'Test unit written to .*' "$log" || true) | sort -u | wc -l)
    # The last progress line ("#N ... cov: C ft: F corp: K/..") holds the totals; final stats
    # repeat the executions when libFuzzer printed them.
    progress=$(grep -aE '^#[0-9]+' "$log" | tail -n 1 || true)
    executions=$(grep -aoE 'stat::number_of_executed_units: [0-9]+' "$log" | grep -oE '[0-9]+$' | tail -n 1 || true)
    [ -n "$executions" ] || executions=$(grep -oE '^#[0-9]+' <<< "$progress" | tr -d '#' || true)
    coverage=$(grep -oE 'cov: [0-9]+ ft: [0-9]+' <<< "$progress" || true)
    if [ $status -ne 0 ] || [ "$found" -gt 0 ] || grep -aqE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:' "$log"; then
        failed=1
        echo "fuzz $t: FAILED (exit $status): ${executions:-0} executions in ${elapsed}s, ${coverage:-no coverage}, $found inputs saved in $artifacts, log $log"
        grep -aE 'ERROR:|runtime error:|SUMMARY:|Test unit written' "$log" | head -n 20 | sed 's/^/  /'
    else
        echo "fuzz $t: ${executions:-0} executions in ${elapsed}s, ${coverage:-no coverage}, 0 crashes/hangs/sanitizer reports"
    fi
done
exit $failed
