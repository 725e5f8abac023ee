#!/usr/bin/env python3
"""Tiles binary PPM images (P6, maxval 255, all the same size) into one PNG,
left to right and top to bottom, with a grey gutter, for a person to look at.

usage: contact_sheet.py OUT.png COLUMNS IMAGE.ppm...
"""
import struct
import sys
import zlib

GUTTER = 4
GUTTER_GREY = 96


def read_ppm(path):
    data = open(path, "rb").read()
    fields, i = [], 2
    if data[:2] != b"P6":
        sys.exit(f"{path}: not a binary PPM")
    while len(fields) < 3:
        while data[i:i + 1].isspace():
            i += 1
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        fields.append(int(data[i:j]))
        i = j
    w, h, maxval = fields
    if maxval != 255:
        sys.exit(f"{path}: maxval {maxval}, expected 255")
    return w, h, data[i + 1:i + 1 + 3 * w * h]


def write_png(path, w, h, rgb):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\0" + rgb[3 * w * y:3 * w * (y + 1)] for y in range(h))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, cols, paths = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    images = [read_ppm(p) for p in paths]
    w, h = images[0][0], images[0][1]
    if any((iw, ih) != (w, h) for iw, ih, _ in images):
        sys.exit("images differ in size")
    rows = (len(images) + cols - 1) // cols
    sw, sh = cols * w + (cols + 1) * GUTTER, rows * h + (rows + 1) * GUTTER
    sheet = bytearray([GUTTER_GREY]) * (3 * sw * sh)
    for k, (_, _, rgb) in enumerate(images):
        x0 = GUTTER + (k % cols) * (w + GUTTER)
        y0 = GUTTER + (k // cols) * (h + GUTTER)
        for y in range(h):
            at = 3 * ((y0 + y) * sw + x0)
            sheet[at:at + 3 * w] = rgb[3 * w * y:3 * w * (y + 1)]
    write_png(out, sw, sh, bytes(sheet))


main()
