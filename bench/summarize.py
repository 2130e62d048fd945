#!/usr/bin/python3
"""Summarizes bench/results: medians over rounds, our fps / llvmpipe fps, a markdown table.

    /usr/bin/python3 bench/summarize.py                    # re-summarize bench/results/*.json
    /usr/bin/python3 bench/summarize.py --out-dir DIR      # another results folder

bench/run_benchmarks.sh calls it with --collect (the per-round files of one session) and
--machine; then it also writes penumbra.json and llvmpipe.json. It always writes summary.json,
summary.md and hard-shadow-fps.png into the results folder and prints the markdown.

Medians, not means: a shared machine's noise is one-sided (other work only slows us down), and a
median over rounds ignores the rounds a neighbour's compile landed in.
"""
import argparse
import glob
import json
import os
import re
import statistics
import sys

PASS_ORDER = ["eye", "silhouette", "volumes", "resolve", "shade"]


def base_name(name):
    """'HardShadowFrame/columns/640x427/min_time:0.300/real_time' -> 'HardShadowFrame/columns/640x427'."""
    return "/".join(p for p in name.split("/") if ":" not in p and p != "real_time")


def collect(work_dir, machine_path, out_dir):
    """Merges one session's per-round files into penumbra.json and llvmpipe.json."""
    machine = json.load(open(machine_path)) if machine_path else {}
    runs, context = [], None
    for path in sorted(glob.glob(os.path.join(work_dir, "penumbra-*.json")),
                       key=lambda p: int(re.search(r"penumbra-(\d+)", p).group(1))):
        data = json.load(open(path))
        round_index = int(re.search(r"penumbra-(\d+)", path).group(1))
        context = context or data.get("context")
        for b in data.get("benchmarks", []):
            b["round"] = round_index
            runs.append(b)
    with open(os.path.join(out_dir, "penumbra.json"), "w") as f:
        json.dump({"machine": machine, "context": context, "benchmarks": runs}, f, indent=1)

    peer_runs = []
    for path in sorted(glob.glob(os.path.join(work_dir, "llvmpipe-*.json"))):
        data = json.load(open(path))
        data["round"] = int(re.search(r"llvmpipe-(\d+)-", path).group(1))
        peer_runs.append(data)
    peer_path = os.path.join(out_dir, "llvmpipe.json")
    if peer_runs:
        with open(peer_path, "w") as f:
            json.dump({"machine": machine, "runs": peer_runs}, f, indent=1)
    elif os.path.exists(peer_path):
        # A stale peer file from an earlier session must not be paired with today's numbers.
        os.remove(peer_path)


def spread(values):
    return {"median": statistics.median(values), "min": min(values), "max": max(values),
            "n": len(values)}


