#!/bin/sh
# Regenerates docs/accuracy.md, its full tables docs/accuracy/*.csv and docs/images/accuracy_*.png
# from scratch: configures build-bench/ with the benchmarks, builds nvv_bench_accuracy, runs its
# five sections (bench/accuracy.cpp), the quadric fit's levers (bench/explore_fit.cpp), the
# Python libraries' estimators on the smooth sections' meshes (bench/python_peers.py) and the
# "cad" section on parts made by gmsh's OpenCASCADE kernel (bench/cad/make_cad_parts.py), the
# "network" section (crease edges, lines and patches) on those parts and the crease shapes (and
# again on two other noise draws of each, "heldout"), and
# turns their tables and CSV files into the page, the CSV files beside it and the plots
# (bench/accuracy_report.py, matplotlib from Debian: apt-get install python3-matplotlib).
# The Python estimators run in a virtual environment, build-bench/pyvenv, made with Debian's
# python3-venv and the pinned packages of bench/python_peers_requirements.txt from PyPI (made
# anew when that file changes; open3d needs Debian's libusb-1.0-0: scripts/install-deps.sh).
# Set NVV_CPU_LOCK=/path/to/lockfile to run each build / run step under flock(1).
# NVV_ACCURACY_ONLY=python reruns only the Python estimators and rewrites the page from the
# other sections' output of the last full run (build-bench/accuracy/), with that run's time;
# NVV_ACCURACY_ONLY=cad does the same for the CAD parts (gmsh from Debian: python3-gmsh) and the
# crease networks measured on them; NVV_ACCURACY_ONLY=network for the crease networks alone.
set -eu
cd "$(dirname "$0")/.."
start=$(date +%s)
lock() { if [ -n "${NVV_CPU_LOCK:-}" ]; then flock "$NVV_CPU_LOCK" "$@"; else "$@"; fi; }

lock cmake -S . -B build-bench -G Ninja -DNVV_BUILD_BENCH=ON -DNVV_BUILD_PLUGIN=OFF -DNVV_BUILD_CLI=OFF \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
lock ninja -C build-bench -j2 nvv_bench_accuracy nvv_bench_explore_fit
out=build-bench/accuracy

# The Python estimators on the meshes of the grids and variants sections.
run_python_peers() {
  t0=$(date +%s)
  py=build-bench/pyvenv
  req=bench/python_peers_requirements.txt
  if [ ! -x "$py/bin/python" ] || ! cmp -s "$req" "$py/requirements.txt"; then
    rm -rf "$py"
    /usr/bin/python3 -m venv "$py"
    "$py/bin/pip" install -q --disable-pip-version-check -r "$req"
    cp "$req" "$py/requirements.txt"
  fi
  t1=$(date +%s)
  rm -rf "$out/python_meshes"
  mkdir -p "$out/python_meshes"
  lock build-bench/bench/nvv_bench_accuracy export "$out/python_meshes" >/dev/null
  lock "$py/bin/python" bench/python_peers.py "$out/python_meshes" "$out/python_peers.csv" >"$out/python_peers.log"
  echo "$(( $(date +%s) - t1 ))" >"$out/python_seconds.txt"
  echo "python peers: $(( $(date +%s) - t1 )) s (and $(( t1 - t0 )) s for the virtual environment)"
}

# Real CAD parts: made and meshed by gmsh's OpenCASCADE kernel (Debian's python3-gmsh) into
# $out/cad, then scored with the ABC model (bench/cad/make_cad_parts.py, bench/cad_parts.cpp).
run_cad() {
  t0=$(date +%s)
  rm -rf "$out/cad"
  lock /usr/bin/python3 bench/cad/make_cad_parts.py "$out/cad" >"$out/cad_parts.txt"
  lock build-bench/bench/nvv_bench_accuracy cad "$out" "$out/cad" >"$out/cad.md"
  echo "$(( $(date +%s) - t0 ))" >"$out/cad_seconds.txt"
  echo "section cad: $(( $(date +%s) - t0 )) s"
}

# Crease edges, lines and patches against the truth on the crease shapes, the CAD parts of
# run_cad and the ABC model, beside MeshLab's and CGAL's (bench/crease_networks.cpp).
run_network() {
  t0=$(date +%s)
  lock build-bench/bench/nvv_bench_accuracy network "$out" "$out/cad" >"$out/network.md"
  echo "$(( $(date +%s) - t0 ))" >"$out/network_seconds.txt"
  echo "section network: $(( $(date +%s) - t0 )) s"
  # The same meshes on two other noise draws, on which no threshold was chosen.
  t0=$(date +%s)
  lock build-bench/bench/nvv_bench_accuracy heldout "$out" "$out/cad" >/dev/null
  echo "section heldout: $(( $(date +%s) - t0 )) s"
}

case "${NVV_ACCURACY_ONLY:-}" in python|cad|network)
  [ -f "$out/full_seconds.txt" ] || { echo "NVV_ACCURACY_ONLY=$NVV_ACCURACY_ONLY needs a full run's $out first" >&2; exit 2; }
  case "$NVV_ACCURACY_ONLY" in
    python) run_python_peers ;;
    cad) run_cad; run_network ;;
    network) run_network ;;
  esac
  seconds=$(cat "$out/full_seconds.txt") ;;
*)
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
  run_python_peers
  run_cad
  run_network
  seconds=$(( $(date +%s) - start ))
  echo "$seconds" >"$out/full_seconds.txt" ;;
esac
rm -f docs/accuracy/*.csv   # the report writes every table family afresh
/usr/bin/python3 bench/accuracy_report.py "$out" bench/accuracy.md.in docs/accuracy.md docs/images "$seconds"
echo "docs/accuracy.md regenerated in $(( $(date +%s) - start )) s"
