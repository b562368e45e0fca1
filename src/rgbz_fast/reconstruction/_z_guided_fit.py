"""The fit of the ``z_guided`` filters (:mod:`._z_guided` defines the model).

:func:`train_z_guided` sums the normal equations of every frame
(:func:`frame_stats`), chooses the ridge, prior and colour prior by k-fold
cross-validation over the training scenes from those equations
(:func:`select_stats`, :func:`fit_folds`) and solves them (:func:`fit_stats`); the
parts are public so that a k-fold run computes each frame's equations once.
"""

from __future__ import annotations

import itertools
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from .._frame import RawFrame
from .._threads import check_workers
from .._validate import check_flag, check_int, check_number
from ._learned import LearnedFilters, default_filters
from ._learned_train import REGULARISATION_MAX, merge_meta, solve_normal
from ._z_guided import N_GUIDE, ZGuidedFilters, _site_features, check_base, guide_grid, z_layout

__all__ = ["train_z_guided", "frame_stats", "fit_stats", "fit_folds", "select_stats",
           "sum_stats", "CV_GRID", "FIXED_SETTINGS", "SELECTIONS"]

#: the values ``select="cv"`` tries by default: every combination of the three axes (100)
CV_GRID = {"ridge": (1e-4, 1e-3, 1e-2, 1e-1),
           "prior": (12.5, 50.0, 200.0, 800.0, 3200.0),
           "colour_prior": (1.0, 4.0, 16.0, 64.0, 256.0)}
#: the settings ``select=None`` takes for a parameter not given (those of the first fit)
FIXED_SETTINGS = {"ridge": 1e-3, "prior": 50.0, "colour_prior": 4.0}
#: how the parameters not given are set: by cross-validation, or to FIXED_SETTINGS
SELECTIONS = ("cv", None)
#: the lower bound of each parameter, and whether it is open
_BOUNDS = {"ridge": (0, False), "prior": (0, False), "colour_prior": (0, True)}
#: the meta keys the fit records itself, by the function that records them (a caller's
#: ``meta`` may not set them: a file had recorded select 'cv' for a fit with select=None)
_STATS_RECORDED = ("n_sites", "ridge", "prior", "colour_prior", "guide", "base", "base_digest",
                   "library_version")
_FOLDS_RECORDED = ("select", "cv_folds", "cv_grid", "cv_rmse") + _STATS_RECORDED
_TRAIN_RECORDED = ("n_images", "lam", "cv_groups") + _FOLDS_RECORDED


