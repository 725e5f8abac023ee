#!/usr/bin/env bash
# minrt --show under Xvfb: what the window shows once the image is complete
# (MINRT_SHOW_SNAPSHOT reads it back) equals the rendered image, for a
# Jaworski, a CS418 and an SLD scene and for host-send's image from the
# simulated board; mid-render (MINRT_SHOW_PARTIAL_SNAPSHOT, with every row
# hand-over slowed by MINRT_SHOW_ROW_DELAY_MS) it shows some rows drawn and
# the rest background, for every format (SLD on one thread, through its PPM
# bytes, and on two) and for the board's rows as they arrive; without a display it warns in one line, exits 0 and still writes
# the file (also miniRT and EASTRAY). A miniRT scene shows its window without
# -o, as its subject wants.
# Usage: window_check.sh MINRT IMAGE_COMPARE SHARED_DIR WORKDIR [HOST_SEND]
set -euo pipefail
minrt=$1 compare=$2 shared=$3 work=$4 host_send=${5:-}
rows_check=$(dirname "$0")/window_rows_check.py
mkdir -p "$work"
# live NAME PROGRAM ARGS...: a mid-render and a final snapshot of one run.
live() {
  local name=$1
  shift
  rm -f "$work/$name-partial.ppm" "$work/$name-final.ppm"
  MINRT_SHOW_ROW_DELAY_MS=${DELAY:-15} MINRT_SHOW_PARTIAL_SNAPSHOT=$work/$name-partial.ppm \
    MINRT_SHOW_SNAPSHOT=$work/$name-final.ppm xvfb-run -a "$@"
  python3 "$rows_check" "$work/$name-partial.ppm" "$work/$name-final.ppm"
}
jw=$shared/formats/jaworski/mixed-nested-deep.txt
cs=$shared/formats/cs418/ray-shadow-plane.txt
MINRT_SHOW_SNAPSHOT=$work/jw-window.ppm xvfb-run -a "$minrt" --show "$jw" -o "$work/jw.bmp"
"$compare" --identical "$work/jw-window.ppm" "$work/jw.bmp" >/dev/null
# CS418: the window shows transparency over black; ray-shadow-plane's alpha
# is 0 or 255, so the PPM (alpha dropped) is exactly what it should show.
MINRT_SHOW_SNAPSHOT=$work/cs-window.ppm xvfb-run -a "$minrt" --show "$cs" -o "$work/cs.ppm"
"$compare" --identical "$work/cs-window.ppm" "$work/cs.ppm" >/dev/null
MINRT_SHOW_SNAPSHOT=$work/sld-window.ppm xvfb-run -a "$minrt" --size 48x32 --format p6 --show \
  -o "$work/sld.ppm" "$shared/scenes/contest.sld"
"$compare" --identical "$work/sld-window.ppm" "$work/sld.ppm" >/dev/null
if [ -n "$host_send" ]; then
  MINRT_SHOW_SNAPSHOT=$work/board-window.ppm xvfb-run -a "$host_send" -q --sim --show "$jw" -o "$work/board.bmp"
  "$compare" --identical "$work/board-window.ppm" "$work/board.bmp" >/dev/null
fi
# miniRT: the subject's mode, the window without -o, shows the rendered image.
rt=$shared/formats/minirt/valid/showcase.rt
MINRT_SHOW_SNAPSHOT=$work/rt-window.ppm xvfb-run -a "$minrt" --size 160x120 "$rt"
"$minrt" --size 160x120 "$rt" -o "$work/rt.ppm"
"$compare" --identical "$work/rt-window.ppm" "$work/rt.ppm" >/dev/null
# Rows appear as they are rendered (two threads: out of order) or arrive.
live jw-live "$minrt" --threads 2 --show "$jw" -o "$work/jw-live.bmp"
"$compare" --identical "$work/jw-live-final.ppm" "$work/jw-live.bmp" >/dev/null
live cs-live "$minrt" --threads 2 --show "$cs" -o "$work/cs-live.ppm"
"$compare" --identical "$work/cs-live-final.ppm" "$work/cs-live.ppm" >/dev/null
live sld-live "$minrt" --size 64x96 --show -o "$work/sld-live.ppm" "$shared/scenes/contest.sld"
"$compare" --identical "$work/sld-live-final.ppm" "$work/sld-live.ppm" >/dev/null
live sld1-live "$minrt" --threads 1 --size 64x96 --show -o "$work/sld1-live.ppm" "$shared/scenes/contest.sld"
"$compare" --identical "$work/sld1-live-final.ppm" "$work/sld1-live.ppm" >/dev/null
live rt-live "$minrt" --size 160x120 --threads 2 --show -o "$work/rt-live.ppm" "$shared/formats/minirt/valid/showcase.rt"
"$compare" --identical "$work/rt-live-final.ppm" "$work/rt-live.ppm" >/dev/null
live ray-live "$minrt" --show -o "$work/ray-live.png" "$shared/formats/eastray/basic_sphere_floor_elight.ray"
"$compare" --identical "$work/ray-live-final.ppm" "$work/ray-live.png" >/dev/null
if [ -n "$host_send" ]; then
  DELAY=1 live board-live "$host_send" -q --sim --show "$jw" -o "$work/board-live.bmp"
  "$compare" --identical "$work/board-live-final.ppm" "$work/board-live.bmp" >/dev/null
  # The board's PNG (stored deflate, one block a row) and its PPM, followed as they arrive.
  DELAY=1 live board-png-live "$host_send" -q --sim --show "$cs" -o "$work/board-live.png"
  # (the board renders as the host's float model; the PPM drops alpha, which is 0 or 255 here)
  "$minrt" --precision float --shims portable "$cs" -o "$work/board-model.ppm"
  "$compare" --identical "$work/board-png-live-final.ppm" "$work/board-model.ppm" >/dev/null
  DELAY=1 live board-ppm-live "$host_send" -q --sim --show --size 64x48 "$shared/scenes/contest.sld" \
    -o "$work/board-live.ppm"
  "$compare" --identical "$work/board-ppm-live-final.ppm" "$work/board-live.ppm" >/dev/null
fi
rm -f "$work/nodisplay.bmp"
err=$(env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$minrt" --show "$jw" -o "$work/nodisplay.bmp" 2>&1)
[ "$err" = "minrt: warning: not showing the image: no display (DISPLAY is not set)" ] || { echo "unexpected: $err"; exit 1; }
[ -s "$work/nodisplay.bmp" ]
echo "window shows the rendered images; without a display the file is still written"
