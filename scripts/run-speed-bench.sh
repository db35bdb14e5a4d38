#!/usr/bin/env bash
# Speed and memory benchmark of Normal Vector Voting against MeshLab's (vcglib) and CGAL's
# curvature estimators on large meshes.
#
#   bash scripts/run-speed-bench.sh [--quick | --full] [extra nvv_bench_speed options]
#
# Configures build-speed/ (Release, benchmarks on), builds only nvv_bench_speed, runs it and
# writes its output to build-speed/speed-bench.md (plus the machine's description). Needs
# ../shared/meshes/real/turbineblade.ply next to the repository (or pass SHARED_MESHES=dir).
# The default plan takes about ten minutes on two idle cores; --quick about two; --full about 30.
# docs/performance.md quotes the latest output.
#
# On a machine shared with other jobs, set NVV_LOCK=/path/to/lockfile: every heavy step then
# runs under flock(1) on it, so the timings are taken on a quiet machine.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build-speed}
SHARED_MESHES=${SHARED_MESHES:-$(cd .. && pwd)/shared/meshes}
OUT=${OUT:-$BUILD/speed-bench.md}
JOBS=${JOBS:-2}
lock() { if [ -n "${NVV_LOCK:-}" ]; then flock "$NVV_LOCK" "$@"; else "$@"; fi; }

lock cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DNVV_BUILD_BENCH=ON >/dev/null
lock cmake --build "$BUILD" -j "$JOBS" --target nvv_bench_speed

{
  echo "Run: $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git rev-parse --short HEAD 2>/dev/null || echo '?')" \
       "(plus uncommitted changes: $(git status --porcelain 2>/dev/null | wc -l) files)"
  echo "Machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores" \
       "($(lscpu | sed -n 's/^Thread(s) per core: *//p') thread(s) per core)," \
       "$(free -g | awk '/^Mem:/ {print $2}') GB memory, $(uname -sr), $(c++ --version | head -1)"
  echo
} >"$OUT"
start=$(date +%s)
lock "$BUILD/bench/nvv_bench_speed" "$SHARED_MESHES" "$@" | tee -a "$OUT"
echo "" >>"$OUT"
echo "Wall time of the benchmark: $(( $(date +%s) - start )) s" | tee -a "$OUT"
echo "Output written to $OUT"
