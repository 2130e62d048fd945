#!/usr/bin/python3
"""Plots a `penumbra bench` sweep like the 2004 paper's Figures 8-10, plus culling efficiency.

    /usr/bin/python3 scripts/plot_sweep.py --csv out/sweep/sweep.csv --out out/sweep

Writes into --out:
  figure8.png             z-buffer reads + LI (stencil) writes per frame vs culling-tile size;
                          second row: plus one (z-min, z-max) read per tile test
  figure9.png             technique time and frame rate vs tile size
  figure10.png            speedups: restructured vs 2002 without culling (10a); full culling vs
                          none and z-max only vs none, on the culled pass and the technique (10b)
  culling_efficiency.png  penumbra pixel tests per pixel truly inside a wedge, per culling mode

The speedups use the same definitions as src/evaluation/sweep_report.cpp (summarizeSweep): "no
culling" is culling none at the largest swept tile level (no tile splitting timed), "full" and
"z-max" are taken at their own fastest tile level. Run with Debian's /usr/bin/python3
(python3-matplotlib).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

IMPLS = ["wedge-3pass", "wedge-1pass"]
IMPL_LABEL = {"wedge-3pass": "three pass", "wedge-1pass": "single pass", "wedge-2002": "2002"}
IMPL_COLOR = {"wedge-3pass": "tab:blue", "wedge-1pass": "tab:orange"}
MODES = ["full", "zmax", "none"]
MODE_STYLE = {"full": "-", "zmax": "--", "none": ":"}
MODE_LABEL = {"full": "z-min + z-max (full)", "zmax": "z-max only", "none": "no culling"}
CULLED_PASS = {"wedge-3pass": "penumbra_ms", "wedge-1pass": "single_pass_ms"}


def load(path):
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            for k, v in r.items():
                if k in ("scene", "technique", "cull"):
                    continue
                r[k] = float(v) if v not in ("", None) else 0.0
            rows.append(r)
    return rows


def scenes_of(rows):
    order = []
    for r in rows:
        if r["scene"] not in order:
            order.append(r["scene"])
    return order


def series(rows, scene, impl, mode):
    pts = [r for r in rows if r["scene"] == scene and r["technique"] == impl and r["cull"] == mode
           and r["tile_level"] > 0]
    return sorted(pts, key=lambda r: r["tile_level"])


def uncull(rows, scene, impl):
    pts = series(rows, scene, impl, "none")
    return pts[-1] if pts else None


def fastest(rows, scene, impl, mode):
    pts = series(rows, scene, impl, mode)
    return min(pts, key=lambda r: r["technique_ms"]) if pts else None


def original(rows, scene):
    for r in rows:
        if r["scene"] == scene and r["technique"] == "wedge-2002":
            return r
    return None


def tile_axis(ax, levels):
    ax.set_xscale("log", base=2)
    ticks = [2 ** int(l) for l in levels]
    ax.set_xticks(ticks)
    ax.set_xticklabels([f"{t}" for t in ticks], fontsize=8)
    ax.set_xlabel("culling tile size (pixels per side)")


def subtitle(rows):
    r = rows[0]
    return f'{int(r["width"])}x{int(r["height"])}, median of {int(r["runs"])} runs'


def figure8(rows, scenes, out):
    fig, axes = plt.subplots(2, len(scenes), figsize=(4.6 * len(scenes), 7.4), squeeze=False)
    measures = [("memory_accesses", "z reads + LI writes (millions)"),
                ("memory_accesses_with_tiles", "same + 1 z-range read per tile test (millions)")]
    for row, (key, ylabel) in enumerate(measures):
        for ax, scene in zip(axes[row], scenes):
            levels = []
            for impl in IMPLS:
                for mode in MODES:
                    pts = series(rows, scene, impl, mode)
                    if not pts:
                        continue
                    levels = [p["tile_level"] for p in pts]
                    ys = [p[key] / 1e6 for p in pts]
                    ax.plot([2 ** p["tile_level"] for p in pts], ys, MODE_STYLE[mode],
                            color=IMPL_COLOR[impl], marker="o" if mode == "full" else None,
                            markersize=3, linewidth=2 if mode == "full" else 1,
                            label=f"{IMPL_LABEL[impl]}, {MODE_LABEL[mode]}")
                    if mode == "full":
                        best = min(range(len(ys)), key=lambda i: ys[i])
                        ax.plot([2 ** pts[best]["tile_level"]], [ys[best]], "*",
                                color=IMPL_COLOR[impl], markersize=12)
            tile_axis(ax, levels)
            if row == 1:
                # Tiny tiles cost millions of tile tests: show the range where the minimum is.
                top = max(p["memory_accesses"] for p in rows if p["scene"] == scene
                          and p["tile_level"] > 0) / 1e6
                ax.set_ylim(0, 1.1 * top)
            else:
                ax.set_ylim(bottom=0)
            ax.set_title(scene if row == 0 else f"{scene}, tile z-range reads counted")
            ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.suptitle(f"Memory accesses per frame vs tile size (2004 paper, Figure 8); "
                 f"{subtitle(rows)}; star: fewest with full culling", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "figure8.png"), dpi=110)
    plt.close(fig)


def figure9(rows, scenes, out):
    fig, axes = plt.subplots(2, len(scenes), figsize=(4.6 * len(scenes), 7.0), squeeze=False)
    for col, scene in enumerate(scenes):
        top, bottom = axes[0][col], axes[1][col]
        levels = []
        for impl in IMPLS:
            for mode in MODES:
                pts = series(rows, scene, impl, mode)
                if not pts:
                    continue
                levels = [p["tile_level"] for p in pts]
                x = [2 ** p["tile_level"] for p in pts]
                style = dict(color=IMPL_COLOR[impl], marker="o" if mode == "full" else None,
                             markersize=3, linewidth=2 if mode == "full" else 1,
                             label=f"{IMPL_LABEL[impl]}, {MODE_LABEL[mode]}")
                top.plot(x, [p["technique_ms"] for p in pts], MODE_STYLE[mode], **style)
                if mode == "full":
                    top.fill_between(x, [p["technique_ms_min"] for p in pts],
                                     [p["technique_ms_max"] for p in pts],
                                     color=IMPL_COLOR[impl], alpha=0.15, linewidth=0)
                bottom.plot(x, [1e3 / p["frame_ms"] for p in pts], MODE_STYLE[mode], **style)
        o = original(rows, scene)
        if o:
            top.axhline(o["technique_ms"], color="gray", linewidth=1,
                        label="2002 algorithm (no culling)")
            bottom.axhline(1e3 / o["frame_ms"], color="gray", linewidth=1,
                           label="2002 algorithm (no culling)")
        for ax in (top, bottom):
            tile_axis(ax, levels)
            ax.set_ylim(bottom=0)
            ax.grid(alpha=0.3)
        top.set_title(scene)
        top.set_ylabel("wedge technique time (ms, median)")
        bottom.set_ylabel("frame rate, eye + wedges + shading (fps)")
    axes[0][0].legend(fontsize=7)
    fig.suptitle(f"Time vs tile size (2004 paper, Figure 9); {subtitle(rows)}; band: min-max "
                 f"of full culling", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "figure9.png"), dpi=110)
    plt.close(fig)


def bars(ax, scenes, values, title, ylabel, paper=None):
    """values: {label: [per scene]}; paper: (low, high) band of the paper's claim."""
    n = len(values)
    width = 0.8 / max(n, 1)
    for i, (label, ys) in enumerate(values.items()):
        xs = [s + (i - (n - 1) / 2) * width for s in range(len(scenes))]
        b = ax.bar(xs, ys, width, label=label)
        ax.bar_label(b, fmt="%.2f", fontsize=7)
    if paper:
        ax.axhspan(paper[0], paper[1], color="green", alpha=0.12,
                   label=f"paper: {paper[0]}-{paper[1]}x")
    ax.axhline(1.0, color="black", linewidth=0.8)
    ax.set_xticks(range(len(scenes)))
    ax.set_xticklabels(scenes)
    ax.set_title(title, fontsize=9)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=7)


