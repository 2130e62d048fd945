#!/usr/bin/python3
"""The performance table and plot of the docs, from the committed benchmark output.

    /usr/bin/python3 bench/plot_results.py                 # print the tables, write the plot
    /usr/bin/python3 bench/plot_results.py --update-docs   # also rewrite the tables in the docs

Reads what bench/run_benchmarks.sh writes (it runs nothing itself):
  bench/results/penumbra.json, llvmpipe.json   hard-shadow frames, ours and the llvmpipe peer's
  bench/results/wedge/penumbra.json            soft-shadow frames (penumbra wedges, the oracle)
Writes:
  bench/results/performance.md                 the tables, with the machine and commit they are from
  docs/images/performance.png                  frame times per scene, size and technique
With --update-docs it replaces the blocks between the markers "<!-- hard-shadow-table:begin -->"
and "<!-- hard-shadow-table:end -->" (and the same for soft-shadow-table) in README.md and
bench/README.md by the tables, so the docs quote exactly these numbers.

Frame time is the median over the rounds of each round's mean frame time. Ratios are the medians
of each round's own ratio: run_benchmarks.sh alternates ours and the peer round by round, so a
round's ratio compares two runs that saw the same machine load.
"""
import argparse
import json
import os
import re
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The blocks --update-docs rewrites: "<!-- NAME:begin -->" ... "<!-- NAME:end -->".
BLOCKS = ("hard-shadow-table", "soft-shadow-table")
BASELINE = "volume"  # the hard-shadow benchmark without a technique suffix renders `volume`


def load(path):
    with open(path) as f:
        return json.load(f)


def strip_options(name):
    """'HardShadowFrame/columns/640x427/min_time:0.300/real_time' -> [HardShadowFrame, columns, 640x427]."""
    return [p for p in name.split("/") if ":" not in p and p != "real_time"]


def frame_ms_by_round(benchmarks, family, default_technique):
    """{(scene, size, technique): {round: frame ms}} for one benchmark family."""
    table = {}
    for b in benchmarks:
        parts = strip_options(b["name"])
        if parts[0] != family or b.get("run_type", "iteration") != "iteration":
            continue
        technique = parts[3] if len(parts) > 3 else default_technique
        key = (parts[1], parts[2], technique)
        table.setdefault(key, {})[b.get("round", 1)] = b.get("frame_ms", b["real_time"])
    return table


def peer_ms_by_round(runs):
    """{(scene, size): {round: the peer's median frame ms}}."""
    table = {}
    for r in runs:
        key = (r["scene"], f"{r['width']}x{r['height']}")
        table.setdefault(key, {})[r.get("round", 1)] = r["median_ms"]
    return table


def round_ratio(numerator, denominator):
    """Median over the rounds both ran of numerator[round] / denominator[round]; None if none."""
    rounds = sorted(set(numerator) & set(denominator))
    if not rounds:
        return None
    return statistics.median(numerator[r] / denominator[r] for r in rounds)


def machine_line(machine, what):
    if not machine:
        return f"{what}: machine not recorded."
    cpu = machine.get("cpu_model", "unknown CPU")
    family = machine.get("cpu_family")
    model = machine.get("cpu_model_number")
    if family and model:
        cpu += f" (family {family} model {model})"
    if machine.get("virtualized"):
        cpu += ", virtual machine"
    return (f"{what}: {cpu}, {machine.get('cores', '?')} cores, {machine.get('date', '?')[:10]}, "
            f"commit {machine.get('commit', '?')}, medians over {machine.get('rounds', '?')} rounds.")


def size_order(size):
    w, h = size.split("x")
    return int(w) * int(h)


def hard_rows(results_dir):
    """Rows of the hard-shadow table and the machine they were measured on."""
    ours_path = os.path.join(results_dir, "penumbra.json")
    if not os.path.exists(ours_path):
        return [], {}
    ours = load(ours_path)
    frames = frame_ms_by_round(ours["benchmarks"], "HardShadowFrame", BASELINE)
    peer_path = os.path.join(results_dir, "llvmpipe.json")
    peer = peer_ms_by_round(load(peer_path)["runs"]) if os.path.exists(peer_path) else {}
    rows = []
    for (scene, size, technique), by_round in frames.items():
        baseline = frames.get((scene, size, BASELINE), {})
        rows.append({
            "scene": scene, "size": size, "technique": technique,
            "frame_ms": statistics.median(by_round.values()),
            "llvmpipe_ms": (statistics.median(peer[(scene, size)].values())
                            if (scene, size) in peer else None),
            "vs_llvmpipe": round_ratio(peer.get((scene, size), {}), by_round),
            "vs_volume": round_ratio(baseline, by_round) if technique != BASELINE else 1.0,
        })
    scenes = list(dict.fromkeys(r["scene"] for r in rows))  # the benchmarks' own order
    rows.sort(key=lambda r: (scenes.index(r["scene"]), size_order(r["size"]),
                             r["technique"] != BASELINE, r["technique"]))
    return rows, ours.get("machine", {})


def soft_rows(results_dir):
    """Rows of the soft-shadow table: penumbra wedges and the 64-ray oracle (`reference-64`)."""
    path = os.path.join(results_dir, "wedge", "penumbra.json")
    if not os.path.exists(path):
        return [], {}
    data = load(path)
    frames = frame_ms_by_round(data["benchmarks"], "SoftShadowFrame", "?")
    rows = []
    for (scene, size, technique), by_round in frames.items():
        oracle = frames.get((scene, size, "reference-64"), {})
        rows.append({
            "scene": scene, "size": size, "technique": technique,
            "frame_ms": statistics.median(by_round.values()),
            "vs_oracle": round_ratio(oracle, by_round),
        })
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    rows.sort(key=lambda r: (scenes.index(r["scene"]), size_order(r["size"]),
                             r["technique"] == "reference-64", r["technique"]))
    return rows, data.get("machine", {})


