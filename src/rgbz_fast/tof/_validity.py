"""Validity of the ToF ISP's measurements: the flag bits, the predicted depth noise, the implied
reflectance and the flying-pixel test.

Flying pixels
-------------
A measurement next to a depth discontinuity may mix the two surfaces (a 2x2
Z pixel straddling the edge, the lens blur, a window the denoise could not
split): its depth then lies anywhere between them. :func:`flying_pixels`
takes second differences of the depths along the rows, columns and
diagonals of the grid -- ~0 on any surface, sloped or not -- and where one
jumps by more than ``max(step, 2 x its noise)`` flags the two measurements
across the jump: the band of measurements along each depth edge, on both
sides (the ISP cannot tell which side of the edge a 2x2 pixel's charge came
from) [1]_.

References
----------
.. [1] Hansard et al., *Time-of-Flight Cameras: Principles, Methods and Applications*, ch. 1: flying pixels at depth discontinuities (docs/references.bib: hansard2013tof)
"""

from __future__ import annotations

import enum

import numpy as np

from .._sensors import DEFAULT_CELL_PITCH_UM, SPEED_OF_LIGHT
from .. import _kernels
from .._validate import as_array, check_number, check_workers, kernel_threads
from ._filters import SiteGrid
from ._noise import fixed_pattern_delta

__all__ = ["ToFFlag", "FLAG_SATURATED", "FLAG_LOW_SIGNAL", "FLAG_INCONSISTENT", "FLAG_FLYING",
           "FLAG_OUT_OF_RANGE", "FLAG_RESOLVED", "flying_pixels"]

class ToFFlag(enum.IntFlag):
    """The bits of :attr:`~rgbz_fast.tof.ToFDepth.flags`: why a measurement is not valid.

    ``ToFFlag(int(result.flags[k]))`` names the tests measurement ``k`` failed.
    The module constants ``FLAG_SATURATED`` ... ``FLAG_OUT_OF_RANGE`` are their
    values as plain ints, so that ``flags |= FLAG_FLYING`` keeps a uint8 array
    uint8 (NumPy takes an IntFlag member for an int64).

    Attributes
    ----------
    SATURATED
        A tap reached full scale (or the sensor flagged it saturated) at some
        frequency.
    LOW_SIGNAL
        The SNR or the amplitude is below its threshold at some frequency, or
        the predicted depth noise above ``max_sigma``.
    INCONSISTENT
        The frequencies disagree: the unwrapping residual exceeds
        ``max_residual``.
    FLYING
        At a depth discontinuity: a second difference of the depths through
        the measurement or an immediate Z neighbour exceeds ``flying_step``
        (and 2 sigma), so the measurement may mix two surfaces.
    OUT_OF_RANGE
        The depth is < 0, within 5 sigma of ``max_range`` or beyond, or
        implies a reflectance below ``min_reflectance`` (most likely a surface
        beyond the unambiguous range, aliased) or above ``max_reflectance`` (a
        depth unwrapped to a wrong, farther alias).
    RESOLVED
        With a guide only: a measurement at a depth edge whose depth lies
        between the two sides and whose cells all have one side's colour
        (a mixture of the two surfaces) holds that side's depth in
        ``ToFDepth.depth``; ``ToFDepth.measured`` keeps the measured one. Not
        valid (its measurement is of no single surface), but
        :func:`~rgbz_fast.tof.upsample_depth` uses it unless it is flagged
        otherwise too (but flying): a side's depth that the range test
        fails flags it OUT_OF_RANGE.

    Examples
    --------
    >>> [f.name for f in ToFFlag if f in ToFFlag(10)]
    ['LOW_SIGNAL', 'FLYING']
    >>> FLAG_FLYING == ToFFlag.FLYING, type(FLAG_FLYING).__name__
    (True, 'int')
    """

    SATURATED = 1
    LOW_SIGNAL = 2
    INCONSISTENT = 4
    FLYING = 8
    OUT_OF_RANGE = 16
    RESOLVED = 32


FLAG_SATURATED = int(ToFFlag.SATURATED)
FLAG_LOW_SIGNAL = int(ToFFlag.LOW_SIGNAL)
FLAG_INCONSISTENT = int(ToFFlag.INCONSISTENT)
FLAG_FLYING = int(ToFFlag.FLYING)
FLAG_OUT_OF_RANGE = int(ToFFlag.OUT_OF_RANGE)
FLAG_RESOLVED = int(ToFFlag.RESOLVED)


