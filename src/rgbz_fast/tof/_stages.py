"""The stages of the ToF ISP, each a function of arrays: demodulation, the paper's box denoise,
unwrapping, and both fused.

Conventions (docs/guide/sensor.md): ``I = A0 - A2``, ``Q = A3 - A1``,
``phase = atan2(Q, I)`` wrapped to [0, 2 pi), ``amplitude = |I + iQ| / 2`` and
``offset = mean(A_k)`` in DN; ``distance = c phase / (4 pi f) + m c / (2 f)``.
The chain that runs them is :func:`~rgbz_fast.tof.tof_depth`; the edge-aware
denoise is in :mod:`._filters`, the validity tests in :mod:`._validity`.
"""

from __future__ import annotations

import math

import numpy as np

from .. import _kernels
from .._sensors import SPEED_OF_LIGHT
from .._validate import (FRAME_DTYPES, as_array, as_list, check_block, check_frequencies,
                         check_image, check_number, check_workers, kernel_threads)
from ._filters import TAP_MAX, SiteGrid, _axis_offsets, _check_odd, check_phasor_values

__all__ = ["demodulate", "phasors", "denoise_phasors", "unwrap", "demodulate_unwrap",
           "unambiguous_range", "MAX_WRAPS"]


#: most wrap counts of the base frequency (the one with the longest ambiguity interval
#: ``c / (2 f)``) that :func:`unwrap` searches per measurement: ``max_range`` may not exceed
#: ``MAX_WRAPS * c / (2 min f)`` (csrc/rgbz.h, RGBZ_TOF_MAX_WRAPS). The cost of the search
#: is linear in the count (at 1024 with two frequencies: 0.4 us per measurement and
#: thread), while any practical frequency set needs a handful (80/100/120 MHz: 4).
MAX_WRAPS = int(_kernels.TOF_MAX_WRAPS)




def _check_taps(taps, name="taps"):
    t = as_array(taps, name)
    if t.ndim != 3 or t.shape[1] != 4 or t.shape[0] < 1:
        raise ValueError(f"{name}: expected shape (F, 4, n_sites), got {t.shape}")
    if t.dtype == np.bool_ or not (np.issubdtype(t.dtype, np.integer)
                                   or np.issubdtype(t.dtype, np.floating)):
        raise TypeError(f"{name}: expected real numbers, got dtype {t.dtype}")
    if np.issubdtype(t.dtype, np.floating) and not np.all(np.isfinite(t)):
        raise ValueError(f"{name}: holds NaN or infinite values; expected finite data")
    if t.size and t.dtype.kind == "f" and float(np.max(np.abs(t))) > TAP_MAX:
        raise ValueError(f"{name}: values up to {float(np.max(np.abs(t))):g} in magnitude, "
                         f"beyond {TAP_MAX:g}: their sums and squares (offset, amplitude, "
                         "noise) would overflow; expected counts or electrons")
    return t


def _check_window(window):
    return _check_odd(window, "window")


def demodulate(taps, *, workers=None):
    """Four-tap demodulation of every measurement at every frequency (C kernel).

    Parameters
    ----------
    taps : ndarray, shape (F, 4, n)
        Tap values in DN. uint16, float32 and float64 are read directly,
        other real types are converted to float64.
    workers : int, optional
        Threads (None or -1: all cores); the result does not depend on it.

    Returns
    -------
    phase, amplitude, offset : ndarray of float64, shape (F, n)
        ``atan2(A3 - A1, A0 - A2)`` in [0, 2 pi); ``|I + iQ| / 2`` (DN);
        ``mean(A_k)`` (DN, black level included).
    """
    t = _check_taps(taps)
    if t.dtype not in (np.uint16, np.float32, np.float64):
        t = t.astype(np.float64)
    t = np.ascontiguousarray(t)
    F, _, n = t.shape
    phase = np.empty((F, n))
    amp = np.empty((F, n))
    off = np.empty((F, n))
    _kernels.tof_demodulate(t, phase, amp, off, check_workers(workers))
    return phase, amp, off


