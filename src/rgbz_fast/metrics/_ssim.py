"""SSIM and multi-scale SSIM (paper eqs. 24-28; Wang et al. 2004 and 2003)."""

from __future__ import annotations

import numbers
from functools import lru_cache

import numpy as np

from .. import _kernels
from .._validate import check_flag, check_int, check_number, check_workers
from ._common import (SSIM_MAX_VALUE, _check_crop, _check_integer_range, _check_magnitude,
                      _check_pair, _check_ssim_data_range,
                      _crop_hw, _kernel_pair, _warn_unit_floats)

__all__ = ["ssim", "ms_ssim", "MS_SSIM_WEIGHTS"]

_SSIM_WHY = ("SSIM multiplies squares of the data, which overflow; rescale both images and "
             "data_range")

#: Exponents beta_j = gamma_j (and alpha_M) of eq. 28, from Wang et al. 2003.
MS_SSIM_WEIGHTS = (0.0448, 0.2856, 0.3001, 0.2363, 0.1333)



def _channels_first(ref, tst, channel_axis):
    """(channels, rows, cols) views of a 2-D or 3-D pair."""
    if ref.ndim == 2:
        return ref[np.newaxis], tst[np.newaxis]
    if channel_axis is None:
        raise ValueError("channel_axis: a 3-D image needs the axis of its channels "
                         "(volumetric SSIM is not supported)")
    if isinstance(channel_axis, bool) or not isinstance(channel_axis, numbers.Integral):
        raise TypeError(f"channel_axis: expected an integer or None, got {channel_axis!r}")
    if not -3 <= channel_axis <= 2:
        raise ValueError(f"channel_axis: {channel_axis} is out of range for a 3-D image")
    return np.moveaxis(ref, channel_axis, 0), np.moveaxis(tst, channel_axis, 0)


@lru_cache(maxsize=16)
def _window(win_size, sigma, gaussian_weights):
    """The 1-D window: scipy.ndimage.gaussian_filter's kernel for ``radius=(win_size - 1) // 2``
    (the same expression, so the same weights bit for bit), or a uniform one; read-only, one
    array per window."""
    w = _window_values(win_size, sigma, gaussian_weights)
    w.setflags(write=False)
    return w


def _window_values(win_size, sigma, gaussian_weights):
    if not gaussian_weights:
        return np.full(win_size, 1.0 / win_size)
    radius = (win_size - 1) // 2
    x = np.arange(-radius, radius + 1)
    if sigma < 1e-150:                    # sigma**2 underflows: the limit, all on the centre
        return (x == 0).astype(np.float64)
    phi = np.exp(-0.5 / (sigma * sigma) * x ** 2)
    return phi / phi.sum()


def _ssim_means(x, y, data_range, win_size, sigma, gaussian_weights, threads,
                x_moments=None, cs_only=False):
    """Per-channel means of the local SSIM and contrast-structure maps (C kernel).

    ``x``, ``y``: C-contiguous (channels, rows, cols) arrays of one kernel dtype
    (:func:`._common._kernel_pair`). Only windows wholly inside the image count
    (the 'valid' part of Wang et al.'s MATLAB code). ``x_moments``: :func:`_ssim_reference`
    of ``x`` with this window, or None; the same means either way, bit for bit.
    ``cs_only``: the SSIM means are not computed (None), the others are the same.
    """
    channels, rows, cols = x.shape
    ssim_sum, cs_sum = (None if cs_only else np.empty(channels)), np.empty(channels)
    _kernels.ssim_sums(x, y, x_moments, _window(win_size, sigma, gaussian_weights),
                       (0.01 * data_range) ** 2, (0.03 * data_range) ** 2, ssim_sum, cs_sum,
                       threads)
    count = (rows - win_size + 1) * (cols - win_size + 1)
    return (None if cs_only else ssim_sum / count), cs_sum / count


def _ssim_reference(x, threads):
    """What the SSIM of ``x`` (as in :func:`_ssim_means`) with the default window takes from
    ``x`` alone (its local means and variances), for the comparisons of one reference with
    many images."""
    channels, rows, cols = x.shape
    moments = np.empty((channels * (rows - 10), 2, cols - 10))
    _kernels.ssim_reference(x, _window(11, 1.5, True), moments, threads)
    return moments


