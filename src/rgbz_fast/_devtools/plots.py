"""The figures of the commands: the depth preview and the flags map of ``rgbz-fast depth``,
the Pareto plot of ``rgbz-fast tradeoff``, the layouts of ``rgbz-fast pattern-study`` and the
sweep of ``rgbz-fast hardware``.

Each function returns PNG bytes, which the command writes with
:func:`rgbz_fast.io.atomic_write`. matplotlib is imported here only, and only
when a figure is drawn (with the Agg backend unless the caller chose one), so
that neither ``import rgbz_fast`` nor a command without figures loads it.
"""

from __future__ import annotations

import io

import numpy as np

__all__ = ["depth_preview", "depth_flags_figure", "full_depth_preview", "tradeoff_plot",
           "tradeoff_figure", "pattern_study_plot", "tile_thumbnail", "hardware_sweep_plot"]


def _pyplot():
    """matplotlib and the figure factory of the reports (figures outside pyplot: the
    caller's backend is left as it is)."""
    import matplotlib

    from ..evaluation._reports import _Figures

    return matplotlib, _Figures


def _png(fig, **kwargs):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, **kwargs)
    return buf.getvalue()


#: the longest side, in pixels, of the image a frame preview draws: the figures are about 700
#: pixels wide and draw the nearest pixel (``interpolation="nearest"``), so a larger frame is
#: taken every k-th pixel first (a 12 MP frame: every third) instead of colour-mapping and
#: resampling all of it
PREVIEW_PIXELS = 1400


def preview_step(shape):
    """k of :data:`PREVIEW_PIXELS`: 1 up to 1400 pixels on the longest side."""
    return max(1, -(-max(shape) // PREVIEW_PIXELS))


def nearest_measurement(res):
    """(rows, cols) of the nearest Z measurement of every pixel of the preview's grid (every
    :func:`preview_step`-th pixel of the frame), for :func:`depth_preview` and
    :func:`depth_flags_figure`."""
    from scipy import ndimage

    measured = res.to_frame(np.ones(res.n_sites, bool), fill=False).astype(bool)
    idx = ndimage.distance_transform_edt(~measured, return_distances=False,
                                         return_indices=True)
    k = preview_step(measured.shape)
    return idx[0][::k, ::k], idx[1][::k, ::k]


def _percentile_scale(good):
    """(min, max) metres of a colour map: the 1st to 99th percentile of ``good``."""
    scale = (float(np.percentile(good, 1)), float(np.percentile(good, 99))) if good.size \
        else (0.0, 1.0)
    return scale if scale[1] > scale[0] else (scale[0], scale[0] + 1e-3)


def depth_scale(res, nearest=None):
    """The default colour scale of :func:`depth_preview`: the 1st to 99th percentile of the
    valid depth on the preview's grid. ``rgbz-fast depth`` gives it to both previews of a
    frame (each had taken its own, so one colour was two depths in two figures side by side)."""
    iy, ix = nearest_measurement(res) if nearest is None else nearest
    depth = res.to_frame(res.depth)[iy, ix]
    valid = res.to_frame(res.valid, fill=False).astype(bool)[iy, ix]
    return _percentile_scale(depth[valid])


def depth_preview(res, title, scale=None, truth_known=None, nearest=None):
    """An 8-bit colour-mapped PNG of a depth result, with its colour scale (PNG bytes).

    The Z measurements are painted on the frame; colour sites show the
    nearest measurement (the preview only: the TIFF holds NaN there), the
    measurements the ISP flags are grey, and, for a simulated frame
    (``truth_known``: the taps' ground-truth validity), the measurements
    whose ground truth is unknown are shaded red: the scene filled their
    depth in from the nearest known one. ``scale``: (min, max) metres of the
    colour map; default the 1st to 99th percentile of the valid depth. A frame longer than
    :data:`PREVIEW_PIXELS` on a side is drawn from every k-th pixel (:func:`preview_step`).
    ``nearest``: :func:`nearest_measurement` of ``res`` when the caller has it.
    """
    matplotlib, plt = _pyplot()
    from matplotlib.patches import Patch

    iy, ix = nearest_measurement(res) if nearest is None else nearest
    depth = res.to_frame(res.depth)[iy, ix]
    valid = res.to_frame(res.valid, fill=False).astype(bool)[iy, ix]
    unknown = None
    if truth_known is not None and not np.all(truth_known):
        known = np.asarray(truth_known, bool)
        unknown = res.to_frame(~known, fill=False).astype(bool)[iy, ix]
    if scale is None:
        scale = depth_scale(res, (iy, ix))
    rows, cols = res.shape
    width = 6.4
    fig, ax = plt.subplots(figsize=(width, width * rows / cols * 0.92 + 0.9))
    cmap = matplotlib.colormaps["viridis"].with_extremes(bad="0.6")
    im = ax.imshow(np.ma.masked_where(~valid, depth), cmap=cmap, vmin=scale[0], vmax=scale[1],
                   interpolation="nearest")
    handles = [Patch(color="0.6", label="no valid depth (flagged)")]
    if unknown is not None:
        overlay = np.zeros(depth.shape + (4,))
        overlay[unknown] = (0.85, 0.1, 0.1, 0.55)
        ax.imshow(overlay, interpolation="nearest")
        handles.append(Patch(color=(0.85, 0.1, 0.1, 0.55),
                             label=f"ground truth unknown ({100 * float(1 - known.mean()):.1f} %)"))
    ax.set_xticks([])
    ax.set_yticks([])
    bar = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, extend="both")
    bar.set_label("distance (m)")
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.0, -0.01), fontsize=8,
              frameon=False, ncol=2)
    ax.set_title(title, fontsize=9)
    return _png(fig, bbox_inches="tight")