def train_z_guided(frames, *, nir=None, base=None, ridge=None, prior=None, colour_prior=None,
                   select="cv", cv_folds=4, cv_grid=None, groups=None, lam=0.01,
                   noise_thresholds=(0.003,), guide=True, meta=None, workers=None):
    """Fit :class:`ZGuidedFilters` to frames whose true colour at the Z sites is known.

    Parameters
    ----------
    frames : iterable of RawFrame
        Frames of one pattern and bit depth, each with its ``reference`` (the
        complete Bayer CFA) and its ToF taps (``frame.tof``, as
        :func:`rgbz_fast.simulation.simulate` makes them) unless ``nir`` gives
        its guide.
    nir : sequence, optional
        One entry per frame: an array of the frame's shape (read at its Z
        sites only) or None (the frame's taps).
    base : LearnedFilters, optional
        The learned filters the fit starts from (their hash and taps); default
        the ones shipped for the pattern and bit depth.
    ridge, prior : float, optional
        As for :func:`rgbz_fast.reconstruction.train`: the ridge term relative
        to the mean diagonal of each normal matrix (>= 0), and the weight, in
        sites, of the phase-wide fit in each bucket's (>= 0). None: set by
        ``select``.
    colour_prior : float, optional
        The prior of the colour correction, times ``prior`` (> 0; a large
        value keeps the colour weights of every bucket at the phase-wide
        correction). None: set by ``select``.
    select : {"cv", None}
        How the parameters among ``ridge``, ``prior`` and ``colour_prior``
        left at None are set. ``"cv"``: the combination of ``cv_grid`` (a
        given parameter held at its value) of least squared error over the
        held-out folds of a ``cv_folds``-fold cross-validation over the
        frames' ``groups``, from the normal equations of the fit (each fold's
        equations solved without it, its error ``y.y - 2 w.v + w' A w``
        summed; no frame is made twice); ties go to the first in the grid's
        order (``ridge`` slowest, ``colour_prior`` fastest). None: the
        settings of the first shipped fit, :data:`FIXED_SETTINGS` (ridge 1e-3,
        prior 50, colour prior 4).
    cv_folds : int
        Folds of the cross-validation, >= 2: group i (in the order the
        groups first appear) is in fold i mod ``cv_folds``; with fewer groups
        than folds, one fold per group.
    cv_grid : dict, optional
        The values to try per parameter, ``{"ridge": [...], "prior": [...],
        "colour_prior": [...]}`` (any of the three; the others from
        :data:`CV_GRID`: ridge 1e-4, 1e-3, 1e-2, 0.1; prior 12.5, 50, 200,
        800, 3200; colour prior 1, 4, 16, 64, 256).
    groups : sequence, optional
        One label per frame: frames of one scene (the noise-free and noisy
        frames of a pair) must share a label, so that a scene is never on
        both sides of a fold. Default: every frame its own group.
    lam : float
        Regularisation of the local linear model (module docstring), > 0.
    noise_thresholds : sequence of float
        Levels of the guide's relative noise variance ``nu`` (increasing,
        > 0; empty: one level). The default 0.003 (a noise of 5.5 % of the
        amplitude) was chosen by 5-fold fits on the RGB-NIR pairs; it
        separates a noise-free guide from the sensor model's at 2 m.
    guide : bool
        False: fit the colour correction alone and leave the guide weights at
        0 -- the same model without what the Z pixels see, to measure what
        the guide adds (the cross-validation scores that model).
    meta : dict, optional
        Extra metadata kept with the filters.
    workers : int, optional
        Threads: the frames' normal equations are made side by side, one
        frame per thread (None or -1: every core). The filters do not depend
        on it.

    Returns
    -------
    ZGuidedFilters
        With ``meta``: the settings used (``ridge``, ``prior``,
        ``colour_prior``), ``select`` (``"cv"`` or ``"none"``) and, with
        ``"cv"``, ``cv_folds`` and ``cv_groups`` (used), ``cv_grid`` (the
        values tried) and ``cv_rmse`` (the held-out root mean squared error in
        DN of every combination, in the grid's order).

    Notes
    -----
    Per Z site of the tile, the features are the learned method's (each tap
    minus the mean of its colour in the window) and the 11 guide features;
    the target is the true value minus the ``base`` filters' estimate. One
    ridge fit on every site, then one per bucket (noise level times
    ``base``'s hash) shrunk towards it (the colour features by
    ``colour_prior`` times more). The
    colour correction is folded onto the taps and added to ``base``'s
    weights, so the colour part is one dot product, as for ``"learned"``.
    """
    guide = check_flag(guide, "guide")
    given = {n: (None if v is None else check_number(v, n, lo=_BOUNDS[n][0],
                                                    lo_open=_BOUNDS[n][1],
                                                    hi=REGULARISATION_MAX))
             for n, v in (("ridge", ridge), ("prior", prior), ("colour_prior", colour_prior))}
    if select not in SELECTIONS:
        raise ValueError(f"select: expected 'cv' or None, got {select!r}")
    cv_folds = check_int(cv_folds, "cv_folds", lo=2)
    if select is None and cv_grid is not None:
        raise ValueError("cv_grid: applies to select='cv' only, got select=None")
    axes = check_grid(cv_grid, "cv_grid") if select == "cv" else None
    lam = check_number(lam, "lam", lo=0, lo_open=True)
    try:
        noise_thresholds = tuple(float(t) for t in noise_thresholds)
    except (TypeError, ValueError):
        raise TypeError(f"noise_thresholds: expected a sequence of numbers, got "
                        f"{noise_thresholds!r}") from None
    if any(not t > 0 for t in noise_thresholds) or any(
            b <= a for a, b in zip(noise_thresholds, noise_thresholds[1:])):
        raise ValueError(f"noise_thresholds: expected increasing numbers > 0, got "
                         f"{noise_thresholds}")
    merge_meta(dict.fromkeys(_TRAIN_RECORDED), meta)     # refused before the frames are read
    frames = list(frames)
    if not frames:
        raise ValueError("frames: no frames to train on")
    nir = [None] * len(frames) if nir is None else list(nir)
    if len(nir) != len(frames):
        raise ValueError(f"nir: expected one entry per frame ({len(frames)}), got {len(nir)}")
    groups = list(range(len(frames))) if groups is None else list(groups)
    if len(groups) != len(frames):
        raise ValueError(f"groups: expected one label per frame ({len(frames)}), got "
                         f"{len(groups)}")
    try:
        order = {g: None for g in groups}          # the groups in the order they appear
    except TypeError:
        raise TypeError("groups: expected hashable labels (numbers, strings)") from None
    order = {g: i for i, g in enumerate(order)}
    pattern = bit_depth = None
    for i, fr in enumerate(frames):
        if not isinstance(fr, RawFrame):
            raise TypeError(f"frames: expected RawFrame entries, got {type(fr).__name__} at {i}")
        if fr.reference is None:
            raise ValueError(f"frames: frame {i} has no reference CFA to learn from")
        if pattern is None:
            pattern, bit_depth = fr.pattern, fr.bit_depth
        elif fr.pattern != pattern or fr.bit_depth != bit_depth:
            raise ValueError(f"frames: frame {i} is {fr.pattern.name!r} at {fr.bit_depth} bits, "
                             f"frame 0 {pattern.name!r} at {bit_depth} bits")
    z_layout(pattern, "frames")
    if base is None:
        base = default_filters(pattern)
        if base is not None and base.bit_depth != bit_depth:
            base = None
        if base is None:
            raise ValueError(f"base: no learned filters ship for pattern {pattern.name!r} at "
                             f"{bit_depth} bits; pass base=")
    elif not isinstance(base, LearnedFilters):
        raise TypeError(f"base: expected LearnedFilters, got {type(base).__name__}")
    check_base(base, pattern, bit_depth, "base")
    folds = [None] * min(cv_folds, len(order))
    # the frames' equations on threads, a batch of one frame per thread at a time (each holds
    # its buckets' normal equations), summed into the folds in the frames' order: the same
    # sums as one frame at a time
    n = min(check_workers(workers), len(frames))

    def stats(i):
        return frame_stats(frames[i], base, lam, noise_thresholds, nir=nir[i], name=f"nir[{i}]")

    with ThreadPoolExecutor(n) as ex:
        for b in range(0, len(frames), n):
            for i, s in zip(range(b, b + n), ex.map(stats, range(b, min(b + n, len(frames))))):
                j = order[groups[i]] % len(folds)
                folds[j] = sum_stats([folds[j], s])
    if select == "cv" and len(order) < 2 and any(
            v is None and len(axes[n]) > 1 for n, v in given.items()):
        raise ValueError("select: cross-validation needs frames of at least 2 groups (scenes), "
                         "got 1; pass select=None, or all of ridge=, prior= and "
                         "colour_prior=")
    info = {"n_images": len(frames), "lam": lam}
    if select == "cv":
        info["cv_groups"] = len(order)
    info = merge_meta(info, meta)
    return fit_folds(folds, base, lam, noise_thresholds, select=select, cv_grid=axes,
                     guide=guide, meta=info, workers=workers, **given)


