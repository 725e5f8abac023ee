#!/usr/bin/env bash
# minrt --show under Xvfb: what the window shows (MINRT_SHOW_SNAPSHOT reads
# it back after the first frame) equals the rendered image, for a Jaworski
# and a CS418 scene and a miniRT one (window only, as its subject wants); without a display it warns in one line, exits 0 and
# still writes the file.
# SLD with -o and host-send --show (the board's image) are checked the same way.
# Usage: window_check.sh MINRT IMAGE_COMPARE SHARED_DIR WORKDIR [HOST_SEND]
set -euo pipefail
minrt=$1 compare=$2 shared=$3 work=$4 host_send=${5:-}
mkdir -p "$work"
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
rm -f "$work/nodisplay.bmp"
err=$(env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$minrt" --show "$jw" -o "$work/nodisplay.bmp" 2>&1)
[ "$err" = "minrt: warning: not showing the image: no display (DISPLAY is not set)" ] || { echo "unexpected: $err"; exit 1; }
[ -s "$work/nodisplay.bmp" ]
echo "window shows the rendered images; without a display the file is still written"