def phasors(taps):
    """In-phase and quadrature components ``I = A0 - A2``, ``Q = A3 - A1`` (float64, DN).

    Parameters
    ----------
    taps : ndarray, shape (F, 4, n)

    Returns
    -------
    i, q : ndarray of float64, shape (F, n)
        ``I + iQ = 2 * amplitude * exp(i * phase)``; the black level cancels.
    """
    t = _check_taps(taps)
    i = np.subtract(t[:, 0], t[:, 2], dtype=np.float64)
    q = np.subtract(t[:, 3], t[:, 1], dtype=np.float64)
    return i, q


def _phasors_offset(t, workers=1):
    """I, Q and the offset (F, n) float64 of checked taps, with the C kernel's arithmetic.

    ``offset = 0.25 * ((A0 + A1) + (A2 + A3))`` in float64, as csrc/tof.c sums it; one C
    pass (csrc/tof_filter.c, ``rgbz_tof_phasors_offset``: the NumPy operations it replaced,
    each tap converted to float64 first, tests/_reference/tof.py) on ``workers`` threads
    (a checked count). Taps of another integer type go through float64, as NumPy converted
    them.
    """
    src = t if t.dtype in FRAME_DTYPES else t.astype(np.float64)
    src = np.ascontiguousarray(src)
    F, n = t.shape[0], t.shape[2]
    i, q, offset = np.empty((F, n)), np.empty((F, n)), np.empty((F, n))
    _kernels.tof_phasors_offset(src, i, q, offset, kernel_threads(workers, F * n))
    return i, q, offset


def denoise_phasors(i, q, sites, *, block=1, window=5, use=None, extra=(),
                    workers=None):
    """Mean of ``I + iQ`` over the Z measurements of a window (paper Fig. 17).

    The paper replaces the ToF ISP's 3x3 averaging filter by a 5x5 kernel in
    which only the Z sites count. Measurement ``m`` enters the mean of
    measurement ``n`` when both their top-left sites lie within
    ``h = (window // 2) * block`` pixels of each other in rows and in columns:

    * Mask1 (``block = 1``, Z sites every 2 pixels): ``h = 2``, the paper's
      5x5 window, which holds 3x3 = 9 Z sites.
    * Mask2 (``block = 2``, one 2x2 Z pixel every 4 pixels): a literal 5x5
      pixel window around a Z pixel holds no other Z pixel, so the window is
      measured in Z-pixel cells: ``h = 4`` pixels, the 3x3 = 9 nearest Z
      pixels (a 12x12-pixel footprint). The same rule gives the 1x5 row of
      Z pixels of the ``rows`` pattern (Z rows 6 pixels apart).

    The mean is taken on the phasor (I, Q), not on the wrapped phase, so a
    phase near 0 / 2 pi averages correctly and each measurement weighs by its
    amplitude. Measurements with ``use = False`` (saturated) stay out of
    every mean; at the frame edges the window holds fewer measurements.

    A C kernel (csrc/tof_filter.c, ``rgbz_tof_box``) on the grid of the
    measurements: separable sums, rows then columns, each in the order of the
    window's offsets, so the same bits as the NumPy code it replaced (kept in
    tests/_reference/tof.py and held to the kernel there).

    Parameters
    ----------
    i, q : ndarray, shape (F, n)
        Components per frequency (see :func:`phasors`).
    sites : (rows, cols) arrays of int, shape (n,), or SiteGrid
        Top-left pixel of every measurement (``ToFTaps.sites``), or their
        grid (:class:`~rgbz_fast.tof._filters.SiteGrid`, built once).
    block : {1, 2}
        Z pixel size in colour pixels.
    window : int
        Odd window size in Z-pixel cells (5: the paper's kernel).
    use : ndarray of bool, shape (n,), optional
        Measurements allowed into the means (default: all).
    extra : tuple of ndarray, shape (F, n) or (n,)
        More per-measurement values averaged with the same weights (e.g. the
        offset).
    workers : int, optional
        Threads of the C kernel (None or -1: all cores); the result does not
        depend on it.

    Returns
    -------
    i_mean, q_mean : ndarray of float64, shape (F, n)
    count : ndarray of float64, shape (n,)
        Measurements in each mean (0 where every one was excluded; the means
        are 0 there).
    extra_mean : list of ndarray
        The means of ``extra``.
    """
    i = np.ascontiguousarray(as_array(i, "i", dtype=np.float64))
    q = np.ascontiguousarray(as_array(q, "q", dtype=np.float64))
    if i.ndim != 2 or q.shape != i.shape:
        raise ValueError(f"i, q: expected two arrays of the same shape (F, n), got "
                         f"{i.shape} and {q.shape}")
    n = i.shape[1]
    block = check_block(block, "block")
    if isinstance(sites, SiteGrid):
        grid = sites
        if grid.n != n:
            raise ValueError(f"sites: expected two arrays of shape ({n},), got ({grid.n},)")
    else:
        rows, cols = (as_array(a, "sites") for a in as_list(sites, "sites", "(rows, cols)")[:2])
        if rows.shape != (n,) or cols.shape != (n,):
            raise ValueError(f"sites: expected two arrays of shape ({n},), got {rows.shape} "
                             f"and {cols.shape}")
        grid = SiteGrid((rows, cols), block)                    # integers, none twice
    window = _check_window(window)
    use = np.ones(n, bool) if use is None else as_array(use, "use", dtype=bool)
    if use.shape != (n,):
        raise ValueError(f"use: expected shape ({n},), got {use.shape}")
    extra = [np.ascontiguousarray(as_array(e, "extra", dtype=np.float64))
             for e in as_list(extra, "extra")]
    F = i.shape[0]
    for k, e in enumerate(extra):
        if e.shape not in ((F, n), (n,)):
            raise ValueError(f"extra: array {k} has shape {e.shape}; expected ({F}, {n}) or "
                             f"({n},), the shape of i or one value per measurement")
    check_phasor_values((i, q), "i, q")
    check_phasor_values(extra, "extra", "values")
    return box_mean(i, q, grid, block, window, use, extra, check_workers(workers))


