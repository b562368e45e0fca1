"""Fitting the learned filters: two passes over the training frames, normal equations per bucket."""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np

from .._frame import RawFrame
from .._validate import check_flag, check_int, check_number
from ._learned_hash import N_ANGLES, gather_windows, hash_buckets, hash_features, learned_geometry

__all__ = ["train"]

#: sites per frame and phase whose hash terms set the thresholds (a random sample)
THRESHOLD_SITES = 20000
#: ratios emax / emin above this count as this (a channel with no texture at all)
_SPREAD_CAP = 1e6
#: the largest ridge and prior weight (and z_guided's colour prior): beyond it a fit is its
#: prior alone, and 1e308 overflowed the normal equations into "filters: weights holds NaN"
REGULARISATION_MAX = 1e6


def _check_z_option_names(z_options):
    """A name among ``z_options`` that neither fit takes, refused with both lists of options
    (every one had been called an option of z_guided, and with z_guided=True it was Python's
    bare "unexpected keyword"); both lists read from the signatures."""
    import inspect

    from ._z_guided_fit import train_z_guided

    own = [k for k, p in inspect.signature(train).parameters.items()
           if p.kind is p.KEYWORD_ONLY and k != "z_guided"]
    z_names = [k for k in inspect.signature(train_z_guided).parameters
               if k not in ("frames", *own)]
    unknown = [k for k in z_options if k not in z_names]
    if unknown:
        raise TypeError(f"{unknown[0]}: not an option of train() (its options: "
                        f"{', '.join(own)}; with z_guided=True also {', '.join(z_names)})")


def train(frames, *, radius=3, hash_radius=3, n_strength=3, n_coherence=3, n_spread=3,
          ridge=None, prior=None, meta=None, z_guided=False, **z_options):
    """Fit :class:`LearnedFilters` to frames whose true colour at the Z sites is known.

    Parameters
    ----------
    frames : iterable of RawFrame
        Frames of one pattern and bit depth, each with its ``reference`` (the
        complete Bayer CFA: :func:`rgbz_fast.simulation.simulate` sets it;
        :func:`rgbz_fast.evaluation.train_filters` makes them from folders of
        images with the evaluation's protocol). Read twice: a list, or any
        object whose ``iter()`` starts again (a one-shot iterator is kept in
        memory).
    radius : int
        Window radius of the taps, 2..5 (3: 7x7, 40 taps on Mask1 and Mask2).
    hash_radius : int
        Radius of the pixel pairs of the hash, 2..radius.
    n_strength, n_coherence, n_spread : int
        Levels of the strength, the coherence and the channel spread of the
        hash, 1..8 (thresholds at the quantiles of the training sites).
        Buckets: 8 x n_strength x n_coherence x n_spread.
    ridge : float, optional
        Ridge term of every least-squares fit, relative to the mean diagonal
        of its normal matrix (0 to 1e6; None: 1e-3).
    prior : float, optional
        Weight of the phase-wide filter in each bucket's fit, in training
        sites (0 to 1e6; None: 50): a bucket with few sites stays close to the
        filter fitted on all of them (rare buckets merge into the common
        filter).
    meta : dict, optional
        Extra metadata kept with the filters (the training set's name...).
    z_guided : bool
        True: fit the filters of ``method="z_guided"`` instead
        (:func:`~rgbz_fast.reconstruction.train_z_guided`, with ``ridge``,
        ``prior``, ``meta`` and its own options ``**z_options``; None leaves
        ``ridge`` and ``prior`` to its ``select``; the taps and
        hash are those of its ``base`` learned filters, so ``radius`` ...
        ``n_spread`` keep their defaults).

    Returns
    -------
    LearnedFilters (ZGuidedFilters with ``z_guided``)

    Notes
    -----
    For each Z site of the tile the fit predicts the residual over the mean
    of the target-colour pixels of the 5x5 window (the bilinear baseline)
    from the taps minus the mean of their own colour in the window. Any
    filter of that form reproduces a flat colour exactly, and the ridge term
    pulls it towards the baseline. The first pass sets the hash thresholds
    from a sample of the sites (:data:`THRESHOLD_SITES` per frame and phase);
    the second sums each bucket's normal equations, so the memory does not
    grow with the training set. The fitted weights are folded into one
    weight per tap, so a reconstruction is one dot product per site.

    Examples
    --------
    >>> import dataclasses
    >>> import numpy as np
    >>> import rgbz_fast as rz
    >>> from rgbz_fast.reconstruction import train
    >>> rng = np.random.default_rng(0)
    >>> img = np.cumsum(rng.random((48, 48, 3)), axis=1) / 48
    >>> frame = rz.mosaic(img, "mask1")
    >>> frames = [dataclasses.replace(frame, reference=rz.mosaic(img, "bayer").data)]
    >>> f = train(frames, n_strength=1, n_coherence=1, n_spread=1)
    >>> f.n_buckets, f.meta["n_images"]
    (8, 1)
    """
    if z_options:
        _check_z_option_names(z_options)
    if check_flag(z_guided, "z_guided"):
        from ._z_guided_fit import train_z_guided
        given = [k for k, v in (("radius", radius), ("hash_radius", hash_radius),
                                ("n_strength", n_strength), ("n_coherence", n_coherence),
                                ("n_spread", n_spread)) if v != 3]
        if given:
            raise ValueError(f"{given[0]}: z_guided filters take the taps and hash of their "
                             "base learned filters; pass base= instead")
        return train_z_guided(frames, ridge=ridge, prior=prior, meta=meta, **z_options)
    if z_options:
        raise TypeError(f"{next(iter(z_options))}: an option of train(z_guided=True) only "
                        "(without it train() fits learned filters)")
    from ._learned import LearnedFilters
    radius = check_int(radius, "radius", lo=2, hi=5)
    hash_radius = check_int(hash_radius, "hash_radius", lo=2, hi=radius)
    levels = [check_int(v, n, lo=1, hi=8) for v, n in ((n_strength, "n_strength"),
                                                      (n_coherence, "n_coherence"),
                                                      (n_spread, "n_spread"))]
    ridge = 1e-3 if ridge is None else check_number(ridge, "ridge", lo=0, hi=REGULARISATION_MAX)
    prior = 50.0 if prior is None else check_number(prior, "prior", lo=0, hi=REGULARISATION_MAX)
    merge_meta(dict.fromkeys(RECORDED), meta)      # refused before the passes, not after
    if isinstance(frames, Iterator):            # one-shot: kept for the second pass
        frames = list(frames)
    pattern, bit_depth, samples, n_frames = _first_pass(frames, radius, hash_radius)
    geometry = learned_geometry(pattern, radius, hash_radius)
    thresholds = [_thresholds(s, *levels) for s in samples]
    del samples
    nb = N_ANGLES * int(np.prod(levels))
    grams = [np.zeros((nb, len(ph["taps"]) + 2, len(ph["taps"]) + 2)) for ph in geometry]
    P, Q = pattern.period
    for fr in frames:
        ref = np.asarray(fr.reference, np.float64)
        for k, (X, (r, c, ny, nx)) in enumerate(gather_windows(fr.data, pattern, radius,
                                                                geometry)):
            y = ref[r::P, c::Q][:ny, :nx].reshape(1, -1)
            bk = hash_buckets(hash_features(X, geometry[k]), *thresholds[k])
            _accumulate(grams[k], np.concatenate([X, y, np.ones_like(y)]), bk)
    n_taps = max(len(g["taps"]) for g in geometry)
    weights = np.zeros((len(geometry), nb, n_taps))
    for k, ph in enumerate(geometry):
        weights[k, :, :len(ph["taps"])] = _fold(_solve(grams[k], ph, ridge, prior), ph)
    counts = np.array([g[:, -1, -1] for g in grams])
    info = {"n_images": n_frames, "n_sites": int(round(counts.sum())),
            "empty_buckets": int((counts == 0).sum()), "ridge": ridge, "prior": prior}
    from .._build_config import VERSION
    info["library_version"] = VERSION
    info = merge_meta(info, meta)
    return LearnedFilters(pattern, bit_depth, weights,
                          *(np.array([t[i] for t in thresholds]).reshape(len(geometry), -1)
                            for i in range(3)),
                          radius=radius, hash_radius=hash_radius, meta=info)


