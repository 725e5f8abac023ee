#!/usr/bin/env python3
"""Reads NAME.neorv32_imem_image.vhd back (runtime/firmware/
neorv32_imem_image.py) and checks it against NAME.bin as NEORV32's IMEM
ROM uses it: package neorv32_imem_image on ieee.std_logic_1164 only;
image_size_c the .bin's size padded to words; rom_t exactly the
2**ceil(log2(image_size_c)) bytes the ROM addresses; image_data_c's
words, each the .bin's little-endian word at its index, then a zero
'others' exactly when the array has room left.

  check_neorv32_imem_image.py NAME.elf
"""
import pathlib
import re
import sys

HEX_WORD = re.compile(r'^x"([0-9a-fA-F]{8})"$')


def parse(text: str):
    """The package's parts, or a one-line reason it has none."""
    code = "\n".join(line.split("--", 1)[0] for line in text.splitlines())
    found = {}
    m = re.search(r"\bpackage\s+(\w+)\s+is\b(.*)\bend\s+package(\s+\w+)?\s*;", code, re.S | re.I)
    if not m:
        return None, "no 'package NAME is ... end package;'"
    found["package"], body = m.group(1), m.group(2)
    found["end_name"] = (m.group(3) or "").strip()
    found["context"] = re.findall(r"^\s*((?:library|use)\s+[^;]+;)", code[:m.start()], re.M | re.I)
    m = re.search(r"\btype\s+rom_t\s+is\s+array\s*\(\s*0\s+to\s+(\d+)\s*\)\s+of\s+"
                  r"std_ulogic_vector\s*\(\s*31\s+downto\s+0\s*\)\s*;", body, re.I)
    if not m:
        return None, "no 'type rom_t is array (0 to N) of std_ulogic_vector(31 downto 0)'"
    found["length"] = int(m.group(1)) + 1
    m = re.search(r"\bconstant\s+image_size_c\s*:\s*natural\s*:=\s*(\d+)\s*;", body, re.I)
    if not m:
        return None, "no 'constant image_size_c : natural := N'"
    found["size"] = int(m.group(1))
    m = re.search(r"\bconstant\s+image_data_c\s*:\s*rom_t\s*:=\s*\((.*)\)\s*;", body, re.S | re.I)
    if not m:
        return None, "no 'constant image_data_c : rom_t := (...)'"
    entries = [e.strip() for e in m.group(1).split(",")]
    found["others"] = False
    if entries and re.fullmatch(r"others\s*=>\s*\(\s*others\s*=>\s*'0'\s*\)", entries[-1], re.I):
        found["others"] = True
        entries.pop()
    words = []
    for n, e in enumerate(entries):
        w = HEX_WORD.match(e)
        if not w:
            return None, f"image_data_c entry {n} is '{e[:40]}', not x\"HHHHHHHH\""
        words.append(int(w.group(1), 16))
    found["words"] = words
    return found, None


def main() -> int:
    if len(sys.argv) != 2:
        print("usage: check_neorv32_imem_image.py NAME.elf", file=sys.stderr)
        return 2
    elf = pathlib.Path(sys.argv[1])
    vhd = elf.with_suffix(".neorv32_imem_image.vhd")
    try:
        binary = elf.with_suffix(".bin").read_bytes()
        text = vhd.read_text()
    except (OSError, UnicodeDecodeError) as e:
        print(f"{elf}: {getattr(e, 'filename', None) or vhd}: {getattr(e, 'strerror', None) or e}")
        return 1
    found, why = parse(text)
    if not found:
        print(f"{vhd}: {why}")
        return 1
    padded = binary + bytes(-len(binary) % 4)
    expected = [int.from_bytes(padded[i:i + 4], "little") for i in range(0, len(padded), 4)]
    # The ROM decodes ceil(log2(image_size_c)) byte-address bits.
    rom_bytes = 1 << max(2, (len(padded) - 1).bit_length())
    problems = []
    if found["package"] != "neorv32_imem_image" or found["end_name"] not in ("", "neorv32_imem_image"):
        problems.append(f"package '{found['package']}' ... end '{found['end_name']}', not neorv32_imem_image")
    context = [" ".join(c.lower().split()) for c in found["context"]]
    if context != ["library ieee;", "use ieee.std_logic_1164.all;"]:
        problems.append(f"context clause {context}, not ieee.std_logic_1164 only")
    if found["size"] != len(padded):
        problems.append(f"image_size_c {found['size']}, .bin padded {len(padded)} bytes")
    if found["length"] * 4 != rom_bytes:
        problems.append(f"rom_t has {found['length']} words, the ROM addresses {rom_bytes // 4}")
    words = found["words"]
    if len(words) != len(expected):
        problems.append(f"{len(words)} words, .bin has {len(expected)}")
    wrong = [i for i, (a, b) in enumerate(zip(words, expected)) if a != b]
    if wrong:
        i = wrong[0]
        problems.append(f"{len(wrong)} words differ from the .bin, first at byte 0x{4 * i:x}: "
                        f"0x{words[i]:08x}, not 0x{expected[i]:08x}")
    if found["others"] != (len(words) < found["length"]):
        problems.append(f"zero 'others' {'present' if found['others'] else 'missing'} with "
                        f"{len(words)} of {found['length']} words given")
    for p in problems:
        print(f"{vhd}: {p}")
    if not problems:
        print(f"{vhd}: package neorv32_imem_image, {len(words)} words ({found['size']} bytes) "
              f"in a {found['length']}-word rom_t: right")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
