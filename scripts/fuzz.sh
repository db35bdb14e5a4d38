#!/usr/bin/env bash
# Fuzzes the core (mesh + parameters) with libFuzzer + AddressSanitizer + UBSan.
# Usage: scripts/fuzz.sh [SECONDS=300]   Crashes land in fuzz/findings/; add each one to
# tests/robustness as a regression case once fixed. The corpus grows in build-fuzz/corpus/.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
seconds=${1:-300}
CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNVV_BUILD_FUZZ=ON \
  -DNVV_BUILD_TESTS=OFF -DNVV_BUILD_PLUGIN=OFF -DNVV_BUILD_CLI=OFF >/dev/null
ninja -C build-fuzz nvv_fuzz_core
mkdir -p build-fuzz/corpus fuzz/findings
ASAN_OPTIONS=detect_leaks=1 ./build-fuzz/fuzz/nvv_fuzz_core -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
  -artifact_prefix=fuzz/findings/ -print_final_stats=1 build-fuzz/corpus
