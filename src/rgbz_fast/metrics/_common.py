"""Argument checks and small helpers shared by the metrics (Python validates)."""

from __future__ import annotations

import math

import numpy as np

from .._validate import check_image, check_int, check_number, outside_stacklevel


#: the data_range SSIM and MS-SSIM accept: c1 = (0.01 L)**2 and the local moments of data
#: in [0, L] (squares of about L**2) stay normal, finite doubles with a wide margin (1e-100
#: to 1e100 leaves 1e54 for data beyond L); outside, c1 overflows (OverflowError) or
#: underflows to 0 (0/0 = NaN in flat windows)
SSIM_DATA_RANGE = (1e-100, 1e100)


def _check_ssim_data_range(value):
    peak = check_number(value, "data_range", lo=0, lo_open=True)
    lo, hi = SSIM_DATA_RANGE
    if not lo <= peak <= hi:
        raise ValueError(f"data_range: expected a number in [{lo:g}, {hi:g}] for SSIM, got "
                         f"{value!r}; rescale the images (the constants (0.01 * data_range)**2 "
                         "and the squared data must stay normal, finite doubles)")
    return peak


def _check_pair(reference, test, ndim, ref_name="reference", test_name="test"):
    """Both arrays real (bool refused), finite, non-empty, of `ndim` dimensions and equal
    shapes."""
    ref = check_image(reference, ref_name, ndim=ndim, values="image values")
    tst = check_image(test, test_name, ndim=ndim, values="image values")
    if ref.shape != tst.shape:
        raise ValueError(f"{test_name}: shape {tst.shape} differs from {ref_name} shape "
                         f"{ref.shape}")
    return ref, tst


def _check_rgb_pair(reference, test, ref_name="reference", test_name="test"):
    ref, tst = _check_pair(reference, test, 3, ref_name, test_name)
    if ref.shape[-1] != 3:
        raise ValueError(f"{ref_name}: expected a colour image of shape (rows, cols, 3), "
                         f"got shape {ref.shape}")
    return ref, tst


#: what a message about the data's range tells the caller to pass, per parameter named: the
#: colour metrics (zipper, delta_e_map) take an encoding, not a range (their message had
#: advised a range, and data_range=65535 was a TypeError there)
_RANGE_ADVICE = {
    "input": ('pass the encoding of the data: input="srgb16" for 16-bit sRGB codes, '
              'input="srgb01" for [0, 1] floats'),
}


def _check_integer_range(arrays, names, data_range, param="data_range"):
    """Integer code values must lie in [0, data_range].

    An integer image above its declared range almost always means a wrong
    `data_range` (e.g. 11-bit data in uint16 with the 8-bit default), which
    would silently inflate every score. Float images are not checked: a
    reconstruction may legitimately overshoot (:func:`_warn_unit_floats` warns about floats
    within [0, 1] scored against 8-bit codes).
    """
    for a, name in zip(arrays, names):
        if np.issubdtype(a.dtype, np.integer):
            info = np.iinfo(a.dtype)
            if info.min >= 0 and info.max <= data_range:
                continue                       # every value of the type is in the range
            # an unsigned array holds no value below 0: its maximum alone decides
            hi = int(a.max())
            if info.min >= 0 and hi <= data_range:
                continue
            lo = int(a.min())
            if lo < 0 or hi > data_range:
                advice = _RANGE_ADVICE.get(
                    param, "pass the real range of the data (2**bit_depth - 1)")
                raise ValueError(f"{param}: {name} holds integer values in [{lo}, {hi}], "
                                 f"outside [0, {data_range:g}]; {advice}")


#: the largest magnitude of the data SSIM takes: its local moments are squares of the data,
#: which stay below 1e300 (the largest double is 1.8e308)
SSIM_MAX_VALUE = 1e150
#: the largest magnitude of the colour metrics' data, in units of the encoding's white: the
#: sRGB decoding raises it to the power 2.4 and the colour differences square it
COLOUR_MAX_VALUE = 1e100


