#!/usr/bin/env python3
"""Caster culling on against off (docs/caster-culling.md): frame and per-pass times of
`penumbra render` on walkthrough frames, rounds alternated (off, on, off, on, ...), medians over
rounds of each run's median frame. A benchmark, not a test.

Usage: bench/caster_culling.py [--build build] [--rounds 3] [--frames 2] [--warmup 1]
           [--runs SCENE:FRAME:WxH:TECHNIQUE ...]
Prints one markdown row per run: frame ms off and on, on / off, the light's passes (median per
pass, on and off), casters culled of tested and silhouette edges off -> on (the last frame's
counters, which do not vary between frames).
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

DEFAULT_RUNS = [
    "city:60:640x427:volume", "city:60:640x427:hierarchical-volume", "city:60:640x427:exact",
    "city:60:1920x1080:volume", "city:60:1920x1080:hierarchical-volume",
    "city:60:1920x1080:exact",
    "interior:30:640x427:volume", "interior:30:640x427:hierarchical-volume",
    "interior:30:640x427:exact",
    "interior:30:1920x1080:volume", "interior:30:1920x1080:hierarchical-volume",
    "interior:30:1920x1080:exact",
]


def run_once(args, scene, frame, size, technique, mode, out):
    width, height = size.split("x")
    stats = os.path.join(out, "stats.json")
    command = [os.path.join(args.build, "penumbra"), "render", scene, "--frame", frame,
               "--technique", technique, "--width", width, "--height", height,
               "--frames", str(args.frames), "--warmup", str(args.warmup),
               "--caster-culling", mode, "-o", os.path.join(out, "frame.png"),
               "--stats", stats]
    text = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    frame_ms = float(re.search(r"median ([0-9.]+), max", text).group(1))
    passes = {}
    per_pass = re.search(r"median per pass: (.*) ms", text).group(1)
    for item in per_pass.split(", "):
        name, ms = item.rsplit(" ", 1)
        passes[name] = float(ms)
    numbered = [f for f in os.listdir(out) if f.startswith("stats") and f.endswith(".json")]
    with open(os.path.join(out, numbered[0])) as f:
        doc = json.load(f)
    for f in numbered:
        os.remove(os.path.join(out, f))
    counters = doc["lights"][0]["stats"]
    return frame_ms, passes, counters


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default="build")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--frames", type=int, default=2)
    parser.add_argument("--warmup", type=int, default=1)
    parser.add_argument("--runs", nargs="*", default=DEFAULT_RUNS)
    args = parser.parse_args()
    print("| scene, frame, size, technique | frame off ms | frame on ms | on / off | "
          "light passes off (median ms) | light passes on (median ms) | casters culled | "
          "silhouette edges off -> on |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as out:
        for run in args.runs:
            scene, frame, size, technique = run.split(":")
            results = {"off": [], "on": []}
            for _ in range(args.rounds):
                for mode in ("off", "on"):
                    results[mode].append(run_once(args, scene, frame, size, technique, mode, out))
                    print(f"  {run} {mode}: {results[mode][-1][0]:.1f} ms", file=sys.stderr)
            frame_ms = {m: statistics.median(r[0] for r in results[m]) for m in results}

            def passes(mode):
                names = [n for n in results[mode][0][1] if n not in ("eye", "shade")]
                return ", ".join(
                    f"{n} {statistics.median(r[1].get(n, 0.0) for r in results[mode]):.1f}"
                    for n in names)

            on, off = results["on"][-1][2], results["off"][-1][2]
            print(f"| {scene} {frame}, {size}, {technique} | {frame_ms['off']:.0f} | "
                  f"{frame_ms['on']:.0f} | {frame_ms['on'] / frame_ms['off']:.2f} | "
                  f"{passes('off')} | {passes('on')} | "
                  f"{on.get('casters_culled', 0)} / {on.get('casters_tested', 0)} | "
                  f"{off.get('silhouette_edges', 0)} -> {on.get('silhouette_edges', 0)} |",
                  flush=True)


if __name__ == "__main__":
    main()
