"""Arithmetic operations per reconstructed pixel, beside the paper's Table 1.

The C kernels do their per-pixel arithmetic through the macros of
``csrc/rgbz_ops.h``. The same sources are compiled a second time with
``-DRGBZ_COUNT_OPS`` into the extension ``_kernels_count`` (docs/guide/performance.md,
"Operation counts beside Table 1"), where every macro also increments a
counter of its category: additions/subtractions,
multiplications, divisions, exponentials, absolute values, comparisons
(min, max, branch tests), square roots and atan2. Loads, index arithmetic,
the final clipping and the conversion to the output type are not counted, as
Table 1 does not count them.

:func:`count_operations` runs that counting kernel on a small frame and
returns, for every target colour, the mean, minimum and maximum count per
missing pixel. Counts depend on the data only through two branches: the
fallback to the plain mean when every weight underflows (it adds
``2n - 3`` additions) and the short-circuit tests of ``edi_rows``; the mean
over a random frame is therefore a slight over-estimate of what natural
images cost, and the maximum is the worst case seen.

Table 1 of the paper gives, for Mask2, two numbers per cell, "a/b". The
caption says green is interpolated from 11 pixels and red/blue from 8, and
the first number is the **red/blue** case: BI's additions are exactly
``2 n^2`` (128 = 2*8^2, 242 = 2*11^2) and its divisions exactly ``n``
(8/11), with ``n`` the number of candidates. :data:`TABLE1` stores the
pairs under the colour they belong to.

``rgbz-fast opcount`` prints the table (:func:`opcount_report`);
docs/guide/performance.md explains every difference of more than 25 %.
"""

from __future__ import annotations

import numpy as np

from .. import _kernels_count
from .._frame import frame_inputs, mosaic
from .._patterns import get_pattern
from ..reconstruction import ReconstructParams, reconstruct
from ..reconstruction import _reconstruct as _recon
from ..reconstruction._plans import build_plans

__all__ = ["CATEGORIES", "TABLE1", "TABLE1_CATEGORIES", "count_operations", "opcount_table",
           "opcount_report", "opcount_legend", "count_tof_operations", "DEFAULT_METHODS"]

#: counter categories, in the order of the C enum rgbz_op (csrc/rgbz.h, RGBZ_OP_*)
CATEGORIES = tuple(sorted(_kernels_count.OP_CATEGORIES, key=_kernels_count.OP_CATEGORIES.get))
#: the categories Table 1 reports
TABLE1_CATEGORIES = ("add", "mul", "div", "exp")
#: target colour groups (Table 1 splits Mask2 into green and red/blue)
GROUPS = ("green", "red/blue")

# Table 1 of the paper: (adds and subs, multiplications, divisions, exponentials).
# Mask2 "a/b" cells: a = red/blue (8 candidates), b = green (11 candidates).
TABLE1 = {
    ("bi", "mask1", "green"): dict(add=32, mul=12, div=4, exp=0),
    ("bi", "mask2", "red/blue"): dict(add=128, mul=32, div=8, exp=0),
    ("bi", "mask2", "green"): dict(add=242, mul=44, div=11, exp=0),
    ("edi_central", "mask1", "green"): dict(add=26, mul=16, div=16, exp=4),
    ("edi_central", "mask2", "red/blue"): dict(add=42, mul=20, div=24, exp=4),
    ("edi_central", "mask2", "green"): dict(add=51, mul=23, div=30, exp=4),
    ("edi_line", "mask1", "green"): dict(add=68, mul=16, div=16, exp=4),
    ("edi_line", "mask2", "red/blue"): dict(add=88, mul=20, div=24, exp=4),
    ("edi_line", "mask2", "green"): dict(add=97, mul=23, div=30, exp=4),
    ("sg", "mask1", "green"): dict(add=72, mul=28, div=28, exp=8),
    ("sg", "mask2", "red/blue"): dict(add=133, mul=55, div=36, exp=12),
    ("sg", "mask2", "green"): dict(add=142, mul=61, div=39, exp=12),
}

