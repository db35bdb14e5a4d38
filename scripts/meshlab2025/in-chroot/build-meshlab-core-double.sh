#!/usr/bin/env bash
# Inside the sid chroot: builds the double-precision MeshLab 2025.07 core that PyMeshLab 2025.7
# bundles (libmeshlab-common.so, version string "2025.07d") and the five plugins our tests chain
# with, from Debian's source, into $NVV_WORK/meshlab-core-double. Reused when already built.
# Results: .../src/distrib/libmeshlab-common.so and .../src/distrib/plugins/lib*.so
set -euo pipefail
src=$NVV_WORK/meshlab-src
build=$NVV_WORK/meshlab-core-double
stamp=$build/.nvv-core-ready
if [ -f "$stamp" ]; then echo "MeshLab double core: reusing $build"; exit 0; fi
plugins="meshlabplugins/io_base;meshlabplugins/filter_meshing;meshlabplugins/filter_unsharp"
plugins+=";meshlabplugins/filter_sampling;meshlabplugins/filter_select"
# GLEW_VERSION and EIGEN3_INCLUDE_DIR: Debian's GLEW and Eigen config files do not set them.
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DMESHLAB_BUILD_WITH_DOUBLE_SCALAR=ON -DMESHLAB_BUILD_MINI=ON -DMESHLAB_BUILD_ONLY_LIBRARIES=ON \
  -DMESHLAB_ALLOW_OPTIONAL_EXTERNAL_LIBRARIES=OFF -DMESHLAB_ALLOW_SYSTEM_GLEW=ON \
  -DMESHLAB_ALLOW_BUNDLED_SOURCE_GLEW=OFF -DGLEW_VERSION=2.3.1 -DVCG_ALLOW_SYSTEM_EIGEN=ON \
  -DVCG_ALLOW_BUNDLED_EIGEN=OFF -DEIGEN3_INCLUDE_DIR=/usr/include/eigen3 \
  "-DMESHLAB_PLUGINS=$plugins" > "$build.configure.log" 2>&1 || { tail -30 "$build.configure.log"; exit 1; }
ninja -C "$build" -j "${NVV_JOBS_CORE:-2}" meshlab-common io_base filter_meshing filter_unsharp filter_sampling filter_select
touch "$stamp"
echo "MeshLab double core: built in $build"
