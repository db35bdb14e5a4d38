#!/usr/bin/env bash
# Runs one of the in-chroot/ steps inside the sid chroot, with /proc, /sys, /dev and the
# repository (read-only, at /nvv-src) mounted for the duration only: an EXIT trap unmounts them
# whatever happens. Builds go to /nvv-work inside the chroot.
# Usage: scripts/meshlab2025/in-chroot.sh STEP.sh [ARGS...]
set -euo pipefail
source "$(dirname "$0")/chroot-env.sh"
# debootstrap, chroot and mount need root: a user with sudo gets it here.
[ "$(id -u)" -eq 0 ] || exec sudo -E bash "$0" "$@"
[ -f "$NVV_CHROOT/.nvv-chroot-ready" ] || nvv_die "no chroot in $NVV_CHROOT: run make-chroot.sh first"
step=$1; shift
[ -f "$nvv_repo/scripts/meshlab2025/in-chroot/$step" ] || nvv_die "no step $step"
trap nvv_unmount_all EXIT
mkdir -p "$NVV_CHROOT$NVV_CHROOT_WORK"
nvv_mount_all with-src
nvv_in_chroot bash "$NVV_CHROOT_SRC/scripts/meshlab2025/in-chroot/$step" "$@"
