"""Dynamic defect-pixel correction of a raw CFA, before the reconstruction (Z sites never read).

The detection compares each colour pixel with its same-colour neighbours of the
5x5 window and with the neighbours of its adjacent pixels (a real detail,
blurred by the optics, lifts every channel; a defect is one pixel); the
measured numbers are in docs/guide/isp.md.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._patterns import Z
from .._validate import as_array, check_flag, check_number
from ._stages import _prepare_cfa, check_white_level, stage_params

__all__ = ["DefectCorrection", "detect_defects", "correct_defects"]


#: the largest spread_factor and cross_factor (the defaults are 1 and 0.1)
FACTOR_MAX = 1e6


@dataclass(frozen=True)
class DefectCorrection:
    """Dynamic defect-pixel correction (before the reconstruction; Z sites never read).

    A colour pixel ``p`` is compared with its *same-colour non-Z neighbours*
    ``N_p`` in the 5x5 window inside the frame (12 for green and 8 for red
    and blue on a Bayer CFA, fewer on RGB-Z patterns). It is **hot** when
    all of

    1. ``v_p - max(N_p) > threshold * white_level`` (it stands out),
    2. ``v_p - max(N_p) > spread_factor * (max(N_p) - min(N_p))`` (more than
       the local texture),
    3. no adjacent non-Z pixel ``q`` (8-neighbourhood, any colour) rises with
       it: ``v_q - mean'(N_q) < cross_factor * (v_p - max(N_p))``, with
       ``mean'`` the mean without the largest and the smallest value (so a
       second defect nearby does not move it). A real detail, blurred by the
       optics, lifts its neighbours in every channel; a defect is one pixel,

    and **cold** in the mirror case. Flagged pixels take the median of
    ``N_p`` (rounded half up for integer CFAs). On the 24 noise-free Kodak
    mosaics (11 bit; scanned film has no lens blur at the pixel scale, so a
    few real one-pixel details exist) the defaults flag 5 pixels in all on
    the Bayer CFA, 18 on Mask1 and 26 on Mask2, of 9.4 million each; they
    find about 70 % of the planted defects that deviate by more than
    500 DN from a noisy frame (docs/guide/isp.md).

    Attributes
    ----------
    enabled : bool
        False: the stage returns its input.
    threshold : float
        Fraction of the white level (0.15).
    spread_factor : float
        (1.0); at most 1e6.
    cross_factor : float
        (0.1); at most 1e6.
    """

    enabled: bool = True
    threshold: float = 0.15
    spread_factor: float = 1.0
    cross_factor: float = 0.1

    def __post_init__(self):
        check_flag(self.enabled, "DefectCorrection.enabled")
        check_number(self.threshold, "DefectCorrection.threshold", lo=0, lo_open=True, hi=1)
        # at most FACTOR_MAX: the float32 tests of the fused ISP overflowed beyond it (1e308)
        check_number(self.spread_factor, "DefectCorrection.spread_factor", lo=0, hi=FACTOR_MAX)
        check_number(self.cross_factor, "DefectCorrection.cross_factor", lo=0, hi=FACTOR_MAX)



def _colour_offsets(tile, py, px):
    """Offsets (dy, dx) of the 5x5 window holding the colour of tile site (py, px)."""
    P, Q = tile.shape
    c = tile[py, px]
    return [(dy, dx) for dy in range(-2, 3) for dx in range(-2, 3)
            if (dy, dx) != (0, 0) and tile[(py + dy) % P, (px + dx) % Q] == c]


#: NaN cells around every position plane (enough for the 5x5 window's reach of +-2 pixels
#: on any tile, including planes one row or column shorter than others)
_PAD = 3


def _position_planes(data, tile):
    """The colour positions of the tile as contiguous float32 sub-images, NaN-padded.

    ``planes[py, px]`` holds ``data[py::P, px::Q]`` (converted to float32, as
    the detection works in float32) inside a border of :data:`_PAD` NaN cells,
    so that every same-colour neighbour of a position is a shifted, unit-stride
    view of one plane and a neighbour outside the frame is NaN. Z positions are
    left out (no colour pixel has a Z neighbour of its colour, and a Z site is
    never read).
    """
    H, W = data.shape
    P, Q = tile.shape
    planes = {}
    for py in range(min(P, H)):
        for px in range(min(Q, W)):
            if tile[py, px] == Z:
                continue
            sub = data[py::P, px::Q]
            buf = np.empty((sub.shape[0] + 2 * _PAD, sub.shape[1] + 2 * _PAD), np.float32)
            buf[:_PAD] = buf[-_PAD:] = buf[:, :_PAD] = buf[:, -_PAD:] = np.nan
            buf[_PAD:-_PAD, _PAD:-_PAD] = sub
            planes[py, px] = buf
    return planes


def _position_extremes(planes, tile, py, px, mx, mn):
    """Max and min (float32) of the same-colour neighbours of every pixel at tile position
    (py, px), into the buffers ``mx`` and ``mn`` (of that plane's shape).

    Neighbours outside the frame do not count (NaN, skipped by fmax / fmin); a
    pixel without any neighbour gets NaN, which no test passes.
    """
    P, Q = tile.shape
    h, w = mx.shape
    views = []
    for dy, dx in _colour_offsets(tile, py, px):
        target = planes.get(((py + dy) % P, (px + dx) % Q))
        if target is None:                        # a position the (tiny) frame does not hold
            continue
        sy, sx = _PAD + (py + dy) // P, _PAD + (px + dx) // Q
        views.append(target[sy:sy + h, sx:sx + w])
    if not views:
        mx.fill(np.nan)
        mn.fill(np.nan)
    elif len(views) == 1:
        np.copyto(mx, views[0])
        np.copyto(mn, views[0])
    else:
        np.fmax(views[0], views[1], out=mx)
        np.fmin(views[0], views[1], out=mn)
        for nb in views[2:]:
            np.fmax(mx, nb, out=mx)
            np.fmin(mn, nb, out=mn)
    return mx, mn


def _site_values(data, tile, rr, cc, dtype, hidden=None):
    """``data[rr, cc]`` as ``dtype`` (then float64), NaN at Z sites and where ``hidden``."""
    P, Q = tile.shape
    v = _at(data, rr, cc).astype(dtype).astype(np.float64)
    drop = _at(tile, rr % P, cc % Q) == Z
    if hidden is not None:
        drop |= _at(hidden, rr, cc)
    v[drop] = np.nan
    return v


def _at(a, rr, cc):
    """``a[rr, cc]`` (indices inside ``a``): one take of flat indices on a C-contiguous
    array, a fraction of the time of two index arrays."""
    if a.flags.c_contiguous:
        return a.reshape(-1).take(rr * a.shape[1] + cc)
    return a[rr, cc]


def _gather_neighbours(data, tile, rr, cc, dtype, hidden=None):
    """Same-colour neighbours of the sites (rr, cc): (len(rr), 24) float64, NaN-padded.

    The values are ``data`` converted to ``dtype``; NaN stands for no
    neighbour: outside the frame, a Z site, or a pixel of ``hidden``.
    """
    H, W = data.shape
    P, Q = tile.shape
    out = np.full((rr.size, 24), np.nan)
    position = (rr % P) * Q + (cc % Q)
    for pos in np.unique(position):
        sel = np.nonzero(position == pos)[0]
        offs = np.array(_colour_offsets(tile, pos // Q, pos % Q), np.int64).reshape(-1, 2)
        r = rr[sel, None] + offs[:, 0]
        c = cc[sel, None] + offs[:, 1]
        inside = (r >= 0) & (r < H) & (c >= 0) & (c < W)
        nb = np.full(r.shape, np.nan)
        nb[inside] = _site_values(data, tile, r[inside], c[inside], dtype, hidden)
        out[sel, :offs.shape[0]] = nb
    return out


def detect_defects(cfa, pattern, params=None, *, white_level=2047, **overrides):
    """Boolean map of the defective colour pixels (see :class:`DefectCorrection`).

    Parameters
    ----------
    cfa : ndarray, shape (rows, cols)
        Raw frame in DN (the values at Z sites are never read).
    pattern : Pattern or str
        The frame's pattern.
    params : DefectCorrection, optional
        Default ``DefectCorrection()``; keyword ``overrides`` replace its
        fields (``threshold=0.05``).
    white_level : float
        Full scale in DN (``2**bit_depth - 1``).

    Returns
    -------
    ndarray of bool, shape (rows, cols)
        False at every Z site.
    """
    data, pattern = _prepare_cfa(cfa, pattern)
    params = stage_params(DefectCorrection, params, overrides, caller="detect_defects()")
    white_level = check_white_level(white_level)
    found = np.zeros(data.shape, bool)
    if params.enabled:
        rr, cc = _detect_sites(data, pattern.tile, params, white_level)
        found[rr, cc] = True
    return found


def _detect_sites(data, tile, params, white_level):
    """Rows and columns of the defects :func:`detect_defects` flags (validated input):
    tests 1 and 2 on every colour pixel (:func:`_candidates`), test 3 on the few
    candidates (:func:`_confirm`)."""
    return _confirm(data, tile, params, white_level,
                    _candidates(data, tile, params, white_level))


def _thresholds(params, white_level):
    """Test 1's threshold and test 2's spread factor, in float32 (as the tests compute)."""
    return np.float32(params.threshold * white_level), np.float32(params.spread_factor)


def _candidates(data, tile, params, white_level):
    """The pixels that pass tests 1 and 2: ``(rr, cc, hot, cold, spread)``, the last three
    float32 (``v - max(N)``, ``min(N) - v``, ``max(N) - min(N)``); in any order.

    One tile position at a time on contiguous NaN-padded sub-images
    (:func:`_position_planes`: Z sites are never read), test 1 first on the whole plane
    and test 2 on the few pixels that pass it.
    """
    P, Q = tile.shape
    thr, k = _thresholds(params, white_level)
    planes = _position_planes(data, tile)
    hmax = max(b.shape[0] for b in planes.values()) - 2 * _PAD if planes else 0
    wmax = max(b.shape[1] for b in planes.values()) - 2 * _PAD if planes else 0
    bufs = [np.empty((hmax, wmax), np.float32) for _ in range(4)]
    rr, cc, e_hot, e_cold, spread = [], [], [], [], []
    for (py, px), buf in planes.items():
        v = buf[_PAD:-_PAD, _PAD:-_PAD]
        h, w = v.shape
        mx, mn, hot, cold = (b[:h, :w] for b in bufs)
        _position_extremes(planes, tile, py, px, mx, mn)
        with np.errstate(invalid="ignore"):
            np.subtract(v, mx, out=hot)
            np.subtract(mn, v, out=cold)
            # test 1 (thr > 0), which the rest needs, on the whole plane
            cand = np.greater(hot, thr)
            cand |= np.greater(cold, thr)
        i, j = np.nonzero(cand)
        if i.size == 0:
            continue
        # test 2 on the few that pass (a pixel without neighbours has NaN: never passes)
        ht, cd = hot[i, j], cold[i, j]
        sp = mx[i, j] - mn[i, j]
        ksp = k * sp
        with np.errstate(invalid="ignore"):
            keep = ((ht > thr) & (ht > ksp)) | ((cd > thr) & (cd > ksp))
        rr.append(py + i[keep] * P)
        cc.append(px + j[keep] * Q)
        e_hot.append(ht[keep])
        e_cold.append(cd[keep])
        spread.append(sp[keep])
    if not rr:
        empty = np.zeros(0, np.float32)
        return np.zeros(0, np.intp), np.zeros(0, np.intp), empty, empty, empty
    return (np.concatenate(rr), np.concatenate(cc), np.concatenate(e_hot),
            np.concatenate(e_cold), np.concatenate(spread))


def _confirm(data, tile, params, white_level, candidates):
    """Test 3 on the ``candidates`` of :func:`_candidates`: rows and columns of the defects."""
    rr, cc, e_hot, e_cold, spread = candidates
    if rr.size == 0:
        return rr, cc
    thr, k = _thresholds(params, white_level)
    e_hot = e_hot.astype(np.float64)
    e_cold = e_cold.astype(np.float64)
    # test 3 on the few candidates: high-pass of the adjacent pixels
    H, W = data.shape
    adj = np.array([(dy, dx) for dy in (-1, 0, 1) for dx in (-1, 0, 1) if dy or dx])
    qr = rr[:, None] + adj[:, 0]
    qc = cc[:, None] + adj[:, 1]
    inside = (qr >= 0) & (qr < H) & (qc >= 0) & (qc < W)
    qr, qc = np.where(inside, qr, 0), np.where(inside, qc, 0)
    uq, inv = np.unique(qr * W + qc, return_inverse=True)
    ur, uc = uq // W, uq % W
    nb = _gather_neighbours(data, tile, ur, uc, np.float32)
    cnt = np.sum(~np.isnan(nb), axis=1)
    tot = np.nansum(nb, axis=1)
    trim = cnt >= 3                        # trimmed mean: one defect nearby does not move it
    with np.errstate(invalid="ignore", divide="ignore"):
        big = np.where(cnt > 0, np.nanmax(np.where(cnt[:, None] > 0, nb, 0), axis=1), 0)
        small = np.where(cnt > 0, np.nanmin(np.where(cnt[:, None] > 0, nb, 0), axis=1), 0)
        mean = np.where(trim, (tot - big - small) / np.maximum(cnt - 2, 1),
                        tot / np.maximum(cnt, 1))
        hp = np.where(cnt > 0, _site_values(data, tile, ur, uc, np.float32) - mean,
                      np.nan)                                   # NaN at Z sites
    hp = hp[inv.reshape(qr.shape)]
    hp[~inside] = np.nan
    f = params.cross_factor
    with np.errstate(invalid="ignore"):
        adj_hi = np.nanmax(np.where(np.isnan(hp), -np.inf, hp), axis=1)
        adj_lo = np.nanmin(np.where(np.isnan(hp), np.inf, hp), axis=1)
        is_hot = (e_hot > thr) & (e_hot > k * spread) & (adj_hi < f * e_hot)
        is_cold = (e_cold > thr) & (e_cold > k * spread) & (adj_lo > -f * e_cold)
    ok = is_hot | is_cold
    return rr[ok], cc[ok]


def correct_defects(cfa, pattern, params=None, *, white_level=2047, known=None,
                    return_mask=False, **overrides):
    """Replace defective colour pixels by the median of their same-colour neighbours.

    Parameters
    ----------
    cfa : ndarray, shape (rows, cols)
        Raw frame in DN. The values at Z sites are neither read nor changed.
    pattern : Pattern or str
    params : DefectCorrection, optional
        Default ``DefectCorrection()``; keyword ``overrides`` replace its
        fields.
    white_level : float
        Full scale in DN.
    known : ndarray of bool, shape (rows, cols), optional
        Known defects (a factory defect map), corrected in addition to the
        detected ones (Z sites in it are ignored).
    return_mask : bool
        Also return the map of corrected pixels.

    Returns
    -------
    out : ndarray, same shape and dtype as ``cfa``
        A copy (the input is never modified).
    mask : ndarray of bool
        Only with ``return_mask``.
    """
    data, pattern = _prepare_cfa(cfa, pattern)
    params = stage_params(DefectCorrection, params, overrides, caller="correct_defects()")
    return_mask = check_flag(return_mask, "return_mask")
    white_level = check_white_level(white_level)
    kn = _check_known(known, data.shape)
    rr, cc, values, mask = _fixes(data, pattern, params, white_level, kn)
    out = data.copy()
    out[rr, cc] = values
    return (out, mask) if return_mask else out


def _check_known(known, shape):
    """The known-defect map, checked (None passes)."""
    if known is None:
        return None
    kn = as_array(known, "known")
    if kn.shape != shape or kn.dtype != np.bool_:
        raise ValueError(f"known: expected a bool map of shape {shape}, got "
                         f"{kn.dtype} {kn.shape}")
    return kn


def _fixes(data, pattern, params, white_level, known, confirmed=None):
    """What :func:`correct_defects` changes, of validated arguments: ``(rr, cc, values,
    mask)``, the corrected pixels, their new values (the CFA's dtype) and the map of the
    corrected pixels. ``confirmed``: the defects of the three tests when already computed
    (the C passes of the fused chain), else :func:`_candidates` and :func:`_confirm` run."""
    mask = np.zeros(data.shape, bool)
    if params.enabled and confirmed is not None:
        rr, cc = confirmed
    elif params.enabled:
        candidates = _candidates(data, pattern.tile, params, white_level)
        rr, cc = _confirm(data, pattern.tile, params, white_level, candidates)
    else:
        rr, cc = (np.zeros(0, np.intp),) * 2
    mask[rr, cc] = True
    if known is not None:
        mask |= known & ~pattern.z_mask(data.shape)
        rr, cc = np.nonzero(mask)
    values = data[rr, cc]
    if rr.size:
        # a defect never repairs another one: the flagged pixels are hidden, as Z sites are
        nb = _gather_neighbours(data, pattern.tile, rr, cc, np.float64, hidden=mask)
        ok = ~np.isnan(nb)
        m = ok.sum(axis=1)
        srt = np.sort(nb, axis=1)             # NaN sorts last
        idx = np.arange(rr.size)
        lo = srt[idx, np.maximum(m - 1, 0) // 2]
        hi = srt[idx, m // 2]
        values = np.where(m > 0, 0.5 * (lo + hi), data[rr, cc])   # no neighbour: kept
        if np.issubdtype(data.dtype, np.integer):
            values = np.floor(values + 0.5)
        values = values.astype(data.dtype)
        mask[rr[m == 0], cc[m == 0]] = False
    return rr, cc, values, mask
