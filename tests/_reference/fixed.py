"""Slow NumPy reference of the fixed-point reconstruction (``precision="fixed"``).

Written from the datapath of docs/guide/hardware.md ("The fixed-point datapath"),
independently of the C streaming model (csrc/hw_recon.c) and of the plans of
``rgbz_fast.reconstruction._plans``: like :mod:`_reference.reconstruction` it
gathers the 5x5 window of every Z site (values and channel codes, borders moved
by whole periods) and finds the candidates, the valid differences and their
groups from the codes. Every quantity is an int64 array over the sites; the
tables are built here from their formulas. Integer sums do not depend on their
order, so nothing here follows the order of a plan: the tests check that the C
model gives the same integers bit for bit.

``reference_fixed(..., probe=dict)`` also records the largest magnitude each
named register reaches, so that the tests can hold the widths the library
declares (:func:`rgbz_fast.reconstruction._fixed.register_widths`) against them.
"""

from __future__ import annotations

import math

import numpy as np

from .reconstruction import (DX, DY, EDI_CENTRAL_GROUPS, EDI_CENTRAL_PAIRS, EDI_LINE_CROSS,
                             EDI_LINE_GROUPS, EDI_LINE_PAIRS, OFF, ORI, SG_COVER, SG_GROUPS,
                             SG_PAIRS, Z, gather, pair_differences)

__all__ = ["reference_fixed", "recip_table", "exp_table", "alpha_constants"]

CENTRE = 12
LN2 = math.log(2.0)


# -- tables and constants --------------------------------------------------------------

def recip_table(cfg):
    """1/(1+f) for f in [0, 1), recip_bits bits: midpoints of 2^k entries ("table"), or the
    2^k + 1 end points ("pwl", the first one 2^recip_bits)."""
    T, W = cfg.recip_table_size, cfg.recip_bits
    if cfg.recip == "table":
        i = np.arange(T, dtype=np.float64)
        v = np.floor(2.0 ** W / (1.0 + (i + 0.5) / T) + 0.5)
        return np.minimum(v, 2.0 ** W - 1).astype(np.int64)
    j = np.arange(T + 1, dtype=np.float64)
    return np.floor(2.0 ** W / (1.0 + j / T) + 0.5).astype(np.int64)


def exp_table(cfg):
    """2^-u for u in [0, 1), exp_bits bits: midpoints ("table") or end points ("pwl")."""
    T, W = cfg.exp_table_size, cfg.exp_bits
    if cfg.exp == "table":
        i = np.arange(T, dtype=np.float64)
        v = np.floor(2.0 ** W * np.exp2(-(i + 0.5) / T) + 0.5)
        return np.minimum(v, 2.0 ** W - 1).astype(np.int64)
    j = np.arange(T + 1, dtype=np.float64)
    return np.floor(2.0 ** W * np.exp2(-j / T) + 0.5).astype(np.int64)


def alpha_constants(cfg):
    """alpha = exp(-d^2/2) = 2^-u, u = d^2 / (2 ln 2), as (mantissa, exponent) per kernel
    position: exponent floor(u), mantissa round(2^alpha_bits 2^-(u - floor u))."""
    d2 = (DY ** 2 + DX ** 2).astype(np.float64)
    u = d2 / (2.0 * LN2)
    e = np.floor(u)
    m = np.floor(2.0 ** cfg.alpha_bits * np.exp2(-(u - e)) + 0.5)
    m = np.minimum(m, 2.0 ** cfg.alpha_bits - 1)
    return m.astype(np.int64), e.astype(np.int64)


def _bitlen(x):
    """floor(log2 x) + 1 of positive int64 values (exact, no float rounding)."""
    x = np.asarray(x, np.int64)
    p = np.zeros(x.shape, np.int64)
    for s in (32, 16, 8, 4, 2, 1):
        big = (x >> (p + s)) > 0
        p = np.where(big, p + s, p)
    return p + (x > 0)


def _shift(x, s):
    """x * 2^s for per-element s of either sign (floor for right shifts)."""
    s = np.asarray(s, np.int64)
    left = np.left_shift(x, np.clip(s, 0, 62))
    right = np.right_shift(x, np.clip(-s, 0, 62))
    return np.where(s >= 0, left, right)


