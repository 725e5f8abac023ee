#!/usr/bin/python3
"""Hard cases of the text formats (CS418, Jaworski, miniRT, EASTRAY): every
scene of test/hard/scenes/<format> rendered by minrt in each math variant and,
with --elf, by the rv32imf firmware in firmware-sim (host-send --sim, as the
firmware tests send a scene); each render's status (crash, hang, refusal) and
its error against double/libm, with SPEC.md 1.6's measures. Writes the section
"Hard cases, per format" of accuracy.md.

Run through bench/accuracy/run.sh --hard-cases, which builds the tools first.
Needs Debian's python3-numpy and python3-pil (use /usr/bin/python3).
"""
import argparse
import concurrent.futures as cf
import glob
import math
import os
import subprocess
import sys
import time

import numpy as np

from format_speed import BOARD, CS418_RANDOM, REF, VARIANTS, compare, premultiplied, read_any, replace_section
from machine import cpu_model
from safe_output import install_signal_handlers, write_atomically

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SECTION = "## Hard cases, per format"
SCENES = os.path.join(ROOT, "test", "hard", "scenes")
# (format, folder under test/hard/scenes, extension, extra minrt/host-send arguments)
FORMATS = [
    ("CS418", "cs418", ".txt", []),
    ("Jaworski", "jaworski", ".txt", []),
    ("miniRT", "minirt", ".rt", ["--size", "64x48"]),
    ("EASTRAY", "eastray", ".ray", []),
]
TIMEOUT = 300  # seconds for one render: longer is a hang
# A bad pixel (docs/accuracy.md, "Hard cases"): off by more than this from
# double/libm ...
BAD_ERROR = 8
# ... where double/libm's image is flat: no channel of the 3x3 neighbourhood
# differs from the pixel by more than BAD_ERROR, nor of a neighbour's (the
# edge mask of SPEC.md 1.6 dilated by one pixel). An edge or a silhouette that
# moves is float's error; a wrong colour inside a flat area is not.
EDGE_DILATION = 1


def shifted_max(d, r):
    """Largest value of d over each pixel's (2r+1)x(2r+1) neighbourhood."""
    h, w = d.shape
    p = np.pad(d, r, mode="edge")
    out = np.zeros_like(d)
    for dy in range(2 * r + 1):
        for dx in range(2 * r + 1):
            out = np.maximum(out, p[dy:dy + h, dx:dx + w])
    return out


def bad_pixels(img, ref, cs418):
    """Pixels off by more than BAD_ERROR from ref outside ref's dilated edge mask."""
    pa = premultiplied(img) if cs418 else img[:, :, :3].astype(np.int32)
    pr = premultiplied(ref) if cs418 else ref[:, :, :3].astype(np.int32)
    d = np.abs(pa - pr).max(axis=2)
    h, w, _ = pr.shape
    p = np.pad(pr, ((1, 1), (1, 1), (0, 0)), mode="edge")
    var = np.zeros((h, w), np.int32)
    for dy in range(3):
        for dx in range(3):
            var = np.maximum(var, np.abs(p[dy:dy + h, dx:dx + w] - pr).max(axis=2))
    edge = shifted_max((var > BAD_ERROR).astype(np.int32), EDGE_DILATION) > 0
    return int(((d > BAD_ERROR) & ~edge).sum())


def psnr(img, ref, cs418):
    pa = premultiplied(img) if cs418 else img[:, :, :3].astype(np.int32)
    pr = premultiplied(ref) if cs418 else ref[:, :, :3].astype(np.int32)
    mse = float(((pa - pr).astype(np.float64) ** 2).mean())
    return math.inf if mse == 0 else 10 * math.log10(255.0 ** 2 / mse)


def run(cmd, out):
    """(status, image path or None, seconds, first stderr line): status is 'ok',
    'refused' (a non-zero exit with a message), 'crash' (a signal) or 'hang'."""
    t = time.time()
    try:
        r = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return "hang", None, time.time() - t, ""
    line = next((x for x in r.stderr.splitlines() if x.strip() and x.strip() != "Error"), "")
    if r.returncode < 0 or r.returncode >= 128:
        return "crash", None, time.time() - t, line
    if r.returncode != 0 or not os.path.exists(out):
        return "refused", None, time.time() - t, line
    return "ok", out, time.time() - t, line