#: the meta keys :func:`train` records itself (a caller's ``meta`` may not set them)
RECORDED = ("n_images", "n_sites", "empty_buckets", "ridge", "prior", "library_version")


def merge_meta(info, meta, name="meta"):
    """``info`` (what a fit records) with the caller's ``meta`` added: a ValueError naming
    ``name`` and the key when ``meta`` sets one of ``info``'s keys (a file had recorded
    ridge 99 for a fit at 1e-3), and the keys checked as the filters keep them."""
    from ._learned import check_meta

    if meta is None:
        return dict(info)
    check_meta(meta, name)                  # a value a file cannot hold: refused before a fit
    for k in meta:
        if str(k) in info:
            raise ValueError(f"{name}: {str(k)!r} is recorded by the fit itself (what it "
                             "used or made); give your own key another name")
    return {**info, **meta}


def solve_normal(A, b):
    """``np.linalg.solve(A, b)`` (a stack of systems too) -- the same bits for every
    non-singular system -- and, for a singular one (too few distinct sites, no
    regularisation: ridge 0 with prior 0, a flat image, a frame of one period), the
    least-squares solution of least norm (``np.linalg.lstsq``) in place of NumPy's
    LinAlgError('Singular matrix')."""
    try:
        return np.linalg.solve(A, b)
    except np.linalg.LinAlgError:
        pass
    if A.ndim == 2:
        return np.linalg.lstsq(A, b, rcond=None)[0]
    out = np.empty(b.shape)
    for i in range(len(A)):
        out[i] = solve_normal(A[i], b[i])
    return out


