#!/bin/sh
# Differential test: run a bare-metal RV32 ELF (UART at 0x10000000, finisher at
# 0x100000, entry in RAM at 0x80000000) on qemu-system-riscv32 -M virt and on
# firmware-sim; the UART bytes and the exit status must be identical.
#   usage: compare-qemu-system.sh FIRMWARE_SIM ELF [TIMEOUT_SECONDS [UART_INPUT_FILE]]
# With UART_INPUT_FILE both receive its bytes on the UART (e.g. a scene for
# the renderer firmware); without, their UART input is empty.
# Exit 0 = same, 1 = different, 77 = skipped (QEMU not installed).
set -u
sim=$1
elf=$2
limit=${3:-120}
input=${4:-/dev/null}
if ! command -v qemu-system-riscv32 >/dev/null 2>&1; then
  echo "SKIP: qemu-system-riscv32 not installed (Debian package qemu-system-misc)"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
timeout "$limit" qemu-system-riscv32 -M virt -bios none -kernel "$elf" -display none -monitor none \
  -serial stdio <"$input" >"$tmp/qemu.out"
qemu_status=$?
timeout "$limit" "$sim" "$elf" <"$input" >"$tmp/sim.out"
sim_status=$?
fail=0
if [ "$qemu_status" -eq 124 ] || [ "$sim_status" -eq 124 ]; then
  echo "FAIL: timeout (qemu $qemu_status, firmware-sim $sim_status)"
  exit 1
fi
if ! cmp -s "$tmp/qemu.out" "$tmp/sim.out"; then
  echo "FAIL: UART output differs"
  diff "$tmp/qemu.out" "$tmp/sim.out" | head -20
  fail=1
fi
if [ "$qemu_status" -ne "$sim_status" ]; then
  echo "FAIL: exit status qemu=$qemu_status firmware-sim=$sim_status"
  fail=1
fi
if [ "$fail" -eq 0 ]; then
  echo "same output ($(wc -c <"$tmp/sim.out") bytes) and exit status $sim_status"
fi
exit $fail
