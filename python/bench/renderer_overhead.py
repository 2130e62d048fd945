#!/usr/bin/env python3
"""Python's overhead on a warm Renderer.render, against the CLI's warm frame loop.

Each round runs `penumbra render SCENE --frames N` (the C++ loop: FrameRenderer::render into one
reused FrameResult, timed per frame in C++) and then N warm frames of one penumbra.Renderer,
each timed in Python around renderer.render() (the call, the GIL release, wrapping the buffers
as numpy arrays); both after the same number of untimed warm-up frames. Prints each round's
medians and their ratio, and the median of the rounds' ratios. On a shared machine the two
processes' frames vary with the load, so each Python frame is also measured against itself:
its time in Python against frame.render_ms, the library's call timed in C++ inside the binding;
the difference is what the binding adds (checks, GIL, wrapping the buffers).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/renderer_overhead.py \
        --cli build/penumbra --scene spheres --rounds 7 --frames 30
"""
import argparse
import re
import statistics
import subprocess
import time

import penumbra


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default="build/penumbra")
    parser.add_argument("--scene", default="spheres")
    parser.add_argument("--technique", default="wedge-3pass")
    parser.add_argument("--size", default=None, help="WxH (default: the scene's)")
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--warmup", type=int, default=3)
    parser.add_argument("--rounds", type=int, default=7)
    return parser.parse_args()


def cli_median_ms(args, size_args):
    out = subprocess.run([args.cli, "render", args.scene, "--technique", args.technique,
                          "--frames", str(args.frames), "--warmup", str(args.warmup),
                          "-o", "out/overhead_cli.png", *size_args],
                         check=True, capture_output=True, text=True).stdout
    match = re.search(r"warm frames? \(.*?\): min [0-9.]+, median ([0-9.]+)", out)
    if not match:
        raise SystemExit(f"no frame timings in the CLI's output:\n{out}")
    return float(match.group(1))


def python_medians(renderer, args):
    """Median ms in Python per frame, and median of the frames' added share over render_ms."""
    for _ in range(args.warmup):
        frame = renderer.render()
    times, added = [], []
    for _ in range(args.frames):
        start = time.perf_counter()
        frame = renderer.render()
        ms = (time.perf_counter() - start) * 1000.0
        times.append(ms)
        added.append(ms / frame.render_ms - 1.0)
    del frame
    return statistics.median(times), statistics.median(added)


def main():
    args = parse_args()
    width, height = (int(v) for v in args.size.split("x")) if args.size else (None, None)
    size_args = ["--width", str(width), "--height", str(height)] if args.size else []
    renderer = penumbra.Renderer(args.scene, technique=args.technique, width=width, height=height)
    ratios, shares = [], []
    for round_index in range(args.rounds):
        cli_ms = cli_median_ms(args, size_args)
        python_ms, added = python_medians(renderer, args)
        ratios.append(python_ms / cli_ms)
        shares.append(added)
        print(f"round {round_index + 1}: CLI median {cli_ms:.3f} ms, Python median "
              f"{python_ms:.3f} ms, ratio {ratios[-1]:.4f}; binding adds {100 * added:.3f} %")
    print(f"{args.scene} {args.technique}: median of {args.rounds} rounds' ratios Python / CLI "
          f"{statistics.median(ratios):.4f}; the binding adds {100 * statistics.median(shares):.3f} "
          f"% of the library's frame (median of rounds)")


if __name__ == "__main__":
    main()