def _warn_unit_floats(arrays, names, data_range, param="data_range"):
    """A warning when float images within [0, 1] (not all zero) are scored against a range of
    2 or more: the [0, 1] convention with the 8-bit default inflates every score (sRGB floats:
    a CPSNR of 70.4 dB for 22.3, an SSIM of 0.9999 for 0.964). Called once the arguments are
    checked, so that an error comes first."""
    if data_range < 2 or not all(np.issubdtype(np.asarray(a).dtype, np.floating)
                                 and np.asarray(a).size for a in arrays):
        return
    hi = max(float(np.nanmax(a)) for a in arrays)
    if 0.0 < hi <= 1.0:
        import warnings

        if param == "input":          # the colour metrics: an encoding, not a range
            scored = f"input=\"srgb{8 if data_range == 255 else 16}\""
            advice = 'pass input="srgb01" for [0, 1] floats'
        else:
            scored = f"{param}={data_range:g}"
            advice = "pass the data's range (1.0 for [0, 1] floats)"
        warnings.warn(f"{param}: the {' and '.join(names)} images are floats within [0, 1], "
                      f"scored as {scored}; {advice}", UserWarning,
                      stacklevel=outside_stacklevel())


def _check_magnitude(arrays, names, limit, why, param=None):
    """Float data within [-limit, limit]: beyond, the metric's arithmetic overflows to inf or
    NaN (integer data is checked against its range by :func:`_check_integer_range`)."""
    for a, name in zip(arrays, names):
        if a.dtype.kind == "f":
            top = float(max(-a.min(), a.max()))
            if top > limit:
                raise ValueError(f"{param or name}: {name} holds values up to {top:g} in "
                                 f"magnitude, beyond {limit:g}: {why}")


def _crop_hw(a, crop, axes=(0, 1)):
    """Remove `crop` pixels from both ends of `axes`."""
    if crop == 0:
        return a
    index = [slice(None)] * a.ndim
    for ax in axes:
        index[ax] = slice(crop, a.shape[ax] - crop)
    return a[tuple(index)]


def _check_crop(crop, shape, minimum=1, what="a non-empty image"):
    """`shape` is the (rows, cols) before cropping; `minimum` the smallest side left."""
    crop = check_int(crop, "crop", lo=0)
    left = min(shape) - 2 * crop
    if left < minimum:
        raise ValueError(f"crop: crop={crop} leaves {shape[0] - 2 * crop} x "
                         f"{shape[1] - 2 * crop} pixels of a {shape[0]} x {shape[1]} image; "
                         f"the metric needs {what} (at least {minimum} x {minimum})")
    return crop


#: element types the metric kernels read as they are (csrc/metrics.h)
_KERNEL_DTYPES = (np.dtype(np.uint8), np.dtype(np.uint16), np.dtype(np.float32),
                  np.dtype(np.float64))


def _kernel_dtype(*dtypes):
    """The dtype in which the metric kernels read arrays of `dtypes` together.

    Their common dtype when it is uint8, uint16, float32 or float64 (bool
    becomes uint8, float16 float32); any other integer or float type becomes
    float64, the type of the computations, as in ``astype(np.float64)``.
    """
    dt = np.result_type(*dtypes)
    if dt == np.bool_:
        return np.dtype(np.uint8)
    if dt == np.float16:
        return np.dtype(np.float32)
    return dt if dt in _KERNEL_DTYPES else np.dtype(np.float64)


def _kernel_pair(a, b):
    """`a` and `b` as C-contiguous arrays of one dtype the metric kernels read."""
    dt = _kernel_dtype(a.dtype, b.dtype)
    return np.ascontiguousarray(a, dtype=dt), np.ascontiguousarray(b, dtype=dt)


def _psnr_from_mse(mse, e, peak):
    """PSNR in dB of the MSE ``mse * 4**e`` (see ``_psnr._mse``) and the peak ``peak``.

    ``10 log10(peak**2 / mse)`` when that ratio is a finite, non-zero double; else the same
    in logarithms, so that a ``data_range`` whose square overflows (or underflows) still gives
    the PSNR of the data, not inf (or -inf). inf when the images are equal (``mse`` 0).
    """
    if mse == 0:
        return math.inf
    if e == 0:
        ratio = peak * peak / mse
        if 0 < ratio < math.inf:
            return float(10.0 * np.log10(ratio))
    return float(20.0 * math.log10(peak) - 10.0 * math.log10(mse)
                 - 20.0 * e * math.log10(2.0))
