"""Phase calibration of an i-ToF sensor from a flat-wall sweep: cyclic error and per-pixel offsets.

A real four-tap pixel does not measure ``phi = 4 pi f d / c``: the light and
the demodulation gates are not sinusoids (their harmonics alias onto the
fundamental and bend the phase: the *cyclic* or *wiggling* error, periodic in
the phase), the four gates do not have the same contrast (an error at twice
the phase), and every pixel's clock arrives with its own delay (a per-pixel
phase offset). :func:`calibrate` fits, from frames of a flat wall at known
distances that sweep the phase of every frequency,

.. math::

    \\phi_{meas} - \\phi_{true} = o_{f,n} + g_f(\\phi_{meas} - \\delta_{f,n}),
    \\qquad g_f(\\phi) = \\sum_{k=1}^{K} a_{f,k} \\cos k\\phi + b_{f,k} \\sin k\\phi

per frequency ``f`` and measurement ``n``: a phase offset per measurement and
frequency, ``delta = o - mean_n(o)`` its deviation from the frequency's mean
offset, and a Fourier series of the cyclic error per frequency (no constant
term: that is in the offsets). The distortion acts on the phase the pixel
sees, its delay included, so ``g`` takes the measured phase (less only the
small per-pixel deviation, which the ISP must remove before it averages
neighbours). The ISP applies it in that order (:func:`~rgbz_fast.tof.tof_depth`
with ``calibration=``): the phasors of every measurement are turned by
``-delta`` before the denoise, and the phase of the denoised phasor ``phi'``
becomes ``phi' - g(phi') - mean(o)`` before the unwrapping. ``g`` is applied
to the denoised phase, not to each noisy one: averaging ``g(phi + noise)``
would shrink its k-th harmonic by ``exp(-k^2 sigma^2 / 2)``.
Optionally a dark sweep (the laser off) gives each tap's dark offset above the
black level (DSNU plus dark current), which is subtracted from the taps first.

The fit alternates: the offsets are the weighted circular means over the
frames of ``e - g``; ``g`` is the weighted least-squares fit of ``e - o`` on
the Fourier basis of ``phi_meas - o``; weights are the inverse phase
variances ``|I + iQ|^2 / var(I)`` of the sensor's noise model, saturated
measurements and those below an SNR of 3 left out. Four alternations
converge (the slope of ``g`` is small).

References
----------
.. [1] Lindner and Kolb, "Lateral and depth calibration of PMD-distance sensors": per-pixel offsets and a smooth distance-dependent correction from planar targets (docs/references.bib: lindner2006pmd)
.. [2] Kahlmann et al., "Calibration for increased accuracy of the range imaging camera SwissRanger": the cyclic distance error and its calibration (docs/references.bib: kahlmann2006swissranger)
.. [3] Lange and Seitz, "Solid-state time-of-flight range camera": harmonics of the four-phase sampling (docs/references.bib: lange2001tof)
"""

from __future__ import annotations

import json
import math
import numbers
from dataclasses import dataclass, field, replace

import numpy as np

from .._frame import RawFrame, ToFTaps
from .._sensors import SPEED_OF_LIGHT
from .._validate import (as_list, check_block, check_frequencies, check_image, check_int,
                         check_meta, check_path, check_sites, read_only_state, real_array)
from ..io import atomic_write, read_npz
from ..io._npz import npz_bytes
from ._noise import tap_variance

__all__ = ["ToFCalibration", "calibrate"]

_FORMAT_TAG = "rgbz-fast ToF calibration"
_MIN_SNR = 3.0


