"""F1 of the 2026-11-27 probes: cpsnr_pooled of a pair whose squared differences underflow
(differences near 1e-160) beside an identical or an ordinary pair."""

from __future__ import annotations

import math

import numpy as np

from rgbz_fast import metrics


def test_cpsnr_pooled_keeps_the_scale_of_a_tiny_pair():
    a = np.zeros((8, 8, 3))
    b = a.copy()
    b[3, 4, 1] = 1e-160
    c = np.full((8, 8, 3), 0.1)
    single = metrics.cpsnr(a, b, data_range=1.0)
    # the pooled MSE of (b, a) is half b's: 10 log10(2) dB above it
    pooled = metrics.cpsnr_pooled([a, a], [b, a], data_range=1.0)
    assert math.isclose(pooled, single + 10 * math.log10(2), rel_tol=1e-9), (pooled, single)
    # beside an ordinary pair the tiny one adds nothing: half c's MSE
    want = 10 * math.log10(1.0 / (0.01 / 2))
    assert math.isclose(metrics.cpsnr_pooled([a, a], [b, c], data_range=1.0), want,
                        rel_tol=1e-9)
