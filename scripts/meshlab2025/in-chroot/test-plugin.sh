#!/usr/bin/env bash
# Inside the sid chroot: runs the scripted-use tests of one build (float against Debian's
# MeshLab 2025.07, double against the PyMeshLab-like double core). Output and JUnit XML go to
# $NVV_WORK/artefacts/. The other build's plugin, when built, must be rejected by this core;
# the host's reference result (nvv CLI), when present, must be matched.
# Usage: test-plugin.sh float|double
set -euo pipefail
scalar=$1
other=double; [ "$scalar" = double ] && other=float
build=$NVV_WORK/build-$scalar
out=$NVV_WORK/artefacts
mkdir -p "$out"
export NVV_OTHER_SCALAR_PLUGIN=""
[ -f "$NVV_WORK/build-$other/libfilter_normal_voting.so" ] && NVV_OTHER_SCALAR_PLUGIN=$NVV_WORK/build-$other/libfilter_normal_voting.so
export NVV_CLI_REFERENCE=""
[ -f "$NVV_WORK/reference/cad_part_noise5_nvv.ply" ] && NVV_CLI_REFERENCE=$NVV_WORK/reference/cad_part_noise5_nvv.ply
# The chains' meshes, for the pictures of docs/meshlab2025.md.
export NVV_ARTEFACTS=$out/meshes-$scalar
rm -rf "$NVV_ARTEFACTS" && mkdir -p "$NVV_ARTEFACTS"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
# The double core has the same SONAME as Debian's float library: the test's RUNPATH picks it.
unset LD_LIBRARY_PATH
set +e
"$build/tests/nvv_meshlab2025_tests" --gtest_output="xml:$out/tests-$scalar.xml" 2>&1 | tee "$out/tests-$scalar.log"
status=${PIPESTATUS[0]}
set -e
[ "$status" -eq 0 ] || { echo "scripted-use tests ($scalar) FAILED" >&2; exit 1; }