@dataclass(frozen=True, eq=False)
class ToFCalibration:
    """What :func:`calibrate` measured; the ToF ISP applies it (``tof_depth(calibration=)``).

    Attributes
    ----------
    frequencies : ndarray, shape (F,)
        Modulation frequencies (Hz) it was measured at.
    offsets : ndarray of float64, shape (F, n)
        Phase offset (rad) of every measurement at every frequency
        (:attr:`mean_offset` and :attr:`deviations` split it).
    coefficients : ndarray of float64, shape (F, K, 2)
        ``(a_k, b_k)`` of the cyclic error ``g_f`` for ``k = 1..K``.
    sites : (rows, cols)
        The Z measurements (top-left pixels) the offsets belong to.
    block : int
    shape : (rows, cols)
        The frame shape.
    dark : ndarray of float64, shape (4, n), or None
        Dark offset of each tap above the black level (DN), or None.
    meta : dict
        ``frames``, ``orders``, ``fit_rms_rad`` (the weighted RMS of the fit's
        residual phase, per frequency) and ``fit_rms_m`` (the same in metres); with
        ``dark``, ``dark_noise_dn2``: the variance (DN^2) of the dark offsets' own
        error (the dark frames' temporal noise over their count and frequencies), a
        fixed offset per tap that the ISP's ``sigma`` takes in place of the DSNU;
        ``dark_bit_depth`` and ``dark_dn_per_electron``: the readout the offsets are in
        (:meth:`check` refuses taps of another).

    Examples
    --------
    >>> import numpy as np
    >>> cal = ToFCalibration(np.array([1e8]), np.zeros((1, 2)), np.zeros((1, 3, 2)),
    ...                      (np.array([0, 0]), np.array([0, 2])), 1, (2, 4))
    >>> cal.cyclic_error(np.array([[0.5, 1.0]])).shape
    (1, 2)
    """

    frequencies: np.ndarray
    offsets: np.ndarray
    coefficients: np.ndarray
    sites: tuple
    block: int
    shape: tuple
    dark: np.ndarray | None = None
    meta: dict = field(default_factory=dict)

    def __setstate__(self, state):          # a pickled or deep-copied copy stays read-only
        read_only_state(self, state)

    def __post_init__(self):
        # own read-only copies (the caller's arrays stay the caller's); every field checked
        # here, where a caller or a file gives it: NaN, 0 or negative frequencies, float or
        # out-of-frame sites, a bool block and any shape were accepted, and a meta that was
        # no dict of lists of numbers made repr fail
        f = check_frequencies(self.frequencies, "frequencies", unique=True)
        rows, cols, span = check_sites(self.sites, "sites", span=True)
        n = rows.size
        off = real_array(self.offsets, "offsets")
        if off.shape != (f.size, n):
            raise ValueError(f"offsets: expected shape ({f.size}, {n}) (frequencies x sites), "
                             f"got {off.shape}")
        coef = real_array(self.coefficients, "coefficients")
        if coef.ndim != 3 or coef.shape[0] != f.size or coef.shape[2] != 2:
            raise ValueError(f"coefficients: expected shape ({f.size}, K, 2), got {coef.shape}")
        for name, a in (("offsets", off), ("coefficients", coef)):
            if not np.all(np.isfinite(a)):
                raise ValueError(f"{name}: holds NaN or infinite values")
        _check_cyclic_amplitude(coef, f)
        dark = None
        if self.dark is not None:
            dark = real_array(self.dark, "dark")
            if dark.shape != (4, n) or not np.all(np.isfinite(dark)):
                raise ValueError(f"dark: expected finite values of shape (4, {n}), got "
                                 f"{dark.shape}")
            _check_dark_range(dark)
        block = check_block(self.block, "block")
        shape = _frame_shape(self.shape, block)
        for label, lo, hi, size in (("rows", *span[:2], shape[0]),
                                    ("cols", *span[2:], shape[1])) if n else ():
            if hi > size - block:              # check_sites refused those < 0
                raise ValueError(f"sites: {label} span [{lo}, {hi}]; a {block}x{block} block "
                                 f"at each must lie inside the {shape[0]}x{shape[1]} frame "
                                 f"({label} <= {size - block})")
        meta = check_meta(self.meta, "meta")
        for a in (f, off, coef, rows, cols) + ((dark,) if dark is not None else ()):
            a.setflags(write=False)
        object.__setattr__(self, "frequencies", f)
        object.__setattr__(self, "offsets", off)
        object.__setattr__(self, "coefficients", coef)
        object.__setattr__(self, "sites", (rows, cols))
        object.__setattr__(self, "block", block)
        object.__setattr__(self, "shape", shape)
        object.__setattr__(self, "dark", dark)
        object.__setattr__(self, "meta", meta)

    @property
    def orders(self):
        """int: K, the highest harmonic of the cyclic-error series."""
        return int(self.coefficients.shape[1])

    def check(self, tof, name="calibration"):
        """ValueError naming ``name`` unless ``tof`` has this calibration's frequencies and sites."""
        tof = as_taps(tof, "tof")
        freqs = np.asarray(tof.frequencies, np.float64).reshape(-1)
        if freqs.shape != self.frequencies.shape or not np.allclose(freqs, self.frequencies,
                                                                    rtol=1e-9, atol=0):
            raise ValueError(f"{name}: measured at {self.frequencies / 1e6} MHz, the taps are at "
                             f"{np.asarray(tof.frequencies) / 1e6} MHz")
        r, c = tof.sites
        if (tuple(tof.shape) != self.shape or int(tof.block) != self.block
                or r.shape != self.sites[0].shape or not np.array_equal(r, self.sites[0])
                or not np.array_equal(c, self.sites[1])):
            raise ValueError(f"{name}: made for {self.sites[0].size} Z measurements of a "
                             f"{self.shape[0]}x{self.shape[1]} frame (block {self.block}), the "
                             f"taps hold {r.size} of a {tof.shape[0]}x{tof.shape[1]} frame "
                             f"(block {tof.block})")
        if self.dark is not None:
            diff = _readout_difference(self.meta.get("dark_bit_depth"),
                                       self.meta.get("dark_dn_per_electron"), tof, "the taps")
            if diff:
                raise ValueError(f"{name}: its dark offsets were measured at another readout "
                                 f"({diff}): they are in that readout's DN")

    @property
    def mean_offset(self):
        """ndarray (F,): the circular mean of the offsets over the measurements (rad)."""
        return np.angle(np.exp(1j * self.offsets).sum(axis=1))

    @property
    def deviations(self):
        """ndarray (F, n): each measurement's offset less the mean, wrapped to (-pi, pi]."""
        return np.angle(np.exp(1j * (self.offsets - self.mean_offset[:, None])))

    def cyclic_error(self, phase):
        """``g_f(phase)`` (rad) for phases of shape (F, ...)."""
        ph = _check_phase(phase, self.frequencies.size)
        k = np.arange(1, self.orders + 1).reshape((1, -1) + (1,) * (ph.ndim - 1))
        a = self.coefficients[:, :, 0].reshape(self.coefficients.shape[:2] + (1,) * (ph.ndim - 1))
        b = self.coefficients[:, :, 1].reshape(a.shape)
        kp = k * ph[:, None]
        return (a * np.cos(kp) + b * np.sin(kp)).sum(axis=1)

    def correct_phase(self, phase):
        """``phase - g(phase) - mean_offset``, wrapped to [0, 2 pi).

        ``phase`` (F, ...) is measured phase less each measurement's
        :attr:`deviations` (the ISP turns the phasors by them before the
        denoise).
        """
        ph = _check_phase(phase, self.frequencies.size)
        mean = self.mean_offset.reshape((-1,) + (1,) * (ph.ndim - 1))
        out = np.mod(ph - self.cyclic_error(ph) - mean, 2 * np.pi)
        out[out >= 2 * np.pi] = 0.0
        return out

    def save(self, path):
        """Write an NPZ file (atomically); returns the path.

        Examples
        --------
        >>> import numpy as np, tempfile, pathlib
        >>> cal = ToFCalibration(np.array([1e8]), np.ones((1, 2)), np.zeros((1, 3, 2)),
        ...                      (np.array([0, 0]), np.array([0, 2])), 1, (2, 4))
        >>> with tempfile.TemporaryDirectory() as d:
        ...     back = ToFCalibration.load(cal.save(pathlib.Path(d) / "cal.npz"))
        >>> back.offsets.tolist(), back.shape
        ([[1.0, 1.0]], (2, 4))
        """
        path = check_path(path, "path")
        header = {"format": _FORMAT_TAG, "block": self.block, "shape": list(self.shape),
                  "meta": _jsonable(self.meta)}
        arrays = {"frequencies": self.frequencies, "offsets": self.offsets,
                  "coefficients": self.coefficients, "rows": self.sites[0],
                  "cols": self.sites[1], "header": np.array(json.dumps(header))}
        if self.dark is not None:
            arrays["dark"] = self.dark
        atomic_write(path, npz_bytes(arrays))
        return path

    @classmethod
    def load(cls, path, *, max_bytes=None):
        """Read a file written by :meth:`save` (ValueError naming ``path`` if it is not one);
        ``max_bytes``: the read limit (:func:`rgbz_fast.io.read_limits`)."""
        path = check_path(path, "path")
        arrays = read_npz(path, "path", required=("header",),      # bounded, no pickles
                          max_bytes=max_bytes)
        try:
            header = json.loads(str(arrays.pop("header")))
        except (ValueError, RecursionError) as exc:
            raise ValueError(f"path: {path} is not a ToF calibration file ({exc})") from None
        if not isinstance(header, dict) or header.get("format") != _FORMAT_TAG:
            raise ValueError(f"path: {path} is not a ToF calibration file")
        try:
            fields = (arrays["frequencies"], arrays["offsets"], arrays["coefficients"],
                      (arrays["rows"], arrays["cols"]), header["block"], header["shape"],
                      arrays.get("dark"), header.get("meta", {}))
        except KeyError as exc:
            raise ValueError(f"path: {path} lacks {exc} (not a ToF calibration file)") from None
        try:            # the values as the file holds them: the class checks every one
            return cls(*fields)
        except (TypeError, ValueError, OverflowError) as exc:
            raise ValueError(f"path: {path} is a damaged ToF calibration file "
                             f"({type(exc).__name__}: {str(exc)[:200]})") from None

    def __repr__(self):
        mhz = ", ".join(f"{f / 1e6:g}" for f in self.frequencies)
        rms = _fit_rms(self.meta.get("fit_rms_m"))
        extra = f", fit RMS {1e3 * rms:.2f} mm" if rms is not None else ""
        return (f"ToFCalibration({self.sites[0].size} measurements, {mhz} MHz, "
                f"{self.orders} harmonics{', dark' if self.dark is not None else ''}{extra})")


