#!/usr/bin/env bash
# GUI smoke test: Debian's MeshLab 2020.09 (from the private prefix) under Xvfb lists the filter in
# Filters > Normals, Curvatures and Orientation, opens its dialog and applies it. Screenshots are
# kept in OUTDIR; text on them is read back with tesseract to assert what a user would see.
# Usage: meshlab_gui_smoke.sh PREFIX MESH OUTDIR
set -euo pipefail
prefix=$1 mesh=$2 out=$3
mkdir -p "$out"
for cmd in Xvfb xdotool import tesseract /usr/bin/convert; do
  command -v "$cmd" >/dev/null || { echo "gui smoke: $cmd is missing (scripts/install-deps.sh installs it)"; exit 1; }
done
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
"$prefix/bin/meshlab" "$mesh" > "$out/meshlab_gui.log" 2>&1 &
mlpid=$!
wid=$(timeout 60 xdotool search --sync --name "MeshLab" | awk 'NR == 1')  # awk reads all: no SIGPIPE
sleep 4
xdotool windowmove "$wid" 0 0
sleep 1
shot() {
  import -window root "$out/$1.png"
  /usr/bin/convert "$out/$1.png" -resize 200% "$out/.shot2x.png"
  tesseract "$out/.shot2x.png" - 2>/dev/null > "$out/$1.txt" || true
}
expect() {  # expect SHOT TEXT: the text must be on the screenshot
  if ! tr '\n' ' ' < "$out/$1.txt" | grep -q "$2"; then
    echo "gui smoke: '$2' not found on $out/$1.png; OCR read:"; cat "$out/$1.txt"; exit 1
  fi
  echo "gui smoke: '$2' is on $1.png"
}
# Clicks the centre of the first word WORD that OCR finds on the screen (no fixed coordinates).
click_word() {
  import -window root "$out/.click.png"
  /usr/bin/convert "$out/.click.png" -resize 200% "$out/.click2x.png"  # OCR misses small UI text at 1x
  local pos
  # psm 11 (sparse text) also finds lone button labels.
  pos=$(tesseract "$out/.click2x.png" - --psm 11 tsv 2>/dev/null |
        awk -F'\t' -v w="$1" '$12 == w && !found { print int(($7 + $9 / 2) / 2), int(($8 + $10 / 2) / 2); found = 1 }')
  [ -n "$pos" ] || { echo "gui smoke: '$1' not found on screen"; cp "$out/.click.png" "$out/not_found_$1.png"; exit 1; }
  # shellcheck disable=SC2086
  xdotool mousemove $pos sleep 0.3 mousemove_relative 2 0 click 1
  sleep 1.5
}
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