def fit_folds(folds, base, lam, noise_thresholds=(0.003,), *, ridge=None, prior=None,
              colour_prior=None, select="cv", cv_grid=None, guide=True, meta=None,
              workers=None):
    """:class:`ZGuidedFilters` fitted on the sum of ``folds`` (summed :func:`frame_stats` of
    each fold of a cross-validation), the parameters left at None set by ``select`` (as in
    :func:`train_z_guided`, which runs this once its frames' equations are summed per fold:
    group i in fold i mod k). Records the choice in ``meta``. ``workers``: as for
    :func:`select_stats`."""
    if select not in SELECTIONS:
        raise ValueError(f"select: expected 'cv' or None, got {select!r}")
    given = {"ridge": ridge, "prior": prior, "colour_prior": colour_prior}
    merge_meta(dict.fromkeys(_FOLDS_RECORDED), meta)
    info = {}
    if select == "cv":
        axes = check_grid(cv_grid, "cv_grid")
        axes = {n: axes[n] if v is None else (v,) for n, v in given.items()}
    # a parameter left to the grid: "cv" even when the grid holds one point of it (scored
    # when there are folds to score it on; "given" had been recorded, and FIXED_SETTINGS fitted)
    from_grid = select == "cv" and any(v is None for v in given.values())
    n_folds = sum(f is not None for f in folds)
    if select == "cv" and (any(len(a) > 1 for a in axes.values())
                           or (from_grid and n_folds >= 2)):
        best, _, rmse = select_stats(folds, base, axes, guide=guide, workers=workers)
        info.update(select="cv", cv_folds=n_folds,
                    cv_grid="; ".join(f"{n} {list(axes[n])}" for n in axes),
                    cv_rmse=str([float(f"{e:.6g}") for e in rmse]))
    elif from_grid:                         # a one-point grid and one fold: nothing to score
        best = {n: axes[n][0] for n in axes}
        info.update(select="cv", cv_grid="; ".join(f"{n} {list(axes[n])}" for n in axes))
    else:                                   # select None, or every parameter given
        best = {n: FIXED_SETTINGS[n] if v is None else v for n, v in given.items()}
        info.update(select="none" if select is None else "given")
    info.update(meta or {})
    return fit_stats(sum_stats(folds), base, lam, noise_thresholds, guide=guide, meta=info,
                     **best)


