#!/usr/bin/python3
"""Renders every scene in every math variant and writes accuracy.md and its
pictures (accuracy/*.png) into the --out folder (docs/ regenerates the
tracked docs/accuracy.md). One progress line per finished step on stderr.

Run through bench/accuracy/run.sh, which builds accuracy-report first. Needs
Debian's python3-numpy and python3-matplotlib (use /usr/bin/python3).
"""
import argparse
import concurrent.futures as cf
import glob
import math
import os
import re
import hashlib
import shutil
import subprocess
import sys
import threading
import time

import numpy as np

from machine import cpu_model
from safe_output import install_signal_handlers, write_atomically

import plots

VARIANTS = [  # (name, file tag), reference first
    ("double/libm", "double-libm"),
    ("float/libm", "float-libm"),
    ("float/portable", "float-portable"),
    ("float/portable-fast", "float-portable-fast"),
    ("float/portable-min", "float-portable-min"),
    ("float/portable+fma", "float-portable-fma"),
]
REF = "double-libm"
MODEL = "float-portable"
SIZE = 128
SPEED_SCENE = "contest"

# The rv32imf firmware under models of a course team's FPU: every
# firmware-sim model file (--fpu-model, docs/firmware_sim.md "FPU models") in
# this folder, each named by its "# unit: NAME" line; the IEEE row is the
# simulator's own exact model file.
FPU_MODEL_DIR = os.path.join("bench", "accuracy", "fpu-models")
IEEE_MODEL = os.path.join("firmware_sim", "models", "fpu-ieee.cfg")
FPU_ISA = "rv32imf"
CHECK_OPS = ["fadd", "fsub", "fmul", "fdiv", "fsqrt"]


# The text formats' hard cases (bench/accuracy/hard_cases.py's section).
HARD_CASES_TESTS = (
    "`test/hard/format_hard_cases_test.cpp` (ctest `hard: ...`) renders every scene of "
    "`test/hard/scenes/<format>` in every variant through minrt's format sides and checks: every "
    "render succeeds at the scene's size, the binary, 16-byte and widest BVH walks (EASTRAY: its "
    "object hierarchy and the plain CSG walk) give the same bytes, each float variant's bad pixels "
    "stay within [test/hard/scenes/README.md](../test/hard/scenes/README.md)'s bounds, and every "
    "`bad/` file is refused with one located line; `hard_case_fixes_test.cpp` pins what they "
    "found at its cause.\n")

def read_model(path):
    """(unit name, {key: value}) of a firmware-sim FPU model file."""
    name, keys = None, {}
    for line in open(path):
        m = re.match(r"\s*#\s*unit:\s*(.+?)\s*$", line)
        if m and name is None:
            name = m.group(1)
        line = line.split("#", 1)[0]
        if "=" in line:
            key, value = line.split("=", 1)
            keys[key.strip()] = value.strip()
    return name or os.path.splitext(os.path.basename(path))[0], keys


def fpu_models(root):
    """[(unit name, file tag, model path relative to root, {key: value})], by file name
    with numbers in numeric order (recip8n1 before recip10n1)."""
    def natural(path):
        return [int(p) if p.isdigit() else p for p in re.split(r"(\d+)", os.path.basename(path))]
    models = []
    for path in sorted(glob.glob(os.path.join(root, FPU_MODEL_DIR, "*.cfg")), key=natural):
        name, keys = read_model(path)
        tag = "fpu-" + os.path.splitext(os.path.basename(path))[0]
        models.append((name, tag, os.path.relpath(path, root), keys))
    return models


def read_ppm(path):
    """P3 or P6 (maxval 255) as an HxWx3 uint8 array."""
    data = open(path, "rb").read()
    tokens = data.split(None, 4)
    magic, w, h = tokens[0], int(tokens[1]), int(tokens[2])
    if magic == b"P6":
        pixels = np.frombuffer(data[len(data) - w * h * 3:], np.uint8)
    elif magic == b"P3":
        pixels = np.array(tokens[4].split(), dtype=np.int64).astype(np.uint8)
    else:
        raise ValueError(f"{path}: not a PPM")
    if pixels.size != w * h * 3:
        raise ValueError(f"{path}: incomplete image")
    return pixels.reshape(h, w, 3)


def compare(a, b):
    """max channel error, differing pixels, pixels off by more than 8, PSNR."""
    err = np.abs(a.astype(np.int32) - b.astype(np.int32))
    per_pixel = err.max(axis=2)
    mse = float((err.astype(np.float64) ** 2).mean())
    psnr = math.inf if mse == 0 else 10 * math.log10(255.0 ** 2 / mse)
    return {"max": int(err.max()), "diff": int((per_pixel > 0).sum()),
            "over8": int((per_pixel > 8).sum()), "psnr": psnr, "map": per_pixel}


def render(tool, scene, outdir):
    r = subprocess.run([tool, "--size", f"{SIZE}x{SIZE}", "--out", outdir, scene],
                       capture_output=True, text=True)
    return scene, r.returncode, r.stderr


def firmware_command(sim, elf, scene, outfile, options):
    return [sim, "--stats", *options, "--uart-in", scene, "--uart-out", outfile, elf, "--",
            "--size", f"{SIZE}x{SIZE}", "--format", "p6"]


def firmware_cache_key(sim, elf, scene, options, files):
    """Hash of everything a firmware run depends on: simulator, ELF, scene, options and
    the contents of the files they name (a cycle model)."""
    h = hashlib.sha256()
    for path in (sim, elf, scene, *files):
        h.update(open(path, "rb").read())
    h.update(" ".join(firmware_command("", "", "", "", options)).encode())
    return h.hexdigest()[:32]


