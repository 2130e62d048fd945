#!/usr/bin/env python3
"""The thesis-style depth-complexity table (Aila 2005, section 5.1) from the DelayStream
benchmarks' JSON (bench/delay_stream_bench.cpp).

    PENUMBRA_DELAY_SCENES=city@0,interior@0 build/penumbra_bench \\
        --benchmark_filter=DelayStream --benchmark_format=json > out/delay.json
    python3 bench/delay_stream_table.py out/delay.json

Per scene and ring: pixels tested and pixels passing the depth test per covered pixel (the
optimum is 1.00 for both), the fewer passing pixels than early-z as a factor, the pairs culled,
and the eye pass's median time with the time of `plain` as the ratio.
"""
import json
import sys


def main(path):
    with open(path) as f:
        runs = json.load(f)["benchmarks"]
    rows = {}
    order = []
    for run in runs:
        if run.get("run_type") == "aggregate":
            continue
        # DelayStream/<scene, which may hold '/'>/<size>/<ring>
        # (Google Benchmark appends "/min_time:...", "/real_time").
        parts = [p for p in run["name"].split("/") if ":" not in p and p != "real_time"]
        scene, size, ring = "/".join(parts[1:-2]), parts[-2], parts[-1]
        key = (scene, size)
        if key not in rows:
            rows[key] = {}
            order.append(key)
        rows[key][ring] = run
    for key in order:
        scene, size = key
        ring_runs = rows[key]
        first = next(iter(ring_runs.values()))
        print(f"\n{scene} {size}: {int(first['triangles'])} triangles set up, "
              f"{int(first['covered'])} covered pixels")
        print("| ring | triangles held | tested / covered | passed / covered | "
              "passed: early-z / this | pairs culled | eye ms | time / plain |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|")
        early = ring_runs.get("early-z")
        plain = ring_runs.get("plain")
        print("| optimum | | 1.00 | 1.00 | | | | |")
        for ring, run in ring_runs.items():
            held = "" if ring == "plain" else f"{int(run['ring_triangles'])}"
            gain = f"{early['passes'] / run['passes']:.2f}x" if early else ""
            ratio = f"{run['eye_ms'] / plain['eye_ms']:.2f}" if plain else ""
            print(f"| {ring} | {held} | {run['tested_per_covered']:.2f} | "
                  f"{run['passes_per_covered']:.2f} | {gain} | {int(run['culled_pairs'])} | "
                  f"{run['eye_ms']:.1f} | {ratio} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "/dev/stdin")
