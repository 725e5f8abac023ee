#!/usr/bin/python3
"""The picture checks of bench/accuracy/plots.py: a figure with overlapping
labels or an axis with a single labelled tick is refused; the report's own
figures, drawn from made-up data of the report's shape, pass and are saved.

Usage: accuracy_plots_test.py REPO OUTDIR
"""
import os
import sys

sys.path.insert(0, os.path.join(sys.argv[1], "bench", "accuracy"))
import numpy as np  # noqa: E402
import plots  # noqa: E402

out = sys.argv[2]
os.makedirs(out, exist_ok=True)
failures = []


def refused(fig, what, needle):
    try:
        plots.check_figure(fig, what)
        failures.append(f"{what}: accepted")
    except plots.FigureError as e:
        if needle not in str(e):
            failures.append(f"{what}: refused for another reason: {e}")
    plots.plt.close(fig)


# Two labels on the same spot.
fig, ax = plots.plt.subplots()
ax.plot([0, 1], [0, 1])
ax.annotate("float/portable", (0.5, 0.5))
ax.annotate("float/portable-fast", (0.5, 0.5))
refused(fig, "overlapping labels", "overlaps")
# One labelled tick: a panel whose points all sit at one x.
fig, ax = plots.plt.subplots()
ax.scatter([2351, 2351], [1.4e3, 1.7e4])
ax.set_xlim(2350.6, 2351.4)
ax.xaxis.set_major_locator(plots.matplotlib.ticker.FixedLocator([2351]))
refused(fig, "single tick", "x axis has 1 labelled tick")

rng = np.random.default_rng(7)
ref = rng.integers(0, 256, (128, 128, 3), dtype=np.uint8)
near = ref.copy()
near[40:60, 40:60] ^= 1
names = ["float/libm", "float/portable", "float/portable-fast", "float/portable-min", "float/portable+fma"]
try:
    plots.heat_map("scene at 128x128", ref, "double/libm", [(n, near) for n in names],
                   os.path.join(out, "heat.png"))
    plots.fpu_gallery([(s, "IEEE FPU", ref, [(f"fdiv recip-mul T={t} N=1", near) for t in (8, 10, 12)])
                       for s in ("contest", "mir")], os.path.join(out, "fpu.png"))
    plots.speed_vs_error(
        [(n, 2300 + 40 * i, 8.5e8 + 2e7 * i) for i, n in enumerate(["double/libm"] + names)],
        [("rv32imf\n(hardware F)", 1.4e9), ("rv32im\n(soft float)", 1.7e10)],
        [("IEEE", 0, 1.435e9, True), ("fdiv recip-mul T=10 N=1", 3046, 1.4338e9, True),
         ("fdiv recip-mul T=12 N=0", 137817, 2.564e9, False)],
        {"host_x": "pixels differing", "host_y": "x86-64 million instructions", "fw_x": "million cycles",
         "fpu_x": "pixels differing", "fpu_y": "million cycles", "fpu_title": "FPU models"},
        os.path.join(out, "speed.png"))
    variants = ["double/libm"] + names[:4]
    plots.formats_speed_vs_error(
        [(fmt, [(v, 0 if i == 0 else 20 * i + k, 3.0e8 + 1.5e7 * i + 1e6 * k) for i, v in enumerate(variants)],
          4.0e8 * (k + 1) if k != 3 else None, ["a", "b", "c"])
         for k, fmt in enumerate(["CS418", "Jaworski", "miniRT", "EASTRAY"])],
        "double/libm", os.path.join(out, "formats.png"))
except plots.FigureError as e:
    failures.append(f"the report's figures: {e}")
for name in ("heat.png", "fpu.png", "speed.png", "formats.png"):
    if not os.path.getsize(os.path.join(out, name)) > 1000:
        failures.append(f"{name} not written")
for f in failures:
    print("FAIL " + f)
print(f"accuracy_plots_test: {len(failures)} failures")
sys.exit(1 if failures else 0)