DEFAULT_METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "learned")
#: the options of count_operations: the bit depth and the fields of ReconstructParams that
#: change the arithmetic
_KW = dict(bit_depth=11, **{k: v for k, v in ReconstructParams().as_dict().items()
                            if k in ("sigma_floor", "sigma_rel", "edge_ratio", "sg_mode", "exp",
                                     "domain")})


def _kernel_codes(precision, kw):
    """The precision and exponential codes of the C kernel for these options."""
    p = ReconstructParams(precision=precision, exp=kw["exp"])
    return _recon._PRECISION_CODES[p.precision], _recon._EXP_CODES[p.exp_mode]


def _group_of(target):
    return "green" if int(target) == 1 else "red/blue"


def _frame_data(pattern, shape, seed, frame, bit_depth):
    """(uint16/float data with Z sites zeroed, pattern, bit depth) of the counting run."""
    if frame is not None:
        data, pattern, bd = frame_inputs(frame, pattern, bit_depth)
        return np.ascontiguousarray(data), pattern, bd
    pattern = get_pattern(pattern)
    try:
        rows, cols = (int(s) for s in shape)
    except (TypeError, ValueError):
        raise TypeError(f"shape: expected (rows, cols), got {shape!r}") from None
    P, Q = pattern.period
    rows, cols = -(-rows // P) * P, -(-cols // Q) * Q       # whole periods
    if rows < 3 * P or cols < 3 * Q:
        raise ValueError(f"shape: expected at least three pattern periods {pattern.period} "
                         f"in each dimension, got {shape!r}")
    bd = 11 if bit_depth is None else int(bit_depth)
    rng = np.random.default_rng(seed)
    data = rng.integers(0, 1 << bd, size=(rows, cols), dtype=np.uint16)
    data[pattern.z_mask((rows, cols))] = 0
    return data, pattern, bd


def _site_counts(data, pattern, method, precision, kw, ablate_beta=False, fast_path=True):
    """Counts of every interior Z site: (targets (n,), counts (n, NOPS) uint64).

    One plan per site (a copy of its phase's plan), so that the counting
    kernel keeps one row of counters per site. The phase map then spans the
    whole frame (period = frame size), which changes the border extension:
    only sites whose window lies inside the frame are used.
    """
    phase_map, plans = build_plans(pattern, method, kw["sg_mode"], kw["domain"])
    if ablate_beta:
        plans = plans.copy()
        plans["use_ab"] = 0
    rows, cols = data.shape
    P, Q = pattern.period
    ry = rx = 2     # at least the 5x5 kernel's radius: the sites the Mask1 fast path takes
    for p in plans:
        n = int(p["n_taps"])
        ry = max(ry, int(np.abs(p["tap_dy"][:n]).max()))
        rx = max(rx, int(np.abs(p["tap_dx"][:n]).max()))
    yy, xx = np.nonzero(pattern.z_mask(data.shape))
    inner = (yy >= ry) & (yy < rows - ry) & (xx >= rx) & (xx < cols - rx)
    yy, xx = yy[inner], xx[inner]
    if yy.size == 0:
        raise ValueError(f"shape: frame {data.shape} too small: no Z site lies {ry} rows and "
                         f"{rx} columns inside the border")
    site_plan = phase_map[(yy % P) * Q + (xx % Q)]
    site_plans = np.ascontiguousarray(plans[site_plan])
    full_map = np.full(rows * cols, -1, np.int32)
    full_map[yy * cols + xx] = np.arange(yy.size, dtype=np.int32)
    counts = np.zeros(yy.size * _kernels_count.NOPS, np.uint64)
    dst = np.empty_like(data)
    prec_code, exp_code = _kernel_codes(precision, kw)
    _kernels_count.reconstruct(data, dst, prec_code, rows, cols, full_map,
                               site_plans.view(np.uint8).reshape(-1), int(yy.size),
                               float(kw["sigma_floor"]), float(kw["sigma_rel"]),
                               float(kw["edge_ratio"]), float((1 << kw["bit_depth"]) - 1),
                               exp_code, 1, opcounts=counts)
    counts = counts.reshape(yy.size, _kernels_count.NOPS)
    if fast_path and not ablate_beta and _uses_mask1_fast(pattern, method, kw):
        counts = (counts.astype(np.int64)
                  + _mask1_fast_delta(data, pattern, yy, xx, method, precision, kw))
    return site_plans["target"].copy(), counts


def _learned_site_counts(data, pattern, precision, bit_depth):
    """Counts of the learned kernel (csrc/learned.c) per Z site: (targets, counts).

    The counting build runs one site per block and keeps one row of counters per
    phase; the hash and the dot product are branch-free, so every site of a
    phase costs the same and the phase's total over its site count is exact.
    """
    from ..reconstruction._learned import resolve_filters

    filters = resolve_filters(None, pattern)
    n_ph = len(filters.geometry)
    counts = np.zeros(n_ph * _kernels_count.NOPS, np.uint64)
    _recon.run_learned(data, np.empty_like(data), pattern, filters, precision, bit_depth, 1,
                       opcounts=counts, kernels=_kernels_count)
    counts = counts.reshape(n_ph, _kernels_count.NOPS)
    P, Q = pattern.period
    targets, rows = [], []
    for k, ph in enumerate(filters.geometry):
        r, c = ph["rc"]
        n = len(range(r, data.shape[0], P)) * len(range(c, data.shape[1], Q))
        targets += [ph["target"]] * n
        rows.append(np.repeat(counts[k:k + 1] // max(n, 1), n, axis=0))
        if counts[k].any() and (counts[k] % n).any():
            raise RuntimeError("learned: site counts differ within a phase")
    return np.array(targets), np.concatenate(rows)


def _counting_guide(shape, seed):
    """A positive NIR image for counting ``z_guided``: its operations do not depend on the
    values, only on the pattern (every counted operation of the kernel is unconditional)."""
    return np.random.default_rng(seed).uniform(0.05, 1.0, shape)


def _z_guided_site_counts(data, pattern, precision, bit_depth, seed):
    """Counts of the z_guided kernel (csrc/z_guided.c) per Z site: (targets, counts). As the
    learned kernel's, every site of a phase costs the same. The cell terms, one per tile,
    computed by the kernel once per tile row (csrc/z_guided.c), are not counted; the
    demodulation of the taps is count_tof_operations'."""
    from ..reconstruction._z_guided import guide_grid, resolve_z_filters
    from ..reconstruction._z_guided_kernel import run_z_guided

    filters = resolve_z_filters(None, pattern, bit_depth)
    n_ph = len(filters.base.geometry)
    counts = np.zeros(n_ph * _kernels_count.NOPS, np.uint64)
    grids = guide_grid(data.shape, pattern, nir=_counting_guide(data.shape, seed))
    run_z_guided(np.ascontiguousarray(data), np.empty_like(data), pattern, filters, grids,
                 precision, bit_depth, 1, opcounts=counts, kernels=_kernels_count)
    counts = counts.reshape(n_ph, _kernels_count.NOPS)
    P, Q = pattern.period
    targets, rows = [], []
    for k, ph in enumerate(filters.base.geometry):
        r, c = ph["rc"]
        n = len(range(r, data.shape[0], P)) * len(range(c, data.shape[1], Q))
        targets += [ph["target"]] * n
        rows.append(np.repeat(counts[k:k + 1] // max(n, 1), n, axis=0))
        if counts[k].any() and (counts[k] % n).any():
            raise RuntimeError("z_guided: site counts differ within a phase")
    return np.array(targets), np.concatenate(rows)


def _uses_mask1_fast(pattern, method, kw):
    """True where reconstruct() runs the Mask1 fast path (csrc/recon_mask1.h)."""
    return _recon.runs_mask1_fast_path(pattern, method, kw["domain"])


def _mask1_fast_delta(data, pattern, yy, xx, method, precision, kw):
    """Per site: counts of the Mask1 fast path minus those of the plan interpreter.

    The fast path counts a whole row into one counter, so each site is run
    alone: a 6x6 frame cut around it on a tile boundary keeps the tile phase
    and has exactly one interior Z site, the only one the fast path takes. The
    counting kernel runs on it with and without the fast path; the difference
    is that site's (the border sites take the same generic path both times).
    """
    phase_map, plans, n = _recon._plans_for(pattern, method, kw["sg_mode"], kw["domain"])
    P, Q = pattern.period
    rows, cols = data.shape
    out = np.zeros((yy.size, _kernels_count.NOPS), np.int64)
    for i, (y, x) in enumerate(zip(yy, xx)):
        # a 6x6 window starting on a tile boundary (so that the tile phase, and the kernel's
        # phase map, stay those of the frame) with the site 2 or 3 rows/cols in: its only
        # interior Z site. Rows/cols beyond the frame (never read by the site) are moved
        # back by whole periods, which keeps their colour.
        y0, x0 = y - 2 - (y - 2) % P, x - 2 - (x - 2) % Q
        ri = np.arange(y0, y0 + 6)
        ci = np.arange(x0, x0 + 6)
        while (ri >= rows).any():
            ri[ri >= rows] -= P
        while (ci >= cols).any():
            ci[ci >= cols] -= Q
        win = np.ascontiguousarray(data[np.ix_(ri, ci)])
        tot = []
        for fast in (0, 1):
            c = np.zeros(n * _kernels_count.NOPS, np.uint64)
            prec_code, exp_code = _kernel_codes(precision, kw)
            _kernels_count.reconstruct(win, np.empty_like(win), prec_code, P, Q,
                                       phase_map, plans, n, float(kw["sigma_floor"]),
                                       float(kw["sigma_rel"]), float(kw["edge_ratio"]),
                                       float((1 << kw["bit_depth"]) - 1), exp_code, 1,
                                       opcounts=c, mask1_fast=fast)
            tot.append(c.reshape(n, -1).sum(axis=0).astype(np.int64))
        out[i] = tot[1] - tot[0]
    return out


def _summarise(targets, counts):
    out = {}
    for g in GROUPS:
        sel = np.array([_group_of(t) == g for t in targets], bool)
        if not sel.any():
            continue
        c = counts[sel].astype(np.float64)
        out[g] = {
            "n_sites": int(sel.sum()),
            "mean": {k: float(c[:, i].mean()) for i, k in enumerate(CATEGORIES)},
            "min": {k: int(c[:, i].min()) for i, k in enumerate(CATEGORIES)},
            "max": {k: int(c[:, i].max()) for i, k in enumerate(CATEGORIES)},
        }
    return out


def count_operations(method, pattern="mask1", *, precision="float64", shape=(64, 64), seed=0,
                     frame=None, path="auto", **reconstruct_kwargs):
    """Count the arithmetic per missing pixel of one reconstruction method.

    Parameters
    ----------
    method : str
        A method of :func:`rgbz_fast.reconstruct` ("bilinear", "bi",
        "edi_central", "edi_line", "sg", "edi_rows", "learned": the shipped
        filters of the pattern; every site, borders included, costs the same;
        "z_guided": its shipped filters guided by a random NIR image, the
        per-site kernel only -- the cell terms, one per tile, are not counted).
    pattern : Pattern or str
        The pattern (default Mask1).
    precision : {"float64", "float32"}
        Arithmetic of the kernel; the counts differ only where a weight
        underflows in one precision and not in the other.
    shape : (rows, cols)
        Size of the random frame (uniform integers over the bit depth, seeded
        by ``seed``) when ``frame`` is not given; rounded up to whole pattern
        periods.
    seed : int
        Seed of the random frame.
    frame : RawFrame or ndarray, optional
        Count on this frame instead (e.g. a mosaicked natural image).
    path : {"auto", "generic"}
        ``"auto"``: the code :func:`rgbz_fast.reconstruct` runs (the Mask1
        fast path, the constant plans of csrc/recon_mask1.h, where it applies);
        ``"generic"``: the plans of ``_plans.py`` everywhere.
    **reconstruct_kwargs
        ``bit_depth``, ``sigma_floor``, ``sigma_rel``, ``edge_ratio``,
        ``sg_mode``, ``exp``, ``domain`` as for :func:`rgbz_fast.reconstruct`.

    Returns
    -------
    dict
        ``{group: {"n_sites", "mean", "min", "max"}}`` with ``group`` in
        ``"green"``, ``"red/blue"`` (the colours the pattern misses) and
        ``mean``/``min``/``max`` dicts over :data:`CATEGORIES`, per missing
        pixel. Only Z sites at least a kernel radius inside the frame are
        counted.

    Examples
    --------
    >>> c = count_operations("bilinear", "mask1", shape=(16, 16))
    >>> c["green"]["mean"]["add"], c["green"]["mean"]["div"]
    (6.0, 1.0)
    """
    bad = set(reconstruct_kwargs) - set(_KW)
    if bad:
        raise TypeError(f"count_operations: unexpected keyword argument(s) "
                        f"{', '.join(sorted(bad))}; expected some of {', '.join(sorted(_KW))}")
    kw = dict(_KW)
    kw.update(reconstruct_kwargs)
    data, pattern, bd = _frame_data(pattern, shape, seed, frame,
                                    reconstruct_kwargs.get("bit_depth"))
    kw["bit_depth"] = bd
    # the public function validates every argument (and runs the normal kernel once)
    guide = {"nir": _counting_guide(data.shape, seed)} if method == "z_guided" else {}
    reconstruct(data, method, pattern=pattern, bit_depth=kw["bit_depth"], workers=1,
                precision=precision, **guide, **{k: v for k, v in kw.items() if k != "bit_depth"})
    if path not in ("auto", "generic"):
        raise ValueError(f"path: expected 'auto' or 'generic', got {path!r}")
    if method == "learned":
        return _summarise(*_learned_site_counts(data, pattern, precision.lower(), bd))
    if method == "z_guided":
        return _summarise(*_z_guided_site_counts(data, pattern, precision.lower(), bd, seed))
    targets, counts = _site_counts(data, pattern, method, precision.lower(), kw,
                                   fast_path=path == "auto")
    return _summarise(targets, counts)


def count_tof_operations(n_sites=64, n_freqs=3, seed=0):
    """Operations of the four-tap ToF demodulation per measurement and frequency.

    Runs ``_kernels_count.tof_demodulate`` on random taps.
    Returns ``{category: count}``, or None when the counting module does not
    count the demodulation.
    """
    taps = np.random.default_rng(seed).integers(0, 2048, (n_freqs, 4, n_sites)).astype(np.uint16)
    phase, amp, off = (np.empty((n_freqs, n_sites)) for _ in range(3))
    counts = np.zeros(_kernels_count.NOPS, np.uint64)
    try:
        _kernels_count.tof_demodulate(taps, phase, amp, off, 1, opcounts=counts)
    except (TypeError, ValueError, RuntimeError):
        return None
    if not counts.any():
        return None
    return {k: float(counts[i]) / (n_sites * n_freqs) for i, k in enumerate(CATEGORIES)}


def _table1_name(pattern):
    """The name Table 1 knows ``pattern`` by: the preset whose tile it has on any Bayer phase
    (the tile 'ZR/BG' and mask1_rggb are Mask1), else its own."""
    for name in ("mask1", "mask2"):
        for phase in ("grbg", "rggb", "bggr", "gbrg"):     # the same work on every phase
            preset = get_pattern(f"{name}_{phase}")
            if np.array_equal(preset.tile, pattern.tile) and \
                    preset.bayer_phase == pattern.bayer_phase:
                return name
    return pattern.name


def _image_frame(image, pattern, size=128):
    """A mosaicked centre crop (size x size, period aligned) of an RGB image."""
    P, Q = pattern.period
    r = min(size, image.shape[0]) // P * P
    c = min(size, image.shape[1]) // Q * Q
    r0 = (image.shape[0] - r) // 2 // P * P
    c0 = (image.shape[1] - c) // 2 // Q * Q
    return mosaic(np.ascontiguousarray(image[r0:r0 + r, c0:c0 + c]), pattern)


def opcount_table(methods=DEFAULT_METHODS, patterns=("mask1", "mask2"), *,
                  precision="float64", shape=(64, 64), seed=0, image=None, image_name=None,
                  **reconstruct_kwargs):
    """Rows of the comparison with Table 1, one per (method, pattern, target colour).

    Each row: ``method``, ``pattern``, ``target``, ``n_sites``, ``mean``,
    ``max`` (random frame), ``paper`` (Table 1 or None), ``ratio`` (mean /
    paper per category, None where the paper has 0 or nothing), ``add_no_beta``
    (mean additions when the intensity factor beta of eq. 4 is left out, for
    the methods that use it), ``path`` (the code path ``reconstruct`` takes:
    the Mask1 fast path or the plan interpreter), ``generic_mean`` (the plan
    interpreter's counts) and, if ``image`` (uint8 RGB) is given,
    ``image_mean`` on a 128x128 crop of it.
    """
    kw = dict(_KW)
    kw.update(reconstruct_kwargs)
    rows = []
    for pat_name in patterns:
        pattern = get_pattern(pat_name)
        for method in methods:
            res = count_operations(method, pattern, precision=precision, shape=shape, seed=seed,
                                   **reconstruct_kwargs)
            data, _, bd = _frame_data(pattern, shape, seed, None, kw["bit_depth"])
            kwb = dict(kw, bit_depth=bd)
            if method in ("learned", "z_guided"):          # no beta, one code path
                nb = gen = res
                path = f"{method} kernel"
            else:
                # the cost of beta, measured on the plan interpreter (plans with beta off)
                t_nb, c_nb = _site_counts(data, pattern, method, precision, kwb,
                                          ablate_beta=True)
                _, c_gen = _site_counts(data, pattern, method, precision, kwb, fast_path=False)
                nb = _summarise(t_nb, c_nb)
                gen = _summarise(t_nb, c_gen)
                path = ("mask1 fast path" if _uses_mask1_fast(pattern, method, kwb)
                        else "plan interpreter")
            img = None
            if image is not None:
                img = count_operations(method, pattern, precision=precision,
                                       frame=_image_frame(image, pattern), **reconstruct_kwargs)
            for g, r in res.items():
                paper = TABLE1.get((method, _table1_name(pattern), g))
                ratio = None
                if paper is not None:
                    ratio = {k: (r["mean"][k] / paper[k] if paper[k] else None)
                             for k in TABLE1_CATEGORIES}
                beta_adds = gen[g]["mean"]["add"] - nb[g]["mean"]["add"]
                rows.append(dict(
                    method=method, pattern=pattern.name, target=g, n_sites=r["n_sites"],
                    path=path, mean=r["mean"], max=r["max"], paper=paper, ratio=ratio,
                    add_no_beta=r["mean"]["add"] - beta_adds if beta_adds else None,
                    generic_mean=gen[g]["mean"],
                    image_mean=None if img is None else img[g]["mean"],
                    image=image_name if image is not None else None))
    return rows


def _fmt(v):
    if v is None:
        return "-"
    if abs(v - round(v)) < 0.05:
        return str(int(round(v)))
    return f"{v:.1f}"


def _cell(row, k):
    mean, mx = row["mean"][k], row["max"][k]
    s = _fmt(mean) + (f" (≤{mx})" if mx > mean + 1e-9 else "")
    paper = row["paper"]
    if paper is None:
        return s
    s += f" / {paper[k]}"
    if row["ratio"] and row["ratio"][k] is not None:
        s += f" ×{row['ratio'][k]:.2f}"
    return s


def opcount_report(rows=None, fmt="markdown", **kwargs):
    """The table of :func:`opcount_table` as Markdown (``fmt="markdown"``) or plain text.

    Cells read "ours (≤max) / Table 1 ×ratio"; "ours" is the mean per missing
    pixel on the random frame, "max" the worst site when it differs.
    """
    if fmt not in ("markdown", "text"):
        raise ValueError(f"fmt: expected 'markdown' or 'text', got {fmt!r}")
    if rows is None:
        rows = opcount_table(**kwargs)
    head = ["method", "mask", "target", "path", "add/sub", "mul", "div", "exp", "abs", "cmp",
            "add w/o β"]
    has_img = any(r.get("image_mean") for r in rows)
    if has_img:
        head += ["add/mul/div/exp on image"]
    body = []
    for r in rows:
        line = [r["method"], r["pattern"], r["target"],
                {"mask1 fast path": "fast", "learned kernel": "learned",
                 "z_guided kernel": "z_guided"}.get(r.get("path"),
                                                                           "plans")]
        line += [_cell(r, k) for k in TABLE1_CATEGORIES]
        line += [_fmt(r["mean"]["abs"]), _fmt(r["mean"]["cmp"])]
        nb = r["add_no_beta"]
        if nb is None:
            line.append("-")
        else:
            line.append(_fmt(nb) + (f" / {r['paper']['add']} ×{nb / r['paper']['add']:.2f}"
                                    if r["paper"] else ""))
        if has_img:
            im = r.get("image_mean")
            line.append("-" if im is None else "/".join(_fmt(im[k]) for k in TABLE1_CATEGORIES))
        body.append(line)
    if fmt == "markdown":
        out = ["| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head) + "|"]
        out += ["| " + " | ".join(b) + " |" for b in body]
        return "\n".join(out)
    widths = [max(len(h), *(len(b[i]) for b in body)) for i, h in enumerate(head)]
    out = ["  ".join(h.ljust(w) for h, w in zip(head, widths)),
           "  ".join("-" * w for w in widths)]
    out += ["  ".join(c.ljust(w) for c, w in zip(b, widths)) for b in body]
    return "\n".join(out)


_LEGEND = ("Cells: ours per missing pixel (mean over the interior Z sites of a {shape} random "
           "frame, seed {seed}, {precision}; (≤max) when some site costs more) / Table 1 "
           "×ratio. Mask2 'red/blue' is Table 1's first number, 'green' its second. abs and "
           "cmp are counted separately (Table 1 has no such rows); 'add w/o β' leaves out the "
           "intensity factor of eq. 4. path: the code reconstruct() runs, the Mask1 fast path "
           "(csrc/recon_mask1.h) or the plan interpreter (_plans.py), one C core "
           "(csrc/recon_core.template.h); or the learned kernel (csrc/learned.c: the hash, "
           "then one dot product over the taps; the same at every site); or the z_guided "
           "kernel (csrc/z_guided.c: the learned kernel's work plus the guide's dot product; "
           "the cell terms, one per tile, are not counted).")


def opcount_legend(shape, seed, precision, image_name=None, tof=None, image_shape=None,
                   periods=()):
    """The paragraph under the table: how to read the cells, the image of the last column
    (``image_name``, of ``image_shape``: the crop is at most 128x128) and the ToF
    demodulation's counts (``tof``, from :func:`count_tof_operations`; None: not counted by
    this build). ``periods``: the patterns' periods, to which the frame is rounded up."""
    size = "x".join(map(str, shape))
    if any(shape[0] % p or shape[1] % q for p, q in periods):
        size += " (rounded up to whole periods of each pattern)"
    legend = _LEGEND.format(shape=size, seed=seed, precision=precision)
    if image_name is not None:
        crop = "128x128" if image_shape is None else \
            f"{min(128, image_shape[0])}x{min(128, image_shape[1])}"
        legend += (f" Last column: means on a centre crop of {image_name} ({crop}, whole "
                   "periods).")
    if tof is None:
        legend += " ToF demodulation: not counted by this build."
    else:
        legend += (" ToF demodulation, per measurement and frequency: "
                   + ", ".join(f"{v:g} {k}" for k, v in tof.items() if v) + ".")
    return legend
