#!/usr/bin/python3
"""Speed against error for the text formats (CS418, Jaworski, miniRT,
EASTRAY): every scene of ../shared/formats/<format> rendered by minrt in each
math variant the format takes, its error against double/libm; a few
representative scenes per format (its heaviest among them) counted on the
host (x86-64 instructions of minrt under callgrind, per variant) and on the
board (the rv32imf firmware in firmware-sim --stats --cycle-model default,
sent each scene by host-send as the firmware tests do). Writes the section
"Speed against error, per format" of accuracy.md and accuracy/formats-speed-vs-error.png.

Run through bench/accuracy/run.sh --formats, which builds the tools first.
Needs Debian's python3-numpy, python3-matplotlib and python3-pil (use /usr/bin/python3).
"""
import argparse
import concurrent.futures as cf
import glob
import hashlib
import math
import os
import re
import subprocess
import sys
import time

import numpy as np
from PIL import Image

from machine import cpu_model
from safe_output import install_signal_handlers, write_atomically
import board_vs_double
import plots

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools", "images"))
from image_files import parse_p6  # noqa: E402

SECTION = "## Speed against error, per format"
REF = "double/libm"
BOARD = "float/portable"  # what the firmware computes
# Every variant host/math_policy_dispatch.hpp builds, for every format: (name, minrt arguments).
VARIANTS = [
    ("double/libm", ["--precision", "double", "--shims", "libm"]),
    ("float/libm", ["--precision", "float", "--shims", "libm"]),
    ("float/portable", ["--precision", "float", "--shims", "portable"]),
    ("float/portable-fast", ["--precision", "float", "--shims", "portable-fast"]),
    ("float/portable-min", ["--precision", "float", "--shims", "portable-min"]),
]
MINIRT_ERROR_SIZE = "800x600"  # the size of "The board against double"
MINIRT_SPEED_SIZE = "320x240"
# (format, scene pattern under formats/, extra minrt/host-send arguments for the
# error renders, for the speed runs, image kind minrt writes, speed scenes: the
# heaviest on the board first).
FORMATS = [
    ("CS418", "cs418/*.txt", [], [], ".png", ["ray-gi.txt", "ray-many.txt", "ray-tex.txt"]),
    ("Jaworski", "jaworski/*.txt", [], [], ".ppm",
     ["raydepth-large-facing-mirrors.txt", "mixed-nested-deep.txt", "huge-and-tiny-numbers.txt"]),
    ("miniRT", "minirt/valid/*.rt", ["--size", MINIRT_ERROR_SIZE], ["--size", MINIRT_SPEED_SIZE], ".ppm",
     ["showcase.rt", "earth_bumped.rt", "bonus_cone.rt"]),
    ("EASTRAY", "eastray/*.ray", [], [], ".ppm",
     ["parts_named_calls.ray", "material_glass_ior.ray", "kinds_20_polygon_mesh.ray"]),
]
# SPEC.md's CS418 random tests (aa, dof, roughness, gi): compared on 4x4-block
# averages of the premultiplied colour.
CS418_RANDOM = re.compile(r"^\s*(aa|dof|roughness|gi)\s", re.M)
CS418_BLOCK = 4


def read_any(path):
    """HxWx4 uint8 (alpha 255 where the file has none) of a P6, PNG or BMP file."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:2] == b"P6":
        w, h, rgb = parse_p6(data, path)
        rgba = np.full((h, w, 4), 255, np.uint8)
        rgba[:, :, :3] = np.frombuffer(rgb, np.uint8).reshape(h, w, 3)
        return rgba
    if data[:2] == b"BM":
        w, h, rgb = board_vs_double.read_bmp(data)
        rgba = np.full((h, w, 4), 255, np.uint8)
        rgba[:, :, :3] = np.frombuffer(rgb, np.uint8).reshape(h, w, 3)
        return rgba
    with Image.open(path) as im:  # PNG: libpng's filters are many times faster in PIL
        return np.asarray(im.convert("RGBA"))


def premultiplied(img):
    """SPEC.md's CS418 comparison: RGB times alpha / 255, with alpha."""
    a = img[:, :, 3:4].astype(np.int32)
    out = img.astype(np.int32)
    out[:, :, :3] = (out[:, :, :3] * a + 127) // 255
    return out


