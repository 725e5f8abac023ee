"""The pictures of docs/accuracy.md, and the check every one of them passes
before it is saved: no two texts overlap (tick labels, axis labels, titles,
legends, notes) and every visible axis shows at least two labelled ticks.
"""
import math
import textwrap

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import PowerNorm  # noqa: E402

from safe_output import save_figure  # noqa: E402
from matplotlib.ticker import FuncFormatter, LogLocator, MaxNLocator  # noqa: E402

DPI = 100
MARKERS = "osD^vPX*<>"
# Error maps: a power scale, so that an error of 1 already shows against the
# black of no error, and 255 is still the brightest.
ERROR_NORM = dict(cmap="inferno", norm=PowerNorm(gamma=0.35, vmin=0, vmax=255))
ERROR_TICKS = [0, 1, 8, 32, 96, 255]


class FigureError(Exception):
    pass


def _texts(fig):
    """Every visible, non-empty text of the figure, with a name for messages."""
    found = []

    def add(artist, what):
        if artist is not None and artist.get_visible() and artist.get_text().strip():
            found.append((what, artist))

    for t in fig.texts:  # the suptitle among them
        add(t, "suptitle" if t is fig._suptitle else "figure text")
    for i, ax in enumerate(fig.axes):
        name = f"axes {i} ({ax.get_title() or ax.get_label() or ''})"
        for t in (ax.title, ax._left_title, ax._right_title):
            add(t, name + " title")
        if ax.axison:
            for axis, letter in ((ax.xaxis, "x"), (ax.yaxis, "y")):
                add(axis.label, f"{name} {letter} label")
                lo, hi = sorted(ax.get_xlim() if letter == "x" else ax.get_ylim())
                for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                    if lo - 1e-9 * abs(hi - lo) <= tick.get_loc() <= hi + 1e-9 * abs(hi - lo):
                        for label in (tick.label1, tick.label2):
                            if label.get_visible():
                                add(label, f"{name} {letter} tick {label.get_text()}")
        for t in ax.texts:
            add(t, name + " text")
        legend = ax.get_legend()
        if legend is not None:
            add(legend.get_title(), name + " legend title")
            for t in legend.get_texts():
                add(t, name + " legend")
    for legend in fig.legends:
        add(legend.get_title(), "figure legend title")
        for t in legend.get_texts():
            add(t, "figure legend")
    return found


