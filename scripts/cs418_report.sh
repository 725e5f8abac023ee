#!/usr/bin/env bash
# Renders every CS418 test of ../shared/formats/cs418 with minrt (double, and
# float with the portable shims the board uses), compares each with the
# course's reference image (image-compare, SPEC.md 1.6) and writes
#   <test>.png   contact sheets: ours (double) | reference | difference
#   table.md     the figures, one row per test
# into an output folder, by default build/reports/cs418 (printed at the end);
# --write-docs regenerates the tracked docs/cs418/ instead (the table's
# figures differ a little between runs and machines).
# Usage: scripts/cs418_report.sh [--shared DIR] [--out DIR | --write-docs]
# Needs build/release with minrt and image-compare (scripts/test.sh builds them).
. "$(dirname "$0")/help.sh"
. "$(dirname "$0")/common.sh"
set -euo pipefail
report=cs418 what="CS418 tests"
. "$(dirname "$0")/report_setup.sh"
figures() {  # A B -> "off alpha psnr"
  "$bin/image-compare" "$@" | awk '/off by/{o=$5}/alpha mis/{a=$3}/PSNR/{p=$3}END{print o, a, p}'
}
{
  echo "| test | pixels | double: off by > 1 | alpha | block PSNR | float/portable: off by > 1 | block PSNR | path |"
  echo "|---|---|---|---|---|---|---|---|"
  for scene in "$dir"/ray-*.txt; do
    t=$(basename "$scene" .txt)
    "$bin/minrt" -q --stats "$scene" -o "$work/$t.png" 2>"$work/stats"
    "$bin/minrt" -q --precision float --shims portable "$scene" -o "$work/$t-f.png"
    read -r off alpha psnr < <(figures "$work/$t.png" "$dir/$t.png" --sheet "$out/$t.png")
    read -r foff _ fpsnr < <(figures "$work/$t-f.png" "$dir/$t.png")
    pixels=$("$bin/image-compare" "$work/$t.png" "$dir/$t.png" | awk '/^pixels/{print $2}')
    path=$(sed -n 's/.*path \([a-z]*\).*/\1/p' "$work/stats")
    echo "| ${t#ray-} | $pixels | $off | $alpha | $psnr | $foff | $fpsnr | $path |"
  done
} > "$out/table.md"
echo "wrote $out/table.md and $(ls "$out"/ray-*.png | wc -l) contact sheets in $out"