def compare(a, b, cs418, random_scene):
    """Pixels differing, off by more than 1 and 8 (largest channel error; CS418:
    premultiplied RGBA), largest error, alpha mismatches, 4x4-block PSNR (CS418
    random scenes, else None)."""
    if cs418:
        pa, pb = premultiplied(a), premultiplied(b)
    else:
        pa, pb = a[:, :, :3].astype(np.int32), b[:, :, :3].astype(np.int32)
    d = np.abs(pa - pb).max(axis=2)
    block = None
    if random_scene:
        h, w = (pa.shape[0] // CS418_BLOCK) * CS418_BLOCK, (pa.shape[1] // CS418_BLOCK) * CS418_BLOCK
        avg = [x[:h, :w, :3].reshape(h // CS418_BLOCK, CS418_BLOCK, w // CS418_BLOCK, CS418_BLOCK, 3)
               .mean(axis=(1, 3)) for x in (pa, pb)]
        mse = float(((avg[0] - avg[1]) ** 2).mean())
        block = math.inf if mse == 0 else 10 * math.log10(255.0 ** 2 / mse)
    return {"ne": int((d > 0).sum()), "gt1": int((d > 1).sum()), "gt8": int((d > 8).sum()),
            "max": int(d.max()), "alpha": int((a[:, :, 3] != b[:, :, 3]).sum()), "block": block,
            "pixels": int(d.size)}


def render(minrt, scene, extra, variant, out):
    r = subprocess.run([minrt, "-q", "--threads", "1", scene, "-o", out] + extra + variant,
                       stdin=subprocess.DEVNULL, capture_output=True, text=True)
    return out if r.returncode == 0 else None


CACHE_HITS = []  # the callgrind counts this run took from the cache


def host_instructions(minrt, scene, extra, variant, cache_dir):
    """x86-64 instructions of the whole minrt process (read, render, no file written).
    Exact, so kept in cache_dir under a hash of minrt, the scene, the files beside it
    (textures, includes) and the arguments, and reused while all are byte-identical."""
    h = hashlib.sha256()
    for path in [minrt, scene] + sorted(glob.glob(os.path.join(os.path.dirname(scene), "*"))):
        if os.path.isfile(path):
            h.update(path.encode() + b"\0" + open(path, "rb").read())
    h.update(" ".join(extra + variant).encode())
    cached = os.path.join(cache_dir, h.hexdigest()[:32] + ".ir")
    if os.path.exists(cached):
        CACHE_HITS.append(cached)
        return int(open(cached).read())
    r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", minrt, "-q", "-n",
                        "--threads", "1", scene] + extra + variant,
                       stdin=subprocess.DEVNULL, capture_output=True, text=True)
    m = re.search(r"Collected : (\d+)", r.stderr)
    if r.returncode != 0 or not m:
        return None
    os.makedirs(cache_dir, exist_ok=True)
    write_atomically(cached, m.group(1))
    return int(m.group(1))


def board_counts(host_send, sim, elf, scene, extra, out, work):
    """The board's --stats (instructions, cycles) for one scene sent by host-send over the raw
    protocol (CRC-checked, so the firmware waits for no idle polls), and its image."""
    stats = out + ".stats"
    wrapper = os.path.join(work, "sim-with-stats.sh")
    env = dict(os.environ, MINRT_REAL_SIM=sim, MINRT_STATS_OUT=stats)
    # A busy machine may take minutes for the first row of the heaviest scene.
    r = subprocess.run([host_send, "-q", "--sim", elf, "--sim-binary", wrapper, "--first-byte-timeout", "3600",
                        "--idle-timeout", "3600", scene, "-o", out] + extra,
                       stdin=subprocess.DEVNULL, capture_output=True, text=True, env=env)
    if r.returncode != 0 or not os.path.exists(stats):
        return None
    text = open(stats).read()
    ins = re.search(r"^instructions: (\d+)", text, re.M)
    cyc = re.search(r"^cycles: (\d+)", text, re.M)
    if not ins or not cyc:
        return None
    return {"instructions": int(ins.group(1)), "cycles": int(cyc.group(1)), "image": out}


