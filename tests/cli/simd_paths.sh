#!/usr/bin/env bash
# Usage: simd_paths.sh VOXC SOURCE_DIR. The host's vectorised loops (the curves multigrid's row
# kernels, colour sweeps and max residuals, the batched noise of the curves' displacement, the
# erosion's row kernels, the mesher's sign classification) give the same bits on every path:
# VOXC_SIMD=avx2 and none against the CPU's widest path (docs/cli.md, "Environment"). On a CPU without AVX-512 the avx512 run is its
# widest path again, so the test still compares every path the CPU has.
set -u
voxc=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
channels=(density normal_x normal_y normal_z amplitude roughness distance smoothed displacement)
for simd in avx512 avx2 none; do
    out="$work/$simd"
    mkdir -p "$out"
    dumps=()
    for channel in "${channels[@]}"; do dumps+=("$channel=$out/$channel.npy"); done
    # An empty cache each time: a solve read from the cache would run no kernel.
    VOXC_SIMD=$simd VOXC_CACHE_DIR="$out/cache" "$voxc" interp -q "$src/examples/curves_cliff.vox" \
        --voxels "$out/cliff.npy" --materials "$out/cliff_materials.npy" --dump "${dumps[@]}" 2> "$out/stderr" ||
        { echo "FAIL: interp with VOXC_SIMD=$simd"; cat "$out/stderr"; status=1; }
    VOXC_SIMD=$simd VOXC_CACHE_DIR="$out/cache" "$voxc" interp -q "$src/examples/mountains.vox" \
        --voxels "$out/mountains.npy" --materials "$out/mountains_materials.npy" 2>> "$out/stderr" ||
        { echo "FAIL: interp of mountains.vox with VOXC_SIMD=$simd"; cat "$out/stderr"; status=1; }
    VOXC_SIMD=$simd VOXC_CACHE_DIR="$out/cache" "$voxc" run -q "$src/examples/overhang.vox" -o "$out/overhang.ply" \
        2>> "$out/stderr" || { echo "FAIL: run with VOXC_SIMD=$simd"; cat "$out/stderr"; status=1; }
    if [ -s "$out/stderr" ]; then echo "FAIL: VOXC_SIMD=$simd printed:"; cat "$out/stderr"; status=1; fi
done
for simd in avx2 none; do
    for file in cliff.npy cliff_materials.npy mountains.npy mountains_materials.npy overhang.ply "${channels[@]/%/.npy}"; do
        if ! cmp -s "$work/avx512/$file" "$work/$simd/$file"; then
            echo "FAIL: $file differs between VOXC_SIMD=avx512 and $simd"
            status=1
        fi
    done
done
# A value it does not know: one warning, the CPU's widest path, the same voxels.
VOXC_SIMD=avx1024 VOXC_CACHE_DIR="$work/cache" "$voxc" interp -q "$src/examples/curves_cliff.vox" \
    --voxels "$work/unknown.npy" 2> "$work/unknown.stderr"
if ! grep -q "VOXC_SIMD=avx1024 is not one of avx512, avx2, none" "$work/unknown.stderr" ||
    [ "$(wc -l < "$work/unknown.stderr")" != 1 ] || ! cmp -s "$work/avx512/cliff.npy" "$work/unknown.npy"; then
    echo "FAIL: an unknown VOXC_SIMD value"
    cat "$work/unknown.stderr"
    status=1
fi
[ $status = 0 ] && echo "simd_paths: every path gave the same bits"
exit $status
