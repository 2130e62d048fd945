#!/bin/bash
# Exact soft shadow volumes against the oracle tracing rays to the same fixed samples: per scene,
# the pixels whose visibility differs (any difference: a different count of blocked samples)
# among the pixels showing geometry, and both frame times from the same run.
#
#   bench/exact_vs_oracle.sh [--samples N] [--size WxH] [scene ...]
# Default: every built-in scene and scene file at its own size, N = 256. Writes under
# out/exact_vs_oracle/: the two visibility EXRs, the depth (mask) and a heat map per scene.
set -euo pipefail
cd "$(dirname "$0")/.."
samples=256
size=()
scenes=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --samples) samples="$2"; shift 2 ;;
    --size) size=(--width "${2%x*}" --height "${2#*x}"); shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
if [[ ${#scenes[@]} -eq 0 ]]; then
  scenes=(spheres columns fractal year2002 multilight scenes/*.json)
fi
bin=build/penumbra
out=out/exact_vs_oracle
mkdir -p "$out"
printf '%-28s %10s %12s %10s %10s %8s\n' scene differing "of covered" exact_ms oracle_ms ratio
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  exact_log=$("$bin" render "$scene" "${size[@]}" --technique exact --samples "$samples" \
    --visibility "$out/$name.exact.exr" --depth "$out/$name.depth.exr" -o "$out/$name.exact.png")
  oracle_log=$("$bin" render "$scene" "${size[@]}" --technique reference --rays "$samples" \
    --sample-set fixed --visibility "$out/$name.oracle.exr" -o "$out/$name.oracle.png")
  json=$("$bin" compare "$out/$name.exact.exr" "$out/$name.oracle.exr" --mask "$out/$name.depth.exr" \
    --tolerance 0 --diff "$out/$name.diff.png" --json)
  differing=$(sed -n 's/.*"count_over_tolerance": *\([0-9]*\).*/\1/p' <<<"$json" | head -1)
  covered=$(sed -n 's/.*"pixels": *\([0-9]*\).*/\1/p' <<<"$json" | head -1)
  # Light passes only (frames add the eye pass and shading, the same for both).
  light_ms() { sed -n 's/.*light [0-9]* \([0-9.]*\) ms.*/\1/p' <<<"$1" | awk '{s += $1} END {print s}'; }
  e=$(light_ms "$exact_log"); o=$(light_ms "$oracle_log")
  printf '%-28s %10s %12s %10.1f %10.1f %8.1f\n' "$name" "$differing" "$covered" "$e" "$o" \
    "$(awk -v a="$o" -v b="$e" 'BEGIN {print a / b}')"
done
