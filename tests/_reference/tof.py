"""NumPy references of the ToF ISP's C kernels: the bilateral phasor mean and the paper's box
mean (csrc/tof_filter.c), the guided ISP's stages (csrc/tof_guided.c) and the validity.

The same weights as the C kernel, written as whole-grid NumPy operations over the
offsets of the window, each offset a shifted view of the grid
(``rgbz_fast.tof._filters.SiteGrid.offsets``). Neighbours enter the sums in the
kernel's order (rows of offsets, then columns), so the two agree to rounding
(exp() of libm and of NumPy may differ by an ulp).
"""

from __future__ import annotations

import numpy as np

from rgbz_fast._sensors import SPEED_OF_LIGHT
from rgbz_fast._validate import as_array, as_list, check_block, check_sites
from rgbz_fast.tof._filters import SiteGrid, _axis_offsets
from rgbz_fast.tof._stages import _check_window


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


# --------------------------------------------------------------------------- guided ISP
# NumPy references of csrc/tof_guided.c, plain loops over offsets in float64. The kernels
# compute the filter in float (the reference agrees to about 1e-5 relative) and the rest in
# double (the same decisions, the same values to rounding).

def denoise_phasors(i, q, sites, *, block=1, window=5, use=None, extra=()):
    """The paper's box mean as the library computed it in NumPy before its C kernel
    (csrc/tof_filter.c, rgbz_tof_box): the reference the kernel is held to bit for bit."""
    i = as_array(i, "i", dtype=np.float64)
    q = as_array(q, "q", dtype=np.float64)
    if i.ndim != 2 or q.shape != i.shape:
        raise ValueError(f"i, q: expected two arrays of the same shape (F, n), got "
                         f"{i.shape} and {q.shape}")
    n = i.shape[1]
    rows, cols = (as_array(a, "sites") for a in as_list(sites, "sites", "(rows, cols)")[:2])
    if rows.shape != (n,) or cols.shape != (n,):
        raise ValueError(f"sites: expected two arrays of shape ({n},), got {rows.shape} and "
                         f"{cols.shape}")
    rows, cols = check_sites((rows, cols), "sites")             # integers, none twice
    block = check_block(block, "block")
    window = _check_window(window)
    use = np.ones(n, bool) if use is None else as_array(use, "use", dtype=bool)
    if use.shape != (n,):
        raise ValueError(f"use: expected shape ({n},), got {use.shape}")
    extra = [as_array(e, "extra", dtype=np.float64) for e in as_list(extra, "extra")]
    planes = [p for p in i] + [p for p in q]
    for e in extra:
        planes += [p for p in e] if e.ndim == 2 else [e]
    radius = (window // 2) * block
    # compress the measurements onto the grid of their distinct rows and columns
    ur, ri = np.unique(rows, return_inverse=True)
    uc, ci = np.unique(cols, return_inverse=True)
    row_offs = _axis_offsets(ur, radius)
    col_offs = _axis_offsets(uc, radius)
    weight = None if use.all() else use.astype(np.float64)
    # Mask1, Mask2, rows: the measurements fill the compressed grid in row-major order
    full = (n == ur.size * uc.size and np.array_equal(ri, np.arange(n) // uc.size)
            and np.array_equal(ci, np.arange(n) % uc.size))

    def box(values):
        if weight is not None:
            values = values * weight
        if full:
            g = values.reshape(ur.size, uc.size)
        else:
            g = np.zeros((ur.size, uc.size))
            g[ri, ci] = values
        tmp = np.zeros_like(g)
        for a, lo, hi, ok in row_offs:
            tmp[lo:hi] += g[lo + a:hi + a] if ok.all() else g[lo + a:hi + a] * ok[:, None]
        out = np.zeros_like(g)
        for a, lo, hi, ok in col_offs:
            out[:, lo:hi] += tmp[:, lo + a:hi + a] if ok.all() else tmp[:, lo + a:hi + a] * ok
        return out.reshape(-1) if full else out[ri, ci]

    count = box(np.ones(n))
    inv = np.divide(1.0, count, out=np.zeros(n), where=count > 0)
    means = [box(p) * inv for p in planes]
    F = i.shape[0]
    i_mean = np.stack(means[:F])
    q_mean = np.stack(means[F:2 * F])
    rest, k = [], 2 * F
    for e in extra:
        m = e.shape[0] if e.ndim == 2 else 1
        rest.append(np.stack(means[k:k + m]) if e.ndim == 2 else means[k])
        k += m
    return i_mean, q_mean, count, rest


def phasors_offset(t):
    """I, Q and the offset of taps as NumPy computed them before the C pass
    (csrc/tof_filter.c, rgbz_tof_phasors_offset)."""
    i = np.subtract(t[:, 0], t[:, 2], dtype=np.float64)
    q = np.subtract(t[:, 3], t[:, 1], dtype=np.float64)
    offset = np.add(t[:, 0], t[:, 1], dtype=np.float64)
    offset += np.add(t[:, 2], t[:, 3], dtype=np.float64)
    offset *= 0.25
    return i, q, offset


def tap_variance(offset, sensor):
    """The variance of one tap as NumPy computed it before the C pass (csrc/tof_filter.c,
    rgbz_tof_tap_variance)."""
    k = sensor.system_gain
    held = np.subtract(offset, sensor.black_level, dtype=np.float64)
    np.maximum(held, 0.0, out=held)
    v = held * k
    if sensor.ambient_suppression:
        v /= 1.0 - sensor.ambient_suppression
    v += k * k * (sensor.read_noise ** 2 + sensor.dsnu ** 2)
    v += 1.0 / 12.0                          # a floor, also without quantisation
    if sensor.prnu:        # PRNU of the charge collected before the suppression (2026-11-27)
        s = sensor.ambient_suppression
        held *= sensor.prnu * (1.0 / (1.0 - s) if s else 1.0)
        v += held * held
    return v


def guided_prepare(taps, gain, black, supp, const_var, prnu, white, fixed_var=0.0):
    """Phasors (F, N), the mean over the frequencies of 2 var(A) (N,), full-scale taps (N,),
    the offset (F, N), and phi (N,): the share of that variance the fixed pattern gives
    (fixed_var, the DSNU's per-tap variance, and the PRNU part)."""
    t = np.asarray(taps, np.float64)
    zr = t[:, 0] - t[:, 2]
    zi = t[:, 3] - t[:, 1]
    offset = 0.25 * ((t[:, 0] + t[:, 1]) + (t[:, 2] + t[:, 3]))
    held = np.maximum(offset - black, 0.0)
    var_a = gain * supp * held + const_var + (prnu * held) ** 2
    v = 2.0 * var_a.mean(axis=0)
    sat = (t.max(axis=(0, 1)) >= white)
    fix = (fixed_var + (prnu * held) ** 2).sum(axis=0)
    total = var_a.sum(axis=0)
    phi = np.divide(fix, total, out=np.zeros_like(total), where=total > 0)
    return zr, zi, v, sat, offset, np.minimum(phi, 0.99)


def guided_colour(guide, rows, cols, block, scale):
    """The guide at the measurements (3, R*C), each cell (block^2, 3, R*C) and the sums of
    |Immerkaer's Laplacian| (3,)."""
    g = np.asarray(guide, np.float64) * scale
    cells = np.stack([np.moveaxis(g[np.add.outer(rows + dr, np.zeros_like(cols)),
                                    np.add.outer(np.zeros_like(rows), cols + dc)], -1, 0)
                      for dr in range(block) for dc in range(block)])
    col = cells.mean(axis=0)
    k = np.array([[1, -2, 1], [-2, 4, -2], [1, -2, 1]], np.float64)
    R, C = rows.size, cols.size
    lap = np.zeros(3)
    for ch in range(3):
        p = col[ch]
        acc = np.zeros((R - 2, C - 2))
        for a in range(3):
            for b in range(3):
                acc += k[a, b] * p[a:a + R - 2, b:b + C - 2]
        lap[ch] = np.abs(acc).sum()
    return col.reshape(3, -1), cells.reshape(block * block, 3, -1), lap


def guided_ring(g, rows, cols, block, inv):
    """The guide at the pixels bordering each Z pixel (rows x cols, top-left cells) times inv
    (3,) per channel, in float32: (4 block + 4, 3, R*C), the offsets row-major, clamped to
    the frame (the guided ISP's guide_ring before its C kernel)."""
    H, W = g.shape[:2]
    r = np.repeat(rows, cols.size)
    c = np.tile(cols, rows.size)
    offs = [(a, b) for a in range(-1, block + 1) for b in range(-1, block + 1)
            if not (0 <= a < block and 0 <= b < block)]
    ring = np.empty((len(offs), 3, r.size), np.float32)
    for k, (a, b) in enumerate(offs):
        px = g[np.clip(r + a, 0, H - 1), np.clip(c + b, 0, W - 1)]
        ring[k] = (px.astype(np.float64) * inv).T
    return ring


def guided_pass(zr, zi, v, nin, gr, gi, gv, col, use, R, C, axis, px, reach, radius_px,
                inv2h2, inv2hc2):
    """One 1-D pass of the cross-bilateral mean: mean (F, N) x 2, variance (N,), n_eff (N,).

    col (3, N), or (4, N) whose fourth row phi is each measurement's fixed-pattern share of
    its variance: the phasor term is then the pair's Mahalanobis distance under a temporal
    diagonal S = gn + gm - A and a fixed part A 1 1^T per I and Q block, A = gn phi_n +
    gm phi_m: (chi - A q / (S + F A)) / S - 2F, q = |sum_f d_f|^2 (csrc/tof_guided.c,
    tofg_xp)."""
    F = zr.shape[0]
    col = np.asarray(col)
    phi = np.asarray(col[3], np.float64).reshape(R, C) if col.shape[0] == 4 else None
    col = col[:3]
    shape = (R, C)
    z = (np.asarray(zr, np.float64) + 1j * np.asarray(zi, np.float64)).reshape(F, R, C)
    g = (np.asarray(gr, np.float64) + 1j * np.asarray(gi, np.float64)).reshape(F, R, C)
    vv, gvv = (np.asarray(a, np.float64).reshape(shape) for a in (v, gv))
    cc = np.asarray(col, np.float64).reshape(3, R, C)
    ok = np.asarray(use, bool).reshape(shape)
    if nin is not None:
        nn = np.asarray(nin, np.float64).reshape(shape)
        ok = ok & (nn > 0)
    num = np.zeros((F, R, C), complex)
    den, w2v, w2n = (np.zeros(shape) for _ in range(3))
    n = C if axis == 1 else R
    for a in range(-reach, reach + 1):
        lo, hi = max(0, -a), min(n, n - a)
        if hi <= lo:
            continue
        near = np.abs(px[lo + a:hi + a] - px[lo:hi]) <= radius_px
        if axis == 1:
            tgt, src = (slice(None), slice(lo, hi)), (slice(None), slice(lo + a, hi + a))
            near = near[None, :]
        else:
            tgt, src = (slice(lo, hi), slice(None)), (slice(lo + a, hi + a), slice(None))
            near = near[:, None]
        d = g[(slice(None),) + src] - g[(slice(None),) + tgt]
        chi = (np.abs(d) ** 2).sum(axis=0)
        if phi is None:
            xp = chi / (gvv[src] + gvv[tgt]) - 2.0 * F
        else:
            A = gvv[src] * phi[src] + gvv[tgt] * phi[tgt]
            S = gvv[src] + gvv[tgt] - A
            q = np.abs(d.sum(axis=0)) ** 2
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                xp = (chi - q * (A / (S + F * A))) / S - 2.0 * F
            xp = np.where(np.isnan(xp), 0.0, xp)        # as the kernel's clamp takes NaN
        dc = cc[(slice(None),) + src] - cc[(slice(None),) + tgt]
        xc = (dc * dc).sum(axis=0) - 3.0
        x = np.maximum(xp, 0.0) * inv2h2 + np.maximum(xc, 0.0) * inv2hc2
        w = np.where(x < 36.0, np.exp(-np.minimum(x, 36.0)), 0.0) * ok[src] * near
        num[(slice(None),) + tgt] += w * z[(slice(None),) + src]
        den[tgt] += w
        w2v[tgt] += w * w * vv[src]
        w2n[tgt] += w * w / (np.where(nn[src] > 0, nn[src], 1.0) if nin is not None else 1.0)
    good = den > 0
    inv = np.divide(1.0, den, out=np.zeros(shape), where=good)
    mean = (num * inv).reshape(F, -1)
    var = np.where(good, w2v * inv * inv, np.inf).reshape(-1)
    if nin is None:
        neff = np.divide(den * den, w2n, out=np.zeros(shape), where=good & (w2n > 0))
    else:
        neff = np.divide(1.0, w2n * inv * inv, out=np.zeros(shape), where=good & (w2n > 0))
    return mean.real, mean.imag, var, neff.reshape(-1)


def guided_denoise(zr, zi, v, col, use, R, C, rows, cols, reach_r, reach_c, radius_px,
                   inv2h2, inv2hc2):
    """The guided denoise (rgbz_tofg_denoise): a row pass guided by the raw phasors, a column
    pass of it guided by itself, a row pass of the raw phasors guided by that, a column pass
    of it guided by the same; the last pass's outputs."""
    def run(data, nin, guide, axis):
        px, reach = (cols, reach_c) if axis == 1 else (rows, reach_r)
        mr, mi, var, neff = guided_pass(*data, nin, *guide, col, use, R, C, axis, px, reach,
                                        radius_px, inv2h2, inv2hc2)
        return (mr, mi, var), neff

    raw = (zr, zi, v)
    rows1, n1 = run(raw, None, raw, 1)
    guide1, _ = run(rows1, n1, rows1, 0)
    rows2, n2 = run(raw, None, guide1, 1)
    (mr, mi, var), neff = run(rows2, n2, guide1, 0)
    return mr, mi, var, neff


def fixed_pattern(phase, amp, offset, count, sigma_scale, black, var_dsnu, fix_dsnu, prnu,
                  shared, pre=1.0):
    """(corr, ind): the variance (m^2) of the depth that the taps' fixed pattern gives (a
    gain 1 + prnu z_k and an offset sqrt(fix_dsnu) z'_k per tap, the same at every
    frequency), through each phase's derivative with respect to each tap, and what the
    independent per-frequency sum of the validity holds of it (var_dsnu + prnu^2 T^2 per
    tap; ``shared``: the mean over the frequencies, the guided chain's one variance)."""
    ph, a = np.asarray(phase, np.float64), np.asarray(amp, np.float64)
    t = np.maximum(np.asarray(offset, np.float64) - black, 0.0) * pre   # charge collected
    ssc = np.asarray(sigma_scale, np.float64)[:, None]
    with np.errstate(divide="ignore", invalid="ignore"):
        z = 2.0 * a * np.exp(1j * ph)                      # I + iQ
        # taps above black: A0, A2 = T +- I/2, A3, A1 = T +- Q/2
        taps = (t + z.real / 2, t - z.imag / 2, t - z.real / 2, t + z.imag / 2)
        # d phase_f / d A_k: phase = atan2(Q, I), I = A0 - A2, Q = A3 - A1
        dI, dQ = -z.imag / np.abs(z) ** 2, z.real / np.abs(z) ** 2
        dphase = (dI, -dQ, -dI, dQ)
        w = np.sqrt(ssc)                                   # d depth / d phase_f
        corr = sum(prnu ** 2 * ((w * dphase[k] * taps[k]).sum(axis=0)) ** 2
                   + fix_dsnu * ((w * dphase[k]).sum(axis=0)) ** 2 for k in range(4))
        fixed = var_dsnu + prnu ** 2 * t * t
        if shared:
            fixed = np.broadcast_to(fixed.mean(axis=0), fixed.shape)
        ind = (ssc * 2.0 * fixed / (4.0 * a * a)).sum(axis=0)
    m = np.ones(ph.shape[1]) if count is None else np.maximum(np.asarray(count, float), 1.0)
    return corr / m, ind / m


def fixed_pattern_delta(*args):
    """rgbz_tof_fixed_pattern: corr - ind, 0 where it is not finite."""
    corr, ind = fixed_pattern(*args)
    d = corr - ind
    return np.where(np.isfinite(d), d, 0.0)


def guided_validity(amp, var, depth, residual, sat, sigma_scale, refl_coef, min_snr,
                    min_amplitude, max_sigma, max_residual, min_reflectance, max_range,
                    delta=None, max_reflectance=np.inf):
    """snr, sigma, reflectance and the bits 1, 2, 4, 16 of every measurement; ``delta``: the
    fixed-pattern correction of sigma^2 where no phase variance reached the cap."""
    amp = np.asarray(amp, np.float64)
    var = np.asarray(var, np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        ph = var[None] / (4.0 * amp * amp)
        capped = np.any(~(ph < np.pi * np.pi / 3.0), axis=0)
        ph = np.where(ph < np.pi * np.pi / 3.0, ph, np.pi * np.pi / 3.0)
        s2 = (np.asarray(sigma_scale)[:, None] * ph).sum(axis=0)
        if delta is not None:
            sd2 = s2 + delta
            s2 = np.where(~capped & (sd2 > 0), sd2, s2)
        sigma = np.sqrt(s2)
        snr = (2.0 * amp / np.sqrt(var)[None]).min(axis=0)
    d = np.asarray(depth)
    dd = np.where(d > 0, d, 1.0)
    refl = np.where(d > 0, (amp * np.asarray(refl_coef)[:, None]).mean(axis=0) * dd * dd, 0.0)
    flags = np.where(np.asarray(sat, bool), 1, 0)
    low = (snr < min_snr) | np.any(amp < min_amplitude, axis=0)
    if max_sigma is not None:
        low |= ~(sigma <= max_sigma)
    flags |= np.where(low, 2, 0)
    flags |= np.where(np.asarray(residual) > max_residual, 4, 0)
    out = ((d < 0) | (d > max_range - 5.0 * sigma) | (refl < min_reflectance)
           | (refl > max_reflectance))
    flags |= np.where(out, 16, 0)
    return snr, sigma, refl, flags.astype(np.uint8)


def flying_pixels(depth, sigma, sites, *, block=1, step=0.05, usable=None, k=2.0):
    """rgbz_fast.tof.flying_pixels (csrc/tof_guided.c, rgbz_tofg_flying_candidates) in whole-grid
    NumPy operations: the grid padded by one cell, each direction's second differences as
    shifted slices, the pair across every hit marked."""
    d = np.asarray(depth, np.float64)
    s = np.asarray(sigma, np.float64)
    grid = sites if isinstance(sites, SiteGrid) else SiteGrid(sites, block)
    ok = np.ones(grid.n, bool) if usable is None else np.asarray(usable, bool)
    R, C = grid.shape
    dg = np.zeros((R + 2, C + 2))
    vg = np.zeros((R + 2, C + 2))
    og = np.zeros((R + 2, C + 2), bool)
    inner = (slice(1, R + 1), slice(1, C + 1))
    good = ok & np.isfinite(s) & np.isfinite(d)
    with np.errstate(over="ignore", invalid="ignore"):
        dg[inner] = grid.to_grid(np.where(good, d, 0.0))
        vg[inner] = grid.to_grid(np.where(good, s * s, 0.0))
    og[inner] = grid.to_grid(good, False) & grid.present
    flag = np.zeros((R + 2, C + 2), bool)
    k2 = k * k
    step2 = step * step

    def at(a, b):
        return slice(1 + a, R + 1 + a), slice(1 + b, C + 1 + b)

    with np.errstate(over="ignore", invalid="ignore"):
        for e in ((0, 1), (1, 0), (1, 1), (1, -1)):
            lo, hi = at(-e[0], -e[1]), at(*e)
            down = dg[inner] - dg[lo]
            up = dg[hi] - dg[inner]
            jump = up - down
            jump *= jump
            noise = vg[hi] + vg[lo]
            noise += 4.0 * vg[inner]
            noise *= k2
            np.maximum(noise, step2, out=noise)
            hit = og[inner] & og[lo] & og[hi] & (jump > noise)
            toward_hi = np.abs(up) >= np.abs(down)
            flag[inner] |= hit
            flag[hi] |= hit & toward_hi
            flag[lo] |= hit & ~toward_hi
    return grid.from_grid(flag[inner] & og[inner])


def guided_flying(depth, sigma, usable, col, cells, ring, R, C, step, k, contrast, side,
                  unflag):
    """Bits 8 (flying) and 32 (resolved) and the depths (resolved ones replaced), with plain
    loops over the cells and the ring pixels in the kernel's order."""
    d = np.asarray(depth, np.float64)
    s = np.asarray(sigma, np.float64)
    u = np.asarray(usable, bool)
    rows, cols = np.divmod(np.arange(R * C), C)
    cand = flying_pixels(d, s, SiteGrid((rows * 2, cols * 2), 1), step=step, usable=u, k=k)
    cc = np.asarray(col, np.float64)
    cl = cc[None] if cells is None else np.asarray(cells, np.float64)
    flags = np.zeros(R * C, np.uint8)
    out = d.copy()
    for m in np.nonzero(cand)[0]:
        r, c = divmod(int(m), C)
        nb = [(r + a) * C + c + b for a in (-1, 0, 1) for b in (-1, 0, 1)
              if (a or b) and 0 <= r + a < R and 0 <= c + b < C and u[(r + a) * C + c + b]]
        vals = [d[n] for n in nb]
        lo, hi = min(vals + [d[m]]), max(vals + [d[m]])
        mid = 0.5 * (lo + hi)
        sides = [[n for n in nb if not d[n] > mid], [n for n in nb if d[n] > mid]]
        dside, cside = [], []
        for grp in sides:
            inv = 1.0 / len(grp) if grp else 0.0
            acc = 0.0
            for n in grp:
                acc += d[n]
            dside.append(acc * inv)
            ch = [0.0, 0.0, 0.0]
            for n in grp:
                for i in range(3):
                    ch[i] += float(np.float32(cc[i, n]))
            cside.append([x * inv for x in ch])
        tol = max(2.5 * s[m], 0.01)
        near = [bool(sides[i]) and abs(d[m] - dside[i]) <= tol for i in (0, 1)]
        axis = [cside[1][i] - cside[0][i] for i in range(3)]
        con = sum(a * a for a in axis)
        sig = bool(sides[0]) and bool(sides[1]) and con > contrast
        all0 = all1 = True
        for kk in range(cl.shape[0]):
            t = sum((float(np.float32(cl[kk, i, m])) - cside[0][i]) * axis[i] for i in range(3))
            t = t / con if con > 0 else 0.5
            all0 &= t < side
            all1 &= t > 1.0 - side
        pure = sig and ((near[0] and all0) or (near[1] and all1))
        if pure and unflag and cl.shape[0] > 1:
            # every pixel bordering the Z pixel nearer the side's colour than the other's
            s1 = not (near[0] and all0)
            ring_ok = True
            for kk in range(0 if ring is None else ring.shape[0]):
                t = sum((float(np.float32(ring[kk, i, m])) - cside[0][i]) * axis[i]
                        for i in range(3)) / con
                ring_ok &= t > 0.5 if s1 else t < 0.5
            if ring_ok:
                continue
            flags[m] |= 8
            continue
        if sig and (all0 or all1) and not near[0] and not near[1]:
            flags[m] |= 32
            out[m] = dside[0] if all0 else dside[1]
            continue
        flags[m] |= 8
    return flags, out


def guided_agree(depth, low, lone, sigma, R, C, tol_k, tol_min):
    """rgbz_tofg_agree (plain loops, on copies): the candidates whose low depth lies within
    max(tol_k sigma, tol_min) of a usable 8-neighbour's (not lone, finite) move into depth."""
    d0 = np.asarray(depth, np.float64).reshape(R, C)
    lw = np.asarray(low, np.float64).reshape(R, C)
    ln = np.asarray(lone).reshape(R, C).astype(bool)
    sg = np.asarray(sigma, np.float64).reshape(R, C)
    d, lo = d0.copy(), lw.copy()
    for r in range(R):
        for c in range(C):
            if not ln[r, c] or np.isnan(lw[r, c]):
                continue
            t = tol_k * float(sg[r, c])                    # 0 * inf: NaN, no warning
            tol = t if t > tol_min else tol_min            # NaN: tol_min, as the kernel
            for i in range(max(r - 1, 0), min(r + 1, R - 1) + 1):
                for j in range(max(c - 1, 0), min(c + 1, C - 1) + 1):
                    if (i, j) != (r, c) and not ln[i, j] and abs(d0[i, j] - lw[r, c]) <= tol:
                        d[r, c], lo[r, c] = lw[r, c], np.nan
    return d.ravel(), lo.ravel()


def guided_upsample(guide, scale, cscale, depth, sigma, col, R, C, rc, cc, spacing, reach,
                    inv2s2, inv2hc2, tol_k, tol_min, own=None, own_k=2.0, ambiguity=1.0,
                    gap=0.0):
    """A depth and a confidence at every pixel (plain loops; csrc/tof_guided.c's rule)."""
    g = np.asarray(guide, np.float64)
    H, W = g.shape[:2]
    d0 = np.asarray(depth, np.float64)
    s0 = np.asarray(sigma, np.float64)
    cm = np.asarray(col, np.float64)
    prior0 = np.isfinite(d0).astype(np.float64)

    def bracket(ctr, v):
        i = int(np.searchsorted(ctr, v, side="right"))
        if i == 0:
            return 0, 0.0
        if i == ctr.size:
            return ctr.size - 1, 0.0
        return i - 1, (v - ctr[i - 1]) / (ctr[i] - ctr[i - 1])

    def mode(pc, ms, ws, d, s, prior, own_d=np.nan, otol=0.0, amb=None):
        w = []
        for m, wsp in zip(ms, ws):
            pr = prior[m] * wsp
            if not pr > 0 or (np.isfinite(own_d) and not abs(d[m] - own_d) <= otol):
                w.append(0.0)
                continue
            chi = ((pc - cm[:, m]) ** 2).sum() - 3.0
            x = max(chi, 0.0) * inv2hc2
            wc = np.exp(-x) if x < 36.0 else 0.0
            w.append(pr * max(wc, 1e-20))
        if not any(v > 0 for v in w):
            return None
        kb = int(np.argmax(w))
        if np.isnan(d[ms[kb]]):                       # a node that vetoes
            return None
        tol = max(tol_k * s[ms[kb]], tol_min)
        used = [(wv, d[m]) for wv, m in zip(w, ms) if wv > 0 and abs(d[m] - d[ms[kb]]) <= tol]
        den = sum(wv for wv, _ in used)
        off = max(gap, tol)
        other = sum(wv for wv, m in zip(w, ms) if wv > 0 and not abs(d[m] - d[ms[kb]]) <= off)
        if amb is not None and other > amb * (den + other):
            return None
        return sum(wv * dv for wv, dv in used) / den, den

    # the nodes without a usable measurement, filled from those within reach
    d, s, prior = d0.copy(), s0.copy(), prior0.copy()
    for r in range(R):
        for c in range(C):
            m = r * C + c
            if prior0[m] > 0:
                continue
            own_d = np.nan if own is None else own[m]
            lv = 1
            while lv <= reach:
                ms, ws = [], []
                for i in range(max(r - lv, 0), min(r + lv, R - 1) + 1):
                    for j in range(max(c - lv, 0), min(c + lv, C - 1) + 1):
                        ms.append(i * C + j)
                        dist = ((rc[i] - rc[r]) ** 2 + (cc[j] - cc[c]) ** 2) / spacing ** 2
                        ws.append(np.exp(-dist * inv2s2))
                got = mode(cm[:, m], ms, ws, d0, s0, prior0, own_d, own_k * s0[m])
                if got is not None:
                    d[m] = got[0]
                    usable = [k for k in ms if prior0[k] > 0]
                    s[m] = s0[min(usable, key=lambda k: abs(d0[k] - got[0]))]
                    prior[m] = 0.25 * got[1] / sum(ws)
                    break
                lv *= 2
            if lv > reach and np.isfinite(own_d):
                d[m], prior[m] = np.nan, 1.0          # no neighbour agrees: a veto
    out = np.full((H, W), np.nan)
    conf = np.zeros((H, W))
    for y in range(H):
        r, fy = bracket(rc, y)
        for x in range(W):
            c, fx = bracket(cc, x)
            pc = g[y, x] * scale * np.asarray(cscale)
            r1, c1 = min(r + 1, R - 1), min(c + 1, C - 1)
            ms = [r * C + c, r * C + c1, r1 * C + c, r1 * C + c1]
            ws = [(1 - fy) * (1 - fx), (1 - fy) * fx, fy * (1 - fx), fy * fx]
            got = mode(pc, ms, ws, d, s, prior, amb=ambiguity)
            if got is not None:
                out[y, x], conf[y, x] = got
    return out, conf


def guided_usable(flags, depth, sigma, present, bad):
    """The measurements that may enter the flying-pixel test (rgbz_tofg_usable): none of the
    bits ``bad`` in flags, depth and sigma finite, present (None: every one)."""
    u = ((flags & bad) == 0) & np.isfinite(depth) & np.isfinite(sigma)
    if present is not None:
        u &= present.astype(bool)
    return u.astype(np.uint8)


# -- the unguided chain's validity (csrc/tof_filter.c, rgbz_tof_validity) ----------------------
# The NumPy code the kernel replaced, as it was (rgbz_fast.tof._validity before 2026-11-26):
# _depth_sigma, _implied_reflectance, assign_flags, and unguided_validity, which runs them as
# the chain did.

FLAG_SATURATED, FLAG_LOW_SIGNAL, FLAG_INCONSISTENT, FLAG_FLYING, FLAG_OUT_OF_RANGE = 1, 2, 4, 8, 16


def _depth_sigma(amp, var, frequencies, delta=None):
    """Depth noise (m) of the f^2-weighted mean of the per-frequency distances.

    ``sigma^2 = sum_f (w_f c / (4 pi f))^2 var_f / |I + iQ|_f^2 / (sum w)^2``, the phase
    variance ``var / |I + iQ|^2`` capped at ``pi^2 / 3``, that of a phase that is all noise
    (uniform on the circle). In place on one (F, n) temporary: it runs on every frame.
    """
    f = np.asarray(frequencies, np.float64)
    w = f * f
    scale = (w * SPEED_OF_LIGHT / (4 * np.pi * f) / w.sum()) ** 2
    t = np.multiply(amp, amp)
    t *= 4.0
    with np.errstate(divide="ignore", invalid="ignore"):
        np.divide(var, t, out=t)                          # phase variance; inf / nan at 0
    capped = np.any(~(t < np.pi * np.pi / 3.0), axis=0)
    np.fmin(t, np.pi * np.pi / 3.0, out=t)               # fmin: a NaN takes the cap
    t *= scale[:, None]
    s2 = t.sum(axis=0)
    if delta is not None:         # the fixed-pattern correction (added 2026-11-27)
        sd2 = s2 + delta
        s2 = np.where(~capped & (sd2 > 0), sd2, s2)
    return np.sqrt(s2)


def _implied_reflectance(depth, amp, sensor, block):
    """NIR reflectance that the amplitude implies at ``depth`` (the sensor's radiometry)."""
    ok = depth > 0
    d = np.where(ok, depth, 1.0)
    s1 = sensor.active_electrons(d)
    contrast = sensor.contrasts.reshape(-1, 1) * float(np.mean(sensor.tap_contrast))
    model = sensor.system_gain * 0.25 * contrast * (s1 * block * block)[None]
    rho = (amp / model).mean(axis=0)
    return np.where(ok, rho, 0.0)


def assign_flags(depth, sigma, snr, amp, residual, reflectance, saturated, grid, *,
                 min_snr, min_amplitude, max_sigma, max_residual, flying_step,
                 min_reflectance, max_range, max_reflectance=np.inf):
    """The flag bits (uint8, shape (n,)) of every measurement (:func:`~rgbz_fast.tof.tof_depth`).

    ``grid`` is the :class:`SiteGrid` of the measurements, or a callable that makes it (the
    flying-pixel test needs it; the other tests do not).
    """
    n = depth.shape[0]
    flags = np.zeros(n, np.uint8)
    flags[saturated] |= FLAG_SATURATED
    low = (snr < min_snr) | np.any(amp < min_amplitude, axis=0)
    if max_sigma is not None:
        low |= ~(sigma <= max_sigma)
    flags[low] |= FLAG_LOW_SIGNAL
    flags[residual > max_residual] |= FLAG_INCONSISTENT
    if flying_step is not None:
        usable = (flags & (FLAG_SATURATED | FLAG_LOW_SIGNAL)) == 0
        if not isinstance(grid, SiteGrid):
            grid = grid()
        flags[flying_pixels(depth, sigma, grid, block=grid.block, step=flying_step,
                            usable=usable)] |= FLAG_FLYING
    # a guard of 5 sigma below the end of the range: a surface just beyond it reads either
    # ~0 m (the reflectance test) or, through the noise, just below the end
    # and a reflectance no surface has at that depth: a wrong, farther alias
    out = ((depth < 0) | (depth > max_range - 5.0 * sigma) | (reflectance < min_reflectance)
           | (reflectance > max_reflectance))
    flags[out] |= FLAG_OUT_OF_RANGE
    return flags


def unguided_validity(depth, residual, amp, var, saturated, sensor, block, frequencies, sites,
                      *, min_snr, min_amplitude, max_sigma, max_residual, flying_step,
                      min_reflectance, max_range, delta=None, max_reflectance=np.inf):
    """snr, sigma, reflectance, flags as the unguided chain computed them in NumPy (sites: the
    measurements' sites or their SiteGrid; delta: the fixed-pattern correction of sigma^2)."""
    snr = (2.0 * amp / np.sqrt(var)).min(axis=0)
    sigma = _depth_sigma(amp, var, frequencies, delta)
    reflectance = _implied_reflectance(depth, amp, sensor, block)
    grid = sites if isinstance(sites, SiteGrid) else SiteGrid(sites, block)
    flags = assign_flags(depth, sigma, snr, amp, residual, reflectance, saturated, grid,
                         min_snr=min_snr,
                         min_amplitude=min_amplitude, max_sigma=max_sigma,
                         max_residual=max_residual, flying_step=flying_step,
                         min_reflectance=min_reflectance, max_range=max_range,
                         max_reflectance=max_reflectance)
    return snr, sigma, reflectance, flags
