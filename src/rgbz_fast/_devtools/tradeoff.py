"""``rgbz-fast tradeoff``: speed against accuracy of every method, precision, exp and domain.

For every reconstruction method x pattern (Mask1, Mask2) x precision
(float32, float64) x exponential (the C library's ``exp``, and the fast
polynomial ``exp="fast"`` for the methods that use one) -- plus the
colour-difference domain of the weighted methods (float64 with libm, float32
with the fast exp) and the learned filters (no exponential) -- it measures

* the speed: frame Mpix/s of ``reconstruct`` on one frame (the benchmark
  scene of ``rgbz-fast bench``, 2048x1536 by default), all threads, the best
  of N runs interleaved across the variants (robust to bursts of load from
  other processes on a shared machine; the median and IQR are reported too);
* the accuracy on a set of images (Kodak with ``--dataset
  ../shared/data/kodak``; by default scikit-image's sample images, so that it
  runs offline), with the frames and the colour chain of ``rgbz-fast
  evaluate`` (:func:`rgbz_fast.evaluation.image_frames`,
  :meth:`rgbz_fast.ColourISP.render`): 8-bit sRGB linearised with the sRGB
  EOTF, noise-free mosaics at 11 bits, mean CFA PSNR on every reconstructed
  (Z) site (eqs. 20-21), and mean CPSNR of the 8-bit sRGB images (grey-world
  white balance estimated on the reference, Malvar 2004, sRGB gamma, 8-pixel
  border left out);
* what the approximations change: for float32 and/or the fast exp, the
  largest difference (DN) and the share of Z pixels that differ from the
  float64 + libm output of the same method.

It draws the Pareto plot (PNG, matplotlib's Agg backend) and writes the table
(Markdown) with a paragraph, computed from the numbers, on what each
approximation costs.

``--quick`` is a smoke test (two 128x128 crops, a 256x192 speed frame, two
runs): its speeds are printed, labelled "quick run: numbers not comparable, no
verdict", but no speed ratio between variants is summarised and no Pareto
front is drawn from them.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import numpy as np

from .._validate import kernel_threads
from ._common import (CliError, check_out_dir, check_workers_arg, common_parser, machine_info,
                      progress, run_main, write_json)

__all__ = ["run_tradeoff", "pareto_front", "plot_tradeoff", "format_markdown", "main"]

METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "learned")
#: border (pixels) left out of CPSNR, as evaluate's default crop
CROP = 8
USES_EXP = ("edi_central", "edi_line", "sg")
#: the methods that also run in the colour-difference domain (eq. 5)
CD_METHODS = ("bi", "edi_central", "edi_line", "sg")
#: the exp column of a method that has no exponential (learned)
NO_EXP = "-"
PATTERNS = ("mask1", "mask2")
SPEED_SHAPE = (1536, 2048)
QUICK_SPEED_SHAPE = (192, 256)


def _variants(methods):
    """(method, precision, exp, domain) of every row."""
    for m in methods:
        for prec in ("float64", "float32"):
            if m == "learned":
                yield m, prec, NO_EXP, "intensity"
                continue
            for exp in (("libm", "fast") if m in USES_EXP else ("libm",)):
                yield m, prec, exp, "intensity"
    for m in methods:
        if m in CD_METHODS:        # the library's defaults: libm in float64, fast in float32
            yield m, "float64", "libm", "colour_difference"
            yield m, "float32", "fast" if m in USES_EXP else "libm", "colour_difference"


def _options(prec, exp, domain):
    """The reconstruct() options of a row."""
    kw = dict(precision=prec, domain=domain)
    if exp != NO_EXP:
        kw["exp"] = exp
    return kw


def _is_base(r):
    """The float64 + libm row of a method and domain, the one the others are compared with."""
    return r["precision"] == "float64" and r["exp"] in ("libm", NO_EXP)


def pareto_front(points, tol=1e-3):
    """Indices of the points (speed, quality) not dominated by another.

    A point is dominated by one at least as fast and at least as good, and
    strictly better in one of the two; qualities closer than ``tol`` (dB) count
    as equal, so that a float32 variant 1e-6 dB "better" than float64 does
    not survive on the front when it is slower.
    """
    idx = []
    for i, (s, q) in enumerate(points):
        dominated = False
        for j, (s2, q2) in enumerate(points):
            if j == i:
                continue
            q_ge = q2 >= q - tol
            q_gt = q2 > q + tol
            if s2 >= s and q_ge and (s2 > s or q_gt):
                dominated = True
                break
        if not dominated:
            idx.append(i)
    return idx


QUICK_NOTE = "quick run: numbers not comparable, no verdict"


def run_tradeoff(dataset, *, methods=METHODS, patterns=PATTERNS, speed_shape=SPEED_SHAPE,
                 repeat=5, workers=None, quiet=True, dataset_name="skimage samples",
                 quick=False):
    """Measure every variant; returns the JSON-able result dict.

    ``dataset``: a list of :class:`rgbz_fast.io.ImageSource`. Returns ``{"rows": [...], ...}``
    with, per row, ``pattern``, ``method``, ``precision``, ``exp``, ``domain``,
    ``mpix_s`` (best of ``repeat`` interleaved runs), ``mpix_s_median``,
    ``mpix_s_lo``/``hi`` (IQR), ``cfa_psnr`` and
    ``cpsnr`` (means over the images), ``max_abs_diff_dn`` and
    ``frac_diff`` (against float64 + libm of the same method and domain) and
    ``pareto`` (on the front of its pattern; None in a ``quick`` run, whose speeds rank
    nothing).
    """
    import rgbz_fast as rz
    from ..evaluation import EvalConfig, image_frames
    from ..metrics import cfa_psnr, cpsnr
    from .bench import make_rgb

    workers = workers or (os.cpu_count() or 1)
    sources = list(dataset)
    if not sources:
        raise ValueError("dataset: expected at least one image")
    # the frames and the colour chain of the dataset evaluation (docs/reports/results.md)
    config = EvalConfig(patterns=patterns, methods=methods, metrics=("cfa_psnr", "cpsnr"),
                        crop=CROP)
    bd = config.bit_depth
    chain = config.colour_isp()
    speed_rgb = make_rgb(speed_shape)
    variants = [(p, m, pr, e, d) for p in patterns for (m, pr, e, d) in _variants(methods)]
    # per pattern, per image: reference CFA, RGB-Z frame, reference sRGB and its gains
    prepared = {p: [] for p in patterns}
    for src in sources:
        img = src.load()
        for p in patterns:
            frame, ref = image_frames(img, p, config)
            phase = frame.pattern.bayer_phase
            ref8, st = chain.render(ref, phase, bit_depth=bd, workers=workers,
                                    return_stages=True)
            prepared[p].append((src.name, ref, frame, ref8, st["gains"]))
    # speed: the runs of all variants are interleaved (round robin), so that a burst of load
    # from other processes slows every variant alike; the speed is the best of the runs
    # (the least disturbed), the median is kept beside it
    speed_frames = {p: rz.mosaic(speed_rgb, rz.get_pattern(p), bd) for p in patterns}
    times = {v: [] for v in variants}
    for p, m, prec, exp, dom in variants:                       # warm-up
        rz.reconstruct(speed_frames[p], m, workers=workers, **_options(prec, exp, dom))
    for _ in progress(range(repeat), desc="speed", quiet=quiet):
        for v in variants:
            p, m, prec, exp, dom = v
            kw = _options(prec, exp, dom)
            t0 = time.perf_counter()
            rz.reconstruct(speed_frames[p], m, workers=workers, **kw)
            times[v].append(time.perf_counter() - t0)
    rows = []
    exact = {}
    for v in progress(variants, desc="accuracy", quiet=quiet):
        p, m, prec, exp, dom = v
        q1, med, q3 = np.percentile(times[v], [25, 50, 75])
        best = min(times[v])
        npix = speed_shape[0] * speed_shape[1] / 1e6
        psnrs, cps, maxdiff, ndiff, nz = [], [], 0.0, 0, 0
        for i, (name, ref, frame, ref8, gains) in enumerate(prepared[p]):
            out = rz.reconstruct(frame, m, workers=workers, **_options(prec, exp, dom))
            z = frame.z_mask
            psnrs.append(cfa_psnr(ref, out, z, bit_depth=bd))
            test8 = chain.render(out, frame.pattern.bayer_phase, bit_depth=bd, gains=gains,
                                 workers=workers)
            cps.append(cpsnr(ref8, test8, crop=CROP))
            key = (p, m, dom, i)
            if prec == "float64" and exp in ("libm", NO_EXP):
                exact[key] = out
            else:
                d = np.abs(out.astype(np.int32) - exact[key].astype(np.int32))[z]
                maxdiff = max(maxdiff, float(d.max()))
                ndiff += int(np.count_nonzero(d))
            nz += int(z.sum())
        base = prec == "float64" and exp in ("libm", NO_EXP)
        rows.append(dict(pattern=p, method=m, precision=prec, exp=exp, domain=dom,
                         mpix_s=npix / best,
                         mpix_s_median=npix / med, mpix_s_lo=npix / q3, mpix_s_hi=npix / q1,
                         cfa_psnr=float(np.mean(psnrs)), cpsnr=float(np.mean(cps)),
                         cfa_psnr_per_image=[float(v) for v in psnrs],
                         max_abs_diff_dn=None if base else maxdiff,
                         frac_diff=None if base else ndiff / nz))
    for p in patterns:
        sub = [r for r in rows if r["pattern"] == p]
        front = set(pareto_front([(r["mpix_s"], r["cfa_psnr"]) for r in sub]))
        for i, r in enumerate(sub):
            r["pareto"] = None if quick else i in front
    return {"machine": machine_info(), "dataset": dataset_name, "quick": bool(quick),
            "images": [src.name for src in sources], "speed_frame": list(speed_shape),
            "repeat": repeat, "warmup_calls": 1, "workers": workers,
            "threads_used": kernel_threads(workers, speed_shape[0] * speed_shape[1]),
            "bit_depth": bd, "rows": rows}


class _Crop:
    """The top-left ``size`` x ``size`` pixels of an image source (``--quick``)."""

    def __init__(self, source, size):
        self.source, self.size, self.name = source, size, source.name

    def load(self):
        return np.ascontiguousarray(self.source.load()[:self.size, :self.size])


def _series(r):
    """The plot series of a row: the method, with " cd" in the colour-difference domain."""
    return r["method"] + (" cd" if r.get("domain") == "colour_difference" else "")


def plot_tradeoff(res, path):
    """Pareto plot (one panel per pattern): Mpix/s (log) against mean CFA PSNR."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    pats = sorted({r["pattern"] for r in res["rows"]}, key=lambda p: PATTERNS.index(p)
                  if p in PATTERNS else 99)
    fig, axes = plt.subplots(1, len(pats), figsize=(6.5 * len(pats), 5), squeeze=False)
    markers = {("float64", "libm"): "o", ("float32", "libm"): "s", ("float64", "fast"): "^",
               ("float32", "fast"): "D", ("float64", NO_EXP): "o", ("float32", NO_EXP): "s"}
    series = list(dict.fromkeys(_series(r) for r in res["rows"]))
    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colours = {m: cycle[i % len(cycle)] for i, m in enumerate(series)}
    for ax, p in zip(axes[0], pats):
        sub = [r for r in res["rows"] if r["pattern"] == p]
        for r in sub:
            ax.scatter(r["mpix_s"], r["cfa_psnr"], marker=markers[(r["precision"], r["exp"])],
                       color=colours[_series(r)], s=50,
                       edgecolor="k" if r["pareto"] else "none", zorder=3)
            ax.plot([r["mpix_s_lo"], r["mpix_s_hi"]], [r["cfa_psnr"]] * 2, lw=1, alpha=0.4,
                    color=colours[_series(r)], zorder=2)     # IQR of the runs
        front = sorted((r for r in sub if r["pareto"]), key=lambda r: r["mpix_s"])
        ax.plot([r["mpix_s"] for r in front], [r["cfa_psnr"] for r in front], "k--", lw=1,
                zorder=1, label="Pareto front")
        for m in series:
            if any(_series(r) == m for r in sub):
                ax.scatter([], [], color=colours[m], label=m)
        for (prec, exp), mk in markers.items():
            if exp != NO_EXP:
                ax.scatter([], [], marker=mk, color="grey", label=f"{prec}, exp={exp}")
        ax.set_xscale("log")
        ax.set_xlabel(f"speed, Mpix/s, best of {res['repeat']} ({_threads(res)}, "
                      f"{res['speed_frame'][1]}x{res['speed_frame'][0]} frame)")
        ax.set_ylabel(f"mean CFA PSNR, dB ({res['dataset']}, {len(res['images'])} images)")
        ax.set_title(p + (f" ({QUICK_NOTE})" if res.get("quick") else ""))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _findings(res):
    """Sentences, from the numbers, on what float32 and the fast exp cost."""
    out = []
    rows = res["rows"]
    for what, sel in (("float32 (libm exp)", lambda r: r["precision"] == "float32"
                       and r["exp"] == "libm"),
                      ("the fast exp (float64)", lambda r: r["precision"] == "float64"
                       and r["exp"] == "fast"),
                      ("float32 with the fast exp", lambda r: r["precision"] == "float32"
                       and r["exp"] == "fast")):
        sub = [r for r in rows if sel(r)]
        if not sub:
            continue
        dps, sp = [], []
        for r in sub:
            base = next(b for b in rows if b["pattern"] == r["pattern"]
                        and b["method"] == r["method"] and b["domain"] == r["domain"]
                        and _is_base(b))
            dps.append(r["cfa_psnr"] - base["cfa_psnr"])
            sp.append(r["mpix_s"] / base["mpix_s"])
        worst = max(sub, key=lambda r: r["max_abs_diff_dn"])
        frac = max(r["frac_diff"] for r in sub)
        speed = (f" ({QUICK_NOTE} on speed)" if res.get("quick") else
                 f"; speed x{min(sp):.2f} to x{max(sp):.2f}")
        out.append(
            f"* **{what}**: mean CFA PSNR changes by {_db(min(dps))} to {_db(max(dps))} dB "
            f"against float64 + libm; at most {frac * 100:.3g} % of the Z pixels of one variant "
            f"differ, by at most {worst['max_abs_diff_dn']:.0f} DN ({worst['method']} "
            f"{worst['pattern']}){speed}.")
    return out


