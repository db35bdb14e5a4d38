#!/usr/bin/env bash
# GUI smoke test: Debian's MeshLab 2020.09 (from the private prefix) under Xvfb lists the filter in
# Filters > Normals, Curvatures and Orientation, opens its dialog and applies it. Screenshots are
# kept in OUTDIR; text on them is read back with tesseract to assert what a user would see.
# Usage: meshlab_gui_smoke.sh PREFIX MESH OUTDIR
set -euo pipefail
prefix=$1 mesh=$2 out=$3
mkdir -p "$out"
source "$(dirname "$0")/gui_session.sh"
gui_start_display
gui_start_meshlab "$prefix/bin/meshlab" "$mesh"
click_word Filters
click_word Normals,
shot meshlab_filter_menu
expect meshlab_filter_menu "Normal Vector Voting: Creases, Normals and Curvature"
click_word Voting:
shot meshlab_filter_dialog
expect meshlab_filter_dialog "Neighbourhood size k"
expect meshlab_filter_dialog "Crease angle"
# Apply with the defaults: the mesh turns to class colours and the log shows the summary line.
click_word Apply
sleep 3
click_word Close
sleep 1
shot meshlab_filter_applied
expect meshlab_filter_applied "sign-aware rule"
echo "gui smoke: passed; screenshots in $out"
