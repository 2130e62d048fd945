#!/usr/bin/env bash
# The viewer loop's overhead (issue 30): frames per second of penumbra-view's loop (full-size
# frames back to back while the window loop runs as it does for a user: events, the pacer, the
# frame texture, the panel) against `penumbra render --frames` on the same scene, technique and
# size, in the same run, rounds alternated. A benchmark, not a test. Needs Xvfb (the window is
# real, on a virtual screen).
#
# Usage: bench/viewer_overhead.sh [BUILD_DIR] [FRAMES] [ROUNDS]
# FRAMES is the CLI's frame count and the viewer's least (it runs at least 3 s).
# SCENES / TECHNIQUES (space-separated) run a subset.
# Prints one line per scene x technique: the medians over rounds of each run's median frame
# time, viewer / CLI (above 1: the viewer is slower), and the display's CPU share: the CPU time
# of the window's thread plus the X server's, over the CPU time of the rendering threads, in the
# same run. Wall-clock ratios on a loaded machine carry its noise; the CPU share does not grow
# with the load. Each round's figures go to stderr.
set -euo pipefail
build=${1:-build}
frames=${2:-20}
rounds=${3:-3}
read -r -a scenes <<<"${SCENES:-spheres columns}"
read -r -a techniques <<<"${TECHNIQUES:-volume wedge-3pass coverage exact}"
command -v Xvfb >/dev/null || { echo "needs Xvfb (apt-get install xvfb)"; exit 1; }
export SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software

median() { sort -g | awk '{v[NR]=$1} END {print (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2)}'; }

# A display of our own, so that the X server's CPU time can be read (/proc/PID/stat).
xvfb_pid=
for d in $(seq 91 140); do
  [ -e "/tmp/.X$d-lock" ] && continue
  Xvfb ":$d" -screen 0 1280x800x24 -nolisten tcp >/dev/null 2>&1 &
  xvfb_pid=$!
  sleep 1
  if kill -0 "$xvfb_pid" 2>/dev/null; then export DISPLAY=":$d"; break; fi
  xvfb_pid=
done
[ -n "$xvfb_pid" ] || { echo "could not start Xvfb"; exit 1; }
trap 'kill "$xvfb_pid"' EXIT
tick_ms=$(awk -v hz="$(getconf CLK_TCK)" 'BEGIN {print 1000 / hz}')
xvfb_cpu_ms() { awk -v t="$tick_ms" '{print ($14 + $15) * t}' "/proc/$xvfb_pid/stat"; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "frames per run: $frames (after 3 warm-up frames), rounds: $rounds, 640x427"
printf '%-8s %-12s %10s %10s %8s %14s\n' scene technique "viewer ms" "cli ms" ratio "display CPU %"
for scene in "${scenes[@]}"; do
  for technique in "${techniques[@]}"; do
    viewer_ms=() cli_ms=() shares=()
    for ((r = 0; r < rounds; r++)); do
      cli=$("$build/penumbra" render "$scene" --technique "$technique" --width 640 --height 427 \
              --frames "$frames" -o /tmp/viewer-overhead-cli.png)
      cli_ms+=("$(sed -n 's/.*warm frames.*median \([0-9.]*\),.*/\1/p' <<<"$cli" | head -1)")
      # The viewer runs for at least 3 s (so that the X server's work for a new window, which its
      # CPU time below includes, is spread over many draws).
      viewer_frames=$(awk -v f="$frames" -v c="${cli_ms[-1]}" 'BEGIN {n = int(3000 / c); print (n > f ? n : f)}')
      x0=$(xvfb_cpu_ms)
      viewer=$("$build/penumbra-view" "$scene" --technique "$technique" --width 640 \
                 --height 427 --bench "$viewer_frames")
      x1=$(xvfb_cpu_ms)
      viewer_ms+=("$(sed -n 's/.*median frame interval \([0-9.]*\) ms.*/\1/p' <<<"$viewer")")
      window=$(sed -n 's/.*window thread \([0-9.]*\) ms.*/\1/p' <<<"$viewer")
      rendering=$(sed -n 's/.*rendering \([0-9.]*\) ms.*/\1/p' <<<"$viewer")
      draws=$(sed -n 's/.*the window drawn \([0-9]*\) times.*/\1/p' <<<"$viewer")
      shares+=("$(awk -v w="$window" -v x="$(awk -v a="$x0" -v b="$x1" 'BEGIN {print b - a}')" \
                    -v r="$rendering" 'BEGIN {print 100 * (w + x) / r}')")
      # Each round's figures, to stderr: on a shared machine the spread says how far to trust
      # the medians.
      echo "  round $r $scene $technique: viewer ${viewer_ms[-1]} ms, cli ${cli_ms[-1]} ms;" \
           "$draws draws; CPU window $window ms + X server $(awk -v a="$x0" -v b="$x1" \
           'BEGIN {print b - a}') ms against rendering $rendering ms" >&2
    done
    v=$(printf '%s\n' "${viewer_ms[@]}" | median)
    c=$(printf '%s\n' "${cli_ms[@]}" | median)
    s=$(printf '%s\n' "${shares[@]}" | median)
    printf '%-8s %-12s %10.3f %10.3f %8.3f %14.2f\n' "$scene" "$technique" "$v" "$c" \
      "$(awk -v v="$v" -v c="$c" 'BEGIN {print v / c}')" "$s"
  done
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
