#!/usr/bin/env python3
"""Sweeps the light's radius with renderers prepared once, changing the light between frames.

For each technique, one Renderer renders the scene at every radius: the share of the covered
pixels in penumbra (0 < visibility < 1) and the frame time are plotted against the radius, with
the visibility images at the smallest, middle and largest radius for the first technique.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/light_radius_sweep.py \
        --scene spheres --out out/light_radius_sweep.png
"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import penumbra


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default="spheres")
    parser.add_argument("--size", default="320x214", help="WxH")
    parser.add_argument("--techniques", default="exact,wedge-3pass,pcss")
    parser.add_argument("--radii", default="0,0.1,0.2,0.4,0.6,0.8",
                        help="light radii, comma-separated (world units)")
    parser.add_argument("--out", default="out/light_radius_sweep.png")
    return parser.parse_args()


def main():
    args = parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    radii = [float(r) for r in args.radii.split(",")]
    techniques = args.techniques.split(",")
    scene = penumbra.load_scene(args.scene)

    shares, times, strips = {}, {}, []
    for technique in techniques:
        renderer = penumbra.Renderer(scene, technique=technique, width=width, height=height)
        shares[technique], times[technique] = [], []
        renderer.render()  # warm-up: the first frame faults in its memory
        for radius in radii:
            scene.lights[0].radius = radius  # the next frame sees it; nothing is re-prepared
            frame = renderer.render()
            visibility = frame.visibility[0]
            covered = frame.depth > 0
            shares[technique].append(np.mean((visibility[covered] > 0) & (visibility[covered] < 1)))
            times[technique].append(frame.render_ms)
            if technique == techniques[0] and radius in (radii[0], radii[len(radii) // 2], radii[-1]):
                strips.append((radius, visibility.copy()))
            print(f"{technique:12s} radius {radius:5.2f}: penumbra {shares[technique][-1]:.3f} "
                  f"of covered pixels, {frame.render_ms:7.2f} ms")

    fig = plt.figure(figsize=(10, 6.5))
    grid = fig.add_gridspec(2, 3)
    ax_share = fig.add_subplot(grid[0, :2])
    ax_time = fig.add_subplot(grid[0, 2])
    for technique in techniques:
        ax_share.plot(radii, shares[technique], marker="o", label=technique)
        ax_time.plot(radii, times[technique], marker="o", label=technique)
    ax_share.set_ylabel("covered pixels in penumbra")
    ax_time.set_ylabel("frame time (ms)")
    for ax in (ax_share, ax_time):
        ax.set_xlabel("light radius")
        ax.grid(True, alpha=0.3)
    ax_share.legend(fontsize=8)
    for column, (radius, visibility) in enumerate(strips[:3]):
        ax = fig.add_subplot(grid[1, column])
        ax.imshow(visibility, cmap="gray", vmin=0, vmax=1)
        ax.set_title(f"{techniques[0]} visibility, radius {radius}", fontsize=9)
        ax.axis("off")
    fig.suptitle(f"{scene.name}, {width}x{height}: light radius sweep")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    fig.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