#: the largest cyclic-error correction (rad): ``g_f`` is a phase error, taken off a phase on
#: the circle, where a turn of more than a half turn (pi) is a shorter turn the other way: no
#: cyclic error is that large (the harmonics of the tests are 0.05 rad). The bound is on
#: ``sum_k |(a_k, b_k)|``, the largest ``|g_f|`` can be at any phase (the Fourier terms of
#: :meth:`ToFCalibration.cyclic_error`)
CYCLIC_AMPLITUDE_MAX = np.pi

#: the largest dark offset (DN) in magnitude: an offset is a tap's mean less the black level,
#: both codes of the sensor's ADC, so within (-(2**bits), 2**bits); a calibration records no
#: bit depth, so the bound is that of the widest ADC a sensor can have (16 bits,
#: ``check_bit_depth``): 2**16 = 65536 DN
DARK_OFFSET_MAX = float(1 << 16)


def _check_cyclic_amplitude(coef, freqs):
    """A ValueError naming ``coefficients`` when, at some frequency, ``sum_k |(a_k, b_k)|``
    (the largest ``|g_f|`` can be: :meth:`ToFCalibration.cyclic_error` sums the Fourier
    terms) exceeds :data:`CYCLIC_AMPLITUDE_MAX`: coefficients of 1e308 had been accepted, and
    ``g`` overflowed in ``tof_depth`` (``phase: holds NaN or infinite values``)."""
    with np.errstate(over="ignore"):                       # 1e308 terms: inf, refused below
        amp = np.hypot(coef[..., 0], coef[..., 1]).sum(axis=1) if coef.size else \
            np.zeros(coef.shape[0])
    bad = np.flatnonzero(~(amp <= CYCLIC_AMPLITUDE_MAX))
    if bad.size:
        i = int(bad[np.argmax(amp[bad])])
        size = f"= {float(amp[i]):.3g}" if np.isfinite(amp[i]) else "> 1.8e+308"
        raise ValueError(f"coefficients: the cyclic error at {freqs[i] / 1e6:g} MHz reaches "
                         f"sum_k |(a_k, b_k)| {size} rad; a phase correction is at most "
                         f"pi (a half turn)")


