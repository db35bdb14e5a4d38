#!/usr/bin/env bash
# Builds everything and runs the whole test suite:
#   1. unit tests of the core, the malformed-mesh corpus, the command-line tool and integration
#      tests that drive Debian's real MeshLab 2020.09 (meshlabserver and the GUI)     (CTest)
#      The command-line tool and the test programs that do not load MeshLab are built with
#      AddressSanitizer + UBSan (NVV_SANITIZE_TESTS=address): they run sanitized here.
#   2. the parallel core and the corpus again under ThreadSanitizer (clang)          (CTest)
#   3. the MeshLab 2025.07 / PyMeshLab 2025.7 builds (float and double) and their scripted-use,
#      chain and GUI tests, inside a Debian sid chroot made under build-2025/      (GoogleTest)
# Installs what it needs first. Ends with one line "tests: N passed, M failed" over all parts;
# stops at the first failing part with its output.
# Usage: sudo bash scripts/run-tests.sh
#   BUILD_DIR=build-tests   main build folder
#   NVV_SANITIZERS=0        no AddressSanitizer in part 1, skip part 2
#   NVV_MESHLAB2025=0       skip part 3
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
build=${BUILD_DIR:-build-tests}
logs="$here/$build/test-logs"
start=$(date +%s)
part() { echo "== run-tests: $* ($(( $(date +%s) - start )) s)"; }

bash scripts/install-deps.sh
mkdir -p "$logs"
rm -f "$logs"/*.log

# The sid chroot is mostly downloading and unpacking: make it while the main build compiles.
chroot_pid=""
if [ "${NVV_MESHLAB2025:-1}" != 0 ]; then
  bash scripts/meshlab2025/make-chroot.sh > "$logs/make-chroot.txt" 2>&1 &
  chroot_pid=$!
fi

part "main build"
asan=address
[ "${NVV_SANITIZERS:-1}" != 0 ] || asan=""
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNVV_SANITIZE_TESTS="$asan"
ninja -C "$build" -j "$(nproc)"
part "main tests"
source scripts/sanitizer-env.sh
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" 2>&1 | tee "$logs/main.ctest.log"

if [ "${NVV_SANITIZERS:-1}" != 0 ]; then
  part "thread sanitizer"
  bash scripts/run-sanitizer-tests.sh thread 2>&1 | tee "$logs/thread.ctest.log"
fi

if [ "${NVV_MESHLAB2025:-1}" != 0 ]; then
  part "MeshLab 2025.07"
  wait "$chroot_pid" || { cat "$logs/make-chroot.txt"; echo "run-tests: making the sid chroot failed" >&2; exit 1; }
  cat "$logs/make-chroot.txt"
  NVV_CLI="$here/$build/filter_normal_voting/cli/nvv" bash scripts/meshlab2025/run-tests-2025.sh 2>&1 |
    tee "$logs/meshlab2025.gtest.log"
fi

# One tally over every part: CTest's "N tests failed out of M" and GoogleTest's summaries.
passed=0 failed=0
for f in "$logs"/*.ctest.log; do
  read -r bad total < <(sed -n 's/.*tests passed, \([0-9]*\) tests failed out of \([0-9]*\).*/\1 \2/p' "$f" |
                        awk '{b += $1; t += $2} END {print b + 0, t + 0}')
  passed=$((passed + total - bad)); failed=$((failed + bad))
done
for f in "$logs"/*.gtest.log; do
  [ -f "$f" ] || continue
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$f" | awk '{s += $1} END {print s + 0}')
  b=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$f" | awk '{s += $1} END {print s + 0}')
  passed=$((passed + p)); failed=$((failed + b))
done
part "done"
echo "tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
