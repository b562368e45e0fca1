"""The edge-aware denoise of the ToF ISP: the bilateral phasor mean on the grid of the Z measurements.

It works on the grid of the Z measurements (:class:`SiteGrid`: one cell per distinct row and
column of their top-left pixels: Mask1's Z sites, Mask2's 2x2 Z pixels, the
Z pixels of the ``rows`` pattern), with the neighbourhood rule of the paper's
denoise (:func:`~rgbz_fast.tof.denoise_phasors`): measurement ``m`` is in the
window of ``n`` when their sites are within ``h = (window // 2) * block``
pixels in rows and in columns.

Bilateral denoise
-----------------
The paper's 5x5 kernel (Fig. 17) averages every Z measurement of the window,
so at a depth edge it mixes the two surfaces: on the six Middlebury scenes
3.8 % of the Mask2 measurements end up more than 5 cm off (docs/reports/isp.md,
"Measured: RGB-D scenes"). The
bilateral version [1]_ weighs each neighbour by how much its phasors agree
with the centre's, measured against their noise:

.. math::

    \\chi^2_{nm} = \\sum_f \\frac{|g_{f,m} - g_{f,n}|^2}{v_{f,m} + v_{f,n}},
    \\qquad w_{nm} = \\exp\\!\\left(-\\frac{\\max(\\chi^2_{nm} - 2F, 0)}{2 h^2}\\right)

with ``g`` the guide phasors ``I + iQ`` of every frequency, ``v`` the
variance of each of their components from the sensor's noise model (so the
range kernel needs no tuning per scene or distance), ``F`` the number of
frequencies (``2F`` is the expectation of ``chi^2`` between two measurements
of one surface) and ``h`` the range scale (``range_scale``, 2). The phasors
of every frequency enter: a depth step changes the phase at each frequency
differently and the amplitude by ``(d1 / d2)^2``, so an edge the noise of a
single frequency hides stands out in ``chi^2``. The first pass is guided by
the raw phasors; the second by the first pass's output (whose noise is
``n_eff`` times smaller: the edges of Mask1's noisy 1x1 Z pixels are found
there). The weights are box-shaped in space (the window), and the variance
of every mean follows from them: ``sum w^2 v / (sum w)^2``, which
:func:`~rgbz_fast.tof.tof_depth` turns into the depth noise ``sigma``.

References
----------
.. [1] Tomasi and Manduchi, "Bilateral filtering for gray and color images" (docs/references.bib: tomasi1998bilateral)
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._validate import check_block, check_int, check_number, check_sites, check_workers

#: the largest tap magnitude: the phasor, its noise and its SNR square sums of taps, which
#: stay finite doubles below it (taps are counts or electrons, far below)
TAP_MAX = 1e150


def check_phasor_values(arrays, name, what="phasors"):
    """Refuse NaN, infinities and magnitudes beyond :data:`TAP_MAX` in ``arrays``: the means
    and squared differences of the denoise would overflow or carry them into every
    neighbour's mean. The minimum and the maximum (NaN propagates through both, and then
    fails the comparison) cost what ``isfinite`` did."""
    for a in arrays:
        if a.size and not (a.min() >= -TAP_MAX and a.max() <= TAP_MAX):
            raise ValueError(f"{name}: hold NaN, infinite values or magnitudes beyond "
                             f"{TAP_MAX:g}; expected finite {what} (sums of taps)")

#: the range of a filter's scale (range_scale, colour_scale): beyond it the weights are those
#: of the bound (every neighbour equal, or none but the exact match), and far beyond it their
#: 1 / (2 h^2) overflows or divides by zero
SCALE_BOUNDS = (1e-6, 1e6)


def check_scale(value, name):
    """A filter scale in :data:`SCALE_BOUNDS`, as float; a ValueError naming ``name``."""
    return check_number(value, name, lo=SCALE_BOUNDS[0], hi=SCALE_BOUNDS[1])

__all__ = ["SiteGrid", "denoise_phasors_bilateral"]


class SiteGrid:
    """The Z measurements of a frame laid out on the grid of their distinct rows and columns.

    Parameters
    ----------
    sites : (rows, cols) arrays of int, shape (n,)
        Top-left pixel of every measurement.
    block : {1, 2}
        Z pixel size in colour pixels.

    Attributes
    ----------
    shape : (R, C)
        Distinct rows and columns.
    full : bool
        The measurements fill the grid in row-major order (Mask1, Mask2,
        rows): gathering and scattering are reshapes.
    """

    def __init__(self, sites, block=1):
        fast = self._checked_row_major(sites)
        if fast:
            self.n = sites[0].size
        else:
            rows, cols = check_sites(sites, "sites")       # integers, none twice
            self.n = rows.size
        self.block = check_block(block, "block")
        if not fast and not self._row_major(rows, cols):
            self._irregular(rows, cols)
        self.present = self.to_grid(np.ones(self.n, bool), False)

    def _checked_row_major(self, sites):
        """The common case checked without check_sites' copies and sort: two int64 arrays of
        one shape that fill a grid in row-major order (strictly increasing grid lines, so no
        site twice) within [0, 2^31); then the grid is made. False: anything else (check_sites
        then names what is wrong)."""
        if not (isinstance(sites, (tuple, list)) and len(sites) == 2):
            return False
        rows, cols = sites
        if not (isinstance(rows, np.ndarray) and isinstance(cols, np.ndarray)
                and rows.dtype == np.int64 and cols.dtype == np.int64 and rows.ndim == 1
                and rows.shape == cols.shape and self._row_major(rows, cols)):
            return False
        return bool(self.rows_u[0] >= 0 and self.cols_u[0] >= 0
                    and self.rows_u[-1] < 1 << 31 and self.cols_u[-1] < 1 << 31)

    def _irregular(self, rows, cols):
        """Any other layout: the grid of the distinct rows and columns."""
        self.rows_u, self._ri = np.unique(rows, return_inverse=True)
        self.cols_u, self._ci = np.unique(cols, return_inverse=True)
        self.shape = (self.rows_u.size, self.cols_u.size)
        self.full = (self.n == self.shape[0] * self.shape[1]
                     and np.array_equal(self._ri, np.arange(self.n) // self.shape[1])
                     and np.array_equal(self._ci, np.arange(self.n) % self.shape[1]))

    def _row_major(self, rows, cols):
        """The fast path (Mask1, Mask2, rows): the sites fill a grid in row-major order, which
        O(n) comparisons prove without sorting 3 million coordinates twice."""
        n = rows.size
        if n == 0:
            return False
        ncols = int(np.searchsorted(rows, rows[0], side="right")) if rows[0] == rows.min() \
            else 0
        if ncols == 0 or n % ncols:
            return False
        nrows = n // ncols
        grid_r = rows.reshape(nrows, ncols)
        grid_c = cols.reshape(nrows, ncols)
        line_r, line_c = grid_r[:, 0], grid_c[0]
        if not (np.all(np.diff(line_r) > 0) and np.all(np.diff(line_c) > 0)
                and np.all(grid_r == line_r[:, None]) and np.all(grid_c == line_c[None])):
            return False
        self.rows_u, self.cols_u = line_r.copy(), line_c.copy()
        self._ri = self._ci = None             # made when asked for (a full grid reshapes)
        self.shape = (nrows, ncols)
        self.full = True
        return True

    @property
    def ri(self):
        """Grid row of every measurement, shape (n,)."""
        if self._ri is None:
            self._ri = np.repeat(np.arange(self.shape[0]), self.shape[1])
        return self._ri

    @property
    def ci(self):
        """Grid column of every measurement, shape (n,)."""
        if self._ci is None:
            self._ci = np.tile(np.arange(self.shape[1]), self.shape[0])
        return self._ci

    def to_grid(self, values, fill=0.0):
        """(..., n) -> (..., R, C); cells without a measurement hold ``fill``."""
        v = np.asarray(values)
        if self.full:
            return v.reshape(v.shape[:-1] + self.shape)
        g = np.full(v.shape[:-1] + self.shape, fill, dtype=v.dtype)
        g[..., self.ri, self.ci] = v
        return g

    def from_grid(self, grid):
        """(..., R, C) -> (..., n), C-contiguous (the C kernels take no other layout)."""
        g = np.asarray(grid)
        if self.full:
            return g.reshape(g.shape[:-2] + (self.n,))
        # fancy indexing of the last two axes lays the result out (n, ...) in memory
        return np.ascontiguousarray(g[..., self.ri, self.ci])

    def reach(self, radius_px):
        """(rows, cols): the largest grid offsets that link two lines within ``radius_px``."""
        return tuple(max((abs(a) for a, *_ in _axis_offsets(u, radius_px)), default=0)
                     for u in (self.rows_u, self.cols_u))

    def offsets(self, radius_px, max_steps=None):
        """[(dr, row_slices, dc, col_slices, mask)] of the neighbours within ``radius_px``.

        For each grid offset ``(dr, dc)``: the target and source slices of the
        overlap and a (rows, cols) bool mask of the cells whose neighbour at
        that offset lies within ``radius_px`` pixels in rows and columns (None
        when all do). ``max_steps`` bounds ``|dr|``, ``|dc|`` in grid steps.
        """
        rows = _axis_offsets(self.rows_u, radius_px, max_steps)
        cols = _axis_offsets(self.cols_u, radius_px, max_steps)
        out = []
        for a, rlo, rhi, rok in rows:
            for b, clo, chi, cok in cols:
                if rok.all() and cok.all():
                    mask = None
                else:
                    mask = rok[:, None] & cok[None, :]
                out.append((a, (slice(rlo, rhi), slice(rlo + a, rhi + a)),
                            b, (slice(clo, chi), slice(clo + b, chi + b)), mask))
        return out


def _axis_offsets(coords, radius, max_steps=None):
    """Grid offsets along one axis of sorted unique pixel coordinates.

    Returns ``(a, lo, hi, ok)`` for every offset ``a`` that links some grid line
    ``u`` in ``[lo, hi)`` to ``u + a`` within ``radius`` pixels; ``ok`` tells which.
    Unique coordinates differ by at least one pixel, so ``|a| <= radius``.
    """
    n = coords.size
    reach = min(radius, n - 1) if max_steps is None else min(radius, n - 1, max_steps)
    out = []
    for a in range(-reach, reach + 1):
        lo, hi = max(0, -a), min(n, n - a)
        ok = np.abs(coords[lo + a:hi + a] - coords[lo:hi]) <= radius
        if ok.any():
            out.append((a, lo, hi, ok))
    return out


def _check_phasor_planes(i, q, var, n_name="i, q"):
    i = np.asarray(i, np.float64)
    q = np.asarray(q, np.float64)
    v = np.asarray(var, np.float64)
    if i.ndim != 2 or q.shape != i.shape or v.shape != i.shape:
        raise ValueError(f"{n_name}, var: expected three arrays of the same shape (F, n), got "
                         f"{i.shape}, {q.shape} and {v.shape}")
    check_phasor_values((i, q), n_name)
    if not np.all(v > 0):
        raise ValueError("var: expected positive variances (the noise of I and Q)")
    return i, q, v


def _bilateral_pass(z_re, z_im, v, g_re, g_im, gv, use, grid, radius_px, reach, inv_h2,
                    workers):
    """One pass of the C kernel on the grid (planes (F, R, C), ``use`` (R, C) uint8); ``reach``:
    the (rows, cols) grid steps that can lie within ``radius_px``.

    Returns the mean (re, im), its variance (F, R, C) and ``n_eff`` (R, C).
    """
    out_re, out_im, out_v = (np.empty(z_re.shape) for _ in range(3))
    neff = np.empty(z_re.shape[1:])
    _kernels.tof_bilateral(z_re, z_im, v, g_re, g_im, gv, use, grid.rows_u, grid.cols_u,
                           reach[0], reach[1], radius_px, inv_h2, out_re, out_im, out_v, neff,
                           workers)
    return out_re, out_im, out_v, neff


def denoise_phasors_bilateral(i, q, var, sites, *, block=1, window=9, use=None,
                              range_scale=2.0, passes=2, workers=None):
    """Edge-aware mean of ``I + iQ`` over the Z measurements of a window (C kernel).

    See the module docstring for the weights. Measurements with ``use =
    False`` (saturated) enter no mean.

    Parameters
    ----------
    i, q : ndarray, shape (F, n)
        Phasor components per frequency (:func:`~rgbz_fast.tof.phasors`).
    var : ndarray, shape (F, n)
        Noise variance of each component (DN^2; ``2 var(A)`` for the
        four-tap differences).
    sites : (rows, cols) or SiteGrid
        Top-left pixel of every measurement (or their grid, built once).
    block : {1, 2}
        Z pixel size in colour pixels.
    window : int
        Odd window size in Z-pixel cells (9: the 5x5 nearest Z measurements;
        5: the paper's 3x3).
    use : ndarray of bool, shape (n,), optional
        Measurements allowed into the means (default: all).
    range_scale : float
        ``h`` of the range kernel, in [1e-6, 1e6]: larger smooths across weaker
        edges.
    passes : {1, 2}
        2: a second pass guided by the first's output.
    workers : int, optional
        Threads (None or -1: all cores); the result does not depend on it.

    Returns
    -------
    i_mean, q_mean : ndarray of float64, shape (F, n)
    var_mean : ndarray of float64, shape (F, n)
        Variance of each component of the mean (inf where nothing entered it).
    n_eff : ndarray of float64, shape (n,)
        ``(sum w)^2 / sum w^2``: the number of independent measurements the
        mean is worth (9x9 cells of a flat wall: 25).

    Examples
    --------
    >>> import numpy as np
    >>> rows, cols = np.nonzero(np.ones((6, 6), bool))
    >>> i = np.where(cols < 3, 10.0, -10.0)[None] + 0.1 * np.cos(rows)[None]
    >>> im, qm, vm, n = denoise_phasors_bilateral(i, np.zeros_like(i), np.full_like(i, 0.01),
    ...                                           (rows * 2, cols * 2))
    >>> bool(np.all(np.sign(im) == np.sign(i))), float(n.max())
    (True, 15.0)
    """
    i, q, v = _check_phasor_planes(i, q, var)
    grid = sites if isinstance(sites, SiteGrid) else SiteGrid(sites, block)
    if grid.n != i.shape[1]:
        raise ValueError(f"sites: expected two arrays of shape ({i.shape[1]},), got "
                         f"({grid.n},)")
    window = _check_odd(window, "window")
    h = check_scale(range_scale, "range_scale")
    passes = check_int(passes, "passes", lo=1, hi=2)
    use = np.ones(grid.n, bool) if use is None else np.asarray(use, bool)
    if use.shape != (grid.n,):
        raise ValueError(f"use: expected shape ({grid.n},), got {use.shape}")
    nthreads = check_workers(workers)
    zr = np.ascontiguousarray(grid.to_grid(i))
    zi = np.ascontiguousarray(grid.to_grid(q))
    vg = np.ascontiguousarray(grid.to_grid(v, 1.0))
    useg = np.ascontiguousarray(grid.to_grid(use, False) & grid.present, np.uint8)
    radius = (window // 2) * block
    reach = grid.reach(radius)
    args = (useg, grid, radius, reach, 1.0 / (h * h), nthreads)
    mr, mi, mvar, n_eff = _bilateral_pass(zr, zi, vg, zr, zi, vg, *args)
    if passes == 2:
        guide_var = np.where(np.isfinite(mvar), mvar, 1e300)
        mr, mi, mvar, n_eff = _bilateral_pass(zr, zi, vg, mr, mi, guide_var, *args)
    return (grid.from_grid(mr), grid.from_grid(mi), grid.from_grid(mvar),
            grid.from_grid(n_eff))


#: the widest window (cells): 2**63 + 1 had been accepted, to fail as a size in the kernel
WINDOW_MAX = 1023


def _check_odd(window, name):
    try:
        w = check_int(window, name, lo=1, hi=WINDOW_MAX)
    except TypeError:
        w = None
    if w is None or w % 2 == 0:
        raise ValueError(f"{name}: expected an odd positive integer (5 = the paper's 5x5 "
                         f"kernel), got {window!r}")
    return w
