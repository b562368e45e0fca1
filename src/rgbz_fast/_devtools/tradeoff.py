"""The engine of ``rgbz-fast tradeoff``: speed against accuracy of every method, precision,
exponential and domain.

:func:`run_tradeoff` measures every variant (:func:`_variants`): its speed,
the best of the runs of :func:`rgbz_fast._devtools.timing.interleaved` across
all variants, and its accuracy on a set of images with the frames and the
colour chain of ``rgbz-fast evaluate``; the rows on the Pareto front of their
pattern are marked (:func:`pareto_front`). :func:`format_markdown` and
:func:`format_text` write the result, with what each approximation costs
computed from the numbers; :func:`rgbz_fast._devtools.plots.tradeoff_plot`
draws it. A quick run ranks nothing: its speeds are reported, labelled
:data:`QUICK_NOTE`, and no front is marked.
"""

from __future__ import annotations

import os

import numpy as np

from .._validate import kernel_threads
from ._common import common_means, machine_info, progress
from .timing import WARMUP_CALLS, interleaved, rate_stats

__all__ = ["run_tradeoff", "pareto_front", "format_markdown", "format_text", "Crop", "METHODS",
           "PATTERNS", "SPEED_SHAPE", "QUICK_SPEED_SHAPE", "QUICK_NOTE"]

METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "learned")
#: what a run may ask for besides: z_guided reads the Z pixels' measurements, so a run with it
#: takes every frame from the sensor model (as evaluate does) and is not a default
OPTIONAL_METHODS = ("z_guided",)
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
            if m in ("learned", "z_guided"):
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
    ``cpsnr`` (means over the images on which every row of the pattern is finite:
    ``left_out`` names the others, those some variant reconstructs exactly), ``max_abs_diff_dn`` and
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
    # a method that does not reconstruct a pattern (learned without filters for a tile) is
    # left out of that pattern's rows, with its reason in "not_applicable"
    variants = [(p, m, pr, e, d) for p in patterns for (m, pr, e, d) in _variants(methods)
                if config.applies(p, m)]
    # per pattern, per image: reference CFA, RGB-Z frame, reference sRGB and its gains
    prepared = {p: [] for p in patterns}
    estimated = []                  # the images whose NIR z_guided's frames estimated
    for src in sources:
        img = src.load()
        for p in patterns:
            nir = src.load_nir() if config.needs_tof and hasattr(src, "load_nir") else None
            if config.needs_tof and nir is None and src.name not in estimated:
                estimated.append(src.name)
            try:
                frame, ref = image_frames(img, p, config, nir)
            except ValueError as exc:           # an image smaller than one period
                if not str(exc).startswith("rgb: "):
                    raise
                raise ValueError(f"dataset: image {src.name!r}: "
                                 f"{str(exc).removeprefix('rgb: ')}") from None
            phase = frame.pattern.bayer_phase
            ref8, st = chain.render(ref, phase, bit_depth=bd, workers=workers,
                                    return_stages=True)
            prepared[p].append((src.name, ref, frame, ref8, st["gains"]))
    # speed: the runs of all variants are interleaved (round robin), so that a burst of load
    # from other processes slows every variant alike; the speed is the best of the runs
    # (the least disturbed), the median is kept beside it
    speed_frames = {p: rz.mosaic(speed_rgb, rz.get_pattern(p), bd) for p in patterns}
    if config.needs_tof:        # frames with ToF taps: the speed includes the demodulation
        from ..simulation import ColourSensor, Scene, simulate
        scene = Scene.from_rgb(speed_rgb, depth=np.full(speed_shape, 2.0))
        speed_frames = {p: simulate(scene, p, ColourSensor(black_level=0), noise=True)
                        for p in patterns}

    def call(v):
        p, m, prec, exp, dom = v
        return lambda: rz.reconstruct(speed_frames[p], m, workers=workers,
                                      **_options(prec, exp, dom))

    times = interleaved({v: call(v) for v in variants}, repeat,
                        rounds=lambda it: progress(it, desc="speed", quiet=quiet))
    rows = []
    exact = {}
    for v in progress(variants, desc="accuracy", quiet=quiet):
        p, m, prec, exp, dom = v
        speed = rate_stats(times[v], speed_shape[0] * speed_shape[1])
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
                         mpix_s=speed["mpix_s_best"], mpix_s_median=speed["mpix_s"],
                         mpix_s_lo=speed["mpix_s_lo"], mpix_s_hi=speed["mpix_s_hi"],
                         cfa_psnr=float(np.mean(psnrs)), cpsnr=float(np.mean(cps)),
                         cfa_psnr_per_image=[float(v) for v in psnrs],
                         cpsnr_per_image=[float(v) for v in cps],
                         max_abs_diff_dn=None if base else maxdiff,
                         frac_diff=None if base else ndiff / nz))
    left_out = _common_means(rows, patterns, [src.name for src in sources])
    for p in patterns:
        sub = [r for r in rows if r["pattern"] == p]
        # a row without a mean (None: no image to average) is on no front; NaN, which no
        # comparison passes, had put every such row on it, in bold
        ranked = [i for i, r in enumerate(sub) if r["cfa_psnr"] is not None]
        front = {ranked[j] for j in pareto_front([(sub[i]["mpix_s"], sub[i]["cfa_psnr"])
                                                   for i in ranked])}
        for i, r in enumerate(sub):
            r["pareto"] = None if quick or r["cfa_psnr"] is None else i in front
    return {"machine": machine_info(), "dataset": dataset_name, "quick": bool(quick),
            "images": [src.name for src in sources], "speed_frame": list(speed_shape),
            "repeat": repeat, "warmup_calls": WARMUP_CALLS, "workers": workers,
            "threads_used": kernel_threads(workers, speed_shape[0] * speed_shape[1]),
            "bit_depth": bd, "rows": rows, "left_out": left_out,
            # how the frames were made (the report's protocol sentence says it): through the
            # sensor model when a method needs the Z pixels' taps (every method then sees
            # those frames), raw files as they are
            "sensor_model": bool(config.needs_tof),
            "raw_images": [src.name for src in sources if getattr(src, "is_raw", False)],
            "ir_estimated": estimated,
            "not_applicable": [[p, m, " ".join(str(why).split())] for (p, m), why
                               in config.not_applicable().items()]}