def summarize(out_dir):
    ours = json.load(open(os.path.join(out_dir, "penumbra.json")))
    peer_path = os.path.join(out_dir, "llvmpipe.json")
    peer = json.load(open(peer_path)) if os.path.exists(peer_path) else None

    by_name = {}
    for b in ours["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
            continue
        by_name.setdefault(base_name(b["name"]), []).append(b)

    def counter(runs, key):
        values = [r[key] for r in runs if key in r]
        return spread(values) if values else None

    context = ours.get("context") or {}
    summary = {"machine": ours.get("machine", {}),
               "simd_target": context.get("penumbra_simd_target"),
               "threads": context.get("penumbra_threads"),
               "hard_shadow_frames": [], "eye_pass": [], "techniques": [],
               "soft_shadow_frames": []}
    if peer and peer["runs"]:
        first = peer["runs"][0]
        summary["peer"] = {k: first.get(k) for k in
                           ("peer", "gl_renderer", "gl_version", "casters", "depth_format",
                            "lp_num_threads", "frames", "warmup")}

    peer_fps = {}
    peer_fps_by_round = {}  # (scene, size) -> {round: fps}
    if peer:
        for r in peer["runs"]:
            key = (r["scene"], f'{r["width"]}x{r["height"]}')
            peer_fps.setdefault(key, []).append(r["fps_median"])
            if "round" in r:
                peer_fps_by_round.setdefault(key, {})[r["round"]] = r["fps_median"]

    def fps_by_round(runs):
        return {r["round"]: r["fps"] for r in runs if "round" in r and "fps" in r}

    def paired(ours_by_round, theirs_by_round):
        """Per-round ratios of two runs made next to each other in one round: the machine's
        drift between rounds (20-40 % here) cancels in each ratio, which the ratio of the two
        medians does not do."""
        ratios = [ours_by_round[k] / theirs_by_round[k] for k in ours_by_round
                  if k in theirs_by_round and theirs_by_round[k] > 0]
        return spread(ratios) if ratios else None

    for name, runs in by_name.items():
        parts = name.split("/")
        if parts[0] == "HardShadowFrame":
            scene, size = parts[1], parts[2]
            row = {"scene": scene, "size": size, "fps": counter(runs, "fps"),
                   "fps_by_round": fps_by_round(runs),
                   "technique": parts[3] if len(parts) > 3 else "volume",
                   "scene_triangles": runs[0].get("scene_triangles"),
                   "pass_ms": {p: counter(runs, p + "_ms")["median"]
                               for p in PASS_ORDER if counter(runs, p + "_ms")}}
            if (scene, size) in peer_fps:
                row["llvmpipe_fps"] = spread(peer_fps[(scene, size)])
                row["ratio"] = row["fps"]["median"] / row["llvmpipe_fps"]["median"]
                row["ratio_per_round"] = paired(row["fps_by_round"],
                                                peer_fps_by_round.get((scene, size), {}))
            summary["hard_shadow_frames"].append(row)
        elif parts[0] == "EyePass":
            summary["eye_pass"].append({"scene": parts[1], "size": parts[2], "kernel": parts[3],
                                        "Mpix/s": counter(runs, "Mpix/s"),
                                        "Mtri/s": counter(runs, "Mtri/s"),
                                        "eye_ms": counter(runs, "eye_ms")})
        elif parts[0] == "SoftShadowFrame":
            summary["soft_shadow_frames"].append(
                {"scene": parts[1], "size": parts[2], "technique": parts[3],
                 "fps": counter(runs, "fps"), "frame_ms": counter(runs, "frame_ms"),
                 "pass_ms": {p[:-3]: counter(runs, p)["median"] for p in runs[0]
                             if p.endswith("_ms") and p != "frame_ms"}})
        elif parts[0] == "Technique":
            summary["techniques"].append({"scene": parts[1], "size": parts[2],
                                          "technique": parts[3], "ms": counter(runs, "technique_ms"),
                                          "Mrays/s": counter(runs, "Mrays/s")})

    # SIMD speedup and oracle ratios are quoted from medians of the same session.
    simd = {(e["scene"], e["size"]): e for e in summary["eye_pass"] if e["kernel"] == "simd"}
    for e in summary["eye_pass"]:
        key = (e["scene"], e["size"])
        if e["kernel"] == "scalar" and key in simd:
            simd[key]["speedup_vs_scalar"] = simd[key]["Mpix/s"]["median"] / e["Mpix/s"]["median"]
    volume = {(t["scene"], t["size"]): t["ms"]["median"] for t in summary["techniques"]
              if t["technique"] == "volume"}
    for t in summary["techniques"]:
        base = volume.get((t["scene"], t["size"]))
        if base and t["technique"] != "volume":
            t["ms_vs_volume"] = t["ms"]["median"] / base

    # "At least 50x faster than the oracle at 64 rays": the oracle's frame over each wedge frame
    # of the same scene, medians of the same session.
    oracle = {(t["scene"], t["size"]): t["frame_ms"]["median"]
              for t in summary["soft_shadow_frames"] if t["technique"].startswith("reference")}
    for t in summary["soft_shadow_frames"]:
        key = (t["scene"], t["size"])
        if key in oracle and not t["technique"].startswith("reference"):
            t["oracle_frame_over_this"] = oracle[key] / t["frame_ms"]["median"]

    # Other techniques' hard-shadow frames (HardShadowFrame/<scene>/<size>/<technique>) against
    # the volume frame of the same scene and size, medians of the same session.
    volume_rows = {(r["scene"], r["size"]): r for r in summary["hard_shadow_frames"]
                   if r["technique"] == "volume"}
    for r in summary["hard_shadow_frames"]:
        base = volume_rows.get((r["scene"], r["size"]))
        if base and r["technique"] != "volume":
            r["fps_vs_volume"] = r["fps"]["median"] / base["fps"]["median"]
            r["fps_vs_volume_per_round"] = paired(r["fps_by_round"], base["fps_by_round"])

    order = {"columns": 0, "spheres": 1, "fractal": 2}
    summary["hard_shadow_frames"].sort(
        key=lambda r: (order.get(r["scene"], 9), int(r["size"].split("x")[0]),
                       r["technique"] != "volume", r["technique"]))
    summary["eye_pass"].sort(key=lambda e: (order.get(e["scene"], 9) == 1,
                                            int(e["size"].split("x")[0]), e["kernel"] != "simd"))

    with open(os.path.join(out_dir, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    markdown = to_markdown(summary, peer is not None)
    with open(os.path.join(out_dir, "summary.md"), "w") as f:
        f.write(markdown)
    plot(summary, os.path.join(out_dir, "hard-shadow-fps.png"))
    return markdown


def spread_text(s):
    return f'{s["median"]:.2f}x [{s["min"]:.2f}-{s["max"]:.2f}]' if s else "-"


def to_markdown(s, have_peer):
    m = s.get("machine", {})
    cpu = m.get("cpu_model", "?")
    if m.get("cpu_family"):
        cpu += f' (family {m["cpu_family"]} model {m.get("cpu_model_number")}, ' \
               f'{m.get("cpu_mhz", "?")} MHz{", virtual machine" if m.get("virtualized") else ""})'
    lines = [f'Machine: {cpu}, {m.get("cores", "?")} hardware threads, '
             f'{m.get("date", "?")}, commit {m.get("commit", "?")}, load average '
             f'{m.get("load_average_before", "?")} before / {m.get("load_average_after", "?")} after; '
             f'medians over {m.get("rounds", "?")} rounds, range in brackets.', ""]
    if s["hard_shadow_frames"]:
        lines += ["Hard-shadow frame (eye pass + shadow volumes, auto z-pass/z-fail + shading). "
                  "Ratio: of the medians; per round: the median of the rounds' own ratios (the "
                  "two runs of a round are minutes apart at most, so the machine's drift between "
                  "rounds cancels), range in brackets:",
                  "", "| scene | size | penumbra fps | eye / silhouette / volumes / resolve / shade "
                  "ms | llvmpipe fps | ratio | per round |", "|---|---|---|---|---|---|---|"]
    for r in s["hard_shadow_frames"]:
        passes = " / ".join(f'{r["pass_ms"].get(p, 0):.1f}' for p in PASS_ORDER)
        fps = r["fps"]
        ours = f'{fps["median"]:.1f} [{fps["min"]:.1f}-{fps["max"]:.1f}]'
        if "llvmpipe_fps" in r:
            p = r["llvmpipe_fps"]
            theirs = f'{p["median"]:.1f} [{p["min"]:.1f}-{p["max"]:.1f}]'
            ratio = f'{r["ratio"]:.2f}x'
        else:
            theirs, ratio = "not run", "-"
        per_round = spread_text(r.get("ratio_per_round"))
        scene = r["scene"] if r["technique"] == "volume" else f'{r["scene"]}, {r["technique"]}'
        if "fps_vs_volume" in r:
            ours += f' ({r["fps_vs_volume"]:.2f}x volume'
            if r.get("fps_vs_volume_per_round"):
                ours += f'; per round {spread_text(r["fps_vs_volume_per_round"])}'
            ours += ")"
        lines.append(f'| {scene} | {r["size"]} | {ours} | {passes} | {theirs} | {ratio} | '
                     f'{per_round} |')
    if have_peer and "peer" in s:
        p = s["peer"]
        lines += ["", f'Peer: {p.get("gl_renderer")}, {p.get("gl_version")}; z-fail stencil '
                      f'volumes, {p.get("casters")} casters, {p.get("depth_format")}, '
                      f'LP_NUM_THREADS={p.get("lp_num_threads")}, median of {p.get("frames")} '
                      f'frames after {p.get("warmup")} warm-up per round. Ratio = penumbra fps / '
                      f'llvmpipe fps (> 1: we are faster).']
    if not have_peer:
        lines += ["", "The llvmpipe peer was not run: ratio columns are empty."]
    lines += ["", f'penumbra: SIMD target {s.get("simd_target", "?")}, '
                  f'{s.get("threads", "?")} worker threads.']
    if s["eye_pass"]:
        lines += ["", "Eye pass (rasterizer alone):", "",
                  "| scene | size | kernel | Mpix/s | Mtri/s | ms | SIMD speedup |",
                  "|---|---|---|---|---|---|---|"]
        for e in s["eye_pass"]:
            speedup = f'{e["speedup_vs_scalar"]:.2f}x' if "speedup_vs_scalar" in e else ""
            lines.append(f'| {e["scene"]} | {e["size"]} | {e["kernel"]} | '
                         f'{e["Mpix/s"]["median"]:.1f} | '
                         f'{e["Mtri/s"]["median"]:.2f} | {e["eye_ms"]["median"]:.1f} | {speedup} |')
    if s["techniques"]:
        lines += ["", "Techniques alone (all lights, eye pass done once outside the loop):", "",
                  "| scene | size | technique | ms | Mrays/s | x volume time |", "|---|---|---|---|---|---|"]
        for t in s["techniques"]:
            rays = f'{t["Mrays/s"]["median"]:.1f}' if t.get("Mrays/s") else ""
            vs = f'{t["ms_vs_volume"]:.1f}x' if "ms_vs_volume" in t else ""
            lines.append(f'| {t["scene"]} | {t["size"]} | {t["technique"]} | '
                         f'{t["ms"]["median"]:.1f} | {rays} | {vs} |')
    if s.get("soft_shadow_frames"):
        lines += ["", "Soft-shadow frame (eye pass + technique + shading; wedges: full culling, 16x16 "
                      "tiles, -tile8: 8x8; last column: the oracle's frame over the wedge frame, "
                      "same size):", "",
                  "| scene | size | technique | fps | frame ms | passes ms | oracle-64 frame / this |",
                  "|---|---|---|---|---|---|---|"]
        for t in s["soft_shadow_frames"]:
            fps = t["fps"]
            passes = ", ".join(f"{k} {v:.1f}" for k, v in t["pass_ms"].items())
            ratio = f'{t["oracle_frame_over_this"]:.0f}x' if "oracle_frame_over_this" in t else ""
            lines.append(f'| {t["scene"]} | {t["size"]} | {t["technique"]} | '
                         f'{fps["median"]:.1f} [{fps["min"]:.1f}-{fps["max"]:.1f}] | '
                         f'{t["frame_ms"]["median"]:.1f} | {passes} | {ratio} |')
    return "\n".join(lines) + "\n"


def plot(s, path):
    rows = [r for r in s["hard_shadow_frames"] if r.get("technique", "volume") == "volume"]
    if not rows:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    labels = [f'{r["scene"]}\n{r["size"]}' for r in rows]
    x = range(len(rows))
    have_peer = any("llvmpipe_fps" in r for r in rows)
    width = 0.4 if have_peer else 0.6
    fig, ax = plt.subplots(figsize=(9, 4.5))
    ours = [r["fps"]["median"] for r in rows]
    ours_err = [[r["fps"]["median"] - r["fps"]["min"] for r in rows],
                [r["fps"]["max"] - r["fps"]["median"] for r in rows]]
    bars = ax.bar([i - (width / 2 if have_peer else 0) for i in x], ours, width, yerr=ours_err,
                  capsize=3, label="penumbra (shadow volumes)")
    ax.bar_label(bars, fmt="%.1f", fontsize=8)
    if have_peer:
        theirs = [r["llvmpipe_fps"]["median"] if "llvmpipe_fps" in r else 0 for r in rows]
        err = [[r["llvmpipe_fps"]["median"] - r["llvmpipe_fps"]["min"] if "llvmpipe_fps" in r
                else 0 for r in rows],
               [r["llvmpipe_fps"]["max"] - r["llvmpipe_fps"]["median"] if "llvmpipe_fps" in r
                else 0 for r in rows]]
        bars = ax.bar([i + width / 2 for i in x], theirs, width, yerr=err, capsize=3,
                      label="Mesa llvmpipe (GL z-fail stencil volumes)")
        ax.bar_label(bars, fmt="%.1f", fontsize=8)
    ax.set_xticks(list(x))
    ax.set_xticklabels(labels)
    ax.set_yscale("log")
    ax.set_ylabel("frames per second (median, log scale)")
    m = s.get("machine", {})
    ax.set_title(f'Hard-shadow frame, {m.get("cpu_model", "?")}, {m.get("cores", "?")} threads, '
                 f'{m.get("date", "?")[:10]}', fontsize=10)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out-dir", default=os.path.join(os.path.dirname(__file__), "results"))
    parser.add_argument("--collect", help="folder of one session's per-round result files")
    parser.add_argument("--machine", help="machine description JSON (with --collect)")
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    if args.collect:
        collect(args.collect, args.machine, args.out_dir)
    if not os.path.exists(os.path.join(args.out_dir, "penumbra.json")):
        sys.exit(f"summarize.py: no penumbra.json in {args.out_dir}: run bench/run_benchmarks.sh")
    sys.stdout.write(summarize(args.out_dir))


if __name__ == "__main__":
    main()