def build_kind(minrt):
    """CMAKE_BUILD_TYPE and MINRT_PGO of the build minrt comes from (its CMakeCache.txt)."""
    cache = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(minrt))), "CMakeCache.txt")
    found = {}
    try:
        for line in open(cache):
            m = re.match(r"(CMAKE_BUILD_TYPE|MINRT_PGO):\w+=(.*)", line.strip())
            if m:
                found[m.group(1)] = m.group(2)
    except OSError:
        return "a build without CMakeCache.txt"
    return (f"a {found.get('CMAKE_BUILD_TYPE') or 'default'} build "
            + ("with" if found.get("MINRT_PGO", "").upper() in ("ON", "1", "TRUE") else "without")
            + " profile-guided optimisation")


def replace_section(doc, section, title=SECTION):
    """doc with the section headed `title` replaced, or inserted before "## The board
    against double" (else "## Regenerating", else at the end)."""
    if title + "\n" in doc:
        a = doc.index(title + "\n")
        b = doc.find("\n## ", a + len(title))
        return doc[:a] + section + (doc[b + 1:] if b >= 0 else "")
    for anchor in ("## The board against double\n", "## Regenerating\n"):
        if anchor in doc:
            a = doc.index(anchor)
            return doc[:a] + section + doc[a:]
    return doc + ("\n" if doc and not doc.endswith("\n\n") else "") + section


