"""The four colour metrics of the paper's second assessment level, in one call."""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._validate import check_number, check_workers
from ._common import (COLOUR_MAX_VALUE, SSIM_MAX_VALUE, _check_crop, _check_integer_range,
                      _check_magnitude, _check_rgb_pair,
                      _check_ssim_data_range, _crop_hw, _kernel_dtype,
                      _psnr_from_mse, _warn_unit_floats)
from ._psnr import _rgb_mse
from ._ssim import _SSIM_WHY, MS_SSIM_WEIGHTS, _check_ms_ssim_size, _ssim_and_ms_ssim
from ._zipper import _COLOUR_WHY, _zipper_percent

__all__ = ["all_metrics"]

#: the colour metrics, in the order of :func:`all_metrics`' dict
COLOUR_METRICS = ("cpsnr", "ssim", "ms_ssim", "zipper")


def all_metrics(reference_rgb, test_rgb, *, data_range=255, crop=0, workers=None):
    """The four colour-image metrics of the paper's second assessment level.

    Parameters
    ----------
    reference_rgb : ndarray, shape (rows, cols, 3)
        Reference sRGB image, code values in [0, data_range].
    test_rgb : ndarray, shape (rows, cols, 3)
        Reconstructed sRGB image.
    data_range : float, default 255
        Code value of sRGB white (255 for 8-bit images, 1.0 for floats in
        [0, 1]); the peak of the C-PSNR and :math:`L` of the SSIMs.
    crop : int, default 0
        Pixels removed from each border of the rows and columns first.
    workers : int, optional
        Threads of the C kernels (None or -1: every core); the results do not
        depend on it.

    Returns
    -------
    metrics : dict
        ``{'cpsnr': dB, 'ssim': float, 'ms_ssim': float, 'zipper': percent}``
        with the defaults of :func:`cpsnr`, :func:`ssim`, :func:`ms_ssim`
        (channels last) and :func:`zipper` (the images divided by
        `data_range` are read as 'srgb01').

    Notes
    -----
    MS-SSIM needs a (cropped) image of at least 161 x 161 pixels; smaller
    images raise ValueError rather than returning a partial dict. The SSIM
    is MS-SSIM's first scale, computed once for both.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import all_metrics
    >>> ref = np.random.default_rng(0).integers(0, 256, (161, 161, 3), dtype=np.uint8)
    >>> all_metrics(ref, ref)
    {'cpsnr': inf, 'ssim': 1.0, 'ms_ssim': 1.0, 'zipper': 0.0}
    """
    return _colour_metrics(reference_rgb, test_rgb, COLOUR_METRICS, data_range, crop, workers,
                           names=("reference_rgb", "test_rgb"))


def _colour_metrics(reference, test, metrics, data_range, crop, workers,
                    names=("reference", "test"), memo=None):
    """The colour metrics ``metrics`` (a subset of :data:`COLOUR_METRICS`) of one image pair,
    with the defaults of the public functions: what :func:`all_metrics` and the dataset
    evaluation compute. The pair is checked, cropped and converted once; SSIM and MS-SSIM
    share their first scale. ``memo``: a dict the caller keeps for the calls with the same
    ``reference``, ``data_range`` and ``crop`` (the dataset evaluation: one reference, many
    test images), which holds what only the reference gives (its planar scales for the
    SSIMs and their local moments, its nearest neighbours for the zipper); the same values."""
    ref, tst = _check_rgb_pair(reference, test, *names)
    want_ssim = "ssim" in metrics or "ms_ssim" in metrics
    if want_ssim:
        peak = _check_ssim_data_range(data_range)
    else:
        peak = check_number(data_range, "data_range", lo=0, lo_open=True)
    _check_integer_range((ref, tst), names, peak)
    if want_ssim:
        _check_magnitude((ref, tst), names, SSIM_MAX_VALUE, _SSIM_WHY)
    if "zipper" in metrics:
        _check_magnitude((ref, tst), names, COLOUR_MAX_VALUE * peak, _COLOUR_WHY)
    threads = check_workers(workers)
    crop = _check_crop(crop, ref.shape[:2], minimum=11 if want_ssim else 3,
                       what="a centre pixel with all eight neighbours" if not want_ssim
                       else "an image at least win_size=11 pixels wide")
    # the cropped pair as the kernels read it, copied once for every metric (the reference
    # once for all the calls that share ``memo``)
    dt = _kernel_dtype(ref.dtype, tst.dtype)
    if memo is None:
        ref = np.ascontiguousarray(_crop_hw(ref, crop), dt)
    else:
        if ("cropped", dt) not in memo:
            memo["cropped", dt] = np.ascontiguousarray(_crop_hw(ref, crop), dt)
        ref = memo["cropped", dt]
    tst = np.ascontiguousarray(_crop_hw(tst, crop), dt)
    if "ms_ssim" in metrics:
        _check_ms_ssim_size(ref.shape[:2], len(MS_SSIM_WEIGHTS), crop)
    out = {}
    if "cpsnr" in metrics:
        out["cpsnr"] = _psnr_from_mse(*_rgb_mse(ref, tst, 0, threads), peak)
    if want_ssim:
        x_cache = None
        if memo is None:
            x = _planar(ref, threads)
        else:
            x, x_cache = memo.get(("ssim", dt)) or memo.setdefault(
                ("ssim", dt), (_planar(ref, threads), []))
        y = _planar(tst, threads)
        ssim_value, ms_value = _ssim_and_ms_ssim(
            x, y, peak, MS_SSIM_WEIGHTS if "ms_ssim" in metrics else None, threads, x_cache)
        out.update(ssim=ssim_value, ms_ssim=ms_value)
    if "zipper" in metrics:
        out["zipper"] = _zipper_percent(ref, tst, peak, 2.3, threads, memo)
    if memo is None:                  # the evaluation's are 8-bit renders
        _warn_unit_floats((ref, tst), names, peak)
    return {m: out[m] for m in metrics}


def _planar(a, threads):
    """The (channels, rows, cols) copy of a contiguous (rows, cols, channels) kernel-typed
    array, as the SSIM kernels read it (C kernel: NumPy copies the strided bytes one by
    one)."""
    out = np.empty((a.shape[2],) + a.shape[:2], a.dtype)
    _kernels.planar(a, out, threads)
    return out
