#!/usr/bin/env python3
"""Checks a mid-render snapshot of the --show window against the finished
one: every row is either already drawn (equal to the finished row) or
still background (black), and there are rows of both kinds among those
whose finished row is not black.

Usage: window_rows_check.py PARTIAL.ppm FINISHED.ppm
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "images"))
from image_files import read_p6  # noqa: E402


def rows_of(path):
    try:
        w, h, pixels = read_p6(path)
    except ValueError as e:
        sys.exit(str(e))
    return w, h, [pixels[y * w * 3:(y + 1) * w * 3] for y in range(h)]


def main():
    pw, ph, partial = rows_of(sys.argv[1])
    fw, fh, finished = rows_of(sys.argv[2])
    if (pw, ph) != (fw, fh):
        sys.exit(f"sizes differ: {pw}x{ph} mid-render, {fw}x{fh} finished")
    black = bytes(pw * 3)
    drawn = waiting = 0
    for y, (p, f) in enumerate(zip(partial, finished)):
        if p == f:
            drawn += f != black
        elif p == black:
            waiting += 1
        else:
            sys.exit(f"row {y} is neither finished nor background in the mid-render snapshot")
    print(f"mid-render: {drawn} rows drawn, {waiting} still background, of {fh}")
    if drawn == 0 or waiting == 0:
        sys.exit("the mid-render snapshot does not show a partly drawn image")


main()
