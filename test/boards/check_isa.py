#!/usr/bin/env python3
"""Checks which RISC-V instruction groups a firmware ELF uses.

  check_isa.py LLVM-OBJDUMP ELF --forbid GROUP... | --require GROUP...

GROUP: m (multiply/divide), f (single/double float, FP CSR access), csr
(Zicsr: csrr*/csrw*/csrs*/csrc*, fscsr/frcsr and friends), fencei
(Zifencei: fence.i). The ELF is
disassembled with every extension enabled, so an instruction the ELF's own
attributes would not name is still decoded.
"""
import re
import subprocess
import sys

GROUPS = {
    "m": re.compile(r"^(mul|mulh|mulhu|mulhsu|div|divu|rem|remu)$"),
    "f": re.compile(r"^(f(?!ence)[a-z0-9]*(\.[a-z0-9]+)*|c\.f(lw|sw|lwsp|swsp|ld|sd|ldsp|sdsp))$"),
    "fencei": re.compile(r"^fence\.i$"),
    "csr": re.compile(r"^(csr[a-z]*|fscsr|frcsr|fsrm|frrm|fsflags|frflags|fsrmi|fsflagsi|rdcycle|rdtime|rdinstret)$"),
}


def main() -> int:
    if len(sys.argv) < 5 or sys.argv[3] not in ("--forbid", "--require"):
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    objdump, elf, mode, groups = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    for g in groups:
        if g not in GROUPS:
            print(f"check_isa.py: unknown group '{g}'", file=sys.stderr)
            return 2
    out = subprocess.run([objdump, "-d", "--mattr=+m,+f,+d,+c", elf], capture_output=True, text=True)
    if out.returncode != 0:
        print(f"check_isa.py: {objdump} failed on {elf}: {out.stderr.strip()}", file=sys.stderr)
        return 1
    found = {g: [] for g in groups}
    for line in out.stdout.splitlines():
        # "80000000: 97 22 0a 00  \tauipc\tt0, 162"
        parts = line.split("\t")
        if len(parts) < 2 or not re.match(r"^\s*[0-9a-f]+:", parts[0]):
            continue
        mnemonic = parts[1].strip()
        for g in groups:
            if GROUPS[g].match(mnemonic):
                found[g].append(line.strip())
    status = 0
    for g in groups:
        if mode == "--forbid" and found[g]:
            print(f"{elf}: {len(found[g])} '{g}' instructions, first: {found[g][0]}")
            status = 1
        elif mode == "--require" and not found[g]:
            print(f"{elf}: no '{g}' instruction, expected some")
            status = 1
        else:
            print(f"{elf}: '{g}' instructions: {len(found[g])}")
    return status


if __name__ == "__main__":
    sys.exit(main())
