#!/usr/bin/env bash
# Inside the sid chroot: GUI smoke test of Debian's MeshLab 2025.07 with the float plugin
# installed the way a user does it, in the per-user extra plugins folder. Under Xvfb, MeshLab
# must list the filter under Filters > Normals, Curvatures and Orientation and open its dialog,
# which shows the python name; applying it adds quality and colour to the mesh. Screenshots are read with
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
rm -f "$out"/.*.png
echo "gui smoke: passed; screenshots in $out"
