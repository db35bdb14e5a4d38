# Shared settings of the MeshLab 2025.07 scripts (sourced, not run). The Debian sid chroot and
# everything built in it live under NVV_BUILD_2025 (default <repo>/build-2025), never in /usr.
#   NVV_BUILD_2025   build folder on the host            (default <repo>/build-2025)
#   NVV_CHROOT       the sid chroot                      (default $NVV_BUILD_2025/chroot)
#   NVV_MIRROR       Debian archive URI                  (default: the host's apt source)
#   NVV_JOBS_CORE    parallel jobs for MeshLab's core    (default 2)
nvv_repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
NVV_BUILD_2025=${NVV_BUILD_2025:-$nvv_repo/build-2025}
NVV_CHROOT=${NVV_CHROOT:-$NVV_BUILD_2025/chroot}
NVV_JOBS_CORE=${NVV_JOBS_CORE:-2}
# Where the repository appears inside the chroot (bind-mounted read-only) and where builds go.
NVV_CHROOT_SRC=/nvv-src
NVV_CHROOT_WORK=/nvv-work

nvv_mirror() {
  if [ -n "${NVV_MIRROR:-}" ]; then echo "$NVV_MIRROR"; return; fi
  local uri=""
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    uri=$(awk '/^URIs:/ && $2 !~ /security/ { print $2; exit }' /etc/apt/sources.list.d/debian.sources)
  elif [ -f /etc/apt/sources.list ]; then
    uri=$(awk '$1 == "deb" && $2 !~ /security/ { print $2; exit }' /etc/apt/sources.list)
  fi
  echo "${uri:-http://deb.debian.org/debian}"
}

nvv_log() { echo "[meshlab2025 $(date +%H:%M:%S)] $*"; }
nvv_die() { echo "[meshlab2025] ERROR: $*" >&2; exit 1; }

# Mounts /proc, /sys, /dev, /dev/pts and the repository into the chroot; nvv_unmount_all undoes
# exactly what was mounted (call it from an EXIT trap).
nvv_mounted=()
nvv_bind() {  # nvv_bind SRC DST [ro]
  local src=$1 dst=$NVV_CHROOT$2
  mkdir -p "$dst"
  mountpoint -q "$dst" && return 0
  mount --bind "$src" "$dst"
  nvv_mounted=("$dst" "${nvv_mounted[@]}")
  if [ "${3:-}" = ro ]; then mount -o remount,bind,ro "$dst"; fi
}
nvv_mount_all() {
  mkdir -p "$NVV_CHROOT/proc"
  if ! mountpoint -q "$NVV_CHROOT/proc"; then
    mount -t proc proc "$NVV_CHROOT/proc"
    nvv_mounted=("$NVV_CHROOT/proc" "${nvv_mounted[@]}")
  fi
  nvv_bind /sys /sys ro
  nvv_bind /dev /dev
  nvv_bind /dev/pts /dev/pts
  if mountpoint -q /dev/shm; then nvv_bind /dev/shm /dev/shm; fi
  if [ "${1:-}" = with-src ]; then nvv_bind "$nvv_repo" "$NVV_CHROOT_SRC" ro; fi
}
nvv_unmount_all() {
  local m
  for m in "${nvv_mounted[@]}"; do
    umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || echo "[meshlab2025] could not unmount $m" >&2
  done
  nvv_mounted=()
}
# Runs a command as root inside the chroot with a clean environment.
nvv_in_chroot() {
  chroot "$NVV_CHROOT" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive NVV_JOBS_CORE="$NVV_JOBS_CORE" \
    NVV_SRC="$NVV_CHROOT_SRC" NVV_WORK="$NVV_CHROOT_WORK" "$@"
}
