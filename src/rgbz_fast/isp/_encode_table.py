"""The sRGB encoding as a table: the linear value at which each output code starts.

:func:`._stages._encode` (the sRGB OETF of IEC 61966-2-1 through NumPy's power, then
``floor(e (2**bits - 1) + 0.5)``) is a non-decreasing step function of its float input.
:func:`encode_thresholds` finds, for every code ``k >= 1``, the smallest float ``t_k`` in
[0, 1] that :func:`_encode` maps to ``k`` or more, by bisection over the floats' bit
patterns (non-negative floats are ordered as their bits) with :func:`_encode` itself as the
oracle. The code of a value ``v`` is then the number of thresholds ``<= clip(v, 0, 1)``, the
very code :func:`_encode` gives, without a power: the table of the fused colour chain
(csrc/isp.c), and of :func:`encode_by_table`, its NumPy twin in the tests.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ._stages import _encode

__all__ = ["encode_thresholds", "encode_by_table"]

_UINT = {np.dtype(np.float32): np.uint32, np.dtype(np.float64): np.uint64}


@lru_cache(maxsize=8)
def encode_thresholds(dtype, bits):
    """Thresholds (``dtype`` array of ``2**bits`` values): ``t[0] = 0`` and ``t[k]`` the
    smallest value in [0, 1] of type ``dtype`` (float32 or float64) whose code is ``k`` or
    more, for ``k = 1 .. 2**bits - 1``. Read-only."""
    dt = np.dtype(dtype)
    ut = _UINT[dt]
    top = (1 << bits) - 1
    want = np.arange(1, top + 1)
    lo = np.zeros(top, ut)
    hi = np.full(top, np.array(1.0, dt).view(ut))          # code(1.0) = top: always there
    while np.any(lo < hi):
        mid = lo + (hi - lo) // 2
        code = _encode(mid.view(dt), bits).astype(np.int64)
        up = code >= want
        hi = np.where(up, mid, hi)
        lo = np.where(up, lo, mid + 1)
    t = np.empty(top + 1, dt)
    t[0] = 0
    t[1:] = hi.view(dt)
    t.setflags(write=False)
    return t


def encode_by_table(linear, bits):
    """8- or 16-bit sRGB codes of float32/float64 values by :func:`encode_thresholds`: the
    codes of :func:`._stages._encode`, bit for bit."""
    x = np.asarray(linear)
    t = encode_thresholds(x.dtype, bits)
    code = np.searchsorted(t[1:], np.clip(x, 0, 1), side="right")
    return code.astype(np.uint8 if bits == 8 else np.uint16)
