"""F2, F3 of the 2026-11-27 probes: grey-world estimates beyond GAIN_RANGE (a frame with
almost no red) were refused when run_pair handed them back as gains=, and overflowed the
fused chain's float32 scale. Estimates are clamped to GAIN_RANGE."""

from __future__ import annotations

import warnings

import numpy as np

import rgbz_fast as rz
from rgbz_fast.isp import ColourISP
from rgbz_fast.isp._stages import GAIN_RANGE


def test_an_estimate_beyond_the_gain_range_is_clamped_and_taken_back():
    img = np.zeros((400, 400, 3))
    img[..., 1], img[..., 2] = 0.5, 0.4                  # a green-blue scene
    m1 = rz.mosaic(img, "mask1")
    ref = rz.mosaic(img, "bayer").data.copy()
    ref[0, 1] = 1                                       # one red pixel at 1 DN
    isp = ColourISP()
    g = isp.white_balance_gains(ref, "GRBG")
    assert g[0] == GAIN_RANGE[1] and g[1] == 1.0
    isp.render(ref, "GRBG", gains=g)                    # the estimate is one it takes back
    isp.run_pair(rz.RawFrame(m1.data, m1.pattern, 11, reference=ref))


def test_the_fused_chain_and_the_stages_agree_on_a_huge_estimate():
    cfa = np.full((16, 16), 1000.0)
    cfa[0::2, 0::2] = 1e-40                              # red (RGGB) essentially black
    isp = ColourISP()
    with warnings.catch_warnings():
        warnings.simplefilter("error")                  # no overflow in the cast
        fused = isp.render(cfa, "RGGB")
    staged, st = isp.render(cfa, "RGGB", return_stages=True)
    assert st["gains"][0] == GAIN_RANGE[1]
    np.testing.assert_array_equal(fused, staged)