#: the reasons a measurement is flagged: (label, flag bit of rgbz_fast.tof, colour)
FLAG_REASONS = (("saturated", "FLAG_SATURATED", "#e7298a"),
                ("low signal", "FLAG_LOW_SIGNAL", "#7570b3"),
                ("inconsistent frequencies", "FLAG_INCONSISTENT", "#d95f02"),
                ("flying pixel", "FLAG_FLYING", "#e6ab02"),
                ("out of range", "FLAG_OUT_OF_RANGE", "#a6761d"),
                ("resolved by the colour guide", "FLAG_RESOLVED", "#66a61e"))
#: the categories of the flags figure: valid, each reason alone, several at once
FLAG_CATEGORIES = ((("valid", "#1b9e77"),) + tuple((label, c) for label, _, c in FLAG_REASONS)
                   + (("several reasons", "#000000"),))


def flag_bits():
    """{label: bit} of :data:`FLAG_REASONS`, from :mod:`rgbz_fast.tof`."""
    from .. import tof

    return {label: int(getattr(tof, name)) for label, name, _ in FLAG_REASONS}


def share_text(count, total):
    """``count`` of ``total`` as a percentage of one decimal, as the command's summary line
    writes it: "< 0.1 %" for a share that rounds to 0.0 but is not none, "> 99.9 %" for one
    that rounds to 100.0 but is not all (the legend had said "0.0 %" of a category it drew)."""
    count, total = int(count), max(int(total), 1)
    if count == 0 or count >= total:
        return f"{100 * (count >= total) * (count > 0):d} %"
    share = 100 * count / total
    if share < 0.05:
        return "< 0.1 %"
    if share >= 99.95:
        return "> 99.9 %"
    return f"{share:.1f} %"