def radiometry_coefficients(sensor, f):
    """(sigma_scale, coef), both (F,) for the frequencies ``f``: ``(w_f c / (4 pi f) /
    sum w)^2``, w = f^2, the weight of a frequency's phase variance in the depth noise; and
    ``(gain / 4) contrast_f``, the amplitude (DN) of one electron of active signal, which the
    implied reflectance divides by. The guided and the unguided validity share them."""
    w = f * f
    sigma_scale = (w * SPEED_OF_LIGHT / (4 * np.pi * f) / w.sum()) ** 2
    contrast = sensor.contrasts * float(np.mean(sensor.tap_contrast))
    coef = sensor.system_gain * 0.25 * contrast
    return (np.ascontiguousarray(sigma_scale, np.float64),
            np.ascontiguousarray(coef, np.float64))


def validity(depth, residual, amp, var, saturated, sensor, block, frequencies, grid, *,
             min_snr, min_amplitude, max_sigma, max_residual, flying_step, min_reflectance,
             max_range, workers=None, fixed_pattern=None, max_reflectance=None):
    """snr, sigma, implied reflectance and flags (uint8) of every measurement of the unguided
    chain (:func:`~rgbz_fast.tof.tof_depth`), from the per-frequency amplitude ``amp`` and
    component variance ``var`` (F, n), ``depth``, ``residual`` and ``saturated`` (n,).

    * snr: ``min_f 2 |I + iQ|_f / sqrt(var_f)``;
    * sigma: the depth noise of the f^2-weighted mean of the per-frequency distances,
      ``sigma^2 = sum_f (w_f c / (4 pi f))^2 var_f / |I + iQ|_f^2 / (sum w)^2``, the phase
      variance ``var / |I + iQ|^2`` capped at ``pi^2 / 3``, that of a phase that is all noise
      (uniform on the circle); ``fixed_pattern`` (phase, offset, count, dark_noise, delay_var), when
      given, adds :func:`~rgbz_fast.tof._noise.fixed_pattern_delta` to ``sigma^2`` where no
      phase variance reached the cap (the DSNU and PRNU of the taps, correlated across
      frequencies);
    * reflectance: the NIR reflectance the amplitude implies at ``depth`` (the sensor's
      radiometry, :meth:`~rgbz_fast.simulation.ToFSensor.active_electrons`), 0 where the
      depth is not positive;
    * flags: saturated, low signal, inconsistent, flying (:func:`flying_pixels` on the
      grid: ``grid`` is the :class:`SiteGrid` of the measurements, or a callable that makes
      it) and out of range (an implied reflectance above ``max_reflectance``, None: no bound,
      too).

    One C pass (csrc/tof_filter.c, ``rgbz_tof_validity``) but for the flying-pixel test; the
    NumPy operations it replaced are its reference (tests/_reference/tof.py), bit for bit.
    """
    scale, coef = radiometry_coefficients(sensor, np.asarray(frequencies, np.float64))
    pitch = float(sensor.pixel_pitch_um or DEFAULT_CELL_PITCH_UM)
    tan_h, tan_v, k_cell = sensor._cell_constants(pitch)
    n = depth.shape[0]
    snr, sigma, reflectance = np.empty(n), np.empty(n), np.empty(n)
    flags = np.empty(n, np.uint8)
    nthreads = check_workers(workers)
    delta = None
    if fixed_pattern is not None:
        fp_phase, fp_offset, fp_count, dark, delay_var = fixed_pattern
        delta = fixed_pattern_delta(fp_phase, amp, fp_offset, fp_count, sensor, scale,
                                    dark_noise=dark, delay_var=delay_var, workers=nthreads)
    _kernels.tof_validity(
        np.ascontiguousarray(amp, np.float64), np.ascontiguousarray(var, np.float64),
        np.ascontiguousarray(depth, np.float64), np.ascontiguousarray(residual, np.float64),
        np.ascontiguousarray(saturated, np.uint8), scale, coef, np.pi * np.pi / 3.0,
        float(sensor.optical_power_w), tan_h, tan_v, k_cell, float(block), float(min_snr),
        float(min_amplitude), -1.0 if max_sigma is None else float(max_sigma),
        float(max_residual), float(min_reflectance), float(max_range), snr, sigma,
        reflectance, flags, kernel_threads(nthreads, n), delta,
        np.inf if max_reflectance is None else float(max_reflectance))
    if flying_step is not None:
        usable = (flags & (FLAG_SATURATED | FLAG_LOW_SIGNAL)) == 0
        if not isinstance(grid, SiteGrid):
            grid = grid()
        flags[flying_pixels(depth, sigma, grid, block=grid.block, step=flying_step,
                            usable=usable, workers=nthreads)] |= FLAG_FLYING
    return snr, sigma, reflectance, flags


