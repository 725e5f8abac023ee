#!/usr/bin/env bash
# Memory footprint of the firmware rendering a scene in firmware-sim:
# code, read-only data, data, bss, arena (size and use), stack (size and the
# measured high-water mark), and whether it all fits the 4 MiB RAM.
#   bench/firmware/footprint.sh [SCENE [WxH]]     (default contest.sld 512x512)
# The firmware's --footprint mode renders as usual, discards the image and
# prints its own report instead (runtime/footprint.cpp).
. "$(dirname "$0")/../../scripts/help.sh"
set -euo pipefail
source "$(dirname "$0")/common.sh"
scene=$(scene_path "${1:-contest.sld}")
size=${2:-512x512}

report=$("$sim" --uart-in "$scene" "$MINRT_FIRMWARE" -- --size "$size" --footprint)
declare -A v
while read -r key value; do v[$key]=$value; done <<<"$report"

ram=$((4 * 1024 * 1024))
reserve=$((ram - v[text] - v[rodata] - v[data] - v[bss] - v[arena] - v[stack]))
echo "firmware: $MINRT_FIRMWARE"
echo "scene:    $scene at $size (${v[image_bytes]} image bytes)"
printf '  %-18s %9d bytes\n' \
  "code (.text)" "${v[text]}" \
  "rodata" "${v[rodata]}" \
  "data" "${v[data]}" \
  "bss" "${v[bss]}" \
  "arena" "${v[arena]}" \
  "  arena used" "${v[arena_used]}" \
  "stack" "${v[stack]}" \
  "  stack high water" "${v[stack_high_water]}" \
  "boot args + align" "$reserve"
used=$((v[text] + v[rodata] + v[data] + v[bss] + v[arena_used] + v[stack_high_water]))
printf '  %-18s %9d bytes of %d (%d%%)\n' "really used" "$used" "$ram" $((used * 100 / ram))
if ((v[stack_high_water] > v[stack] || reserve < 0)); then
  echo "DOES NOT FIT" >&2
  exit 1
fi