def check_figure(fig, what):
    """Raises FigureError when two texts overlap or an axis shows fewer than two
    labelled ticks."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = [(name, t.get_window_extent(renderer)) for name, t in _texts(fig)]
    problems = []
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            a, b = boxes[i][1], boxes[j][1]
            # One pixel of tolerance: touching is not overlapping.
            if (min(a.x1, b.x1) - max(a.x0, b.x0) > 1 and min(a.y1, b.y1) - max(a.y0, b.y0) > 1):
                problems.append(f"'{boxes[i][0]}' overlaps '{boxes[j][0]}'")
    for i, ax in enumerate(fig.axes):
        if not ax.axison:
            continue
        for axis, letter in ((ax.xaxis, "x"), (ax.yaxis, "y")):
            if not axis.get_visible() or not any(
                    t.tick1line.get_visible() or t.label1.get_visible() for t in axis.get_major_ticks()):
                continue
            lo, hi = sorted(ax.get_xlim() if letter == "x" else ax.get_ylim())
            labelled = {t.label1.get_text() for t in axis.get_major_ticks() + axis.get_minor_ticks()
                        if lo <= t.get_loc() <= hi and t.label1.get_visible() and t.label1.get_text()}
            if len(labelled) < 2:
                problems.append(f"axes {i} ({ax.get_title()}): {letter} axis has {len(labelled)} "
                                "labelled tick(s)")
    if problems:
        raise FigureError(f"{what}: " + "; ".join(problems))


def save(fig, path):
    try:
        check_figure(fig, path)
    except FigureError:
        save_figure(fig, path + ".rejected.png", dpi=DPI, bbox_inches="tight", pad_inches=0.05)
        raise
    save_figure(fig, path, dpi=DPI, bbox_inches="tight", pad_inches=0.05)
    plt.close(fig)


def _millions(v, _pos):
    return f"{v:,.0f}"


def speed_vs_error(host_points, firmware_bars, fpu_points, labels, path):
    """Three panels.

    host_points: [(variant, pixels differing, x86 instructions)];
    firmware_bars: [(label, modelled cycles)];
    fpu_points: [(unit, pixels differing from float/portable, cycles, meets the rules)];
    labels: dict with the axis texts (keys host_x, host_y, fw_x, fpu_x, fpu_y, fpu_title).
    """
    panels = 1 + bool(firmware_bars) + bool(fpu_points)
    # One row per panel: each has its legend on its right.
    fig, axes = plt.subplots(panels, 1, figsize=(8.5, 3.6 * panels), layout="constrained",
                             squeeze=False)
    axes = list(axes[:, 0])
    ax = axes.pop(0)
    # Points in a legend, not annotations: nearby variants cannot collide.
    for (name, x, y), marker in zip(host_points, MARKERS):
        ax.scatter([x], [y / 1e6], marker=marker, s=45, label=name)
    ax.set_xlabel(labels["host_x"])
    ax.set_ylabel(labels["host_y"])
    ax.set_title("host: speed against error (callgrind)", fontsize=10)
    ax.xaxis.set_major_locator(MaxNLocator(5))
    ax.yaxis.set_major_locator(MaxNLocator(6))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    if firmware_bars:
        ax = axes.pop(0)
        names = [n for n, _ in firmware_bars]
        values = [c / 1e6 for _, c in firmware_bars]
        ax.barh(range(len(values)), values, color=["tab:blue", "tab:orange", "tab:green"][:len(values)])
        ax.set_yticks(range(len(values)), names, fontsize=8)
        ax.invert_yaxis()
        ax.set_xscale("log")
        lo = 10 ** math.floor(math.log10(min(values)))
        hi = 10 ** math.ceil(math.log10(max(values) * 1.8))
        if hi / lo < 100:
            hi = lo * 100  # at least three labelled decades
        ax.set_xlim(lo, hi)
        ax.xaxis.set_major_locator(LogLocator(base=10, numticks=10))
        ax.xaxis.set_major_formatter(FuncFormatter(_millions))
        for i, v in enumerate(values):
            ax.text(v * 1.05, i, f"{v:,.0f}", va="center", fontsize=8)
        ax.set_xlabel(labels["fw_x"])
        ax.set_title("firmware: float/portable on the board", fontsize=10)
        ax.grid(alpha=0.3, axis="x")
    if fpu_points:
        ax = axes.pop(0)
        for (name, x, cycles, ok), marker in zip(fpu_points, MARKERS):
            if cycles is None:
                continue
            ax.scatter([x], [cycles / 1e6], color="tab:green" if ok else "tab:red", marker=marker, s=45,
                       label=name + ("" if ok else " (misses the rules)"))
        ax.set_xscale("symlog", linthresh=10)
        ax.set_xlim(left=-1)
        ax.yaxis.set_major_locator(MaxNLocator(6))
        ax.yaxis.set_major_formatter(FuncFormatter(_millions))
        ax.set_xlabel(labels["fpu_x"])
        ax.set_ylabel(labels["fpu_y"])
        ax.set_title(labels["fpu_title"], fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False,
                  title="green: meets the course's rules,\nred: misses them", title_fontsize=8)
    save(fig, path)


def error_map(a, b):
    return np.abs(a.astype(np.int32) - b.astype(np.int32)).max(axis=2)


def heat_map(title, reference, reference_name, others, path):
    """The reference image, then one panel per (name, image): the largest channel
    error per pixel against the reference. Panels touch the images; no margins."""
    n = 1 + len(others)
    fig, axes = plt.subplots(1, n, figsize=(1.75 * n + 0.5, 2.25), layout="constrained")
    fig.get_layout_engine().set(w_pad=0.02, h_pad=0.06, wspace=0.02)
    axes[0].imshow(reference, interpolation="nearest")
    axes[0].set_title(f"{reference_name}\n(reference)", fontsize=7)
    im = None
    for ax, (name, image) in zip(axes[1:], others):
        err = error_map(image, reference)
        im = ax.imshow(err, interpolation="nearest", **ERROR_NORM)
        ax.set_title(f"{name}\nmax {err.max()}, {int((err > 0).sum())} px", fontsize=7)
    for ax in axes:
        ax.set_axis_off()
    if im is not None:
        bar = fig.colorbar(im, ax=list(axes), fraction=0.02, pad=0.01)
        bar.set_ticks(ERROR_TICKS)
        bar.ax.tick_params(labelsize=7)
        bar.set_label("channel error", fontsize=7)
    fig.suptitle(title, fontsize=9)
    save(fig, path)


def fpu_gallery(scenes, path):
    """For each scene a row of renders, the reference first, then each FPU model's
    image; under it a row with each model's error map against the reference.

    scenes: [(scene name, reference name, reference image, [(model, image)])]."""
    cols = 1 + max(len(models) for _, _, _, models in scenes)
    rows = 2 * len(scenes)
    fig, axes = plt.subplots(rows, cols, figsize=(1.6 * cols + 0.5, 1.85 * rows), layout="constrained",
                             squeeze=False)
    fig.get_layout_engine().set(w_pad=0.02, h_pad=0.02, wspace=0.02, hspace=0.04)
    im = None
    for r, (scene, ref_name, ref, models) in enumerate(scenes):
        top, bottom = axes[2 * r], axes[2 * r + 1]
        top[0].imshow(ref, interpolation="nearest")
        top[0].set_title(f"{scene}: {ref_name}", fontsize=7)
        bottom[0].text(0.5, 0.5, "under each render:\nits channel error\nagainst the reference",
                       ha="center", va="center", fontsize=7, transform=bottom[0].transAxes)
        for c, (name, image) in enumerate(models, start=1):
            err = error_map(image, ref)
            top[c].imshow(image, interpolation="nearest")
            top[c].set_title("\n".join(textwrap.wrap(name, 22)), fontsize=7)
            im = bottom[c].imshow(err, interpolation="nearest", **ERROR_NORM)
            bottom[c].set_title(f"{int((err > 0).sum())} px differ", fontsize=7)
        for ax in list(top) + list(bottom):
            ax.set_axis_off()
    if im is not None:
        bar = fig.colorbar(im, ax=list(axes.flat), fraction=0.015, pad=0.01)
        bar.set_ticks(ERROR_TICKS)
        bar.ax.tick_params(labelsize=7)
        bar.set_label("channel error", fontsize=7)
    save(fig, path)


def formats_speed_vs_error(formats, reference, path):
    """One panel per format: each variant's pixels differing from the reference
    (x) against its x86-64 instructions on the format's speed scenes (y).

    formats: [(format, [(variant, pixels differing, instructions)], board cycles or
    None, speed scene names)]."""
    cols = 2
    rows = (len(formats) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(10, 3.4 * rows), layout="constrained", squeeze=False)
    variants = []
    for ax, (name, points, cycles, scenes) in zip(axes.flat, formats):
        for variant, x, y in points:
            if variant not in variants:
                variants.append(variant)
            ax.scatter([x], [y / 1e6], marker=MARKERS[variants.index(variant)], s=45,
                       color=f"C{variants.index(variant)}", label=variant)
        top = max((x for _, x, _ in points), default=0)
        ax.set_xscale("symlog", linthresh=10)
        ax.set_xlim(-1, max(20, top * 1.6))
        ys = [y / 1e6 for _, _, y in points]
        if ys:
            pad = max(0.05 * (max(ys) - min(ys)), 0.02 * max(ys))
            ax.set_ylim(min(ys) - pad, max(ys) + pad)
        ax.yaxis.set_major_locator(MaxNLocator(5))
        ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _p: f"{v:,.0f}" if v >= 100 else f"{v:,.1f}"))
        ax.set_xlabel(f"pixels differing from {reference}\n(every scene of the format)", fontsize=8)
        ax.set_ylabel("x86-64 million instructions\n(speed scenes, callgrind)", fontsize=8)
        ax.tick_params(labelsize=8)
        board = f"; board: {cycles / 1e6:,.0f} M RV32 cycles" if cycles else ""
        ax.set_title(f"{name}{board}", fontsize=9)
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[len(formats):]:
        ax.set_axis_off()
    handles = {}
    for ax in axes.flat:
        for h, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, h)
    if handles:
        axes[0][-1].legend(list(handles.values()), list(handles.keys()), fontsize=8, loc="upper left",
                           bbox_to_anchor=(1.02, 1.0), frameon=False)
    save(fig, path)