def render(minrt, scene, extra, variant, out):
    if os.path.exists(out):
        os.remove(out)
    return run([minrt, "-q", "--threads", "1", scene, "-o", out] + extra + variant, out)


def board(host_send, sim, elf, scene, extra, out):
    if os.path.exists(out):
        os.remove(out)
    return run([host_send, "-q", "--sim", elf, "--sim-binary", sim, "--first-byte-timeout", str(TIMEOUT),
                "--idle-timeout", str(TIMEOUT), scene, "-o", out] + extra, out)


def cell(c):
    db = "∞" if c["psnr"] == math.inf else f"{c['psnr']:.1f}"
    return f"{c['max']} / {c['ne']} / {c['gt8']} / {c['bad']} / {db}"


def main():
    install_signal_handlers()
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--minrt", required=True)
    ap.add_argument("--host-send", help="with --sim and --elf: also the board")
    ap.add_argument("--sim", help="firmware-sim")
    ap.add_argument("--elf", help="the rv32imf firmware")
    ap.add_argument("--work", required=True, help="folder for the renders")
    ap.add_argument("--doc", required=True, help="accuracy.md to update (created if missing)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--command", default="bench/accuracy/run.sh --hard-cases")
    args = ap.parse_args()
    start = time.time()
    with_board = bool(args.host_send and args.sim and args.elf)
    pool = cf.ThreadPoolExecutor(max_workers=args.jobs)
    jobs = {}
    scenes = {}
    for name, folder, ext, extra in FORMATS:
        found = sorted(glob.glob(os.path.join(SCENES, folder, "*" + ext)))
        scenes[name] = found
        fdir = os.path.join(args.work, folder)
        os.makedirs(fdir, exist_ok=True)
        for path in found:
            stem = os.path.splitext(os.path.basename(path))[0]
            img_ext = ".png" if name == "CS418" else ".ppm"
            if with_board:
                jobs[(name, path, "board")] = pool.submit(
                    board, args.host_send, args.sim, args.elf, path, extra,
                    os.path.join(fdir, stem + ".board" + (".bmp" if name == "Jaworski" else ".png")))
            for i, (v, va) in enumerate(VARIANTS):
                jobs[(name, path, v)] = pool.submit(render, args.minrt, path, extra, va,
                                                    os.path.join(fdir, f"{stem}.{i}{img_ext}"))
    problems = []
    lines = [SECTION, ""]
    lines.append(
        "Scenes made to break a renderer's arithmetic, for each text format: very large (1e6 to 1e19) and "
        "very small (1e-6) scales, objects far from the origin, rays grazing spheres, planes and triangle "
        "edges, degenerate triangles and zero or tiny vectors, the camera inside an object, coincident "
        "surfaces, huge light intensities and values near float's overflow (test/hard/scenes/<format>; "
        "[its README](../test/hard/scenes/README.md) says what each scene holds). Every one renders in "
        "every variant of minrt and on the board without a crash, a hang or a refusal; the values a "
        "reader must refuse are the `bad/` files there, each refused with one located line.")
    lines.append("")
    lines.append(
        "Each cell: max / px ≠ / px > 8 / **bad** / PSNR against double/libm (CS418: SPEC.md 1.6's premultiplied "
        "RGBA). A **bad** pixel is off by more than 8 where double/libm's image is flat: outside its edge mask "
        "(a pixel whose 3x3 neighbourhood differs from it by more than 8) dilated by one pixel. A moved edge "
        "or silhouette is float's error and counts only in px > 8; a wrong colour inside a flat area "
        "(NaN turned black, a lost object, speckle) is bad. **board** is the rv32imf firmware in "
        "firmware-sim against minrt's float/portable: = when equal.")
    lines.append("")
    for name, folder, ext, extra in FORMATS:
        cs418 = name == "CS418"
        head = [v for v, _ in VARIANTS[1:]]
        size = " (at 64x48)" if name == "miniRT" else ""
        lines.append(f"### {name}{size}")
        lines.append("")
        lines.append("| scene | " + " | ".join(head) + (" | board |" if with_board else " |"))
        lines.append("|---|" + "---|" * len(head) + ("---|" if with_board else ""))
        for path in scenes[name]:
            base = os.path.basename(path)
            res = {v: jobs[(name, path, v)].result() for v, _ in VARIANTS}
            for v, (st, _, secs, msg) in res.items():
                if st != "ok":
                    problems.append(f"{name} {base} {v}: {st} {msg}")
            ref = res[REF][1]
            row = [base]
            text = open(path, errors="replace").read()
            rnd = cs418 and bool(CS418_RANDOM.search(text))
            ref_img = read_any(ref) if ref else None
            for v in head:
                st, out, _, _ = res[v]
                if st != "ok" or ref_img is None:
                    row.append(st if st != "ok" else "no reference")
                    continue
                img = read_any(out)
                if img.shape != ref_img.shape:
                    row.append("size differs")
                    problems.append(f"{name} {base} {v}: image of another size")
                    continue
                c = compare(img, ref_img, cs418, rnd)
                c["bad"] = bad_pixels(img, ref_img, cs418)
                c["psnr"] = psnr(img, ref_img, cs418)
                row.append(cell(c))
            if with_board:
                st, out, secs, msg = jobs[(name, path, "board")].result()
                host = res[BOARD][1]
                if st != "ok" or not host:
                    row.append(st)
                    problems.append(f"{name} {base} board: {st} {msg}")
                else:
                    a, b = read_any(out), read_any(host)
                    chans = 4 if cs418 else 3
                    same = a.shape == b.shape and np.array_equal(a[:, :, :chans], b[:, :, :chans])
                    row.append("=" if same else "**differs**")
                    if not same:
                        problems.append(f"{name} {base} board: differs from float/portable")
            lines.append("| " + " | ".join(row) + " |")
        lines.append("")
    pool.shutdown()
    renders = sum(len(scenes[n]) for n, _, _, _ in FORMATS) * (len(VARIANTS) + (1 if with_board else 0))
    lines.append("Reading the numbers:")
    lines.append("")
    lines.append(f"- {renders} renders, {len(problems)} of them a crash, a hang, a refusal, an image of another size "
                 "or a board image unlike minrt's float/portable.")
    lines.append("- Where a scene has bad pixels, single precision cannot hold the scene: coordinates of 1e7 (float's "
                 "spacing there is 1), a scene at 1e6 (spacing 0.06, above the secondary rays' offsets), a squared "
                 "radius beyond float's 3.4e38 (a sphere around the camera is lost), a field of view whose pixels differ by less than float's spacing. "
                 "[test/hard/scenes/README.md](../test/hard/scenes/README.md) says which, per scene; the test holds "
                 "every float variant to those counts.")
    lines.append("- Vectors a reader takes only as a direction (an EASTRAY axis, a plane's (A, B, C), Jaworski's plane "
                 "normal in float, CS418's forward, up, sun and rough normal) keep it when their squared length under- or overflows "
                 "float (`squarable_direction`, core/math/vec3.hpp); a thin EASTRAY quadric (semi-axes 1 and 1e-4) "
                 "takes its discriminant without cancellation, so its object hierarchy and the plain walk agree.")
    lines.append("")
    load = open("/proc/loadavg").read().split()[0]
    lines.append(f"Made by `{args.command}` in {time.time() - start:.0f} s of wall time on the {cpu_model()} "
                 f"(2 cores shared with other work; one-minute load average {load} at the end).")
    lines.append("")
    for p in problems:
        print("hard_cases: " + p, file=sys.stderr)
    section = "\n".join(lines) + "\n"
    doc = open(args.doc).read() if os.path.exists(args.doc) else ""
    write_atomically(args.doc, replace_section(doc, section, SECTION))
    print(f"hard_cases: wrote {args.doc} ({len(problems)} problems)", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