def _check_dark_range(dark):
    """A ValueError naming ``dark`` when an offset lies beyond :data:`DARK_OFFSET_MAX` DN
    (1e5 DN had silently changed sigma, 1e308 flagged every measurement)."""
    top = float(np.max(np.abs(dark))) if dark.size else 0.0
    if not top <= DARK_OFFSET_MAX:
        raise ValueError(f"dark: offsets of up to {top:.3g} DN; a dark offset (a tap's mean "
                         f"less the black level) lies within [-{DARK_OFFSET_MAX:.0f}, "
                         f"{DARK_OFFSET_MAX:.0f}] DN (2**16: the widest ADC of a sensor)")


def _fit_rms(value):
    """The largest of ``meta["fit_rms_m"]`` when it is a non-empty list of real numbers
    (what :func:`calibrate` writes), else None: meta is free-form, repr must not fail."""
    if not isinstance(value, (list, tuple, np.ndarray)):
        return None
    try:
        a = np.asarray(value)
    except (TypeError, ValueError, OverflowError):           # ragged or odd content
        return None
    if a.dtype.kind not in "iuf" or a.ndim != 1 or a.size == 0:
        return None
    return float(a.max())


def _jsonable(meta):
    """The entries of ``meta`` JSON holds as they are (numbers, strings, None, arrays and
    lists of numbers, lists of strings); the others are left out (save never fails on them)."""
    out = {}
    for k, v in meta.items():
        if isinstance(v, (str, bool, np.bool_)) or v is None:
            out[k] = v if not isinstance(v, np.bool_) else bool(v)
        elif isinstance(v, (numbers.Integral, numbers.Real)):
            out[k] = int(v) if isinstance(v, numbers.Integral) else float(v)
        elif isinstance(v, (list, tuple, np.ndarray)):
            try:
                a = np.asarray(v)
            except (TypeError, ValueError, OverflowError):
                continue
            if a.dtype.kind in "biuf" or (a.dtype.kind == "U" and (
                    isinstance(v, np.ndarray) or all(isinstance(x, str) for x in v))):
                out[k] = a.tolist()
    return out