def box_mean(i, q, grid, block, window, use, extra, nthreads):
    """:func:`denoise_phasors` on checked arguments (the ToF ISP's own phasors, from checked
    taps): C-contiguous float64 ``i``, ``q`` (F, n) and ``extra``, a SiteGrid, a bool
    ``use`` (n,)."""
    n = i.shape[1]
    radius = (window // 2) * block
    # the offsets of the window that link some pair of grid lines (as the NumPy code took them)
    offs = [np.array([a for a, *_ in _axis_offsets(u, radius)], np.int64)
            for u in (grid.rows_u, grid.cols_u)]
    F = i.shape[0]
    i_mean, q_mean = np.empty((F, n)), np.empty((F, n))
    rest = [np.empty(e.shape) for e in extra]
    planes = [p for p in i] + [p for p in q]
    outs = [p for p in i_mean] + [p for p in q_mean]
    for e, m in zip(extra, rest):
        planes += [p for p in e] if e.ndim == 2 else [e]
        outs += [p for p in m] if e.ndim == 2 else [m]
    weight = None if use.all() else use.astype(np.float64)
    count = np.empty(grid.shape)
    if grid.full:
        if weight is not None:
            weight = weight.reshape(grid.shape)
        _kernels.tof_box(planes, outs, grid.rows_u, grid.cols_u, offs[0], offs[1], radius,
                         weight, count, nthreads)
        return i_mean, q_mean, count.reshape(n), rest
    # measurements with holes between them: the values on the grid (0 in a hole, which the
    # weight keeps out), the means taken back
    weight = grid.to_grid(use.astype(np.float64), 0.0)
    cells = [np.ascontiguousarray(grid.to_grid(p, 0.0)).reshape(-1) for p in planes]
    means = [np.empty(grid.shape[0] * grid.shape[1]) for _ in planes]
    _kernels.tof_box(cells, means, grid.rows_u, grid.cols_u, offs[0], offs[1], radius,
                     weight, count, nthreads)
    for m, out in zip(means, outs):
        out[...] = grid.from_grid(m.reshape(grid.shape))
    return i_mean, q_mean, grid.from_grid(count), rest


def unambiguous_range(frequencies):
    """``c / (2 gcd(f_i))`` in metres, the frequencies rounded to whole Hz (inf if they all
    round to 0 Hz).

    Depths that differ by this much give the same phases at every frequency: no
    unwrapping can tell them apart (:attr:`rgbz_fast.ToFSensor.unambiguous_range`).
    """
    g = 0
    for v in check_frequencies(frequencies, "frequencies"):
        g = math.gcd(g, int(round(float(v))))
    return SPEED_OF_LIGHT / (2 * g) if g else math.inf


def _search_range(f, max_range):
    """The validated unwrapping range (m) of frequencies ``f``: a search the kernel can finish.

    None: the unambiguous range, unless it holds more than :data:`MAX_WRAPS` wraps of the
    base frequency (nearly coprime frequencies): then the caller must choose. An explicit
    range may not exceed the unambiguous range (the search would only repeat itself:
    depths one range apart cost the same) nor :data:`MAX_WRAPS` base wraps.
    """
    amb = SPEED_OF_LIGHT / (2 * float(f.min()))
    cap = MAX_WRAPS * amb
    rng = unambiguous_range(f)
    mhz = ", ".join(f"{v / 1e6:.9g}" for v in f)

    def wraps(r):
        return max(1, math.ceil(r / amb - 1e-12))

    if max_range is None:
        if rng > cap:
            raise ValueError(
                f"frequencies: the unambiguous range of {mhz} MHz is {rng:.6g} m, "
                f"{rng / amb:.3g} wraps of the {amb:.6g} m interval of the lowest frequency; "
                f"the search stops at {MAX_WRAPS} (nearly coprime frequencies): pass "
                f"max_range= (at most {cap:.6g} m) for the distances you expect")
        return _whole_wraps(rng, amb)
    max_range = check_number(max_range, "max_range", lo=0, lo_open=True)
    if max_range > rng * (1 + 1e-9):
        raise ValueError(
            f"max_range: {max_range:g} m is beyond the {rng:.6g} m unambiguous range of "
            f"{mhz} MHz; farther depths alias onto nearer ones (the search would only "
            f"repeat), so it must be at most that")
    if wraps(max_range) > MAX_WRAPS:
        raise ValueError(
            f"max_range: {max_range:g} m holds {wraps(max_range)} wraps of the {amb:.6g} m "
            f"interval of the lowest frequency; the search stops at {MAX_WRAPS} "
            f"(max_range <= {cap:.6g} m)")
    return _whole_wraps(max_range, amb)


def _whole_wraps(max_range, amb):
    """``max_range``, or ``k * amb`` when it lies a hair (< 1e-6 of a wrap) above ``k`` whole
    wraps of the lowest frequency's interval ``amb``: the kernel searches ``ceil(max_range /
    amb)`` wraps, and a frequency a fraction of a Hz off a whole number (80 MHz + 0.4 Hz)
    puts the unambiguous range, computed from whole Hz, 2e-8 of a wrap above 4: a fifth
    wrap past that range held aliases of equal cost, and the far one took 75 % of the
    measurements of a test scene, 7.49 m too far."""
    n = max_range / amb
    k = round(n)
    if k >= 1 and n - 1e-12 > k and n - k < 1e-6:
        return k * amb
    return max_range


def _check_unwrap_args(phase_rows, frequencies, weights, max_range):
    """(frequencies, weights, max_range) as the kernels take them, or a ValueError."""
    try:
        f = check_frequencies(frequencies, "frequencies")       # TypeError: not numbers
    except ValueError:
        f = None
    if f is None or f.shape != (phase_rows,):
        raise ValueError(f"frequencies: expected {phase_rows} positive values in Hz, got "
                         f"{frequencies!r}")
    if phase_rows > _kernels.TOF_MAX_FREQS:
        raise ValueError(f"phase: at most {_kernels.TOF_MAX_FREQS} frequencies, got "
                         f"{phase_rows}")
    w = f ** 2 if weights is None else \
        check_image(weights, "weights").astype(np.float64).reshape(-1)
    if (w.shape != f.shape or not np.all(np.isfinite(w)) or np.any(w < 0) or w.sum() <= 0
            or not np.isfinite(w.sum())):
        raise ValueError(f"weights: expected {f.size} non-negative values, not all 0, got "
                         f"{weights!r}")
    return np.ascontiguousarray(f), np.ascontiguousarray(w), _search_range(f, max_range)


def _phase_error(ph):
    """The ValueError for phases the unwrap kernel refused (it checks them as it reads them, so
    this extra pass runs on the error path only)."""
    if not np.all(np.isfinite(ph)):
        return ValueError("phase: holds NaN or infinite values; expected finite data")
    return ValueError(f"phase: values span [{float(ph.min())!r}, {float(ph.max())!r}]; expected "
                      f"wrapped phases in [0, 2 pi) (as demodulate returns them)")


def unwrap(phase, frequencies, *, weights=None, max_range=None, workers=None):
    """Multi-frequency phase unwrapping to a distance (C kernel).

    Brute force over the wrap counts of the frequency with the longest
    ambiguity interval ``c / (2 f)``; every other frequency takes the wrap
    count nearest to that candidate; the candidate with the smallest
    weighted squared distance residual wins. The distance is the weighted
    mean of the per-frequency distances.

    Parameters
    ----------
    phase : ndarray, shape (F, n)
        Wrapped phases in [0, 2 pi) (:func:`demodulate`'s). Anything else,
        NaN included, raises ValueError (checked inside the kernel: no extra
        pass over the data).
    frequencies : array_like, shape (F,)
        Modulation frequencies in Hz (at most 16).
    weights : array_like, shape (F,), optional
        Default ``f_i^2``: the inverse variance of each frequency's distance
        for equal phase noise.
    max_range : float, optional
        Largest distance searched (m): at most the unambiguous range
        ``c / (2 gcd(f_i))`` (frequencies rounded to whole Hz; beyond it the
        search only repeats itself) and at most :data:`MAX_WRAPS` (1024)
        wraps of the lowest frequency. Default: the unambiguous range; when
        that is more than :data:`MAX_WRAPS` wraps (nearly coprime
        frequencies such as 80 MHz + 1 Hz and 100 MHz: 1.5e8 m) a ValueError
        naming ``frequencies`` asks for an explicit ``max_range``.
    workers : int, optional
        Threads (None or -1: all cores).

    Returns
    -------
    depth : ndarray of float64, shape (n,)
        Metres.
    residual : ndarray of float64, shape (n,)
        Weighted RMS of the per-frequency distances about the candidate (m):
        small when the frequencies agree.
    wraps : ndarray of int32, shape (n,)
        Wrap count of the base frequency.

    Raises
    ------
    ValueError
        Malformed phases (shape, NaN, outside [0, 2 pi)), frequencies, weights
        or ``max_range`` (see above); the message names the parameter.
    """
    ph = as_array(phase, "phase", dtype=np.float64)
    if ph.ndim != 2:
        raise ValueError(f"phase: expected shape (F, n), got {ph.shape}")
    f, w, max_range = _check_unwrap_args(ph.shape[0], frequencies, weights, max_range)
    ph = np.ascontiguousarray(ph)
    n = ph.shape[1]
    depth = np.empty(n)
    residual = np.empty(n)
    wraps = np.empty(n, np.int32)
    if not _kernels.tof_unwrap(ph, f, w, max_range, depth, residual, wraps,
                               check_workers(workers)):
        raise _phase_error(ph)
    return depth, residual, wraps


def demodulate_unwrap(taps, frequencies, *, weights=None, max_range=None, workers=None):
    """Demodulation and unwrapping fused in one C pass per measurement.

    The same results as ``demodulate(taps)`` followed by ``unwrap(phase,
    frequencies, ...)`` (phase, amplitude and offset bit for bit; depth and
    residual to rounding), without the intermediate arrays: the kernel
    demodulates a block of 128 measurements at every frequency into a scratch
    buffer that stays in cache and unwraps it there.

    Parameters
    ----------
    taps : ndarray, shape (F, 4, n)
        As :func:`demodulate`.
    frequencies, weights, max_range, workers
        As :func:`unwrap`.

    Returns
    -------
    depth, residual : ndarray of float64, shape (n,)
    wraps : ndarray of int32, shape (n,)
    phase, amplitude, offset : ndarray of float64, shape (F, n)
    """
    t = _check_taps(taps)
    f, w, max_range = _check_unwrap_args(t.shape[0], frequencies, weights, max_range)
    if t.dtype not in (np.uint16, np.float32, np.float64):
        t = t.astype(np.float64)
    t = np.ascontiguousarray(t)
    F, _, n = t.shape
    depth = np.empty(n)
    residual = np.empty(n)
    wraps = np.empty(n, np.int32)
    phase, amp, off = (np.empty((F, n)) for _ in range(3))
    _kernels.tof_depth(t, f, w, max_range, depth, residual, wraps, phase, amp, off,
                       workers=check_workers(workers))
    return depth, residual, wraps, phase, amp, off

