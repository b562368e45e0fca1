"""The geometry and the hash of the learned reconstruction (NumPy; csrc/learned.c is the kernel).

For one Z position of a pattern's tile (a *phase*), :func:`learned_geometry`
lists the taps (the known pixels of the window), their colours and the hash
pairs; :func:`hash_features` computes the hash terms of windows gathered
tap-major (:func:`gather_windows`) and :func:`hash_buckets` quantises them.
docs/guide/learned.md is the specification.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from .._patterns import Z, get_pattern
from .._validate import ReadOnlyDict

__all__ = ["N_ANGLES", "HASH_STEPS", "SPREAD_DIRECTIONS", "learned_geometry", "hash_features", "hash_buckets",
           "gather_windows", "extend_index", "mirror_octants"]

#: orientation bins of the hash (45 degrees of the doubled angle each)
N_ANGLES = 8
#: the four hash directions: steps between two same-colour pixels (horizontal,
#: vertical, main diagonal, anti-diagonal)
HASH_STEPS = ((0, 2), (2, 0), (2, 2), (2, -2))
#: the directions whose pairs give the colour energies of the channel spread (horizontal
#: and vertical: as informative as all four on the validation images, at half the cost)
SPREAD_DIRECTIONS = 2
_COS, _SIN = math.cos(math.pi / 8), math.sin(math.pi / 8)


@lru_cache(maxsize=64)
def learned_geometry(pattern, radius=3, hash_radius=3):
    """Per Z site of the tile: the taps, the target colour and the hash pairs.

    Returns a tuple with one dict per Z position of the tile (row-major):
    ``rc`` (its tile position), ``taps`` ((n, 2) int array of (dy, dx): the
    known pixels of the (2 radius + 1)^2 window, row-major), ``colours``
    (channel of each tap), ``target`` (the colour to fill in), ``base`` (the
    taps of the target colour within 5x5, whose mean the fit starts from),
    ``pairs`` (for each direction of :data:`HASH_STEPS`, an (m, 2) array of tap
    indices: both pixels known, of one colour, within ``hash_radius``),
    ``pair_colours`` (the colour of each pair, per direction) and
    ``colour_pairs`` (the number of horizontal and vertical pairs of each
    colour R, G, B: :data:`SPREAD_DIRECTIONS`; each is at least 1).
    """
    pattern = get_pattern(pattern)
    tile, btile = pattern.tile, pattern.bayer_tile()
    P, Q = pattern.period
    out = []
    for r in range(P):
        for c in range(Q):
            if tile[r, c] != Z:
                continue

            def ch(dy, dx, r=r, c=c):
                return int(tile[(r + dy) % P, (c + dx) % Q])

            taps = [(dy, dx) for dy in range(-radius, radius + 1)
                    for dx in range(-radius, radius + 1) if ch(dy, dx) != Z]
            index = {t: i for i, t in enumerate(taps)}
            colours = np.array([ch(*t) for t in taps], np.int32)
            target = int(btile[r, c])
            base = [i for i, (dy, dx) in enumerate(taps)
                    if abs(dy) <= 2 and abs(dx) <= 2 and colours[i] == target]
            if not base:
                raise ValueError(f"pattern: the Z site ({r}, {c}) of {pattern.name!r} has no "
                                 f"known pixel of its colour ({'RGB'[target]}) in the 5x5 "
                                 "window, so 'learned' cannot reconstruct it")
            pairs, pair_colours = [], []
            for sy, sx in HASH_STEPS:
                pp = [(i, index[(dy + sy, dx + sx)]) for i, (dy, dx) in enumerate(taps)
                      if (dy + sy, dx + sx) in index
                      and max(abs(dy), abs(dx), abs(dy + sy), abs(dx + sx)) <= hash_radius
                      and colours[i] == colours[index[(dy + sy, dx + sx)]]]
                if not pp:
                    raise ValueError(f"pattern: the Z site ({r}, {c}) of {pattern.name!r} has no "
                                     f"same-colour pair along ({sy}, {sx}) within the hash "
                                     f"radius {hash_radius}")
                pp = np.array(pp, np.int32).reshape(-1, 2)
                pairs.append(pp)
                pair_colours.append(colours[pp[:, 0]])
            colour_pairs = np.bincount(np.concatenate(pair_colours[:SPREAD_DIRECTIONS]),
                                       minlength=3)[:3]
            if np.any(colour_pairs == 0):
                missing = "RGB"[int(np.flatnonzero(colour_pairs == 0)[0])]
                raise ValueError(f"pattern: the Z site ({r}, {c}) of {pattern.name!r} has no "
                                 f"pair of {missing} pixels within the hash radius "
                                 f"{hash_radius}, so the channel spread of the hash is "
                                 "undefined")
            out.append({"rc": (r, c), "taps": np.array(taps, np.int32).reshape(-1, 2),
                        "colours": colours, "target": target, "base": np.array(base),
                        "pairs": tuple(pairs), "pair_colours": tuple(pair_colours),
                        "colour_pairs": colour_pairs})
    # shared by every filter set of the pattern (the cache), so read-only all through: a
    # caller's write into one set's geometry had changed the shipped filters' output (H99)
    for ph in out:
        for v in ph.values():
            for a in (v if isinstance(v, tuple) else (v,)):
                if isinstance(a, np.ndarray):
                    a.setflags(write=False)
    return tuple(_Phase(ph) for ph in out)


class _Phase(ReadOnlyDict):
    """One phase of :func:`learned_geometry`: a dict that refuses changes (its arrays are
    read-only too), and pickles and copies as one (a MappingProxyType did not pickle)."""

    _what = "the learned geometry is read-only (shared by every filter set of the pattern)"


def hash_features(X, ph):
    """The hash terms of windows ``X`` (n_taps, n_sites), tap-major, float64.

    Returns ``(a, b, t, emax, emin)``: ``E_d``, the mean of the squared
    differences of the pairs of direction d, gives ``a = E_h - E_v``,
    ``b = (E_d1 - E_d2) / 2`` (the doubled-angle vector) and
    ``t = (E_h + E_v) / 2 + (E_d1 + E_d2) / 4`` (the energy); ``E_c``, the
    mean squared difference of the horizontal and vertical pairs of colour c,
    gives the largest and the smallest of the three (the channel spread is
    ``emax / emin``).
    """
    n = X.shape[1]
    E = []
    Ec = np.zeros((3, n))
    for k, (pp, pc) in enumerate(zip(ph["pairs"], ph["pair_colours"])):
        e = np.zeros(n)
        for (i, j), col in zip(pp, pc):
            d = X[i] - X[j]
            d *= d
            e += d
            if k < SPREAD_DIRECTIONS:
                Ec[col] += d
        E.append(e * (1.0 / len(pp)))
    eh, ev, ed1, ed2 = E
    Ec *= (1.0 / ph["colour_pairs"])[:, None]
    return (eh - ev, (ed1 - ed2) * 0.5, (eh + ev) * 0.5 + (ed1 + ed2) * 0.25,
            Ec.max(0), Ec.min(0))


def hash_buckets(features, strength_thresholds, coherence_thresholds, spread_thresholds=()):
    """Bucket of every site: ``((angle * n_str + strength) * n_coh + coherence) * n_spr + spread``.

    ``features``: :func:`hash_features`'s tuple. Angle: the octant of the
    doubled-angle vector ``(a, b)`` rotated by 22.5 degrees (8 bins of 22.5
    degrees of edge orientation, the first centred on the horizontal
    gradient), by sign tests and one comparison -- no arctangent; a flat
    window (``a = b = 0``) is in octant 0. Strength: how many thresholds
    ``t`` exceeds. Coherence: how many thresholds ``c`` satisfy
    ``a^2 + b^2 > c^2 (t t)`` (coherence ``sqrt(a^2 + b^2) / t`` without a
    root or a division). Spread: how many thresholds ``s`` satisfy
    ``emax > s emin`` (``emax / emin`` without a division), as the C kernel
    computes them.
    """
    a, b, t, emax, emin = features
    ar = _COS * a - _SIN * b
    br = _SIN * a + _COS * b
    neg = br < 0
    ar, br = np.where(neg, -ar, ar), np.where(neg, -br, br)
    left = ar < 0
    ar, br = np.where(left, br, ar), np.where(left, -ar, br)
    octant = 4 * neg + 2 * left + (br > ar)
    s = np.zeros(a.shape, np.int64)
    for thr in strength_thresholds:
        s += t > thr
    m2 = a * a + b * b
    t2 = t * t
    c = np.zeros(a.shape, np.int64)
    for thr in coherence_thresholds:
        c += m2 > (thr * thr) * t2
    k = np.zeros(a.shape, np.int64)
    for thr in spread_thresholds:
        k += emax > thr * emin
    ns, nc = len(strength_thresholds) + 1, len(coherence_thresholds) + 1
    nk = len(spread_thresholds) + 1
    return ((octant * ns + s) * nc + c) * nk + k


def mirror_octants():
    """The octant of ``(a, -b)`` for each octant of ``(a, b)``: a left-right (or up-down)
    mirror of a window swaps the diagonals, so ``b`` changes sign and the doubled angle
    ``theta`` becomes ``-theta``."""
    return np.array([(N_ANGLES - o) % N_ANGLES for o in range(N_ANGLES)])


def extend_index(n, pad, period):
    """Indices -pad..n+pad-1 moved inside [0, n) by whole periods (the kernels' border rule)."""
    i = np.arange(-pad, n + pad)
    out = i.copy()
    lo, hi = i < 0, i >= n
    out[lo] = i[lo] + period * (-(i[lo] // period))
    out[hi] = i[hi] - period * (-(-(i[hi] - n + 1) // period))
    return out


def gather_windows(data, pattern, radius, geometry):
    """For each phase: (windows (n_taps, n_sites) float64, tap-major; (row0, col0, n_rows,
    n_cols) of its sites)."""
    P, Q = pattern.period
    H, W = data.shape
    pad = np.asarray(data)[extend_index(H, radius, P)][:, extend_index(W, radius, Q)]
    pad = pad.astype(np.float64)
    out = []
    for ph in geometry:
        r, c = ph["rc"]
        ny, nx = len(range(r, H, P)), len(range(c, W, Q))
        X = np.empty((len(ph["taps"]), ny * nx))
        for t, (dy, dx) in enumerate(ph["taps"]):
            X[t] = pad[radius + r + dy::P, radius + c + dx::Q][:ny, :nx].reshape(-1)
        out.append((X, (r, c, ny, nx)))
    return out
