#!/bin/sh
# host-send throughput: raw protocol, P6, paced line. Prints the achieved rate
# as a fraction of the 8N1 limit (baud/10 bytes/s) for several rates.
#
#   bench/host_send/run_bench.sh [BUILD_DIR] [SCENE]
#
# The board is the test stand-in (test/host_send/standin_board.cpp), which
# paces its output in real time at baud/10 bytes/s like a UART; the transfer
# time is measured by host-send as the course does it (first byte sent to
# last pixel received), so it includes the upload and the render start.
# With firmware-sim, --baud paces in simulated time instead, so the real-time
# rate there measures the simulator's speed; that run is informational.
. "$(dirname "$0")/../../scripts/help.sh"
set -eu
BUILD=${1:-build/release}
SCENE=${2:-../shared/scenes/ball.sld}
HS=$BUILD/host/send/host-send
STANDIN=$BUILD/test/host_send/hs_standin_board
[ -x "$HS" ] && [ -x "$STANDIN" ] || { echo "build host-send and hs_standin_board in $BUILD first" >&2; exit 1; }
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
run() {  # baud size [extra...]
  baud=$1; size=$2; shift 2
  line=$("$HS" --sim-binary "$STANDIN" --sim "$STANDIN" --baud "$baud" --size "$size" --format p6 "$@" \
         "$SCENE" -o "$OUT/img.ppm" 2>&1 | grep 'of the 8N1 limit' || true)
  printf '%-8s %-8s %s\n' "$baud" "$size" "${line#host-send: }"
}
echo "baud     size     result (stand-in board, paced)"
run 115200 128x128
run 921600 512x512
run 3000000 512x512
run 1000000 256x256
FWSIM=$BUILD/firmware_sim/firmware-sim
ELF=$BUILD/firmware/minrt-rv32imf.elf
if [ -x "$FWSIM" ] && [ -f "$ELF" ]; then
  echo "firmware-sim (pacing in simulated time; informational):"
  for b in 115200 921600; do
    line=$("$HS" --sim-binary "$FWSIM" --sim "$ELF" --baud "$b" --size 64x64 --format p6 "$SCENE" \
           -o "$OUT/img.ppm" 2>&1 | grep -E 'of the 8N1 limit|error' || true)
    printf '%-8s %-8s %s\n' "$b" 64x64 "${line#host-send: }"
  done
fi
