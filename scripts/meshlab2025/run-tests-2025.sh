#!/usr/bin/env bash
# Builds and tests the filter for MeshLab 2025.07 and PyMeshLab 2025.7, inside a Debian sid
# chroot (created on first use under build-2025/chroot, then reused):
#   1. the chroot, with sid's MeshLab 2025.07 (float) and the build tools      make-chroot.sh
#   2. MeshLab 2025.07's source (Debian's orig tarball)                         fetch-meshlab-source.sh
#   3. a double-precision MeshLab 2025.07 core + 5 plugins (what PyMeshLab runs) build-meshlab-core-double.sh
#   4. our plugin, float and double, with the scripted-use tests and tarballs    build-plugin.sh
#   5. the scripted-use tests against both cores                                 test-plugin.sh
#   6. the GUI smoke test in MeshLab 2025.07 under Xvfb                          gui-smoke-2025.sh
# Release tarballs, test logs, JUnit XML and screenshots end up in build-2025/artefacts/.
# Fails (non-zero) on the first failing step. Run as root: sudo bash scripts/meshlab2025/run-tests-2025.sh
# Settings: see chroot-env.sh (NVV_BUILD_2025, NVV_CHROOT, NVV_MIRROR, NVV_JOBS_CORE); NVV_CLI
# points at the main build's nvv tool (default: the first build*/filter_normal_voting/cli/nvv).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/chroot-env.sh"
# debootstrap, chroot and mount need root: a user with sudo gets it here.
[ "$(id -u)" -eq 0 ] || exec sudo -E bash "$0" "$@"
start=$(date +%s)
step() { nvv_log "== $* ($(( $(date +%s) - start )) s)"; }
trap 'echo "[meshlab2025] FAILED after $(( $(date +%s) - start )) s" >&2' ERR

step "sid chroot"
bash "$here/make-chroot.sh"
work=$NVV_CHROOT$NVV_CHROOT_WORK
mkdir -p "$work/reference" "$work/artefacts"

# The reference numbers of the main build: its command-line tool on the same mesh.
cli=${NVV_CLI:-$(ls "$nvv_repo"/build*/filter_normal_voting/cli/nvv 2>/dev/null | head -1 || true)}
rm -f "$work/reference/cad_part_noise5_nvv.ply"
if [ -n "$cli" ] && [ -x "$cli" ]; then
  step "reference result with $cli"
  "$cli" "$nvv_repo/sample_meshes/cad_part_noise5.ply" "$work/reference/cad_part_noise5_nvv.ply" > "$work/reference/nvv.log"
else
  nvv_log "no nvv tool built: the comparison with the command-line tool is skipped"
fi

# The coarse CAD part the GUI test shows with its crease lines and patches (gmsh runs on the host).
rm -rf "$work/reference/cad"
if /usr/bin/python3 -c 'import gmsh' 2>/dev/null; then
  step "CAD part for the GUI test"
  /usr/bin/python3 "$nvv_repo/bench/cad/make_cad_parts.py" "$work/reference/cad" block_coarse > "$work/reference/gmsh.log"
else
  nvv_log "no python3-gmsh: the GUI test's crease-lines screenshot is skipped"
fi

step "MeshLab 2025.07 source"
bash "$here/in-chroot.sh" fetch-meshlab-source.sh
step "double-precision MeshLab 2025.07 core (-j$NVV_JOBS_CORE)"
bash "$here/in-chroot.sh" build-meshlab-core-double.sh
for scalar in float double; do
  step "plugin, $scalar"
  bash "$here/in-chroot.sh" build-plugin.sh "$scalar"
done
for scalar in float double; do
  step "scripted-use tests, $scalar"
  bash "$here/in-chroot.sh" test-plugin.sh "$scalar"
done
step "GUI smoke test"
bash "$here/in-chroot.sh" gui-smoke-2025.sh

step "artefacts"
dest=$NVV_BUILD_2025/artefacts
rm -rf "$dest" && mkdir -p "$dest"
cp "$work"/build-float/filter-normal-voting-*.tar.gz "$work"/build-double/filter-normal-voting-*.tar.gz "$dest/"
cp -r "$work/artefacts/." "$dest/"
ls -l "$dest"
nvv_log "MeshLab 2025.07 part passed in $(( $(date +%s) - start )) s"
