#!/usr/bin/env bash
# The main job: builds the plugin, loads it into Debian's real meshlabserver 2020.09 (from a
# private prefix, the system's MeshLab is not modified), runs the filter on a sample mesh and
# writes the result meshes and a picture coloured by class and by curvature into out/.
# Usage: sudo bash scripts/run-main-job.sh [INPUT_MESH]   (default: sample_meshes/cad_part_noise5.ply)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
input=$(readlink -f "${1:-sample_meshes/cad_part_noise5.ply}")
build=${BUILD_DIR:-build}
out="$here/out"
bash scripts/install-deps.sh
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DNVV_BUILD_TESTS=OFF >/dev/null
ninja -C "$build" -j "$(nproc)" filter_normal_voting nvv_mlx nvv_render
prefix=$(bash scripts/meshlab-prefix.sh "$build/meshlab-prefix" "$build/filter_normal_voting/meshlab/v2020/libfilter_normal_voting.so")
mkdir -p "$out"
name=$(basename "${input%.*}")
# Two runs of the same filter: colour by class, then colour by mean curvature (quality ramp).
"$build/tools/nvv_mlx" color=0 quality=0 > "$out/normal_voting_classes.mlx"
"$build/tools/nvv_mlx" color=1 quality=0 > "$out/normal_voting_curvature.mlx"
for kind in classes curvature; do
  xvfb-run -a "$prefix/bin/meshlabserver" -i "$input" -o "$out/${name}_$kind.ply" -m vc vq vn \
    -s "$out/normal_voting_$kind.mlx" > "$out/${name}_$kind.log" 2>&1 || {
      echo "meshlabserver failed; its output:" >&2; cat "$out/${name}_$kind.log" >&2; exit 1; }
done
grep -m1 "LOG: .*Normal vector voting: [0-9]" "$out/${name}_classes.log" | sed 's/^LOG: [0-9]* //'
QT_QPA_PLATFORM=offscreen "$build/tools/nvv_render" "$out/$name.png" 600 450 30 35 \
  "$out/${name}_classes.ply" "classes: surface grey, crease red, corner blue" \
  "$out/${name}_curvature.ply" "mean curvature (red low, blue high)" 2>/dev/null
echo "main job: wrote $out/${name}_classes.ply, $out/${name}_curvature.ply and $out/$name.png"
