#!/usr/bin/env bash
# Runs the llvmpipe peer on the hard-shadow acceptance cases (spheres and columns, 640x427 and
# 1920x1080) and writes bench/results/llvmpipe-<scene>-<width>x<height>.json.
# Timings are ratios: run this in the same session as our own benchmark, on the same machine,
# with the same thread count, and quote medians.
#
# Environment:
#   PEER     the peer binary (default: build-peer/, then build/ under the repository root)
#   THREADS  LP_NUM_THREADS and silhouette workers (default: all cores, as our renderer uses)
#   FRAMES   timed frames per case (default 30), WARMUP untimed frames first (default 5)
#   CASTERS  one-sided (classic Everitt-Kilgard, default) or two-sided (our renderer's volumes)
#   DEPTH    d24s8 (default) or d32fs8
#   PNG=1    also write the last frame of every case next to its JSON
#   OUT      results folder (default: bench/results)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
peer="${PEER:-}"
if [ -z "$peer" ]; then
  for candidate in "$root/build-peer/penumbra_llvmpipe_peer" "$root/build/penumbra_llvmpipe_peer"; do
    if [ -x "$candidate" ]; then peer="$candidate"; break; fi
  done
fi
if [ -z "$peer" ] || [ ! -x "$peer" ]; then
  echo "run_peer: no penumbra_llvmpipe_peer binary; build it (needs libegl-dev libepoxy-dev) or set PEER" >&2
  exit 1
fi

threads="${THREADS:-$(nproc)}"
frames="${FRAMES:-30}"
warmup="${WARMUP:-5}"
casters="${CASTERS:-one-sided}"
depth="${DEPTH:-d24s8}"
out="${OUT:-$root/bench/results}"
mkdir -p "$out"

for scene in spheres columns; do
  for size in 640x427 1920x1080; do
    width="${size%x*}"
    height="${size#*x}"
    name="llvmpipe-$scene-$size"
    extra=()
    if [ "${PNG:-0}" = 1 ]; then extra=(--png "$out/$name.png"); fi
    echo "== $scene $size"
    "$peer" --scene "$scene" --width "$width" --height "$height" --frames "$frames" \
      --warmup "$warmup" --threads "$threads" --casters "$casters" --depth "$depth" \
      --json "$out/$name.json" "${extra[@]}"
  done
done