def _first_pass(frames, radius, hash_radius):
    """Check the frames; the hash terms of a sample of each phase's sites."""
    pattern = bit_depth = geometry = None
    samples, n = None, 0
    for i, fr in enumerate(frames):
        if not isinstance(fr, RawFrame):
            raise TypeError(f"frames: expected RawFrame entries, got {type(fr).__name__} at {i}")
        if fr.reference is None:
            raise ValueError(f"frames: frame {i} has no reference CFA to learn from")
        if pattern is None:
            pattern, bit_depth = fr.pattern, fr.bit_depth
            if not pattern.has_z:
                raise ValueError(f"frames: pattern {pattern.name!r} has no Z site to "
                                 "reconstruct")
            if pattern.bayer_phase is None:
                raise ValueError(f"frames: pattern {pattern.name!r} fits no Bayer phase")
            geometry = learned_geometry(pattern, radius, hash_radius)
            samples = [[] for _ in geometry]
        elif fr.pattern != pattern or fr.bit_depth != bit_depth:
            raise ValueError(f"frames: frame {i} is {fr.pattern.name!r} at {fr.bit_depth} bits, "
                             f"frame 0 {pattern.name!r} at {bit_depth} bits")
        rng = np.random.default_rng(i)
        for k, (X, _) in enumerate(gather_windows(fr.data, pattern, radius, geometry)):
            if X.shape[1] > THRESHOLD_SITES:
                X = X[:, np.sort(rng.choice(X.shape[1], THRESHOLD_SITES, replace=False))]
            samples[k].append(np.array(hash_features(X, geometry[k])))
        n += 1
    if pattern is None:
        raise ValueError("frames: no frames to train on")
    return pattern, bit_depth, [np.concatenate(s, axis=1) for s in samples], n


def _thresholds(features, n_strength, n_coherence, n_spread):
    """The quantile thresholds of the sampled hash terms (a, b, t, emax, emin)."""
    a, b, t, emax, emin = features
    coh = np.sqrt(a * a + b * b) / np.maximum(t, np.finfo(float).tiny)
    st = np.quantile(t, np.arange(1, n_strength) / n_strength)
    ct = np.quantile(np.minimum(coh, 1.0), np.arange(1, n_coherence) / n_coherence)
    textured = emax > 0
    ratio = np.minimum(emax[textured] / np.maximum(emin[textured], emax[textured] / _SPREAD_CAP),
                       _SPREAD_CAP)
    kt = (np.quantile(ratio, np.arange(1, n_spread) / n_spread) if ratio.size
          else np.ones(n_spread - 1))
    return st, ct, np.maximum(kt, 1.0)


def _accumulate(gram, M, buckets):
    """gram[b] += M_b M_b^T over the columns of each bucket b."""
    order = np.argsort(buckets, kind="stable")
    bounds = np.searchsorted(buckets[order], np.arange(gram.shape[0] + 1))
    M = M[:, order]
    for j in np.flatnonzero(np.diff(bounds)):
        Mj = M[:, bounds[j]:bounds[j + 1]]
        gram[j] += Mj @ Mj.T


def _transform(ph):
    """``T`` and ``beta``: the features ``T^T x`` (every tap minus the mean of the taps of
    its colour) and the baseline ``beta . x`` (the mean of the 5x5 target-colour taps)."""
    p = len(ph["taps"])
    T = np.eye(p)
    for col in np.unique(ph["colours"]):
        m = ph["colours"] == col
        T[np.ix_(m, m)] -= 1.0 / m.sum()
    beta = np.zeros(p)
    beta[ph["base"]] = 1.0 / len(ph["base"])
    return T, beta


def _solve(gram, ph, ridge, prior):
    """Ridge fits of the residual over the baseline: one on every site, then one per bucket
    shrunk towards it by ``prior`` sites' worth (from the bucket Gram matrices of [x, y, 1])."""
    p = len(ph["taps"])
    T, beta = _transform(ph)
    XX, Xy, N = gram[:, :p, :p], gram[:, :p, p], gram[:, p + 1, p + 1]
    A = T.T @ XX @ T                               # F^T F, F = X T (T symmetric)
    B = (Xy - XX @ beta) @ T                       # F^T (y - X beta)
    At, Bt = A.sum(0), B.sum(0)
    scale = max(np.trace(At) / p, np.finfo(float).tiny)
    eye = np.eye(p)
    wg = solve_normal(At + ridge * scale * eye, Bt)
    per_site = scale / max(N.sum(), 1.0)
    W = np.empty((len(A), p))
    for j in range(len(A)):
        lam = prior * per_site + ridge * np.trace(A[j]) / p
        if lam <= 0:
            lam = ridge * scale + np.finfo(float).tiny
        W[j] = solve_normal(A[j] + lam * eye, B[j] + lam * wg)
    return W


def _fold(w, ph):
    """Weights on the features -> weights on the taps (prediction = weights . taps)."""
    eff = np.array(w, np.float64)
    eff[:, ph["base"]] += 1.0 / len(ph["base"])
    for col in np.unique(ph["colours"]):
        m = ph["colours"] == col
        eff[:, m] -= w[:, m].sum(1, keepdims=True) / m.sum()
    return eff