def run_firmware(sim, elf, scene, outfile, cache_dir, options=("--cycle-model", "default"),
                 files=()):
    """--stats figures of one firmware run, output kept: {"instructions", "cycles",
    "fp_div", "fp_sqrt" (with a cycle model), "cached"}, or None if it failed.

    The soft-float run takes many minutes and the FPU-model runs are many, so the
    --stats text and image are kept in cache_dir under a hash of the simulator, ELF,
    scene, options and model files; a run is reused only when all are byte-identical."""
    key = firmware_cache_key(sim, elf, scene, options, files)
    stats_path = os.path.join(cache_dir, key + ".stats")
    image_path = os.path.join(cache_dir, key + ".ppm")
    cached = os.path.exists(stats_path) and os.path.exists(image_path)
    if cached:
        stats = open(stats_path).read()
        shutil.copyfile(image_path, outfile)
    else:
        r = subprocess.run(firmware_command(sim, elf, scene, outfile, list(options)),
                           capture_output=True, text=True)
        if r.returncode != 0:
            return None
        stats = r.stderr
        os.makedirs(cache_dir, exist_ok=True)
        # Whole or not at all: a cut-off entry would be taken as a cached run.
        with open(outfile, "rb") as f:
            write_atomically(image_path, f.read())
        write_atomically(stats_path, stats)
    ins = re.search(r"^instructions: (\d+)", stats, re.M)
    cyc = re.search(r"^cycles: (\d+)", stats, re.M)
    if not ins or not cyc:
        return None
    mix = lambda cls: re.search(rf"^instruction mix:.* {cls}=(\d+)", stats, re.M)  # noqa: E731
    mips = re.search(r"^host MIPS: ([0-9.]+)", stats, re.M)
    seconds = int(ins.group(1)) / (float(mips.group(1)) * 1e6) if mips and float(mips.group(1)) else 0
    return {"instructions": int(ins.group(1)), "cycles": int(cyc.group(1)), "cached": cached,
            "seconds": seconds,
            "fp_div": int(mix("fp_div").group(1)) if mix("fp_div") else 0,
            "fp_sqrt": int(mix("fp_sqrt").group(1)) if mix("fp_sqrt") else 0}


def fpu_check(sim, model):
    """firmware-sim --fpu-model FILE --fpu-check: op -> (max error as printed, "meet"/"MISS")."""
    r = subprocess.run([sim, "--fpu-model", model, "--fpu-check"], capture_output=True, text=True)
    out = {}
    for line in r.stdout.splitlines():
        words = line.split()
        if words and words[0] in CHECK_OPS and len(words) >= 4:
            out[words[0]] = (words[-3], words[-1])
    return out


def default_latencies(root):
    """fp_add, fp_mul, fp_div, fp_sqrt of the built-in cycle model (its source file)."""
    lat = {}
    for line in open(os.path.join(root, "firmware_sim", "models", "default.cfg")):
        m = re.match(r"\s*(fp_add|fp_mul|fp_div|fp_sqrt)\s*=\s*(\d+)", line)
        if m:
            lat[m.group(1)] = int(m.group(2))
    return lat


def unit_latencies(keys, lat):
    """fp_div and fp_sqrt of the unit a model file describes, assuming one cycle for the
    table, the default model's fp_mul/fp_add per dependent operation, no pipelining:
    reciprocal step = 2 mul + 1 sub, inverse-square-root step = 3 mul + 1 sub, then the
    final multiply. Exact ops keep the default model's latency."""
    div, sqrt = lat["fp_div"], lat["fp_sqrt"]
    if keys.get("div") == "recip-mul":
        n = int(keys.get("recip_newton_steps", 1))
        div = 1 + n * (2 * lat["fp_mul"] + lat["fp_add"]) + lat["fp_mul"]
    if keys.get("sqrt") == "table-newton":
        n = int(keys.get("rsqrt_newton_steps", 1))
        sqrt = 1 + n * (3 * lat["fp_mul"] + lat["fp_add"]) + lat["fp_mul"]
    return div, sqrt


def run_callgrind(tool, variant, scene):
    """x86-64 instructions (callgrind Ir) of accuracy-report rendering one variant."""
    cmd = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", tool,
           "--variant", variant, "--size", f"{SIZE}x{SIZE}", scene]
    r = subprocess.run(cmd, capture_output=True, text=True)
    m = re.search(r"Collected : (\d+)", r.stderr)
    return int(m.group(1)) if r.returncode == 0 and m else None


def kept_section(path, heading):
    """The section of the current document that starts at heading, up to the
    next one (without its trailing newline), or None."""
    try:
        with open(path) as f:
            doc = f.read()
    except OSError:
        return None
    a = doc.find(heading + "\n")
    if a < 0:
        return None
    b = doc.find("\n## ", a + len(heading))
    return doc[a:b if b >= 0 else len(doc)].rstrip("\n") + "\n"


def fmt_psnr(p):
    return "∞" if math.isinf(p) else f"{p:.1f}"


def heat_map(scene, images, outpath):
    plots.heat_map(f"{scene} at {SIZE}x{SIZE}: largest channel error per pixel against double/libm",
                   images[REF], "double/libm",
                   [(name, images[tag]) for name, tag in VARIANTS if tag != REF], outpath)


class Progress:
    """Prints "accuracy: step n of N (elapsed): what" on stderr as each
    background job finishes, so a run of minutes shows it is moving."""

    def __init__(self, start):
        self.start, self.jobs, self.done, self.lock = start, [], 0, threading.Lock()

    def track(self, job, what):
        self.jobs.append((job, what))
        return job

    def begin(self):
        """Called once every job is submitted: N is known from here on."""
        for job, what in self.jobs:
            job.add_done_callback(lambda _, what=what: self.step(what))

    def step(self, what):
        with self.lock:
            self.done += 1
            print(f"accuracy: step {self.done} of {len(self.jobs)} ({time.time() - self.start:.0f} s): "
                  f"{what}", file=sys.stderr, flush=True)


