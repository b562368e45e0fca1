"""Slow NumPy reference of the z_guided reconstruction (method "z_guided").

Written from docs/guide/z_guided.md, apart from ``rgbz_fast.reconstruction._z_guided``
and csrc/z_guided.c: the window, its taps and the hash come from the channel codes of
the gathered window by :func:`_reference.learned.hash_sites` (an arctangent for the
orientation, a root and a division for the coherence); the guide features of each site from its own
Z pixel and the 3 x 3 around it, the colour means from the pixels of the box
gathered with the border rule of every kernel. The amplitude grid and its noise
variance from the taps: :func:`reference_guide_grid`, from ``ToFTaps.amplitude``
(the data model's demodulation) in NumPy; the fitted numbers are read from the
library. Arithmetic is float64; the result is clipped to [0, maxval] but not
rounded.
"""

from __future__ import annotations

import numpy as np

from .learned import Z, hash_sites
from .reconstruction import shift_index, window_offsets

#: the guide's median runs over every s-th of the N Z pixels, s = N // SAMPLE + 1
SAMPLE = 16384


def _colour_mean(data, chan, t, y0, x0, b, period):
    """Mean of the pixels of colour t in the box of the Z pixel at (y0, x0) (size b) and the
    two pixels around it: (n,) for arrays y0, x0."""
    P, Q = period
    dy, dx = np.mgrid[-2:b + 2, -2:b + 2]
    yy = shift_index(y0[:, None] + dy.ravel()[None, :], data.shape[0], P)
    xx = shift_index(x0[:, None] + dx.ravel()[None, :], data.shape[1], Q)
    keep = chan[yy, xx] == t
    return np.where(keep, data[yy, xx], 0.0).sum(1) / keep.sum(1)


def reference_guide_grid(shape, pattern, tof):
    """The amplitude grid and its noise variance (tile rows, tile columns) from the taps of
    ``tof``, as docs/guide/z_guided.md states them: the mean over the frequencies of the
    amplitude, sum_f (A_f / r_f - mean_f A_f / r_f)^2 / (F (F - 1)) with r_f the median of
    A_f / mean over the lit sites of a sample (every s-th Z pixel in row-major order,
    s = N // SAMPLE + 1; 1 if none lit, or if it is not > 0); a Z pixel cut by the frame's
    edge takes the values of the last complete row and column."""
    P, Q = pattern.period
    z = np.argwhere(pattern.tile == Z)
    zr, zc = (int(v) for v in z.min(axis=0))
    b = 1 if len(z) == 1 else 2
    gy, gx = len(range(zr, shape[0], P)), len(range(zc, shape[1], Q))
    amp = tof.amplitude("all")
    mean = amp.mean(axis=0)
    F = amp.shape[0]
    var = np.zeros_like(mean)
    rows, cols = tof.sites
    iy, ix = (rows - zr) // P, (cols - zc) // Q
    if F > 1:
        sample = np.argsort(iy * gx + ix, kind="stable")[::len(mean) // SAMPLE + 1]
        lit = sample[mean[sample] > 0]
        ratio = np.median(amp[:, lit] / mean[lit], axis=1) if len(lit) else np.ones(F)
        norm = amp / np.where(ratio > 0, ratio, 1.0)[:, None]
        var = ((norm - norm.mean(axis=0)) ** 2).sum(axis=0) / (F * (F - 1))
    # the complete Z pixels: the first gyc rows and gxc columns of the grid
    gyc = len([r for r in range(zr, shape[0], P) if r + b - 1 < shape[0]])
    gxc = len([c for c in range(zc, shape[1], Q) if c + b - 1 < shape[1]])
    out = []
    for values in (mean, var):
        grid = np.zeros((gy, gx))
        grid[iy, ix] = values
        grid = grid[np.minimum(np.arange(gy), gyc - 1)][:, np.minimum(np.arange(gx), gxc - 1)]
        out.append(grid)
    return tuple(out)


def reference_z_guided(data, filters, grid, var):
    """Every pixel of ``data`` (colour sites copied, Z sites reconstructed), float64."""
    lf = filters.base
    pattern = filters.pattern
    P, Q = pattern.period
    R, hr = lf.radius, lf.hash_radius
    offsets = window_offsets(R, R)
    chan = pattern.channel_map(data.shape)
    target = pattern.bayer_pattern().channel_map(data.shape)
    data = data.astype(np.float64)
    out = data.copy()
    gy, gx = grid.shape
    z = np.argwhere(pattern.tile == Z)
    zr, zc = z.min(axis=0)
    b = 1 if len(z) == 1 else 2
    phase = 0
    for r in range(P):
        for c in range(Q):
            if pattern.tile[r, c] != Z:
                continue
            ys, xs, X, taps, tap_off, codes, _, _, bucket = hash_sites(
                data, chan, pattern, (r, c), offsets, hr, lf, phase)
            # the guide: the site's Z pixel (its tile) and the 3 x 3 around it, clamped
            tc = int(target[r, c])
            base_taps = [i for i, (dy, dx) in enumerate(tap_off)
                         if abs(dy) <= 2 and abs(dx) <= 2 and codes[0, taps[i]] == tc]
            base = X[:, base_taps].mean(1)
            iy, ix = ys // P, xs // Q
            N, V, C = [], [], []
            for dy in (-1, 0, 1):
                for dx in (-1, 0, 1):
                    jy, jx = np.clip(iy + dy, 0, gy - 1), np.clip(ix + dx, 0, gx - 1)
                    N.append(grid[jy, jx])
                    V.append(var[jy, jx])
                    C.append(_colour_mean(data, chan, tc, zr + P * jy, zc + Q * jx, b, (P, Q)))
            N, V, C = (np.stack(v, 1) for v in (N, V, C))
            mean_n = N.mean(1)
            lit = mean_n > 0
            safe = np.where(lit, mean_n, 1.0)
            u = np.where(lit[:, None], N / safe[:, None] - 1, 0.0)
            nu = np.where(lit, V.mean(1) / safe ** 2, 1.0)
            U = (u ** 2).sum(1)
            share = U / (U + 9 * nu + np.finfo(float).tiny)
            dC = C - C.mean(1)[:, None]
            slope = (u * dC).sum(1) / (U + 9 * (filters.lam + nu))
            G = np.hstack([base[:, None] * share[:, None] * u,
                           (C.mean(1) + slope * u[:, 4] - base)[:, None],
                           (slope * u[:, 4] - dC[:, 4])[:, None]])
            level = (nu[:, None] > filters.noise_thresholds[None, :]).sum(1)
            full = level * lf.n_buckets + bucket
            est = (X * filters.weights[phase][full][:, :len(taps)]).sum(1) + \
                (G * filters.guide_weights[phase][full]).sum(1)
            out[ys, xs] = np.clip(est, 0, (1 << lf.bit_depth) - 1)
            phase += 1
    return out
