#!/usr/bin/env bash
# Inside the sid chroot: GUI smoke test of Debian's MeshLab 2025.07 with the float plugin
# installed the way a user does it, in the per-user extra plugins folder. Under Xvfb, MeshLab
# must list the filter under Filters > Normals, Curvatures and Orientation and open its dialog,
# which shows the python name; applying it adds quality and colour to the mesh; on a CAD part, colour by
# patch and the crease lines layer set in the dialog give a new layer. Screenshots are read with
# tesseract (no fixed coordinates) and kept in $NVV_WORK/artefacts/gui/.
set -euo pipefail
plugin=$NVV_WORK/build-float/libfilter_normal_voting.so
mesh=$NVV_SRC/sample_meshes/cad_part_noise5.ply
out=$NVV_WORK/artefacts/gui
rm -rf "$out" && mkdir -p "$out"
[ -f "$plugin" ] || { echo "gui smoke: $plugin not built"; exit 1; }
export HOME=$NVV_WORK/gui-home XDG_DATA_HOME=$NVV_WORK/gui-home/.local/share
rm -rf "$HOME"
extra=$XDG_DATA_HOME/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/2025.07
mkdir -p "$extra"
cp "$plugin" "$extra/"
source "$NVV_SRC/tests/gui/gui_session.sh"
gui_start_display
gui_start_meshlab meshlab "$mesh"
click_word Filters
click_word Normals,
shot meshlab2025_filter_menu
expect meshlab2025_filter_menu "Normal Vector Voting: Creases, Normals and Curvature"
click_word Voting:
sleep 1
shot meshlab2025_filter_dialog
expect meshlab2025_filter_dialog "Neighbourhood size k"
expect meshlab2025_filter_dialog "PyMeshLab Filter"
# The python name; OCR sometimes splits "normal" at this size, so allow a few letters there.
expect meshlab2025_filter_dialog "compute_n.{0,4}al_vector_voting"
click_word Apply
sleep 4
click_word Close
sleep 2
shot meshlab2025_filter_applied
# The mesh now has per-vertex quality and colour (the info overlay lists VQ VC); the log's small
# monospace summary line is not always readable by OCR.
expect meshlab2025_filter_applied "VQ VC|sign-aware rule"

# A coarse CAD part (made on the host by bench/cad/make_cad_parts.py): colour by patch and the crease
# lines as a new layer, set in the dialog as a user does; the layer must appear in the layer panel.
# The screenshot is the README's (docs/images/meshlab2025_crease_lines.png).
part=$NVV_WORK/reference/cad/block_coarse.obj
if [ -f "$part" ]; then
  kill "$gui_mlpid" 2>/dev/null; wait "$gui_mlpid" 2>/dev/null || true
  gui_start_meshlab meshlab "$part"
  click_word Filters
  click_word Normals,
  click_word Voting:
  sleep 1
  click_word Class        # the "Vertex colour" list, showing "Class colours"
  click_word Patches
  click_right_of layer 14 # the check box of "Crease lines as a new layer"
  shot meshlab2025_crease_lines_dialog
  expect meshlab2025_crease_lines_dialog "Patches"
  click_word Apply
  sleep 4
  click_word Close
  sleep 2
  # Turn the part so its top, a side and the hole show (a drag in the 3D view), then hide nothing.
  xdotool mousemove 400 300 mousedown 1 sleep 0.2 mousemove 420 380 sleep 0.2 mousemove 440 460 sleep 0.2 \
    mousemove 460 540 sleep 0.2 mouseup 1
  sleep 2
  shot meshlab2025_crease_lines
  expect meshlab2025_crease_lines "crease lines"
else
  echo "gui smoke: no CAD part (python3-gmsh missing on the host): crease-lines screenshot skipped"
fi
rm -f "$out"/.*.png
echo "gui smoke: passed; screenshots in $out"
