#!/usr/bin/env bash
# Dynamic instruction count and modelled cycles of the firmware for a scene at
# one or more sizes, plus a per-function profile of the first size.
#   bench/firmware/count.sh [SCENE [WxH ...]]   (default contest.sld 128x128 512x512)
#   bench/firmware/count.sh --isa [SCENE [WxH]] (default contest.sld 128x128)
# --isa: one table row per ISA variant of the reference board (rv32i,
# rv32im, rv32imf: minrt-<isa>.elf in the build's firmware/), with the
# instruction count, cycles and the output's sha256 (the same image from
# each). Needs valgrind's callgrind_annotate for the profile table.
. "$(dirname "$0")/../../scripts/help.sh"
set -euo pipefail
source "$(dirname "$0")/common.sh"

if [[ ${1:-} == --isa ]]; then
  shift
  scene=$(scene_path "${1:-contest.sld}")
  size=${2:-128x128}
  printf '%-8s %15s %15s  %s\n' isa instructions cycles "image sha256"
  for isa in rv32i rv32im rv32imf; do
    elf=$MINRT_BUILD_DIR/firmware/minrt-$isa.elf
    [[ -e $elf ]] || { echo "missing $elf (build the firmware target)" >&2; exit 1; }
    out=$(mktemp)
    stats=$("$sim" --stats --cycle-model default --uart-in "$scene" --uart-out "$out" "$elf" -- --size "$size" 2>&1)
    n=$(sed -n 's/^instructions: *//p' <<<"$stats" | tr -d ,)
    c=$(sed -n 's/^cycles: *//p' <<<"$stats" | tr -d ,)
    printf '%-8s %15s %15s  %s\n' "$isa" "$n" "$c" "$(sha256sum <"$out" | cut -c1-16)"
    rm -f "$out"
  done
  exit 0
fi
scene=$(scene_path "${1:-contest.sld}")
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(128x128 512x512)
out=${MINRT_BENCH_OUT:-$MINRT_BUILD_DIR/bench-firmware}
mkdir -p "$out"
name=$(basename "$scene" .sld)

for size in "${sizes[@]}"; do
  prof=()
  [[ $size == "${sizes[0]}" ]] && prof=(--profile-out "$out/$name-$size.callgrind")
  echo "== $name $size: $MINRT_FIRMWARE"
  "$sim" --stats --cycle-model default "${prof[@]}" --uart-in "$scene" \
    --uart-out "$out/$name-$size.ppm" "$MINRT_FIRMWARE" -- --size "$size" 2>&1 |
    grep -E '^(instructions|cycles|CPI|host MIPS|clock):'
done

if command -v callgrind_annotate >/dev/null; then
  echo "== per-function profile, $name ${sizes[0]} (self instructions, self cycles)"
  callgrind_annotate "$out/$name-${sizes[0]}.callgrind" | c++filt |
    sed -n '/file:function/,$p' | sed -e 's/ \[[^]]*\]$//' -e 's/???://' | head -25
else
  echo "callgrind_annotate not found; profile in $out/$name-${sizes[0]}.callgrind"
fi
