#!/bin/sh
# firmware-sim speed benchmark on the renderer firmware: runs the same ELF
# (1) plain, (2) with the default cycle model plus per-function profiling
# (callgrind + folded output), (3) in qemu-system-riscv32 -M virt when
# installed, and with --old PATH (4, 5) an older firmware-sim build the same
# two ways, interleaved round by round so machine load hits all alike.
# Prints MIPS per CPU-second (best of N rounds, default 3) and the CPU model.
#   bench/sim/run-bench.sh [--sim PATH] [--old PATH] [--elf ELF] [--scene FILE] [--runs N] [--compute]
# --compute runs bench/sim/compute.c (built with clang) instead of the renderer.
. "$(dirname "$0")/../../scripts/help.sh"
. "$(dirname "$0")/../../scripts/common.sh"
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
sim=$root/build/release/firmware_sim/firmware-sim
elf=$root/build/release/firmware/minrt-rv32imf.elf
scene=$root/../shared/scenes/ball.sld
old=
runs=3
compute=0
script_options "--sim sim" "--old old" "--elf elf" "--scene scene" "--runs runs" "--compute compute=1" -- "$@"
[ -x "$sim" ] || { echo "run-bench.sh: no firmware-sim at $sim (build target firmware-sim first)" >&2; exit 2; }
[ -z "$old" ] || [ -x "$old" ] || { echo "run-bench.sh: no firmware-sim at $old" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ "$compute" = 1 ]; then
  clang --target=riscv32-unknown-elf -march=rv32imf -mabi=ilp32f -O2 -fno-math-errno -ffreestanding \
    -nostdlib -fuse-ld=lld -mno-relax -I"$root/include" -I"$root/test/sim/firmware" \
    -Wl,-T,"$root/test/sim/firmware/link.ld" "$root/test/sim/firmware/crt0.S" "$root/bench/sim/compute.c" \
    -o "$tmp/program.elf"
  elf=$tmp/program.elf
  scene=/dev/null
  what="bench/sim/compute.c"
else
  [ -f "$elf" ] || { echo "run-bench.sh: no renderer firmware at $elf (build target firmware-rv32imf first)" >&2; exit 2; }
  [ -f "$scene" ] || { echo "run-bench.sh: no scene $scene" >&2; exit 2; }
  what="renderer $(basename "$elf") on $(basename "$scene") (default size)"
fi

# sim_mips NAME BINARY [OPTIONS]: one run; keeps the best MIPS per CPU-second in $tmp/NAME.best.
sim_mips() {
  name=$1 bin=$2
  shift 2
  "$bin" --stats "$@" --uart-in "$scene" --uart-out "$tmp/$name.out" "$elf" 2>"$tmp/$name.err" || true
  u=$(sed -n 's/^host CPU MIPS: \([0-9.]*\).*/\1/p' "$tmp/$name.err")
  [ -n "$u" ] || { echo "run-bench.sh: $bin gave no statistics:" >&2; cat "$tmp/$name.err" >&2; exit 1; }
  b=$(cat "$tmp/$name.best" 2>/dev/null || echo 0)
  awk -v a="$b" -v x="$u" 'BEGIN { print (x > a) ? x : a }' >"$tmp/$name.best"
}
timed="--cycle-model default --profile-out $tmp/cg.out --folded-out $tmp/folded.txt"
qemu=$(command -v qemu-system-riscv32 || true)
i=0
while [ $i -lt "$runs" ]; do
  sim_mips plain "$sim"
  # shellcheck disable=SC2086
  sim_mips timed "$sim" $timed
  if [ -n "$old" ]; then
    sim_mips old_plain "$old"
    # shellcheck disable=SC2086
    sim_mips old_timed "$old" $timed
  fi
  if [ -n "$qemu" ]; then
    # CPU seconds of QEMU itself (user + system), start-up included.
    /usr/bin/time -f '%U %S' -o "$tmp/qemu.time" timeout 600 "$qemu" -M virt -bios none -kernel "$elf" \
      -display none -monitor none -serial stdio <"$scene" >"$tmp/qemu.out" || true
    s=$(awk '{ print $1 + $2 }' "$tmp/qemu.time" | tail -1)
    b=$(cat "$tmp/qemu.best" 2>/dev/null || echo 0)
    awk -v a="$b" -v x="$s" 'BEGIN { print (a == 0 || x < a) ? x : a }' >"$tmp/qemu.best"
  fi
  i=$((i + 1))
done
insns=$(sed -n 's/^instructions: //p' "$tmp/plain.err")
cycles=$(sed -n 's/^cycles: //p' "$tmp/timed.err")
plain=$(cat "$tmp/plain.best")
tm=$(cat "$tmp/timed.best")
echo "program: $what, $insns instructions"
echo "cpu: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1), load average $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
echo "MIPS per CPU-second, best of $runs interleaved rounds:"
echo "firmware-sim plain:                 $plain"
echo "firmware-sim cycle model + profile: $tm ($cycles cycles; $(awk -v p="$plain" -v t="$tm" 'BEGIN { printf "%.2f", p / t }')x the plain time)"
if [ -n "$old" ]; then
  op=$(cat "$tmp/old_plain.best")
  ot=$(cat "$tmp/old_timed.best")
  echo "old build plain:                    $op (new/old $(awk -v a="$plain" -v b="$op" 'BEGIN { printf "%.2f", a / b }'))"
  echo "old build cycle model + profile:    $ot (new/old $(awk -v a="$tm" -v b="$ot" 'BEGIN { printf "%.2f", a / b }'))"
fi
if [ -n "$qemu" ]; then
  qs=$(cat "$tmp/qemu.best")
  same=$(cmp -s "$tmp/qemu.out" "$tmp/plain.out" && echo "same output" || echo "OUTPUT DIFFERS")
  echo "qemu-system-riscv32 (TCG):          $(awk -v n="$insns" -v s="$qs" 'BEGIN { printf "%.1f", (s > 0) ? n / s / 1e6 : 0 }') ($qs CPU s, $same)"
else
  echo "qemu-system-riscv32:                not installed"
fi
