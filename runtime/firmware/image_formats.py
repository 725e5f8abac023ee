#!/usr/bin/env python3
"""Writes a flat firmware image (llvm-objcopy -O binary) in the formats FPGA
memory initialisation reads, next to it:

  NAME.hex  one 32-bit word per line, 8 hex digits, for Verilog $readmemh
  NAME.coe  Vivado block-RAM init (radix 16, one word per entry)
  NAME.mem  Vivado updatemem / $readmemh with an @0 address line

Words are little-endian (byte 0 of the image is bits 7:0 of word 0), as an
RV32 CPU reads them; the last word is padded with zero bytes. Word 0 is the
image's first address, the board's reset address.

usage: image_formats.py NAME.bin
"""
import pathlib
import sys


def words(data: bytes):
    data += bytes(-len(data) % 4)
    for i in range(0, len(data), 4):
        yield int.from_bytes(data[i:i + 4], "little")


def write(path: pathlib.Path, text: str) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    tmp.replace(path)


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    src = pathlib.Path(sys.argv[1])
    try:
        data = src.read_bytes()
    except OSError as e:
        print(f"image_formats.py: {src}: {e.strerror}", file=sys.stderr)
        return 1
    hexwords = [f"{w:08x}" for w in words(data)]
    body = "\n".join(hexwords) + "\n"
    write(src.with_suffix(".hex"), body)
    write(src.with_suffix(".mem"), "@00000000\n" + body)
    write(src.with_suffix(".coe"),
          "memory_initialization_radix=16;\nmemory_initialization_vector=\n"
          + ",\n".join(hexwords) + ";\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
