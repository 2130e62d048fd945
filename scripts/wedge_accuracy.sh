#!/usr/bin/env bash
# Renders the wedge technique and the 1024-ray oracle on the acceptance scenes of issue 3 and
# writes their visibility images and error heat maps (docs/wedge-accuracy.md shows them):
#   scripts/wedge_accuracy.sh [build dir] [output dir]
set -euo pipefail
build="${1:-build}"
out="${2:-docs/images/wedge-accuracy}"
mkdir -p "$out"
for scene in spheres columns scenes/bunny-lowres.json tests/data/scenes/stanford-bunny.json; do
  name="$(basename "$scene" .json)"
  "$build/penumbra" render "$scene" --width 640 --height 427 --quiet --technique wedge-3pass \
    --visibility "$out/$name-wedge.exr" --visibility-png "$out/$name-wedge.png" -o "$out/shaded.png"
  "$build/penumbra" render "$scene" --width 640 --height 427 --quiet --technique reference \
    --rays 1024 --visibility "$out/$name-oracle.exr" --visibility-png "$out/$name-oracle.png" \
    -o "$out/oracle-shaded.png"
  echo "== $name (wedge-3pass against the 1024-ray oracle)"
  "$build/penumbra" compare "$out/$name-wedge.exr" "$out/$name-oracle.exr" \
    --diff "$out/$name-diff.png" --diff-scale 0.25
done
rm -f "$out"/*.exr "$out/shaded.png" "$out/oracle-shaded.png"
