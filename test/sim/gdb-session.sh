#!/bin/sh
# GDB session against firmware-sim --gdb, in batch mode with Debian's
# gdb-multiarch: break at main, continue, step, read registers (integer and
# FP) and memory, break in fw_exit, change a0 (the exit code) and continue to
# the end. The exit code gdb reports and the simulator's status must be the
# changed one. Exit 77 (skipped) when gdb-multiarch is missing.
#   gdb-session.sh FIRMWARE_SIM TEST_FIRMWARE_ELF
set -u
sim=$1 elf=$2
gdb=$(command -v gdb-multiarch) || { echo "gdb-session.sh: gdb-multiarch not installed: skipped"; exit 77; }
work=$(mktemp -d "${TMPDIR:-/tmp}/fwsim-gdb.XXXXXX")
trap 'rm -rf "$work"' EXIT

"$sim" --gdb 0 "$elf" -- exit 3 2>"$work/sim.err" &
sim_pid=$!
port=
for _ in $(seq 100); do
  port=$(sed -n 's/^firmware-sim: waiting for gdb on 127\.0\.0\.1:\([0-9][0-9]*\)$/\1/p' "$work/sim.err")
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { echo "no 'waiting for gdb' line from firmware-sim:"; cat "$work/sim.err"; kill "$sim_pid"; exit 1; }

timeout 120 "$gdb" -batch -nx \
  -ex "target remote 127.0.0.1:$port" \
  -ex "break main" -ex "continue" \
  -ex "x/4cb argv[1]" \
  -ex "stepi" -ex "info registers pc" \
  -ex "next" \
  -ex "info registers ft0 fcsr" \
  -ex "break fw_exit" -ex "continue" \
  -ex "info registers a0" \
  -ex 'set var $a0 = 5' \
  -ex "continue" \
  "$elf" >"$work/gdb.out" 2>&1
gdb_status=$?
wait "$sim_pid"
sim_status=$?

fail=0
expect() {  # expect REGEX WHAT
  grep -Eq "$1" "$work/gdb.out" || { echo "FAIL: $2 (no line matching: $1)"; fail=1; }
}
expect '^Breakpoint 1, main \(argc=3, argv=0x[0-9a-f]+\)' "stopped at main with argc 3"
expect "^0x[0-9a-f]+:[[:space:]]+101 'e'[[:space:]]+120 'x'[[:space:]]+105 'i'[[:space:]]+116 't'" "memory read of argv[1]"
expect '^pc[[:space:]]+0x8[0-9a-f]{7}[[:space:]]+0x8[0-9a-f]{7} <' "pc after stepi"
expect '^ft0[[:space:]]+0[[:space:]]+\(raw 0x00000000\)' "FP register read"
expect '^fcsr[[:space:]]+0x0[[:space:]]' "fcsr read"
expect '^Breakpoint 2, fw_exit \(code=3\)' "stopped at fw_exit with code 3"
expect '^a0[[:space:]]+0x3[[:space:]]+3$' "a0 read"
expect '^\[Inferior 1 \(.*\) exited with code 05\]' "exit code 5 (a0 written) reported"
[ "$gdb_status" -eq 0 ] || { echo "FAIL: gdb exited with $gdb_status"; fail=1; }
[ "$sim_status" -eq 5 ] || { echo "FAIL: firmware-sim exited with $sim_status, expected 5"; fail=1; }
if [ "$fail" -ne 0 ]; then
  echo "--- gdb output"; cat "$work/gdb.out"; echo "--- firmware-sim stderr"; cat "$work/sim.err"
  exit 1
fi
echo "gdb session: break, step, registers, memory, register write, exit code 5: ok"