def ratio(a, b):
    return a / b if a and b else 0.0


def figure10(rows, scenes, out):
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4))
    restructured = {}
    culling = {}
    zmax = {}
    for impl in IMPLS:
        restructured[IMPL_LABEL[impl]] = []
        culling[f"{IMPL_LABEL[impl]}, culled pass"] = []
        culling[f"{IMPL_LABEL[impl]}, technique"] = []
        zmax[f"{IMPL_LABEL[impl]}, culled pass"] = []
        for scene in scenes:
            none, o = uncull(rows, scene, impl), original(rows, scene)
            full, zm = fastest(rows, scene, impl, "full"), fastest(rows, scene, impl, "zmax")
            restructured[IMPL_LABEL[impl]].append(
                ratio(o["technique_ms"], none["technique_ms"]) if o and none else 0.0)
            p = CULLED_PASS[impl]
            culling[f"{IMPL_LABEL[impl]}, culled pass"].append(
                ratio(none[p], full[p]) if none and full else 0.0)
            culling[f"{IMPL_LABEL[impl]}, technique"].append(
                ratio(none["technique_ms"], full["technique_ms"]) if none and full else 0.0)
            zmax[f"{IMPL_LABEL[impl]}, culled pass"].append(
                ratio(none[p], zm[p]) if none and zm else 0.0)
    bars(axes[0], scenes, restructured,
         "(a) restructured vs 2002 algorithm, no culling", "speedup (x)", paper=(1.3, 1.4))
    bars(axes[1], scenes, culling,
         "(b) full culling (fastest tile) vs none\nculled pass: three pass = penumbra pass, "
         "single pass = its one pass", "speedup (x)", paper=(3, 4))
    bars(axes[2], scenes, zmax, "(c) z-max only (fastest tile) vs none, culled pass",
         "speedup (x)")
    fig.suptitle(f"Speedups (2004 paper, Figure 10 and section 7); {subtitle(rows)}", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "figure10.png"), dpi=110)
    plt.close(fig)


