#!/usr/bin/env python3
"""Reads NAME.neorv32.exe back (runtime/firmware/neorv32_exe.py) and checks
it against NAME.bin as the NEORV32 bootloader does: signature 0x214F454E,
the base address given, the size of the zero-padded image, the image's
bytes, and the words summing with the checksum to 0xFFFFFFFF.

  check_neorv32_exe.py NAME.elf BASE
"""
import pathlib
import struct
import sys


def main() -> int:
    if len(sys.argv) != 3:
        print("usage: check_neorv32_exe.py NAME.elf BASE", file=sys.stderr)
        return 2
    elf = pathlib.Path(sys.argv[1])
    base = int(sys.argv[2], 0)
    binary = elf.with_suffix(".bin").read_bytes()
    exe = elf.with_suffix(".neorv32.exe").read_bytes()
    problems = []
    if len(exe) < 16:
        print(f"{elf}: .neorv32.exe has no header")
        return 1
    signature, exe_base, size, checksum = struct.unpack_from("<4I", exe, 0)
    image = exe[16:]
    padded = binary + bytes(-len(binary) % 4)
    if signature != 0x214F454E:
        problems.append(f"signature 0x{signature:08x}, not 0x214f454e")
    if exe_base != base:
        problems.append(f"base 0x{exe_base:08x}, not 0x{base:08x}")
    if size != len(padded) or size != len(image):
        problems.append(f"size {size}, image {len(image)} bytes, .bin padded {len(padded)}")
    if image != padded:
        problems.append("image bytes differ from the .bin")
    words = struct.unpack(f"<{len(image) // 4}I", image[:len(image) // 4 * 4])
    if (sum(words) + checksum) & 0xFFFFFFFF != 0xFFFFFFFF:
        problems.append(f"checksum 0x{checksum:08x} does not complement the words' sum")
    for p in problems:
        print(f"{elf}: {p}")
    if not problems:
        print(f"{elf}: .neorv32.exe signature, base 0x{base:08x}, {size} bytes, checksum 0x{checksum:08x}: right")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
