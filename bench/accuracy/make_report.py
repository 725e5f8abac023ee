#!/usr/bin/python3
"""Renders every scene in every math variant and writes docs/accuracy.md.

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
import time

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

VARIANTS = [  # (name, file tag), reference first
    ("double/libm", "double-libm"),
    ("float/libm", "float-libm"),
    ("float/portable", "float-portable"),
    ("float/portable-fast", "float-portable-fast"),
    ("float/portable+fma", "float-portable-fma"),
]
REF = "double-libm"
MODEL = "float-portable"
SIZE = 128
SPEED_SCENE = "contest"


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


def firmware_command(sim, elf, scene, outfile):
    return [sim, "--stats", "--cycle-model", "default", "--uart-in", scene, "--uart-out",
            outfile, elf, "--", "--size", f"{SIZE}x{SIZE}", "--format", "p6"]


def firmware_cache_key(sim, elf, scene):
    """Hash of everything a firmware run depends on: simulator, ELF, scene, arguments."""
    h = hashlib.sha256()
    for path in (sim, elf, scene):
        h.update(open(path, "rb").read())
    h.update(" ".join(firmware_command("", "", "", "")).encode())
    return h.hexdigest()[:32]


def run_firmware(sim, elf, scene, outfile, cache_dir):
    """(instructions, modelled cycles, from cache?) of one firmware run, output kept.

    The soft-float run takes many minutes, so its --stats text and image are
    kept in cache_dir under a hash of the simulator, ELF, scene and arguments;
    a run is reused only when all of them are byte-identical."""
    key = firmware_cache_key(sim, elf, scene)
    stats_path = os.path.join(cache_dir, key + ".stats")
    image_path = os.path.join(cache_dir, key + ".ppm")
    cached = os.path.exists(stats_path) and os.path.exists(image_path)
    if cached:
        stats = open(stats_path).read()
        shutil.copyfile(image_path, outfile)
    else:
        r = subprocess.run(firmware_command(sim, elf, scene, outfile),
                           capture_output=True, text=True)
        if r.returncode != 0:
            return None
        stats = r.stderr
        os.makedirs(cache_dir, exist_ok=True)
        shutil.copyfile(outfile, image_path)
        with open(stats_path, "w") as f:
            f.write(stats)
    ins = re.search(r"^instructions: (\d+)", stats, re.M)
    cyc = re.search(r"^cycles: (\d+)", stats, re.M)
    if not ins or not cyc:
        return None
    return int(ins.group(1)), int(cyc.group(1)), cached


def run_callgrind(tool, variant, scene):
    """x86-64 instructions (callgrind Ir) of accuracy-report rendering one variant."""
    cmd = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", tool,
           "--variant", variant, "--size", f"{SIZE}x{SIZE}", scene]
    r = subprocess.run(cmd, capture_output=True, text=True)
    m = re.search(r"Collected : (\d+)", r.stderr)
    return int(m.group(1)) if r.returncode == 0 and m else None


def fmt_psnr(p):
    return "∞" if math.isinf(p) else f"{p:.1f}"


def heat_map(scene, images, outpath):
    shown = [t for _, t in VARIANTS if t != REF]
    fig, axes = plt.subplots(1, 1 + len(shown), figsize=(3 * (1 + len(shown)), 3.6))
    axes[0].imshow(images[REF], interpolation="nearest")
    axes[0].set_title("double/libm (reference)", fontsize=8)
    for ax, tag in zip(axes[1:], shown):
        err = np.abs(images[tag].astype(np.int32) - images[REF].astype(np.int32)).max(axis=2)
        im = ax.imshow(err, cmap="inferno", vmin=0, vmax=255, interpolation="nearest")
        name = dict((t, n) for n, t in VARIANTS)[tag]
        ax.set_title(f"{name}\n|diff|, max {err.max()}", fontsize=8)
    for ax in axes:
        ax.axis("off")
    fig.colorbar(im, ax=list(axes), shrink=0.8, label="max channel error")
    fig.suptitle(f"{scene} at {SIZE}x{SIZE}")
    fig.savefig(outpath, dpi=80)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tool", required=True)
    ap.add_argument("--root", required=True)
    ap.add_argument("--shared", required=True)
    ap.add_argument("--work", required=True)
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
    docdir = os.path.join(args.root, "docs", "accuracy")
    os.makedirs(docdir, exist_ok=True)

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
                fw_jobs[isa] = (pool.submit(run_firmware, args.sim, elf, speed_scene, out,
                                           cache_dir), out)
    cg_jobs = {tag: pool.submit(run_callgrind, args.tool, tag, speed_scene)
               for _, tag in VARIANTS} if os.path.exists(speed_scene) else {}
    render_jobs = [pool.submit(render, args.tool, s, imgdir) for s in course + hard]
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
      f"{SIZE}x{SIZE} by `build-acc/tools/accuracy/accuracy-report` in each variant, in-process:\n")
    w("| variant | what |\n|---|---|")
    w("| double/libm | `LibmDouble`: the reference, byte-identical to the original program |")
    w("| float/libm | `LibmFloat`: float with glibc's `sqrtf sinf cosf atanf floorf` |")
    w("| float/portable | `PortableFloat`: float shims from add/sub/mul/div only; the firmware's model |")
    w("| float/portable-fast | `PortableFloatFast`: the cheaper shims (within 2.6 ULP) |")
    w("| float/portable+fma | `PortableFloat` compiled with `-ffp-contract=fast -mfma -O2` "
      "(tools/accuracy/fma_variant.cpp): the compiler fuses a*b+c into one rounding, "
      "as an FPU with `fmadd.s` and a contracting compiler would |\n")
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
                w(f"| {name}, {label} | {res[0]:,} | {res[1]:,} | {cgs} |")
            else:
                w(f"| {name}, {label} | not measured | not measured | {cgs} |")
    w("")
    for isa, (res, same) in firmware.items():
        if same is not None:
            w(f"- firmware `minrt-{isa}.elf` output on {SPEED_SCENE} "
              f"{'**equals**' if same else '**differs from**'} the host's float/portable image"
              + (" (counts reused from the firmware cache: same simulator, ELF, scene and "
                 "arguments as a previous run)." if res and res[2] else "."))
    w("- The x86 counts are the whole `accuracy-report --variant V` process (start-up, "
      "reading the scene, rendering, no file written), counted by `valgrind --tool=callgrind`. "
      "They are x86-64 instructions of a `-O3` host build and are not comparable with the "
      "RV32 counts.\n")

    # Speed against error plot.
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    ax = axes[0]
    for name, tag in VARIANTS:
        cg = callgrind.get(tag)
        if not cg:
            continue
        err = totals(course, tag, 0)["diff"]
        ax.scatter([err], [cg / 1e6])
        ax.annotate(name, (err, cg / 1e6), fontsize=8, xytext=(4, 4), textcoords="offset points")
    ax.set_xlabel("pixels differing from double/libm, 25 course scenes")
    ax.set_ylabel(f"x86-64 Minstructions ({SPEED_SCENE} {SIZE}x{SIZE})")
    ax.set_title("host (callgrind)")
    ax.grid(alpha=0.3)
    ax = axes[1]
    err = totals(course, MODEL, 0)["diff"]
    for isa, (res, _) in firmware.items():
        if res:
            ax.scatter([err], [res[1] / 1e6])
            ax.annotate(f"float/portable {isa}", (err, res[1] / 1e6), fontsize=8,
                        xytext=(4, 4), textcoords="offset points")
    ax.set_yscale("log")
    ax.set_xlabel("pixels differing from double/libm, 25 course scenes")
    ax.set_ylabel(f"RV32 Mcycles, modelled ({SPEED_SCENE} {SIZE}x{SIZE})")
    ax.set_title("firmware (firmware-sim, default cycle model)")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(docdir, "speed-vs-error.png"), dpi=80)
    plt.close(fig)
    w("![speed against error](accuracy/speed-vs-error.png)\n")

    # Heat maps of the worst scenes: most pixels off by more than 8, any variant.
    def badness(s):
        return max((rows[stem(s)][t][0]["over8"], rows[stem(s)][t][0]["diff"])
                   for _, t in VARIANTS[1:])
    worst = [s for s in sorted(course + hard, key=badness, reverse=True)[:6]
             if badness(s)[1] > 0]
    w("## Where the differences are\n")
    w("Heat maps (largest channel error per pixel, against double/libm) of the six scenes "
      "with the most pixels off by more than 8 in any variant:\n")
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
    w("## Open problems\n")
    w("- The firmware exists only for float/portable; the other variants' RV32 cost is not "
      "measured (only their x86 instruction counts).")
    w("- The firmware runs here use the simulator's exact IEEE single-precision FPU. "
      "Approximate FPU models (the "
      "course's error bounds: mul 2^-22, div 2^-20, sqrt 2^-20 relative, or a fused "
      "`fmadd.s`) are not covered by this report; once they exist, their images can be compared with these "
      "tables by rendering through `firmware-sim` and the same comparison code.")
    w("- float/portable+fma is a host approximation of an FPU with fused multiply-add: which "
      "products get fused depends on GCC's choices for x86-64, not on what a RISC-V compiler "
      "would emit for `fmadd.s`.")
    w("- huge.sld shows that single precision cannot render scenes with coordinates around 1e6; "
      "nothing in the shims can fix that.\n")

    w("## Regenerating\n")
    w("```sh\n" + args.command + "\n```\n")
    reused = [isa for isa, (res, _) in firmware.items() if res and res[2]]
    w(f"This run took {elapsed:.0f} s of wall time on the 2-core development machine after the "
      "build (renders and callgrind two at a time"
      + (f"; the firmware counts of {', '.join(reused)} came from the cache" if reused else "")
      + "). Without the cache (`NO_CACHE=1`, or after the simulator or an ELF changes) the "
      "firmware runs under the cycle model add about 1 minute (rv32imf) and 4 to 10 minutes "
      "(rv32im soft float, 23 billion instructions; 557 s when it was measured on a loaded "
      "machine), overlapped with the renders.\n")
    path = os.path.join(args.root, "docs", "accuracy.md")
    with open(path, "w") as f:
        f.write("\n".join(out))
    print(f"wrote {path} in {elapsed:.0f} s", file=sys.stderr)
    return 1 if failures or not all(ref_check.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