def _frame_shape(shape, block):
    """The frame shape: two integers (rows, cols), each holding at least one ``block``."""
    dims = as_list(shape, "shape", "a (rows, cols) frame shape")
    if len(dims) != 2:
        raise ValueError(f"shape: expected a (rows, cols) frame shape, got {len(dims)} values "
                         f"{shape!r:.60}")
    if not all(isinstance(v, numbers.Integral) and not isinstance(v, (bool, np.bool_))
               for v in dims):
        raise TypeError(f"shape: expected two integers (rows, cols), got {shape!r:.60}")
    if not all(block <= v < 1 << 31 for v in dims):
        raise ValueError(f"shape: expected two integers in [{block}, 2**31) (rows, cols; "
                         f"block {block}), got {shape!r:.60}")
    return tuple(int(v) for v in dims)


def as_taps(item, name):
    """``item`` (ToFTaps, or a RawFrame with taps) as ToFTaps; errors name ``name``."""
    if isinstance(item, RawFrame):
        if item.tof is None:
            raise ValueError(f"{name}: the frame holds no ToF taps "
                             f"({item.meta.get('tof', 'none')})")
        item = item.tof
    if not isinstance(item, ToFTaps):
        raise TypeError(f"{name}: expected ToFTaps or a RawFrame with taps, got "
                        f"{type(item).__name__}")
    return item


def _check_phase(phase, nfreq):
    """Phases of shape (F, ...), one row per frequency of the calibration, as float64."""
    ph = check_image(phase, "phase").astype(np.float64)
    if ph.ndim < 1 or ph.shape[0] != nfreq:
        raise ValueError(f"phase: expected shape ({nfreq}, ...), one row per frequency, got "
                         f"{ph.shape}")
    return ph


def _mhz(freqs):
    return ", ".join(f"{f / 1e6:g}" for f in freqs)


def _check_same_layout(t, first, name, k, than="", frequencies=True):
    """A ValueError naming ``name`` unless frame ``k`` (ToFTaps) holds the Z measurements
    (sites, block) and frame shape of ``first``, and with ``frequencies`` its frequencies:
    the sweep's frames among themselves (``than`` empty), and the dark frames against the
    sweep's first (any frequencies: with the lens capped no modulated light reaches a tap,
    and the offsets are one per tap at every frequency)."""
    diffs = []
    tf, ff = (np.asarray(x.frequencies, np.float64).reshape(-1) for x in (t, first))
    if frequencies and not np.array_equal(tf, ff):
        diffs.append(f"frequencies {_mhz(tf)} MHz, not {_mhz(ff)}")
    if tuple(t.shape) != tuple(first.shape):
        diffs.append(f"a {t.shape[0]}x{t.shape[1]} frame, not {first.shape[0]}x"
                     f"{first.shape[1]}")
    if int(t.block) != int(first.block):
        diffs.append(f"block {t.block}, not {first.block}")
    if t.n_sites != first.n_sites:
        diffs.append(f"{t.n_sites} Z measurements, not {first.n_sites}")
    elif not all(np.array_equal(a, b) for a, b in zip(t.sites, first.sites)):
        diffs.append("Z measurements at other sites")
    cut = 0 if frequencies else 1
    if not diffs and t.taps.shape[cut:] != first.taps.shape[cut:]:
        diffs.append(f"taps of shape {t.taps.shape}, not {first.taps.shape}")
    if diffs:
        what = "the same frequencies and Z measurements" if frequencies else \
            "the same Z measurements"
        raise ValueError(f"{name}: every frame must hold {what}{than} (frame {k}: "
                         f"{'; '.join(diffs)})")


def _dark_offsets(dark, first):
    frames = [dark] if isinstance(dark, (ToFTaps, RawFrame)) else \
        as_list(dark, "dark", "frames or ToFTaps of the capped lens")
    if not frames:
        raise ValueError("dark: no frames")
    acc = np.zeros((4, first.n_sites))
    noise = 0.0
    for k, t in enumerate(frames):
        t = as_taps(t, "dark")
        # the sweep's own check: the offsets are stored per tap and Z measurement of the
        # sweep, so frames of other sites, block or frame shape are refused (a 48x32 frame
        # of as many sites had been subtracted as the 32x48 sweep's offsets); any
        # frequencies: a capped lens passes no modulated light, one offset per tap.
        # The sensor object is not compared, as for the sweep's frames: a dark frame's
        # sensor differs by construction (no light: optical power, ambient), and its offset
        # is measured above its own black level, so another black level changes nothing
        _check_same_layout(t, first, "dark", k, " as the sweep", frequencies=False)
        _check_same_scale(t, first, k)
        taps = np.asarray(t.taps, np.float64)
        _check_unlit(taps, t.sensor, k)
        acc += taps.mean(axis=0) - t.sensor.black_level
        # the temporal noise of a dark tap (the model without its fixed pattern), averaged
        # over the frame's frequencies
        temporal = replace(t.sensor, dsnu=0.0, prnu=0.0)
        noise += float(np.mean(tap_variance(taps.mean(axis=1), temporal))) / taps.shape[0]
    n = len(frames)
    # the offsets' own error: a fixed offset per tap, the same at every frequency, of this
    # variance (DN^2); the ISP's sigma takes it in place of the DSNU the offsets remove
    return acc / n, noise / (n * n)


