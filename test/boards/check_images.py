#!/usr/bin/env python3
"""Checks the image files next to a firmware ELF (NAME.bin/.hex/.coe/.mem,
runtime/firmware/image_formats.py): each holds the flat binary's bytes as
32-bit little-endian words, and the flat binary is not empty.

  check_images.py NAME.elf
"""
import pathlib
import sys


def main() -> int:
    if len(sys.argv) != 2:
        print("usage: check_images.py NAME.elf", file=sys.stderr)
        return 2
    elf = pathlib.Path(sys.argv[1])
    binary = elf.with_suffix(".bin").read_bytes()
    if not binary:
        print(f"{elf.with_suffix('.bin')}: empty")
        return 1
    padded = binary + bytes(-len(binary) % 4)
    want = [int.from_bytes(padded[i:i + 4], "little") for i in range(0, len(padded), 4)]

    hex_words = [int(w, 16) for w in elf.with_suffix(".hex").read_text().split()]
    mem_lines = elf.with_suffix(".mem").read_text().split()
    coe = elf.with_suffix(".coe").read_text()
    head, _, vector = coe.partition("memory_initialization_vector=")
    coe_words = [int(w, 16) for w in vector.replace(";", " ").replace(",", " ").split()]

    problems = []
    if hex_words != want:
        problems.append(".hex words differ from the binary")
    if mem_lines[:1] != ["@00000000"] or [int(w, 16) for w in mem_lines[1:]] != want:
        problems.append(".mem is not @00000000 and the binary's words")
    if "memory_initialization_radix=16;" not in head or coe_words != want:
        problems.append(".coe is not radix 16 with the binary's words")
    for p in problems:
        print(f"{elf}: {p}")
    if not problems:
        print(f"{elf}: .bin {len(binary)} bytes, .hex/.mem/.coe {len(want)} words each, equal")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
