#!/usr/bin/env bash
# Builds and runs the tests under a sanitizer, in its own build folder.
#   address: AddressSanitizer + UndefinedBehaviorSanitizer over the core, robustness-corpus, result-PLY
#            and command-line suites (GCC); run-tests.sh gets the same within its normal build;
#   thread:  ThreadSanitizer over the parallel core (clang with LLVM's OpenMP runtime and its Archer
#            tool, so that OpenMP's own synchronisation is understood).
# Any report fails the run. Usage: scripts/run-sanitizer-tests.sh address|thread
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
mode=${1:?usage: run-sanitizer-tests.sh address|thread}
build="build-$mode-sanitizer"
jobs=$(nproc)
case "$mode" in
  address)
    # The same mechanism as the normal test build of run-tests.sh (NVV_SANITIZE_TESTS), alone.
    cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNVV_SANITIZE_TESTS=address \
      -DNVV_BUILD_PLUGIN=OFF >/dev/null
    ninja -C "$build" -j "$jobs" nvv_core_tests nvv_robustness_tests nvv_result_ply_tests nvv_cli_tests nvv_cli nvv_io_tests
    source scripts/sanitizer-env.sh
    ctest --test-dir "$build" --output-on-failure -j "$jobs" -R "^(GeodesicMarch|Pass|Invariance|Determinism|Cancellation|Degenerate|FilterOptions|ApplyResults|MalformedCorpus|AbsurdParameters|ResultPly|Cli|PlyReader|ObjReader|OffReader|StlReader|MeshFiles)"
    ;;
  thread)
    archer=$(ls /usr/lib/llvm-14/lib/libarcher.so 2>/dev/null || true)
    [ -n "$archer" ] || { echo "run-sanitizer-tests: libarcher.so not found (package libomp-14-dev)"; exit 1; }
    CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
      -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" -DNVV_SANITIZE=thread -DNVV_BUILD_PLUGIN=OFF \
      -DNVV_BUILD_CLI=OFF >/dev/null
    ninja -C "$build" -j "$jobs" nvv_parallel_tests nvv_robustness_tests
    export OMP_TOOL_LIBRARIES="$archer"
    # libomp itself is not instrumented: its own locking is known to Archer, not to TSan.
    export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ignore_noninstrumented_modules=1"
    export OMP_NUM_THREADS=4  # more threads than cores: more interleavings
    export NVV_CORPUS_STRIDE=8  # an eighth of the malformed corpus, spread over all its kinds
    export NVV_CORPUS_SECONDS=300
    ctest --test-dir "$build" --output-on-failure -j 1 -R "^(Determinism|Cancellation|Invariance|Pass2|MalformedCorpus.EveryCase)"
    ;;
  *) echo "run-sanitizer-tests: unknown mode $mode"; exit 2 ;;
esac
