"""The C kernel of ``method="z_guided"`` (csrc/z_guided.h): its arrays and its call.

The kernel computes every Z site; what a site takes from its Z pixels alone -- the
11 cell terms and the noise level of its tile (:func:`._z_guided.cell_terms`) --
is one value per tile, computed here on the grid of the tiles (1/16 of the pixels
on Mask1, 1/36 on Mask2) and handed to the kernel with the weights.
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from ._z_guided import _neighbours, cell_terms, colour_grids

__all__ = ["run_z_guided", "cell_arrays", "kernel_arrays"]

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
                                "str_thr", "coh_thr2", "radius", "hash_radius")}
    out.update(w_f32=w64.astype(np.float32), w_f64=w64, g_f32=g64.astype(np.float32),
               g_f64=g64, n_base=n_base, base_idx=base_idx)
    object.__setattr__(filters, "_kernel", out)
    return out


def cell_arrays(filters, data, grids):
    """``(cell, level)``: the cell terms (n_phases, tile rows, tile columns, 11) of every
    phase's target colour and the noise level (tile rows, tile columns) of every tile."""
    grid, var = grids
    gy, gx = grid.shape
    geo = filters.base.geometry
    iy, ix = np.divmod(np.arange(gy * gx), gx)
    N, V = _neighbours(grid, iy, ix), _neighbours(var, iy, ix)
    cg = colour_grids(data, filters.pattern, sorted({ph["target"] for ph in geo}))
    cell = np.empty((len(geo), gy, gx, 11))
    terms = {}
    nu = None
    for k, ph in enumerate(geo):
        t = ph["target"]
        if t not in terms:
            terms[t], nu = cell_terms(N, V, _neighbours(cg[t], iy, ix), filters.lam)
        cell[k] = terms[t].reshape(gy, gx, 11)
    level = np.zeros(gy * gx, np.int32)
    for thr in filters.noise_thresholds:
        level += nu > thr
    return cell, level.reshape(gy, gx)


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
    cell, level = cell_arrays(filters, src, grids)
    k = _kernels if kernels is None else kernels
    extra = {} if opcounts is None else {"opcounts": opcounts}
    k.z_guided(src, out, _PRECISION_CODES[precision], P, Q, phase_map, cell=cell, level=level,
               maxval=float((1 << bit_depth) - 1), workers=nthreads, **kernel_arrays(filters),
               **extra)
    return out