def depth_flags_figure(res, title, nearest=None):
    """Why each Z measurement is flagged, as a map with a legend (PNG bytes).

    Each measurement is painted over its footprint (every pixel shows the
    nearest measurement, as the preview does, on the same grid), in one colour per reason:
    valid, each flag bit alone, or several at once. The legend gives each
    category's share of the measurements. The flag bits themselves are in the
    command's flags TIFF.
    """
    matplotlib, plt = _pyplot()
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    flags = np.asarray(res.flags).astype(np.int64)
    bits = list(flag_bits().values())
    reasons = sum(((flags & b) != 0).astype(int) for b in bits)
    category = np.zeros(flags.shape, np.int64)                    # 0 valid
    for k, b in enumerate(bits):
        category[(flags & b) != 0] = k + 1
    category[reasons > 1] = len(FLAG_CATEGORIES) - 1
    iy, ix = nearest_measurement(res) if nearest is None else nearest
    grid = res.to_frame(category.astype(float), fill=0.0)[iy, ix]
    rows, cols = res.shape
    width = 6.4
    fig, ax = plt.subplots(figsize=(width, width * rows / cols * 0.92 + 1.1))
    cmap = ListedColormap([c for _, c in FLAG_CATEGORIES])
    ax.imshow(grid, cmap=cmap, vmin=-0.5, vmax=len(FLAG_CATEGORIES) - 0.5,
              interpolation="nearest")
    ax.set_xticks([])
    ax.set_yticks([])
    n = max(res.n_sites, 1)
    handles = [Patch(color=colour, label=f"{label} ({share_text(np.sum(category == k), n)})")
               for k, (label, colour) in enumerate(FLAG_CATEGORIES)
               if k == 0 or np.any(category == k)]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.0, -0.01), fontsize=8,
              frameon=False, ncol=3)
    ax.set_title(f"{title} ({n} measurements)", fontsize=9)
    return _png(fig, bbox_inches="tight")


#: marker of each (precision, exponential) of the trade-off rows
_MARKERS = {("float64", "libm"): "o", ("float32", "libm"): "s", ("float64", "fast"): "^",
            ("float32", "fast"): "D", ("float64", "-"): "o", ("float32", "-"): "s"}
#: one colour per method (tab10 without its grey, which would read as 'no colour')
_METHOD_COLOURS = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                   "#e377c2", "#bcbd22", "#17becf")


