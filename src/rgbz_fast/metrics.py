"""Image-quality metrics of Rebiere et al., section 5.3 (eqs. 20-31).

Two levels of assessment are used in the paper [1]_:

* on the reconstructed CFA image, the PSNR restricted to the reconstructed
  (Z) sites: :func:`cfa_psnr` (eqs. 20-21);
* on the full-colour image at the end of the ISP: the colour PSNR
  :func:`cpsnr` (eqs. 22-23, with :func:`cpsnr_pooled` for a data set),
  the SSIM :func:`ssim` (eqs. 24-27) [2]_, the multi-scale SSIM
  :func:`ms_ssim` (eq. 28) [3]_ and the zipper-effect metric :func:`zipper`
  (eqs. 29-31) [4]_. :func:`all_metrics` returns the four colour metrics.

Every function takes the reference first and the image under test second
and works in float64 whatever the input dtype, so uint8 and float inputs
holding the same values give the same results; every score is returned as a
Python ``float``.

``crop`` removes that many pixels from each border of the rows and columns
before anything else is computed (the usual way to keep demosaicing border
artefacts out of a score).

References
----------
.. [1] V. Rebiere, A. Drouot, B. Granado, A. Bourge, A. Pinna, "Color pixel
       reconstruction for a monolithic RGB-Z CMOS imager", section 5.3.
.. [2] Z. Wang, A. C. Bovik, H. R. Sheikh, E. P. Simoncelli, "Image quality
       assessment: from error visibility to structural similarity," IEEE
       Trans. Image Process. 13(4), 600-612 (2004). :DOI:`10.1109/TIP.2003.819861`
.. [3] Z. Wang, E. P. Simoncelli, A. C. Bovik, "Multiscale structural
       similarity for image quality assessment," Proc. 37th Asilomar Conf.
       Signals, Systems and Computers, 1398-1402 (2003).
       :DOI:`10.1109/ACSSC.2003.1292216`
.. [4] W. Lu, Y.-P. Tan, "Color filter array demosaicking: new method and
       performance measures," IEEE Trans. Image Process. 12(10), 1194-1210
       (2003). :DOI:`10.1109/TIP.2003.816004`
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from ._validate import check_choice, check_image

__all__ = [
    "cfa_psnr",
    "cpsnr",
    "cpsnr_pooled",
    "ssim",
    "ms_ssim",
    "zipper",
    "delta_e_map",
    "all_metrics",
    "MS_SSIM_WEIGHTS",
    "ZIPPER_INPUTS",
]

#: Exponents beta_j = gamma_j (and alpha_M) of eq. 28, from Wang et al. 2003.
MS_SSIM_WEIGHTS = (0.0448, 0.2856, 0.3001, 0.2363, 0.1333)

#: Encodings accepted by :func:`zipper` and :func:`delta_e_map`, with the code
#: value of sRGB white (None: the input is already CIELAB).
ZIPPER_INPUTS = {"srgb8": 255.0, "srgb16": 65535.0, "srgb01": 1.0, "lab": None}

# The eight neighbours of eq. 30 in raster order; on a tie of the reference
# Delta E the first one in this order is taken.
_NEIGHBOURS = ((-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1))


# --------------------------------------------------------------------------
# argument checks (Python validates; every message names the parameter)
# --------------------------------------------------------------------------

def _check_positive_real(value, name, *, allow_zero=False):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}: expected a real number, got {value!r}")
    value = float(value)
    if not math.isfinite(value) or value < 0 or (value == 0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise ValueError(f"{name}: expected a finite number {bound}, got {value!r}")
    return value


#: the data_range SSIM and MS-SSIM accept: c1 = (0.01 L)**2 and the local moments of data
#: in [0, L] (squares of about L**2) stay normal, finite doubles with a wide margin (1e-100
#: to 1e100 leaves 1e54 for data beyond L); outside, c1 overflows (OverflowError) or
#: underflows to 0 (0/0 = NaN in flat windows)
SSIM_DATA_RANGE = (1e-100, 1e100)


def _check_ssim_data_range(value):
    peak = _check_positive_real(value, "data_range")
    lo, hi = SSIM_DATA_RANGE
    if not lo <= peak <= hi:
        raise ValueError(f"data_range: expected a number in [{lo:g}, {hi:g}] for SSIM, got "
                         f"{value!r}; rescale the images (the constants (0.01 * data_range)**2 "
                         "and the squared data must stay normal, finite doubles)")
    return peak


def _check_int(value, name, minimum):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}: expected an integer, got {value!r}")
    if value < minimum:
        raise ValueError(f"{name}: expected an integer >= {minimum}, got {value!r}")
    return int(value)


def _check_pair(reference, test, ndim, ref_name="reference", test_name="test"):
    """Both arrays real, finite, non-empty, of `ndim` dimensions and equal shapes."""
    ref = check_image(reference, ref_name, ndim=ndim)
    tst = check_image(test, test_name, ndim=ndim)
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


def _check_integer_range(arrays, names, data_range, param="data_range"):
    """Integer code values must lie in [0, data_range].

    An integer image above its declared range almost always means a wrong
    `data_range` (e.g. 11-bit data in uint16 with the 8-bit default), which
    would silently inflate every score. Float images are not checked: a
    reconstruction may legitimately overshoot.
    """
    for a, name in zip(arrays, names):
        if np.issubdtype(a.dtype, np.integer):
            lo, hi = int(a.min()), int(a.max())
            if lo < 0 or hi > data_range:
                raise ValueError(f"{param}: {name} holds integer values in [{lo}, {hi}], "
                                 f"outside [0, {data_range:g}]; pass the real range of the "
                                 f"data (2**bit_depth - 1)")


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
    crop = _check_int(crop, "crop", 0)
    left = min(shape) - 2 * crop
    if left < minimum:
        raise ValueError(f"crop: crop={crop} leaves {shape[0] - 2 * crop} x "
                         f"{shape[1] - 2 * crop} pixels of a {shape[0]} x {shape[1]} image; "
                         f"the metric needs {what} (at least {minimum} x {minimum})")
    return crop


def _psnr_from_mse(mse, peak):
    if mse == 0:
        return math.inf
    return float(10.0 * np.log10(peak * peak / mse))


# --------------------------------------------------------------------------
# PSNR family (eqs. 20-23)
# --------------------------------------------------------------------------

def cfa_psnr(reference, test, mask=None, *, data_range=None, bit_depth=None):
    r"""PSNR of a reconstructed CFA image on the masked (reconstructed) sites.

    Parameters
    ----------
    reference : ndarray, shape (rows, cols[, channels])
        The reference CFA image (the plain Bayer mosaic of the same exposure).
        uint8, uint16 or float.
    test : ndarray, same shape as `reference`
        The reconstructed CFA image.
    mask : ndarray of bool, shape (rows, cols) or same shape as `reference`, optional
        True at the pixels that enter the score, normally the Z sites
        (:attr:`rgbz_fast.RawFrame.z_mask`). A (rows, cols) mask applies to
        every channel of a 3-D image. None scores every pixel.
    data_range : float, optional
        The peak value :math:`s` of eq. 21.
    bit_depth : int, optional
        Alternative to `data_range`: :math:`s = 2^b - 1`. Exactly one of
        `data_range` and `bit_depth` must be given.

    Returns
    -------
    psnr : float
        PSNR in dB; ``inf`` when the masked pixels are identical.

    Notes
    -----
    Eqs. 20-21 of [1]_ with the mean taken over the masked pixels only:

    .. math::

        \mathrm{MSE} = \frac{1}{|\Omega|} \sum_{(m, n) \in \Omega}
        (I_d(m, n) - I_r(m, n))^2, \qquad
        \mathrm{PSNR} = 10 \log_{10} \frac{s^2}{\mathrm{MSE}}

    The peak :math:`s` is never guessed, for integer or float input: the
    paper's raw frames are 11-bit values held in uint16 (or as floats), so a
    dtype-based default (65535 or 1.0) would be wrong. Integer images must lie
    in [0, s].

    References
    ----------
    .. [1] V. Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z
           CMOS imager", eqs. 20-21.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import cfa_psnr
    >>> ref = np.full((4, 4), 100, dtype=np.uint16)
    >>> test = ref.copy()
    >>> test[1, 1] = 110                     # the one reconstructed site is off by 10
    >>> mask = np.zeros((4, 4), dtype=bool)
    >>> mask[1, 1] = True
    >>> round(cfa_psnr(ref, test, mask, bit_depth=11), 2)   # 10 log10(2047**2 / 100)
    46.22
    >>> cfa_psnr(ref, ref, mask, bit_depth=11)
    inf
    """
    ref, tst = _check_pair(reference, test, (2, 3))
    if (data_range is None) == (bit_depth is None):
        raise ValueError("data_range: pass exactly one of data_range (the peak value s) and "
                         "bit_depth (s = 2**bit_depth - 1); "
                         + ("got both" if data_range is not None else "got neither"))
    if bit_depth is not None:
        bits = _check_int(bit_depth, "bit_depth", 1)
        if bits > 32:
            raise ValueError(f"bit_depth: expected 1..32 bits, got {bit_depth}")
        peak = float(2 ** bits - 1)
        _check_integer_range((ref, tst), ("reference", "test"), peak, param="bit_depth")
    else:
        peak = _check_positive_real(data_range, "data_range")
        _check_integer_range((ref, tst), ("reference", "test"), peak)
    diff2 = (ref.astype(np.float64) - tst.astype(np.float64)) ** 2
    if mask is None:
        return _psnr_from_mse(float(diff2.mean()), peak)
    m = np.asarray(mask)
    if m.dtype != np.bool_:
        raise TypeError(f"mask: expected a boolean array, got dtype {m.dtype}")
    if m.shape == ref.shape[:2] and ref.ndim == 3:
        m = m[:, :, np.newaxis]
    elif m.shape != ref.shape:
        raise ValueError(f"mask: shape {m.shape} matches neither the image shape {ref.shape} "
                         f"nor its (rows, cols) {ref.shape[:2]}")
    m = np.broadcast_to(m, ref.shape)
    count = int(np.count_nonzero(m))
    if count == 0:
        raise ValueError("mask: selects no pixel; the PSNR of an empty set is undefined")
    return _psnr_from_mse(float(diff2[m].sum() / count), peak)


def _rgb_mse(ref, tst, crop):
    crop = _check_crop(crop, ref.shape[:2])
    diff = _crop_hw(ref, crop).astype(np.float64) - _crop_hw(tst, crop).astype(np.float64)
    return float(np.mean(diff * diff))


def cpsnr(reference, test, *, data_range=255, crop=0):
    r"""Colour PSNR of a full-colour image (eqs. 22-23).

    Parameters
    ----------
    reference : ndarray, shape (rows, cols, 3)
        Reference colour image (typically 8-bit sRGB); any real dtype.
    test : ndarray, shape (rows, cols, 3)
        Reconstructed colour image.
    data_range : float, default 255
        The peak value :math:`s`. Integer images must lie in [0, data_range].
    crop : int, default 0
        Pixels removed from each border of the rows and columns first.

    Returns
    -------
    cpsnr : float
        C-PSNR in dB; ``inf`` for identical images.

    Notes
    -----
    The mean squared error is taken over the three channels together:

    .. math::

        \mathrm{MSE}_C = \frac{1}{3NM} \sum_{k=1}^{3} \sum_{m, n}
        (I_d(m, n, k) - I_r(m, n, k))^2, \qquad
        \mathrm{C\text{-}PSNR} = 10 \log_{10} \frac{s^2}{\mathrm{MSE}_C}

    The three channels share one MSE, so this is not the mean of three
    per-channel PSNRs. For a data set, see :func:`cpsnr_pooled`.

    References
    ----------
    .. [1] V. Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z
           CMOS imager", eqs. 22-23.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import cpsnr
    >>> ref = np.full((8, 8, 3), 100, dtype=np.uint8)
    >>> round(cpsnr(ref, ref + 5), 4)          # 10 log10(255**2 / 25)
    34.1514
    """
    ref, tst = _check_rgb_pair(reference, test)
    peak = _check_positive_real(data_range, "data_range")
    _check_integer_range((ref, tst), ("reference", "test"), peak)
    return _psnr_from_mse(_rgb_mse(ref, tst, crop), peak)


def cpsnr_pooled(references, tests, *, data_range=255, crop=0):
    r"""C-PSNR of a set of images, from the mean of their colour MSEs.

    Parameters
    ----------
    references : sequence of ndarray, each of shape (rows_i, cols_i, 3)
        Reference colour images; sizes may differ between images.
    tests : sequence of ndarray
        Reconstructed images, one per reference and of the same shape.
    data_range : float, default 255
        The peak value :math:`s`.
    crop : int, default 0
        Pixels removed from each border of every image first.

    Returns
    -------
    cpsnr : float
        :math:`10 \log_{10}(s^2 / \overline{\mathrm{MSE}_C})` in dB, ``inf``
        when every pair is identical.

    Notes
    -----
    Every image has the same weight in the mean MSE, whatever its size (for
    equal sizes this is the same as pooling all pixels). The average of the
    per-image C-PSNRs, which weights bad images less, is simply
    ``np.mean([cpsnr(r, t) for r, t in zip(references, tests)])``; the two
    differ, so say which one a table reports.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import cpsnr, cpsnr_pooled
    >>> ref = np.full((8, 8, 3), 100, dtype=np.uint8)
    >>> refs, tests = [ref, ref], [ref + 1, ref + 7]          # MSE 1 and 49
    >>> round(cpsnr_pooled(refs, tests), 4)                   # 10 log10(255**2 / 25)
    34.1514
    >>> round(float(np.mean([cpsnr(r, t) for r, t in zip(refs, tests)])), 4)
    39.6798
    """
    for value, name in ((references, "references"), (tests, "tests")):
        if isinstance(value, np.ndarray) and value.ndim != 4:
            raise TypeError(f"{name}: expected a sequence of (rows, cols, 3) images, got an "
                            f"array of shape {value.shape}")
        if not hasattr(value, "__len__"):
            raise TypeError(f"{name}: expected a sequence of images, got {type(value).__name__}")
    if len(references) != len(tests):
        raise ValueError(f"tests: {len(tests)} images for {len(references)} references")
    if len(references) == 0:
        raise ValueError("references: the sequence is empty")
    peak = _check_positive_real(data_range, "data_range")
    mses = []
    for i, (r, t) in enumerate(zip(references, tests)):
        ref, tst = _check_rgb_pair(r, t, f"references[{i}]", f"tests[{i}]")
        _check_integer_range((ref, tst), (f"references[{i}]", f"tests[{i}]"), peak)
        mses.append(_rgb_mse(ref, tst, crop))
    return _psnr_from_mse(float(np.mean(mses)), peak)


# --------------------------------------------------------------------------
# SSIM family (eqs. 24-28)
# --------------------------------------------------------------------------

def _channels_first(ref, tst, channel_axis):
    """(channels, rows, cols) float64 views of a 2-D or 3-D pair."""
    if ref.ndim == 2:
        return ref[np.newaxis].astype(np.float64), tst[np.newaxis].astype(np.float64)
    if channel_axis is None:
        raise ValueError("channel_axis: a 3-D image needs the axis of its channels "
                         "(volumetric SSIM is not supported)")
    if isinstance(channel_axis, bool) or not isinstance(channel_axis, numbers.Integral):
        raise TypeError(f"channel_axis: expected an integer or None, got {channel_axis!r}")
    if not -3 <= channel_axis <= 2:
        raise ValueError(f"channel_axis: {channel_axis} is out of range for a 3-D image")
    return (np.moveaxis(ref, channel_axis, 0).astype(np.float64),
            np.moveaxis(tst, channel_axis, 0).astype(np.float64))


def _ssim_maps(x, y, data_range, win_size, sigma, gaussian_weights):
    """Local SSIM and contrast-structure maps of (channels, rows, cols) float64 stacks.

    The maps are cropped by the window radius, so every value comes from a
    window lying wholly inside the image (the 'valid' part of Wang et al.'s
    MATLAB code); the boundary mode of the filter then does not matter.
    """
    from scipy import ndimage as ndi   # lazy: keeps `import rgbz_fast` light

    pad = (win_size - 1) // 2
    stack = np.stack([x, y, x * x, y * y, x * y])           # (5, channels, rows, cols)
    if gaussian_weights:
        filtered = ndi.gaussian_filter(stack, sigma=(0, 0, sigma, sigma),
                                       radius=(0, 0, pad, pad), mode="reflect")
    else:
        filtered = ndi.uniform_filter(stack, size=(1, 1, win_size, win_size),
                                      mode="reflect")
    if pad:
        filtered = filtered[:, :, pad:-pad, pad:-pad]
    mx, my, mxx, myy, mxy = filtered
    # population (weighted) moments, as in Wang et al. 2004
    vx = mxx - mx * mx
    vy = myy - my * my
    vxy = mxy - mx * my
    c1 = (0.01 * data_range) ** 2
    c2 = (0.03 * data_range) ** 2
    luminance = (2 * mx * my + c1) / (mx * mx + my * my + c1)
    # with c3 = c2 / 2, c(d, r) s(d, r) = (2 sigma_dr + c2) / (sigma_d^2 + sigma_r^2 + c2)
    contrast_structure = (2 * vxy + c2) / (vx + vy + c2)
    return luminance * contrast_structure, contrast_structure


def _check_ssim_window(win_size, sigma):
    win_size = _check_int(win_size, "win_size", 1)
    if win_size % 2 == 0:
        raise ValueError(f"win_size: expected an odd window size, got {win_size}")
    sigma = _check_positive_real(sigma, "sigma")
    return win_size, sigma


def ssim(reference, test, *, data_range=255, crop=0, channel_axis=-1, gaussian_weights=True,
         sigma=1.5, win_size=11):
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
        each border of the SSIM map before averaging.

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
    float64 for every input dtype.

    References
    ----------
    .. [1] V. Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z
           CMOS imager", eqs. 24-27.
    .. [2] Z. Wang, A. C. Bovik, H. R. Sheikh, E. P. Simoncelli, "Image quality
           assessment: from error visibility to structural similarity," IEEE
           Trans. Image Process. 13(4), 600-612 (2004).

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
    gaussian_weights = bool(gaussian_weights)
    _check_integer_range((ref, tst), ("reference", "test"), peak)
    x, y = _channels_first(ref, tst, channel_axis)
    crop = _check_crop(crop, x.shape[1:], minimum=win_size,
                       what=f"an image at least win_size={win_size} pixels wide")
    x, y = _crop_hw(x, crop, (1, 2)), _crop_hw(y, crop, (1, 2))
    ssim_map, _ = _ssim_maps(x, y, peak, win_size, sigma, gaussian_weights)
    return float(ssim_map.mean(axis=(1, 2)).mean())


def _downsample2(a):
    """2x2 mean then keep every second pixel (Wang et al.'s MATLAB code).

    Odd sides are padded by repeating the last row/column ('symmetric'), so
    a side of n becomes ceil(n / 2).
    """
    rows, cols = a.shape[-2:]
    if rows % 2 or cols % 2:
        a = np.pad(a, ((0, 0), (0, rows % 2), (0, cols % 2)), mode="symmetric")
    c, r2, c2 = a.shape
    return a.reshape(c, r2 // 2, 2, c2 // 2, 2).mean(axis=(2, 4))


def ms_ssim(reference, test, *, data_range=255, crop=0, weights=MS_SSIM_WEIGHTS,
            channel_axis=-1):
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
        M; the default are the five values of Wang et al. 2003.
    channel_axis : int or None, default -1
        As in :func:`ssim`: the score is the mean over channels of the
        per-channel MS-SSIM.

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
    the images are low-passed by a 2 x 2 mean and decimated by 2 [2]_. As in
    Wang et al.'s reference code, the factor of scale j < M is the mean of
    the local :math:`c \cdot s` map, and the coarsest scale contributes the
    mean of its full SSIM map :math:`l \cdot c \cdot s` raised to
    :math:`w_M`. A mean below zero (anti-correlated structure) is clipped to
    0 before the power, so a fractional exponent never meets a negative base;
    such an image scores 0.

    References
    ----------
    .. [1] V. Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z
           CMOS imager", eq. 28.
    .. [2] Z. Wang, E. P. Simoncelli, A. C. Bovik, "Multiscale structural
           similarity for image quality assessment," Proc. 37th Asilomar Conf.
           Signals, Systems and Computers (2003).

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
    if isinstance(weights, (str, bytes)) or not hasattr(weights, "__len__"):
        raise TypeError(f"weights: expected a sequence of numbers, got {weights!r}")
    try:
        w = np.asarray(weights, dtype=np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"weights: expected a sequence of numbers, got {weights!r}") from None
    if w.ndim != 1 or w.size == 0:
        raise ValueError(f"weights: expected a non-empty 1-D sequence, got {weights!r}")
    if not np.all(np.isfinite(w)) or np.any(w < 0):
        raise ValueError(f"weights: expected finite exponents >= 0, got {weights!r}")
    _check_integer_range((ref, tst), ("reference", "test"), peak)
    x, y = _channels_first(ref, tst, channel_axis)
    crop = _check_crop(crop, x.shape[1:])
    x, y = _crop_hw(x, crop, (1, 2)), _crop_hw(y, crop, (1, 2))
    win_size, levels = 11, w.size
    minimum = (win_size - 1) * 2 ** (levels - 1) + 1
    if min(x.shape[1:]) < minimum:
        raise ValueError(f"reference: MS-SSIM with {levels} scales needs at least "
                         f"{minimum} x {minimum} pixels (after crop={crop}), got "
                         f"{x.shape[1]} x {x.shape[2]}")
    factors = np.empty((levels, x.shape[0]))                 # (scales, channels)
    for j in range(levels):                                 # 5 scales, not pixels
        ssim_map, cs_map = _ssim_maps(x, y, peak, win_size, 1.5, True)
        last = j == levels - 1
        factors[j] = (ssim_map if last else cs_map).mean(axis=(1, 2))
        if not last:
            x, y = _downsample2(x), _downsample2(y)
    per_channel = np.prod(np.maximum(factors, 0.0) ** w[:, np.newaxis], axis=0)
    return float(per_channel.mean())


# --------------------------------------------------------------------------
# zipper-effect metric (eqs. 29-31)
# --------------------------------------------------------------------------

def _to_lab(rgb, input):
    """CIELAB (D65, CIE 1931 2 deg) of an (rows, cols, 3) image in encoding `input`."""
    full_scale = ZIPPER_INPUTS[input]
    if full_scale is None:
        return rgb.astype(np.float64)
    import colour   # lazy: colour-science takes about a second to import

    rgb01 = rgb.astype(np.float64) / full_scale
    # Pin colour's domain-range scale to 'reference' (Lab L* in 0..100), but
    # only when the user changed it: the setting is process-global state.
    if colour.utilities.get_domain_range_scale() != "reference":
        with colour.utilities.domain_range_scale("reference"):
            return np.asarray(colour.XYZ_to_Lab(colour.sRGB_to_XYZ(rgb01)), dtype=np.float64)
    return np.asarray(colour.XYZ_to_Lab(colour.sRGB_to_XYZ(rgb01)), dtype=np.float64)


def _check_colour_input(ref, tst, input):
    input = check_choice(input, tuple(ZIPPER_INPUTS), "input")
    if ZIPPER_INPUTS[input] is not None:
        _check_integer_range((ref, tst), ("reference", "test"), ZIPPER_INPUTS[input],
                             param="input")
    return input


def _delta_e(lab1, lab2):
    d = lab1 - lab2
    return np.sqrt(np.sum(d * d, axis=-1))


def _zipper_lab(lab_ref, lab_test, delta):
    """Percentage of interior pixels with |psi| > delta (eqs. 30-31)."""
    rows, cols = lab_ref.shape[:2]
    centre_ref = lab_ref[1:-1, 1:-1]
    centre_test = lab_test[1:-1, 1:-1]
    best_ref = np.full(centre_ref.shape[:2], np.inf)
    best_test = np.zeros(centre_ref.shape[:2])
    for dr, dc in _NEIGHBOURS:                       # 8 shifted whole-image views
        window = (slice(1 + dr, rows - 1 + dr), slice(1 + dc, cols - 1 + dc))
        de_ref = _delta_e(centre_ref, lab_ref[window])
        closer = de_ref < best_ref                   # strict: ties keep the earlier one
        best_ref = np.where(closer, de_ref, best_ref)
        best_test = np.where(closer, _delta_e(centre_test, lab_test[window]), best_test)
    psi = best_test - best_ref
    return float(100.0 * np.count_nonzero(np.abs(psi) > delta) / psi.size)


def delta_e_map(reference, test, *, input="srgb8"):
    r"""Per-pixel CIE 1976 colour difference :math:`\Delta E^*_{ab}` of two images.

    Parameters
    ----------
    reference, test : ndarray, shape (rows, cols, 3)
        Colour images in the encoding `input`.
    input : {'srgb8', 'srgb16', 'srgb01', 'lab'}, default 'srgb8'
        sRGB code values scaled to 255, 65535 or 1 (converted to CIELAB under
        D65 with colour-science), or images already in CIELAB.

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
    return _delta_e(_to_lab(ref, input), _to_lab(tst, input))


def zipper(reference, test, *, delta=2.3, crop=0, input="srgb8"):
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
    .. [1] V. Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z
           CMOS imager", eqs. 29-31.
    .. [2] W. Lu, Y.-P. Tan, "Color filter array demosaicking: new method and
           performance measures," IEEE Trans. Image Process. 12(10),
           1194-1210 (2003).

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
    delta = _check_positive_real(delta, "delta", allow_zero=True)
    input = _check_colour_input(ref, tst, input)
    crop = _check_crop(crop, ref.shape[:2], minimum=3,
                       what="a centre pixel with all eight neighbours")
    ref, tst = _crop_hw(ref, crop), _crop_hw(tst, crop)
    return _zipper_lab(_to_lab(ref, input), _to_lab(tst, input), delta)


def all_metrics(reference_rgb, test_rgb, *, data_range=255, crop=0):
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
    images raise ValueError rather than returning a partial dict.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import all_metrics
    >>> ref = np.random.default_rng(0).integers(0, 256, (161, 161, 3), dtype=np.uint8)
    >>> all_metrics(ref, ref)
    {'cpsnr': inf, 'ssim': 1.0, 'ms_ssim': 1.0, 'zipper': 0.0}
    """
    ref, tst = _check_rgb_pair(reference_rgb, test_rgb, "reference_rgb", "test_rgb")
    peak = _check_positive_real(data_range, "data_range")
    _check_integer_range((ref, tst), ("reference_rgb", "test_rgb"), peak)
    crop = _check_crop(crop, ref.shape[:2], minimum=3,
                       what="a centre pixel with all eight neighbours")
    ref, tst = _crop_hw(ref, crop), _crop_hw(tst, crop)
    return {
        "cpsnr": cpsnr(ref, tst, data_range=peak),
        "ssim": ssim(ref, tst, data_range=peak),
        "ms_ssim": ms_ssim(ref, tst, data_range=peak),
        "zipper": _zipper_lab(_to_lab(ref / peak, "srgb01"), _to_lab(tst / peak, "srgb01"),
                              2.3),
    }
