#!/usr/bin/env python3
"""Writes NAME.neorv32_imem_image.vhd next to a flat firmware image: the
VHDL package NEORV32 (v1.12.8 and later) compiles into library neorv32 to
pre-initialise its IMEM as a ROM (BOOT_MODE_SELECT = 2). It replaces the
processor's rtl/core/neorv32_imem_image.vhd.

  package neorv32_imem_image
    type rom_t          array (0 to WORDS - 1) of std_ulogic_vector(31 downto 0)
    constant image_size_c : natural   the image's bytes, zero-padded to words
    constant image_data_c : rom_t     the image as little-endian 32-bit words

WORDS is the smallest power of two holding the image: the IMEM ROM indexes
image_data_c with index_size_f(image_size_c) address bits, so the array
must span all of them.

usage: neorv32_imem_image.py NAME.bin
"""
import pathlib
import sys

PACKAGE = "neorv32_imem_image"


def rom_words(image_bytes: int) -> int:
    """Array length: the smallest power of two of words >= the image."""
    words = 1
    while words * 4 < image_bytes:
        words *= 2
    return words


def package_text(data: bytes, source: str) -> str:
    words = [int.from_bytes(data[i:i + 4], "little") for i in range(0, len(data), 4)]
    length = rom_words(len(data))
    lines = [
        f"-- minrt firmware image for NEORV32's IMEM ROM, from {source}",
        f"-- ({len(data)} bytes); compile into library neorv32.",
        "",
        "library ieee;",
        "use ieee.std_logic_1164.all;",
        "",
        f"package {PACKAGE} is",
        "",
        f"type rom_t is array (0 to {length - 1}) of std_ulogic_vector(31 downto 0);",
        f"constant image_size_c : natural := {len(data)};",
        "constant image_data_c : rom_t := (",
    ]
    entries = [f'x"{w:08x}"' for w in words]
    # The zero fill only when words are left to fill, as NEORV32's own does.
    if len(words) < length:
        entries.append("others => (others => '0')")
    lines += [e + "," for e in entries[:-1]] + [entries[-1], ");", "", f"end package {PACKAGE};", ""]
    return "\n".join(lines)


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    src = pathlib.Path(sys.argv[1])
    try:
        data = src.read_bytes()
    except OSError as e:
        print(f"neorv32_imem_image.py: {src}: {e.strerror}", file=sys.stderr)
        return 1
    if not data:
        print(f"neorv32_imem_image.py: {src}: empty image", file=sys.stderr)
        return 1
    data += bytes(-len(data) % 4)
    out = src.with_suffix(f".{PACKAGE}.vhd")
    tmp = out.with_name(out.name + ".tmp")
    tmp.write_text(package_text(data, src.name))
    tmp.replace(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
