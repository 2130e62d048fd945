#!/usr/bin/env bash
# Builds one libFuzzer target under ASan + UBSan with clang and runs it for a given time:
#   scripts/fuzz.sh obj|ply|gltf|scene SECONDS
# Seeds come from fuzz/corpus/<target>/ (read only); new inputs go to build-fuzz/corpus/<target>/
# and crashing or hanging inputs to build-fuzz/findings/<target>/ (reproduce one with
# build-fuzz/penumbra_fuzz_<target> FILE). One job, one core: the machines are shared.
# PENUMBRA_FUZZ_SEED fixes libFuzzer's random seed (0, the default, lets it pick one): CI fixes
# it so that a run is repeatable; campaigns by hand leave it to vary.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ne 2 ] || [[ ! "$1" =~ ^(obj|ply|gltf|scene)$ ]] || [[ ! "$2" =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh obj|ply|gltf|scene SECONDS" >&2
  exit 2
fi
target=$1
seconds=$2
build=build-fuzz
cxx=$(command -v clang++ || command -v clang++-14 || true)
if [ -z "$cxx" ]; then
  echo "fuzz: clang++ not found (scripts/setup-debian.sh installs clang-14 and libclang-rt-14-dev)" >&2
  exit 1
fi
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" -DPENUMBRA_SANITIZE=ON -DPENUMBRA_BUILD_FUZZ=ON \
  -DPENUMBRA_BUILD_TESTS=OFF -DPENUMBRA_BUILD_BENCH=OFF -DPENUMBRA_BUILD_LLVMPIPE_PEER=OFF > /dev/null
cmake --build "$build" -j2 --target "penumbra_fuzz_$target"
mkdir -p "$build/corpus/$target" "$build/findings/$target"
# -timeout: an input taking longer is a hang; -rss_limit_mb: more memory is runaway allocation.
ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$build/penumbra_fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len=16384 -seed="${PENUMBRA_FUZZ_SEED:-0}" -print_final_stats=1 -artifact_prefix="$build/findings/$target/" \
  "$build/corpus/$target" "fuzz/corpus/$target"
