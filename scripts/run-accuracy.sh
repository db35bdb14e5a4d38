#!/bin/sh
# Regenerates docs/accuracy.md, its full tables docs/accuracy/*.csv and docs/images/accuracy_*.png
# from scratch: configures build-bench/ with the benchmarks, builds nvv_bench_accuracy, runs its
# five sections (bench/accuracy.cpp) and the quadric fit's levers (bench/explore_fit.cpp), and
# turns their tables and CSV files into the page, the CSV files beside it and the plots
# (bench/accuracy_report.py, matplotlib from Debian: apt-get install python3-matplotlib).
# Set NVV_CPU_LOCK=/path/to/lockfile to run each build / run step under flock(1).
set -eu
cd "$(dirname "$0")/.."
start=$(date +%s)
lock() { if [ -n "${NVV_CPU_LOCK:-}" ]; then flock "$NVV_CPU_LOCK" "$@"; else "$@"; fi; }

lock cmake -S . -B build-bench -G Ninja -DNVV_BUILD_BENCH=ON -DNVV_BUILD_PLUGIN=OFF -DNVV_BUILD_CLI=OFF \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
lock ninja -C build-bench -j2 nvv_bench_accuracy nvv_bench_explore_fit
out=build-bench/accuracy
rm -rf "$out"
mkdir -p "$out"
for s in grids variants f1 near real; do
  t0=$(date +%s)
  lock build-bench/bench/nvv_bench_accuracy "$s" "$out" >"$out/$s.md"
  echo "section $s: $(( $(date +%s) - t0 )) s"
done
# The quadric fit's levers: slope-row weight (l_ave) and number of fits, at k = 3 and 5.
lock sh -c '
  echo "| k | noise | slope weight | fits | normal (deg) | cylinder min. direction (deg) | sphere curvature (%) |"
  echo "|---|---|---|---|---|---|---|"
  for a in "3 5 1 1" "3 5 2 1" "3 5 4 1" "3 5 2 2" "3 5 2 3" "5 5 2 1" "5 5 2 2" "3 20 2 1" "3 20 2 2" "5 20 2 1" "5 20 2 2"; do
    build-bench/bench/nvv_bench_explore_fit $a
  done' >"$out/levers.md"
rm -f docs/accuracy/*.csv   # the report writes every table family afresh
/usr/bin/python3 bench/accuracy_report.py "$out" bench/accuracy.md.in docs/accuracy.md docs/images \
  "$(( $(date +%s) - start ))"
echo "docs/accuracy.md regenerated in $(( $(date +%s) - start )) s"