def _log_axis_numbers(ax):
    """A log x axis labelled with plain numbers at 1, 2 and 5 per decade (and no minor
    labels), so that neighbouring labels never run together."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    ax.xaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.xaxis.set_minor_formatter(NullFormatter())


def full_depth_preview(depth, title, scale=None):
    """An 8-bit colour-mapped PNG of a full-resolution depth map (NaN grey), with its scale.

    ``scale``: (min, max) metres; default the 1st to 99th percentile of the finite depths
    (drawn from every k-th pixel, :func:`preview_step`)."""
    matplotlib, plt = _pyplot()
    covered = float(np.isfinite(depth).mean()) if depth.size else 0.0
    missing = int(depth.size - np.isfinite(depth).sum())
    rows, cols = depth.shape
    k = preview_step(depth.shape)
    depth = depth[::k, ::k]
    if scale is None:
        scale = _percentile_scale(depth[np.isfinite(depth)])
    fig, ax = plt.subplots(figsize=(6.4, 6.4 * rows / cols * 0.92 + 0.6))
    cmap = matplotlib.colormaps["viridis"].with_extremes(bad="0.6")
    im = ax.imshow(np.ma.masked_invalid(depth), cmap=cmap, vmin=scale[0], vmax=scale[1],
                   interpolation="nearest")
    ax.set_xticks([])
    ax.set_yticks([])
    fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, extend="both").set_label("distance (m)")
    if covered < 1:
        # grey said, as the sampled preview says its grey: it had been unexplained
        from matplotlib.patches import Patch

        ax.legend(handles=[Patch(color="0.6", label=f"no depth (NaN, "
                                 f"{share_text(missing, rows * cols)})")],
                  loc="upper left", bbox_to_anchor=(0.0, -0.01), fontsize=8, frameon=False)
    ax.set_title(f"{title} ({100 * covered:.1f} % covered)", fontsize=9)
    return _png(fig, bbox_inches="tight")


def tradeoff_plot(res):
    """Pareto plot of :func:`rgbz_fast._devtools.tradeoff.run_tradeoff`'s result (PNG bytes):
    :func:`tradeoff_figure` drawn."""
    return _png(tradeoff_figure(res), bbox_inches="tight")


def tradeoff_figure(res):
    """The matplotlib figure of :func:`tradeoff_plot`.

    One panel per pattern: Mpix/s (log) against mean CFA PSNR. Each row is a
    point with its IQR bar: its colour is the method, its fill the domain
    (filled: intensity, open: colour difference), its shape the precision and
    exponential; the points of the Pareto front are ringed in black and joined
    by a dashed line. One legend, beside the panels, says all four.
    """
    from matplotlib.lines import Line2D

    from ..reconstruction import NEEDS_TOF
    from .tradeoff import NO_EXP, PATTERNS, QUICK_NOTE, threads_text

    _, plt = _pyplot()
    rows = res["rows"]
    pats = sorted({r["pattern"] for r in rows},
                  key=lambda p: PATTERNS.index(p) if p in PATTERNS else 99)
    methods = list(dict.fromkeys(r["method"] for r in rows))
    colours = {m: _METHOD_COLOURS[i % len(_METHOD_COLOURS)] for i, m in enumerate(methods)}
    fig, axes = plt.subplots(1, len(pats), figsize=(5.6 * len(pats) + 2.4, 5), squeeze=False)
    for ax, p in zip(axes[0], pats):
        # a mean left without an image (each reconstructed exactly by some variant: NaN,
        # run_tradeoff's common means) has no point; an empty panel says why (matplotlib
        # had refused the log axis of no data)
        sub = [r for r in rows if r["pattern"] == p and r["cfa_psnr"] is not None
               and np.isfinite(r["cfa_psnr"])]
        if not sub:
            ax.text(0.5, 0.5, "no image that every variant reconstructs\nwith a finite PSNR",
                    ha="center", va="center", transform=ax.transAxes)
            ax.set_title(p)
            continue
        for r in sub:
            col = colours[r["method"]]
            cd = r.get("domain") == "colour_difference"
            mk = _MARKERS[(r["precision"], r["exp"])]
            if r["pareto"]:
                ax.scatter(r["mpix_s"], r["cfa_psnr"], marker=mk, s=150, facecolor="none",
                           edgecolor="k", linewidth=1.4, zorder=2)
            ax.scatter(r["mpix_s"], r["cfa_psnr"], marker=mk, s=50,
                       facecolor="white" if cd else col, edgecolor=col,
                       linewidth=1.6 if cd else 0.5, zorder=3)
            ax.plot([r["mpix_s_lo"], r["mpix_s_hi"]], [r["cfa_psnr"]] * 2, lw=1, alpha=0.5,
                    color=col, zorder=1)                              # IQR of the runs
        front = sorted((r for r in sub if r["pareto"]), key=lambda r: r["mpix_s"])
        ax.plot([r["mpix_s"] for r in front], [r["cfa_psnr"] for r in front], "k--", lw=1,
                zorder=1)
        ax.set_xscale("log")
        _log_axis_numbers(ax)
        ax.set_xlabel(f"speed, Mpix/s, best of {res['repeat']} ({threads_text(res)}, "
                      f"{res['speed_frame'][0]}x{res['speed_frame'][1]} frame)")
        ax.set_ylabel(f"mean CFA PSNR, dB ({res['dataset']}, {len(res['images'])} images)")
        ax.set_title(p + (f" ({QUICK_NOTE})" if res.get("quick") else ""))
        ax.grid(True, which="major", alpha=0.3)
        ax.grid(True, which="minor", alpha=0.1)

    def point(label, marker="o", face="k", edge="k", width=0.5, size=7):
        return Line2D([], [], ls="none", marker=marker, markersize=size, markerfacecolor=face,
                      markeredgecolor=edge, markeredgewidth=width, label=label)

    def header(text):
        return Line2D([], [], ls="none", label=text)

    # z_guided on a NIR estimated from the RGB (res["ir_estimated"]): marked, and the text
    # report's caveat said under the panels (the plot had shown its rows as any other's)
    leaked = [m for m in methods if m in NEEDS_TOF] if res.get("ir_estimated") else []
    handles = [header("colour: method")]
    handles += [point(m + ("*" if m in leaked else ""), face=colours[m], edge=colours[m])
                for m in methods]
    handles += [header("fill: domain"), point("intensity"),
                point("colour difference", face="white", width=1.6)]
    handles += [header("shape: precision, exp")]
    shapes = sorted({(r["precision"], r["exp"]) for r in rows},
                    key=lambda k: list(_MARKERS).index(k))
    handles += [point(f"{prec}" + (f", exp={exp}" if exp != NO_EXP else ""),
                      marker=_MARKERS[(prec, exp)], face="white", width=1.2)
                for prec, exp in shapes if exp != NO_EXP or not any(
                    (prec, e) in shapes for e in ("libm", "fast"))]
    # the line beside each point: it had been explained nowhere, and lies left of its point
    # (the point is the best run), so it read as an error bar the point falls outside of
    handles += [header("line: speed spread"),
                Line2D([], [], color="k", lw=1, alpha=0.5,
                       label="IQR of the timed runs;\npoint: the best run")]
    if any(r["pareto"] for r in rows):          # a quick run computes no front: none is drawn
        handles += [header("Pareto front"),
                    Line2D([], [], ls="--", color="k", lw=1, marker="o", markersize=10,
                           markerfacecolor="none", markeredgecolor="k", label="ringed, dashed")]
    legend = fig.legend(handles=handles, loc="center left", bbox_to_anchor=(1.0, 0.5),
                        fontsize=8, frameon=False, handletextpad=0.6)
    for text, h in zip(legend.get_texts(), handles):
        if h.get_marker() in (None, "None", "none", "") and h.get_linestyle() in ("None", "none"):
            text.set_fontweight("bold")                               # a header
    fig.tight_layout()
    if leaked:
        from ..evaluation._reports import _footnote
        from .tradeoff import _leak_note

        _footnote(fig, ["* " + _leak_note(res)], fontsize=8)     # as evaluate's charts do
    return fig


#: colours of the channels in a tile thumbnail (R, G, B, Z)
_TILE_RGB = np.array([[0.85, 0.15, 0.15], [0.2, 0.7, 0.25], [0.2, 0.35, 0.9],
                      [0.12, 0.12, 0.12]])


def tile_thumbnail(tile, least=8):
    """An RGB image (float, rows x cols x 3) of a tile string repeated to at least ``least``
    sites a side: R, G, B as colours, Z dark."""
    from .._patterns import CHANNELS

    codes = np.array([[CHANNELS.index(ch) for ch in r] for r in tile.split("/")])
    reps = [-(-least // n) for n in codes.shape]
    return _TILE_RGB[np.tile(codes, reps)]


def pattern_study_plot(res):
    """Pareto plot of :func:`rgbz_fast._devtools.pattern_study.pattern_study` (PNG bytes).

    Each layout at its best method (highest CPSNR): the wall's predicted depth noise (x)
    against that CPSNR (y), marker area proportional to the method's operations per frame
    pixel, each point labelled with a thumbnail of its tile (repeated to 8 sites a side; R,
    G, B in colour, Z dark);
    the Pareto front is a dashed line. Layouts without a depth measurement are left out
    (named under the axes).
    """
    from matplotlib.offsetbox import AnnotationBbox, OffsetImage

    from .pattern_report import best_rows, pareto_layouts

    _, plt = _pyplot()
    best = best_rows(res["rows"])
    pts = [r for r in best if r.get("cpsnr") is not None and r.get("wall_sigma_mm") is not None]
    left = [r["layout"] for r in best if r not in pts]
    front = set(pareto_layouts(res["rows"]))
    fig, ax = plt.subplots(figsize=(8, 6))
    ops = np.array([r.get("ops_per_pixel") or 0.0 for r in pts])
    size = 40 + 400 * ops / ops.max() if ops.size and ops.max() > 0 else np.full(len(pts), 60)
    for r, s in zip(pts, size):
        ax.scatter(r["wall_sigma_mm"], r["cpsnr"], s=s, alpha=0.5,
                   color="C3" if r["layout"] in front else "C0",
                   edgecolor="k" if r["layout"] in front else "none", zorder=3)
    fr = sorted((r for r in pts if r["layout"] in front), key=lambda r: r["wall_sigma_mm"])
    # the dashed line's entry only where a line is drawn (one layout on the front draws none)
    ax.plot([r["wall_sigma_mm"] for r in fr], [r["cpsnr"] for r in fr], "k--", lw=1,
            zorder=1, label="Pareto front" if len(fr) > 1 else None)
    if len(fr) == 1:
        ax.scatter([], [], s=60, color="C3", alpha=0.5, edgecolor="k",
                   label="on the Pareto front")
    # one entry per distinct cost as printed: layouts of one cost had listed it twice
    sizes = (np.percentile(ops, 10), ops.max()) if ops.size and ops.max() > 0 else ()
    for text, v in {f"{v:.1f} ops per pixel": v for v in sizes}.items():
        ax.scatter([], [], s=40 + 400 * v / ops.max(), color="C0", alpha=0.5, label=text)
    st = res["settings"]
    ax.set_xlabel(f"predicted depth noise on a wall at {st['wall_distance']:g} m "
                  "(guided ToF ISP), mm")
    ax.set_ylabel(f"CPSNR of the best method, dB ({res['dataset']['name']}, "
                  f"{len(res['dataset']['images'])} images)")
    ax.set_title("RGB-Z layouts: colour loss against depth noise (marker area: cost)",
                 fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    if left:
        fig.text(0.01, 0.01, "no depth measured: " + ", ".join(left), fontsize=7)
    ax.margins(x=0.08, y=0.12)
    lo, hi = ax.get_xlim()
    ax.set_xlim(lo, hi + 0.3 * (hi - lo))          # room for the labels right of the points
    fig.tight_layout()
    # labels last, where the axes are final: each takes the first offset above or below its
    # point whose box (thumbnail and text, in points) covers no label placed before it
    to_pt = ax.transData + fig.dpi_scale_trans.inverted()
    placed = []
    for r in sorted(pts, key=lambda r: r["cpsnr"]):
        xy = (r["wall_sigma_mm"], r["cpsnr"])
        x0, y0 = to_pt.transform(xy) * 72
        text = f"{r['layout']} ({r['method']})"
        width = 34 + 4.2 * len(text)
        dy = next((d for d in (16, -16, 34, -34, 52, -52, 70, -70)
                   if not any(abs(y0 + d - py) < 18 and x0 < px + pw and px < x0 + width
                              for px, py, pw in placed)), 16)
        placed.append((x0, y0 + dy, width))
        img = tile_thumbnail(r["tile"])
        ax.add_artist(AnnotationBbox(OffsetImage(img, zoom=20.0 / max(img.shape[:2]),
                                                 interpolation="nearest"),
                                     xy, xybox=(20, dy), xycoords="data",
                                     boxcoords="offset points", pad=0.1, frameon=True))
        ax.annotate(text, xy, xytext=(34, dy - 3), textcoords="offset points", fontsize=7,
                    arrowprops=dict(arrowstyle="-", lw=0.4, color="0.5") if abs(dy) > 16
                    else None)
    return _png(fig)


def hardware_sweep_plot(rows, title="", dataset=None):
    """Quality (share of Z sites more than 1 LSB from float64, log) against table + datapath
    bits of :func:`rgbz_fast._devtools.hardware.run_sweep`'s rows (PNG bytes): green where the
    target is met, outlined and labelled on the front; a configuration with no site beyond
    1 LSB (0 %, which a log axis cannot show) is a triangle at the axis floor. The title
    names ``dataset`` (when given) and the images measured."""
    from matplotlib.lines import Line2D

    from .hardware import TARGET

    _, plt = _pyplot()
    ok = [r for r in rows if "bits" in r]
    floor = 1e-4
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    points = []
    for r in ok:
        x = (r["bits"]["tables"] + r["bits"]["datapath"]) / 1000.0
        beyond = 100.0 - r["within_1lsb_pct"]
        exact = beyond <= 0
        # exact rows drawn at the axis floor, as triangles: a dot there read as 1e-4 %
        y = floor if exact else max(beyond, floor)
        ax.scatter(x, y, c="tab:green" if r["meets_target"] else "tab:red",
                   marker="v" if exact else "o", s=36 if r["pareto"] else 14,
                   edgecolors="k" if r["pareto"] else "none", zorder=3)
        if r["pareto"] or r["label"] == "default":
            points.append((x, y, r["label"]))
    target = 100.0 - TARGET["within_1lsb_pct"]
    ax.axhline(target, color="grey", ls="--", lw=0.8)
    ax.set_yscale("log")
    ax.set_xlabel("table + datapath bits (thousands; line buffers excluded: fixed)")
    ax.set_ylabel("% of Z sites more than 1 LSB from float64")
    images = {e.get("images") for r in ok for e in (r.get("error") or {}).values()
              if isinstance(e, dict)} - {None}
    what = ", ".join(t for t in (
        title, f"dataset {dataset}" if dataset else "",
        f"{max(images)} image{'s' if max(images) != 1 else ''}" if images else "") if t)
    ax.set_title(what, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)

    def dot(colour, label, marker="o", edge="none", size=6):
        return Line2D([], [], ls="none", marker=marker, markersize=size, markerfacecolor=colour,
                      markeredgecolor=edge, label=label)

    handles = [dot("tab:green", "meets the target"), dot("tab:red", "misses the target"),
               dot("white", "Pareto front (labelled)", edge="k", size=8),
               Line2D([], [], ls="--", color="grey", lw=0.8,
                      label=f"target: {target:g} % beyond 1 LSB")]
    if any(100.0 - r["within_1lsb_pct"] <= 0 for r in ok):
        handles.append(dot("0.5", f"0 %: exact (drawn at {floor:g} %)", marker="v"))
    ax.legend(handles=handles, fontsize=7, loc="upper right", framealpha=0.9)
    fig.tight_layout()
    # labels last, on the final axes: each takes the first offset whose box covers no label
    # placed before it nor the legend ("default" and "recip_table_size=16" had printed as one
    # smear, a few bits apart at the floor)
    renderer = fig.canvas.get_renderer()
    taken = [ax.get_legend().get_window_extent(renderer)]
    for x, y, label in sorted(points, key=lambda p: (p[1], p[0])):
        for dx, dy in ((4, 4), (4, -11), (4, 13), (4, -20), (-4, 4), (-4, -11), (4, 22),
                       (4, -29), (-4, 13), (-4, -20), (4, 31), (4, -38)):
            t = ax.annotate(label, (x, y), fontsize=7, xytext=(dx, dy),
                            textcoords="offset points", ha="left" if dx > 0 else "right",
                            arrowprops=dict(arrowstyle="-", lw=0.4, color="0.5")
                            if abs(dy) > 13 else None)
            box = t.get_window_extent(renderer)
            # inside the axes too: the rightmost front point's label had run off the figure
            # (the labels are placed after tight_layout); the left-side offsets take it
            if not any(box.overlaps(b) for b in taken) and ax.bbox.x0 <= box.x0 \
                    and box.x1 <= ax.bbox.x1:
                break
            t.remove()
        else:
            t = ax.annotate(label, (x, y), fontsize=7, xytext=(4, 4),
                            textcoords="offset points")
            box = t.get_window_extent(renderer)
        taken.append(box)
    # the configurations the model refused have no point: named under the axes (the table
    # lists them; the plot had left them out without a word)
    refused = [r["label"] for r in rows if "bits" not in r]
    if refused:
        from ..evaluation._reports import _footnote

        _footnote(fig, [f"Not drawn: {len(refused)} configuration"
                        f"{'s' if len(refused) != 1 else ''} the model refused "
                        f"({', '.join(refused)}; the table gives the reason)."], fontsize=7)
    return _png(fig, bbox_inches="tight")
