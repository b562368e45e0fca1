"""The i-ToF ISP: four-tap demodulation, edge-aware denoise, phase unwrapping, depth.

Paper §5.1.4 and Fig. 17: the depth is computed at the Z measurements only
(no depth is interpolated at the colour sites); the paper's ISP turns its 3x3
averaging filter into a 5x5 kernel in which only the Z sites count
(``denoise="box"``). The default denoise is edge-aware instead.

Chain (:func:`tof_depth`; every stage is also a function of its own)::

    taps (F, 4, n) ─► [calibration: dark offsets, per-measurement phase offsets]
                   ─► I, Q per frequency (demodulate, phasors)
                   ─► denoise_phasors_bilateral (C; default) or denoise_phasors (the
                      paper's box), saturated measurements left out of every mean
                   ─► phase = atan2(Q, I) in [0, 2 pi) ─► [cyclic-error correction]
                   ─► unwrap (C, weights f_i^2): depth, residual, wrap count
                   ─► sigma (predicted depth noise), implied reflectance
                   ─► validity: saturated, low signal, inconsistent, flying, out of range

Without the denoise and the calibration, demodulation and unwrapping run as one
fused C pass (:func:`demodulate_unwrap`); otherwise the atan2 of the averaged
phasors and the unwrapping do.

Conventions (docs/guide/sensor.md): ``I = A0 - A2``, ``Q = A3 - A1``,
``phase = atan2(Q, I)`` wrapped to [0, 2 pi), ``amplitude = |I + iQ| / 2`` and
``offset = mean(A_k)`` in DN; ``distance = c phase / (4 pi f) + m c / (2 f)``.
The choices are explained in docs/guide/isp.md and measured in docs/reports/isp.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _kernels
from .._sensors import SPEED_OF_LIGHT
from .._validate import (as_array, as_list, check_choice, check_fill, check_frequencies,
                         check_block, check_image, check_number, check_sites, check_workers)
from ._calibration import ToFCalibration, as_taps
from ._filters import (SiteGrid, _axis_offsets, _check_odd, denoise_phasors_bilateral,
                       flying_pixels)
from ._noise import tap_variance

__all__ = ["ToFISP", "ToFDepth", "tof_depth", "demodulate", "phasors", "denoise_phasors",
           "unwrap", "demodulate_unwrap", "unambiguous_range", "MAX_WRAPS",
           "FLAG_SATURATED", "FLAG_LOW_SIGNAL", "FLAG_INCONSISTENT", "FLAG_FLYING",
           "FLAG_OUT_OF_RANGE"]

#: most wrap counts of the base frequency (the one with the longest ambiguity interval
#: ``c / (2 f)``) that :func:`unwrap` searches per measurement: ``max_range`` may not exceed
#: ``MAX_WRAPS * c / (2 min f)`` (csrc/rgbz.h, RGBZ_TOF_MAX_WRAPS). The cost of the search
#: is linear in the count (at 1024 with two frequencies: 0.4 us per measurement and
#: thread), while any practical frequency set needs a handful (80/100/120 MHz: 4).
MAX_WRAPS = int(_kernels.TOF_MAX_WRAPS)

#: bits of :attr:`ToFDepth.flags`: a tap of the measurement reached full scale (or the
#: sensor flagged it saturated) at some frequency
FLAG_SATURATED = 1
#: the signal-to-noise ratio or the amplitude is below the threshold at some frequency
FLAG_LOW_SIGNAL = 2
#: the frequencies disagree: the unwrapping residual exceeds ``max_residual``
FLAG_INCONSISTENT = 4
#: at a depth discontinuity: a second difference of the depths through the measurement or an
#: immediate Z neighbour exceeds ``flying_step`` (and 2 sigma), so the measurement may mix
#: two surfaces (a flying pixel)
FLAG_FLYING = 8
#: the depth is < 0 or within 5 sigma of ``max_range`` or beyond, or implies a reflectance below
#: ``min_reflectance``: most likely a surface beyond the unambiguous range, aliased
FLAG_OUT_OF_RANGE = 16


# --------------------------------------------------------------------------- checks
def _check_taps(taps, name="taps"):
    t = as_array(taps, name)
    if t.ndim != 3 or t.shape[1] != 4 or t.shape[0] < 1:
        raise ValueError(f"{name}: expected shape (F, 4, n_sites), got {t.shape}")
    if t.dtype == np.bool_ or not (np.issubdtype(t.dtype, np.integer)
                                   or np.issubdtype(t.dtype, np.floating)):
        raise TypeError(f"{name}: expected real numbers, got dtype {t.dtype}")
    if np.issubdtype(t.dtype, np.floating) and not np.all(np.isfinite(t)):
        raise ValueError(f"{name}: holds NaN or infinite values; expected finite data")
    return t


def _check_window(window):
    return _check_odd(window, "window")


# --------------------------------------------------------------------------- stages
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


def _phasors_offset(t):
    """I, Q and the offset (F, n) float64 of checked taps, with the C kernel's arithmetic.

    ``offset = 0.25 * ((A0 + A1) + (A2 + A3))`` in float64, as csrc/tof.c sums it.
    """
    i = np.subtract(t[:, 0], t[:, 2], dtype=np.float64)
    q = np.subtract(t[:, 3], t[:, 1], dtype=np.float64)
    offset = np.add(t[:, 0], t[:, 1], dtype=np.float64)
    offset += np.add(t[:, 2], t[:, 3], dtype=np.float64)
    offset *= 0.25
    return i, q, offset


def denoise_phasors(i, q, sites, *, block=1, window=5, use=None, extra=()):
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

    Parameters
    ----------
    i, q : ndarray, shape (F, n)
        Components per frequency (see :func:`phasors`).
    sites : (rows, cols) arrays of int, shape (n,)
        Top-left pixel of every measurement (``ToFTaps.sites``).
    block : {1, 2}
        Z pixel size in colour pixels.
    window : int
        Odd window size in Z-pixel cells (5: the paper's kernel).
    use : ndarray of bool, shape (n,), optional
        Measurements allowed into the means (default: all).
    extra : tuple of ndarray, shape (F, n) or (n,)
        More per-measurement values averaged with the same weights (e.g. the
        offset).

    Returns
    -------
    i_mean, q_mean : ndarray of float64, shape (F, n)
    count : ndarray of float64, shape (n,)
        Measurements in each mean (0 where every one was excluded; the means
        are 0 there).
    extra_mean : list of ndarray
        The means of ``extra``.
    """
    i = as_array(i, "i", dtype=np.float64)
    q = as_array(q, "q", dtype=np.float64)
    if i.ndim != 2 or q.shape != i.shape:
        raise ValueError(f"i, q: expected two arrays of the same shape (F, n), got "
                         f"{i.shape} and {q.shape}")
    n = i.shape[1]
    rows, cols = (as_array(a, "sites") for a in as_list(sites, "sites", "(rows, cols)")[:2])
    if rows.shape != (n,) or cols.shape != (n,):
        raise ValueError(f"sites: expected two arrays of shape ({n},), got {rows.shape} and "
                         f"{cols.shape}")
    rows, cols = check_sites((rows, cols), "sites")             # integers, none twice
    block = check_block(block, "block")
    window = _check_window(window)
    use = np.ones(n, bool) if use is None else as_array(use, "use", dtype=bool)
    if use.shape != (n,):
        raise ValueError(f"use: expected shape ({n},), got {use.shape}")
    extra = [as_array(e, "extra", dtype=np.float64) for e in as_list(extra, "extra")]
    planes = [p for p in i] + [p for p in q]
    for e in extra:
        planes += [p for p in e] if e.ndim == 2 else [e]
    radius = (window // 2) * block
    # compress the measurements onto the grid of their distinct rows and columns
    ur, ri = np.unique(rows, return_inverse=True)
    uc, ci = np.unique(cols, return_inverse=True)
    row_offs = _axis_offsets(ur, radius)
    col_offs = _axis_offsets(uc, radius)
    weight = None if use.all() else use.astype(np.float64)
    # Mask1, Mask2, rows: the measurements fill the compressed grid in row-major order
    full = (n == ur.size * uc.size and np.array_equal(ri, np.arange(n) // uc.size)
            and np.array_equal(ci, np.arange(n) % uc.size))

    def box(values):
        if weight is not None:
            values = values * weight
        if full:
            g = values.reshape(ur.size, uc.size)
        else:
            g = np.zeros((ur.size, uc.size))
            g[ri, ci] = values
        tmp = np.zeros_like(g)
        for a, lo, hi, ok in row_offs:
            tmp[lo:hi] += g[lo + a:hi + a] if ok.all() else g[lo + a:hi + a] * ok[:, None]
        out = np.zeros_like(g)
        for a, lo, hi, ok in col_offs:
            out[:, lo:hi] += tmp[:, lo + a:hi + a] if ok.all() else tmp[:, lo + a:hi + a] * ok
        return out.reshape(-1) if full else out[ri, ci]

    count = box(np.ones(n))
    inv = np.divide(1.0, count, out=np.zeros(n), where=count > 0)
    means = [box(p) * inv for p in planes]
    F = i.shape[0]
    i_mean = np.stack(means[:F])
    q_mean = np.stack(means[F:2 * F])
    rest, k = [], 2 * F
    for e in extra:
        m = e.shape[0] if e.ndim == 2 else 1
        rest.append(np.stack(means[k:k + m]) if e.ndim == 2 else means[k])
        k += m
    return i_mean, q_mean, count, rest


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
    """The validated unwrapping range (m) of frequencies ``f`` (B2).

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
        return rng
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
    """The ValueError for phases the unwrap kernel refused (B3); only on the error path."""
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


# --------------------------------------------------------------------------- result
@dataclass(frozen=True, eq=False)
class ToFDepth:
    """Output of the ToF ISP: one value per Z measurement.

    Attributes
    ----------
    depth : ndarray of float64, shape (n,)
        Distance in metres (every measurement; trust it where ``valid``).
    residual : ndarray of float64, shape (n,)
        Weighted RMS disagreement of the frequencies after unwrapping (m).
    wraps : ndarray of int32, shape (n,)
        Wrap count of the base (lowest) frequency.
    phase, amplitude, offset : ndarray of float64, shape (F, n)
        Phase in [0, 2 pi) and amplitude ``|I + iQ| / 2`` (DN) after the
        denoise (and the calibration); offset ``mean(A_k)`` (DN, raw).
    snr : ndarray of float64, shape (n,)
        Smallest over the frequencies of ``|I + iQ| / sigma_I``, with
        ``sigma_I`` the noise of the (averaged) I component from the sensor's
        noise model. The phase noise is about ``1 / snr`` radians.
    sigma : ndarray of float64, shape (n,)
        Predicted noise (standard deviation, m) of ``depth``: the phase
        noise of every frequency through the unwrapping's weighted mean.
    reflectance : ndarray of float64, shape (n,)
        The NIR reflectance that the amplitude implies at the measured
        distance (the sensor's radiometry, mean over the frequencies; 0 where
        the depth is <= 0). A depth beyond the unambiguous range aliases to a
        shorter one and implies a reflectance ``(d_alias / d_true)^2`` times
        too small.
    count : ndarray of float64, shape (n,)
        Measurements averaged into each one: the window's count (box), the
        effective number ``(sum w)^2 / sum w^2`` (bilateral), 1 without
        denoise.
    valid : ndarray of bool, shape (n,)
        ``flags == 0``.
    flags : ndarray of uint8, shape (n,)
        :data:`FLAG_SATURATED`, :data:`FLAG_LOW_SIGNAL`,
        :data:`FLAG_INCONSISTENT`, :data:`FLAG_FLYING`,
        :data:`FLAG_OUT_OF_RANGE` (bitwise or).
    frequencies : ndarray, shape (F,)
    sites : (rows, cols)
    block : int
    shape : (rows, cols)
        Frame shape, for :meth:`to_frame`.
    """

    depth: np.ndarray
    residual: np.ndarray
    wraps: np.ndarray
    phase: np.ndarray
    amplitude: np.ndarray
    offset: np.ndarray
    snr: np.ndarray
    sigma: np.ndarray
    reflectance: np.ndarray
    count: np.ndarray
    valid: np.ndarray
    flags: np.ndarray
    frequencies: np.ndarray
    sites: tuple
    block: int
    shape: tuple

    _FIELDS = ("depth", "residual", "snr", "sigma", "reflectance", "valid", "flags", "wraps",
               "count", "phase", "amplitude", "offset")

    @property
    def n_sites(self):
        return int(self.depth.shape[0])

    def to_frame(self, values="depth", fill=np.nan):
        """Paint per-measurement values onto the frame (every cell of each Z pixel).

        Parameters
        ----------
        values : str or ndarray
            A field name (``"depth"``, ``"residual"``, ``"snr"``, ``"sigma"``,
            ``"reflectance"``, ``"valid"``, ``"flags"``, ``"wraps"``,
            ``"count"``, ``"phase"``, ``"amplitude"``, ``"offset"``) or an
            array of shape (n,) or (F, n).
        fill : scalar
            Value of the pixels that hold no Z measurement (NaN by default;
            use 0 or False for integer and boolean fields).

        Returns
        -------
        ndarray, shape (rows, cols) or (F, rows, cols)
        """
        if isinstance(values, str):
            if values not in self._FIELDS:
                raise ValueError(f"values: unknown field {values!r}")
            v = getattr(self, values)
        else:
            v = as_array(values, "values")
        fill = check_fill(fill)
        n = self.n_sites
        if v.shape[-1:] != (n,) or v.ndim > 2:
            raise ValueError(f"values: expected shape ({n},) or (F, {n}), got {v.shape}")
        dtype = np.result_type(v.dtype, np.min_scalar_type(fill))
        out = np.full(v.shape[:-1] + tuple(self.shape), fill, dtype=dtype)
        r, c = self.sites
        for dr in range(self.block):
            for dc in range(self.block):
                out[..., r + dr, c + dc] = v
        return out

    def depth_map(self, fill=np.nan):
        """Depth (m) on the frame where valid; ``fill`` elsewhere."""
        fill = check_fill(fill)
        return self.to_frame(np.where(self.valid, self.depth, fill), fill)

    def __repr__(self):
        return (f"ToFDepth({self.n_sites} measurements, block {self.block}, "
                f"{int(self.valid.sum())} valid)")


# --------------------------------------------------------------------------- the chain
_DENOISE = ("bilateral", "box", "none")


def _check_denoise(denoise):
    """'bilateral', 'box' or 'none'; True is the default ('bilateral'), False is 'none'."""
    if isinstance(denoise, (bool, np.bool_)):
        return "bilateral" if denoise else "none"
    return check_choice(denoise, _DENOISE, "denoise")


def _check_calibration(calibration):
    if calibration is not None and not isinstance(calibration, ToFCalibration):
        raise TypeError(f"calibration: expected a ToFCalibration or None, got "
                        f"{type(calibration).__name__}")
    return calibration


@dataclass(frozen=True)
class ToFISP:
    """Parameters of the ToF ISP (see :func:`tof_depth` for each one).

    Attributes
    ----------
    denoise : {"bilateral", "box", "none"}
        The edge-aware phasor mean (default), the paper's plain average
        (Fig. 17) or none.
    window : int or None
        Odd window size in Z-pixel cells; None: 9 (the 5x5 nearest Z
        measurements) for the bilateral denoise, 5 (the paper's 3x3) for
        the box.
    range_scale : float
        Range scale ``h`` of the bilateral weights (2).
    min_snr : float
        Smallest per-frequency ``|I + iQ| / sigma_I`` of a valid measurement
        (4: on noisy walls the unwrapping errs on 0.07 % of the measurements
        at SNR 4-5 and on 1 of 154 000 above 5, see docs/reports/isp.md).
    min_amplitude : float
        Smallest per-frequency amplitude (DN) of a valid measurement (0: only
        the SNR test).
    max_residual : float
        Largest unwrapping residual (m) of a valid measurement (0.15: a wrong
        wrap combination of 80/100/120 MHz leaves about 0.17 m or more).
        Retune it for other frequency sets.
    max_sigma, flying_step, min_reflectance : float or None
        The validity tests of depth noise, flying pixels and aliasing
        (:func:`tof_depth`).
    max_range : float or None
        Unwrapping range (m); None: the unambiguous range of the frequencies.
    calibration : ToFCalibration or None
        Phase calibration applied to the taps (:func:`~rgbz_fast.tof.calibrate`).
    """

    denoise: str = "bilateral"
    window: int | None = None
    range_scale: float = 2.0
    min_snr: float = 4.0
    min_amplitude: float = 0.0
    max_residual: float = 0.15
    max_sigma: float | None = 0.015
    flying_step: float | None = 0.05
    min_reflectance: float = 0.05
    max_range: float | None = None
    calibration: ToFCalibration | None = None

    def __post_init__(self):
        object.__setattr__(self, "denoise", _check_denoise(self.denoise))
        if self.window is not None:
            _check_window(self.window)
        check_number(self.range_scale, "range_scale", lo=0, lo_open=True)
        check_number(self.min_snr, "min_snr", lo=0)
        check_number(self.min_amplitude, "min_amplitude", lo=0)
        check_number(self.max_residual, "max_residual", lo=0, lo_open=True)
        check_number(self.max_sigma, "max_sigma", lo=0, lo_open=True, allow_none=True)
        check_number(self.flying_step, "flying_step", lo=0, lo_open=True, allow_none=True)
        check_number(self.min_reflectance, "min_reflectance", lo=0, hi=1)
        check_number(self.max_range, "max_range", lo=0, lo_open=True, allow_none=True)
        _check_calibration(self.calibration)

    def run(self, tof, *, workers=None):
        """Depth, amplitude and validity of every Z measurement of ``tof``."""
        return tof_depth(tof, denoise=self.denoise, window=self.window,
                         range_scale=self.range_scale, min_snr=self.min_snr,
                         min_amplitude=self.min_amplitude, max_residual=self.max_residual,
                         max_sigma=self.max_sigma, flying_step=self.flying_step,
                         min_reflectance=self.min_reflectance, max_range=self.max_range,
                         calibration=self.calibration, workers=workers)


def _depth_sigma(amp, var, frequencies):
    """Depth noise (m) of the f^2-weighted mean of the per-frequency distances.

    ``sigma^2 = sum_f (w_f c / (4 pi f))^2 var_f / |I + iQ|_f^2 / (sum w)^2``, the phase
    variance ``var / |I + iQ|^2`` capped at ``pi^2 / 3``, that of a phase that is all noise
    (uniform on the circle). In place on one (F, n) temporary: it runs on every frame.
    """
    f = np.asarray(frequencies, np.float64)
    w = f * f
    scale = (w * SPEED_OF_LIGHT / (4 * np.pi * f) / w.sum()) ** 2
    t = np.multiply(amp, amp)
    t *= 4.0
    with np.errstate(divide="ignore", invalid="ignore"):
        np.divide(var, t, out=t)                          # phase variance; inf / nan at 0
    np.fmin(t, np.pi * np.pi / 3.0, out=t)               # fmin: a NaN takes the cap
    t *= scale[:, None]
    return np.sqrt(t.sum(axis=0))


def _implied_reflectance(depth, amp, sensor, block):
    """NIR reflectance that the amplitude implies at ``depth`` (the sensor's radiometry)."""
    ok = depth > 0
    d = np.where(ok, depth, 1.0)
    s1, _ = sensor._cell_electrons(d, 1.0, sensor.pixel_pitch_um or 2.8)
    contrast = sensor.contrasts.reshape(-1, 1) * float(np.mean(sensor.tap_contrast))
    model = sensor.system_gain * 0.25 * contrast * (s1 * block * block)[None]
    rho = (amp / model).mean(axis=0)
    return np.where(ok, rho, 0.0)


def tof_depth(tof, *, denoise="bilateral", window=None, range_scale=2.0, min_snr=4.0,
              min_amplitude=0.0, max_residual=0.15, max_sigma=0.015, flying_step=0.05,
              min_reflectance=0.05, max_range=None, calibration=None, workers=None):
    """The ToF ISP: taps of every Z measurement -> depth, amplitude, validity.

    Parameters
    ----------
    tof : ToFTaps or RawFrame
        The taps (``frame.tof`` of :func:`rgbz_fast.simulate`). The noise
        model and the radiometry use ``tof.sensor`` (system gain, read noise,
        DSNU, PRNU, black level, ambient suppression; source power, lens,
        pixel): the ISP is calibrated for its sensor.
    denoise : {"bilateral", "box", "none"}
        ``"bilateral"`` (default): the edge-aware mean of the phasors over the
        Z measurements of the window, two passes
        (:func:`~rgbz_fast.tof.denoise_phasors_bilateral`); ``"box"``: the
        paper's plain mean (Fig. 17, :func:`denoise_phasors`); ``"none"``.
        True and False mean ``"bilateral"`` and ``"none"``.
    window : int, optional
        Odd window size in Z-pixel cells; default 9 for the bilateral denoise
        (the 5x5 nearest Z measurements) and 5 for the box (the paper's
        5x5-pixel kernel: 3x3 Z measurements).
    range_scale : float
        Range scale of the bilateral weights (2; larger smooths across
        weaker edges).
    min_snr, min_amplitude, max_residual : float
        Validity thresholds: per-frequency SNR (4) and amplitude (0 DN), and
        the unwrapping residual (0.15 m).
    max_sigma : float or None
        Largest predicted depth noise (m) of a valid measurement (0.015: a
        5 cm error is then a 3.3-sigma event, 0.1 % of the valid
        measurements); None: no limit.
    flying_step : float or None
        Depth jump (m) that marks a discontinuity (0.05; see
        :func:`~rgbz_fast.tof.flying_pixels`); None: no flying-pixel test.
    min_reflectance : float
        Smallest NIR reflectance a valid measurement may imply (0.05; 0: no
        test). Depths beyond the unambiguous range alias to shorter ones and
        imply much darker surfaces: see Notes.
    max_range : float, optional
        Unwrapping range in metres (see :func:`unwrap`): default
        ``tof.unambiguous_range``, unless that spans more than
        :data:`MAX_WRAPS` wraps of the lowest frequency (nearly coprime
        frequencies), in which case a ValueError naming ``frequencies`` asks
        for an explicit one; at most the unambiguous range. Depths found
        beyond it are flagged out of range.
    calibration : ToFCalibration, optional
        Per-measurement phase offsets and per-frequency cyclic error
        (:func:`~rgbz_fast.tof.calibrate`), and the taps' dark offsets when
        it holds them. It must have been made for these frequencies and Z
        measurements.
    workers : int, optional
        Threads of the C kernels (None or -1: all cores). The result does
        not depend on it.

    Returns
    -------
    ToFDepth

    Raises
    ------
    ValueError, TypeError
        A frame without taps, malformed taps, thresholds out of range, a
        calibration of another sensor layout, or a ``max_range`` the
        unwrapping cannot search (see above).

    Notes
    -----
    Validity. A measurement is flagged

    * saturated when a tap reached the white level at some frequency, or
      the sensor flagged it (``tof.saturated``): its phase is biased;
    * low-signal when ``snr < min_snr``, the amplitude is below
      ``min_amplitude`` at some frequency, or ``sigma > max_sigma``.
      ``snr = |I + iQ| / sigma_I`` with ``sigma_I^2`` the variance of the
      (averaged) component: ``2 var(A)`` per measurement, ``var(A) = K c +
      K^2 (read^2 + dsnu^2) + 1/12 + (prnu K e)^2`` (shot noise of the
      collected charge ``c``, read noise, DSNU, quantisation and PRNU of a
      tap holding ``e`` electrons, in DN^2), through the denoise's weights;
    * inconsistent when the unwrapping residual exceeds ``max_residual``:
      the frequencies disagree (a wrong unwrap, a mixed return);
    * flying when the depth jumps by more than ``max(flying_step, 2 sigma)``
      within one Z measurement of it (second differences along rows, columns
      and diagonals, usable measurements only; slopes do not count): the
      measurement may mix the two surfaces of a depth edge;
    * out of range when the depth is < 0 or beyond ``max_range - 5 sigma``
      (a guard: a surface just beyond the range reads either ~0 m or, through
      the noise, just below the end), or the implied reflectance is below
      ``min_reflectance``. A surface at ``D``
      beyond the unambiguous range ``U`` gives the phases of ``D - kU`` at
      every frequency -- no test on the phases can see it -- but its
      amplitude is that of a surface ``((D - kU) / D)^2`` times darker: with
      ``rho <= 1`` every ``D < U / (1 - sqrt(min_reflectance))`` (9.66 m for
      80/100/120 MHz and 0.05) is flagged; farther ones only when their signal
      is too low to be valid (docs/reports/isp.md measures both).

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.simulation import Scene
    >>> from rgbz_fast.simulation import simulate
    >>> scene = Scene(np.full((16, 16, 3), 0.5), depth=np.full((16, 16), 1.5))
    >>> result = tof_depth(simulate(scene, "mask1", noise=False).tof)
    >>> bool(np.allclose(result.depth, 1.5, atol=2e-3)), bool(result.valid.all())
    (True, True)
    """
    tof = as_taps(tof, "tof")
    denoise = _check_denoise(denoise)
    window = (9 if denoise == "bilateral" else 5) if window is None else _check_window(window)
    range_scale = check_number(range_scale, "range_scale", lo=0, lo_open=True)
    min_snr = check_number(min_snr, "min_snr", lo=0)
    min_amplitude = check_number(min_amplitude, "min_amplitude", lo=0)
    max_residual = check_number(max_residual, "max_residual", lo=0, lo_open=True)
    max_sigma = check_number(max_sigma, "max_sigma", lo=0, lo_open=True, allow_none=True)
    flying_step = check_number(flying_step, "flying_step", lo=0, lo_open=True,
                               allow_none=True)
    min_reflectance = check_number(min_reflectance, "min_reflectance", lo=0, hi=1)
    calibration = _check_calibration(calibration)
    nthreads = check_workers(workers)

    taps = tof.taps
    n = tof.n_sites
    sensor = tof.sensor
    f, w, max_range = _check_unwrap_args(taps.shape[0], tof.frequencies, None, max_range)
    if calibration is not None:
        calibration.check(tof)
    # max over the 4F taps (uint16 reductions), then one comparison: = any(tap >= white)
    saturated = np.asarray(tof.saturated, bool) | (taps.max(axis=(0, 1)) >= tof.white_level)
    if calibration is not None and calibration.dark is not None:
        taps = np.asarray(taps, np.float64) - calibration.dark[None]
    depth, residual = np.empty(n), np.empty(n)
    wraps = np.empty(n, np.int32)
    grid = None                     # the grid of the Z measurements, built once when needed
    if denoise == "none" and calibration is None:
        depth, residual, wraps, phase, amp, offset = demodulate_unwrap(
            taps, f, max_range=max_range, workers=nthreads)
        count = np.ones(n)
        var = 2.0 * tap_variance(offset, sensor)
    else:
        # one pass over the taps in NumPy (I, Q and the offset exactly as the C kernel
        # computes them), the calibration's offsets, the mean over the window, then one C
        # pass from the phasors
        i, q, offset = _phasors_offset(taps)
        if calibration is not None:
            z = (i + 1j * q) * np.exp(-1j * calibration.deviations)
            i, q = np.ascontiguousarray(z.real), np.ascontiguousarray(z.imag)
        if denoise == "box":
            i, q, count, (off_mean,) = denoise_phasors(i, q, tof.sites, block=tof.block,
                                                       window=window, use=~saturated,
                                                       extra=(offset,))
            noise_offset = np.where(count > 0, off_mean, offset)
            var = 2.0 * tap_variance(noise_offset, sensor) / np.maximum(count, 1.0)
        elif denoise == "bilateral":
            var = 2.0 * tap_variance(offset, sensor)
            grid = SiteGrid(tof.sites, tof.block)
            i, q, var, count = denoise_phasors_bilateral(
                i, q, var, grid, block=tof.block, window=window, use=~saturated,
                range_scale=range_scale, workers=nthreads)
        else:
            count = np.ones(n)
            var = 2.0 * tap_variance(offset, sensor)
        # atan2, amplitude and unwrapping of the phasors in one C pass
        phase, amp = np.empty_like(i), np.empty_like(i)
        if not _kernels.tof_depth_iq(np.ascontiguousarray(i), np.ascontiguousarray(q), f, w,
                                     max_range, depth, residual, wraps, phase, amp,
                                     workers=nthreads):
            raise ValueError("taps: the averaged phasors overflow (|I|, |Q| > 1.8e308)")
        if calibration is not None:
            phase = calibration.correct_phase(phase)
            depth, residual, wraps = unwrap(phase, f, max_range=max_range, workers=nthreads)
    snr = (2.0 * amp / np.sqrt(var)).min(axis=0)
    sigma = _depth_sigma(amp, var, f)
    reflectance = _implied_reflectance(depth, amp, sensor, tof.block)

    flags = np.zeros(n, np.uint8)
    flags[saturated] |= FLAG_SATURATED
    low = (snr < min_snr) | np.any(amp < min_amplitude, axis=0)
    if max_sigma is not None:
        low |= ~(sigma <= max_sigma)
    flags[low] |= FLAG_LOW_SIGNAL
    flags[residual > max_residual] |= FLAG_INCONSISTENT
    if flying_step is not None:
        usable = (flags & (FLAG_SATURATED | FLAG_LOW_SIGNAL)) == 0
        if grid is None:
            grid = SiteGrid(tof.sites, tof.block)
        flags[flying_pixels(depth, sigma, grid, block=tof.block, step=flying_step,
                            usable=usable)] |= FLAG_FLYING
    # a guard of 5 sigma below the end of the range: a surface just beyond it reads either
    # ~0 m (the reflectance test) or, through the noise, just below the end
    out = (depth < 0) | (depth > max_range - 5.0 * sigma) | (reflectance < min_reflectance)
    flags[out] |= FLAG_OUT_OF_RANGE
    return ToFDepth(depth=depth, residual=residual, wraps=wraps, phase=phase, amplitude=amp,
                    offset=offset, snr=snr, sigma=sigma, reflectance=reflectance, count=count,
                    valid=flags == 0, flags=flags,
                    frequencies=np.asarray(tof.frequencies, np.float64).copy(),
                    sites=tuple(np.asarray(a) for a in tof.sites), block=int(tof.block),
                    shape=tuple(tof.shape))
