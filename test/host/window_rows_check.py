#!/usr/bin/env python3
"""Checks a mid-render snapshot of the --show window against the finished
one: every row is either already drawn (equal to the finished row) or
still background (black), and there are rows of both kinds among those
whose finished row is not black.

Usage: window_rows_check.py PARTIAL.ppm FINISHED.ppm
"""
import sys


def read_p6(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b"P6" or fields[3] != b"255":
        sys.exit(f"{path}: not an 8-bit P6 image")
    w, h = int(fields[1]), int(fields[2])
    pixels = data[pos + 1:]
    if len(pixels) != w * h * 3:
        sys.exit(f"{path}: {len(pixels)} pixel bytes, expected {w * h * 3}")
    return w, h, [pixels[y * w * 3:(y + 1) * w * 3] for y in range(h)]


def main():
    pw, ph, partial = read_p6(sys.argv[1])
    fw, fh, finished = read_p6(sys.argv[2])
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
