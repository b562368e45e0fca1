"""The zipper-effect metric and CIELAB colour differences (paper eqs. 29-31; Lu & Tan 2003)."""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._validate import check_choice, check_number, check_workers
from ._common import (COLOUR_MAX_VALUE, _check_crop, _check_integer_range, _check_magnitude,
                      _check_rgb_pair, _crop_hw,
                      _kernel_dtype, _kernel_pair, _warn_unit_floats)

__all__ = ["zipper", "delta_e_map", "ZIPPER_INPUTS"]

#: Encodings accepted by :func:`zipper` and :func:`delta_e_map`, with the code
#: value of sRGB white (None: the input is already CIELAB).
ZIPPER_INPUTS = {"srgb8": 255.0, "srgb16": 65535.0, "srgb01": 1.0, "lab": None}



def _to_lab(rgb, input, threads):
    """CIELAB (D65, CIE 1931 2 deg), float64 (rows, cols, 3), of an image in encoding `input`."""
    full_scale = ZIPPER_INPUTS[input]
    if full_scale is None:
        return rgb.astype(np.float64)
    a = np.ascontiguousarray(rgb, dtype=_kernel_dtype(rgb.dtype))
    lab = np.empty(a.shape, dtype=np.float64)
    _kernels.srgb_to_lab(a.reshape(-1, 3), full_scale, lab.reshape(-1, 3), threads)
    return lab


_COLOUR_WHY = ("the sRGB decoding and the colour differences of such values overflow; "
               "expected colour images in the range of their encoding")


def _check_colour_input(ref, tst, input):
    input = check_choice(input, tuple(ZIPPER_INPUTS), "input")
    white = ZIPPER_INPUTS[input]
    if white is not None:
        _check_integer_range((ref, tst), ("reference", "test"), white, param="input")
    _check_magnitude((ref, tst), ("reference", "test"), COLOUR_MAX_VALUE * (white or 1.0),
                     _COLOUR_WHY, param="input")
    return input


def _delta_e(lab1, lab2):
    d = lab1 - lab2
    return np.sqrt(np.sum(d * d, axis=-1))


def _zipper_percent(ref, tst, full_scale, delta, threads, memo=None):
    """Percentage of interior pixels with |psi| > delta (eqs. 30-31), one fused C pass.

    ``full_scale``: the sRGB code value of white, or None for CIELAB images. ``memo``: a
    dict kept for the calls with the same ``ref`` (one reference, many test images), which
    holds the reference's nearest neighbours; the same percentage.
    """
    scale = 0.0 if full_scale is None else float(full_scale)
    if memo is None:
        a, b = _kernel_pair(ref, tst)
        count = _kernels.zipper_count(a, b, scale, float(delta), threads)
    else:
        dt = _kernel_dtype(ref.dtype, tst.dtype)
        key = ("zipper", dt, scale)
        if key not in memo:
            a = np.ascontiguousarray(ref, dtype=dt)
            best = np.empty((a.shape[0] - 2, a.shape[1] - 2))
            nearest = np.empty(best.shape, dtype=np.uint8)
            _kernels.zipper_reference(a, scale, best, nearest, threads)
            memo[key] = best, nearest
        b = np.ascontiguousarray(tst, dtype=dt)
        count = _kernels.zipper_count_reference(b, scale, *memo[key], float(delta), threads)
    return float(100.0 * count / ((ref.shape[0] - 2) * (ref.shape[1] - 2)))


def delta_e_map(reference, test, *, input="srgb8", workers=None):
    r"""Per-pixel CIE 1976 colour difference :math:`\Delta E^*_{ab}` of two images.

    Parameters
    ----------
    reference, test : ndarray, shape (rows, cols, 3)
        Colour images in the encoding `input`.
    input : {'srgb8', 'srgb16', 'srgb01', 'lab'}, default 'srgb8'
        sRGB code values scaled to 255, 65535 or 1 (converted to CIELAB under
        D65 with colour-science's constants), or images already in CIELAB.
    workers : int, optional
        Threads of the conversion kernel (None or -1: every core).

    Returns
    -------
    delta_e : ndarray of float64, shape (rows, cols)
        Eq. 29 between co-located pixels.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import delta_e_map
    >>> black = np.zeros((1, 2, 3), dtype=np.uint8)
    >>> white = np.full((1, 2, 3), 255, dtype=np.uint8)
    >>> delta_e_map(black, white).round(3).tolist()       # L* goes from 0 to 100
    [[100.0, 100.0]]
    """
    ref, tst = _check_rgb_pair(reference, test)
    input = _check_colour_input(ref, tst, input)
    threads = check_workers(workers)
    return _delta_e(_to_lab(ref, input, threads), _to_lab(tst, input, threads))


