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
disp=""
for d in $(seq 91 160); do
  if [ ! -e "/tmp/.X$d-lock" ] && [ ! -e "/tmp/.X11-unix/X$d" ]; then disp=$d; break; fi
done
[ -n "$disp" ] || { echo "gui smoke: no free X display"; exit 1; }
Xvfb ":$disp" -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
xpid=$!
mlpid=""
cleanup() { [ -n "$mlpid" ] && kill "$mlpid" 2>/dev/null; kill "$xpid" 2>/dev/null; true; }
trap cleanup EXIT
export DISPLAY=":$disp"
for _ in $(seq 50); do xdotool getdisplaygeometry >/dev/null 2>&1 && break; sleep 0.1; done
meshlab "$mesh" > "$out/meshlab_gui.log" 2>&1 &
mlpid=$!
wid=$(timeout 60 xdotool search --sync --name "MeshLab" | awk 'NR == 1')
sleep 5
xdotool windowmove "$wid" 0 0 windowsize "$wid" 1280 1000
sleep 2
shot() {
  import -window root "$out/$1.png"
  convert "$out/$1.png" -resize 200% "$out/.shot2x.png"
  tesseract "$out/.shot2x.png" - 2>/dev/null > "$out/$1.txt" || true
}
expect() {  # expect SHOT REGEX: the text must be on the screenshot
  if ! tr '\n' ' ' < "$out/$1.txt" | grep -Eiq "$2"; then
    echo "gui smoke: '$2' not found on $out/$1.png; OCR read:"; cat "$out/$1.txt"; exit 1
  fi
  echo "gui smoke: '$2' is on $1.png"
}
# Clicks the centre of the first word WORD that OCR finds on the screen.
click_word() {
  import -window root "$out/.click.png"
  convert "$out/.click.png" -resize 200% "$out/.click2x.png"  # OCR misses small UI text at 1x
  local pos
  pos=$(tesseract "$out/.click2x.png" - --psm 11 tsv 2>/dev/null |
        awk -F'\t' -v w="$1" '$12 == w && !found { print int(($7 + $9 / 2) / 2), int(($8 + $10 / 2) / 2); found = 1 }')
  [ -n "$pos" ] || { echo "gui smoke: '$1' not found on screen"; cp "$out/.click.png" "$out/not_found_$1.png"; exit 1; }
  # shellcheck disable=SC2086
  xdotool mousemove $pos sleep 0.3 mousemove_relative 2 0 click 1
  sleep 1.5
}
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
