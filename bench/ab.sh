#!/usr/bin/env bash
# A/B of two penumbra_bench binaries in one run: ROUNDS rounds (default 5), each runs both,
# alternating which goes first, so a neighbour's load falls on both alike; then the median
# frame (or technique) time of every benchmark and the ratio new / old.
#   bench/ab.sh OLD_BINARY NEW_BINARY 'BENCHMARK_FILTER'
# Environment: ROUNDS, OUT (folder for the per-run JSON files; default a temporary folder).
set -euo pipefail
if [ $# -ne 3 ]; then
  echo "usage: $0 OLD_BINARY NEW_BINARY 'BENCHMARK_FILTER'" >&2
  exit 2
fi
old=$1 new=$2 filter=$3
rounds=${ROUNDS:-5}
out=${OUT:-$(mktemp -d)}
mkdir -p "$out"
for r in $(seq 1 "$rounds"); do
  if [ $((r % 2)) -eq 1 ]; then order="old new"; else order="new old"; fi
  for which in $order; do
    bin=$old
    [ "$which" = new ] && bin=$new
    "$bin" --benchmark_filter="$filter" --benchmark_out="$out/$which-$r.json" \
      --benchmark_out_format=json > /dev/null
  done
done
/usr/bin/python3 - "$out" "$rounds" <<'PY'
import json, statistics, sys
out, rounds = sys.argv[1], int(sys.argv[2])
times = {}
for which in ("old", "new"):
    for r in range(1, rounds + 1):
        for b in json.load(open(f"{out}/{which}-{r}.json"))["benchmarks"]:
            ms = b.get("frame_ms", b.get("technique_ms", b.get("real_time")))
            times.setdefault(b["name"].split("/min_time")[0], {}).setdefault(which, []).append(ms)
print(f"{'benchmark':58s} {'old ms':>9s} {'new ms':>9s} {'new/old':>8s}")
for name, t in times.items():
    o, n = statistics.median(t["old"]), statistics.median(t["new"])
    print(f"{name:58s} {o:9.2f} {n:9.2f} {n / o:8.3f}")
print(f"({rounds} rounds, JSON in {out})")
PY
