#!/usr/bin/env python3
"""Writes NAME.neorv32.exe next to a flat firmware image: the executable
format the NEORV32 bootloader accepts for upload over UART0 (or from SPI
flash). Four little-endian 32-bit header words, then the image:

  0  signature  0x214F454E
  4  base       the address the image runs at (the board's reset address)
  8  size       image bytes (a multiple of 4: the image is zero-padded)
  12 checksum   the bitwise complement of the sum of the image's words
                (mod 2^32), so words + checksum sum to 0xFFFFFFFF

usage: neorv32_exe.py NAME.bin BASE
"""
import pathlib
import sys

SIGNATURE = 0x214F454E


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    src = pathlib.Path(sys.argv[1])
    try:
        base = int(sys.argv[2], 0)
        data = src.read_bytes()
    except ValueError:
        print(f"neorv32_exe.py: base '{sys.argv[2]}' is not a number", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"neorv32_exe.py: {src}: {e.strerror}", file=sys.stderr)
        return 1
    data += bytes(-len(data) % 4)
    total = sum(int.from_bytes(data[i:i + 4], "little") for i in range(0, len(data), 4))
    checksum = ~total & 0xFFFFFFFF
    header = b"".join(v.to_bytes(4, "little") for v in (SIGNATURE, base & 0xFFFFFFFF, len(data), checksum))
    out = src.with_suffix(".neorv32.exe")
    tmp = out.with_name(out.name + ".tmp")
    tmp.write_bytes(header + data)
    tmp.replace(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
