#!/usr/bin/env python3
"""Penumbra error against frame time for every soft technique on one scene.

Each soft technique renders the scene with a Renderer (prepared once, then --frames warm frames
timed); its visibility is compared with the ray-traced oracle's (--oracle-rays rays per pixel)
over the penumbra pixels (0 < oracle < 1), and the median frame time and the mean absolute
error go on one log-log plot, written as a PNG.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/error_vs_time.py \
        --scene spheres --size 320x214 --out out/error_vs_time.png
"""
import argparse
import os
import statistics

import matplotlib
matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt
import numpy as np

import penumbra


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default="spheres", help="built-in name, scene or mesh file")
    parser.add_argument("--size", default="320x214", help="WxH")
    parser.add_argument("--frames", type=int, default=3, help="warm frames timed per technique")
    parser.add_argument("--oracle-rays", type=int, default=1024)
    parser.add_argument("--out", default="out/error_vs_time.png")
    return parser.parse_args()


def soft_techniques():
    # Every soft technique; the oracle itself is plotted at a few ray counts below.
    return [t["name"] for t in penumbra.techniques()
            if t["traits"]["soft"] and not t["traits"]["ray_traced"]]


def measure(scene, technique, size, frames, oracle, penumbra_mask, **options):
    renderer = penumbra.Renderer(scene, technique=technique, width=size[0], height=size[1],
                                 **options)
    renderer.render()  # warm-up: first-touch allocations, shading records
    times = []
    for _ in range(frames):
        frame = renderer.render()
        times.append(frame.render_ms)
    error = penumbra.compare(frame.visibility[0], oracle, mask=penumbra_mask)["mae"]
    return statistics.median(times), error


def main():
    args = parse_args()
    size = tuple(int(v) for v in args.size.split("x"))
    scene = penumbra.load_scene(args.scene)
    oracle = penumbra.render(scene, technique="reference", width=size[0], height=size[1],
                             rays=args.oracle_rays).visibility[0].copy()
    penumbra_mask = ((oracle > 0) & (oracle < 1)).astype(np.float32)

    points = {}
    for technique in soft_techniques():
        points[technique] = measure(scene, technique, size, args.frames, oracle, penumbra_mask)
        print(f"{technique:14s} {points[technique][0]:8.2f} ms  penumbra MAE "
              f"{points[technique][1]:.4f}")
    oracle_points = []
    for rays in (4, 16, 64):
        oracle_points.append(measure(scene, "reference", size, args.frames, oracle,
                                     penumbra_mask, rays=rays, seed=2))
        print(f"reference {rays:4d} {oracle_points[-1][0]:8.2f} ms  penumbra MAE "
              f"{oracle_points[-1][1]:.4f}")

    fig, ax = plt.subplots(figsize=(8.5, 4.5))
    floor = 1e-5  # an error of 0 (the oracle's answer exactly) still shows on the log axis
    markers = "osD^vP*Xh<>"
    for index, (technique, (ms, error)) in enumerate(points.items()):
        # A legend rather than labels beside the points: techniques of one family share an error.
        ax.scatter(ms, max(error, floor), s=45, marker=markers[index % len(markers)],
                   label=technique)
    ax.plot([p[0] for p in oracle_points], [max(p[1], floor) for p in oracle_points], "k--",
            marker="o",
            markersize=4, label="reference (oracle) at 4, 16, 64 rays")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("frame time (ms, median of warm frames)")
    ax.set_ylabel(f"penumbra MAE vs {args.oracle_rays}-ray oracle")
    ax.set_title(f"{scene.name}, {size[0]}x{size[1]}: soft shadow techniques")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    fig.savefig(args.out, dpi=110)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
