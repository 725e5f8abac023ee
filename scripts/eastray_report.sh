#!/usr/bin/env bash
# Renders every EASTRAY scene of ../shared/formats/eastray with minrt in
# double and in float with the portable shims the board uses, and writes
#   <scene>.png       contact sheets: double | float/portable | difference
#   table.md          the figures, one row per scene
#   own-<scene>.png   the same sheets for test/eastray/scenes (mapping, bump,
#                     anisotropy, stereo: the right image, background)
# into an output folder, by default build/reports/eastray (printed at the end);
# --write-docs regenerates the tracked docs/eastray/ instead (the table's
# timings differ between runs and machines).
# There is no reference renderer: the sheets are for looking at (the README
# of the scenes says what each must show; test/eastray/eastray_test.cpp
# probes it).
# Usage: scripts/eastray_report.sh [--shared DIR] [--out DIR | --write-docs]
# Needs build/release with minrt and image-compare (scripts/test.sh builds them).
. "$(dirname "$0")/help.sh"
. "$(dirname "$0")/common.sh"
set -euo pipefail
report=eastray what="EASTRAY scenes"
. "$(dirname "$0")/report_setup.sh"
{
  echo "| scene | double ms | float/portable: pixels off by > 1 | largest channel error | block PSNR |"
  echo "|---|---|---|---|---|"
  for scene in "$dir"/*.ray; do
    t=$(basename "$scene" .ray)
    start=$(date +%s%N)
    "$bin/minrt" -q "$scene" -o "$work/$t.png"
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    "$bin/minrt" -q --precision float --shims portable "$scene" -o "$work/$t-f.png"
    read -r off maxerr psnr < <("$bin/image-compare" "$work/$t.png" "$work/$t-f.png" --sheet "$out/$t.png" |
      awk '/off by/{o=$5}/max channel/{m=$4}/PSNR/{p=$3}END{print o, m, p}')
    echo "| $t | $ms | $off | $maxerr | $psnr |"
  done
} > "$out/table.md"
# Our own scenes (their maps lie beside them; rmode 1 writes NAME_r, NAME_l).
own=$root/test/eastray/scenes
for scene in "$own"/*.ray; do
  t=$(basename "$scene" .ray)
  (cd "$own" && "$bin/minrt" -q "$t.ray" -o "$work/own-$t.png" &&
     "$bin/minrt" -q --precision float --shims portable "$t.ray" -o "$work/own-$t-f.png")
  a=$work/own-$t.png b=$work/own-$t-f.png
  [ -f "$a" ] || { a=$work/own-${t}_r.png; b=$work/own-$t-f_r.png; }
  "$bin/image-compare" "$a" "$b" --sheet "$out/own-$t.png" > /dev/null || true
done
echo "wrote $out/table.md and $(ls "$out"/*.png | wc -l) contact sheets in $out"
