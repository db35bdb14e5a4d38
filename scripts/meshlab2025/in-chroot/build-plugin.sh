#!/usr/bin/env bash
# Inside the sid chroot: builds the MeshLab 2025.07 plugin and its scripted-use tests for one
# scalar, and packs the release tarball.
#   float  - against Debian sid's libmeshlab-common.so (MeshLab's GUI)
#   double - against the double-precision core of build-meshlab-core-double.sh (PyMeshLab)
# Usage: build-plugin.sh float|double     -> $NVV_WORK/build-<scalar>/
set -euo pipefail
scalar=$1
case "$scalar" in
  float) libdir=/usr/lib/x86_64-linux-gnu/meshlab ;;
  double) libdir=$NVV_WORK/meshlab-core-double/src/distrib ;;
  *) echo "usage: build-plugin.sh float|double" >&2; exit 2 ;;
esac
build=$NVV_WORK/build-$scalar
cmake -S "$NVV_SRC/filter_normal_voting/meshlab/v2025" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DNVV_MESHLAB_SCALAR="$scalar" -DNVV_MESHLAB_SRC="$NVV_WORK/meshlab-src" \
  -DNVV_MESHLAB_LIB_DIR="$libdir" -DNVV_MESHLAB_PLUGIN_DIR="$libdir/plugins" > "$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; exit 1; }
ninja -C "$build" -j 1
(cd "$build" && cpack -G TGZ > cpack.log 2>&1) || { cat "$build/cpack.log"; exit 1; }
ls "$build"/filter-normal-voting-*.tar.gz
