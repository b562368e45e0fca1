"""Slow NumPy / SciPy / colour-science references of the metric kernels (csrc/metrics.c).

These are the implementations ``rgbz_fast.metrics`` used before its C kernels,
kept as they were: SSIM and MS-SSIM with ``scipy.ndimage.gaussian_filter`` over a
stack of the five moment images, the 2 x 2 decimation by ``reshape().mean()``,
CIELAB through ``colour.XYZ_to_Lab(colour.sRGB_to_XYZ(...))`` and the zipper
metric over eight shifted whole-image views. They take validated arrays (the
public functions' checks are not repeated) and compute in float64.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage as ndi

__all__ = ["ssim_maps", "downsample2", "ssim", "ms_ssim", "to_lab", "zipper_lab",
           "zipper_map", "zipper", "delta_e", "mse"]

MS_SSIM_WEIGHTS = (0.0448, 0.2856, 0.3001, 0.2363, 0.1333)
NEIGHBOURS = ((-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 1), (1, -1), (1, 0), (1, 1))


def mse(reference, test, mask=None):
    """Mean of the squared differences over the elements where the (broadcast) mask is True."""
    diff2 = (np.asarray(reference).astype(np.float64)
             - np.asarray(test).astype(np.float64)) ** 2
    if mask is None:
        return float(diff2.mean())
    m = np.asarray(mask)
    if m.shape == diff2.shape[:2] and diff2.ndim == 3:
        m = m[:, :, np.newaxis]
    m = np.broadcast_to(m, diff2.shape)
    return float(diff2[m].sum() / np.count_nonzero(m))


def _channels_first(ref, tst, channel_axis=-1):
    if ref.ndim == 2:
        return ref[np.newaxis].astype(np.float64), tst[np.newaxis].astype(np.float64)
    return (np.moveaxis(ref, channel_axis, 0).astype(np.float64),
            np.moveaxis(tst, channel_axis, 0).astype(np.float64))


def _crop(a, crop, axes):
    if crop == 0:
        return a
    index = [slice(None)] * a.ndim
    for ax in axes:
        index[ax] = slice(crop, a.shape[ax] - crop)
    return a[tuple(index)]


def ssim_maps(x, y, data_range, win_size=11, sigma=1.5, gaussian_weights=True):
    """SSIM and contrast-structure maps of (channels, rows, cols) float64 stacks ('valid')."""
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
    vx = mxx - mx * mx
    vy = myy - my * my
    vxy = mxy - mx * my
    c1 = (0.01 * data_range) ** 2
    c2 = (0.03 * data_range) ** 2
    luminance = (2 * mx * my + c1) / (mx * mx + my * my + c1)
    contrast_structure = (2 * vxy + c2) / (vx + vy + c2)
    return luminance * contrast_structure, contrast_structure


def downsample2(a):
    """2x2 mean then every second pixel; odd sides padded 'symmetric' (Wang et al.)."""
    rows, cols = a.shape[-2:]
    if rows % 2 or cols % 2:
        a = np.pad(a, ((0, 0), (0, rows % 2), (0, cols % 2)), mode="symmetric")
    c, r2, c2 = a.shape
    return a.reshape(c, r2 // 2, 2, c2 // 2, 2).mean(axis=(2, 4))


def ssim(reference, test, data_range=255, crop=0, channel_axis=-1, gaussian_weights=True,
         sigma=1.5, win_size=11):
    x, y = _channels_first(np.asarray(reference), np.asarray(test), channel_axis)
    x, y = _crop(x, crop, (1, 2)), _crop(y, crop, (1, 2))
    ssim_map, _ = ssim_maps(x, y, data_range, win_size, sigma, gaussian_weights)
    return float(ssim_map.mean(axis=(1, 2)).mean())


def ms_ssim(reference, test, data_range=255, crop=0, weights=MS_SSIM_WEIGHTS,
            channel_axis=-1):
    x, y = _channels_first(np.asarray(reference), np.asarray(test), channel_axis)
    x, y = _crop(x, crop, (1, 2)), _crop(y, crop, (1, 2))
    w = np.asarray(weights, dtype=np.float64)
    factors = np.empty((w.size, x.shape[0]))
    for j in range(w.size):
        ssim_map, cs_map = ssim_maps(x, y, data_range)
        last = j == w.size - 1
        factors[j] = (ssim_map if last else cs_map).mean(axis=(1, 2))
        if not last:
            x, y = downsample2(x), downsample2(y)
    return float(np.prod(np.maximum(factors, 0.0) ** w[:, np.newaxis], axis=0).mean())


def to_lab(rgb, full_scale):
    """CIELAB (D65) of sRGB code values over ``full_scale`` with colour-science; None: Lab."""
    if full_scale is None:
        return np.asarray(rgb, dtype=np.float64)
    import colour

    rgb01 = np.asarray(rgb).astype(np.float64) / full_scale
    with colour.utilities.domain_range_scale("reference"):
        return np.asarray(colour.XYZ_to_Lab(colour.sRGB_to_XYZ(rgb01)), dtype=np.float64)


def delta_e(lab1, lab2):
    d = lab1 - lab2
    return np.sqrt(np.sum(d * d, axis=-1))


def zipper_map(lab_ref, lab_test, delta):
    """(|psi| > delta map of the interior pixels, psi, index of the chosen neighbour)."""
    rows, cols = lab_ref.shape[:2]
    centre_ref = lab_ref[1:-1, 1:-1]
    centre_test = lab_test[1:-1, 1:-1]
    best_ref = np.full(centre_ref.shape[:2], np.inf)
    best_test = np.zeros(centre_ref.shape[:2])
    chosen = np.full(centre_ref.shape[:2], -1)
    for k, (dr, dc) in enumerate(NEIGHBOURS):
        window = (slice(1 + dr, rows - 1 + dr), slice(1 + dc, cols - 1 + dc))
        de_ref = delta_e(centre_ref, lab_ref[window])
        closer = de_ref < best_ref                   # strict: ties keep the earlier one
        best_ref = np.where(closer, de_ref, best_ref)
        best_test = np.where(closer, delta_e(centre_test, lab_test[window]), best_test)
        chosen = np.where(closer, k, chosen)
    psi = best_test - best_ref
    return np.abs(psi) > delta, psi, chosen


def zipper_lab(lab_ref, lab_test, delta):
    """Percentage of interior pixels with |psi| > delta (eqs. 30-31)."""
    flags = zipper_map(lab_ref, lab_test, delta)[0]
    return float(100.0 * np.count_nonzero(flags) / flags.size)


def zipper(reference, test, delta=2.3, crop=0, full_scale=255.0):
    ref = _crop(np.asarray(reference), crop, (0, 1))
    tst = _crop(np.asarray(test), crop, (0, 1))
    return zipper_lab(to_lab(ref, full_scale), to_lab(tst, full_scale), delta)
