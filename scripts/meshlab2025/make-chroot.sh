#!/usr/bin/env bash
# Creates the Debian sid chroot in which MeshLab 2025.07 runs and the 2025 builds are made, and
# installs into it, from Debian's archive only: sid's meshlab (2025.07, float) with the
# libraries its plugins need, an X server, the compilers and headers, GoogleTest, and the tools
# of the GUI smoke test. Reuses the chroot when it is complete (stamp file). The host's /usr is
# not changed, except that debootstrap is installed when missing.
# Usage: scripts/meshlab2025/make-chroot.sh        (as root; see chroot-env.sh for settings)
set -euo pipefail
source "$(dirname "$0")/chroot-env.sh"
# debootstrap, chroot and mount need root: a user with sudo gets it here.
[ "$(id -u)" -eq 0 ] || exec sudo -E bash "$0" "$@"
stamp=$NVV_CHROOT/.nvv-chroot-ready
if [ -f "$stamp" ]; then nvv_log "reusing the sid chroot in $NVV_CHROOT"; exit 0; fi

# The packages installed in the chroot. meshlab's Recommends are listed by name: without them
# four of its plugins fail to load and the GUI then ignores the per-user plugin folder.
packages=(meshlab lib3ds-1-3 libmuparser2v5 libopenctm1 libqhull-r8.0 libgomp1
          xvfb xauth xdotool imagemagick tesseract-ocr tesseract-ocr-eng
          g++ cmake make ninja-build dpkg-dev xz-utils file
          qtbase5-dev qtbase5-dev-tools libqt5opengl5-dev libglew-dev libeigen3-dev libgtest-dev)

if ! command -v debootstrap >/dev/null; then
  nvv_log "installing debootstrap on the host"
  apt-get update -q >/dev/null
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap >/dev/null
fi

trap nvv_unmount_all EXIT
# A half-made chroot from an interrupted run is thrown away; never delete through a mount.
if [ -d "$NVV_CHROOT" ]; then
  if grep -q " $NVV_CHROOT/" /proc/mounts; then nvv_die "something is still mounted under $NVV_CHROOT"; fi
  rm -rf "$NVV_CHROOT"
fi
mkdir -p "$NVV_BUILD_2025"
mirror=$(nvv_mirror)
nvv_log "debootstrap --variant=minbase sid from $mirror"
debootstrap --variant=minbase sid "$NVV_CHROOT" "$mirror" > "$NVV_BUILD_2025/debootstrap.log" 2>&1 ||
  { tail -20 "$NVV_BUILD_2025/debootstrap.log"; nvv_die "debootstrap failed (log: $NVV_BUILD_2025/debootstrap.log)"; }

# sid's archive snapshot here is frozen: its Release file has expired.
cat > "$NVV_CHROOT/etc/apt/sources.list" <<SRC
deb $mirror sid main
deb-src $mirror sid main
SRC
cat > "$NVV_CHROOT/etc/apt/apt.conf.d/90nvv" <<'CONF'
Acquire::Check-Valid-Until "false";
APT::Install-Recommends "false";
CONF
# No daemon may start inside the chroot.
printf '#!/bin/sh\nexit 101\n' > "$NVV_CHROOT/usr/sbin/policy-rc.d"
chmod +x "$NVV_CHROOT/usr/sbin/policy-rc.d"
cp -L /etc/resolv.conf "$NVV_CHROOT/etc/resolv.conf"

nvv_mount_all
nvv_log "apt-get install in the chroot (${#packages[@]} packages and their dependencies)"
nvv_in_chroot apt-get update -q > "$NVV_BUILD_2025/apt.log" 2>&1 ||
  { tail -20 "$NVV_BUILD_2025/apt.log"; nvv_die "apt-get update in the chroot failed"; }
nvv_in_chroot apt-get install -y -q "${packages[@]}" >> "$NVV_BUILD_2025/apt.log" 2>&1 ||
  { tail -20 "$NVV_BUILD_2025/apt.log"; nvv_die "apt-get install in the chroot failed"; }
nvv_in_chroot apt-get clean
nvv_in_chroot dpkg-query -W -f='${Package} ${Version}\n' meshlab | tee "$NVV_BUILD_2025/meshlab-version.txt"
touch "$stamp"
nvv_log "sid chroot ready in $NVV_CHROOT"
