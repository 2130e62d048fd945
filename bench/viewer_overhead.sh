#!/usr/bin/env bash
# The viewer loop's overhead (issue 30): frames per second of penumbra-view's loop (full-size
# frames back to back through the window: events, texture upload, panel) against `penumbra
# render --frames` on the same scene, technique and size, in the same run, rounds alternated.
# A benchmark, not a test. Needs xvfb-run (the window is real, on a virtual screen).
#
# Usage: bench/viewer_overhead.sh [BUILD_DIR] [FRAMES] [ROUNDS]
# Prints one line per scene x technique: the medians over rounds of each round's median frame
# time, and viewer / CLI (above 1: the viewer is slower); each round's pair goes to stderr.
set -euo pipefail
build=${1:-build}
frames=${2:-20}
rounds=${3:-3}
scenes=(spheres columns)
techniques=(volume wedge-3pass coverage exact)
command -v xvfb-run >/dev/null || { echo "needs xvfb-run (apt-get install xvfb xauth)"; exit 1; }
export SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software

median() { sort -g | awk '{v[NR]=$1} END {print (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2)}'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "frames per run: $frames (after 3 warm-up frames), rounds: $rounds, 640x427"
printf '%-8s %-12s %12s %12s %8s\n' scene technique "viewer ms" "cli ms" ratio
for scene in "${scenes[@]}"; do
  for technique in "${techniques[@]}"; do
    viewer_ms=() cli_ms=()
    for ((r = 0; r < rounds; r++)); do
      cli=$("$build/penumbra" render "$scene" --technique "$technique" --width 640 --height 427 \
              --frames "$frames" -o /tmp/viewer-overhead-cli.png)
      cli_ms+=("$(sed -n 's/.*warm frames.*median \([0-9.]*\),.*/\1/p' <<<"$cli" | head -1)")
      viewer=$(xvfb-run -a -s "-screen 0 1280x800x24" "$build/penumbra-view" "$scene" \
                 --technique "$technique" --width 640 --height 427 --bench "$frames")
      viewer_ms+=("$(sed -n 's/.*median frame interval \([0-9.]*\) ms.*/\1/p' <<<"$viewer")")
      # Each round's pair, to stderr: on a shared machine the spread says how far to trust
      # the medians.
      echo "  round $r $scene $technique: viewer ${viewer_ms[-1]} ms, cli ${cli_ms[-1]} ms" >&2
    done
    v=$(printf '%s\n' "${viewer_ms[@]}" | median)
    c=$(printf '%s\n' "${cli_ms[@]}" | median)
    printf '%-8s %-12s %12.3f %12.3f %8.3f\n' "$scene" "$technique" "$v" "$c" \
      "$(awk -v v="$v" -v c="$c" 'BEGIN {print v / c}')"
  done
done
