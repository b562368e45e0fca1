"""A slow reference of the defect correction of ``rgbz_fast.isp``, pixel by pixel.

Written from the definition in the docstring of :class:`rgbz_fast.isp.DefectCorrection`,
one colour pixel at a time with plain Python loops over its 5x5 window and its
8-neighbourhood, reading colours from ``Pattern.channel_map`` (the library works on
padded per-position sub-images and reads colours from the tile). The arithmetic
types are the library's: the detection compares float32 values (differences and the
``spread_factor`` product rounded to float32, as NumPy's float32 arithmetic does),
its third test and the correction's median work in float64. Sums of at most 24
float32 values are exact in float64 whatever the order (``math.fsum`` here, NumPy's
pairwise sum there) for the frames of the tests (values below 2**16 with float32's
24-bit mantissa), so the two agree bit for bit.
"""

from __future__ import annotations

import math

import numpy as np

from rgbz_fast._patterns import Z, get_pattern
from rgbz_fast.isp import DefectCorrection

__all__ = ["reference_detect_defects", "reference_correct_defects"]

f32 = np.float32


def _same_colour_neighbours(channels, y, x):
    """Positions of the same-colour non-Z pixels of the 5x5 window around (y, x), inside the
    frame, the pixel itself excluded."""
    H, W = channels.shape
    c = channels[y, x]
    return [(y + dy, x + dx) for dy in range(-2, 3) for dx in range(-2, 3)
            if (dy or dx) and 0 <= y + dy < H and 0 <= x + dx < W
            and channels[y + dy, x + dx] == c]


def _trimmed_mean(values):
    """Mean of ``values`` without the largest and the smallest one when there are 3 or more."""
    if len(values) >= 3:
        return (math.fsum(values) - max(values) - min(values)) / (len(values) - 2)
    return math.fsum(values) / len(values)


def _is_defect(v32, channels, y, x, thr, k, f):
    """Tests 1 to 3 of DefectCorrection for the colour pixel (y, x)."""
    nb = [v32[q] for q in _same_colour_neighbours(channels, y, x)]
    if not nb:
        return False                          # a pixel without neighbours is never flagged
    p, hi, lo = v32[y, x], max(nb), min(nb)
    spread = f32(hi - lo)
    hot, cold = f32(p - hi), f32(lo - p)
    bound = f32(k * spread)
    for excess, sign in ((hot, 1.0), (cold, -1.0)):
        if not (excess > thr and excess > bound):             # tests 1 and 2
            continue
        # test 3: no adjacent non-Z pixel q rises (falls) with p by a share of its excess
        H, W = channels.shape
        rises = []
        for qy in range(y - 1, y + 2):
            for qx in range(x - 1, x + 2):
                if (qy, qx) == (y, x) or not (0 <= qy < H and 0 <= qx < W):
                    continue
                if channels[qy, qx] == Z:
                    continue
                qnb = [float(v32[q]) for q in _same_colour_neighbours(channels, qy, qx)]
                if qnb:
                    rises.append(sign * (float(v32[qy, qx]) - _trimmed_mean(qnb)))
        if all(r < f * float(excess) for r in rises):
            return True
    return False


def reference_detect_defects(cfa, pattern, params=DefectCorrection(), *, white_level=2047):
    """``rgbz_fast.isp.detect_defects`` (same parameters and results), pixel by pixel."""
    data, pattern = np.asarray(cfa), get_pattern(pattern)
    found = np.zeros(data.shape, bool)
    if not params.enabled:
        return found
    channels = pattern.channel_map(data.shape)
    v32 = data.astype(np.float32)
    thr = f32(params.threshold * float(white_level))
    k = f32(params.spread_factor)
    for y in range(data.shape[0]):
        for x in range(data.shape[1]):
            if channels[y, x] != Z:
                found[y, x] = _is_defect(v32, channels, y, x, thr, k, params.cross_factor)
    return found


def reference_correct_defects(cfa, pattern, params=DefectCorrection(), *, white_level=2047,
                              known=None, return_mask=False):
    """``rgbz_fast.isp.correct_defects`` (same parameters and results), pixel by pixel.

    A flagged pixel (detected, or in ``known`` and not a Z site) takes the median of
    its same-colour neighbours that are not flagged themselves; one without such a
    neighbour keeps its value and is not reported as corrected.
    """
    data, pattern = np.asarray(cfa), get_pattern(pattern)
    channels = pattern.channel_map(data.shape)
    mask = reference_detect_defects(data, pattern, params, white_level=white_level)
    if known is not None:
        mask |= np.asarray(known, bool) & (channels != Z)
    out = data.copy()
    corrected = mask.copy()
    for y, x in zip(*np.nonzero(mask)):
        good = sorted(float(data[q]) for q in _same_colour_neighbours(channels, y, x)
                      if not mask[q])
        if not good:
            corrected[y, x] = False
            continue
        n = len(good)
        median = 0.5 * (good[(n - 1) // 2] + good[n // 2])
        if np.issubdtype(out.dtype, np.integer):
            median = math.floor(median + 0.5)
        out[y, x] = median
    return (out, corrected) if return_mask else out
