"""Slow NumPy reference of the learned reconstruction (method "learned").

Written from docs/guide/learned.md, independently of ``rgbz_fast.reconstruction._learned``
and of csrc/learned.c: the window, its taps and the hash pairs come from the channel codes
of the gathered window (not from the library's geometry), the orientation from an
arctangent (not from the octant tests of the kernels), the coherence from a root and a
division, the channel spread from a division. Only the fitted numbers (weights, thresholds) are read from the filters object.
Arithmetic is float64; the result is clipped to [0, maxval] but not rounded.

*Fragile* sites: an isotropic window that is not flat (a and b zero in exact arithmetic,
t > 0, e.g. a ramp at 45 degrees or a checkerboard of fractional values) leaves (a, b) at
the level of rounding noise, whose sign -- which the order of the sums decides -- picks
the orientation. ``reference_learned(..., return_fragile=True)`` marks the sites whose
coherence is below FRAGILE_COHERENCE; the tests leave them out of exact comparisons.
"""

from __future__ import annotations

import numpy as np

from .reconstruction import gather, window_offsets

Z = 3
STEPS = ((0, 2), (2, 0), (2, 2), (2, -2))
#: coherence below which the orientation of a non-flat window is rounding noise
FRAGILE_COHERENCE = 1e-9


def reference_learned(data, filters, return_fragile=False, bit_depth=None):
    """Every pixel of ``data`` (colour sites copied, Z sites reconstructed), float64;
    with ``return_fragile``, also the bool frame of the fragile sites. ``bit_depth``: the
    frame's (default: the filters'): the strength thresholds scale with the squared ratio of
    the white levels."""
    bd = filters.bit_depth if bit_depth is None else bit_depth
    gain = (((1 << bd) - 1) / ((1 << filters.bit_depth) - 1)) ** 2
    pattern = filters.pattern
    P, Q = pattern.period
    R, hr = filters.radius, filters.hash_radius
    offsets = window_offsets(R, R)
    chan = pattern.channel_map(data.shape)
    out = data.astype(np.float64).copy()
    fragile = np.zeros(data.shape, bool)
    phase = 0
    for r in range(P):
        for c in range(Q):
            if pattern.tile[r, c] != Z:
                continue
            ys, xs, X, taps, _, _, t, coherence, bucket = hash_sites(
                data, chan, pattern, (r, c), offsets, hr, filters, phase, gain)
            w = filters.weights[phase][bucket][:, :len(taps)]
            est = (X * w).sum(1)
            out[ys, xs] = np.clip(est, 0, (1 << bd) - 1)
            fragile[ys, xs] = (t > 0) & ~(coherence > FRAGILE_COHERENCE)
            phase += 1
    return (out, fragile) if return_fragile else out


def hash_sites(data, chan, pattern, site, offsets, hr, filters, phase, gain=1.0):
    """The Z sites of one phase of the tile (``site`` = its (row, col) in the tile) and their
    hash: ``(ys, xs, X, taps, tap_off, codes, t, coherence, bucket)``, X the values of the
    known taps (sites x taps, row-major), ``taps`` their indices in ``offsets``, ``tap_off``
    their offsets, ``codes`` the gathered channel codes; the strength thresholds
    of ``filters`` (LearnedFilters) scaled by ``gain``."""
    P, Q = pattern.period
    r, c = site
    ys, xs = np.mgrid[r:data.shape[0]:P, c:data.shape[1]:Q]
    ys, xs = ys.ravel(), xs.ravel()
    vals, codes = gather(data, chan, ys, xs, offsets, (P, Q))
    known = codes[0] != Z                       # the same at every site of a phase
    taps = np.flatnonzero(known)                # row-major: the weights' tap order
    X = vals[:, taps]
    tap_off = [tuple(offsets[i]) for i in taps]
    E = []
    by_colour = {0: [], 1: [], 2: []}          # horizontal and vertical pairs' squared
    for sy, sx in STEPS:                        # differences, by colour
        terms = []
        for i, (dy, dx) in enumerate(tap_off):
            other = (dy + sy, dx + sx)
            if (other in tap_off and max(abs(dy), abs(dx), abs(other[0]),
                                         abs(other[1])) <= hr
                    and codes[0, taps[i]] == codes[0, taps[tap_off.index(other)]]):
                terms.append((X[:, i] - X[:, tap_off.index(other)]) ** 2)
                if sy == 0 or sx == 0:
                    by_colour[int(codes[0, taps[i]])].append(terms[-1])
        E.append(np.mean(terms, axis=0))
    Ec = np.array([np.mean(by_colour[c], axis=0) for c in range(3)])
    with np.errstate(invalid="ignore", divide="ignore"):
        spread = Ec.max(0) / Ec.min(0)          # inf: a channel without texture
    spread[Ec.max(0) == 0] = 0.0                 # no texture at all: the lowest level
    eh, ev, ed1, ed2 = E
    a = eh - ev
    b = (ed1 - ed2) / 2
    t = (eh + ev) / 2 + (ed1 + ed2) / 4
    theta = np.degrees(np.arctan2(b, a))        # the doubled angle, (-180, 180]
    octant = np.floor((theta + 22.5) / 45.0).astype(int) % 8
    with np.errstate(invalid="ignore", divide="ignore"):
        coherence = np.sqrt(a * a + b * b) / t
    strength = (t[:, None] > gain * filters.strength_thresholds[phase][None, :]).sum(1)
    coh = (coherence[:, None] > filters.coherence_thresholds[phase][None, :]).sum(1)
    spr = (spread[:, None] > filters.spread_thresholds[phase][None, :]).sum(1)
    bucket = (((octant * filters.n_strength + strength) * filters.n_coherence + coh)
              * filters.n_spread + spr)
    return ys, xs, X, taps, tap_off, codes, t, coherence, bucket
