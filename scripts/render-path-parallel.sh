#!/usr/bin/env bash
# Renders every frame of a scene's camera and light path with GNU parallel on this machine: one
# `penumbra render SCENE --frame K` per frame, the frames spread over the cores. Writes the same
# numbered files as `penumbra render SCENE --path -o OUTPUT` (out/city.png: out/city.0000.png,
# out/city.0001.png, ...). No scheduler of our own: parallel runs the job list that
# `penumbra render SCENE --list-frames` prints.
#
#   scripts/render-path-parallel.sh SCENE OUTPUT.png [JOBS] [-- MORE penumbra render OPTIONS]
#   scripts/render-path-parallel.sh city out/city/frame.png 2 -- --technique volume --width 960
#
# JOBS (default: the number of cores) frames render at once, each with one worker thread.
# PENUMBRA names the CLI (default: build/penumbra). A failed frame stops the run with its error.
set -euo pipefail

if [[ $# -lt 2 ]]; then
  sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
scene=$1
output=$2
shift 2
jobs=$(nproc)
if [[ $# -gt 0 && $1 != -- ]]; then
  jobs=$1
  shift
fi
[[ $# -gt 0 && $1 == -- ]] && shift
penumbra=${PENUMBRA:-build/penumbra}
command -v parallel >/dev/null || { echo "$0: GNU parallel is not installed (scripts/setup-debian.sh installs it)" >&2; exit 1; }
[[ -x $penumbra ]] || { echo "$0: $penumbra is not an executable (build it, or set PENUMBRA)" >&2; exit 1; }

frames=$("$penumbra" render "$scene" --list-frames)
# -q: the command's words are passed as they are (a scene path with spaces stays one argument).
printf '%s\n' "$frames" |
  parallel --halt now,fail=1 -j "$jobs" -q \
    "$penumbra" render "$scene" --frame '{}' -o "$output" --threads 1 --quiet "$@"
echo "rendered $(printf '%s\n' "$frames" | wc -l) frames of $scene to ${output%.*}.NNNN.${output##*.}"
