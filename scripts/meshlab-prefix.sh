#!/usr/bin/env bash
# Makes a private MeshLab 2020.09 prefix that loads Debian's plugins plus ours, without touching
# the system: PREFIX/bin/meshlabserver and PREFIX/bin/meshlab are copies (a symlink would resolve
# to /usr/bin and load the system plugin folder), PREFIX/lib/x86_64-linux-gnu/meshlab/plugins
# links the system plugins and our plugin.
# Usage: scripts/meshlab-prefix.sh PREFIX PLUGIN.so
set -euo pipefail
prefix=$1
plugin=$(readlink -f "$2")
sys=/usr/lib/x86_64-linux-gnu/meshlab
[ -f "$plugin" ] || { echo "meshlab-prefix: plugin $plugin not found" >&2; exit 1; }
[ -x /usr/bin/meshlabserver ] || { echo "meshlab-prefix: Debian's meshlab is not installed" >&2; exit 1; }
mkdir -p "$prefix/bin" "$prefix/lib/x86_64-linux-gnu/meshlab/plugins"
cp -f /usr/bin/meshlabserver /usr/bin/meshlab "$prefix/bin/"
ln -sf "$sys/libmeshlab-common.so"* "$prefix/lib/x86_64-linux-gnu/meshlab/" 2>/dev/null || true
for p in "$sys"/plugins/*.so; do
  ln -sf "$p" "$prefix/lib/x86_64-linux-gnu/meshlab/plugins/"
done
ln -sf "$plugin" "$prefix/lib/x86_64-linux-gnu/meshlab/plugins/$(basename "$plugin")"
echo "$prefix"
