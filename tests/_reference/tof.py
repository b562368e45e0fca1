"""NumPy reference of the ToF ISP's bilateral phasor mean (csrc/tof_filter.c).

The same weights as the C kernel, written as whole-grid NumPy operations over the
offsets of the window, each offset a shifted view of the grid
(``rgbz_fast.tof._filters.SiteGrid.offsets``). Neighbours enter the sums in the
kernel's order (rows of offsets, then columns), so the two agree to rounding
(exp() of libm and of NumPy may differ by an ulp).
"""

from __future__ import annotations

import numpy as np

from rgbz_fast.tof._filters import SiteGrid


def bilateral_pass(z, v, gz, gv, use, offsets, inv_h2):
    """One pass on the grid: weighted means of ``z`` (F, R, C) guided by ``gz``.

    Returns the mean (F, R, C), its variance (inf where nothing entered) and n_eff.
    """
    nfreq = z.shape[0]
    num = np.zeros_like(z)
    den = np.zeros(z.shape[1:])
    w2 = np.zeros(z.shape[1:])
    w2v = np.zeros(v.shape)
    for _a, (rt, rs), _b, (ct, cs), mask in offsets:
        src = (slice(None), rs, cs)
        tgt = (slice(None), rt, ct)
        diff = gz[src] - gz[tgt]
        chi = ((diff.real ** 2 + diff.imag ** 2) / (gv[src] + gv[tgt])).sum(axis=0)
        x = 0.5 * inv_h2 * (chi - 2.0 * nfreq)
        w = np.where(x > 0, np.where(x < 36.0, np.exp(-np.minimum(x, 36.0)), 0.0), 1.0)
        w = w * use[rs, cs]
        if mask is not None:
            w = w * mask
        num[tgt] += w * z[src]
        den[rt, ct] += w
        w2[rt, ct] += w * w
        w2v[tgt] += (w * w) * v[src]
    ok = den > 0
    inv = np.divide(1.0, den, out=np.zeros_like(den), where=ok)
    mean = num * inv
    var = np.where(ok, w2v * (inv * inv), np.inf)
    n_eff = np.divide(den * den, w2, out=np.zeros_like(den), where=w2 > 0)
    return mean, var, n_eff


def denoise_phasors_bilateral(i, q, var, sites, *, block=1, window=9, use=None,
                              range_scale=2.0, passes=2):
    """What :func:`rgbz_fast.tof.denoise_phasors_bilateral` returns, in NumPy."""
    grid = SiteGrid(sites, block)
    use = np.ones(grid.n, bool) if use is None else np.asarray(use, bool)
    z = grid.to_grid(np.asarray(i) + 1j * np.asarray(q))
    vg = grid.to_grid(np.asarray(var, np.float64), 1.0)
    useg = (grid.to_grid(use, False) & grid.present).astype(np.float64)
    offsets = grid.offsets((window // 2) * block)
    inv_h2 = 1.0 / (range_scale * range_scale)
    mean, mvar, n_eff = bilateral_pass(z, vg, z, vg, useg, offsets, inv_h2)
    if passes == 2:
        gv = np.where(np.isfinite(mvar), mvar, 1e300)
        mean, mvar, n_eff = bilateral_pass(z, vg, mean, gv, useg, offsets, inv_h2)
    mean = grid.from_grid(mean)
    return mean.real, mean.imag, grid.from_grid(mvar), grid.from_grid(n_eff)