def flying_pixels(depth, sigma, sites, *, block=1, step=0.05, usable=None, k=2.0,
                  workers=None):
    """Measurements at a depth discontinuity (possible mixtures of two surfaces).

    Along each of the four grid directions (rows, columns, both diagonals) the
    second difference ``J = |d[m+e] - 2 d[m] + d[m-e]|`` is ~0 on a surface,
    sloped or not, and jumps at a discontinuity; where it exceeds
    ``max(step, k sqrt(s[m+e]^2 + 4 s[m]^2 + s[m-e]^2))``, ``m`` and the
    neighbour across the larger of its two first differences are flagged: the
    pair on either side of the discontinuity. A measurement halfway between
    the two surfaces (a 50 % mixture) is on the straight line through its
    neighbours but not through its neighbours' neighbours: it is flagged by the
    differences centred on them. (A first difference would flag slopes: none is
    used, so two usable measurements alone on a line -- a frame corner's
    diagonal -- are not tested along it.)

    Parameters
    ----------
    depth, sigma : ndarray, shape (n,)
        Depth and its noise (m).
    sites : (rows, cols) or SiteGrid
        Top-left pixel of every measurement (or their grid, built once).
    block : {1, 2}
        Z pixel size in colour pixels.
    step : float
        Smallest jump (m) that counts as a discontinuity.
    usable : ndarray of bool, shape (n,), optional
        Measurements whose depth can be trusted (default all); the others
        take part in no difference.
    k : float
        A jump must also exceed ``k`` times the noise of the difference.
    workers : int, optional
        Threads of the C kernel (csrc/tof_guided.c; default: all cores).

    Returns
    -------
    ndarray of bool, shape (n,)

    Examples
    --------
    >>> import numpy as np
    >>> rows, cols = (a * 2 for a in np.nonzero(np.ones((3, 8), bool)))
    >>> step = np.where(cols < 8, 1.0, 1.3)                     # a 30 cm step
    >>> flying_pixels(step, np.full(24, 0.002), (rows, cols)).reshape(3, 8)[0].astype(int)
    array([0, 0, 0, 1, 1, 0, 0, 0])
    >>> slope = 1.0 + 0.06 * cols                             # 12 cm per Z site, no edge
    >>> bool(flying_pixels(slope, np.full(24, 0.002), (rows, cols)).any())
    False
    """
    d = as_array(depth, "depth", dtype=np.float64)
    s = as_array(sigma, "sigma", dtype=np.float64)
    k = check_number(k, "k", lo=0)
    nthreads = check_workers(workers)
    grid = sites if isinstance(sites, SiteGrid) else SiteGrid(sites, block)
    if d.shape != (grid.n,) or s.shape != (grid.n,):
        raise ValueError(f"depth, sigma: expected shape ({grid.n},), got {d.shape} and "
                         f"{s.shape}")
    step = check_number(step, "step", lo=0)
    ok = np.ones(grid.n, bool) if usable is None else as_array(usable, "usable", dtype=bool)
    if ok.shape != (grid.n,):
        raise ValueError(f"usable: expected shape ({grid.n},), got {ok.shape}")
    R, C = grid.shape
    good = ok & np.isfinite(s) & np.isfinite(d)
    usable_grid = np.ascontiguousarray(grid.to_grid(good, False) & grid.present, np.uint8)
    # k = 0: the noise term is 0 whatever sigma is, so sigma 0 and any k > 0 give it
    dg = np.ascontiguousarray(grid.to_grid(np.where(good, d, 0.0)), np.float64)
    sg = np.ascontiguousarray(grid.to_grid(np.where(good & (k > 0), s, 0.0)), np.float64)
    cand = np.empty(R * C, np.uint8)
    _kernels.tofg_flying_candidates(dg.reshape(-1), sg.reshape(-1), usable_grid.reshape(-1),
                                    R, C, step, k if k > 0 else 1.0, cand,
                                    kernel_threads(nthreads, R * C))
    return grid.from_grid(cand.reshape(R, C).astype(bool))
