#!/bin/sh
# Error of FPU-model configurations as measured by `firmware-sim --fpu-check`,
# as the markdown table in docs/firmware_sim.md ("Measured errors").
#   bench/sim/fpu-check-table.sh [--sim PATH]
. "$(dirname "$0")/../../scripts/help.sh"
. "$(dirname "$0")/../../scripts/common.sh"
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
sim=$root/build/release/firmware_sim/firmware-sim
script_options "--sim sim" -- "$@"
[ -x "$sim" ] || { echo "fpu-check-table.sh: no firmware-sim at $sim" >&2; exit 2; }

# op (as --fpu-check prints it) and --fpu settings, one configuration a line.
configs="fdiv div=recip-mul,recip_table_bits=16,recip_newton_steps=0
fdiv div=recip-mul,recip_table_bits=8,recip_newton_steps=1
fdiv div=recip-mul,recip_table_bits=9,recip_newton_steps=1
fdiv div=recip-mul,recip_table_bits=10,recip_newton_steps=1
fdiv div=recip-mul,recip_table_bits=10,recip_newton_steps=1,recip_entry_bits=12
fdiv div=recip-mul,recip_table_bits=11,recip_newton_steps=1
fdiv div=recip-mul,recip_table_bits=4,recip_newton_steps=2
fdiv div=recip-mul,recip_table_bits=5,recip_newton_steps=2
fdiv div=recip-mul,recip_table_bits=10,recip_newton_steps=1,mul=truncate,add=truncate
fsqrt sqrt=table-newton,rsqrt_table_bits=16,rsqrt_newton_steps=0
fsqrt sqrt=table-newton,rsqrt_table_bits=8,rsqrt_newton_steps=1
fsqrt sqrt=table-newton,rsqrt_table_bits=9,rsqrt_newton_steps=1
fsqrt sqrt=table-newton,rsqrt_table_bits=10,rsqrt_newton_steps=1
fsqrt sqrt=table-newton,rsqrt_table_bits=11,rsqrt_newton_steps=1
fsqrt sqrt=table-newton,rsqrt_table_bits=6,rsqrt_newton_steps=2
fmul mul=truncate
fadd add=truncate
fdiv subnormals=flush
fdiv div=recip-mul,subnormals=flush"

echo "| op | \`--fpu\` | max error | rule | result |"
echo "|---|---|---:|---:|---|"
echo "$configs" | while read -r op fpu; do
  line=$("$sim" --fpu "$fpu" --fpu-check | grep "^$op " || true)
  [ -n "$line" ] || { echo "fpu-check-table.sh: no $op line for $fpu" >&2; exit 1; }
  # Columns from the end: ... max-error rule result.
  set -- $line
  shift $(($# - 3))
  echo "| $op | \`$fpu\` | $1 | $2 | $3 |"
done
