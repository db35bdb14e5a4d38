#!/usr/bin/env bash
# The committed sample meshes are exactly what the committed generator writes.
# Usage: check_sample_meshes.sh NVV_MAKE_SAMPLES SAMPLE_DIR
set -euo pipefail
gen=$1 dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$gen" "$tmp" > /dev/null
n=0
for f in "$tmp"/*.ply; do
  cmp "$f" "$dir/$(basename "$f")" || { echo "sample mesh $(basename "$f") differs from the generator's output"; exit 1; }
  n=$((n + 1))
done
[ "$(ls "$dir"/*.ply | wc -l)" -eq "$n" ] || { echo "sample_meshes/ holds PLY files the generator does not write"; exit 1; }
echo "$n sample meshes match the generator"
