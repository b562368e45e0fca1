"""The C kernel of ``method="z_guided"`` (csrc/z_guided.h): its arrays and its call.

One pass: the kernel computes what a site takes from its Z pixels alone -- the
11 cell terms and the noise level of its tile (:func:`._z_guided.cell_terms`)
-- once per tile row in the rows it reconstructs, then every Z site of them.
From ToF taps (:func:`guide_source`) it also demodulates the amplitude grid and
its variance there, row by row, so that the taps are read once: only the
medians of :func:`._z_guided.guide_grid` come first.
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._patterns import get_pattern
from ._learned import _read_only
from ._z_guided import _grid_shape, guide_grid, tof_taps, z_layout

__all__ = ["run_z_guided", "kernel_arrays", "guide_source", "TapGuide"]

#: an amplitude this far below the frame's brightest reads as unlit (:func:`_in_range`): float32
#: holds the reciprocal of any 3x3 mean above it
NIR_FLOOR = 2.0 ** -100
_PRECISION_CODES = {"float32": _kernels.PRECISIONS["float32"],
                    "float64": _kernels.PRECISIONS["float64"]}
#: the element types of the taps (tof_taps gives no other) -> the kernel's type codes
_TYPE_CODES = {np.dtype(t).char: _kernels.TYPES[c] for t, c in
               ((np.uint8, "u8"), (np.uint16, "u16"), (np.float32, "f32"), (np.float64, "f64"))}


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
    object.__setattr__(filters, "_kernel", _read_only(out))    # not pickled (H101)
    return out


class TapGuide:
    """The guide of z_guided as the kernel computes it from the taps: the taps (F, 4,
    gyc * gxc) and sites of the complete Z pixels, their medians ``ratio`` (F,), the grid's
    shape and its complete part; ``redo()``: the same with the sites checked first (and
    sorted when they are not in row-major order, which the kernel checks as it reads them)."""

    def __init__(self, taps, rows, cols, ratio, gy, gx, gyc, gxc, redo):
        self.taps, self.rows, self.cols, self.ratio = taps, rows, cols, ratio
        self.gy, self.gx, self.gyc, self.gxc = gy, gx, gyc, gxc
        self.redo = redo


def guide_source(shape, pattern, *, tof=None, nir=None, name="nir", workers=1, check=False):
    """What :func:`run_z_guided` takes as its guide: ``guide_grid``'s grids for ``nir``, else
    a :class:`TapGuide` of ``tof`` (the same checks and errors as :func:`guide_grid`; its
    grids are then computed by the kernel, the same values). The order of the sites is
    checked by the kernel as it reads them (``check``: here, before)."""
    if nir is not None or tof is None:
        return guide_grid(shape, pattern, tof=tof, nir=nir, name=name, workers=workers)
    ratio = []

    def medians(taps, *args):
        ratio[:] = [np.empty(taps.shape[0])]
        return _kernels.z_guided_ratios(taps, *args, ratio[0], int(check), workers)

    taps, rows, cols, gyc, gxc = tof_taps(shape, pattern, tof, name, medians)
    gy, gx = _grid_shape(shape, get_pattern(pattern))
    return TapGuide(taps, rows, cols, ratio[0], gy, gx, gyc, gxc,
                    lambda: guide_source(shape, pattern, tof=tof, name=name, workers=workers,
                                         check=True))


def run_z_guided(src, out, pattern, filters, grids, precision, bit_depth, nthreads,
                 opcounts=None, kernels=None):
    """Fill ``out``: the colour sites of ``src`` and its Z sites by ``filters`` guided by
    ``grids`` (:func:`._z_guided.guide_grid`'s, or a :class:`TapGuide`), clipped to
    [0, 2^b - 1] (integer types rounded half up), by the C kernel; ``kernels``: the counting
    extension."""
    P, Q = pattern.period
    phase_map = np.full(P * Q, -1, np.int32)
    for k, ph in enumerate(filters.base.geometry):
        r, c = ph["rc"]
        phase_map[r * Q + c] = k
    k = _kernels if kernels is None else kernels
    extra = {} if opcounts is None else {"opcounts": opcounts}
    args = (src, out, _PRECISION_CODES[precision], P, Q, phase_map)
    kw = dict(maxval=float((1 << bit_depth) - 1), workers=nthreads, **kernel_arrays(filters))
    if not isinstance(grids, TapGuide):
        grid, var = _in_range(*grids)
        k.z_guided(*args, **kw, **extra, grid=grid, var=var)
    elif not k.z_guided(*args, **kw, **extra, **_tap_arrays(grids)):
        # the sites were not in row-major order: checked and sorted (or refused), once more
        k.z_guided(*args, **kw, **extra, **_tap_arrays(grids.redo()))
    return out


def _in_range(grid, var):
    """The grids scaled by a power of two that puts the largest amplitude in [0.5, 1), one
    2^-100 below it and less made 0 (unlit): the kernel reads each amplitude against its 3x3
    mean in its precision (float32 by default), so a ``nir`` in any unit (documented: any
    positive scale) stays in its range; an exact scaling, so the same bits at any ordinary
    scale (a nir of 1e-39 or 1e39 had made the Z sites 0)."""
    grid = np.array(grid, np.float64)
    var = np.array(var, np.float64)
    top = grid.max() if grid.size else 0.0
    if top > 0:
        e = -int(np.frexp(top)[1])
        grid = np.ldexp(grid, e)
        var = np.ldexp(var, 2 * e)
        grid[grid < NIR_FLOOR] = 0.0
    return grid, var


def _tap_arrays(g):
    """The kernel's arguments of a TapGuide."""
    return dict(grid=None, var=None, taps=g.taps.reshape(-1).view(np.uint8),
                taps_type=_TYPE_CODES[g.taps.dtype.char], taps_F=g.taps.shape[0], gy=g.gy,
                gx=g.gx, gyc=g.gyc, gxc=g.gxc, ratio=g.ratio, site_rows=g.rows,
                site_cols=g.cols)
