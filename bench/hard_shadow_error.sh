#!/bin/bash
# Hard shadows against the one-ray oracle: per scene and technique, the covered pixels whose
# visibility is on the other side of 0.5 from the oracle's, and the median warm frame time
# (eye pass + shadows + shading, technique prepared once), every technique one after the other
# in the same run. Techniques: shadow volumes (`volume`), the alias-free shadow map
# (`alias-free`), and the standard shadow map (`shadow-map`, plain 1 x 1 lookups and its default
# bias) at several resolutions per cube face.
#
#   bench/hard_shadow_error.sh [--size WxH] [--frames R] [--maps "256 1024 4096"] [scene ...]
# Default: columns and fractal at 640x427, R = 3 timed frames after the render command's three
# warm-up frames. Writes the visibility EXRs and depth masks under out/hard_shadow_error/.
set -euo pipefail
cd "$(dirname "$0")/.."
frames=3
size=(--width 640 --height 427)
maps="256 1024 4096"
scenes=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --size) size=(--width "${2%x*}" --height "${2#*x}"); shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --maps) maps="$2"; shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
if [[ ${#scenes[@]} -eq 0 ]]; then scenes=(columns fractal); fi
bin=build/penumbra
out=out/hard_shadow_error
mkdir -p "$out"
median() { sed -n 's/.*warm frame.*median \([0-9.]*\), max.*/\1/p' <<<"$1"; }
field() { sed -n "s/.*\"$1\": \([0-9.e+-]*\).*/\1/p" <<<"$2"; }
printf '%-10s %-20s %10s %10s %10s\n' scene technique differing "% covered" frame_ms
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  log=$("$bin" render "$scene" "${size[@]}" --technique reference --hard --frames "$frames" \
    --visibility "$out/$name.oracle.exr" --depth "$out/$name.depth.exr" -o "$out/$name.oracle.png")
  printf '%-10s %-20s %10s %10s %10s\n' "$name" "reference --hard" - - "$(median "$log")"
  runs=("volume:--technique volume" "alias-free:--technique alias-free")
  for m in $maps; do
    runs+=("shadow-map-$m:--technique shadow-map --shadow-map-size $m --pcf-kernel 1")
  done
  for run in "${runs[@]}"; do
    id=${run%%:*}
    read -r -a flags <<<"${run#*:}"
    log=$("$bin" render "$scene" "${size[@]}" "${flags[@]}" --frames "$frames" \
      --visibility "$out/$name.$id.exr" -o "$out/$name.$id.png")
    cmp=$("$bin" compare "$out/$name.$id.exr" "$out/$name.oracle.exr" \
      --mask "$out/$name.depth.exr" --tolerance 0.5 --json)
    differing=$(field count_over_tolerance "$cmp")
    pixels=$(field pixels "$cmp")
    printf '%-10s %-20s %10s %10.4f %10s\n' "$name" "$id" "$differing" \
      "$(awk -v d="$differing" -v p="$pixels" 'BEGIN { print 100 * d / p }')" "$(median "$log")"
  done
done
