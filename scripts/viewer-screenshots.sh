#!/usr/bin/env bash
# Regenerates the README's viewer screenshots (docs/images/viewer-*.png) under Xvfb: the whole
# window (frame and panel) after a scripted session each.
# Usage: scripts/viewer-screenshots.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
command -v xvfb-run >/dev/null || { echo "needs xvfb-run (apt-get install xvfb xauth)"; exit 1; }
[ -x "$build/penumbra-view" ] || { echo "no $build/penumbra-view: build the viewer first"; exit 1; }
export SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software
scripts=$(mktemp -d)
trap 'rm -rf "$scripts"' EXIT

shot() {  # NAME SCENE SCRIPT_TEXT [viewer args...]
  local name=$1 scene=$2 text=$3
  shift 3
  printf '%s\n' "$text" > "$scripts/$name.txt"
  xvfb-run -a -s "-screen 0 1400x800x24" "$build/penumbra-view" "$scene" "$@" \
    --script "$scripts/$name.txt" --quit-after 20 \
    --window-screenshot "docs/images/viewer-$name.png" > /dev/null
  echo "docs/images/viewer-$name.png"
}

# The light dragged to the left and up (ctrl + drag, ctrl + shift + drag), penumbra wedges.
shot light-dragged spheres "wait 2
drag left 320 200 220 190 8 ctrl
wait 2
drag left 320 200 320 170 4 ctrl shift
wait 4" --technique wedge-3pass

# Compare mode: the wedges' visibility against the oracle as an error heat map, with the MAE
# and the share of pixels off, after 4 oracle passes (256 rays a pixel).
shot compare columns "compare heatmap
wait 2
wait-oracle 4
wait 2" --technique wedge-3pass

# Overlays, the technique's debug layers (DebugLayer, include/penumbra/shadows/technique.h):
# the wedges' footprints after tile culling, the silhouette edges they are built on, the
# culled tiles of both passes.
shot overlays spheres "overlay wedge-footprints
wait 4" --technique wedge-3pass
shot silhouettes columns "overlay silhouette-edges
wait 4" --technique wedge-3pass
shot culled-tiles columns "overlay culled-tiles
wait 4" --technique wedge-3pass
# The penumbra pixels of exact soft shadow volumes tinted over the frame.
shot penumbra spheres "overlay penumbra
wait 4" --technique exact
