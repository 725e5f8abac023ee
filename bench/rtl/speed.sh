#!/bin/sh
# Simulated speed of the RTL harness with the reference core: ball.sld at
# SIZE (default 16x16) from a file on the register-level UART, and the same
# with lock-step checking. Prints the harness's report (cycles, retired
# instructions, CPI, wall and CPU seconds, simulated MHz per CPU second:
# the wall time also counts the waits for input and a loaded machine).
#
#   bench/rtl/speed.sh [BUILD_DIR] [SIZE]
. "$(dirname "$0")/../../scripts/help.sh"
set -eu
BUILD=${1:-build/release}
SIZE=${2:-16x16}
RTL=$BUILD/rtl/minrt-rtl
ELF=$BUILD/firmware/minrt-rtl-reference.elf
SCENE=$(dirname "$0")/../../../shared/scenes/ball.sld
[ -x "$RTL" ] && [ -f "$ELF" ] || { echo "build minrt-rtl and firmware-rtl-reference in $BUILD first" >&2; exit 1; }
run() {  # label [options...]
  label=$1; shift
  report=$("$RTL" "$@" --uart-in "$SCENE" --uart-out /dev/null "$ELF" -- --size "$SIZE" --format p6 2>&1 >/dev/null |
           grep -E '^minrt-rtl: [0-9]+ cycles')
  echo "$label ${report#minrt-rtl: }"
}
echo "ball.sld $SIZE on the reference core (rtl/core/minrt_ref_core.sv):"
run "harness  "
run "lock-step" --lockstep
