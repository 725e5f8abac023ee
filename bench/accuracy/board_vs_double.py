#!/usr/bin/env python3
"""The board's arithmetic against double on the text formats: renders every
scene of ../shared/formats/{minirt/valid,cs418,jaworski,eastray} with minrt
in double (libm: the goldens) and in float with the portable shims (what the
board computes: host-send's tests check the board sends exactly these
pixels), counts the pixels that differ, and writes the section "The board
against double" of docs/accuracy.md (replacing it, or inserting it before
"Regenerating"; bench/accuracy/make_report.py keeps it when it rewrites the
file): miniRT per scene at 800x600 with a picture of the scene with the most
pixels off by more than 1 (docs/accuracy/minirt-worst.png), the other
formats summed, at the sizes their files give.

Usage: bench/accuracy/board_vs_double.py [--minrt PATH] [--shared DIR]
"""
import argparse
import glob
import os
import struct
import subprocess
import sys
import tempfile
import time
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools", "images"))
from image_files import parse_p6, write_png  # noqa: E402
from machine import cpu_model  # noqa: E402
from safe_output import write_atomically  # noqa: E402
SECTION = "## The board against double"
MINIRT_SIZE = "800x600"
# Format, scene pattern under formats/, extra minrt arguments, output extension.
FORMATS = [
    ("miniRT", "minirt/valid/*.rt", ["--size", MINIRT_SIZE], ".ppm"),
    ("CS418", "cs418/*.txt", [], ".ppm"),
    ("Jaworski", "jaworski/*.txt", [], ".bmp"),
    ("EASTRAY", "eastray/*.ray", [], ".png"),
]
FLOAT = ["--precision", "float", "--shims", "portable"]


def read_bmp(data):
    """Uncompressed 24- or 32-bit BMP (minrt writes 32-bit BGRA for Jaworski) as top-down RGB."""
    offset, = struct.unpack_from("<I", data, 10)
    w, h, _, bpp = struct.unpack_from("<iiHH", data, 18)
    assert bpp in (24, 32), "24- or 32-bit BMP expected"
    n = bpp // 8
    stride = (w * n + 3) & ~3
    rows = range(abs(h)) if h < 0 else range(h - 1, -1, -1)
    out = bytearray()
    for y in rows:
        row = data[offset + y * stride:offset + y * stride + w * n]
        for x in range(w):
            out += bytes((row[n * x + 2], row[n * x + 1], row[n * x]))
    return w, abs(h), bytes(out)


def read_png(data, alpha=False):
    """8-bit RGB or RGBA, non-interlaced PNG as RGB (alpha dropped), or as
    RGBA with alpha=True (255 where the file has none)."""
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack_from(">I4s", data, pos)
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and ctype in (2, 6) and interlace == 0, "8-bit RGB(A) PNG expected"
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = w * bpp
    prev = bytearray(stride)
    out = bytearray()
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prev = line
        for x in range(w):
            out += line[x * bpp:x * bpp + 3]
            if alpha:
                out.append(line[x * bpp + 3] if bpp == 4 else 255)
    return w, h, bytes(out)


def read_image(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:2] == b"P6":
        return parse_p6(data, path)
    if data[:2] == b"BM":
        return read_bmp(data)
    if data[:4] == b"\x89PNG":
        return read_png(data)
    raise ValueError(f"{path}: not a P6, BMP or PNG image")


