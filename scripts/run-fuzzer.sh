#!/bin/bash
# Build the fuzz targets with clang (tests/fuzz) and run one on its seed corpus
# for a bounded time: scripts/run-fuzzer.sh TARGET SECONDS [BUILD_DIR].
# Exit 0 if the fuzzer found nothing; a finding leaves its input in
# BUILD_DIR/findings/ and the sanitizer report on the screen.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
target=$1
seconds=$2
build=${3:-$root/build/fuzz}
cmake -S "$root/tests/fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug > "$build.log" 2>&1 \
  || { cat "$build.log"; exit 1; }
cmake --build "$build" --target "fuzz_$target" -j"$(nproc)" > "$build.log" 2>&1 || { cat "$build.log"; exit 1; }
# The corpus grows in a scratch copy; the committed seeds stay as they are.
corpus="$build/corpus/$target"
mkdir -p "$corpus" "$build/findings"
cp "$root/tests/fuzz/seeds/$target"/* "$corpus"/
"$build/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix="$build/findings/" -print_final_stats=1 "$corpus" 2>&1 | tail -12