def _rec(probe, name, values):
    if probe is not None and np.size(values):
        probe[name] = max(probe.get(name, 0), int(np.max(np.abs(values))))


# -- the two table units -------------------------------------------------------------------

def recip(x, cfg, RT, probe=None, name="recip_in"):
    """1/x ~ m 2^-(p + recip_bits), p = floor(log2 x), for int64 x >= 1."""
    _rec(probe, name, x)
    p = _bitlen(x) - 1
    Tb = cfg.recip_index_bits
    Fi = cfg.recip_bits if cfg.recip == "pwl" else 0
    F = Tb + Fi
    xf = _shift(x, F - p) - (np.int64(1) << F)
    i = xf >> Fi
    if cfg.recip == "table":
        return RT[i], p
    fr = xf & ((np.int64(1) << Fi) - 1)
    return RT[i] - (((RT[i] - RT[i + 1]) * fr) >> Fi), p


def exp2neg(y, cfg, ET):
    """2^-y ~ m 2^-(exp_bits + e), y with ratio_bits fractional bits: e = floor(y)."""
    Ft, Te = cfg.ratio_bits, cfg.exp_index_bits
    yi = y >> Ft
    yf = y & ((np.int64(1) << Ft) - 1)
    if Ft >= Te:
        Fi = Ft - Te
        i = yf >> Fi
        fr = yf & ((np.int64(1) << Fi) - 1)
    else:
        Fi = 0
        i = yf << (Te - Ft)
        fr = np.zeros_like(yf)
    if cfg.exp == "table":
        return ET[i], yi
    return ET[i] - (((ET[i] - ET[i + 1]) * fr) >> Fi), yi


# -- eq. 7 for one family of groups ---------------------------------------------------------

def _lcm_rows(counts, known):
    out = np.ones(counts.shape[0], np.int64)
    for g in range(counts.shape[1]):
        out = np.where(known[:, g], np.lcm(out, np.maximum(counts[:, g], 1)), out)
    return out