def _downsample2(a, threads):
    """2x2 mean then keep every second pixel (Wang et al.'s MATLAB code), C kernel.

    Odd sides are padded by repeating the last row/column ('symmetric'), so
    a side of n becomes ceil(n / 2). Returns float64.
    """
    channels, rows, cols = a.shape
    out = np.empty((channels, (rows + 1) // 2, (cols + 1) // 2))
    _kernels.downsample2(a, out, threads)
    return out


def _check_ms_ssim_size(shape, levels, crop):
    minimum = 10 * 2 ** (levels - 1) + 1
    if min(shape) < minimum:
        raise ValueError(f"reference: MS-SSIM with {levels} scales needs at least "
                         f"{minimum} x {minimum} pixels (after crop={crop}), got "
                         f"{shape[0]} x {shape[1]}")


def _ssim_and_ms_ssim(x, y, data_range, weights, threads, x_cache=None):
    """(SSIM, MS-SSIM) of planar kernel-typed arrays with the default window.

    The SSIM is MS-SSIM's first scale, computed once; ``weights`` None: the
    MS-SSIM is not computed (None). ``x_cache``: a list that holds (or receives), for
    each scale j, ``x`` at that scale and its :func:`_ssim_reference`, for the other calls
    with the same ``x`` (the same values, computed once).
    """
    scales = 1 if weights is None else len(weights)
    factors = np.empty((scales, x.shape[0]))                 # (scales, channels)
    xj = x
    for j in range(scales):                                 # 5 scales, not pixels
        if j:
            y = _downsample2(y, threads)
        moments = None
        if x_cache is not None:
            if len(x_cache) <= j:
                xj = x_cache[j - 1][0] if j else x
                xj = _downsample2(xj, threads) if j else xj
                x_cache.append((xj, _ssim_reference(xj, threads)))
            xj, moments = x_cache[j]
        elif j:
            xj = _downsample2(xj, threads)
        # the scales between the first and the last contribute their c s alone
        s, cs = _ssim_means(xj, y, data_range, 11, 1.5, True, threads, moments,
                            cs_only=0 < j < scales - 1)
        if j == 0:
            ssim_value = float(s.mean())
            if weights is None:
                return ssim_value, None
        factors[j] = s if j == scales - 1 else cs
    w = np.asarray(weights, dtype=np.float64)
    per_channel = np.prod(np.maximum(factors, 0.0) ** w[:, np.newaxis], axis=0)
    return ssim_value, float(per_channel.mean())


def _check_weights(weights):
    """MS-SSIM's exponents as a float64 vector: a non-empty 1-D sequence of real numbers (no
    bool, complex or text, which NumPy would read as 1, drop the imaginary part of, or parse),
    finite and >= 0, with a sum > 0 (all-zero exponents make every factor 1: a score of 1.0
    for any pair)."""
    if isinstance(weights, (str, bytes)) or not hasattr(weights, "__len__"):
        raise TypeError(f"weights: expected a sequence of numbers, got {weights!r}")
    try:
        raw = np.asarray(weights)
        bad = raw.dtype.kind in "bcUSMmV" or (raw.ndim == 1 and any(
            isinstance(v, _NOT_REAL) for v in (raw if raw.dtype == object else weights)))
    except (TypeError, ValueError):
        bad = False                      # ragged: refused below, as before
    if bad:
        raise TypeError(f"weights: expected a sequence of real numbers (bool, complex and text "
                        f"are refused), got {weights!r:.80}")
    try:
        w = np.asarray(weights, dtype=np.float64)
    except OverflowError:
        raise ValueError("weights: holds a number too large for float64") from None
    except (TypeError, ValueError):
        raise TypeError(f"weights: expected a sequence of numbers, got {weights!r}") from None
    if w.ndim != 1 or w.size == 0:
        raise ValueError(f"weights: expected a non-empty 1-D sequence, got {weights!r}")
    if not np.all(np.isfinite(w)) or np.any(w < 0):
        raise ValueError(f"weights: expected finite exponents >= 0, got {weights!r}")
    if not w.sum() > 0:
        raise ValueError(f"weights: expected exponents with a sum > 0, got {weights!r}; "
                         "all-zero exponents score every pair 1.0")
    return w


#: what a weight may not be: NumPy reads True as 1, drops an imaginary part, parses text
_NOT_REAL = (bool, np.bool_, complex, np.complexfloating, str, bytes)


def _check_ssim_window(win_size, sigma):
    win_size = check_int(win_size, "win_size", lo=1, hi=_kernels.SSIM_MAX_TAPS)
    if win_size % 2 == 0:
        raise ValueError(f"win_size: expected an odd window size, got {win_size}")
    sigma = check_number(sigma, "sigma", lo=0, lo_open=True)
    return win_size, sigma


def ssim(reference, test, *, data_range=255, crop=0, channel_axis=-1, gaussian_weights=True,
         sigma=1.5, win_size=11, workers=None):
    r"""Mean structural similarity (SSIM) index (eqs. 24-27).

    Parameters
    ----------
    reference : ndarray, shape (rows, cols) or (rows, cols, channels)
        Reference image; any real dtype.
    test : ndarray, same shape as `reference`
        Image under test.
    data_range : float, default 255
        The dynamic range :math:`L` of the images (``2**bit_depth - 1``),
        in [1e-100, 1e100] (:data:`SSIM_DATA_RANGE`; beyond, the constants
        :math:`c_1, c_2` leave the range of doubles). Integer images must lie
        in [0, data_range].
    crop : int, default 0
        Pixels removed from each border of the rows and columns first.
    channel_axis : int or None, default -1
        Axis of a 3-D input that holds the channels; the score is the mean
        over channels. A 2-D input is one grey channel and this argument is
        not used; a 3-D input with ``channel_axis=None`` is an error.
    gaussian_weights : bool, default True
        Weight the window with a Gaussian of standard deviation `sigma`
        (Wang et al. 2004); False uses a uniform ``win_size`` square window.
    sigma : float, default 1.5
        Standard deviation of the Gaussian window.
    win_size : int, default 11
        Side of the (odd) window: the Gaussian is truncated to
        ``win_size`` taps, and ``(win_size - 1) // 2`` pixels are dropped at
        each border of the SSIM map before averaging. At most 255.
    workers : int, optional
        Threads of the C kernel (None or -1: every core); the result does not
        depend on it.

    Returns
    -------
    ssim : float
        Mean of the local SSIM map (1 for identical images).

    Notes
    -----
    With :math:`\alpha = \beta = \gamma = 1`, :math:`c_1 = (0.01 L)^2`,
    :math:`c_2 = (0.03 L)^2` and :math:`c_3 = c_2 / 2` the product of
    eqs. 25-27 reduces to

    .. math::

        \mathrm{SSIM}(d, r) = \frac{(2 \mu_d \mu_r + c_1)(2 \sigma_{dr} + c_2)}
        {(\mu_d^2 + \mu_r^2 + c_1)(\sigma_d^2 + \sigma_r^2 + c_2)}

    (eq. 27 of [1]_ is printed with :math:`\sigma_d + \sigma_r` in the
    denominator; the structure term of [2]_, :math:`(\sigma_{dr} + c_3) /
    (\sigma_d \sigma_r + c_3)`, is the one used). Local moments are Gaussian
    weighted population moments, as in [2]_. Only windows wholly inside the
    (cropped) image are averaged, which equals
    ``skimage.metrics.structural_similarity(reference, test,
    data_range=data_range, gaussian_weights=True, sigma=1.5,
    use_sample_covariance=False, channel_axis=-1)`` for the default
    ``sigma=1.5, win_size=11`` (skimage sizes its Gaussian from ``sigma``
    alone, so the two differ for other `sigma`), and with
    ``gaussian_weights=False`` for any `win_size`. The computation is in
    float64 for every input dtype, by a C kernel that filters the five local
    moments row by row with the separable window in the order of operations
    of ``scipy.ndimage.gaussian_filter`` (the same moments, bit for bit); only
    the mean of the map is summed in another order (per row, then the rows),
    which moves the score by about 1e-16 relative.

    References
    ----------
    .. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", eqs. 24-27 (docs/references.bib: rebiere_rgbz)
    .. [2] Wang et al., "Image quality assessment: from error visibility to structural similarity" (docs/references.bib: wang2004ssim)

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import ssim
    >>> ref = np.random.default_rng(0).integers(0, 256, (32, 32, 3), dtype=np.uint8)
    >>> ssim(ref, ref)
    1.0
    >>> noisy = np.clip(ref + np.random.default_rng(1).normal(0, 20, ref.shape), 0, 255)
    >>> 0 < ssim(ref, noisy) < 1
    True
    """
    ref, tst = _check_pair(reference, test, (2, 3))
    peak = _check_ssim_data_range(data_range)
    win_size, sigma = _check_ssim_window(win_size, sigma)
    gaussian_weights = check_flag(gaussian_weights, "gaussian_weights")
    _check_integer_range((ref, tst), ("reference", "test"), peak)
    _check_magnitude((ref, tst), ("reference", "test"), SSIM_MAX_VALUE, _SSIM_WHY)
    threads = check_workers(workers)
    x, y = _channels_first(ref, tst, channel_axis)
    crop = _check_crop(crop, x.shape[1:], minimum=win_size,
                       what=f"an image at least win_size={win_size} pixels wide")
    x, y = _kernel_pair(_crop_hw(x, crop, (1, 2)), _crop_hw(y, crop, (1, 2)))
    ssim_means, _ = _ssim_means(x, y, peak, win_size, sigma, gaussian_weights, threads)
    _warn_unit_floats((ref, tst), ("reference", "test"), peak)
    return float(ssim_means.mean())


def ms_ssim(reference, test, *, data_range=255, crop=0, weights=MS_SSIM_WEIGHTS,
            channel_axis=-1, workers=None):
    r"""Multi-scale structural similarity (MS-SSIM) index (eq. 28).

    Parameters
    ----------
    reference : ndarray, shape (rows, cols) or (rows, cols, channels)
        Reference image; any real dtype.
    test : ndarray, same shape as `reference`
        Image under test.
    data_range : float, default 255
        The dynamic range :math:`L` of the images, in [1e-100, 1e100] as in
        :func:`ssim`. Integer images must lie in [0, data_range].
    crop : int, default 0
        Pixels removed from each border of the rows and columns first.
    weights : sequence of float, default :data:`MS_SSIM_WEIGHTS`
        Exponents :math:`\beta_j = \gamma_j` of scales 1 (finest) to M, the
        last one also :math:`\alpha_M`. Their number is the number of scales
        M; the default are the five values of Wang et al. 2003. Real numbers
        (not bool) >= 0, with a sum > 0.
    channel_axis : int or None, default -1
        As in :func:`ssim`: the score is the mean over channels of the
        per-channel MS-SSIM.
    workers : int, optional
        Threads of the C kernels (None or -1: every core); the result does
        not depend on it.

    Returns
    -------
    ms_ssim : float
        The MS-SSIM index, in [0, 1] (1 for identical images).

    Raises
    ------
    ValueError
        If the (cropped) image is smaller than
        ``10 * 2**(M - 1) + 1`` pixels on a side (161 for five scales), so
        that the coarsest scale still holds one 11 x 11 window; if
        `data_range` lies outside [1e-100, 1e100].

    Notes
    -----
    .. math::

        \mathrm{MS\text{-}SSIM}(d, r) = [l_M(d, r)]^{\alpha_M}
        \prod_{j=1}^{M} [c_j(d, r)]^{\beta_j} [s_j(d, r)]^{\gamma_j}

    Each scale uses the SSIM of :func:`ssim` (11-tap Gaussian window,
    :math:`\sigma = 1.5`, windows wholly inside the image). Between scales
    the images are low-passed by a 2 x 2 mean and decimated by 2 [2]_ (a C
    kernel, with NumPy's order of the four additions). As in
    Wang et al.'s reference code, the factor of scale j < M is the mean of
    the local :math:`c \cdot s` map, and the coarsest scale contributes the
    mean of its full SSIM map :math:`l \cdot c \cdot s` raised to
    :math:`w_M`. A mean below zero (anti-correlated structure) is clipped to
    0 before the power, so a fractional exponent never meets a negative base;
    such an image scores 0.

    References
    ----------
    .. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", eq. 28 (docs/references.bib: rebiere_rgbz)
    .. [2] Wang, Simoncelli and Bovik, "Multiscale structural similarity for image quality assessment" (docs/references.bib: wang2003msssim)

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import ms_ssim
    >>> ref = np.random.default_rng(0).integers(0, 256, (161, 161), dtype=np.uint8)
    >>> ms_ssim(ref, ref)
    1.0
    >>> ms_ssim(ref[:160, :160], ref[:160, :160])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: reference: MS-SSIM with 5 scales needs at least 161 x 161 pixels ...
    """
    ref, tst = _check_pair(reference, test, (2, 3))
    peak = _check_ssim_data_range(data_range)
    w = _check_weights(weights)
    _check_integer_range((ref, tst), ("reference", "test"), peak)
    _check_magnitude((ref, tst), ("reference", "test"), SSIM_MAX_VALUE, _SSIM_WHY)
    threads = check_workers(workers)
    x, y = _channels_first(ref, tst, channel_axis)
    crop = _check_crop(crop, x.shape[1:])
    x, y = _crop_hw(x, crop, (1, 2)), _crop_hw(y, crop, (1, 2))
    _check_ms_ssim_size(x.shape[1:], w.size, crop)
    x, y = _kernel_pair(x, y)
    out = _ssim_and_ms_ssim(x, y, peak, w, threads)[1]
    _warn_unit_floats((ref, tst), ("reference", "test"), peak)
    return out