def _check_same_scale(t, first, k):
    """A ValueError naming ``dark`` when dark frame ``k`` was read out at another bit depth or
    system gain (DN per electron) than the sweep's first frame: its offsets, in its own DN,
    had been subtracted from the sweep's taps as they were (a 12-bit dark frame's offsets of
    a 10-bit sweep, four times too large, without a word)."""
    diff = _readout_difference(int(t.bit_depth), t.sensor.system_gain, first, "not")
    if diff:
        raise ValueError(f"dark: frame {k} was read out differently from the sweep "
                         f"({diff}): its offsets are in its own DN; take dark "
                         "frames with the sweep's bit depth and gain")


def _readout_difference(bits, gain, taps, than):
    """How a readout of ``bits`` and ``gain`` (DN per electron; None: not known) differs from
    that of the ToFTaps ``taps`` ("12-bit, THAN 10-bit", or the gains when the bit depths
    agree), or None: the DN scale that dark offsets are in."""
    if isinstance(bits, int) and bits != int(taps.bit_depth):
        return f"{bits}-bit, {than} {taps.bit_depth}-bit"
    other = taps.sensor.system_gain
    if isinstance(gain, (int, float)) and not math.isclose(gain, other, rel_tol=1e-9):
        return f"{gain:.6g} DN per electron, {than} {other:.6g}"
    return None


#: the largest ratio of a dark frame's phasor power to what its noise alone gives (about 1
#: for a capped lens; 26 for a lit wall at 2.4 m, 950 at 0.6 m)
DARK_POWER_MAX = 4.0


def _check_unlit(taps, sensor, k):
    """A ValueError naming ``dark`` when frame ``k`` holds modulated light: its phasors'
    mean power ``|I + iQ|^2`` is more than :data:`DARK_POWER_MAX` times the ``4 var`` its
    noise alone gives (a lit frame given as dark had been subtracted as the taps' dark
    offsets, and the fit's residual tripled). A wall too dim or too far to tell is let
    through; its light biases the offsets as little as it shows."""
    i, q = taps[:, 0] - taps[:, 2], taps[:, 3] - taps[:, 1]
    var = tap_variance(taps.mean(axis=1), sensor)
    ratio = np.mean(i * i + q * q, axis=1) / np.maximum(np.mean(4 * var, axis=1), 1e-300)
    if np.any(ratio > DARK_POWER_MAX):
        raise ValueError(f"dark: frame {k} holds modulated light (its phasors carry "
                         f"{float(ratio.max()):.3g} times the power of its noise); a "
                         "lens-capped frame holds none")


def _check_phase_cover(truth, freqs, orders):
    """A ValueError naming ``distances`` when, at some frequency, the walls leave a gap of more
    than 1 / (orders + 1) of the phase circle: the harmonics are then fitted where nothing
    was measured (a 0.6-1.2 m sweep of 17 positions had fitted coefficients of 1000 rad,
    reported a residual of 0.64 mm, and put a wall at 1.25 m 3.4 m away, marked valid)."""
    d = np.unique(np.round(np.median(truth, axis=1), 9))          # one distance per position
    for fr in np.asarray(freqs, np.float64):
        wrap = SPEED_OF_LIGHT / (2.0 * fr)
        ph = np.sort(np.mod(d / wrap, 1.0))
        gap = float(np.max(np.diff(np.concatenate([ph, ph[:1] + 1.0])))) if ph.size else 1.0
        if gap > 1.0 / (orders + 1):
            raise ValueError(
                f"distances: the walls leave {100 * gap:.0f} % of the phase circle of "
                f"{fr / 1e6:g} MHz unmeasured (a gap of {gap * wrap:.3g} m of its {wrap:.3g} m "
                f"wrap); fitting {orders} harmonics needs gaps of at most 1 / (orders + 1) of "
                f"a wrap: sweep over at least one wrap of the lowest frequency, or lower orders")