def zipper(reference, test, *, delta=2.3, crop=0, input="srgb8", workers=None):
    r"""Zipper-effect metric: percentage of pixels whose closest-neighbour contrast changed.

    Parameters
    ----------
    reference : ndarray, shape (rows, cols, 3)
        Reference colour image.
    test : ndarray, shape (rows, cols, 3)
        Reconstructed colour image.
    delta : float, default 2.3
        Threshold :math:`\delta` on :math:`|\psi|`, in :math:`\Delta E^*_{ab}`
        units (2.3 is a just-noticeable difference).
    crop : int, default 0
        Pixels removed from each border of the rows and columns first.
    input : {'srgb8', 'srgb16', 'srgb01', 'lab'}, default 'srgb8'
        Encoding of both images: sRGB code values scaled to 255 ('srgb8',
        any dtype), 65535 ('srgb16') or 1 ('srgb01'), converted with
        ``colour.XYZ_to_Lab(colour.sRGB_to_XYZ(rgb))`` (D65, CIE 1931 2 deg
        observer); or 'lab', images already in CIELAB. Integer images must lie
        in [0, full scale]; float values are converted as they are (no
        clipping).
    workers : int, optional
        Threads of the C kernel (None or -1: every core); the result does not
        depend on it.

    Returns
    -------
    zipper : float
        Percentage (0 to 100) of the evaluated pixels with
        :math:`|\psi| > \delta`; 0 for identical images.

    Notes
    -----
    In the reference, every pixel P is paired with the one of its eight
    neighbours :math:`\epsilon` that is closest in colour (eqs. 29-30):

    .. math::

        I = \operatorname{argmin}_{i \in \epsilon} \Delta E^*_{ab}(P, i),
        \qquad
        \psi = \Delta \tilde E^*_{ab}(P, I) - \Delta E^*_{ab}(P, I)

    where :math:`\Delta \tilde E^*_{ab}` is measured between the same two
    pixels of the reconstructed image (eq. 31). Only pixels with all eight
    neighbours inside the (cropped) image are evaluated: the outer one-pixel
    ring of the cropped image is a neighbour but never a centre, so an
    (rows, cols) image yields (rows - 2 crop - 2)(cols - 2 crop - 2)
    evaluated pixels. When several neighbours tie for the minimum, the first
    in raster order (top-left, top, top-right, left, right, bottom-left,
    bottom, bottom-right) is taken.

    References
    ----------
    .. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", eqs. 29-31 (docs/references.bib: rebiere_rgbz)
    .. [2] Lu and Tan, "Color filter array demosaicking: new method and performance measures" (docs/references.bib: lu2003zipper)

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import zipper
    >>> ref = np.zeros((5, 5, 3), dtype=np.uint8)      # flat black: 3 x 3 evaluated pixels
    >>> zipper(ref, ref + 40)                          # flat grey: no contrast changed
    0.0
    >>> test = ref.copy()
    >>> test[2, 2] = 255                               # one white dot
    >>> zipper(ref, test, crop=1)                      # only the dot is evaluated
    100.0
    """
    ref, tst = _check_rgb_pair(reference, test)
    delta = check_number(delta, "delta", lo=0)
    input = _check_colour_input(ref, tst, input)
    crop = _check_crop(crop, ref.shape[:2], minimum=3,
                       what="a centre pixel with all eight neighbours")
    threads = check_workers(workers)
    ref, tst = _crop_hw(ref, crop), _crop_hw(tst, crop)
    out = _zipper_percent(ref, tst, ZIPPER_INPUTS[input], delta, threads)
    if ZIPPER_INPUTS[input] is not None:
        _warn_unit_floats((ref, tst), ("reference", "test"), ZIPPER_INPUTS[input], "input")
    return out
