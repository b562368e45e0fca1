"""Vectorised NumPy twin of the ToF kernels of csrc/tof.c (not a public API).

The same algorithm, candidate set and arithmetic as the C code, written as
whole-array NumPy operations: the reference the tests compare the C kernels
with, and the "NumPy" column of ``rgbz-fast bench``'s ToF section.

* demodulation: ``I = A0 - A2``, ``Q = A3 - A1``, ``np.arctan2`` wrapped to
  [0, 2 pi), amplitude ``hypot(I, Q) / 2``, offset ``mean(A_k)``;
* unwrapping: for every wrap count ``w`` of the base frequency (the longest
  ambiguity interval ``A``) and every other frequency ``i``:
  ``x = (d_base - d_i) / a_i + w A / a_i``, ``k = floor(x + 0.5)``,
  ``cost += w_i a_i^2 (k - x)^2``; the first smallest cost wins; depth =
  weighted mean of ``d_i + k_i a_i``. The precomputed constants are the C
  plan's (``1 / a_i``, ``A / a_i``, ``w_i a_i^2``), so that from the same
  phases the C kernel and this code give the same wrap counts and depths
  equal to the last bit (tests/tof/test_tof.py).

Nothing here validates its input: call it with what :mod:`rgbz_fast.tof` accepts.
"""

from __future__ import annotations

import math

import numpy as np

from ..simulation import SPEED_OF_LIGHT

TWO_PI = 2 * np.pi

__all__ = ["unwrap_plan", "numpy_demodulate", "numpy_unwrap", "numpy_tof_depth"]


def unwrap_plan(frequencies, weights=None, max_range=None):
    """The constants of the C kernel's ``tof_plan`` (csrc/tof.c), as NumPy arrays.

    ``max_range`` None: the unambiguous range ``c / (2 gcd(f))`` (whole Hz).
    """
    f = np.asarray(frequencies, np.float64).reshape(-1)
    w = f ** 2 if weights is None else np.asarray(weights, np.float64).reshape(-1)
    if max_range is None:
        g = 0
        for v in f:
            g = math.gcd(g, int(round(v)))
        max_range = SPEED_OF_LIGHT / (2 * g)
    amb = SPEED_OF_LIGHT / (2.0 * f)
    base = int(np.argmax(amb))                       # the first of equal maxima, as in C
    nwrap = max(1, int(math.ceil(max_range / amb[base] - 1e-12)))
    return {"amb": amb, "base": base, "nwrap": nwrap, "scale": amb / TWO_PI,
            "inv_amb": 1.0 / amb, "ratio": amb[base] / amb, "wcost": w * amb * amb,
            "w": w, "wsum": float(sum(float(v) for v in w))}


def numpy_demodulate(taps):
    """Phase in [0, 2 pi), amplitude and offset (F, n) float64 of taps (F, 4, n)."""
    t = np.asarray(taps)
    i = np.subtract(t[:, 0], t[:, 2], dtype=np.float64)
    q = np.subtract(t[:, 3], t[:, 1], dtype=np.float64)
    phase = np.arctan2(q, i)
    np.add(phase, TWO_PI, out=phase, where=phase < 0)
    phase[phase >= TWO_PI] = 0.0
    amp = np.hypot(i, q)
    amp *= 0.5
    offset = np.add(t[:, 0], t[:, 1], dtype=np.float64)
    offset += np.add(t[:, 2], t[:, 3], dtype=np.float64)
    offset *= 0.25
    return phase, amp, offset


def numpy_unwrap(phase, frequencies, weights=None, max_range=None, plan=None):
    """Depth, residual (n,) float64 and base wrap count (n,) int32 of phases (F, n)."""
    p = plan if plan is not None else unwrap_plan(frequencies, weights, max_range)
    ph = np.asarray(phase, np.float64)
    F, n = ph.shape
    b = p["base"]
    d = ph * p["scale"][:, None]
    others = [i for i in range(F) if i != b]
    y = [(d[b] - d[i]) * p["inv_amb"][i] for i in others]
    best = np.full(n, np.inf)
    bw = np.zeros(n, np.int32)
    cost = np.empty(n)
    x = np.empty(n)
    e = np.empty(n)
    better = np.empty(n, bool)
    for w in range(p["nwrap"]):
        cost.fill(0.0)
        for j, i in enumerate(others):
            np.add(y[j], w * p["ratio"][i], out=x)
            np.add(x, 0.5, out=e)
            np.floor(e, out=e)
            e -= x
            e *= e
            e *= p["wcost"][i]
            cost += e
        np.less(cost, best, out=better)
        np.copyto(best, cost, where=better)
        bw[better] = w
    num = p["w"][b] * (d[b] + bw * p["amb"][b])
    for j, i in enumerate(others):
        k = np.floor(y[j] + bw * p["ratio"][i] + 0.5)
        num += p["w"][i] * (d[i] + k * p["amb"][i])
    depth = num / p["wsum"]
    residual = np.sqrt(best / p["wsum"])
    return depth, residual, bw


def numpy_tof_depth(taps, frequencies, weights=None, max_range=None):
    """Demodulation + unwrapping in NumPy: (depth, residual, wraps, phase, amplitude, offset),
    the outputs of ``rgbz_fast.tof.demodulate_unwrap``."""
    phase, amp, offset = numpy_demodulate(taps)
    depth, residual, wraps = numpy_unwrap(phase, frequencies, weights, max_range)
    return depth, residual, wraps, phase, amp, offset