def family_gammas(vals, codes, pairs, groups, cfg, sigma_floor, sigma_rel, RT, ET, cross=None,
                  probe=None):
    """(m, e, known) of the gamma of every group of a family, (n, G) each.

    Group sums of absolute differences (valid pairs only), scaled to L times their mean
    (L the lcm of the known groups' counts); with n the number of known groups,
    n sigma = max(n min, n floor, rel * sum) in sigma_bits fractional bits (rel * mean
    without a division), r c = n G / (n sigma) sqrt(log2(e)/2) through the reciprocal
    table, y = (r c)^2 saturated, gamma = 2^-y through the exponential table.
    """
    d, valid = pair_differences(vals, codes, pairs, cross=cross)
    d = d.astype(np.int64)
    _rec(probe, "diff", d)
    n = vals.shape[0]
    ng = len(groups)
    cnt = np.stack([valid[:, g].sum(axis=1) for g in groups], axis=1).astype(np.int64)
    sums = np.stack([d[:, g].sum(axis=1) for g in groups], axis=1)
    _rec(probe, "group_sum", sums)
    known = cnt > 0
    nk = known.sum(axis=1)
    L = _lcm_rows(cnt, known)
    Gs = np.where(known, sums * (L[:, None] // np.maximum(cnt, 1)), 0)
    _rec(probe, "group_scaled", Gs)
    sR, Wr, Ft = cfg.sigma_bits, cfg.recip_bits, cfg.ratio_bits
    big = np.int64(1) << 62
    gmin = np.where(known, Gs, big).min(axis=1)
    gsum = Gs.sum(axis=1)
    _rec(probe, "group_total", gsum)
    # n sigma = max(n min, n floor, rel * sum), n the known groups: the mean without a division
    fq = np.maximum(1, np.floor(sigma_floor * nk * L.astype(np.float64) * 2.0 ** sR + 0.5)
                    ).astype(np.int64)
    sigma = np.maximum((np.where(nk > 0, gmin, 0) * nk) << sR, fq)
    if sigma_rel > 0:
        R = int(np.floor(sigma_rel * 2.0 ** sR + 0.5))
        sigma = np.maximum(sigma, R * gsum)
    _rec(probe, "sigma", sigma)
    ms, ps = recip(sigma, cfg, RT, probe, "sigma")
    cq = int(math.floor(math.sqrt(0.5 / LN2) * 2.0 ** Wr + 0.5))
    mc = (ms * cq) >> Wr
    ymax = (np.int64(1) << (cfg.exp_range_bits + Ft)) - 1
    tcap = math.isqrt(int(ymax) << Ft) + 1
    sh = (ps + Wr - sR - Ft)[:, None]
    X = Gs * (nk * mc)[:, None]
    _rec(probe, "ratio_product", X)
    k = np.clip(-sh, 0, 62)
    t_left = np.where(X > (tcap >> k), tcap, X << k)
    t = np.where(sh >= 0, np.minimum(X >> np.clip(sh, 0, 62), tcap), t_left)
    _rec(probe, "ratio", t)
    y = np.minimum((t * t) >> Ft, ymax)
    m, e = exp2neg(y, cfg, ET)
    m = np.where(known, m, 0)
    e = np.where(known, e, 0)
    none = nk == 0
    m[none] = (1 << cfg.exp_bits) - 1
    e[none] = 0
    return m, e, known


# -- the site ---------------------------------------------------------------------------------

def _mean_round(c_sum, nc, bit_depth):
    """floor(S / n + 1/2) by a constant multiplier (exact): X = 2S + n, d = 2n."""
    nc = np.asarray(nc, np.int64)
    X = 2 * c_sum + nc
    top = 2 * nc * ((1 << bit_depth) - 1) + nc
    N = _bitlen(top)
    d = 2 * nc
    s = N + _bitlen(d - 1)
    M = (np.int64(1) << s) // d + 1
    return (X * M) >> s


def _sg_factor(mg, eg, known, cfg, cand, probe=None):
    """Eq. 19: per candidate position, the sum of the gammas of its covering (known)
    semi-gradients, aligned to the largest; times lcm / n_cover where the candidates of a
    site have different cover counts. Returns (m_sv, e_sv, K) with K = max n_cover * mult."""
    n = mg.shape[0]
    cover = SG_COVER[None, :, :] & known[:, None, :]                  # (n, 25, 8)
    none = ~cover.any(axis=2)
    cover = np.where(none[:, :, None], known[:, None, :], cover)
    ncov = cover.sum(axis=2).astype(np.int64)                          # (n, 25)
    big = np.int64(1) << 40
    emin = np.where(cover, eg[:, None, :], big).min(axis=2)
    shift = np.clip(eg[:, None, :] - emin[:, :, None], 0, 62)
    msum = np.where(cover, mg[:, None, :] >> shift, 0).sum(axis=2)
    emin = np.where(ncov > 0, emin, 0)
    cc = np.where(cand, ncov, 0)
    lo = np.where(cand, ncov, 99).min(axis=1)
    hi = cc.max(axis=1)
    scaled = lo != hi
    Lc = np.ones(n, np.int64)
    for k in range(25):
        Lc = np.where(cand[:, k] & (ncov[:, k] > 0), np.lcm(Lc, np.maximum(ncov[:, k], 1)), Lc)
    mult = np.where(scaled[:, None], Lc[:, None] // np.maximum(ncov, 1), 1)
    K = np.where(cand, ncov * mult, 0).max(axis=1)
    msv = msum * mult
    _rec(probe, "sg_sum", np.where(cand, msv, 0))
    return msv, emin, K


def _site_values(vals, codes, target, method, cfg, bit_depth, sigma_floor, sigma_rel, sg_mode,
                 RT, ET, probe=None):
    n = vals.shape[0]
    v = vals.astype(np.int64)
    cand = (codes == target[:, None]) & (codes != Z)
    cand[:, CENTRE] = False
    nc = cand.sum(axis=1).astype(np.int64)
    first = np.argmax(cand, axis=1)
    c0 = v[np.arange(n), first]
    csum = np.where(cand, v, 0).sum(axis=1)
    _rec(probe, "cand_sum", csum)
    mean = _mean_round(csum, nc, bit_depth)
    if method == "bilinear":
        return mean
    diagonal = (DY != 0) & (DX != 0)
    use_sg = method == "sg"
    pure = np.zeros(n, bool)
    if use_sg:
        pure = {"pure": np.ones(n, bool), "combined": np.zeros(n, bool),
                "auto": ~np.any(cand & ~diagonal[None, :], axis=1)}[sg_mode]
    Ww, Wg, Wr, Wa = cfg.weight_bits, cfg.exp_bits, cfg.recip_bits, cfg.alpha_bits
    mixed = ~pure                      # the sites whose weights hold alpha * beta
    w = E = None
    if mixed.any():
        sub = probe if mixed.all() else None     # a probe records the sites that use it
        # alpha * beta (eqs. 2-4)
        S = 1 + (np.abs(v[:, :, None] - v[:, None, :]) * (cand[:, :, None] & cand[:, None, :])
                 ).sum(axis=2)
        _rec(sub, "beta_sum", np.where(cand, S, 0))
        mb, pb = recip(np.where(cand, S, 1), cfg, RT)
        ma, ea = alpha_constants(cfg)
        w = _shift(ma[None, :] * mb, -(Wa + Wr - Ww))
        E = ea[None, :] + pb
        if method != "bi":
            # the gradient factor gamma(ori) (eqs. 6-11)
            pairs, groups, cross = ((EDI_CENTRAL_PAIRS, EDI_CENTRAL_GROUPS, None)
                                    if method == "edi_central" else
                                    (EDI_LINE_PAIRS, EDI_LINE_GROUPS, EDI_LINE_CROSS))
            gm, ge, _ = family_gammas(vals, codes, pairs, groups, cfg, sigma_floor, sigma_rel,
                                      RT, ET, cross=cross, probe=sub)
            o = np.where(ORI >= 0, ORI, 0)
            w = (w * gm[:, o]) >> Wg
            E = E + ge[:, o]
    if use_sg:
        sm, se, sk = family_gammas(vals, codes, SG_PAIRS, SG_GROUPS, cfg, sigma_floor,
                                   sigma_rel, RT, ET, probe=probe)
        msv, esv, K = _sg_factor(sm, se, sk, cfg, cand, probe)
        if w is None:
            w, E = msv, esv
        else:
            Mg = (1 << Wg) - (cfg.exp == "table")
            Wsv = _bitlen(K * Mg)[:, None]
            w = np.where(pure[:, None], msv, _shift(w * msv, -Wsv))
            E = np.where(pure[:, None], esv, E + esv)
    w = np.where(cand, w, 0)
    _rec(probe, "weight", w)
    live = cand & (w > 0)
    big = np.int64(1) << 40
    Emin = np.where(live, E, big).min(axis=1)
    a = np.where(live, w >> np.clip(E - Emin[:, None], 0, 62), 0)
    den = a.sum(axis=1)
    num = (a * np.where(cand, v - c0[:, None], 0)).sum(axis=1)
    _rec(probe, "den", den)
    _rec(probe, "num", num)
    md, pd = recip(np.maximum(den, 1), cfg, RT)
    sh = pd + Wr
    prod = num * md
    _rec(probe, "quotient_product", prod)
    q = (prod + (np.int64(1) << (sh - 1))) >> sh
    return np.where(den > 0, c0 + q, mean)


def reference_fixed(data, pattern, method, config, bit_depth=11, sigma_floor=1e-3,
                    sigma_rel=0.5, sg_mode="auto", probe=None):
    """The fixed-point reconstruction of an integer frame: int64 frame, colour sites copied."""
    if method not in ("bilinear", "bi", "edi_central", "edi_line", "sg"):
        raise ValueError(f"method: {method!r} has no fixed-point model")
    data = np.asarray(data)
    shape = data.shape
    chan = pattern.channel_map(shape)
    missing = pattern.missing_colour(shape)
    out = data.astype(np.int64).copy()
    ys, xs = np.nonzero(chan == Z)
    if ys.size == 0:
        return out
    target = missing[ys, xs].astype(np.int64)
    vals, codes = gather(data, chan, ys, xs, OFF, pattern.period)
    RT, ET = recip_table(config), exp_table(config)
    val = _site_values(vals, codes, target, method, config, bit_depth, sigma_floor,
                       sigma_rel, sg_mode, RT, ET, probe)
    out[ys, xs] = np.clip(val, 0, (1 << bit_depth) - 1)
    return out
