"""The C kernels of ``method="z_guided"`` (csrc/z_guided.h): their arrays and their calls.

Two passes: what a site takes from its Z pixels alone -- the 11 cell terms and
the noise level of its tile (:func:`._z_guided.cell_terms`) -- is one value per
tile (``_kernels.z_guided_cells``), then every Z site (``_kernels.z_guided``).
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from ._z_guided import z_layout

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
                                "pair_col", "inv_col", "str_thr", "coh_thr2", "spr_thr",
                                "radius", "hash_radius")}
    out.update(w_f32=w64.astype(np.float32), w_f64=w64, g_f32=g64.astype(np.float32),
               g_f64=g64, n_base=n_base, base_idx=base_idx)
    object.__setattr__(filters, "_kernel", out)
    return out


def cell_arrays(filters, data, grids, nthreads=1, kernels=None):
    """``(cell, level)``: the cell terms (n_phases, tile rows, tile columns, 11) of every
    phase's target colour and the noise level (tile rows, tile columns) of every tile, by
    the C kernel (the NumPy path: :func:`._z_guided.cell_terms`)."""
    grid, var = (np.ascontiguousarray(g, np.float64) for g in grids)
    gy, gx = grid.shape
    pattern = filters.pattern
    P, Q = pattern.period
    zr, zc, b = z_layout(pattern)
    geo = filters.base.geometry
    chan = np.ascontiguousarray(pattern.channel_map((P, Q)).reshape(-1), np.int8)
    targets = np.array([ph["target"] for ph in geo], np.int32)
    cell = np.empty((len(geo), gy, gx, 11))
    level = np.empty((gy, gx), np.int32)
    k = _kernels if kernels is None else kernels
    k.z_guided_cells(np.ascontiguousarray(data), P, Q, chan, zr, zc, b, grid, var, targets,
                     float(filters.lam), np.ascontiguousarray(filters.noise_thresholds), cell,
                     level, nthreads)
    return cell, level


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
    cell, level = cell_arrays(filters, src, grids, nthreads, kernels)
    k = _kernels if kernels is None else kernels
    extra = {} if opcounts is None else {"opcounts": opcounts}
    k.z_guided(src, out, _PRECISION_CODES[precision], P, Q, phase_map, cell=cell, level=level,
               maxval=float((1 << bit_depth) - 1), workers=nthreads, **kernel_arrays(filters),
               **extra)
    return out