def _threads(res):
    used = res.get("threads_used", res["workers"])
    return f"{used} thread{'s' if used > 1 else ''}" + (
        "" if used == res["workers"] else f" (of {res['workers']}: one per 2**18 pixels)")


def _db(v):
    return f"{v:+.4f}" if abs(v) >= 1e-3 or v == 0 else f"{v:+.1e}"


def format_markdown(res, png_name=None, command=None):
    m = res["machine"]
    quick = [f"**{QUICK_NOTE.capitalize()}** (`--quick`: a smoke test; its speeds rank "
             "nothing and no Pareto front is marked).", ""] if res.get("quick") else []
    lines = ["# Speed/accuracy trade-off", ""] + quick + [
             "Generated by `rgbz-fast tradeoff` "
             + (f"(`{command}`)" if command else "") + f". Machine: {m['cpu_model']}, "
             f"{m['logical_cores']} logical cores; {_threads(res)}. Speed: frame "
             f"Mpix/s of `reconstruct` on a {res['speed_frame'][1]}x{res['speed_frame'][0]} "
             f"uint16 frame, best of {res['repeat']} runs interleaved across the variants "
             f"after {res.get('warmup_calls', 1)} warm-up call each "
             "(median [IQR] beside it). Accuracy: noise-free "
             f"{res['bit_depth']}-bit mosaics of {len(res['images'])} linearised images "
             f"({res['dataset']}), mean CFA PSNR on every Z site and mean CPSNR of the 8-bit "
             f"sRGB images of the library's colour chain (grey-world white balance of the "
             f"reference, Malvar 2004, sRGB gamma; {CROP}-pixel border left out): the protocol "
             "of `rgbz-fast evaluate` (docs/reports/results.md). Domain: intensity (the "
             "paper) or colour_difference (eq. 5); learned: the shipped filters (no "
             "exponential). Δ: against float64 + libm exp of the same method and domain, "
             "over every Z site "
             "(largest |difference| in DN, share of Z pixels that differ). Bold: on the "
             "Pareto front of its mask (nothing both faster and more accurate).", ""]
    if png_name:
        lines += [f"![Pareto plot]({png_name})", ""]
    lines += ["## What the approximations cost", ""] + _findings(res) + ([""] if quick else [
        "", "Speed ratios between variants are within run-to-run noise on a shared machine "
        "when they are close to 1; see the IQR column.", ""])
    for p in sorted({r["pattern"] for r in res["rows"]}):
        lines += [f"## {p}", "", "| method | domain | precision | exp | Mpix/s best | "
                  "median [IQR] | CFA PSNR (dB) | CPSNR (dB) | max Δ (DN) | pixels differing |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        for r in (r for r in res["rows"] if r["pattern"] == p):
            b = "**" if r["pareto"] else ""
            d = "-" if r["max_abs_diff_dn"] is None else f"{r['max_abs_diff_dn']:.0f}"
            f = "-" if r["frac_diff"] is None else f"{r['frac_diff'] * 100:.3g} %"
            lines.append(f"| {b}{r['method']}{b} | {r['domain']} | {r['precision']} | "
                         f"{r['exp']} | "
                         f"{r['mpix_s']:.1f} | {r['mpix_s_median']:.1f} "
                         f"[{r['mpix_s_lo']:.1f}-{r['mpix_s_hi']:.1f}] | "
                         f"{r['cfa_psnr']:.3f} | {r['cpsnr']:.3f} | {d} | {f} |")
        lines.append("")
    return "\n".join(lines)


def format_text(res):
    head = f"{'pattern':7}  {'method':14}  {'prec':7}  {'exp':4}  {'Mpix/s':>7}  " \
           f"{'CFA PSNR':>8}  {'CPSNR':>7}  {'maxΔ':>5}  {'differ':>8}  pareto"
    lines = ([QUICK_NOTE.capitalize() + " (a smoke test)"] if res.get("quick") else []) + [
        f"speed: best of {res['repeat']} timed runs after {res.get('warmup_calls', 1)} warm-up "
        f"call, {_threads(res)}, {res['speed_frame'][1]}x{res['speed_frame'][0]} frame",
        head, "-" * len(head)]
    for r in res["rows"]:
        d = "-" if r["max_abs_diff_dn"] is None else f"{r['max_abs_diff_dn']:.0f}"
        f = "-" if r["frac_diff"] is None else f"{r['frac_diff'] * 100:.3g}%"
        lines.append(f"{r['pattern']:7}  {_series(r):14}  {r['precision']:7}  {r['exp']:4}  "
                     f"{r['mpix_s']:7.1f}  {r['cfa_psnr']:8.3f}  {r['cpsnr']:7.3f}  {d:>5}  "
                     f"{f:>8}  {'*' if r['pareto'] else ''}")
    return "\n".join(lines + [""] + _findings(res))


def main(argv=None):
    """``rgbz-fast tradeoff``."""
    p = common_parser("rgbz-fast tradeoff", __doc__)
    p.add_argument("--dataset", default=None, metavar="DIR",
                   help="folder of images (e.g. ../shared/data/kodak); default: scikit-image "
                        "sample images")
    p.add_argument("--limit", type=int, default=None,
                   help="use the first N images only (default: all)")
    p.add_argument("--repeat", type=int, default=None, help="timed runs (default 5, quick 2)")
    p.add_argument("--methods", default=",".join(METHODS),
                   help="comma-separated methods (default: %(default)s)")
    p.add_argument("--patterns", default=",".join(PATTERNS),
                   help="comma-separated patterns (default: %(default)s)")

    def body(args):
        workers = check_workers_arg(args.workers)
        out = check_out_dir(args.out)
        if args.limit is not None and args.limit < 1:
            raise CliError(f"--limit: expected a positive integer, got {args.limit}")
        from ..io import folder_dataset, sample_dataset
        if args.dataset:
            images = folder_dataset(args.dataset, args.limit)
            name = Path(args.dataset).name
        else:
            images = sample_dataset()[: args.limit]
            name = "scikit-image samples"
        methods = tuple(m.strip() for m in args.methods.split(",") if m.strip())
        bad = [m for m in methods if m not in METHODS]
        if bad:
            raise CliError(f"--methods: unknown {', '.join(bad)}; expected some of "
                           f"{', '.join(METHODS)}")
        patterns = tuple(s.strip() for s in args.patterns.split(",") if s.strip())
        if args.quick:
            images = [_Crop(src, 128) for src in images[:2]]
        repeat = args.repeat if args.repeat is not None else (2 if args.quick else 5)
        if repeat < 1:
            raise CliError(f"--repeat: expected a positive integer, got {repeat}")
        res = run_tradeoff(images, methods=methods, patterns=patterns,
                           speed_shape=QUICK_SPEED_SHAPE if args.quick else SPEED_SHAPE,
                           repeat=repeat, workers=workers, quiet=args.quiet, dataset_name=name,
                           quick=args.quick)
        command = "rgbz-fast tradeoff " + " ".join(sys.argv[1:] if argv is None else argv)
        res["command"] = command
        if out is not None:
            plot_tradeoff(res, out / "tradeoff.png")
            (out / "tradeoff.md").write_text(format_markdown(res, "tradeoff.png", command) + "\n",
                                             encoding="utf-8")
            write_json(res, out / "tradeoff.json")
        print(write_json(res) if args.json else format_text(res))
        return 0

    return run_main(p, body, argv)


if __name__ == "__main__":
    sys.exit(main())