def calibrate(sweep, distances, *, orders=8, dark=None, iterations=4):
    """Fit the cyclic error and the per-measurement phase offsets from a flat-wall sweep.

    Parameters
    ----------
    sweep : sequence of ToFTaps or RawFrame
        Frames of a flat wall (taps of one sensor: the same frequencies and Z
        measurements), e.g. ``simulate_tof`` of walls at ``distances``. The
        distances must sweep at least one wrap range of the lowest
        frequency (``c / (2 f_min)``, 1.874 m at 80 MHz) in steps small
        enough to sample ``2 * orders + 1`` phases per period: a sweep whose
        usable walls (not saturated, above the SNR floor) leave more than
        ``1 / (orders + 1)`` of some frequency's phase circle unmeasured is
        refused, since the fitted harmonics would be free there (a 0.6-1.2 m
        sweep had put a wall at 1.25 m 3.4 m away, marked valid).
    distances : sequence
        The true distance of every frame: one number (m) for a wall seen
        square-on, or an array of shape (n,) per frame (e.g. the line-of-sight
        distance of every measurement).
    orders : int
        K, the harmonics of the cyclic-error series (8, 1..32).
    dark : ToFTaps or sequence of them, optional
        Frames with the laser off (same sensor): the mean of every tap minus
        the black level is stored and subtracted first. They must hold the
        sweep's Z measurements and frame shape (at any frequencies: no modulated
        light reaches a capped lens) and be read out at its bit depth and system
        gain (their offsets are in their own DN).
    iterations : int
        Alternations of the fit (4, 1..50).

    Returns
    -------
    ToFCalibration

    Raises
    ------
    ValueError, TypeError
        An empty or mismatched sweep, distances of the wrong count or shape
        or not > 0, or frames with too few usable measurements.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.simulation import Scene, ToFSensor, simulate_tof
    >>> sensor = ToFSensor(delay_ps=50.0, harmonics=((3, 0.05, 0.0),))
    >>> ds = np.linspace(0.6, 2.6, 24)
    >>> sweep = [simulate_tof(Scene(np.full((8, 8, 3), 0.5), depth=np.full((8, 8), d)), "mask2",
    ...                       sensor, noise=False) for d in ds]
    >>> cal = calibrate(sweep, ds)
    >>> cal.offsets.shape, bool(np.allclose(cal.offsets[1], 2 * np.pi * 100e6 * 50e-12, atol=1e-2))
    ((3, 4), True)
    """
    try:
        frames = list(sweep)
    except TypeError:
        raise TypeError(f"sweep: expected a sequence of ToFTaps, got {type(sweep).__name__}") \
            from None
    if len(frames) < 2:
        raise ValueError(f"sweep: expected at least 2 frames, got {len(frames)}")
    frames = [as_taps(t, "sweep") for t in frames]
    first = frames[0]
    for k, t in enumerate(frames[1:], 1):
        _check_same_layout(t, first, "sweep", k)
    try:
        dists = list(distances)
    except TypeError:
        raise TypeError(f"distances: expected one distance per frame, got {distances!r}") \
            from None
    if len(dists) != len(frames):
        raise ValueError(f"distances: expected {len(frames)} values (one per frame), got "
                         f"{len(dists)}")
    n = first.n_sites
    truth = np.empty((len(frames), n))
    for k, d in enumerate(dists):
        try:
            v = np.broadcast_to(np.asarray(d, np.float64), (n,))
        except ValueError:
            raise ValueError(f"distances: entry {k} has shape {np.shape(d)}; expected a number "
                             f"or shape ({n},)") from None
        if not (np.all(np.isfinite(v)) and np.all(v > 0)):
            raise ValueError(f"distances: entry {k} holds values that are not > 0")
        truth[k] = v
    orders = check_int(orders, "orders", lo=1, hi=32)
    iterations = check_int(iterations, "iterations", lo=1, hi=50)
    positions = np.unique(np.round(truth, 9), axis=0).shape[0]
    if positions < 2 * orders + 1:
        raise ValueError(f"distances: {positions} distinct wall positions cannot fit {orders} "
                         f"harmonics (2 * orders + 1 = {2 * orders + 1} phases are needed); "
                         "add positions or lower orders")
    dark_off, dark_var = _dark_offsets(dark, first) if dark is not None else (None, None)

    f = first.frequencies.reshape(-1, 1)
    F = f.shape[0]
    meas = np.empty((len(frames), F, n))
    weight = np.empty_like(meas)
    for k, t in enumerate(frames):
        taps = np.asarray(t.taps, np.float64)
        sat = np.asarray(t.saturated, bool) | (taps.max(axis=(0, 1)) >= t.white_level)
        if dark_off is not None:
            taps = taps - dark_off[None]
        i = taps[:, 0] - taps[:, 2]
        q = taps[:, 3] - taps[:, 1]
        var = 2.0 * tap_variance(taps.mean(axis=1), t.sensor)
        power = (i * i + q * q) / var
        meas[k] = np.mod(np.arctan2(q, i), 2 * np.pi)
        w = np.where(power >= _MIN_SNR ** 2, power, 0.0)
        w[:, sat] = 0.0
        weight[k] = w
    if not np.all(weight.sum(axis=0) > 0):
        bad = int(np.sum(np.any(weight.sum(axis=0) == 0, axis=0)))
        raise ValueError(f"sweep: {bad} of {n} Z measurements have no usable frame (saturated "
                         f"or SNR < {_MIN_SNR:g} in every frame); move the wall or raise the "
                         "signal")
    # the positions that give the fit something (a frame saturated everywhere covers nothing)
    _check_phase_cover(truth[weight.sum(axis=(1, 2)) > 0], first.frequencies, orders)
    true_phase = np.mod(4 * np.pi * f[None] * truth[:, None] / SPEED_OF_LIGHT, 2 * np.pi)
    err = np.angle(np.exp(1j * (meas - true_phase)))                       # (frames, F, n)
    offsets = np.zeros((F, n))
    coef = np.zeros((F, orders, 2))
    kk = np.arange(1, orders + 1)
    def deviation(o):
        mean = np.angle(np.exp(1j * o).sum(axis=1, keepdims=True))
        return np.angle(np.exp(1j * (o - mean)))

    for _ in range(iterations):
        # offsets: weighted circular mean over the frames of e - g(phi - delta)
        g = _series(coef, meas - deviation(offsets)[None], kk)
        offsets = np.angle((weight * np.exp(1j * (err - g))).sum(axis=0))
        # the cyclic error: weighted least squares of e - o on the Fourier basis of
        # phi - delta, per frequency
        ph = meas - deviation(offsets)[None]
        resid = np.angle(np.exp(1j * (err - offsets[None])))
        for fi in range(F):
            lhs, rhs = np.zeros((2 * orders, 2 * orders)), np.zeros(2 * orders)
            for k in range(len(frames)):        # a frame at a time: the basis of one frame
                x, y, w = ph[k, fi], resid[k, fi], weight[k, fi]
                zk = _harmonics(x, orders)
                basis = np.concatenate([zk.real, zk.imag], axis=1)
                lhs += basis.T @ (basis * w[:, None])
                rhs += basis.T @ (w * y)
            sol = np.linalg.lstsq(lhs, rhs, rcond=None)[0]
            coef[fi, :, 0] = sol[:orders]
            coef[fi, :, 1] = sol[orders:]
    g = _series(coef, meas - deviation(offsets)[None], kk)
    resid = np.angle(np.exp(1j * (err - offsets[None] - g)))
    rms = np.sqrt((weight * resid ** 2).sum(axis=(0, 2)) / weight.sum(axis=(0, 2)))
    meta = {"frames": len(frames), "orders": orders, "fit_rms_rad": rms.tolist(),
            "fit_rms_m": (rms * SPEED_OF_LIGHT / (4 * np.pi * f[:, 0])).tolist()}
    if dark_var is not None:
        # the readout the dark offsets are in: check() refuses taps of another one
        meta.update(dark_noise_dn2=dark_var, dark_bit_depth=int(first.bit_depth),
                    dark_dn_per_electron=float(first.sensor.system_gain))
    return ToFCalibration(first.frequencies.copy(), offsets, coef, first.sites, first.block,
                          first.shape, dark_off, meta)


def _series(coef, phase, kk):
    """``sum_k a_k cos(k phi) + b_k sin(k phi)`` for phases (frames, F, n) and coef (F, K, 2)."""
    z = np.exp(1j * phase)
    zk = np.ones_like(z)
    out = np.zeros(phase.shape)
    for j in range(len(kk)):         # one harmonic at a time: the memory of one phase array
        zk *= z                                                   # exp(i k phi), k = j + 1
        out += coef[None, :, j, 0, None] * zk.real + coef[None, :, j, 1, None] * zk.imag
    return out


def _harmonics(x, orders):
    """(n, K) complex: ``exp(i k x)`` for ``k = 1..K``, by repeated products (one exp)."""
    out = np.empty((x.size, orders), complex)
    out[:, 0] = np.exp(1j * x)
    for j in range(1, orders):
        out[:, j] = out[:, j - 1] * out[:, 0]
    return out
