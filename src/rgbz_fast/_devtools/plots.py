"""The figures of the commands: the depth preview of ``rgbz-fast depth`` and the Pareto plot
of ``rgbz-fast tradeoff``.

Each function returns PNG bytes, which the command writes with
:func:`rgbz_fast.io.atomic_write`. matplotlib is imported here only, and only
when a figure is drawn (with the Agg backend unless the caller chose one), so
that neither ``import rgbz_fast`` nor a command without figures loads it.
"""

from __future__ import annotations

import io

import numpy as np

__all__ = ["depth_preview", "tradeoff_plot"]


def _pyplot():
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return matplotlib, plt


def _png(fig, plt, **kwargs):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, **kwargs)
    plt.close(fig)
    return buf.getvalue()


def depth_preview(res, title, scale=None, truth_known=None):
    """An 8-bit colour-mapped PNG of a depth result, with its colour scale (PNG bytes).

    The Z measurements are painted on the frame; colour sites show the
    nearest measurement (the preview only: the TIFF holds NaN there), the
    measurements the ISP flags are grey, and, for a simulated frame
    (``truth_known``: the taps' ground-truth validity), the measurements
    whose ground truth is unknown are shaded red: the scene filled their
    depth in from the nearest known one. ``scale``: (min, max) metres of the
    colour map; default the 1st to 99th percentile of the valid depth.
    """
    matplotlib, plt = _pyplot()
    from matplotlib.patches import Patch
    from scipy import ndimage

    depth = res.to_frame(res.depth)
    valid = res.to_frame(res.valid, fill=False).astype(bool)
    measured = res.to_frame(np.ones(res.n_sites, bool), fill=False).astype(bool)
    idx = ndimage.distance_transform_edt(~measured, return_distances=False,
                                         return_indices=True)
    depth = depth[idx[0], idx[1]]
    valid = valid[idx[0], idx[1]]
    unknown = None
    if truth_known is not None and not np.all(truth_known):
        known = np.asarray(truth_known, bool)
        unknown = res.to_frame(~known, fill=False).astype(bool)[idx[0], idx[1]]
    good = depth[valid]
    if scale is None:
        scale = (float(np.percentile(good, 1)), float(np.percentile(good, 99))) if good.size \
            else (0.0, 1.0)
        if scale[1] <= scale[0]:
            scale = (scale[0], scale[0] + 1e-3)
    rows, cols = depth.shape
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
    return _png(fig, plt, bbox_inches="tight")


#: marker of each (precision, exponential) of the trade-off rows
_MARKERS = {("float64", "libm"): "o", ("float32", "libm"): "s", ("float64", "fast"): "^",
            ("float32", "fast"): "D", ("float64", "-"): "o", ("float32", "-"): "s"}


def full_depth_preview(depth, title, scale=None):
    """An 8-bit colour-mapped PNG of a full-resolution depth map (NaN grey), with its scale.

    ``scale``: (min, max) metres; default the 1st to 99th percentile of the finite depths."""
    matplotlib, plt = _pyplot()
    good = depth[np.isfinite(depth)]
    if scale is None:
        scale = (float(np.percentile(good, 1)), float(np.percentile(good, 99))) if good.size \
            else (0.0, 1.0)
        if scale[1] <= scale[0]:
            scale = (scale[0], scale[0] + 1e-3)
    rows, cols = depth.shape
    fig, ax = plt.subplots(figsize=(6.4, 6.4 * rows / cols * 0.92 + 0.6))
    cmap = matplotlib.colormaps["viridis"].with_extremes(bad="0.6")
    im = ax.imshow(np.ma.masked_invalid(depth), cmap=cmap, vmin=scale[0], vmax=scale[1],
                   interpolation="nearest")
    ax.set_xticks([])
    ax.set_yticks([])
    fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, extend="both").set_label("distance (m)")
    ax.set_title(f"{title} ({100 * good.size / depth.size:.1f} % covered)", fontsize=9)
    return _png(fig, plt, bbox_inches="tight")


def tradeoff_plot(res):
    """Pareto plot of :func:`rgbz_fast._devtools.tradeoff.run_tradeoff`'s result (PNG bytes).

    One panel per pattern: Mpix/s (log) against mean CFA PSNR. Each row is a
    point with its IQR bar, coloured by method (and domain), shaped by its
    precision and exponential, outlined when on the front; the front is a
    dashed line.
    """
    from .tradeoff import NO_EXP, PATTERNS, QUICK_NOTE, series, threads_text

    _, plt = _pyplot()
    pats = sorted({r["pattern"] for r in res["rows"]},
                  key=lambda p: PATTERNS.index(p) if p in PATTERNS else 99)
    fig, axes = plt.subplots(1, len(pats), figsize=(6.5 * len(pats), 5), squeeze=False)
    names = list(dict.fromkeys(series(r) for r in res["rows"]))
    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colours = {m: cycle[i % len(cycle)] for i, m in enumerate(names)}
    for ax, p in zip(axes[0], pats):
        sub = [r for r in res["rows"] if r["pattern"] == p]
        for r in sub:
            ax.scatter(r["mpix_s"], r["cfa_psnr"], marker=_MARKERS[(r["precision"], r["exp"])],
                       color=colours[series(r)], s=50,
                       edgecolor="k" if r["pareto"] else "none", zorder=3)
            ax.plot([r["mpix_s_lo"], r["mpix_s_hi"]], [r["cfa_psnr"]] * 2, lw=1, alpha=0.4,
                    color=colours[series(r)], zorder=2)     # IQR of the runs
        front = sorted((r for r in sub if r["pareto"]), key=lambda r: r["mpix_s"])
        ax.plot([r["mpix_s"] for r in front], [r["cfa_psnr"] for r in front], "k--", lw=1,
                zorder=1, label="Pareto front")
        for m in names:
            if any(series(r) == m for r in sub):
                ax.scatter([], [], color=colours[m], label=m)
        for (prec, exp), mk in _MARKERS.items():
            if exp != NO_EXP:
                ax.scatter([], [], marker=mk, color="grey", label=f"{prec}, exp={exp}")
        ax.set_xscale("log")
        ax.set_xlabel(f"speed, Mpix/s, best of {res['repeat']} ({threads_text(res)}, "
                      f"{res['speed_frame'][1]}x{res['speed_frame'][0]} frame)")
        ax.set_ylabel(f"mean CFA PSNR, dB ({res['dataset']}, {len(res['images'])} images)")
        ax.set_title(p + (f" ({QUICK_NOTE})" if res.get("quick") else ""))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    return _png(fig, plt)
