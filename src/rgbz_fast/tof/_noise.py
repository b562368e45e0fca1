"""The ToF ISP's noise model of a tap, from the sensor's parameters (the ISP is calibrated
for its sensor): shared by the depth chain and the calibration."""

from __future__ import annotations

import numbers

import numpy as np

from .. import _kernels
from .._sensors import SPEED_OF_LIGHT
from .._validate import kernel_threads

__all__ = ["tap_variance", "fixed_pattern_delta", "collected_scale", "prnu_gain", "dark_noise",
           "delay_fpn_variance", "fixed_pattern_args", "NOISE_MODEL"]

#: The revision of the ISP's noise model (``sigma``): caches of depth results hold it, so
#: that a result of an earlier model is not served (2: the fixed pattern correlated across
#: the frequencies, 2026-11-27; the PRNU of the collected charge and the delay pattern, the
#: same day, change nothing for the default sensor).
NOISE_MODEL = 2


def collected_scale(sensor):
    """The charge a tap collected over the charge it holds after the ambient suppression
    ``s`` drained its share of the common mode: ``1 / (1 - s)`` (1 without suppression).
    The shot noise and the PRNU act on the collected charge."""
    s = sensor.ambient_suppression
    return 1.0 / (1.0 - s) if s else 1.0


def prnu_gain(sensor):
    """The PRNU's share of a tap's held charge in the model: ``prnu / (1 - s)``, since the
    gain multiplies the charge the tap collected before the suppression drained its
    share."""
    return float(sensor.prnu) * collected_scale(sensor)


def tap_variance(offset, sensor, *, scale=1.0, count=None, workers=1):
    """Expected variance (DN^2) of one tap from its offset and the sensor's readout.

    Shot noise of the collected charge, read noise and DSNU (both in
    electrons), quantisation and the tap's PRNU:
    ``K^2 c + K^2 (read^2 + dsnu^2) + 1/12 + (prnu K c)^2`` with ``e = (offset
    - black) / K`` the electrons the tap holds and ``c = e / (1 - s)`` the
    electrons it collected (the ambient suppression ``s`` drains a share of
    the common mode but not its shot noise, nor the PRNU of the charge before
    it). PRNU is a fixed gain per tap: it enters as a variance because it
    differs from tap to tap and pixel to pixel (the denoise averages it like
    noise). The model keeps the shot noise and the 1/12 of the ADC for a sensor made
    without them (``shot_noise=False``, ``quantise=False``): conservative there, and a
    floor for noise-free sensors (a model without them, tried on 2026-11-27, stopped the
    bilateral denoise and the calibration on a noise-free sensor and left the guided range
    kernel narrow enough to take an unmodelled delay pattern for edges). DSNU and PRNU are the same in the
    frames of every frequency, so their share of the depth noise is not
    independent across frequencies: :func:`fixed_pattern_delta` corrects the
    depth's sigma for it.

    The NumPy operations of this formula run as one C pass (csrc/tof_filter.c,
    ``rgbz_tof_tap_variance``; tests/_reference/tof.py holds it to them bit for bit),
    which also applies the caller's ``scale`` (``scale * v``) and divides by
    ``max(count, 1)`` (``count``: one value per measurement, the offsets' last axis).
    """
    k = float(sensor.system_gain)
    off = np.asarray(offset)
    flat = np.ascontiguousarray(off, np.float64).reshape(-1)
    out = np.empty(off.shape)
    s = sensor.ambient_suppression
    cnt = None
    if count is not None:
        cnt = np.ascontiguousarray(count, np.float64).reshape(-1)
        if off.ndim == 0 or cnt.size != off.shape[-1]:
            raise ValueError(f"count: expected {off.shape[-1:]} values, got {cnt.size}")
    _kernels.tof_tap_variance(flat, float(sensor.black_level), k, 1.0 - s if s else 0.0,
                              k * k * (sensor.read_noise ** 2 + sensor.dsnu ** 2),
                              prnu_gain(sensor), float(scale), cnt, out.reshape(-1),
                              kernel_threads(workers, flat.size))
    return out


def dark_noise(calibration):
    """The variance (DN^2) of the fixed offset per tap that a calibration's dark frame
    leaves (its own error), or None without a calibration or a dark frame."""
    if calibration is None or calibration.dark is None:
        return None
    v = calibration.meta.get("dark_noise_dn2", 0.0)
    ok = isinstance(v, numbers.Real) and not isinstance(v, bool) and np.isfinite(v) and v >= 0
    return float(v) if ok else 0.0          # a file of before 2026-11-27 does not hold it


