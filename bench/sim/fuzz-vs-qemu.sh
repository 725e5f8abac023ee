#!/bin/sh
# Differential fuzzing of firmware-sim against qemu-riscv32 (QEMU user mode):
# random RV32IMF programs (test/sim/fuzz/fuzz_gen.cpp) run on both; the dumps
# of all registers and fcsr must be identical.
#
#   bench/sim/fuzz-vs-qemu.sh [--seed N] [--count M] [--sim PATH] [--gen PATH] [--work DIR]
#
# Defaults: seed 1, count 200, binaries from build/release/ (scripts/setup.sh). CI runs it through
# ctest with --seed 1 --count 40. Exit 0 = all equal, 1 = a mismatch (the
# program is kept in the work dir), 77 = skipped (qemu-riscv32 or clang absent).
. "$(dirname "$0")/../../scripts/help.sh"
. "$(dirname "$0")/../../scripts/common.sh"
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
seed=1
count=200
sim=$root/build/release/firmware_sim/firmware-sim
gen=$root/build/release/test/sim/fwsim-fuzzgen
work=
script_options "--seed seed" "--count count" "--sim sim" "--gen gen" "--work work" -- "$@"
for tool in qemu-riscv32 clang ld.lld; do
  if ! command -v $tool >/dev/null 2>&1; then
    echo "SKIP: $tool not installed (Debian packages qemu-user, clang, lld)"
    exit 77
  fi
done
[ -x "$sim" ] || { echo "fuzz-vs-qemu.sh: no firmware-sim at $sim (build it first)" >&2; exit 2; }
[ -x "$gen" ] || { echo "fuzz-vs-qemu.sh: no fwsim-fuzzgen at $gen (build it first)" >&2; exit 2; }
[ -n "$work" ] || work=$(mktemp -d)
mkdir -p "$work"
fuzz=$root/test/sim/fuzz
flags="-march=rv32imf -mabi=ilp32f -nostdlib -fuse-ld=lld -mno-relax"
names="ra t0 t1 t2 s0 s1 a0 a1 a2 a3 a4 a5 a6 a7 s2 s3 s4 s5 s6 s7 s8 s9 s10 t3 t4 t5 t6"
i=0
while [ $i -lt "$count" ]; do
  s=$((seed + i))
  body=$work/body_$s.S
  "$gen" $s "$body" || exit 1
  clang --target=riscv32-unknown-linux-gnu $flags -static "$fuzz/linux_main.S" "$body" -o "$work/linux.elf" || exit 1
  clang --target=riscv32-unknown-elf $flags -Wl,-T,"$root/test/sim/firmware/link.ld" \
    "$fuzz/bare_main.S" "$body" -o "$work/bare.elf" || exit 1
  qemu-riscv32 "$work/linux.elf" >"$work/qemu.bin" || { echo "seed $s: qemu-riscv32 failed"; exit 1; }
  "$sim" "$work/bare.elf" >"$work/sim.bin" </dev/null || { echo "seed $s: firmware-sim failed"; exit 1; }
  if ! cmp -s "$work/qemu.bin" "$work/sim.bin"; then
    echo "MISMATCH for seed $s (program: $body)"
    od -An -v -tx4 -w4 "$work/qemu.bin" >"$work/qemu.txt"
    od -An -v -tx4 -w4 "$work/sim.bin" >"$work/sim.txt"
    labels=$(for n in $names; do echo $n; done; k=0; while [ $k -lt 32 ]; do echo f$k; k=$((k + 1)); done; echo fcsr)
    echo "$labels" | paste - "$work/qemu.txt" "$work/sim.txt" | awk '$2 != $3 { print "  " $1 ": qemu " $2 "  firmware-sim " $3 }'
    exit 1
  fi
  rm -f "$body"
  i=$((i + 1))
done
echo "$count random programs (seeds $seed..$((seed + count - 1))): firmware-sim matches qemu-riscv32"
