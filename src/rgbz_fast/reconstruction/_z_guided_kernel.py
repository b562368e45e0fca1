"""The C kernel of ``method="z_guided"`` (csrc/z_guided.h): its arrays and its call.

One pass: the kernel computes what a site takes from its Z pixels alone -- the
11 cell terms and the noise level of its tile (:func:`._z_guided.cell_terms`)
-- once per tile row in the rows it reconstructs, then every Z site of them.
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from ._z_guided import z_layout

__all__ = ["run_z_guided", "kernel_arrays"]

_PRECISION_CODES = {"float32": _kernels.PRECISIONS["float32"],
                    "float64": _kernels.PRECISIONS["float64"]}


def kernel_arrays(filters):
    """The frame-independent arrays of the kernel for ZGuidedFilters ``filters`` (made once
    and kept on the filters object)."""
    cached = getattr(filters, "_kernel", None)
    if cached is not None:
        return cached
    base = filters.base.kernel_arrays()
    geo = filters.base.geometry
    n_base = np.array([len(ph["base"]) for ph in geo], np.int32)
    base_idx = np.zeros((len(geo), int(n_base.max())), np.int32)
    for k, ph in enumerate(geo):
        base_idx[k, :n_base[k]] = ph["base"]
    w64 = np.ascontiguousarray(filters.weights.transpose(0, 2, 1))
    g64 = np.ascontiguousarray(filters.guide_weights)
    out = {k: base[k] for k in ("n_taps", "tap_dy", "tap_dx", "n_pairs", "pair_a", "pair_b",
                                "pair_col", "inv_col", "str_thr", "coh_thr2", "spr_thr",
                                "radius", "hash_radius", "bayer")}
    pattern = filters.pattern
    P, Q = pattern.period
    zr, zc, b = z_layout(pattern)
    out.update(w_f32=w64.astype(np.float32), w_f64=w64, g_f32=g64.astype(np.float32),
               g_f64=g64, n_base=n_base, base_idx=base_idx,
               chan=np.ascontiguousarray(pattern.channel_map((P, Q)).reshape(-1), np.int8),
               zr=zr, zc=zc, block=b,
               targets=np.array([ph["target"] for ph in geo], np.int32),
               lam=float(filters.lam), thr=np.ascontiguousarray(filters.noise_thresholds))
    R = int(base["radius"])
    if R <= 3:
        # the kernel's fast path: each window row as 8 colour weights, 0 off the taps
        dense = np.zeros((len(geo), w64.shape[2], 2 * R + 1, 8))
        for k, ph in enumerate(geo):
            nt = len(ph["taps"])
            # (advanced indices around a slice put the tap axis first)
            dense[k, :, ph["taps"][:, 0] + R, ph["taps"][:, 1] + R] = w64[k, :nt, :]
        out.update(wd_f32=dense.astype(np.float32), wd_f64=dense)
    object.__setattr__(filters, "_kernel", out)
    return out


def run_z_guided(src, out, pattern, filters, grids, precision, bit_depth, nthreads,
                 opcounts=None, kernels=None):
    """Fill ``out``: the colour sites of ``src`` and its Z sites by ``filters`` guided by
    ``grids`` (:func:`._z_guided.guide_grid`), clipped to [0, 2^b - 1] (integer types
    rounded half up), by the C kernel; ``kernels``: the counting extension."""
    P, Q = pattern.period
    phase_map = np.full(P * Q, -1, np.int32)
    for k, ph in enumerate(filters.base.geometry):
        r, c = ph["rc"]
        phase_map[r * Q + c] = k
    grid, var = (np.ascontiguousarray(g, np.float64) for g in grids)
    k = _kernels if kernels is None else kernels
    extra = {} if opcounts is None else {"opcounts": opcounts}
    k.z_guided(src, out, _PRECISION_CODES[precision], P, Q, phase_map, grid=grid, var=var,
               maxval=float((1 << bit_depth) - 1), workers=nthreads, **kernel_arrays(filters),
               **extra)
    return out