def ratio_text(value):
    return "—" if value is None else f"{value:.2f}×"


def hard_table(rows, machine):
    if not rows:
        return ""
    lines = [
        "Hard-shadow frame (eye pass, shadow technique, shading; one light). A ratio above 1 means "
        "Penumbra's frame is that many times faster than llvmpipe's (Mesa's software OpenGL "
        "running z-fail stencil shadow volumes on the same scene) or than `volume`'s.",
        "",
        "| scene | size | technique | frame time | × llvmpipe | × `volume` |",
        "|---|---|---|---:|---:|---:|",
    ]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['size']} | `{r['technique']}` | "
                     f"{r['frame_ms']:.2f} ms | {ratio_text(r['vs_llvmpipe'])} | "
                     f"{ratio_text(r['vs_volume'])} |")
    lines += ["", machine_line(machine, "Measured on")]
    return "\n".join(lines) + "\n"


def soft_table(rows, machine):
    if not rows:
        return ""
    lines = [
        "Soft-shadow frame (penumbra wedges; `-3pass`: umbra, then penumbra; `-1pass`: one "
        "pass; `-tile8`: 8×8 tiles instead of 16×16; `-one-level`: no coarse tile level). The "
        "last column is the 64-ray oracle's (`reference-64`) frame time over this frame's, "
        "where the oracle ran at that size.",
        "",
        "| scene | size | technique | frame time | × oracle |",
        "|---|---|---|---:|---:|",
    ]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['size']} | `{r['technique']}` | "
                     f"{r['frame_ms']:.2f} ms | {ratio_text(r['vs_oracle'])} |")
    lines += ["", machine_line(machine, "Measured on")]
    return "\n".join(lines) + "\n"


def plot(hard, soft, caption, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = [p for p in (("Hard shadows", hard), ("Soft shadows (columns)", soft)) if p[1]]
    fig, axes = plt.subplots(1, len(panels), figsize=(6.5 * len(panels), 4.2), squeeze=False)
    for ax, (title, rows) in zip(axes[0], panels):
        cases = []
        for r in rows:
            case = f"{r['scene']}\n{r['size']}"
            if case not in cases:
                cases.append(case)
        series = {}
        for r in rows:
            series.setdefault(r["technique"], {})[f"{r['scene']}\n{r['size']}"] = r["frame_ms"]
        if title.startswith("Hard") and any(r["vs_llvmpipe"] is not None for r in rows):
            peer = {}
            for r in rows:
                if r["technique"] == BASELINE and r["llvmpipe_ms"] is not None:
                    peer[f"{r['scene']}\n{r['size']}"] = r["llvmpipe_ms"]
            series = {"llvmpipe (peer)": peer, **series}
        width = 0.8 / len(series)
        for i, (name, values) in enumerate(series.items()):
            xs = [c + (i - (len(series) - 1) / 2) * width for c in range(len(cases))]
            ys = [values.get(case, 0.0) for case in cases]
            ax.bar(xs, ys, width, label=name)
        ax.set_xticks(range(len(cases)))
        ax.set_xticklabels(cases, fontsize=8)
        ax.set_yscale("log")
        ax.set_ylabel("frame time, ms (log scale; lower is faster)")
        ax.set_title(title)
        ax.legend(fontsize=7)
        ax.grid(axis="y", which="both", alpha=0.3)
    fig.text(0.5, 0.01, caption, ha="center", fontsize=7)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fig.savefig(path, dpi=100)
    plt.close(fig)


def replace_blocks(path, texts):
    """Replaces each marked block the document has by its text; a document with none is an error."""
    with open(path) as f:
        doc = f.read()
    found = 0
    for name, text in texts.items():
        begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
        pattern = re.compile(re.escape(begin) + ".*?" + re.escape(end), re.S)
        doc, count = pattern.subn(lambda _: f"{begin}\n{text}{end}", doc)
        found += count
    if found == 0:
        sys.exit(f"plot_results.py: {path} has none of the blocks {', '.join(BLOCKS)} to update")
    with open(path, "w") as f:
        f.write(doc)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "bench", "results"),
                        help="the folder run_benchmarks.sh wrote (default bench/results)")
    parser.add_argument("--plot", default=os.path.join(ROOT, "docs", "images", "performance.png"))
    parser.add_argument("--update-docs", action="store_true",
                        help="rewrite the tables between the markers in README.md and bench/README.md")
    args = parser.parse_args()

    hard, hard_machine = hard_rows(args.results)
    soft, soft_machine = soft_rows(args.results)
    if not hard and not soft:
        sys.exit(f"plot_results.py: no benchmark output in {args.results} "
                 "(run bench/run_benchmarks.sh first)")
    texts = dict(zip(BLOCKS, (hard_table(hard, hard_machine), soft_table(soft, soft_machine))))
    markdown = "\n".join(t for t in texts.values() if t)
    with open(os.path.join(args.results, "performance.md"), "w") as f:
        f.write(markdown)
    caption = "\n".join(machine_line(m, what) for m, what, rows in
                        ((hard_machine, "Hard", hard), (soft_machine, "Soft", soft)) if rows)
    plot(hard, soft, caption, args.plot)
    if args.update_docs:
        for doc in ("README.md", os.path.join("bench", "README.md")):
            replace_blocks(os.path.join(ROOT, doc), texts)
    print(markdown, end="")
    print(f"\nwrote {os.path.join(args.results, 'performance.md')} and {args.plot}")


if __name__ == "__main__":
    main()
