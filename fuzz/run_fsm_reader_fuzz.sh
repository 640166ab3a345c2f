#!/bin/sh
# Builds the .fsm reader fuzz target with clang++ -fsanitize=fuzzer,address and runs it for a
# short budget on a copy of the seed corpus (the repository is never written to).
# usage: run_fsm_reader_fuzz.sh SOURCE_DIR BUILD_DIR [SECONDS]
# Exit 77 (ctest: skipped) only when clang++ is not installed.
set -eu
src=$1
out=$2/fuzz
seconds=${3:-20}
if ! command -v clang++ >/dev/null 2>&1; then
  echo "SKIPPED: clang++ not found; the libFuzzer target needs clang (apt-get install clang)"
  exit 77
fi
mkdir -p "$out"
clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
  -I "$src" -I "$src/impl/include" \
  "$src/fuzz/fsm_reader_fuzz.cpp" \
  "$src/impl/supervisor/fsm_read.cpp" \
  "$src/impl/supervisor/fsm_write.cpp" \
  "$src/spec/supervisor/automaton.cpp" \
  -o "$out/fsm_reader_fuzz"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src"/fuzz/corpus/* "$work"/
# Inputs up to 4 KiB keep each run fast; artifacts (crash inputs) go to the build folder.
"$out/fsm_reader_fuzz" -max_total_time="$seconds" -max_len=4096 -timeout=5 \
  -artifact_prefix="$out/" -print_final_stats=1 "$work"
