"""The fit of the ``z_guided`` filters (:mod:`._z_guided` defines the model).

:func:`train_z_guided` sums the normal equations of every frame
(:func:`frame_stats`) and solves them (:func:`fit_stats`); the two halves are
public so that a k-fold run computes each frame's equations once.
"""

from __future__ import annotations

import numpy as np

from .._frame import RawFrame
from .._validate import check_flag, check_number
from ._learned import LearnedFilters, default_filters
from ._z_guided import N_GUIDE, ZGuidedFilters, _site_features, check_base, guide_grid, z_layout

__all__ = ["train_z_guided", "frame_stats", "fit_stats"]


def train_z_guided(frames, *, nir=None, base=None, ridge=1e-3, prior=50.0, colour_prior=4.0,
                   lam=0.01, noise_thresholds=(0.003,), guide=True, meta=None):
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
    ridge, prior : float
        As for :func:`rgbz_fast.reconstruction.train`: the ridge term relative
        to the mean diagonal of each normal matrix, and the weight, in sites,
        of the phase-wide fit in each bucket's.
    colour_prior : float
        The prior of the colour correction, times ``prior`` (> 0; a large
        value keeps the colour weights of every bucket at the phase-wide
        correction).
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
        the guide adds.
    meta : dict, optional
        Extra metadata kept with the filters.

    Returns
    -------
    ZGuidedFilters

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
    ridge = check_number(ridge, "ridge", lo=0)
    prior = check_number(prior, "prior", lo=0)
    colour_prior = check_number(colour_prior, "colour_prior", lo=0, lo_open=True)
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
    frames = list(frames)
    if not frames:
        raise ValueError("frames: no frames to train on")
    nir = [None] * len(frames) if nir is None else list(nir)
    if len(nir) != len(frames):
        raise ValueError(f"nir: expected one entry per frame ({len(frames)}), got {len(nir)}")
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
    stats = None
    for i, fr in enumerate(frames):
        s = frame_stats(fr, base, lam, noise_thresholds, nir=nir[i], name=f"nir[{i}]")
        stats = s if stats is None else [[a + b for a, b in zip(x, y)] for x, y in zip(stats, s)]
    info = {"n_images": len(frames), "lam": lam}
    info.update(meta or {})
    return fit_stats(stats, base, lam, noise_thresholds, ridge=ridge, prior=prior,
                     colour_prior=colour_prior, guide=guide, meta=info)


def frame_stats(frame, base, lam, noise_thresholds=(0.003,), *, nir=None, name="nir"):
    """The normal equations of one frame, per Z site of the tile: ``[A, v, counts]`` with ``A``
    (n_buckets, q, q) and ``v`` (n_buckets, q) over the q = taps + 11 features of each
    bucket's sites (n_levels x the hash's buckets), and the sites per bucket
    (:func:`train_z_guided` sums them)."""
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
        A, v = np.zeros((nb, q, q)), np.zeros((nb, q))
        for j in range(nb):
            a, e = bounds[j], bounds[j + 1]
            if e > a:
                A[j] = FG[a:e].T @ FG[a:e]
                v[j] = FG[a:e].T @ y[a:e]
        out.append([A, v, np.diff(bounds)])
    return out


def fit_stats(stats, base, lam, noise_thresholds=(0.003,), *, ridge=1e-3, prior=50.0,
              colour_prior=4.0, guide=True, meta=None):
    """:class:`ZGuidedFilters` from summed :func:`frame_stats` (see :func:`train_z_guided`)."""
    levels = len(noise_thresholds) + 1
    weights = np.tile(np.asarray(base.weights, np.float64), (1, levels, 1))
    gw = np.zeros((len(base.geometry), weights.shape[1], N_GUIDE))
    for k, ph in enumerate(base.geometry):
        A, v, counts = stats[k]
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
    info.update(meta or {})
    return ZGuidedFilters(base, weights, gw, noise_thresholds, lam, meta=info)


def _features(X, ph):
    """The windows ``X`` (sites, taps) minus the mean of each tap's colour in the window (the
    features of the learned fit)."""
    F = X.copy()
    for col in np.unique(ph["colours"]):
        m = ph["colours"] == col
        F[:, m] -= X[:, m].mean(1, keepdims=True)
    return F


def _fit_buckets(A, v, counts, ridge, prior, mult):
    """Ridge fits from the normal equations: one on every site, then one per bucket shrunk
    towards it by ``prior`` sites (times ``mult`` per feature)."""
    p = A.shape[1]
    Ag, vg, n = A.sum(axis=0), v.sum(axis=0), max(int(counts.sum()), 1)
    scale = max(np.trace(Ag) / p, np.finfo(float).tiny)
    eye = np.eye(p)
    wg = np.linalg.solve(Ag + ridge * scale * eye, vg)
    W = np.empty((len(A), p))
    for j in range(len(A)):
        lam = (prior * scale / n + ridge * np.trace(A[j]) / p) * mult
        lam = np.where(lam > 0, lam, ridge * scale + np.finfo(float).tiny)
        W[j] = np.linalg.solve(A[j] + np.diag(lam), v[j] + lam * wg)
    return W
