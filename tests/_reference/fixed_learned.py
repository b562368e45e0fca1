"""Slow NumPy integer reference of the learned fixed-point model (csrc/hw_learned.c).

Written from csrc/hw_learned.h and docs/guide/hardware.md, independently of
``rgbz_fast.reconstruction._fixed_learned``: the taps and hash pairs come from the
reference's own window (tests/_reference/learned.py's hash_sites), the integer constants
are derived here from the configuration's fields and the filters' fitted numbers, and the
frame is processed whole (no streaming): every Z site of a phase at once, in int64.
It must agree with the C model bit for bit.
"""

from __future__ import annotations

import math

import numpy as np

from .learned import STEPS, Z, hash_sites
from .reconstruction import window_offsets


def _rnd(x):
    return np.floor(np.asarray(x, np.float64) + 0.5).astype(np.int64)


def _bitlen(x):
    """floor(log2 x) + 1 of int64 x >= 0, elementwise (0 for 0)."""
    x = np.asarray(x, np.int64)
    out = np.zeros(x.shape, np.int64)
    for s in range(62, -1, -1):
        hit = (out == 0) & (x >> s > 0)
        out[hit] = s + 1
    return out


def tap_fraction(weights, tap_bits):
    lim = (1 << (tap_bits - 1)) - 1
    wmax = float(np.abs(weights).max())
    return next(F for F in range(40, -1, -1) if np.floor(wmax * 2.0 ** F + 0.5) <= lim)


def reference_fixed_learned(data, filters, config, bit_depth, return_buckets=False):
    """Every pixel of the integer frame ``data`` (colour sites copied, Z sites the fixed
    model's value), int64; with ``return_buckets``, also the bucket of every Z site (-1 at
    colour sites)."""
    N, H, K = config.hash_norm_bits, config.hash_bits, config.hash_const_bits
    top = (1 << bit_depth) - 1
    gain = (top / ((1 << filters.bit_depth) - 1)) ** 2
    s_all = filters.strength_thresholds * gain if bit_depth != filters.bit_depth \
        else filters.strength_thresholds
    F = tap_fraction(filters.weights, config.tap_bits)
    cq = int(math.floor(math.cos(math.pi / 8) * 2.0 ** K + 0.5))
    sq = int(math.floor(math.sin(math.pi / 8) * 2.0 ** K + 0.5))
    pattern = filters.pattern
    P, Q = pattern.period
    offsets = window_offsets(filters.radius, filters.radius)
    chan = pattern.channel_map(data.shape)
    out = data.astype(np.int64).copy()
    buckets = np.full(data.shape, -1, np.int64)
    phase = 0
    for r in range(P):
        for c in range(Q):
            if pattern.tile[r, c] != Z:
                continue
            ys, xs, X, taps, tap_off, codes, _, _, _ = hash_sites(
                data, chan, pattern, (r, c), offsets, filters.hash_radius, filters, phase)
            V = X.astype(np.int64)
            E = []
            Sc = np.zeros((3, len(ys)), np.int64)
            nc = np.zeros(3, np.int64)
            for d, (sy, sx) in enumerate(STEPS):
                S = np.zeros(len(ys), np.int64)
                n = 0
                for i, (dy, dx) in enumerate(tap_off):
                    o = (dy + sy, dx + sx)
                    if o not in tap_off:
                        continue
                    j = tap_off.index(o)
                    if max(abs(dy), abs(dx), abs(o[0]), abs(o[1])) > filters.hash_radius \
                            or codes[0, taps[i]] != codes[0, taps[j]]:
                        continue
                    sqd = (V[:, i] - V[:, j]) ** 2
                    S += sqd
                    n += 1
                    if d < 2:
                        col = int(codes[0, taps[i]])
                        Sc[col] += sqd
                        nc[col] += 1
                E.append(S * int(math.floor(2.0 ** N / n + 0.5)))
            eh, ev, e1, e2 = E
            A, B, T = 4 * (eh - ev), 2 * (e1 - e2), 2 * (eh + ev) + e1 + e2
            str_q = np.floor(s_all[phase] * (4.0 * 2.0 ** N)).astype(np.int64)
            strength = (T[:, None] > str_q[None, :]).sum(1)
            sh = np.maximum(_bitlen(T) - H, 0)
            a, b, t = A >> sh, B >> sh, T >> sh
            # the octant of the rotated vector: the angle of (ar, br) in [0, 360) / 45
            ar, br = cq * a - sq * b, sq * a + cq * b
            neg = br < 0
            ar1, br1 = np.where(neg, -ar, ar), np.where(neg, -br, br)
            left = ar1 < 0
            ar2, br2 = np.where(left, br1, ar1), np.where(left, -ar1, br1)
            octant = 4 * neg + 2 * left + (br2 > ar2)
            coh_q = _rnd(filters.coherence_thresholds[phase] ** 2 * 2.0 ** K)
            m2 = (a * a + b * b) << K
            coherence = (m2[:, None] > coh_q[None, :] * (t * t)[:, None]).sum(1)
            kc = np.array([int(math.floor(2.0 ** N / n + 0.5)) for n in nc], np.int64)
            Ec = Sc * kc[:, None]
            emax, emin = Ec.max(0), Ec.min(0)
            sh2 = np.maximum(_bitlen(emax) - H, 0)
            spr_q = _rnd(filters.spread_thresholds[phase] * 2.0 ** K)
            hi, lo = (emax >> sh2) << K, emin >> sh2
            spread = (hi[:, None] > spr_q[None, :] * lo[:, None]).sum(1)
            bucket = (((octant * filters.n_strength + strength) * filters.n_coherence
                       + coherence) * filters.n_spread + spread)
            wq = _rnd(filters.weights[phase] * 2.0 ** F)[bucket][:, :len(taps)]
            acc = (wq * V).sum(1)
            val = (acc + (1 << (F - 1))) >> F if F > 0 else acc
            out[ys, xs] = np.clip(val, 0, top)
            buckets[ys, xs] = bucket
            phase += 1
    return (out, buckets) if return_buckets else out
