#!/usr/bin/env bash
# Fuzzes with libFuzzer + AddressSanitizer + UBSan: the core (mesh + parameters), each mesh
# reader (PLY, OBJ, OFF, STL) and the whole command-line path (options + file bytes through
# `nvv`), one after the other, each for SECONDS.
# Usage: scripts/fuzz.sh [SECONDS=300] [TARGET...]   TARGET: core ply obj off stl cli (default: all)
# Crashes land in fuzz/findings/ (named after the target); add each one as a regression case
# once fixed (tests/robustness for the core, tests/io for the readers). The corpora grow in
# build-fuzz/corpus/ (core) and build-fuzz/corpus-<format>/, the readers starting from the
# committed seeds in fuzz/seeds/<format>/; the command-line path's in build-fuzz/corpus-cli/, from
# fuzz/seeds/cli/ (format byte, option line, file bytes: fuzz/fuzz_cli.cpp) with fuzz/cli.dict.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
seconds=${1:-300}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(core ply obj off stl cli)
for t in "${targets[@]}"; do
  case "$t" in core|ply|obj|off|stl|cli) ;; *) echo "unknown fuzz target '$t' (core ply obj off stl cli)" >&2; exit 2 ;; esac
done
CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNVV_BUILD_FUZZ=ON \
  -DNVV_BUILD_TESTS=OFF -DNVV_BUILD_PLUGIN=OFF -DNVV_BUILD_CLI=OFF >/dev/null
ninja -C build-fuzz "${targets[@]/#/nvv_fuzz_}"
mkdir -p fuzz/findings
for t in "${targets[@]}"; do
  echo "== fuzzing $t for $seconds s"
  if [ "$t" = core ]; then
    mkdir -p build-fuzz/corpus
    ASAN_OPTIONS=detect_leaks=1 ./build-fuzz/fuzz/nvv_fuzz_core -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
      -artifact_prefix=fuzz/findings/ -print_final_stats=1 build-fuzz/corpus
  elif [ "$t" = cli ]; then
    mkdir -p build-fuzz/corpus-cli
    ASAN_OPTIONS=detect_leaks=1 ./build-fuzz/fuzz/nvv_fuzz_cli -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
      -max_len=65536 -close_fd_mask=3 -dict=fuzz/cli.dict -artifact_prefix=fuzz/findings/cli- -print_final_stats=1 \
      build-fuzz/corpus-cli fuzz/seeds/cli
  else
    mkdir -p "build-fuzz/corpus-$t"
    ASAN_OPTIONS=detect_leaks=1 "./build-fuzz/fuzz/nvv_fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len=65536 -artifact_prefix="fuzz/findings/$t-" -print_final_stats=1 "build-fuzz/corpus-$t" "fuzz/seeds/$t"
  fi
done
