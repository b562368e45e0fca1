"""PSNR on the reconstructed CFA sites and colour PSNR (paper eqs. 20-23)."""

from __future__ import annotations

import math

import numpy as np

from .. import _kernels
from .._validate import as_array, check_int, check_number, check_workers
from ._common import (_check_crop, _check_integer_range, _check_pair, _check_rgb_pair, _crop_hw,
                      _kernel_pair, _psnr_from_mse, _warn_unit_floats)

__all__ = ["cfa_psnr", "cpsnr", "cpsnr_pooled"]



def cfa_psnr(reference, test, mask=None, *, data_range=None, bit_depth=None, workers=None):
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
    workers : int, optional
        Threads of the C kernel (None or -1: every core).

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
    in [0, s]. The squared differences are summed by a C kernel, exactly for
    integer images (in 64-bit integers).

    References
    ----------
    .. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", eqs. 20-21 (docs/references.bib: rebiere_rgbz)

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
        bits = check_int(bit_depth, "bit_depth", lo=1)
        if bits > 32:
            raise ValueError(f"bit_depth: expected 1..32 bits, got {bit_depth}")
        peak = float(2 ** bits - 1)
        _check_integer_range((ref, tst), ("reference", "test"), peak, param="bit_depth")
    else:
        peak = check_number(data_range, "data_range", lo=0, lo_open=True)
        _check_integer_range((ref, tst), ("reference", "test"), peak)
    threads = check_workers(workers)
    m = None
    if mask is not None:
        m = as_array(mask, "mask")
        if m.dtype != np.bool_:
            raise TypeError(f"mask: expected a boolean array, got dtype {m.dtype}")
        if m.shape != ref.shape and not (m.shape == ref.shape[:2] and ref.ndim == 3):
            raise ValueError(f"mask: shape {m.shape} matches neither the image shape "
                             f"{ref.shape} nor its (rows, cols) {ref.shape[:2]}")
        if not m.any():
            raise ValueError("mask: selects no pixel; the PSNR of an empty set is undefined")
        if m.ndim == 3:                # one flag per element: each element is a 'pixel'
            ref, tst = ref.reshape(ref.shape[0], -1), tst.reshape(tst.shape[0], -1)
            m = m.reshape(m.shape[0], -1)
    out = _psnr_from_mse(*_mse(ref, tst, m, threads), peak)
    _warn_unit_floats((ref, tst), ("reference", "test"), peak,
                      "data_range" if bit_depth is None else "bit_depth")
    return out


def _mse(ref, tst, mask, threads):
    """The mean squared difference over ``mask`` (None: every element) as ``(m, e)``, the MSE
    being ``m * 4**e``.

    ``e`` is 0 and ``m`` the C kernel's sum over the count, unless the squares of float
    differences leave the normal doubles: differences beyond ~1e154 overflow the sum (inf, or
    NaN from inf - inf), differences below ~1e-154 underflow it (0 for two different images,
    or a subnormal sum that has lost its digits). Those are summed again on differences
    scaled by a power of two (exact), so the PSNR of any two finite images is a finite number
    (or inf when they are equal).
    """
    total, count = _sq_diff_sum(ref, tst, mask, threads)
    if total >= _NORMAL or (total == 0 and ref.dtype.kind in "biu" and tst.dtype.kind in "biu"):
        if total < math.inf:
            return total / count, 0
    a, b = ref.astype(np.float64), tst.astype(np.float64)
    if mask is not None:
        a, b = a[mask], b[mask]
    with np.errstate(over="ignore"):
        diff = a - b                            # exact for subnormals (no halving rounds them)
    extra = 0
    if not np.all(np.isfinite(diff)):           # beyond the largest double: halves, exact there
        diff, extra = a * 0.5 - b * 0.5, 1
    top = float(np.max(np.abs(diff)))
    if top == 0:
        return 0.0, 0
    exp = math.frexp(top)[1]
    r = np.ldexp(diff, -exp)                    # |r| < 1
    return float(np.mean(r * r)), exp + extra   # (2**extra diff)**2 = r**2 * 4**(exp + extra)


#: the smallest normal double: a sum of squares below it has lost digits (or underflowed)
_NORMAL = float(np.finfo(np.float64).tiny)


def _sq_diff_sum(ref, tst, mask, threads):
    """(sum of squared differences, number of elements) of a (rows, cols[, channels]) pair over
    the pixels where the (rows, cols) boolean `mask` is True, or over all (mask None); C kernel,
    exact for integer images."""
    a, b = _kernel_pair(ref, tst)
    if a.ndim == 2:
        a, b = a[:, :, np.newaxis], b[:, :, np.newaxis]
    if mask is not None:
        mask = np.ascontiguousarray(mask).view(np.uint8)
    return _kernels.sq_diff_sum(a, b, mask, threads)


def _rgb_mse(ref, tst, crop, threads):
    """The colour MSE after the crop, as ``(m, e)`` (see :func:`_mse`)."""
    crop = _check_crop(crop, ref.shape[:2])
    return _mse(_crop_hw(ref, crop), _crop_hw(tst, crop), None, threads)


def cpsnr(reference, test, *, data_range=255, crop=0, workers=None):
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
    workers : int, optional
        Threads of the C kernel (None or -1: every core).

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
    per-channel PSNRs. For a data set, see :func:`cpsnr_pooled`. The
    squared differences are summed by a C kernel, exactly for integer images.

    References
    ----------
    .. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", eqs. 22-23 (docs/references.bib: rebiere_rgbz)

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.metrics import cpsnr
    >>> ref = np.full((8, 8, 3), 100, dtype=np.uint8)
    >>> round(cpsnr(ref, ref + 5), 4)          # 10 log10(255**2 / 25)
    34.1514
    """
    ref, tst = _check_rgb_pair(reference, test)
    peak = check_number(data_range, "data_range", lo=0, lo_open=True)
    _check_integer_range((ref, tst), ("reference", "test"), peak)
    out = _psnr_from_mse(*_rgb_mse(ref, tst, crop, check_workers(workers)), peak)
    _warn_unit_floats((ref, tst), ("reference", "test"), peak)
    return out


def cpsnr_pooled(references, tests, *, data_range=255, crop=0, workers=None):
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
    workers : int, optional
        Threads of the C kernel (None or -1: every core).

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
    peak = check_number(data_range, "data_range", lo=0, lo_open=True)
    threads = check_workers(workers)
    mses = []
    for i, (r, t) in enumerate(zip(references, tests)):
        ref, tst = _check_rgb_pair(r, t, f"references[{i}]", f"tests[{i}]")
        _check_integer_range((ref, tst), (f"references[{i}]", f"tests[{i}]"), peak)
        mses.append(_rgb_mse(ref, tst, crop, threads))
    _warn_unit_floats(list(references) + list(tests), ("references", "tests"), peak)
    # the scale of the pairs that differ (an identical pair, 0 at any scale, would pull it to
    # 0 and leave a tiny pair's scaled term subnormal)
    top = max((e for m, e in mses if m > 0), default=0)
    # a common scale: the mean of m_i * 4**e_i is 4**top times the mean of the scaled terms
    # (with top == 0 too, where ldexp by 0 leaves the ordinary pairs' values as they are: a
    # pair of differences below 1e-154, whose e is negative, had been taken at its scaled m)
    return _psnr_from_mse(float(np.mean([math.ldexp(m, 2 * (e - top)) for m, e in mses])),
                          top, peak)