def check_grid(grid, name="cv_grid"):
    """The axes of a cross-validation grid: :data:`CV_GRID` with the axes ``grid`` gives."""
    if grid is None:
        return dict(CV_GRID)
    if not isinstance(grid, dict):
        raise TypeError(f"{name}: expected a dict of value lists per parameter, got "
                        f"{type(grid).__name__}")
    unknown = [k for k in grid if k not in CV_GRID]
    if unknown:
        raise ValueError(f"{name}: unknown parameter {unknown[0]!r}; expected some of "
                         f"{', '.join(CV_GRID)}")
    out = dict(CV_GRID)
    for n, values in grid.items():
        if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
            raise TypeError(f"{name}[{n!r}]: expected a sequence of numbers, got {values!r}")
        lo, lo_open = _BOUNDS[n]
        vals = tuple(check_number(v, f"{name}[{n!r}]", lo=lo, lo_open=lo_open,
                                  hi=REGULARISATION_MAX) for v in values)
        if not vals:
            raise ValueError(f"{name}[{n!r}]: expected at least one value, got none")
        if len(set(vals)) != len(vals):
            raise ValueError(f"{name}[{n!r}]: expected distinct values, got {list(vals)}")
        out[n] = vals
    return out


def sum_stats(stats):
    """The sum of :func:`frame_stats` results (None entries skipped; None if all are)."""
    total = None
    for s in stats:
        if s is None:
            continue
        total = s if total is None else [[a + b for a, b in zip(x, y)] for x, y in zip(total, s)]
    return total


def select_stats(folds, base, axes=None, *, guide=True, workers=None):
    """The (ridge, prior, colour_prior) of least held-out squared error, by cross-validation.

    ``folds``: summed :func:`frame_stats` of each fold (at least 2); each fold is held out in
    turn, the model fitted on the others' sum (:func:`fit_stats`'s solution) and its squared
    error on the fold's sites ``y.y - 2 w.v + w' A w`` added up. ``axes``: the values to try
    per parameter (default :data:`CV_GRID`; :func:`check_grid`). Returns the best setting (a
    dict; ties to the first in the grid's order), the grid's points and the held-out root
    mean squared error of each (DN). The grid's points are fitted on ``workers`` threads
    (None or -1: every core; the errors are added up in the same order on any count).
    """
    axes = check_grid(axes, "axes")
    folds = [f for f in folds if f is not None]
    if len(folds) < 2:
        raise ValueError(f"folds: cross-validation needs at least 2 folds, got {len(folds)}")
    names = list(CV_GRID)
    grid = list(itertools.product(*(axes[n] for n in names)))
    sse = np.zeros(len(grid))
    n_sites = 0
    with ThreadPoolExecutor(min(check_workers(workers), len(grid))) as ex:
        for j, held in enumerate(folds):
            train = sum_stats([f for i, f in enumerate(folds) if i != j])
            n_sites += int(sum(int(s[2].sum()) for s in held))
            for k, ph in enumerate(base.geometry):
                A, v, counts, _ = train[k]
                Ah, vh, held_counts, yh = held[k]
                nt = len(ph["taps"])
                keep = slice(None) if guide else slice(0, nt)
                A, v, Ah, vh = A[:, keep, keep], v[:, keep], Ah[:, keep, keep], vh[:, keep]
                used = held_counts > 0                  # the other buckets add no error
                Ah, vh = Ah[used], vh[used]

                def error(setting, A=A, v=v, Ah=Ah, vh=vh, yh=yh, counts=counts, nt=nt,
                          used=used):
                    ridge, prior, cp = setting
                    mult = np.ones(A.shape[1])
                    mult[:nt] = cp
                    W = _fit_buckets(A, v, counts, ridge, prior, mult, only=used)
                    return yh.sum() - 2 * np.einsum("bi,bi->", W, vh) + \
                        np.einsum("bi,bi->", (Ah @ W[:, :, None])[:, :, 0], W)

                for g, e in enumerate(ex.map(error, grid)):
                    sse[g] += e
    best = int(np.argmin(sse))
    rmse = np.sqrt(np.maximum(sse, 0) / max(n_sites, 1))
    return dict(zip(names, grid[best])), grid, rmse