def culling_efficiency(rows, scenes, out):
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.6 * len(scenes), 4.0), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        levels = []
        for impl in IMPLS:
            for mode in MODES:
                pts = [p for p in series(rows, scene, impl, mode) if p["penumbra_inside"] > 0]
                if not pts:
                    continue
                levels = [p["tile_level"] for p in pts]
                ax.plot([2 ** p["tile_level"] for p in pts],
                        [p["penumbra_tests"] / p["penumbra_inside"] for p in pts],
                        MODE_STYLE[mode], color=IMPL_COLOR[impl],
                        marker="o" if impl == "wedge-3pass" else "x", markersize=4,
                        label=f"{IMPL_LABEL[impl]}, {MODE_LABEL[mode]}")
        tile_axis(ax, levels)
        ax.set_yscale("log")
        ax.axhline(1.0, color="black", linewidth=0.8)
        ax.set_title(scene)
        ax.set_ylabel("penumbra pixel tests / pixels inside a wedge")
        ax.grid(alpha=0.3, which="both")
    axes[0][0].legend(fontsize=7)
    fig.suptitle(f"Distance from perfect culling (1 = only pixels inside a wedge tested); "
                 f"{subtitle(rows)}", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "culling_efficiency.png"), dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", default="out/sweep/sweep.csv")
    parser.add_argument("--out", default=None, help="folder for the PNGs (default: the CSV's)")
    args = parser.parse_args()
    rows = load(args.csv)
    if not rows:
        sys.exit(f"plot_sweep.py: {args.csv} has no rows")
    out = args.out or os.path.dirname(os.path.abspath(args.csv))
    os.makedirs(out, exist_ok=True)
    scenes = scenes_of(rows)
    figure8(rows, scenes, out)
    figure9(rows, scenes, out)
    figure10(rows, scenes, out)
    culling_efficiency(rows, scenes, out)
    print("wrote " + ", ".join(os.path.join(out, n) for n in
                               ("figure8.png", "figure9.png", "figure10.png",
                                "culling_efficiency.png")))


if __name__ == "__main__":
    main()
