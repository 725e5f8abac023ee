"""Binary PPM in (P6, maxval 255: what minrt --format p6 writes) and RGB PNG
out, for the Python tools that look at minrt's images: bench/accuracy/,
test/host/, tools/minirt/. Import it with this folder on sys.path."""
import os
import struct
import zlib


def parse_p6(data, name="image"):
    """(width, height, RGB bytes) of a P6 image with maxval 255; a ValueError
    naming `name` for anything else or an incomplete image."""
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while pos < len(data) and not data[pos:pos + 1].isspace():
            pos += 1
        if start == pos:
            raise ValueError(f"{name}: the PPM header ends early")
        fields.append(bytes(data[start:pos]))
    if fields[0] != b"P6" or fields[3] != b"255":
        raise ValueError(f"{name}: not an 8-bit P6 image")
    w, h = int(fields[1]), int(fields[2])
    pixels = bytes(data[pos + 1:])
    if len(pixels) != w * h * 3:
        raise ValueError(f"{name}: {len(pixels)} pixel bytes, expected {w * h * 3}")
    return w, h, pixels


def read_p6(path):
    """parse_p6 of the file at `path`."""
    with open(path, "rb") as f:
        return parse_p6(f.read(), path)


def write_png(path, w, h, rgb):
    """8-bit RGB PNG of `rgb` (rows top down), written whole: to a temporary
    name first, then renamed."""
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    raw = b"".join(b"\0" + bytes(rgb[3 * w * y:3 * w * (y + 1)]) for y in range(h))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(png)
    os.replace(tmp, path)