def _common_means(rows, patterns, names):
    """Each row's ``cfa_psnr`` and ``cpsnr`` as the mean over the images on which every row of
    its pattern is finite, so that the variants compare on the same images; returns
    ``{pattern: {metric: [images left out]}}`` (those with a +inf PSNR somewhere: a variant
    that reconstructs an image exactly). Every mean had been +inf beside one exact image
    (a flat one), the findings' differences NaN and the plot refused (`evaluate` leaves
    +inf out as well, and says so)."""
    out = {}
    for p in patterns:
        sub = [r for r in rows if r["pattern"] == p]
        for k in ("cfa_psnr", "cpsnr"):
            means, _, left = common_means(
                {i: dict(zip(names, r[f"{k}_per_image"])) for i, r in enumerate(sub)}, names)
            if left:
                out.setdefault(p, {})[k] = left
                for i, r in enumerate(sub):
                    r[k] = means[i]                 # inf when exact everywhere, else None
    return out


def _db_cell(v):
    """A mean PSNR of a table: 3 decimals, "inf" (exact on every image), "-" (no mean)."""
    return "-" if v is None else f"{v:.3f}"


def _left_out_note(res):
    """One sentence naming the images a pattern's means leave out ("" when none)."""
    parts = []
    for p, per in sorted(res.get("left_out", {}).items()):
        for k, names in per.items():
            label = {"cfa_psnr": "CFA PSNR", "cpsnr": "CPSNR"}[k]
            parts.append(f"{label} on {p} leaves out {', '.join(names)}")
    if not parts:
        return ""
    return ("Means over the images every variant reconstructs with a finite PSNR (an exact "
            "reconstruction's is +inf): " + "; ".join(parts) + ".")


class Crop:
    """The top-left ``size`` x ``size`` pixels of an image source (a quick run)."""

    def __init__(self, source, size):
        self.source, self.size, self.name = source, size, source.name

    def load(self):
        return np.ascontiguousarray(self.source.load()[:self.size, :self.size])

    def load_nir(self):
        nir = getattr(self.source, "load_nir", lambda: None)()
        return None if nir is None else np.ascontiguousarray(nir[:self.size, :self.size])


def series(r):
    """The plot series of a row: the method, with " cd" in the colour-difference domain."""
    return r["method"] + (" cd" if r.get("domain") == "colour_difference" else "")


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
            if all(isinstance(x, float) and np.isfinite(x)
                   for x in (r["cfa_psnr"], base["cfa_psnr"])):
                dps.append(r["cfa_psnr"] - base["cfa_psnr"])
            sp.append(r["mpix_s"] / base["mpix_s"])
        worst = max(sub, key=lambda r: r["max_abs_diff_dn"])
        frac = max(r["frac_diff"] for r in sub)
        speed = (f" ({QUICK_NOTE} on speed)" if res.get("quick") else
                 f"; speed x{min(sp):.2f} to x{max(sp):.2f}")
        widest = max(sub, key=lambda r: r["frac_diff"])
        # each figure names its own variant: the largest share and the largest difference
        # may be two variants' (the share had been named after the largest difference's)
        # (the domain too: the colour-difference row's share had been named after the
        # intensity row of its method)
        same = (series(widest), widest["pattern"]) == (series(worst), worst["pattern"])
        differ = ((f"at most {frac * 100:.3g} % of the Z pixels of one variant differ "
                   f"({series(widest)} {widest['pattern']}), by at most "
                   f"{worst['max_abs_diff_dn']:.0f} DN"
                   + ("" if same else f" ({series(worst)} {worst['pattern']})"))
                  if worst["max_abs_diff_dn"] > 0 else "no Z pixel differs")
        psnr = (f"mean CFA PSNR changes by {_db(min(dps))} to {_db(max(dps))} dB against "
                "float64 + libm" if dps else
                "no image with a finite CFA PSNR for every variant to compare on")
        out.append(f"* **{what}**: {psnr}; {differ}{speed}.")
    return out


