#!/usr/bin/env bash
# One scene rendered by the RTL harness's CPU through host-send over the
# harness's pseudo-terminal, compared with the host float model:
# the PPM (SLD) and BMP (Jaworski) byte for byte, the PNGs (CS418, miniRT,
# EASTRAY: host-send re-compresses the board's stored stream) pixel for pixel.
#   render_check.sh SEND MINRT COMPARE HARNESS ELF SCENE WORK [SIZE]
set -euo pipefail
send=$1 minrt=$2 compare=$3 harness=$4 elf=$5 scene=$6 work=$7 size=${8:-}
mkdir -p "$work"
file=$(basename "$scene")
name=${file%.*}
case $file in
  *.sld) ext=ppm ;;
  *.rt | *.ray) ext=png ;;
  *) if head -c 4 "$scene" | grep -q '^png'; then ext=png; else ext=bmp; fi ;;
esac
size_args=()
if [[ -n $size ]]; then size_args=(--size "$size"); fi
format_args=()
if [[ $ext == ppm ]]; then format_args=(--format p6); fi
rm -f "$work/$name-rtl.$ext" "$work/$name-host.$ext"
"$send" -q --sim-binary "$harness" --sim "$elf" "${size_args[@]}" "${format_args[@]}" "$scene" -o "$work/$name-rtl.$ext"
if [[ $ext == ppm ]]; then
  "$minrt" -q --precision float --shims portable "${size_args[@]}" --format p6 "$scene" > "$work/$name-host.$ext"
else
  "$minrt" -q --precision float --shims portable "${size_args[@]}" "$scene" -o "$work/$name-host.$ext"
fi
if [[ $ext == png ]]; then
  "$compare" --identical "$work/$name-rtl.$ext" "$work/$name-host.$ext" >/dev/null
else
  cmp "$work/$name-rtl.$ext" "$work/$name-host.$ext"
fi
echo "$name: the RTL CPU's image over host-send and the pty equals the host float model"
