#!/usr/bin/env python3
"""voxc's fbm5 on the host beside FastNoise2, alternated in one sitting.

Usage: bench/fbm5-fastnoise2.py VOXC_BENCH FN2_FBM5 OUT.json [PAIRS]

VOXC_BENCH is build/bench/voxc-bench; FN2_FBM5 the harness of ../shared/peers/fastnoise2 (built
outside this tree, see its README). Runs PAIRS (default 5) pairs at the CPU's widest SIMD, then
three with both held to AVX2 (VOXC_SIMD=avx2, FN2_SIMD=AVX2), each voxc run the median of five
repetitions of `fbm5/256/host`, each FastNoise2 run the median of five runs on two threads; prints
one line per pair and writes every record, with the load average before the pair, to OUT.json.
"""
import json
import os
import subprocess
import sys


def load_average():
    with open("/proc/loadavg") as f:
        return f.read().split()[0]


def voxc_run(bench, simd):
    out = subprocess.run([bench, "--json", "--sizes", "128", "--field-sizes", "256", "--backends", "host",
                          "--repetitions", "5", "--benchmark_filter=^fbm5/256/host"],
                         env=dict(os.environ, VOXC_SIMD=simd), capture_output=True, text=True, check=True).stdout
    record = next(r for r in json.loads(out) if r.get("case") == "fbm5" and r.get("backend") == "host")
    record["simd_env"] = simd
    return record


def fastnoise_run(harness, simd):
    env = dict(os.environ)
    if simd:
        env["FN2_SIMD"] = simd
    out = subprocess.run([harness, "--n", "256", "--runs", "5", "--warmup", "1", "--threads", "2", "--json"],
                         env=env, capture_output=True, text=True, check=True).stdout
    records = json.loads(out)
    return records if isinstance(records, list) else [records]


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    bench, harness, output = sys.argv[1:4]
    pairs = int(sys.argv[4]) if len(sys.argv) == 5 else 5
    records = []
    for simd, peer_simd, count in (("avx512", None, pairs), ("avx2", "AVX2", 3)):
        for pair in range(count):
            load = load_average()
            voxc = voxc_run(bench, simd)
            peer = fastnoise_run(harness, peer_simd)
            for record in [voxc] + peer:
                record["load"], record["pair"] = load, pair
            records += [voxc] + peer
            peer_ms = ", ".join("%.1f" % r["median_ms"] for r in peer)
            print(f"{simd} pair {pair}: voxc {voxc['ms']:.1f} ms, FastNoise2 {peer_ms} ms, load {load}", flush=True)
    with open(output, "w") as f:
        json.dump(records, f, indent=1)


if __name__ == "__main__":
    main()
