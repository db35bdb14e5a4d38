#!/usr/bin/env bash
# Makes a private MeshLab 2020.09 prefix that loads Debian's plugins plus ours, without touching
# the system: PREFIX/bin/meshlabserver and PREFIX/bin/meshlab are copies (a symlink would resolve
# to /usr/bin and load the system plugin folder), PREFIX/lib/<multiarch>/meshlab/plugins links the
# system plugins and our plugin (Debian's MeshLab looks only there, relative to its executable).
# Usage: scripts/meshlab-prefix.sh PREFIX PLUGIN.so
set -euo pipefail
prefix=$1
plugin=$(readlink -f "$2")
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -dumpmachine)
sys=/usr/lib/$multiarch/meshlab
lib=lib/$multiarch/meshlab
[ -f "$plugin" ] || { echo "meshlab-prefix: plugin $plugin not found" >&2; exit 1; }
[ -x /usr/bin/meshlabserver ] || { echo "meshlab-prefix: Debian's meshlab is not installed" >&2; exit 1; }
mkdir -p "$prefix/bin" "$prefix/$lib/plugins"
cp -f /usr/bin/meshlabserver /usr/bin/meshlab "$prefix/bin/"
ln -sf "$sys/libmeshlab-common.so"* "$prefix/$lib/" 2>/dev/null || true
for p in "$sys"/plugins/*.so; do
  ln -sf "$p" "$prefix/$lib/plugins/"
done
ln -sf "$plugin" "$prefix/$lib/plugins/$(basename "$plugin")"
echo "$prefix"
