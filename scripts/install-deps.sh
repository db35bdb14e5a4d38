#!/usr/bin/env bash
# Installs everything the build, the tests and the main job need on Debian bookworm,
# from Debian's archive only, and unpacks MeshLab 2020.09's source (headers) into
# third_party_src/ (ignored by git). Idempotent: a second run does little.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# MeshLab's headers come from its Debian source package: enable deb-src once.
src_list=/etc/apt/sources.list.d/nvv-deb-src.sources
if ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ && ! grep -qs '^deb-src' /etc/apt/sources.list; then
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources | $SUDO tee "$src_list" >/dev/null
  else
    sed -n 's/^deb /deb-src /p' /etc/apt/sources.list | $SUDO tee /etc/apt/sources.list.d/nvv-deb-src.list >/dev/null
  fi
fi

pkgs=(build-essential cmake ninja-build pkg-config dpkg-dev
      meshlab xvfb xauth x11-apps imagemagick xdotool
      qtbase5-dev qtbase5-dev-tools libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libeigen3-dev
      libgtest-dev googletest libcgal-dev libgmp-dev libmpfr-dev libomp-dev tesseract-ocr tesseract-ocr-eng
      clang-14 libclang-rt-14-dev libomp-14-dev python3-matplotlib debootstrap
      python3-venv libusb-1.0-0   # Python venvs (accuracy benchmark, PyMeshLab tests); open3d needs libusb
      gmsh python3-gmsh)          # gmsh 4.8.4 with OpenCASCADE: the accuracy benchmark's CAD parts
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ] || [ ! -d "$here/third_party_src/meshlab" ]; then
  $SUDO apt-get update -q
fi
if [ ${#missing[@]} -gt 0 ]; then
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

if [ ! -f "$here/third_party_src/meshlab/src/common/interfaces.h" ]; then
  mkdir -p "$here/third_party_src"
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get source -q meshlab=2020.09+dfsg1-2 >/dev/null 2>&1 || (cd "$tmp" && apt-get source -q meshlab))
  rm -rf "$here/third_party_src/meshlab"
  mv "$tmp"/meshlab-2020.09* "$here/third_party_src/meshlab"
  rm -rf "$tmp"
fi
echo "install-deps: ok (MeshLab source in third_party_src/meshlab)"