def main():
    install_signal_handlers()
    ap = argparse.ArgumentParser()
    ap.add_argument("--tool", required=True)
    ap.add_argument("--root", required=True)
    ap.add_argument("--shared", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--out", required=True, help="folder for accuracy.md and accuracy/*.png")
    ap.add_argument("--sim")
    ap.add_argument("--firmware-dir")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--firmware-isas", default="rv32imf,rv32im")
    ap.add_argument("--no-cache", action="store_true", help="rerun the firmware even if cached")
    ap.add_argument("--command", default="bench/accuracy/run.sh")
    args = ap.parse_args()
    start = time.time()
    imgdir = os.path.join(args.work, "images")
    os.makedirs(imgdir, exist_ok=True)
    docdir = os.path.join(args.out, "accuracy")
    os.makedirs(docdir, exist_ok=True)
    progress = Progress(start)

    course = sorted(glob.glob(os.path.join(args.shared, "scenes", "*.sld")))
    hard = sorted(glob.glob(os.path.join(args.root, "sld", "hard", "*.sld")))
    speed_scene = os.path.join(args.shared, "scenes", SPEED_SCENE + ".sld")
    stem = lambda p: os.path.splitext(os.path.basename(p))[0]  # noqa: E731

    # Slow measurements first, in the background, while the renders run.
    pool = cf.ThreadPoolExecutor(max_workers=args.jobs)
    fw_jobs = {}
    if args.sim and args.firmware_dir and os.path.exists(speed_scene):
        cache_dir = os.path.join(args.work, "firmware-cache")
        if args.no_cache and os.path.isdir(cache_dir):
            shutil.rmtree(cache_dir)
        for isa in args.firmware_isas.split(","):
            elf = os.path.join(args.firmware_dir, f"minrt-{isa}.elf")
            if os.path.exists(elf):
                out = os.path.join(args.work, f"firmware-{isa}-{SPEED_SCENE}.ppm")
                fw_jobs[isa] = (progress.track(pool.submit(run_firmware, args.sim, elf, speed_scene,
                                                           out, cache_dir),
                                               f"firmware {isa} on {SPEED_SCENE}.sld"), out)
    cg_jobs = {tag: progress.track(pool.submit(run_callgrind, args.tool, tag, speed_scene),
                                   f"callgrind {tag} on {SPEED_SCENE}.sld")
               for _, tag in VARIANTS} if os.path.exists(speed_scene) else {}
    render_jobs = [progress.track(pool.submit(render, args.tool, s, imgdir),
                                  f"rendered {os.path.basename(s)} in {len(VARIANTS)} variants")
                   for s in course + hard]
    # FPU models: contest under the cycle model (with the unit's fp_div/fp_sqrt
    # latencies) for the counts, every course scene for the error.
    fpu_jobs = {}  # tag -> {"check": job, "latency": (div, sqrt), scene -> (job, image)}
    ieee_check = None
    fpu_elf = os.path.join(args.firmware_dir or "", f"minrt-{FPU_ISA}.elf")
    lat = default_latencies(args.root)
    models = fpu_models(args.root)
    if fw_jobs and FPU_ISA in fw_jobs and os.path.exists(fpu_elf):
        fpu_dir = os.path.join(args.work, "fpu-models")
        os.makedirs(fpu_dir, exist_ok=True)
        ieee_check = progress.track(pool.submit(fpu_check, args.sim, os.path.join(args.root, IEEE_MODEL)),
                                    "operation check of the IEEE FPU model")
        for _, tag, model, keys in models:
            model = os.path.join(args.root, model)
            div, sqrt = unit_latencies(keys, lat)
            cfg = os.path.join(fpu_dir, tag + ".cfg")
            write_atomically(cfg, f"# the default model with this unit's latencies\nfp_div = {div}\n"
                             f"fp_sqrt = {sqrt}\n")
            jobs = {"check": progress.track(pool.submit(fpu_check, args.sim, model),
                                            f"operation check of FPU model {tag}"),
                    "latency": (div, sqrt)}
            for scene in course:
                image = os.path.join(fpu_dir, f"{stem(scene)}.{tag}.ppm")
                timed = stem(scene) == SPEED_SCENE
                options = ["--fpu-model", model] + (["--cycle-model", cfg] if timed else [])
                jobs[stem(scene)] = (progress.track(
                    pool.submit(run_firmware, args.sim, fpu_elf, scene, image, cache_dir, options,
                                [model] + ([cfg] if timed else [])),
                    f"firmware {FPU_ISA} on {stem(scene)}.sld under FPU model {tag}"), image)
            fpu_jobs[tag] = jobs
    progress.begin()
    failures = []
    warnings = {}  # scene -> distinct warning texts (the same in every variant)
    for job in render_jobs:
        scene, rc, err = job.result()
        if rc != 0:
            failures.append(f"{os.path.basename(scene)}: status {rc} {err.strip()}")
        texts = sorted({line.split(": warning: ", 1)[1] for line in err.splitlines()
                        if ": warning: " in line})
        if texts:
            warnings[os.path.basename(scene)] = texts
            if scene in hard:
                failures.append(f"{os.path.basename(scene)}: unexpected warning")

    rows = {}  # scene -> tag -> comparison
    images = {}
    ref_check = {}
    for s in course + hard:
        name = stem(s)
        images[name] = {tag: read_ppm(os.path.join(imgdir, f"{name}.{tag}.ppm"))
                        for _, tag in VARIANTS}
        rows[name] = {tag: (compare(images[name][tag], images[name][REF]),
                            compare(images[name][tag], images[name][MODEL]))
                      for _, tag in VARIANTS}
        orig = os.path.join(args.shared, "reference", str(SIZE), name + ".ppm")
        if s in course and os.path.exists(orig):
            ref_check[name] = bool(np.array_equal(read_ppm(orig), images[name][REF]))

    firmware = {}
    for isa, (job, out) in fw_jobs.items():
        res = job.result()
        same = None
        if res and os.path.exists(out):
            same = bool(np.array_equal(read_ppm(out), images[SPEED_SCENE][MODEL]))
        firmware[isa] = (res, same)
    callgrind = {tag: job.result() for tag, job in cg_jobs.items()}
    # FPU variants: per course scene, (against double/libm, against float/portable).
    fpu = {}  # tag -> {"check", "latency", "speed", "rows": scene -> comparisons}
    fpu_runs = []  # every FPU-model run's --stats figures
    for tag, jobs in fpu_jobs.items():
        entry = {"check": jobs["check"].result(), "latency": jobs["latency"], "rows": {},
                 "speed": None, "images": {}}
        for scene in course:
            job, image = jobs[stem(scene)]
            res = job.result()
            if not res:
                failures.append(f"{stem(scene)}.sld: firmware under FPU model {tag} failed")
                continue
            fpu_runs.append(res)
            if stem(scene) == SPEED_SCENE:
                entry["speed"] = res
            img = read_ppm(image)
            entry["images"][stem(scene)] = img
            entry["rows"][stem(scene)] = (compare(img, images[stem(scene)][REF]),
                                          compare(img, images[stem(scene)][MODEL]))
        fpu[tag] = entry
    ieee_check = ieee_check.result() if ieee_check else {}
    pool.shutdown()

    def totals(group, tag, which):
        cs = [rows[stem(s)][tag][which] for s in group]
        finite = [c["psnr"] for c in cs if not math.isinf(c["psnr"])]
        return {"max": max(c["max"] for c in cs), "diff": sum(c["diff"] for c in cs),
                "over8": sum(c["over8"] for c in cs),
                "scenes": sum(1 for c in cs if c["diff"] > 0),
                "minpsnr": min(finite) if finite else math.inf}

    out = []
    w = out.append
    w("# Accuracy of the math variants\n")
    w("Generated by `bench/accuracy/run.sh` (do not edit by hand); the exact command is at "
      "the end. Every scene is rendered at "
      f"{SIZE}x{SIZE} by `{os.path.relpath(args.tool, args.root)}` in each variant, in-process:\n")
    w("| variant | what |\n|---|---|")
    w("| double/libm | `LibmDouble`: the reference, byte-identical to the original program |")
    w("| float/libm | `LibmFloat`: float with glibc's `sqrtf sinf cosf atanf floorf` |")
    w("| float/portable | `PortableFloat`: float shims from add/sub/mul/div only; the firmware's model |")
    w("| float/portable-fast | `PortableFloatFast`: the cheaper shims (within 2.6 ULP) |")
    w("| float/portable-min | `PortableFloatMin`: the cheapest shims that still meet the course's "
      "error rules (2^-18 sin/cos, 2^-20 sqrt/atan; docs/shims.md) |")
    w("| float/portable+fma | `PortableFloat` compiled with `-ffp-contract=fast -mfma -O2` "
      "(tools/accuracy/fma_variant.cpp): the compiler fuses a*b+c into one rounding, "
      "as an FPU with `fmadd.s` and a contracting compiler would |\n")
    w("The rv32imf firmware is also rendered through `firmware-sim` under models of course "
      "teams' own FPUs (approximate division and square root, truncation): see "
      "[FPU models in the firmware](#fpu-models-in-the-firmware).\n")
    w("Columns: **max** = largest error of one colour channel (0–255); **px ≠** = pixels "
      "with any channel different; **px > 8** = pixels with a channel off by more than 8; "
      "**PSNR** in dB over all channels (∞ = identical; the minimum over the scenes that "
      "differ); **scenes ≠** = scenes with at least one differing pixel. "
      f"Each scene has {SIZE * SIZE} pixels.\n")

    w("## The reference\n")
    ok = sum(ref_check.values())
    w(f"double/libm equals the original program's output (`shared/reference/{SIZE}`) "
      f"pixel for pixel on **{ok} of {len(ref_check)}** course scenes"
      + ("." if ok == len(ref_check) else
         ": differs on " + ", ".join(k for k, v in ref_check.items() if not v) + ".") + "\n")
    if warnings:
        w("Reader warnings (the lattice scenes' are expected, see docs/format.md; the hard "
          "scenes must have none):\n")
        for name, texts in sorted(warnings.items()):
            w(f"- {name}: " + "; ".join(texts))
        w("")
    if failures:
        w("Renders that failed:\n")
        for f in failures:
            w(f"- {f}")
        w("")

    hard_but_huge = [s for s in hard if stem(s) != "huge"]
    for title, group in (("Course scenes (`shared/scenes`, 25)", course),
                         (f"Hard scenes (`sld/hard`, {len(hard)})", hard),
                         ("Hard scenes without huge.sld (which no float variant can render)",
                          hard_but_huge)):
        w(f"## {title}: summary\n")
        w("| variant | against | max | px ≠ | px > 8 | scenes ≠ | min PSNR |")
        w("|---|---|---:|---:|---:|---:|---:|")
        for name, tag in VARIANTS[1:]:
            for which, against in ((0, "double/libm"), (1, "float/portable")):
                if which == 1 and tag == MODEL:
                    continue
                t = totals(group, tag, which)
                w(f"| {name} | {against} | {t['max']} | {t['diff']} | {t['over8']} | "
                  f"{t['scenes']} | {fmt_psnr(t['minpsnr'])} |")
        w("")

    # What the numbers say, with the numbers of this run.
    fp = totals(course, MODEL, 0)
    fl = totals(course, "float-libm", 1)
    ff = totals(course, "float-portable-fast", 1)
    fm = totals(course, "float-portable-fma", 1)
    fmr = totals(course, "float-portable-fma", 0)
    w("## Reading the numbers\n")
    w(f"- **Float itself is the error, not the shims.** On the course scenes float/portable "
      f"differs from the original on {fp['diff']} pixels ({fp['over8']} by more than 8), but "
      f"from float/libm (glibc's float functions) on only {fl['diff']}: the portable shims are "
      "as good as the C library's, and what separates every float variant from the original "
      "is single-precision arithmetic in the tracer (hit tests near edges and grazing angles "
      "flip, then a whole pixel changes colour: the errors are few but large, see the heat maps).")
    w(f"- **float/portable-fast** moves {ff['diff']} pixels away from float/portable "
      f"({ff['over8']} by more than 8) on the course scenes, for "
      + (f"{1 - callgrind['float-portable-fast'] / callgrind['float-portable']:.1%} fewer "
         "host instructions. " if callgrind.get("float-portable-fast") and
         callgrind.get("float-portable") else "")
      + "Against the original it is about as far as float/portable.")
    fmin = totals(course, "float-portable-min", 1)
    fminr = totals(course, "float-portable-min", 0)
    w(f"- **float/portable-min** (the minimum the course's error rules allow) moves "
      f"{fmin['diff']} pixels away from float/portable ({fmin['over8']} by more than 8) on the "
      f"course scenes ({fminr['diff']} from the original, {fminr['over8']} by more than 8), for "
      + (f"{1 - callgrind['float-portable-min'] / callgrind['float-portable']:.1%} fewer "
         "host instructions than float/portable"
         + (f" and {1 - callgrind['float-portable-min'] / callgrind['float-portable-fast']:.1%} "
            "fewer than float/portable-fast" if callgrind.get("float-portable-fast") else "")
         + "." if callgrind.get("float-portable-min") and callgrind.get("float-portable")
         else "its instruction count see the speed table."))
    w(f"- **Multiply-add contraction changes the picture more than any choice of shims:** "
      f"float/portable+fma differs from float/portable on {fm['diff']} pixels "
      f"({fm['over8']} by more than 8) but is not closer to the original ({fmr['diff']} "
      f"pixels differ, {fmr['over8']} by more than 8). A simulator or FPU that fuses "
      "`a*b+c` therefore cannot be checked bit for bit against the host's float/portable "
      "images; the project builds with `-ffp-contract=off` for this reason.")
    w("- **huge.sld** (coordinates of 1e6) cannot be rendered in single precision at all: the "
      "float spacing there (0.06) is larger than the tracer's fixed offsets (0.01 to 0.1), so "
      "nearly every pixel is wrong in every float variant. The other hard scenes stay close to "
      "the reference; rot90-objects, camera-inside and texture-far have the largest local "
      "errors (objects or texture cells flipping at an edge).\n")

    def per_scene_table(title, which, shown):
        w(f"## {title}\n")
        w("Each cell: max / px ≠ / px > 8 / PSNR. Hard scenes are marked *.\n")
        w("| scene | " + " | ".join(n for n, _ in shown) + " |")
        w("|---|" + "---|" * len(shown))
        for s in course + hard:
            cells = []
            for _, tag in shown:
                c = rows[stem(s)][tag][which]
                cells.append(f"{c['max']} / {c['diff']} / {c['over8']} / {fmt_psnr(c['psnr'])}")
            w(f"| {stem(s)}{' *' if s in hard else ''} | " + " | ".join(cells) + " |")
        w("")

    per_scene_table("Per scene, against double/libm", 0, VARIANTS[1:])
    per_scene_table("Per scene, against float/portable (the firmware's model)", 1,
                    [v for v in VARIANTS if v[1] != MODEL])


    # FPU models: the units, then speed and error.
    fpu_shown = [(n, t, m) for n, t, m, _ in models if t in fpu and fpu[t]["rows"]]
    ieee_fw = firmware.get(FPU_ISA, (None, None))[0]
    if fpu_shown:
        def fpu_totals(tag, which):
            cs = [fpu[tag]["rows"][stem(s)][which] for s in course if stem(s) in fpu[tag]["rows"]]
            finite = [c["psnr"] for c in cs if not math.isinf(c["psnr"])]
            return {"max": max(c["max"] for c in cs), "diff": sum(c["diff"] for c in cs),
                    "over8": sum(c["over8"] for c in cs),
                    "scenes": sum(1 for c in cs if c["diff"] > 0),
                    "minpsnr": min(finite) if finite else math.inf, "count": len(cs)}

        def meets(check):
            return bool(check) and all(check.get(op, ("", "MISS"))[1] == "meet" for op in CHECK_OPS)

        def check_cell(check, op):
            err, verdict = check.get(op, ("n/a", "n/a"))
            return f"{err} {'meet' if verdict == 'meet' else '**' + verdict + '**'}"

        def err_cell(t):
            return f"{t['max']} / {t['diff']} / {t['over8']} / {fmt_psnr(t['minpsnr'])}"

        w("## FPU models in the firmware\n")
        w(f"The {FPU_ISA} firmware rendered by `firmware-sim` with a model of a course team's FPU "
          "in place of the exact IEEE one (`firmware-sim --fpu-model FILE`, one file per unit in "
          f"[{FPU_MODEL_DIR}](../{FPU_MODEL_DIR}); the arithmetic is defined "
          "bit for bit in [firmware_sim.md](firmware_sim.md#fpu-models)). The firmware is "
          "unchanged: its shims build sin, cos and atan from the modelled add, mul and div, so "
          "the model's error reaches them too. Every course scene is rendered at "
          f"{SIZE}x{SIZE}, and {SPEED_SCENE}.sld also under the cycle model for the counts. The "
          "IEEE row is the same firmware with the exact FPU, whose output is the host's "
          "float/portable image (the firmware tests check that on every course scene).\n")
        w("The error columns of the first table are `firmware-sim --fpu-model FILE --fpu-check`: the "
          "largest error of each operation over random, edge and exhaustive operands, as the "
          "course's rules measure it (relative, with a floor of 2^-126), against the rules "
          "2^-23 (fadd, fsub), 2^-22 (fmul), 2^-20 (fdiv, fsqrt).\n")
        w("Latencies are an assumption, not a measurement: the default cycle model with fp_div "
          "and fp_sqrt set to what each unit needs if the table takes one cycle and every "
          f"dependent operation after it the default fp_mul/fp_add ({lat['fp_mul']}/"
          f"{lat['fp_add']} cycles), without pipelining: 1 + N (2 mul + 1 sub) + 1 mul for the "
          "divider, 1 + N (3 mul + 1 sub) + 1 mul for the square root. An exact divider or "
          f"square root keeps the default's {lat['fp_div']} and {lat['fp_sqrt']}.\n")
        def model_cell(path):
            keys = read_model(os.path.join(args.root, path))[1]
            return (f"[{os.path.basename(path)}](../{path})" +
                    (": " + ", ".join(f"`{k}={v}`" for k, v in keys.items()) if path != IEEE_MODEL else ""))

        w("| unit | model file | fadd | fsub | fmul | fdiv | fsqrt | fp_div / fp_sqrt cycles |")
        w("|---|---|---|---|---|---|---|---:|")
        w(f"| IEEE | {model_cell(IEEE_MODEL)} | " + " | ".join(check_cell(ieee_check, op) for op in CHECK_OPS)
          + f" | {lat['fp_div']} / {lat['fp_sqrt']} |")
        for name, tag, model in fpu_shown:
            div, sqrt = fpu[tag]["latency"]
            w(f"| {name} | {model_cell(model)} | "
              + " | ".join(check_cell(fpu[tag]["check"], op) for op in CHECK_OPS)
              + f" | {div} / {sqrt} |")
        w("")
        w(f"Speed on {SPEED_SCENE}.sld at {SIZE}x{SIZE}; error over the {len(course)} course "
          "scenes (each cell: max / px ≠ / px > 8 / min PSNR):\n")
        w("| unit | RV32 instructions | modelled cycles | fdiv.s / fsqrt.s executed | "
          "against double/libm | against float/portable |")
        w("|---|---:|---:|---:|---|---|")
        if ieee_fw:
            zero = {"max": 0, "diff": 0, "over8": 0, "minpsnr": math.inf}
            w(f"| IEEE | {ieee_fw['instructions']:,} | {ieee_fw['cycles']:,} | "
              f"{ieee_fw['fp_div']:,} / {ieee_fw['fp_sqrt']:,} | "
              f"{err_cell(totals(course, MODEL, 0))} | {err_cell(zero)} |")
        for name, tag, _ in fpu_shown:
            sp = fpu[tag]["speed"]
            speed = (f"{sp['instructions']:,} | {sp['cycles']:,} | {sp['fp_div']:,} / "
                     f"{sp['fp_sqrt']:,}") if sp else "failed | failed | failed"
            w(f"| {name} | {speed} | {err_cell(fpu_totals(tag, 0))} | "
              f"{err_cell(fpu_totals(tag, 1))} |")
        w("")
        # What these numbers say, from this run's numbers.
        w("Reading the numbers:\n")
        fl = totals(course, "float-libm", 1)
        for name, tag, _ in fpu_shown:
            t, sp = fpu_totals(tag, 1), fpu[tag]["speed"]
            verdict = ("meets every rule" if meets(fpu[tag]["check"]) else "misses " + ", ".join(
                op for op in CHECK_OPS if fpu[tag]["check"].get(op, ("", "MISS"))[1] != "meet"))
            line = (f"- **{name}** ({verdict}): {t['diff']} pixels of the course scenes differ "
                    f"from float/portable, {t['over8']} by more than 8, on {t['scenes']} scenes")
            if sp and ieee_fw:
                line += (f"; {SPEED_SCENE} takes {sp['cycles'] / ieee_fw['cycles'] - 1:+.2%} "
                         "modelled cycles against the IEEE firmware")
            w(line + ".")
        good = [fpu_totals(t, 1)["diff"] for _, t, _ in fpu_shown if meets(fpu[t]["check"])]
        bad = [fpu_totals(t, 1)["diff"] for _, t, _ in fpu_shown if not meets(fpu[t]["check"])]
        if good and bad:
            w("- Meeting the rules " + ("does" if max(good) < min(bad) else "does not always")
              + f" keep a unit closer to float/portable: units that meet them change {min(good)} "
              f"to {max(good)} pixels, units that miss them {min(bad)} to {max(bad)}. For scale, "
              f"float/libm (glibc's float functions on exact IEEE arithmetic) differs from "
              f"float/portable on {fl['diff']} pixels.")
        ref_good = [fpu_totals(t, 0)["diff"] for _, t, _ in fpu_shown if meets(fpu[t]["check"])]
        if ref_good:
            w(f"- Against the original (double/libm), the units that meet the rules differ on "
              f"{min(ref_good)} to {max(ref_good)} pixels where the exact float FPU differs on "
              f"{totals(course, MODEL, 0)['diff']}"
              + (": within the course's bounds an FPU at most doubles the pixels that single "
                 "precision already changes." if max(ref_good) < 2 * totals(course, MODEL, 0)["diff"]
                 else "."))
        w("")
        w("Per scene, against float/portable (max / px ≠ / px > 8 / PSNR):\n")
        w("| scene | " + " | ".join(n for n, _, _ in fpu_shown) + " |")
        w("|---|" + "---|" * len(fpu_shown))
        for sc in course:
            cells = []
            for _, tag, _ in fpu_shown:
                c = fpu[tag]["rows"].get(stem(sc))
                cells.append(f"{c[1]['max']} / {c[1]['diff']} / {c[1]['over8']} / "
                             f"{fmt_psnr(c[1]['psnr'])}" if c else "failed")
            w(f"| {stem(sc)} | " + " | ".join(cells) + " |")
        w("")
        # What each unit does to the picture: the speed scene and the scene the
        # units change most, each model's render beside the IEEE one.
        changed = lambda sc: sum(fpu[t]["rows"][sc][1]["diff"]  # noqa: E731
                                 for _, t, _ in fpu_shown if sc in fpu[t]["rows"])
        others = sorted((stem(sc) for sc in course if stem(sc) != SPEED_SCENE), key=changed, reverse=True)
        gallery = [sc for sc in [SPEED_SCENE] + others[:1]
                   if all(sc in fpu[t]["images"] for _, t, _ in fpu_shown)]
        if gallery:
            plots.fpu_gallery([(sc, "IEEE FPU", images[sc][MODEL],
                                [(name, fpu[tag]["images"][sc]) for name, tag, _ in fpu_shown])
                               for sc in gallery], os.path.join(docdir, "fpu-models.png"))
            w(f"What each unit does to the picture ({' and '.join(s + '.sld' for s in gallery)} at "
              f"{SIZE}x{SIZE}; {gallery[-1]} is the course scene the units change most): the IEEE "
              "firmware's render (the host's float/portable image) beside each model's, and under "
              "each render its largest channel error per pixel against the IEEE one (the heat "
              "maps' power scale).\n")
            w("![the FPU models' renders](accuracy/fpu-models.png)\n")

    w(f"## Speed: {SPEED_SCENE}.sld at {SIZE}x{SIZE}\n")
    w("| variant | RV32 firmware instructions | RV32 modelled cycles (default model) | "
      "x86-64 instructions of accuracy-report (callgrind, host) |")
    w("|---|---:|---:|---:|")
    fw_of = {"float-portable": [("rv32imf", "minrt-rv32imf.elf (hardware F)"),
                                ("rv32im", "minrt-rv32im.elf (soft float)")]}
    for name, tag in VARIANTS:
        cg = callgrind.get(tag)
        cgs = f"{cg:,}" if cg else "n/a"
        fws = fw_of.get(tag)
        if not fws:
            w(f"| {name} | no firmware | no firmware | {cgs} |")
            continue
        for isa, label in fws:
            res, same = firmware.get(isa, (None, None))
            if res:
                w(f"| {name}, {label} | {res['instructions']:,} | {res['cycles']:,} | {cgs} |")
            else:
                w(f"| {name}, {label} | not measured | not measured | {cgs} |")
    w("")
    for isa, (res, same) in firmware.items():
        if same is not None:
            w(f"- firmware `minrt-{isa}.elf` output on {SPEED_SCENE} "
              f"{'**equals**' if same else '**differs from**'} the host's float/portable image"
              + (" (counts reused from the firmware cache: same simulator, ELF, scene and "
                 "arguments as a previous run)." if res and res["cached"] else "."))
    w("- The x86 counts are the whole `accuracy-report --variant V` process (start-up, "
      "reading the scene, rendering, no file written), counted by `valgrind --tool=callgrind`. "
      "They are x86-64 instructions of a `-O3` host build and are not comparable with the "
      "RV32 counts.")
    w("- The other formats (CS418, Jaworski, miniRT, EASTRAY): "
      "[Speed against error, per format](#speed-against-error-per-format).\n")

    # Speed against error: the host variants, the firmware, the FPU models.
    course_n = len(course)
    host_points = [(name, totals(course, tag, 0)["diff"], callgrind[tag])
                   for name, tag in VARIANTS if callgrind.get(tag)]
    isa_label = {"rv32imf": "rv32imf\n(hardware F)", "rv32im": "rv32im\n(soft float)"}
    firmware_bars = [(isa_label.get(isa, isa), res["cycles"]) for isa, (res, _) in firmware.items() if res]
    fpu_points = []
    if fpu_shown:
        fpu_points.append(("IEEE", 0, ieee_fw["cycles"] if ieee_fw else None, True))
        for name, tag, _ in fpu_shown:
            sp = fpu[tag]["speed"]
            fpu_points.append((name, fpu_totals(tag, 1)["diff"], sp["cycles"] if sp else None,
                               meets(fpu[tag]["check"])))
    plots.speed_vs_error(host_points, firmware_bars, fpu_points, {
        "host_x": f"pixels differing from double/libm\n({course_n} course scenes)",
        "host_y": f"x86-64 million instructions\n({SPEED_SCENE} {SIZE}x{SIZE})",
        "fw_x": f"million RV32 cycles, default cycle model\n({SPEED_SCENE} {SIZE}x{SIZE})",
        "fpu_x": f"pixels differing from float/portable\n({course_n} course scenes)",
        "fpu_y": f"million RV32 cycles, unit latencies\n({SPEED_SCENE} {SIZE}x{SIZE})",
        "fpu_title": f"FPU models ({FPU_ISA} firmware)",
    }, os.path.join(docdir, "speed-vs-error.png"))
    w("![speed against error](accuracy/speed-vs-error.png)\n")

    # Heat maps of the worst scenes: most pixels off by more than 8, any variant.
    def badness(s):
        return max((rows[stem(s)][t][0]["over8"], rows[stem(s)][t][0]["diff"])
                   for _, t in VARIANTS[1:])
    worst = [s for s in sorted(course + hard, key=badness, reverse=True)[:6]
             if badness(s)[1] > 0]
    w("## Where the differences are\n")
    w("Heat maps (largest channel error per pixel, against double/libm, on a power scale so "
      "that an error of 1 shows; the title of each map gives its largest error and the pixels "
      "that differ) of the six scenes with the most pixels off by more than 8 in any variant:\n")
    for s in worst:
        png = f"heat-{stem(s)}.png"
        heat_map(stem(s), images[stem(s)], os.path.join(docdir, png))
        w(f"![{stem(s)}](accuracy/{png})\n")

    elapsed = time.time() - start
    w("## Tests\n")
    w("`test/hard/` (ctest, `hard_scene_tests`) renders every scene of `sld/hard` at 48x48 in "
      "every variant and checks: the reader gives no warning, every render succeeds and is a "
      "complete image, the difference from double/libm stays within the per-scene bounds of "
      "[sld/hard/README.md](../sld/hard/README.md), the output is deterministic, and "
      "float/portable+fma really differs from float/portable (i.e. the compiler did fuse; "
      "`objdump -d` of `fma_variant.cpp.o` shows `vfmadd`/`vfnmadd` instructions).\n")
    w(HARD_CASES_TESTS)
    w("`test/sim/` (ctest `sim: ...` and `sim cli: ...`) checks the FPU models: table entries "
      "and Newton steps on operands worked out by hand from the definition, IEEE results for "
      "zeros, infinities and NaNs, subnormals kept and flushed, `--fpu-check` meeting 2^-20 "
      "with a 10-bit reciprocal table and one Newton step and missing it with 8 bits, and the "
      "renderer firmware giving complete images under a coarse model.\n")
    w("## Open problems\n")
    w("- The firmware exists only for float/portable; the other variants' RV32 cost is not "
      "measured (only their x86 instruction counts).")
    w("- The FPU models cover division by reciprocal table and Newton steps, square root by "
      "inverse-square-root table and Newton steps, truncating fmul/fadd/fsub and flushed "
      "subnormals. A fused `fmadd.s` stays exact IEEE under every model (the firmware uses "
      "none), and the FPU-model latencies above are assumptions; a team's measured latencies "
      "go into its cycle model.")
    w("- float/portable+fma is a host approximation of an FPU with fused multiply-add: which "
      "products get fused depends on GCC's choices for x86-64, not on what a RISC-V compiler "
      "would emit for `fmadd.s`.")
    w("- huge.sld shows that single precision cannot render scenes with coordinates around 1e6; "
      "nothing in the shims can fix that.\n")

    # These sections are bench/accuracy/format_speed.py's (rewritten after this
    # script by run.sh) and board_vs_double.py's: kept as they were.
    for heading in ("## Speed against error, per format", "## Hard cases, per format", "## The board against double"):
        kept = kept_section(os.path.join(args.root, "docs", "accuracy.md"), heading)
        if kept:
            w(kept)
    w("## Regenerating\n")
    w("```sh\n" + args.command + "\n```\n")
    w("Without `--write-docs`, `bench/accuracy/run.sh` writes the same report into "
      "`build/reports/accuracy` (or `--out DIR`) and leaves docs/ alone. It prints one "
      "progress line per step on stderr. With `--formats` it redoes only "
      "[Speed against error, per format](#speed-against-error-per-format) (a few minutes; "
      "that section ends with the command and time of its run); with `--hard-cases` only "
      "[Hard cases, per format](#hard-cases-per-format) (seconds).\n")
    reused = [isa for isa, (res, _) in firmware.items() if res and res["cached"]]
    w(f"This run took {elapsed:.0f} s of wall time on the development machine ({cpu_model()}, "
      f"{os.cpu_count()} cores) after the "
      "build (renders and callgrind two at a time"
      + (f"; the firmware counts of {', '.join(reused)} came from the cache" if reused else "")
      + "). Without the cache (`NO_CACHE=1`, or after the simulator or an ELF changes) the "
      "firmware runs under the cycle model are redone, overlapped with the renders; they took "
      + ", ".join(f"{res['seconds']:.0f} s ({isa}, {res['instructions'] / 1e9:.1f} billion "
                  "instructions)" for isa, (res, _) in firmware.items() if res)
      + " of simulator time when they ran.")
    if fpu_runs:
        w(f"The FPU-model renders ({len(fpu_runs)} firmware runs, "
          f"{sum(r['instructions'] for r in fpu_runs) / 1e9:.0f} billion instructions) took "
          f"{sum(r['seconds'] for r in fpu_runs):.0f} s of simulator time when they were run, two "
          f"at a time; {sum(1 for r in fpu_runs if r['cached'])} of them came from the cache in "
          "this run.")
    w("")
    path = os.path.join(args.out, "accuracy.md")
    write_atomically(path, "\n".join(out))
    print(f"wrote {path} in {elapsed:.0f} s", file=sys.stderr)
    return 1 if failures or not all(ref_check.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
