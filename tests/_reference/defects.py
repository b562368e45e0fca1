"""The defect correction of ``rgbz_fast.isp`` as it was first written (full-frame NumPy).

Kept verbatim (argument checks dropped) as the reference
of the phase-plane implementation in ``rgbz_fast.isp``, which must give the
same map and the same corrected values (tests/test_isp.py): per tile phase,
strided views of padded full-frame copies (``np.pad`` with +-inf), a float32
working copy of the frame with NaN at the Z sites, and a float64 one for the
medians.
"""

from __future__ import annotations

import numpy as np

from rgbz_fast._patterns import Z, get_pattern
from rgbz_fast.isp import DefectCorrection

__all__ = ["reference_detect_defects", "reference_correct_defects"]


def _colour_offsets(tile, py, px):
    """Offsets (dy, dx) of the 5x5 window holding the colour of tile site (py, px)."""
    P, Q = tile.shape
    c = tile[py, px]
    return [(dy, dx) for dy in range(-2, 3) for dx in range(-2, 3)
            if (dy, dx) != (0, 0) and tile[(py + dy) % P, (px + dx) % Q] == c]


def _neighbour_extremes(work, tile):
    """Max and min of the same-colour non-Z neighbours of every colour site (float32).

    ``work`` is float32 with NaN at the Z sites (which no colour offset
    reaches anyway). Pixels outside the frame do not count; a site without any
    neighbour gets -inf / +inf, which no test passes.
    """
    H, W = work.shape
    P, Q = tile.shape
    lo_pad = np.pad(work, 2, constant_values=np.inf)
    hi_pad = np.pad(work, 2, constant_values=-np.inf)
    mx = np.full((H, W), -np.inf, np.float32)
    mn = np.full((H, W), np.inf, np.float32)
    for py in range(min(P, H)):
        for px in range(min(Q, W)):
            if tile[py, px] == Z:
                continue
            h, w = work[py::P, px::Q].shape
            lmx = np.full((h, w), -np.inf, np.float32)
            lmn = np.full((h, w), np.inf, np.float32)
            for dy, dx in _colour_offsets(tile, py, px):
                sl = (slice(2 + py + dy, None, P), slice(2 + px + dx, None, Q))
                np.maximum(lmx, hi_pad[sl][:h, :w], out=lmx)
                np.minimum(lmn, lo_pad[sl][:h, :w], out=lmn)
            mx[py::P, px::Q] = lmx
            mn[py::P, px::Q] = lmn
    return mx, mn


