#!/usr/bin/env bash
# Compiles the core for a bare RV32 target with each math policy, lists its
# undefined symbols and links it against stubs of exactly the documented
# externals (docs/architecture.md). Any other undefined symbol fails the link.
set -euo pipefail
clangxx=$1 lld=$2 nm=$3 src=$4 out=$5
mkdir -p "$out"
common=(-std=c++20 -O2 -ffreestanding -nostdlib -fno-exceptions -fno-rtti -ffp-contract=off
        -I"$src" -I"$src/include")
# memcpy/memset/memmove: struct copies; __udivdi3: the 64-bit division of a
# CS418 pixel's alpha (hits * 255 / samples past 2^32/255 samples).
mem="memcpy memset memmove __udivdi3"
check() {  # name march mabi policy allowed-symbols...
  local name=$1 march=$2 mabi=$3 policy=$4; shift 4
  local allowed="$* $mem"
  "$clangxx" --target=riscv32-unknown-elf -march="$march" -mabi="$mabi" "${common[@]}" \
    -DPOLICY="$policy" -c "$src/test/core/freestanding_entry.cpp" -o "$out/$name.o"
  local undefined
  undefined=$("$nm" -u "$out/$name.o" | awk '{print $2}' | sort)
  echo "$name ($march/$mabi, $policy) needs: $(echo $undefined)"
  for sym in $undefined; do
    case " $allowed " in *" $sym "*) ;; *) echo "FAIL: $name needs undocumented symbol $sym"; exit 1;; esac
  done
  # Stubs for the allowed externals, then a real link with no unresolved symbol.
  { for sym in $allowed; do echo "void $sym(void) {}"; done; } > "$out/$name-stubs.c"
  "$clangxx" --target=riscv32-unknown-elf -march="$march" -mabi="$mabi" -x c -O2 -ffreestanding \
    -c "$out/$name-stubs.c" -o "$out/$name-stubs.o"
  "$lld" -m elf32lriscv --entry=minrt_entry "$out/$name.o" "$out/$name-stubs.o" -o "$out/$name.elf"
}
check portable rv32imf ilp32f minrt::PortableFloat
check portable-fast rv32imf ilp32f minrt::PortableFloatFast
check libm-float rv32imf ilp32f minrt::LibmFloat sqrtf floorf sinf cosf atanf atan2f expf logf
check libm-double rv32imfd ilp32d minrt::LibmDouble sqrt floor sin cos atan atan2 exp log
check portable-softfloat rv32im ilp32 minrt::PortableFloat \
  __addsf3 __subsf3 __mulsf3 __divsf3 __eqsf2 __nesf2 __ltsf2 __lesf2 __gtsf2 __gesf2 __unordsf2 \
  __floatsisf __floatunsisf
echo "freestanding link check passed"