def compare(a, b):
    """(pixels with any channel different, off by more than 1, off by more than 8, largest error, off > 1 list)"""
    ne = gt1 = gt8 = worst = 0
    far = []
    for i in range(0, len(a), 3):
        d = max(abs(a[i] - b[i]), abs(a[i + 1] - b[i + 1]), abs(a[i + 2] - b[i + 2]))
        if d:
            ne += 1
            worst = max(worst, d)
            if d > 1:
                gt1 += 1
                far.append(i // 3)
            if d > 8:
                gt8 += 1
    return ne, gt1, gt8, worst, far


def picture(path, w, h, double, single, far):
    """Double on the left, float on the right, each pixel off by more than 1
    circled by a magenta square on both."""
    out = bytearray(2 * w * 3 * h)
    for y in range(h):
        out[y * 2 * w * 3:y * 2 * w * 3 + w * 3] = double[y * w * 3:(y + 1) * w * 3]
        out[y * 2 * w * 3 + w * 3:(y + 1) * 2 * w * 3] = single[y * w * 3:(y + 1) * w * 3]
    r = 6
    for p in far:
        px, py = p % w, p // w
        for side in (0, w):
            for k in range(-r, r + 1):
                for (x, y) in ((px + k, py - r), (px + k, py + r), (px - r, py + k), (px + r, py + k)):
                    if 0 <= x < w and 0 <= y < h:
                        o = (y * 2 * w + side + x) * 3
                        out[o:o + 3] = b"\xff\x00\xff"
    write_png(path, 2 * w, h, out)


def render(minrt, scene, extra, out):
    """The image minrt renders, or None when it refuses the scene."""
    run = subprocess.run([minrt, scene, "-o", out] + extra, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, cwd=os.path.dirname(out))
    return read_image(out) if run.returncode == 0 else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--minrt", default=os.path.join(ROOT, "build/release/host/minrt"))
    ap.add_argument("--shared", default=os.path.join(ROOT, "../shared"))
    args = ap.parse_args()
    command = "bench/accuracy/board_vs_double.py" + "".join(
        f" --{k} {os.path.relpath(v, ROOT)}" for k, v in (("minrt", args.minrt), ("shared", args.shared))
        if os.path.abspath(v) != os.path.abspath(ap.get_default(k)))
    args.minrt = os.path.abspath(args.minrt)  # minrt runs in the render folder
    start = time.time()
    results = {}  # format -> [(scene, pixels, ne, gt1, gt8, max, far, double, float, w, h)]
    refused = {}
    with tempfile.TemporaryDirectory() as work:
        for name, pattern, extra, ext in FORMATS:
            results[name], refused[name] = [], []
            for scene in sorted(glob.glob(os.path.join(args.shared, "formats", pattern))):
                d = render(args.minrt, scene, extra, os.path.join(work, "double" + ext))
                f = render(args.minrt, scene, extra + FLOAT, os.path.join(work, "float" + ext))
                if d is None or f is None or d[:2] != f[:2]:
                    refused[name].append(os.path.basename(scene))
                    continue
                w, h = d[0], d[1]
                ne, gt1, gt8, mx, far = compare(d[2], f[2])
                results[name].append((os.path.basename(scene), w * h, ne, gt1, gt8, mx, far, d[2], f[2], w, h))
    cpu = cpu_model()
    lines = [SECTION, "",
             "Every scene of `shared/formats` rendered by minrt in float with the portable shims (what the "
             "board computes: the `host_send` tests check the board sends exactly these pixels) against "
             "double/libm (the goldens). Columns as above; **px > 1** = pixels with a channel off by more "
             "than 1.", "",
             "| format | scenes | scenes ≠ | pixels | px ≠ | px > 1 | px > 8 | max |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for name, _, _, _ in FORMATS:
        rows = results[name]
        lines.append(f"| {name} | {len(rows)} | {sum(1 for r in rows if r[2])} | {sum(r[1] for r in rows)} | "
                     f"{sum(r[2] for r in rows)} | {sum(r[3] for r in rows)} | {sum(r[4] for r in rows)} | "
                     f"{max((r[5] for r in rows), default=0)} |")
    notes = [f"{name}: {len(v)} scene{'s' if len(v) != 1 else ''} the reader refuses or that need files "
             f"minrt does not find from here ({', '.join(v)})" for name, v in refused.items() if v]
    if notes:
        lines += ["", "Left out: " + "; ".join(notes) + "."]
    for name, _, _, _ in FORMATS[1:]:
        rows = [r for r in results[name] if r[3]]
        if rows:
            worst = max(rows, key=lambda r: (r[3], r[2]))
            lines += ["", f"{name}: the most pixels off by more than 1 is {worst[0]}, {worst[3]} of {worst[1]} "
                      f"(largest error {worst[5]})."]
    rows = results["miniRT"]
    lines += ["", f"### miniRT, per scene ({MINIRT_SIZE}, {rows[0][1] if rows else 0} pixels)", "",
              "| scene | px ≠ | px > 1 | px > 8 | max |", "|---|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r[0]} | {r[2]} | {r[3]} | {r[4]} | {r[5]} |")
    if rows:
        worst = max(rows, key=lambda r: (r[3], r[2]))
        picture(os.path.join(ROOT, "docs/accuracy/minirt-worst.png"), worst[9], worst[10], worst[7], worst[8],
                worst[6])
        lines += ["", f"The most pixels off by more than 1: {worst[0]}, {worst[3]} of {worst[1]} (double left, "
                  "float right, each such pixel in a magenta square):", "",
                  "![the worst miniRT scene, double and float](accuracy/minirt-worst.png)"]
    lines += ["", f"Made by `{command}` ({time.time() - start:.0f} s on the {cpu}, 2 "
              "cores shared with other work).", "", ""]
    section = "\n".join(lines)
    path = os.path.join(ROOT, "docs/accuracy.md")
    with open(path) as fdoc:
        doc = fdoc.read()
    if SECTION + "\n" in doc:
        a = doc.index(SECTION + "\n")
        b = doc.find("\n## ", a + len(SECTION))
        doc = doc[:a] + section + (doc[b + 1:] if b >= 0 else "")
    else:
        a = doc.index("## Regenerating")
        doc = doc[:a] + section + "\n" + doc[a:]
    write_atomically(path, doc)
    print(f"wrote {path} and docs/accuracy/minirt-worst.png", file=sys.stderr)


if __name__ == "__main__":
    main()
