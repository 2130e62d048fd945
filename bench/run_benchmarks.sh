#!/usr/bin/env bash
# Runs our benchmarks and the llvmpipe peer alternately in one session and writes
#   bench/results/penumbra.json   every Google Benchmark run of every round
#   bench/results/llvmpipe.json   every peer run of every round (absent without the peer)
#   bench/results/summary.json    medians, our fps / llvmpipe fps per scene and size, machine
#   bench/results/summary.md      the same as a markdown table
#   bench/results/hard-shadow-fps.png
#
# Builds nothing: it expects $BUILD_DIR/penumbra_bench and, if present,
# $BUILD_DIR/penumbra_llvmpipe_peer. Rounds alternate ours and the peer so that both see the same
# machine load (machines are shared and noisy); quote medians and ratios, never one run.
#
#   bench/run_benchmarks.sh                          # 5 rounds, build/
#   ROUNDS=3 BUILD_DIR=build-bench bench/run_benchmarks.sh
#   PEER=/path/to/penumbra_llvmpipe_peer bench/run_benchmarks.sh
#   FILTER='HardShadowFrame' bench/run_benchmarks.sh # only some of our benchmarks
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

build_dir="${BUILD_DIR:-build}"
rounds="${ROUNDS:-5}"
filter="${FILTER:-.}"
out_dir="${OUT_DIR:-bench/results}"
bench="$build_dir/penumbra_bench"
peer="${PEER:-$build_dir/penumbra_llvmpipe_peer}"
peer_frames="${PEER_FRAMES:-10}"
peer_warmup="${PEER_WARMUP:-3}"
threads="$(nproc)"
# The scenes and sizes of HardShadowFrame/<scene>/<size> in bench/frame_bench.cpp.
scenes=(columns spheres fractal)
sizes=(640x427 1920x1080)

if [[ ! -x "$bench" ]]; then
  echo "run_benchmarks.sh: $bench not found; build it first:" >&2
  echo "  cmake -S . -B $build_dir && cmake --build $build_dir -j2 --target penumbra_bench" >&2
  exit 1
fi
have_peer=1
if [[ ! -x "$peer" ]]; then
  have_peer=0
  echo "run_benchmarks.sh: llvmpipe peer $peer not found: writing our numbers only." >&2
  echo "  (it builds where EGL and epoxy exist: cmake --build $build_dir --target penumbra_llvmpipe_peer)" >&2
fi

mkdir -p "$out_dir"
work="$(mktemp -d)"
# Load before and after: on a shared machine it says how much the numbers can be trusted.
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
trap 'rm -rf "$work"' EXIT

for ((round = 1; round <= rounds; ++round)); do
  echo "== round $round/$rounds: penumbra_bench" >&2
  # One repetition per round; the rounds are the repetitions, interleaved with the peer's.
  "$bench" --benchmark_filter="$filter" --benchmark_repetitions=1 \
    --benchmark_out="$work/penumbra-$round.json" --benchmark_out_format=json >&2
  if ((have_peer)); then
    echo "== round $round/$rounds: llvmpipe peer" >&2
    for scene in "${scenes[@]}"; do
      for size in "${sizes[@]}"; do
        "$peer" --scene "$scene" --width "${size%x*}" --height "${size#*x}" \
          --frames "$peer_frames" --warmup "$peer_warmup" --threads "$threads" \
          --json "$work/llvmpipe-$round-$scene-$size.json" >&2
      done
    done
  fi
done

machine_json="$work/machine.json"
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
commit="$(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [[ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ]]; then commit="$commit+dirty"; fi
/usr/bin/python3 - "$machine_json" "$threads" "$rounds" "$load_before" "$load_after" "$commit" <<'EOF'
import datetime, json, platform, sys
path, cores, rounds, before, after, commit = sys.argv[1:7]
# The first processor's fields: "model name" alone can be as vague as "AMD EPYC" in a VM, the
# family/model numbers name the microarchitecture (25/17 is Zen 4).
cpu = {}
for line in open("/proc/cpuinfo"):
    if not line.strip():
        break
    key, _, value = line.partition(":")
    cpu[key.strip()] = value.strip()
flags = cpu.get("flags", "").split()
json.dump({"cpu_model": cpu.get("model name", "unknown"), "cpu_family": cpu.get("cpu family"),
           "cpu_model_number": cpu.get("model"), "cpu_stepping": cpu.get("stepping"),
           "cpu_mhz": cpu.get("cpu MHz"), "virtualized": "hypervisor" in flags,
           "simd_flags": [f for f in ("avx2", "avx512f") if f in flags],
           "cores": int(cores), "kernel": platform.release(),
           "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
           "rounds": int(rounds), "load_average_before": before, "load_average_after": after,
           "commit": commit}, open(path, "w"), indent=2)
EOF

/usr/bin/python3 bench/summarize.py --collect "$work" --machine "$machine_json" --out-dir "$out_dir"