def _gather_neighbours(work, tile, rr, cc):
    """Same-colour neighbours of the sites (rr, cc): (len(rr), 24) float64, NaN-padded.

    NaN stands for no neighbour: outside the frame, or a NaN in ``work``
    (a Z site, or a pixel the caller hid).
    """
    H, W = work.shape
    P, Q = tile.shape
    out = np.full((rr.size, 24), np.nan)
    phase = (rr % P) * Q + (cc % Q)
    for ph in np.unique(phase):
        sel = np.nonzero(phase == ph)[0]
        offs = np.array(_colour_offsets(tile, ph // Q, ph % Q), np.int64).reshape(-1, 2)
        r = rr[sel, None] + offs[:, 0]
        c = cc[sel, None] + offs[:, 1]
        inside = (r >= 0) & (r < H) & (c >= 0) & (c < W)
        nb = np.full(r.shape, np.nan)
        nb[inside] = work[r[inside], c[inside]]
        out[sel, :offs.shape[0]] = nb
    return out


def reference_detect_defects(cfa, pattern, params=DefectCorrection(), *, white_level=2047):
    """``rgbz_fast.isp.detect_defects`` (same parameters and results), full-frame NumPy."""
    data, pattern = np.asarray(cfa), get_pattern(pattern)
    white_level = float(white_level)
    found = np.zeros(data.shape, bool)
    if not params.enabled:
        return found
    zmask = pattern.z_mask(data.shape)
    tile = pattern.tile
    work = data.astype(np.float32)
    work[zmask] = np.nan                  # Z sites are hidden before anything reads them
    # tests 1 and 2 on every pixel
    mx, mn = _neighbour_extremes(work, tile)
    thr = np.float32(params.threshold * white_level)
    k = np.float32(params.spread_factor)
    spread = mx - mn
    with np.errstate(invalid="ignore"):
        hot = work - mx
        cold = mn - work
        cand = ((hot > thr) & (hot > k * spread)) | ((cold > thr) & (cold > k * spread))
    cand &= ~zmask & np.isfinite(mx)                    # a pixel needs neighbours
    rr, cc = np.nonzero(cand)
    if rr.size == 0:
        return found
    # test 3 on the few candidates: high-pass of the adjacent pixels
    H, W = data.shape
    adj = np.array([(dy, dx) for dy in (-1, 0, 1) for dx in (-1, 0, 1) if dy or dx])
    qr = rr[:, None] + adj[:, 0]
    qc = cc[:, None] + adj[:, 1]
    inside = (qr >= 0) & (qr < H) & (qc >= 0) & (qc < W)
    qr, qc = np.where(inside, qr, 0), np.where(inside, qc, 0)
    uq, inv = np.unique(qr * W + qc, return_inverse=True)
    ur, uc = uq // W, uq % W
    nb = _gather_neighbours(work, tile, ur, uc)
    cnt = np.sum(~np.isnan(nb), axis=1)
    tot = np.nansum(nb, axis=1)
    trim = cnt >= 3                        # trimmed mean: one defect nearby does not move it
    with np.errstate(invalid="ignore", divide="ignore"):
        big = np.where(cnt > 0, np.nanmax(np.where(cnt[:, None] > 0, nb, 0), axis=1), 0)
        small = np.where(cnt > 0, np.nanmin(np.where(cnt[:, None] > 0, nb, 0), axis=1), 0)
        mean = np.where(trim, (tot - big - small) / np.maximum(cnt - 2, 1),
                        tot / np.maximum(cnt, 1))
        hp = np.where(cnt > 0, work[ur, uc] - mean, np.nan)   # NaN at Z sites
    hp = hp[inv.reshape(qr.shape)]
    hp[~inside] = np.nan
    e_hot = hot[rr, cc].astype(np.float64)
    e_cold = cold[rr, cc].astype(np.float64)
    f = params.cross_factor
    with np.errstate(invalid="ignore"):
        adj_hi = np.nanmax(np.where(np.isnan(hp), -np.inf, hp), axis=1)
        adj_lo = np.nanmin(np.where(np.isnan(hp), np.inf, hp), axis=1)
        is_hot = (e_hot > thr) & (e_hot > k * spread[rr, cc]) & (adj_hi < f * e_hot)
        is_cold = (e_cold > thr) & (e_cold > k * spread[rr, cc]) & (adj_lo > -f * e_cold)
    found[rr, cc] = is_hot | is_cold
    return found


def reference_correct_defects(cfa, pattern, params=DefectCorrection(), *, white_level=2047,
                              known=None, return_mask=False):
    """``rgbz_fast.isp.correct_defects`` (same parameters and results), full-frame NumPy."""
    data, pattern = np.asarray(cfa), get_pattern(pattern)
    mask = reference_detect_defects(data, pattern, params, white_level=white_level)
    zmask = pattern.z_mask(data.shape)
    if known is not None:
        kn = np.asarray(known)
        if kn.shape != data.shape or kn.dtype != np.bool_:
            raise ValueError(f"known: expected a bool map of shape {data.shape}, got "
                             f"{kn.dtype} {kn.shape}")
        mask = mask | (kn & ~zmask)
    out = data.copy()
    if mask.any():
        rr, cc = np.nonzero(mask)
        work = data.astype(np.float64)
        work[zmask] = np.nan
        work[mask] = np.nan                   # a defect never repairs another one
        nb = _gather_neighbours(work, pattern.tile, rr, cc)
        ok = ~np.isnan(nb)
        m = ok.sum(axis=1)
        srt = np.sort(nb, axis=1)             # NaN sorts last
        idx = np.arange(rr.size)
        lo = srt[idx, np.maximum(m - 1, 0) // 2]
        hi = srt[idx, m // 2]
        values = np.where(m > 0, 0.5 * (lo + hi), data[rr, cc])   # no neighbour: kept
        if np.issubdtype(out.dtype, np.integer):
            values = np.floor(values + 0.5)
        out[rr, cc] = values.astype(out.dtype)
        mask[rr[m == 0], cc[m == 0]] = False
    return (out, mask) if return_mask else out
