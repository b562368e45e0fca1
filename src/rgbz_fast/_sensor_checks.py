"""The checks of the sensor descriptions' fields (:mod:`rgbz_fast._sensors`).

Each check reads a field of a frozen sensor object, raises a ValueError or
TypeError naming it (``"ToFSensor.duty_cycle: ..."``), and stores the
normalised value (a float, a tuple) back on the object, so that two equal
descriptions compare and hash equal. The checks shared by both sensors
(:func:`check_readout`, :func:`check_pixel_noise`) are written once here.
"""

from __future__ import annotations

import numpy as np

from ._validate import check_bit_depth, check_flag, check_int, check_number, check_seed

__all__ = ["check_readout", "check_pixel_noise", "check_spectrum", "check_tof_contrast",
           "check_tof_nonideal", "store_number", "store_flag"]


def check_readout(obj):
    """Well, conversion gain, swing, ADC bits and black level: shared by both sensors."""
    store_number(obj, "full_well", lo=0, lo_open=True, allow_inf=True)
    # at least 1e-6 uV per electron: the gain divides the white level, which a subnormal one
    # turns into a division by zero
    store_number(obj, "conversion_gain_uv_per_e", lo=1e-6, hi=1e4)
    store_number(obj, "voltage_swing", lo=0, hi=100, lo_open=True)
    object.__setattr__(obj, "bit_depth",
                       check_bit_depth(obj.bit_depth, f"{type(obj).__name__}.bit_depth"))
    top = (1 << obj.bit_depth) - 1
    try:
        store_number(obj, "black_level", lo=0, hi=top, hi_open=True)
    except ValueError as exc:              # the default 64 does not fit a narrow ADC: say why
        raise ValueError(f"{exc} (a {obj.bit_depth}-bit ADC's codes are 0-{top}; give "
                         "black_level with bit_depth)") from None


def check_pixel_noise(obj):
    """The noise terms and the fixed-pattern seed: shared by both sensors."""
    store_flag(obj, "shot_noise")
    store_number(obj, "dark_current", lo=0, hi=1e7)
    store_number(obj, "read_noise", lo=0, hi=1e5)
    store_number(obj, "dsnu", lo=0, hi=1e5)
    store_number(obj, "prnu", lo=0, hi=1, hi_open=True)
    store_flag(obj, "quantise")
    object.__setattr__(obj, "fpn_seed",
                       check_seed(obj.fpn_seed, f"{type(obj).__name__}.fpn_seed"))


def store_number(obj, name, **bounds):
    """Check the number ``obj.name`` (:func:`~rgbz_fast._validate.check_number`); store it
    as a float."""
    v = check_number(getattr(obj, name), f"{type(obj).__name__}.{name}", **bounds)
    object.__setattr__(obj, name, v)
    return v


def store_flag(obj, name):
    """Check the flag ``obj.name`` (True or False); store it as a bool."""
    value = check_flag(getattr(obj, name), f"{type(obj).__name__}.{name}")
    object.__setattr__(obj, name, value)


def check_spectrum(obj, name, ncols):
    """A colour-science name, or (wavelengths, values) turned into hashable tuples."""
    value = getattr(obj, name)
    label = f"{type(obj).__name__}.{name}"
    if isinstance(value, str):
        return
    try:
        wl, vals = value
        wl = np.asarray(wl, dtype=np.float64)
        vals = np.asarray(vals, dtype=np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"{label}: expected a colour-science dataset name or a "
                        f"(wavelengths, values) pair, got {type(value).__name__}") from None
    if vals.ndim == 1 and ncols == 1:
        vals = vals[:, None]
    if wl.ndim != 1 or vals.shape != (wl.size, ncols) or wl.size < 2:
        raise ValueError(f"{label}: expected wavelengths (N,) and values (N, {ncols}), got "
                         f"{wl.shape} and {vals.shape}")
    if not (np.all(np.isfinite(wl)) and np.all(np.isfinite(vals))):
        raise ValueError(f"{label}: holds NaN or infinite values")
    if np.any(np.diff(wl) <= 0):
        raise ValueError(f"{label}: wavelengths must be strictly increasing")
    if vals.min() < 0:
        raise ValueError(f"{label}: a spectral sensitivity or power is >= 0, got {vals.min()}")
    object.__setattr__(obj, name, (tuple(wl.tolist()), tuple(map(tuple, vals.tolist()))))


def check_tof_contrast(obj, nfreq):
    """``modulation_contrast``: one number, or one per frequency (stored as a tuple)."""
    value = obj.modulation_contrast
    if isinstance(value, (tuple, list)) or (isinstance(value, np.ndarray) and value.ndim):
        values = tuple(check_number(v, "ToFSensor.modulation_contrast", lo=0, hi=1, lo_open=True)
                       for v in value)
        if len(values) != nfreq:
            raise ValueError(f"ToFSensor.modulation_contrast: expected one number or one per "
                             f"frequency ({nfreq}), got {len(values)}")
        object.__setattr__(obj, "modulation_contrast", values)
    else:
        store_number(obj, "modulation_contrast", lo=0, hi=1, lo_open=True)


def check_tof_nonideal(obj):
    """Harmonics, tap contrasts, delays, multipath, ambient suppression, duty cycle."""
    label = "ToFSensor.harmonics"
    try:
        entries = [tuple(e) for e in obj.harmonics]
    except TypeError:
        raise TypeError(f"{label}: expected a sequence of (order, amplitude, phase) triples, "
                        f"got {obj.harmonics!r}") from None
    harmonics = []
    for e in entries:
        if len(e) != 3:
            raise ValueError(f"{label}: expected (order, amplitude, phase) triples, got {e!r}")
        order = check_int(e[0], f"{label} order", lo=2, hi=64)
        amp = check_number(e[1], f"{label} amplitude", lo=0, hi=1)
        phase = check_number(e[2], f"{label} phase", lo=-100, hi=100)
        harmonics.append((order, amp, phase))
    if len({h[0] for h in harmonics}) != len(harmonics):
        raise ValueError(f"{label}: an order is repeated in {obj.harmonics!r}")
    object.__setattr__(obj, "harmonics", tuple(harmonics))
    try:
        taps = tuple(obj.tap_contrast)
    except TypeError:
        raise TypeError(f"ToFSensor.tap_contrast: expected 4 numbers, got "
                        f"{obj.tap_contrast!r}") from None
    if len(taps) != 4:
        raise ValueError(f"ToFSensor.tap_contrast: expected 4 numbers (one per tap), got "
                         f"{len(taps)}")
    object.__setattr__(obj, "tap_contrast", tuple(
        check_number(t, "ToFSensor.tap_contrast", lo=0, hi=2, lo_open=True) for t in taps))
    store_number(obj, "delay_ps", lo=-1e6, hi=1e6)
    store_number(obj, "delay_fpn_ps", lo=0, hi=1e6)
    if obj.multipath is not None:
        try:
            ratio, extra = obj.multipath
        except (TypeError, ValueError):
            raise TypeError(f"ToFSensor.multipath: expected None or (relative_amplitude, "
                            f"extra_path_m), got {obj.multipath!r}") from None
        object.__setattr__(obj, "multipath", (
            check_number(ratio, "ToFSensor.multipath amplitude", lo=0, hi=1),
            check_number(extra, "ToFSensor.multipath extra path", lo=0, hi=1e4, lo_open=True)))
    store_number(obj, "ambient_suppression", lo=0, hi=1, hi_open=True)
    store_number(obj, "duty_cycle", lo=0, hi=1, lo_open=True)
