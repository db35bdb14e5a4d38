# Shared by the GUI smoke tests of MeshLab 2020.09 (host) and 2025.07 (sid chroot); sourced, not run.
# Starts a private Xvfb display, starts MeshLab on it, and offers screenshot / OCR helpers that find
# what a user would see without fixed coordinates. The caller sets `out` (the screenshot folder)
# and calls gui_start_display, then gui_start_meshlab CMD ARGS...
# Needs Xvfb, xdotool, ImageMagick's import and convert, and tesseract.
for cmd in Xvfb xdotool import tesseract /usr/bin/convert; do
  command -v "$cmd" >/dev/null || { echo "gui smoke: $cmd is missing"; exit 1; }
done
# A failing command anywhere, functions included (errtrace), says which before set -e ends the test.
set -E
trap 'echo "gui smoke: failed at line $LINENO: $BASH_COMMAND" >&2' ERR
gui_xpid="" gui_mlpid=""
# A process that has already gone is no failure of a test that passed (under set -e a failed kill in
# the exit trap would turn the test's status into 1 after it printed "passed").
gui_cleanup() {
  if [ -n "$gui_mlpid" ]; then kill "$gui_mlpid" 2>/dev/null || true; fi
  if [ -n "$gui_xpid" ]; then kill "$gui_xpid" 2>/dev/null || true; fi
}
trap gui_cleanup EXIT

gui_start_display() {
  local d disp=""
  for d in $(seq 91 160); do
    if [ ! -e "/tmp/.X$d-lock" ] && [ ! -e "/tmp/.X11-unix/X$d" ]; then disp=$d; break; fi
  done
  [ -n "$disp" ] || { echo "gui smoke: no free X display"; exit 1; }
  # -noreset: without it the server resets when its last client leaves, and a client that connects
  # during the reset (MeshLab, right after the readiness probe below) is refused.
  Xvfb ":$disp" -screen 0 1280x1024x24 -nolisten tcp -noreset >/dev/null 2>&1 &
  gui_xpid=$!
  export DISPLAY=":$disp"
  for _ in $(seq 50); do xdotool getdisplaygeometry >/dev/null 2>&1 && break; sleep 0.1; done
}

# gui_start_meshlab CMD ARGS...: starts it (log in $out/meshlab_gui.log) and puts its window at the
# top left, 1280 x 1000 (there is no window manager).
gui_start_meshlab() {
  "$@" > "$out/meshlab_gui.log" 2>&1 &
  gui_mlpid=$!
  local wid
  gui_find_window 60 >/dev/null || { echo "gui smoke: no MeshLab window; its log:"; cat "$out/meshlab_gui.log"; exit 1; }
  sleep 5
  # Searched again: the first match may have been a window MeshLab closed while it started.
  wid=$(gui_find_window 10) || { echo "gui smoke: MeshLab's window went away; its log:"; cat "$out/meshlab_gui.log"; exit 1; }
  xdotool windowmove "$wid" 0 0 windowsize "$wid" 1280 1000
  sleep 2
}

# gui_find_window SECONDS: prints the id of a visible window named MeshLab, polling for up to
# SECONDS. xdotool's search reads the properties of every window on the display and exits with
# BadWindow when one closes meanwhile (MeshLab's start-up opens and closes several), so a failed
# search is tried again rather than taken for an answer.
gui_find_window() {
  local wid="" i
  for i in $(seq $(($1 * 2))); do
    kill -0 "$gui_mlpid" 2>/dev/null || return 1
    wid=$(xdotool search --onlyvisible --name "MeshLab" 2>/dev/null | awk 'NR == 1') || wid=""  # awk reads all: no SIGPIPE
    [ -n "$wid" ] && { echo "$wid"; return 0; }
    sleep 0.5
  done
  return 1
}

# shot NAME: a screenshot $out/NAME.png and the text OCR reads on it, $out/NAME.txt.
shot() {
  import -window root "$out/$1.png"
  /usr/bin/convert "$out/$1.png" -resize 200% "$out/.shot2x.png"  # OCR misses small UI text at 1x
  tesseract "$out/.shot2x.png" - 2>/dev/null > "$out/$1.txt" || true
}

# expect NAME REGEX: the text (extended regex, any case) must be on screenshot NAME.
expect() {
  if ! tr '\n' ' ' < "$out/$1.txt" | grep -Eiq "$2"; then
    echo "gui smoke: '$2' not found on $out/$1.png; OCR read:"; cat "$out/$1.txt"; exit 1
  fi
  echo "gui smoke: '$2' is on $1.png"
}

# click_word WORD: clicks the centre of the first word WORD that OCR finds on the screen.
click_word() {
  import -window root "$out/.click.png"
  /usr/bin/convert "$out/.click.png" -resize 200% "$out/.click2x.png"
  local pos
  # psm 11 (sparse text) also finds lone button labels.
  pos=$(tesseract "$out/.click2x.png" - --psm 11 tsv 2>/dev/null |
        awk -F'\t' -v w="$1" '$12 == w && !found { print int(($7 + $9 / 2) / 2), int(($8 + $10 / 2) / 2); found = 1 }')
  [ -n "$pos" ] || { echo "gui smoke: '$1' not found on screen"; cp "$out/.click.png" "$out/not_found_$1.png"; exit 1; }
  # shellcheck disable=SC2086
  xdotool mousemove $pos sleep 0.3 mousemove_relative 2 0 click 1
  sleep 1.5
}

# click_right_of WORD DX: clicks DX pixels right of the end of the first word WORD that OCR finds
# (the check box of a dialog's parameter, whose label ends in WORD).
click_right_of() {
  import -window root "$out/.click.png"
  /usr/bin/convert "$out/.click.png" -resize 200% "$out/.click2x.png"
  local pos
  pos=$(tesseract "$out/.click2x.png" - --psm 11 tsv 2>/dev/null |
        awk -F'\t' -v w="$1" -v dx="$2" '$12 == w && !found { print int(($7 + $9) / 2) + dx, int(($8 + $10 / 2) / 2); found = 1 }')
  [ -n "$pos" ] || { echo "gui smoke: '$1' not found on screen"; cp "$out/.click.png" "$out/not_found_$1.png"; exit 1; }
  # shellcheck disable=SC2086
  xdotool mousemove $pos sleep 0.3 click 1
  sleep 1
}