def threads_text(res):
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
             f"{m['logical_cores']} logical cores; {threads_text(res)}. Speed: frame "
             f"Mpix/s of `reconstruct` on a {res['speed_frame'][0]}x{res['speed_frame'][1]} "
             f"uint16 frame, best of {res['repeat']} runs interleaved across the variants "
             f"after {res.get('warmup_calls', 1)} warm-up call each "
             f"(median [IQR] beside it). Accuracy: {_protocol(res)} "
             f"({res['dataset']}), mean CFA PSNR on every Z site and mean CPSNR of the 8-bit "
             f"sRGB images of the library's colour chain (grey-world white balance of the "
             f"reference, Malvar 2004, sRGB gamma; {CROP}-pixel border left out): the protocol "
             "of `rgbz-fast evaluate` (docs/reports/results.md). Domain: intensity (the "
             "paper) or colour_difference (eq. 5); learned: the shipped filters (no "
             "exponential). Δ: against float64 + libm exp of the same method and domain, "
             "over every Z site "
             "(largest |difference| in DN, share of Z pixels that differ). Bold: on the "
             "Pareto front of its mask (nothing both faster and more accurate).", ""]
    if res.get("ir_estimated"):
        lines += [_leak_note(res), ""]
    if _left_out_note(res):
        lines += [_left_out_note(res), ""]
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
                         f"{_db_cell(r['cfa_psnr'])} | {_db_cell(r['cpsnr'])} | {d} | {f} |")
        lines.append("")
    lines += [f"Not run: {m} on {p} ({why})." for p, m, why in res.get("not_applicable", ())]
    return "\n".join(lines)


def format_text(res):
    head = f"{'pattern':7}  {'method':14}  {'prec':7}  {'exp':4}  {'Mpix/s':>7}  " \
           f"{'CFA PSNR':>8}  {'CPSNR':>7}  {'maxΔ':>5}  {'differ':>8}  pareto"
    lines = ([QUICK_NOTE.capitalize() + " (a smoke test)"] if res.get("quick") else []) + [
        f"speed: best of {res['repeat']} timed runs after {res.get('warmup_calls', 1)} warm-up "
        f"call, {threads_text(res)}, {res['speed_frame'][0]}x{res['speed_frame'][1]} frame",
        head, "-" * len(head)]
    for r in res["rows"]:
        d = "-" if r["max_abs_diff_dn"] is None else f"{r['max_abs_diff_dn']:.0f}"
        f = "-" if r["frac_diff"] is None else f"{r['frac_diff'] * 100:.3g}%"
        lines.append(f"{r['pattern']:7}  {series(r):14}  {r['precision']:7}  {r['exp']:4}  "
                     f"{r['mpix_s']:7.1f}  {_db_cell(r['cfa_psnr']):>8}  "
                     f"{_db_cell(r['cpsnr']):>7}  {d:>5}  "
                     f"{f:>8}  {'*' if r['pareto'] else ''}")
    lines += [f"not run: {m} on {p} ({why})" for p, m, why in res.get("not_applicable", ())]
    if res.get("ir_estimated"):
        lines.append(_leak_note(res))
    if _left_out_note(res):
        lines.append(_left_out_note(res))
    return "\n".join(lines + [""] + _findings(res))


def _protocol(res):
    """How the accuracy's frames were made, as the run made them."""
    n, raw = len(res["images"]), len(res.get("raw_images", ()))
    if res.get("sensor_model"):
        text = (f"noise-free {res['bit_depth']}-bit frames of the sensor model (with ToF taps, "
                f"a wall at 2 m; every method sees them, as in `rgbz-fast evaluate` with "
                f"z_guided) of {n} image{'s' if n != 1 else ''}")
    else:
        text = (f"noise-free {res['bit_depth']}-bit mosaics of {n - raw} linearised "
                f"image{'s' if n - raw != 1 else ''}")
    if raw:
        text += (f" and {raw} raw file{'s' if raw != 1 else ''} measured as "
                 f"{'it is' if raw == 1 else 'they are'} (on the file's own Bayer phase)")
    return text


def _leak_note(res):
    """z_guided on NIR estimated from the RGB: the caveat rgbz-fast evaluate prints."""
    est, n = len(res["ir_estimated"]), len(res["images"])
    return (f"z_guided: the NIR was estimated from the RGB on {est} of {n} image"
            f"{'s' if n != 1 else ''} ({', '.join(res['ir_estimated'][:4])}"
            f"{', ...' if est > 4 else ''}): its guide then leaks the answer, and its rows are "
            "not evidence; measure it on registered RGB + NIR pairs.")
