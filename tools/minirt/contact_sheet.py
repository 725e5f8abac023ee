#!/usr/bin/env python3
"""Tiles binary PPM images (P6, maxval 255, all the same size) into one PNG,
left to right and top to bottom, with a grey gutter, for a person to look at.

usage: contact_sheet.py OUT.png COLUMNS IMAGE.ppm...
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "images"))
from image_files import read_p6, write_png  # noqa: E402

GUTTER = 4
GUTTER_GREY = 96


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, cols, paths = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    try:
        images = [read_p6(p) for p in paths]
    except ValueError as e:
        sys.exit(str(e))
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
