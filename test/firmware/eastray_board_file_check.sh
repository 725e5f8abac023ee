#!/usr/bin/env bash
# host-send writes the board's EASTRAY image as minrt writes its own: the
# scene (test/eastray/scenes/board_tiff_window.ray: output_mode 16 with
# dither, a window of columns 0-31) into a new TIFF, then its other half
# (columns 32-63) into the same file, which keeps the first half. Each time
# host-send's file must be minrt's (--precision float --shims portable),
# byte for byte, and the two halves the whole image's.
# Usage: eastray_board_file_check.sh SIM FIRMWARE HOST_SEND MINRT SCENE WORKDIR
set -euo pipefail
sim=$1 fw=$2 send=$3 minrt=$4 scene=$5 work=$6
mkdir -p "$work"
rm -f "$work/fw.tif" "$work/host.tif"
sed 's/^display 64 48 0 0 31 47 /display 64 48 32 0 63 47 /' "$scene" >"$work/right.ray"
grep -q '^display 64 48 32 0 63 47 ' "$work/right.ray"
for half in "$scene" "$work/right.ray"; do
  "$send" -q --sim-binary "$sim" --sim "$fw" "$half" -o "$work/fw.tif"
  "$minrt" -q --precision float --shims portable "$half" -o "$work/host.tif"
  cmp "$work/fw.tif" "$work/host.tif"
done
# The two windows make the whole image.
sed 's/^display 64 48 0 0 31 47 /display 64 48 0 0 63 47 /' "$scene" >"$work/whole.ray"
rm -f "$work/whole.tif"
"$minrt" -q --precision float --shims portable "$work/whole.ray" -o "$work/whole.tif"
cmp "$work/fw.tif" "$work/whole.tif"
echo "board_tiff_window: host-send's TIFF, both windows, byte for byte minrt's"