def frame_stats(frame, base, lam, noise_thresholds=(0.003,), *, nir=None, name="nir"):
    """The normal equations of one frame, per Z site of the tile: ``[A, v, counts, yy]`` with ``A``
    (n_buckets, q, q) and ``v`` (n_buckets, q) over the q = taps + 11 features of each
    bucket's sites (n_levels x the hash's buckets), the sites per bucket and the sum of the
    squared targets per bucket (:func:`train_z_guided` sums them: :func:`sum_stats`)."""
    pattern, geometry = frame.pattern, base.geometry
    nb = (len(noise_thresholds) + 1) * base.n_buckets
    P, Q = pattern.period
    grids = guide_grid(frame.shape, pattern, tof=frame.tof, nir=nir, name=name)
    ref = np.asarray(frame.reference, np.float64)
    out = []
    for k, (X, bk, G, (r, c, ny, nx)) in enumerate(
            _site_features(frame.data, pattern, grids, base, lam, noise_thresholds)):
        F = _features(X, geometry[k])
        y = ref[r::P, c::Q][:ny, :nx].reshape(-1) - np.einsum(
            "ij,ij->i", X, base.weights[k][:, :X.shape[1]][bk % base.n_buckets])
        order = np.argsort(bk, kind="stable")
        FG, y = np.hstack([F, G])[order], y[order]
        bounds = np.searchsorted(bk[order], np.arange(nb + 1))
        q = FG.shape[1]
        A, v, yy = np.zeros((nb, q, q)), np.zeros((nb, q)), np.zeros(nb)
        for j in range(nb):
            a, e = bounds[j], bounds[j + 1]
            if e > a:
                A[j] = FG[a:e].T @ FG[a:e]
                v[j] = FG[a:e].T @ y[a:e]
                yy[j] = y[a:e] @ y[a:e]
        out.append([A, v, np.diff(bounds), yy])
    return out


def fit_stats(stats, base, lam, noise_thresholds=(0.003,), *, ridge=1e-3, prior=50.0,
              colour_prior=4.0, guide=True, meta=None):
    """:class:`ZGuidedFilters` from summed :func:`frame_stats` (see :func:`train_z_guided`)."""
    levels = len(noise_thresholds) + 1
    weights = np.tile(np.asarray(base.weights, np.float64), (1, levels, 1))
    gw = np.zeros((len(base.geometry), weights.shape[1], N_GUIDE))
    for k, ph in enumerate(base.geometry):
        A, v, counts = stats[k][:3]
        nt = len(ph["taps"])
        keep = slice(None) if guide else slice(0, nt)
        mult = np.ones(A.shape[1])[keep]
        mult[:nt] = colour_prior
        W = _fit_buckets(A[:, keep, keep], v[:, keep], counts, ridge, prior, mult)
        delta = W[:, :nt]
        for col in np.unique(ph["colours"]):      # onto the taps: each colour's mean removed
            m = ph["colours"] == col
            delta[:, m] -= delta[:, m].sum(axis=1, keepdims=True) / m.sum()
        weights[k, :, :nt] += delta
        if guide:
            gw[k] = W[:, nt:]
    from .._build_config import VERSION
    info = {"n_sites": int(sum(s[2].sum() for s in stats)), "ridge": ridge, "prior": prior,
            "colour_prior": colour_prior, "guide": int(bool(guide)),
            "base": base.meta.get("training_set", "?"), "base_digest": base.digest,
            "library_version": VERSION}
    info = merge_meta(info, meta)
    return ZGuidedFilters(base, weights, gw, noise_thresholds, lam, meta=info)


def _features(X, ph):
    """The windows ``X`` (sites, taps) minus the mean of each tap's colour in the window (the
    features of the learned fit)."""
    F = X.copy()
    for col in np.unique(ph["colours"]):
        m = ph["colours"] == col
        F[:, m] -= X[:, m].mean(1, keepdims=True)
    return F


def _fit_buckets(A, v, counts, ridge, prior, mult, only=None):
    """Ridge fits from the normal equations: one on every site, then one per bucket shrunk
    towards it by ``prior`` sites (times ``mult`` per feature); all buckets at once, or
    those of the bool mask ``only``."""
    p = A.shape[1]
    Ag, vg, n = A.sum(axis=0), v.sum(axis=0), max(int(counts.sum()), 1)
    scale = max(np.trace(Ag) / p, np.finfo(float).tiny)
    wg = solve_normal(Ag + ridge * scale * np.eye(p), vg)
    if only is not None:
        A, v = A[only], v[only]
    lam = (prior * scale / n + ridge * np.trace(A, axis1=1, axis2=2)[:, None] / p) * mult
    lam = np.where(lam > 0, lam, ridge * scale + np.finfo(float).tiny)
    return solve_normal(A + lam[:, :, None] * np.eye(p), (v + lam * wg)[..., None])[..., 0]