def main():
    install_signal_handlers()
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--minrt", required=True)
    ap.add_argument("--host-send", required=True)
    ap.add_argument("--sim", required=True, help="firmware-sim")
    ap.add_argument("--elf", required=True, help="the rv32imf firmware")
    ap.add_argument("--shared", required=True)
    ap.add_argument("--work", required=True, help="folder for the renders")
    ap.add_argument("--doc", required=True, help="accuracy.md to update (created if missing)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--command", default="bench/accuracy/run.sh --formats")
    args = ap.parse_args()
    start = time.time()
    load_start = open("/proc/loadavg").read().split()[0]
    os.makedirs(args.work, exist_ok=True)
    figdir = os.path.join(os.path.dirname(os.path.abspath(args.doc)), "accuracy")
    os.makedirs(figdir, exist_ok=True)
    wrapper = os.path.join(args.work, "sim-with-stats.sh")
    # host-send's --sim-binary: firmware-sim with the counts, its stderr (the pty line
    # host-send waits for, then --stats) also kept in a file.
    write_atomically(wrapper, '#!/usr/bin/env bash\nexec "$MINRT_REAL_SIM" --stats --cycle-model default "$@" '
                     '2> >(tee "$MINRT_STATS_OUT" >&2)\n')
    os.chmod(wrapper, 0o755)

    pool = cf.ThreadPoolExecutor(max_workers=args.jobs)
    jobs = {}  # (format, scene, what) -> future
    scenes = {}
    done = [0]

    def submit(key, fn, *a):
        fut = pool.submit(fn, *a)
        fut.add_done_callback(lambda _f, key=key: (done.__setitem__(0, done[0] + 1), print(
            f"format_speed: {done[0]} of {len(jobs)} ({time.time() - start:.0f} s): {key[0]} {key[1]} {key[2]}",
            file=sys.stderr, flush=True)))
        jobs[key] = fut

    for name, pattern, err_extra, speed_extra, ext, speed in FORMATS:
        found = sorted(glob.glob(os.path.join(args.shared, "formats", pattern)))
        scenes[name] = found
        fdir = os.path.join(args.work, name)
        os.makedirs(fdir, exist_ok=True)
        # Slow ones first: the board and callgrind on the speed scenes.
        for s in speed:
            path = os.path.join(args.shared, "formats", os.path.dirname(pattern), s)
            board_ext = {"Jaworski": ".bmp"}.get(name, ".png")
            submit((name, s, "board"), board_counts, args.host_send, args.sim, args.elf, path, speed_extra,
                   os.path.join(fdir, os.path.splitext(s)[0] + ".board" + board_ext), args.work)
            submit((name, s, "host " + REF + " " + ext), render, args.minrt, path, speed_extra, VARIANTS[0][1],
                   os.path.join(fdir, os.path.splitext(s)[0] + ".speed-ref" + ext))
            submit((name, s, "host " + BOARD + " " + ext), render, args.minrt, path, speed_extra,
                   dict(VARIANTS)[BOARD], os.path.join(fdir, os.path.splitext(s)[0] + ".speed-board" + ext))
            for v, va in VARIANTS:
                submit((name, s, "callgrind " + v), host_instructions, args.minrt, path, speed_extra, va,
                       os.path.join(args.work, "callgrind-cache"))
        for path in found:
            for i, (v, va) in enumerate(VARIANTS):
                submit((name, os.path.basename(path), v), render, args.minrt, path, err_extra, va,
                       os.path.join(fdir, f"{os.path.splitext(os.path.basename(path))[0]}.{i}{ext}"))

    failures = []
    results = {}
    for name, pattern, err_extra, speed_extra, ext, speed in FORMATS:
        cs418 = name == "CS418"
        err = {v: [] for v, _ in VARIANTS[1:]}  # variant -> [(scene, comparison)]
        for path in scenes[name]:
            base = os.path.basename(path)
            outs = [jobs[(name, base, v)].result() for v, _ in VARIANTS]
            if any(o is None for o in outs):
                failures.append(f"{name} {base}: minrt refused a variant")
                continue
            imgs = [read_any(o) for o in outs]
            rnd = cs418 and bool(CS418_RANDOM.search(open(path, errors="replace").read()))
            for (v, _), img in zip(VARIANTS[1:], imgs[1:]):
                if img.shape != imgs[0].shape:
                    failures.append(f"{name} {base}: {v} image of another size")
                    continue
                err[v].append((base, compare(img, imgs[0], cs418, rnd)))
        speed_rows = []
        for s in speed:
            b = jobs[(name, s, "board")].result()
            ref_img = jobs[(name, s, "host " + REF + " " + ext)].result()
            board_img = jobs[(name, s, "host " + BOARD + " " + ext)].result()
            same = None
            if b and board_img:
                same = bool(np.array_equal(read_any(b["image"])[:, :, :3 if not cs418 else 4],
                                           read_any(board_img)[:, :, :3 if not cs418 else 4]))
            shape = read_any(ref_img).shape if ref_img else None
            if not b:
                failures.append(f"{name} {s}: the firmware run failed")
            speed_rows.append({"scene": s, "board": b, "same": same,
                               "size": f"{shape[1]}x{shape[0]}" if shape else "?",
                               "host": {v: jobs[(name, s, "callgrind " + v)].result() for v, _ in VARIANTS}})
        results[name] = {"err": err, "speed": speed_rows, "count": len(scenes[name])}
    pool.shutdown()

    def tot(rows):
        return {"ne": sum(c["ne"] for _, c in rows), "gt1": sum(c["gt1"] for _, c in rows),
                "gt8": sum(c["gt8"] for _, c in rows), "max": max((c["max"] for _, c in rows), default=0),
                "alpha": sum(c["alpha"] for _, c in rows), "scenes": sum(1 for _, c in rows if c["ne"]),
                "pixels": sum(c["pixels"] for _, c in rows),
                "block": min((c["block"] for _, c in rows if c["block"] is not None), default=None)}

    def fmt_db(x):
        return "∞" if x is None or math.isinf(x) else f"{x:.1f}"

    elapsed = time.time() - start
    load_end = open("/proc/loadavg").read().split()[0]
    L = [SECTION, "",
         "The text formats in every math variant minrt has for them (`--precision` and `--shims`: the "
         "policies of docs/architecture.md, the same five for every format; float/portable+fma exists only "
         "in accuracy-report, for SLD):", "",
         "- **Error**: every scene of `shared/formats/<format>` rendered by minrt against double/libm, at "
         f"the size its file gives (miniRT: {MINIRT_ERROR_SIZE}, as in "
         "[the board against double](#the-board-against-double)). Columns as above; **px > 1** = pixels "
         "with a channel off by more than 1. For CS418 the channels are SPEC.md's premultiplied RGBA "
         "(colour times alpha), **α ≠** counts pixels whose alpha differs, and **block PSNR** is SPEC.md's "
         f"metric for its random scenes (aa, dof, roughness, gi): the PSNR of {CS418_BLOCK}x{CS418_BLOCK}-"
         "block averages, the lowest over those scenes.",
         "- **Speed**, on three scenes per format, the format's heaviest on the board first (miniRT at "
         f"{MINIRT_SPEED_SIZE}): **x86-64 instructions** of the whole `minrt --threads 1 -n` process "
         f"(start-up, reading, rendering, no file written; minrt from {build_kind(args.minrt)}) "
         "counted by `valgrind --tool=callgrind`: exact, whatever the machine's load, and kept in the work "
         "folder's callgrind cache while minrt and the scene stay byte-identical.",
         "- **RV32** instructions and modelled cycles of the rv32imf firmware, from "
         "`firmware-sim --stats --cycle-model default`, the scene sent by `host-send --sim` over the raw "
         "protocol as the firmware tests do (textures and EASTRAY's preprocessing on the host, the scene "
         "behind its byte count and CRC). They include the firmware's UART polls while host-send's bytes "
         "arrive through the pseudo-terminal, so they vary between runs by up to about 0.1% on a busy "
         "machine. The firmware computes float/portable only (with `fsqrt.s`: the same bits), so the "
         "other variants have no RV32 figures; **board = host** says whether its image equals minrt's "
         "float/portable one. x86 and RV32 counts are not comparable with each other.", ""]
    plot_data = []
    for name, pattern, *_ in FORMATS:
        res = results[name]
        cs418 = name == "CS418"
        sp = res["speed"]
        host_sum = {v: (sum(r["host"][v] for r in sp) if all(r["host"][v] for r in sp) else None)
                    for v, _ in VARIANTS}
        board_ins = sum(r["board"]["instructions"] for r in sp if r["board"])
        board_cyc = sum(r["board"]["cycles"] for r in sp if r["board"])
        L += [f"### {name} ({res['count']} scenes, {os.path.dirname(pattern)})", ""]
        head = "| variant | x86 instructions, speed scenes | vs double | RV32 instructions | RV32 cycles | " \
               "scenes ≠ | px ≠ | px > 1 | px > 8 | max |"
        rule = "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        if cs418:
            head += " α ≠ | block PSNR |"
            rule += "---:|---:|"
        L += [head, rule]
        ref_host = host_sum[REF]
        points = []
        for v, _ in VARIANTS:
            hs = host_sum[v]
            rel = f"{hs / ref_host - 1:+.1%}" if hs and ref_host else "n/a"
            fw = (f"{board_ins:,} | {board_cyc:,}" if v == BOARD and all(r["board"] for r in sp)
                  else "no firmware | no firmware")
            if v == REF:
                t = {"ne": 0, "gt1": 0, "gt8": 0, "max": 0, "alpha": 0, "scenes": 0, "block": None}
                errs = "reference | 0 | 0 | 0 | 0" + (" | 0 | ∞ |" if cs418 else " |")
            else:
                t = tot(res["err"][v])
                errs = (f"{t['scenes']} | {t['ne']} | {t['gt1']} | {t['gt8']} | {t['max']} |"
                        + (f" {t['alpha']} | {fmt_db(t['block'])} |" if cs418 else ""))
            L.append(f"| {v} | {hs:,} | {rel} | {fw} | {errs}" if hs else f"| {v} | n/a | n/a | {fw} | {errs}")
            if hs:
                points.append((v, t["ne"], hs))
        L += ["", "Per speed scene: x86-64 instructions per variant; RV32 of the firmware (float/portable).", "",
              "| scene | size | " + " | ".join(v for v, _ in VARIANTS) + " | RV32 instructions | RV32 cycles | "
              "board = host |",
              "|---|---|" + "---:|" * len(VARIANTS) + "---:|---:|---|"]
        for r in sp:
            b = r["board"]
            L.append(f"| {r['scene']} | {r['size']} | "
                     + " | ".join(f"{r['host'][v]:,}" if r["host"][v] else "failed" for v, _ in VARIANTS)
                     + (f" | {b['instructions']:,} | {b['cycles']:,} |" if b else " | failed | failed |")
                     + {True: " yes |", False: " **no** |", None: " n/a |"}[r["same"]])
        L.append("")
        worst = {v: max(res["err"][v], key=lambda x: (x[1]["gt1"], x[1]["ne"]), default=None)
                 for v, _ in VARIANTS[1:]}
        w = worst[BOARD]
        if w and w[1]["gt1"]:
            L += [f"Most pixels off by more than 1 in {BOARD}: {w[0]}, {w[1]['gt1']} of {w[1]['pixels']} "
                  f"(largest error {w[1]['max']}).", ""]
        elif w:
            L += [f"No pixel of {BOARD} is off by more than 1.", ""]
        plot_data.append((name, points, board_cyc if all(r["board"] for r in sp) else None,
                          [r["scene"] for r in sp]))
    # What the numbers say, from this run's numbers.
    L += ["Reading the numbers:", ""]
    for name, *_ in FORMATS:
        res = results[name]
        host = {v: sum(r["host"][v] or 0 for r in res["speed"]) for v, _ in VARIANTS}
        if not host[REF]:
            continue
        errs = {v: tot(res["err"][v]) for v, _ in VARIANTS[1:]}
        cheaper = (f"; float/portable-min, the cheapest shims, takes "
                   f"{host['float/portable-min'] / host[BOARD] - 1:+.1%} against float/portable and changes "
                   f"{errs['float/portable-min']['ne']} pixels ({errs['float/portable-min']['gt8']} by more "
                   "than 8)" if host["float/portable-min"] else "")
        L.append(f"- **{name}**: the board's float/portable takes {host[BOARD] / host[REF] - 1:+.1%} x86 "
                 f"instructions against double/libm on the speed scenes and changes {errs[BOARD]['ne']} of "
                 f"{errs[BOARD]['pixels']} pixels ({errs[BOARD]['gt8']} by more than 8); float/libm takes "
                 f"{host['float/libm'] / host[REF] - 1:+.1%} for {errs['float/libm']['ne']} pixels" + cheaper
                 + ".")
    same = [name for name, *_ in FORMATS
            if results[name]["err"]["float/libm"] and abs(tot(results[name]["err"]["float/libm"])["ne"]
                                                        - tot(results[name]["err"][BOARD])["ne"])
            <= 0.1 * max(1, tot(results[name]["err"][BOARD])["ne"])]
    if same:
        L.append(f"- Single precision is the error, not the shims: in {', '.join(same)} float/libm (glibc's float "
                 "functions) and float/portable differ from double/libm on about the same pixels (within 10%), "
                 "so what the board's shims cost on the host buys no accuracy there; on the board "
                 "float/portable is the only variant.")
    L += ["", "![speed against error, per format](accuracy/formats-speed-vs-error.png)", "",
          f"Made by `{args.command}` in {elapsed:.0f} s of wall time on the {cpu_model()} "
          f"({os.cpu_count()} cores shared with other work: one-minute load average {load_start} at the start, "
          f"{load_end} at the end; {args.jobs} runs at a time; {len(CACHE_HITS)} of "
          f"{sum(1 for k in jobs if k[2].startswith('callgrind'))} callgrind counts came from the cache). "
          "The instruction counts do not depend on the load.", "", ""]
    if failures:
        L[-1:-1] = ["Failed: " + "; ".join(failures) + ".", ""]
    plots.formats_speed_vs_error(plot_data, REF, os.path.join(figdir, "formats-speed-vs-error.png"))
    section = "\n".join(L)
    try:
        doc = open(args.doc).read()
    except FileNotFoundError:
        doc = ""
    write_atomically(args.doc, replace_section(doc, section))
    print(f"format_speed: wrote {args.doc} and {figdir}/formats-speed-vs-error.png in {elapsed:.0f} s",
          file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
