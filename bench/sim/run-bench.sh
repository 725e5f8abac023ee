#!/bin/sh
# firmware-sim speed benchmark: builds bench/sim/compute.c for rv32imf with
# clang -O2 and runs it (1) plain and (2) with the default cycle model plus
# per-function profiling (callgrind + folded output). Prints host MIPS for
# each, best of N runs (default 3) to damp noise from other processes.
#   bench/sim/run-bench.sh [--sim PATH] [--runs N]
. "$(dirname "$0")/../../scripts/help.sh"
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
sim=$root/build/release/firmware_sim/firmware-sim
runs=3
while [ $# -gt 0 ]; do
  case $1 in
    --sim) sim=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    *) echo "run-bench.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -x "$sim" ] || { echo "run-bench.sh: no firmware-sim at $sim (build target firmware-sim first)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
clang --target=riscv32-unknown-elf -march=rv32imf -mabi=ilp32f -O2 -fno-math-errno -ffreestanding \
  -nostdlib -fuse-ld=lld -mno-relax -I"$root/include" -I"$root/test/sim/firmware" \
  -Wl,-T,"$root/test/sim/firmware/link.ld" "$root/test/sim/firmware/crt0.S" "$root/bench/sim/compute.c" \
  -o "$tmp/compute.elf"

best() {  # best wall-clock and CPU-time MIPS over $runs runs of: firmware-sim --stats "$@"
  b=0
  c=0
  i=0
  while [ $i -lt "$runs" ]; do
    "$sim" --stats "$@" "$tmp/compute.elf" >"$tmp/out" 2>"$tmp/err"
    m=$(sed -n 's/^host MIPS: //p' "$tmp/err")
    u=$(sed -n 's/^host CPU MIPS: \([0-9.]*\).*/\1/p' "$tmp/err")
    b=$(awk -v a="$b" -v x="$m" 'BEGIN { print (x > a) ? x : a }')
    c=$(awk -v a="$c" -v x="$u" 'BEGIN { print (x > a) ? x : a }')
    i=$((i + 1))
  done
  echo "$b MIPS wall-clock, $c MIPS per CPU-second"
}
plain=$(best)
insns=$(sed -n 's/^instructions: //p' "$tmp/err")
timed=$(best --cycle-model default --profile-out "$tmp/cg.out" --folded-out "$tmp/folded.txt")
cycles=$(sed -n 's/^cycles: //p' "$tmp/err")
echo "program: bench/sim/compute.c, $insns instructions, output: $(cat "$tmp/out")"
echo "plain:                 $plain"
echo "cycle model + profile: $timed ($cycles cycles)"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
