#!/usr/bin/env bash
# Inside the sid chroot: unpacks MeshLab 2025.07's source (Debian's orig tarball, whose
# src/common equals upstream tag MeshLab-2025.07) into $NVV_WORK/meshlab-src. Its headers build
# our plugin; its tree builds the double-precision core. `apt-get source` fails on sid's .dsc
# here, but the orig tarball it fetches first is all that is needed.
set -euo pipefail
dest=$NVV_WORK/meshlab-src
if [ -f "$dest/src/common/plugins/interfaces/filter_plugin.h" ]; then echo "MeshLab source: reusing $dest"; exit 0; fi
dl=$NVV_WORK/meshlab-download
mkdir -p "$dl"
cd "$dl"
apt-get update -q >/dev/null 2>&1 || true
apt-get source --download-only -q meshlab >apt-source.log 2>&1 || true
tarball=$(ls meshlab_2025.07*.orig.tar.* 2>/dev/null | head -1)
[ -n "$tarball" ] || { cat apt-source.log; echo "MeshLab 2025.07 orig tarball not fetched" >&2; exit 1; }
rm -rf "$dest.tmp" && mkdir -p "$dest.tmp"
tar -xf "$tarball" -C "$dest.tmp" --strip-components=1
[ -f "$dest.tmp/src/common/plugins/interfaces/filter_plugin.h" ] || { echo "unexpected layout in $tarball" >&2; exit 1; }
rm -rf "$dest" && mv "$dest.tmp" "$dest"
echo "MeshLab source: $tarball unpacked in $dest"
