#!/usr/bin/env bash
#SBATCH --job-name=penumbra-path
#SBATCH --cpus-per-task=2
#SBATCH --output=penumbra-path-%A_%a.log
# One frame of a scene's camera and light path per task of a Slurm job array: the task's
# SLURM_ARRAY_TASK_ID is the frame. Slurm schedules the frames over the cluster; the files are
# those `penumbra render SCENE --path -o OUTPUT` writes (out/city.png: out/city.0007.png for
# frame 7). Submit from the repository root (the output folder must be on a shared filesystem):
#
#   frames=$(build/penumbra render city --list-frames | wc -l)
#   sbatch --array=0-$((frames - 1)) scripts/render-path-slurm.sh city out/city.png
#   sbatch --array=0-119%16 scripts/render-path-slurm.sh city out/city.png -- --technique volume
#
# (%16: at most 16 frames at once.) Each task uses its SLURM_CPUS_PER_TASK cores. PENUMBRA names
# the CLI (default: build/penumbra). Anything after `--` goes to penumbra render.
set -euo pipefail

if [[ $# -lt 2 ]]; then
  sed -n '5,15p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
: "${SLURM_ARRAY_TASK_ID:?is not set: submit this script with sbatch --array=0-(frames-1), see its first lines}"
scene=$1
output=$2
shift 2
[[ $# -gt 0 && $1 == -- ]] && shift
exec "${PENUMBRA:-build/penumbra}" render "$scene" --frame "$SLURM_ARRAY_TASK_ID" -o "$output" \
  --threads "${SLURM_CPUS_PER_TASK:-0}" --quiet "$@"
