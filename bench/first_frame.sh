#!/usr/bin/env bash
# A technique's first frame against its warm frames, for one or two penumbra CLIs in the same
# run: per round and binary (alternating which goes first), `render SCENE --frames 1 --warmup 0`
# (the first frame a user waits for after preparing, with the preparation timed apart in a
# third run without --frames: its stats' `prepare` pass) and `render SCENE --frames 5
# --warmup 2` (the median warm frame); then per binary the medians over the rounds of the first
# frame, the warm frame, their ratio and the preparation. On a shared machine read the ratios,
# measured a minute apart, not the absolute times.
#   bench/first_frame.sh [--technique NAME] [--rounds R] SCENE BINARY [BINARY]
# Example: bench/first_frame.sh --rounds 3 dragon_vrip.ply old/penumbra build/penumbra
set -euo pipefail
technique=exact
rounds=3
while [[ $# -gt 0 ]]; do
  case "$1" in
    --technique) technique="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) break ;;
  esac
done
if [[ $# -lt 2 || $# -gt 3 ]]; then
  echo "usage: $0 [--technique NAME] [--rounds R] SCENE BINARY [BINARY]" >&2
  exit 2
fi
scene=$1; shift
binaries=("$@")
for bin in "${binaries[@]}"; do
  [[ -x "$bin" ]] || { echo "first_frame: '$bin' is not an executable" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median_of() { sed -n 's/.*warm frames\{0,1\} ([0-9]* warm-up): min [0-9.]*, median \([0-9.]*\),.*/\1/p' "$1"; }
for r in $(seq 1 "$rounds"); do
  order=("${!binaries[@]}")
  if [[ ${#binaries[@]} -eq 2 && $((r % 2)) -eq 0 ]]; then order=(1 0); fi
  for i in "${order[@]}"; do
    bin=${binaries[$i]}
    "$bin" render "$scene" --technique "$technique" --frames 1 --warmup 0 -o "$work/f.png" \
      > "$work/first-$i-$r.txt"
    "$bin" render "$scene" --technique "$technique" --frames 5 --warmup 2 -o "$work/w.png" \
      > "$work/warm-$i-$r.txt"
    "$bin" render "$scene" --technique "$technique" -q --stats "$work/prepare-$i-$r.json" \
      -o "$work/p.png"
    first=$(median_of "$work/first-$i-$r.txt")
    warm=$(median_of "$work/warm-$i-$r.txt")
    prepare=$(/usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); \
print(next(t['ms'] for t in d['total']['time_ms'] if t['pass'] == 'prepare'))" \
      "$work/prepare-$i-$r.json")
    echo "$i $r $first $warm $prepare" >> "$work/rows"
    printf 'round %d %-28s first %8.1f ms  warm %8.1f ms  first/warm %5.2f  prepare %7.1f ms\n' \
      "$r" "$bin" "$first" "$warm" "$(awk -v a="$first" -v b="$warm" 'BEGIN {print a / b}')" \
      "$prepare"
  done
done
/usr/bin/python3 - "$work/rows" "${binaries[@]}" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])]
for i, name in enumerate(sys.argv[2:]):
    mine = [r for r in rows if int(r[0]) == i]
    first = statistics.median(float(r[2]) for r in mine)
    warm = statistics.median(float(r[3]) for r in mine)
    ratio = statistics.median(float(r[2]) / float(r[3]) for r in mine)
    prepare = statistics.median(float(r[4]) for r in mine)
    print(f"{name}: medians over {len(mine)} rounds: first {first:.1f} ms, warm {warm:.1f} ms, "
          f"first/warm {ratio:.2f} (per round), prepare {prepare:.1f} ms")
PY
