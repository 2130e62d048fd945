#!/bin/bash
# Exact soft shadow volumes against the oracle tracing rays to the same fixed samples: per scene,
# the pixels whose visibility differs (any difference: a different count of blocked samples)
# among the pixels showing geometry, and the median frame times of both, measured one after
# the other in the same run (frame = eye pass + shadows + shading, the technique prepared once:
# the oracle's BVH build is not in it).
#
#   [PENUMBRA_BIN=build/penumbra] bench/exact_vs_oracle.sh [--samples N] [--size WxH] [--frames R] [scene ...]
# Default: every built-in scene and scene file at its own size, N = 256, R = 3 timed frames
# after the render command's three warm-up frames. Writes under out/exact_vs_oracle/: the two
# visibility EXRs, the depth (mask) and a heat map per scene.
set -euo pipefail
cd "$(dirname "$0")/.."
samples=256
frames=3
size=()
scenes=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --samples) samples="$2"; shift 2 ;;
    --size) size=(--width "${2%x*}" --height "${2#*x}"); shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
if [[ ${#scenes[@]} -eq 0 ]]; then
  scenes=(spheres columns fractal year2002 multilight scenes/*.json)
fi
bin=${PENUMBRA_BIN:-build/penumbra}  # another build: PENUMBRA_BIN=path/to/penumbra
out=out/exact_vs_oracle
mkdir -p "$out"
printf '%-28s %10s %12s %10s %10s %8s\n' scene differing "of covered" exact_ms oracle_ms ratio
median() { sed -n 's/.*warm frame.*median \([0-9.]*\), max.*/\1/p' <<<"$1"; }
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  exact_log=$("$bin" render "$scene" "${size[@]}" --technique exact --samples "$samples" \
    --frames "$frames" --visibility "$out/$name.exact.exr" --depth "$out/$name.depth.exr" \
    -o "$out/$name.exact.png")
  oracle_log=$("$bin" render "$scene" "${size[@]}" --technique reference --rays "$samples" \
    --sample-set fixed --frames "$frames" --visibility "$out/$name.oracle.exr" \
    -o "$out/$name.oracle.png")
  json=$("$bin" compare "$out/$name.exact.exr" "$out/$name.oracle.exr" --mask "$out/$name.depth.exr" \
    --tolerance 0 --diff "$out/$name.diff.png" --json)
  differing=$(sed -n 's/.*"count_over_tolerance": *\([0-9]*\).*/\1/p' <<<"$json" | head -1)
  covered=$(sed -n 's/.*"pixels": *\([0-9]*\).*/\1/p' <<<"$json" | head -1)
  e=$(median "$exact_log"); o=$(median "$oracle_log")
  printf '%-28s %10s %12s %10.1f %10.1f %8.1f\n' "$name" "$differing" "$covered" "$e" "$o" \
    "$(awk -v a="$o" -v b="$e" 'BEGIN {print a / b}')"
done