def delay_fpn_variance(sensor, calibration):
    """The depth variance (m^2) of the sensor's per-pixel delay pattern (``delay_fpn_ps``):
    a delay ``tau`` turns every frequency's phase by ``2 pi f tau``, a depth error of
    ``c tau / 2`` at each, so fully correlated; 0 with a calibration, whose per-measurement
    offsets take it off."""
    if calibration is not None or not sensor.delay_fpn_ps:
        return 0.0
    return (SPEED_OF_LIGHT * float(sensor.delay_fpn_ps) * 1e-12 / 2.0) ** 2


def fixed_pattern_args(sensor, dark_noise=None, delay_var=0.0):
    """The sensor's numbers in :func:`fixed_pattern_delta`'s C pass: (black level, the
    collected scale before an ambient suppression, the DSNU variance, the fixed offset's
    variance (the DSNU's, or a dark frame's own error), PRNU, ``delay_var``) as float64, the
    ``fixed`` argument of the guided denoise, which makes the correction row by row."""
    k = float(sensor.system_gain)
    var_dsnu = k * k * float(sensor.dsnu) ** 2
    return np.array([float(sensor.black_level), collected_scale(sensor), var_dsnu,
                     var_dsnu if dark_noise is None else float(dark_noise), float(sensor.prnu),
                     float(delay_var)], np.float64)


def fixed_pattern_delta(phase, amp, offset, count, sensor, sigma_scale, *, shared=False,
                        dark_noise=None, delay_var=0.0, workers=1):
    """The correction of the depth variance (m^2) for the fixed-pattern noise's correlation
    across frequencies, one value per measurement.

    A tap's DSNU offset and PRNU gain do not change between the frames of the F
    frequencies, so the phase errors they cause are correlated: with phases 0.5 rad apart
    they add, with phases pi apart they cancel. The ISP's sigma sums the per-frequency
    phase variances as if independent (:func:`tap_variance` holds DSNU and PRNU with the
    temporal noise); this returns ``corr - ind``: ``corr`` the variance the fixed
    pattern gives the f^2-weighted mean of the per-frequency distances, computed through
    each tap (``A0, A2 = T +- a cos(phase)``, ``A3, A1 = T +- a sin(phase)``, ``T`` the
    offset above black, as collected before an ambient suppression, ``a`` the amplitude),
    ``ind`` what the sum holds of it (per tap ``prnu^2 T^2``, without the taps'
    modulation: so even one frequency gets a small correction), both over
    ``max(count, 1)``. On flat walls at 0.3-4 m of a sensor whose only noise is DSNU and
    PRNU, the predicted sigma of single measurements, and of the box mean, then matches
    the spread of the depths within 1-16 % in variance, where the independent sum was
    0.27-3.6x off (docs/reports/isp.md, "Depth noise on flat walls"); the bilateral and
    guided means keep more of such a sensor's noise than their n_eff says (their range
    kernels take the frequencies' errors as independent).

    ``phase`` (F, n) is the angle of each phasor in the taps' own frame (before any
    calibration turned it); ``amp`` the amplitude ``|I + iQ| / 2``, ``offset`` the mean
    tap (DN), ``count`` (n,) the measurements averaged (None: 1), ``sigma_scale`` (F,) the
    weights of :func:`~rgbz_fast.tof._validity.radiometry_coefficients`. ``shared``: the
    variance is one per measurement, the mean over the frequencies (the guided chain's).
    ``dark_noise``: a calibration's dark frame took the DSNU off the taps (which the
    variance still holds), leaving its own error, a fixed offset per tap of this variance
    (DN^2; ``ToFCalibration.meta["dark_noise_dn2"]``, 0 when a file does not hold it);
    None: no dark frame. ``delay_var``: :func:`delay_fpn_variance`, added over
    ``max(count, 1)``. One C pass (csrc/tof_filter.c, ``rgbz_tof_fixed_pattern``);
    tests/_reference/tof.py holds its NumPy reference.
    """
    black, pre, var_dsnu, fix_dsnu, prnu, _ = fixed_pattern_args(sensor, dark_noise)
    ph = np.ascontiguousarray(phase, np.float64)
    if ph.ndim != 2 or not 1 <= ph.shape[0] <= 16:
        raise ValueError(f"phase: expected (F, n) with 1 <= F <= 16, got shape {ph.shape}")
    out = np.empty(ph.shape[1])
    cnt = None if count is None else np.ascontiguousarray(count, np.float64)
    _kernels.tof_fixed_pattern(ph, np.ascontiguousarray(amp, np.float64),
                               np.ascontiguousarray(offset, np.float64), cnt,
                               np.ascontiguousarray(sigma_scale, np.float64), black, pre,
                               var_dsnu, fix_dsnu, prnu, bool(shared), out,
                               kernel_threads(workers, out.size))
    if delay_var:
        m = np.ones(out.size) if cnt is None else np.maximum(cnt, 1.0)
        out += delay_var / m
    return out
