#!/usr/bin/env bash
# Builds everything and runs the whole test suite:
#   1. every CTest label of the main build: unit (core, options, docs), corpus (malformed meshes),
#      cli (the tool as a child process), meshlab (Debian's meshlabserver 2020.09) and gui (its
#      window under Xvfb). The command-line tool and the test programs that do not load MeshLab
#      are built with AddressSanitizer + UBSan (NVV_SANITIZE_TESTS=address): they run sanitized.
#   2. the parallel core and the corpus again under ThreadSanitizer (clang)
#   3. meshlab2025: the MeshLab 2025.07 / PyMeshLab 2025.7 builds (float and double) and their
#      scripted-use, chain and GUI tests, inside a Debian sid chroot made under build-2025/
#   4. pymeshlab: the plugin built for the real PyMeshLab 2025.7.post1 from pip, packed as the
#      wheel pymeshlab_normal_voting, and the pytest suite (tests/python/) in a fresh virtual
#      environment, with the README's Python example run as printed
# Installs what it needs first. Ends with one line "tests: N passed, M failed, K skipped" over all
# parts; stops at the first failing part with its output.
#
# Usage: bash scripts/run-tests.sh            the full suite (CI runs this); as root, or a user with sudo
#        bash scripts/run-tests.sh --quick    the development loop: unit and cli labels, no
#                                             sanitizers, no MeshLab (a few minutes after the first build)
#   BUILD_DIR=build-tests   main build folder (--quick: build-quick)
#   NVV_SANITIZERS=0        no AddressSanitizer in part 1, skip part 2
#   NVV_MESHLAB2025=0       skip part 3
#   NVV_PYMESHLAB=0         skip part 4
#   NVV_FUZZ_SECONDS=30     seconds of fuzzing per target after part 1 (0: none)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
quick=0
[ "${1:-}" = "--quick" ] && quick=1
build=${BUILD_DIR:-build-tests}
[ "$quick" = 1 ] && build=${BUILD_DIR:-build-quick}
logs="$here/$build/test-logs"
start=$(date +%s)
part() { echo "== run-tests: $* ($(( $(date +%s) - start )) s)"; }

bash scripts/install-deps.sh
mkdir -p "$logs"
rm -f "$logs"/*.log

# One tally over every part: CTest's "N tests failed out of M" less the tests it lists as
# skipped (GTEST_SKIP), GoogleTest's own summaries, and the pytest part's "pytest: ..." line.
tally() {
  local passed=0 failed=0 skipped=0 f bad total skip p b s
  for f in "$logs"/*.ctest.log; do
    [ -f "$f" ] || continue
    read -r bad total < <(sed -n 's/.*tests passed, \([0-9]*\) tests failed out of \([0-9]*\).*/\1 \2/p' "$f" |
                          awk '{b += $1; t += $2} END {print b + 0, t + 0}')
    skip=$(grep -c '(Skipped)$' "$f" || true)
    passed=$((passed + total - bad - skip)); failed=$((failed + bad)); skipped=$((skipped + skip))
  done
  for f in "$logs"/*.gtest.log; do
    [ -f "$f" ] || continue
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$f" | awk '{s += $1} END {print s + 0}')
    b=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$f" | awk '{s += $1} END {print s + 0}')
    s=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' "$f" | awk '{s += $1} END {print s + 0}')
    passed=$((passed + p)); failed=$((failed + b)); skipped=$((skipped + s))
  done
  for f in "$logs"/*.pytest.log; do
    [ -f "$f" ] || continue
    read -r p b s < <(sed -n 's/^pytest: \([0-9]*\) passed, \([0-9]*\) failed, \([0-9]*\) skipped$/\1 \2 \3/p' "$f" | tail -1)
    passed=$((passed + ${p:-0})); failed=$((failed + ${b:-0})); skipped=$((skipped + ${s:-0}))
  done
  part "done"
  grep -h '(Skipped)$' "$logs"/*.ctest.log 2>/dev/null | sed 's/^ */skipped: /' || true
  echo "tests: $passed passed, $failed failed, $skipped skipped"
  [ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
}

if [ "$quick" = 1 ]; then
  part "quick build"
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNVV_BUILD_PLUGIN=OFF >/dev/null
  ninja -C "$build" -j "$(nproc)"
  part "unit and cli tests"
  ctest --test-dir "$build" --output-on-failure -j "$(nproc)" -L "^(unit|cli)$" 2>&1 | tee "$logs/quick.ctest.log"
  tally
  exit
fi

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

# A few minutes of coverage-guided fuzzing of the core, of each mesh reader and of the whole
# command-line path (clang's libFuzzer), from the committed seeds; any finding fails the run (it
# lands in fuzz/findings/).
if [ "${NVV_FUZZ_SECONDS:-30}" != 0 ]; then
  part "fuzzing, ${NVV_FUZZ_SECONDS:-30} s per target"
  bash scripts/fuzz.sh "${NVV_FUZZ_SECONDS:-30}" > "$logs/fuzz.txt" 2>&1 ||
    { tail -60 "$logs/fuzz.txt"; echo "run-tests: fuzzing found a crash (fuzz/findings/)" >&2; exit 1; }
  grep -E "^== fuzzing|^Done [0-9]+ runs" "$logs/fuzz.txt" || true
fi

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

if [ "${NVV_PYMESHLAB:-1}" != 0 ]; then
  part "PyMeshLab 2025.7 from pip"
  bash scripts/pymeshlab/run-tests-pymeshlab.sh 2>&1 |
    tee "$logs/pymeshlab.pytest.log"
fi
tally
