#!/usr/bin/env bash
# Viewer.ScriptedDragMatchesCli: the viewer opens `spheres` under Xvfb with SDL's software
# renderer, a script (drag_light_switch_technique.txt) orbits, drags the light and switches
# technique, and on quitting the viewer writes its frame and its camera and lights as a scene
# file. `penumbra render` of that file with the command line the viewer printed must write the
# same PNG, byte for byte; and the frame must differ from the scene's untouched one (else the
# drag did nothing and the equality proves little).
# Usage: scripted_drag_matches_cli.sh VIEWER CLI TESTS_DIR WORK_DIR. Exit 77: skipped.
set -euo pipefail
viewer=$1 cli=$2 tests=$3 work=$4
if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "skipped: xvfb-run is missing (apt-get install xvfb xauth, or scripts/setup-debian.sh)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
export SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software
xvfb-run -a -s "-screen 0 1024x768x24" \
  "$viewer" spheres --technique volume --width 160 --height 107 \
  --script "$tests/drag_light_switch_technique.txt" --quit-after 30 \
  --screenshot "$work/viewer.png" --save-scene "$work/saved.json" | tee "$work/viewer.log"

# The command the viewer printed, with the CLI's path in place of `penumbra`.
command_line=$(sed -n 's/.*; the same frame: penumbra render //p' "$work/viewer.log")
[ -n "$command_line" ] || { echo "FAIL: the viewer printed no render command"; exit 1; }
echo "render: $command_line"
# shellcheck disable=SC2086  # the printed flags are single words
"$cli" render $command_line -o "$work/cli.png" --quiet
grep -q -- "--technique wedge-3pass --cull zmax" <<<"$command_line" ||
  { echo "FAIL: the printed command does not select the scripted technique: $command_line"; exit 1; }
cmp "$work/viewer.png" "$work/cli.png" ||
  { echo "FAIL: the viewer's frame differs from penumbra render of the saved scene"; exit 1; }

"$cli" render spheres --technique wedge-3pass --cull zmax --width 160 --height 107 \
  -o "$work/untouched.png" --quiet
if cmp -s "$work/viewer.png" "$work/untouched.png"; then
  echo "FAIL: the scripted drags changed nothing in the frame"
  exit 1
fi
echo "PASS: the viewer's frame equals penumbra render of its saved scene"
