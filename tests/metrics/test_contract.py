"""The bad-input contract of rgbz_fast.metrics.

Rows of docs/reports/robustness.md (``metrics.*``), run by the shared runner of
``tests/_contract.py``; then SSIM at the bounds of its data range.
"""

from __future__ import annotations

import numpy as np
import pytest

from _contract import Row, api_tests, f64, files, u16, u8img, with_value  # noqa: F401
from rgbz_fast import metrics

R = Row

ROWS = [
    # -- metrics ---------------------------------------------------------------------------
    R("metrics.cfa_psnr-range-neither", "cfa_psnr(ref, test) without data_range/bit_depth",
      lambda f: metrics.cfa_psnr(f64(), f64()), ValueError,
      "data_range: pass exactly one of data_range"),
    R("metrics.cfa_psnr-range-both", "cfa_psnr(data_range=1, bit_depth=1)",
      lambda f: metrics.cfa_psnr(f64(), f64(), data_range=1, bit_depth=1), ValueError,
      "data_range: pass exactly one of data_range"),
    R("metrics.cfa_psnr-shape", "cfa_psnr(8x8, 4x8)",
      lambda f: metrics.cfa_psnr(f64(), f64((4, 8)), bit_depth=8), ValueError,
      "test: shape (4, 8) differs from reference shape (8, 8)"),
    R("metrics.cfa_psnr-ndim", "cfa_psnr(1-D)",
      lambda f: metrics.cfa_psnr(np.zeros(4), np.zeros(4), bit_depth=8), ValueError,
      "reference: expected a 2-D or 3-D array"),
    R("metrics.cfa_psnr-nan", "cfa_psnr(NaN)",
      lambda f: metrics.cfa_psnr(with_value(np.nan), f64(), bit_depth=8), ValueError,
      "reference: holds 1 NaN or infinite value(s)"),
    R("metrics.cfa_psnr-mask-dtype", "cfa_psnr(mask of ints)",
      lambda f: metrics.cfa_psnr(f64(), f64(), np.ones((8, 8), int), bit_depth=8), TypeError,
      "mask: expected a boolean array"),
    R("metrics.cfa_psnr-mask-shape", "cfa_psnr(mask 4x8)",
      lambda f: metrics.cfa_psnr(f64(), f64(), np.ones((4, 8), bool), bit_depth=8),
      ValueError, "mask: shape (4, 8) matches neither"),
    R("metrics.cfa_psnr-mask-empty", "cfa_psnr(all-False mask)",
      lambda f: metrics.cfa_psnr(f64(), f64(), np.zeros((8, 8), bool), bit_depth=8),
      ValueError, "mask: selects no pixel"),
    R("metrics.cfa_psnr-bit_depth", "cfa_psnr(bit_depth=33)",
      lambda f: metrics.cfa_psnr(f64(), f64(), bit_depth=33), ValueError,
      "bit_depth: expected 1..32 bits"),
    R("metrics.cfa_psnr-data_range", "cfa_psnr(data_range=0)",
      lambda f: metrics.cfa_psnr(f64(), f64(), data_range=0), ValueError,
      "data_range: expected a finite number > 0"),
    R("metrics.cfa_psnr-data_range-type", "cfa_psnr(data_range='1')",
      lambda f: metrics.cfa_psnr(f64(), f64(), data_range="1"), TypeError,
      "data_range: expected a number"),
    R("metrics.cfa_psnr-int-range", "cfa_psnr(uint16 300, bit_depth=8)",
      lambda f: metrics.cfa_psnr(u16(value=300), u16(value=300), bit_depth=8), ValueError,
      "bit_depth: reference holds integer values in [300, 300], outside [0, 255]"),
    R("metrics.cpsnr-ndim", "cpsnr(2-D)", lambda f: metrics.cpsnr(f64(), f64()), ValueError,
      "reference: expected a 3-D array"),
    R("metrics.cpsnr-channels", "cpsnr(4 channels)",
      lambda f: metrics.cpsnr(np.zeros((4, 4, 4)), np.zeros((4, 4, 4))), ValueError,
      "reference: expected a colour image of shape (rows, cols, 3)"),
    R("metrics.cpsnr-crop-large", "cpsnr(16x16, crop=8)",
      lambda f: metrics.cpsnr(u8img(), u8img(), crop=8), ValueError,
      "crop: crop=8 leaves 0 x 0 pixels"),
    R("metrics.cpsnr-crop-negative", "cpsnr(crop=-1)",
      lambda f: metrics.cpsnr(u8img(), u8img(), crop=-1), ValueError,
      "crop: expected an integer >= 0"),
    R("metrics.cpsnr-crop-float", "cpsnr(crop=1.0)",
      lambda f: metrics.cpsnr(u8img(), u8img(), crop=1.0), TypeError,
      "crop: expected an integer"),
    R("metrics.cpsnr-int-range", "cpsnr(uint16 300, data_range=255)",
      lambda f: metrics.cpsnr(np.full((4, 4, 3), 300, np.uint16),
                              np.full((4, 4, 3), 300, np.uint16)), ValueError,
      "data_range: reference holds integer values"),
    R("metrics.cpsnr_pooled-empty", "cpsnr_pooled([], [])",
      lambda f: metrics.cpsnr_pooled([], []), ValueError, "references: the sequence is empty"),
    R("metrics.cpsnr_pooled-length", "cpsnr_pooled([a], [a, a])",
      lambda f: metrics.cpsnr_pooled([u8img()], [u8img()] * 2), ValueError,
      "tests: 2 images for 1 references"),
    R("metrics.cpsnr_pooled-array", "cpsnr_pooled(one 3-D array)",
      lambda f: metrics.cpsnr_pooled(u8img(), u8img()), TypeError,
      "references: expected a sequence of (rows, cols, 3) images"),
    R("metrics.cpsnr_pooled-generator", "cpsnr_pooled(generator)",
      lambda f: metrics.cpsnr_pooled((x for x in [u8img()]), [u8img()]), TypeError,
      "references: expected a sequence of images"),
    R("metrics.ssim-gaussian_weights-text", "ssim(gaussian_weights='no')",
      lambda f: metrics.ssim(f64((16, 16)), f64((16, 16)), gaussian_weights="no"), TypeError,
      "gaussian_weights: expected True or False, got 'no'"),
    R("metrics.ssim-small", "ssim(5x5)", lambda f: metrics.ssim(f64((5, 5)), f64((5, 5))),
      ValueError, "crop: crop=0 leaves 5 x 5 pixels"),
    R("metrics.ssim-win-even", "ssim(win_size=4)",
      lambda f: metrics.ssim(u8img(), u8img(), win_size=4), ValueError,
      "win_size: expected an odd window size"),
    R("metrics.ssim-sigma", "ssim(sigma=0)", lambda f: metrics.ssim(u8img(), u8img(), sigma=0),
      ValueError, "sigma: expected a finite number > 0"),
    R("metrics.ssim-channel_axis-none", "ssim(3-D, channel_axis=None)",
      lambda f: metrics.ssim(u8img(), u8img(), channel_axis=None), ValueError,
      "channel_axis: a 3-D image needs the axis of its channels"),
    R("metrics.ssim-channel_axis-range", "ssim(channel_axis=5)",
      lambda f: metrics.ssim(u8img(), u8img(), channel_axis=5), ValueError,
      "channel_axis: 5 is out of range"),
    R("metrics.ssim-channel_axis-type", "ssim(channel_axis='x')",
      lambda f: metrics.ssim(u8img(), u8img(), channel_axis="x"), TypeError,
      "channel_axis: expected an integer or None"),
    # SSIM's constants (0.01 L)**2 leave the doubles beyond these bounds
    R("metrics.ssim-data_range-huge", "ssim(data_range=1e300)",
      lambda f: metrics.ssim(f64((16, 16), 1.0), f64((16, 16)), data_range=1e300),
      ValueError, "data_range: expected a number in [1e-100, 1e+100] for SSIM"),
    R("metrics.ssim-data_range-tiny", "ssim(data_range=1e-300)",
      lambda f: metrics.ssim(f64((16, 16)), f64((16, 16)), data_range=1e-300),
      ValueError, "data_range: expected a number in [1e-100, 1e+100] for SSIM"),
    R("metrics.ms_ssim-small", "ms_ssim(16x16)",
      lambda f: metrics.ms_ssim(u8img(), u8img()), ValueError,
      "reference: MS-SSIM with 5 scales needs at least 161 x 161 pixels"),
    R("metrics.ms_ssim-data_range-huge", "ms_ssim(data_range=1e300)",
      lambda f: metrics.ms_ssim(f64((161, 161), 1.0), f64((161, 161)), data_range=1e300),
      ValueError, "data_range: expected a number in [1e-100, 1e+100] for SSIM"),
    R("metrics.ms_ssim-weights-empty", "ms_ssim(weights=[])",
      lambda f: metrics.ms_ssim(u8img(), u8img(), weights=[]), ValueError,
      "weights: expected a non-empty 1-D sequence"),
    R("metrics.ms_ssim-weights-text", "ms_ssim(weights='abc')",
      lambda f: metrics.ms_ssim(u8img(), u8img(), weights="abc"), TypeError,
      "weights: expected a sequence of numbers"),
    R("metrics.ms_ssim-weights-negative", "ms_ssim(weights=[-1])",
      lambda f: metrics.ms_ssim(u8img(), u8img(), weights=[-1]), ValueError,
      "weights: expected finite exponents >= 0"),
    # -- bool arrays are masks, not images: True is not the value 1 of a 0..255 image -------
    R("metrics.cpsnr-bool", "cpsnr(bool, bool)",
      lambda f: metrics.cpsnr(np.zeros((8, 8, 3), bool), np.ones((8, 8, 3), bool)), TypeError,
      "reference: dtype bool is not supported; expected image values (an integer or float "
      "array), not a mask"),
    R("metrics.cpsnr-bool-test", "cpsnr(uint8, bool)",
      lambda f: metrics.cpsnr(u8img(), np.ones((16, 16, 3), bool)), TypeError,
      "test: dtype bool is not supported"),
    R("metrics.cpsnr_pooled-bool", "cpsnr_pooled([bool], [bool])",
      lambda f: metrics.cpsnr_pooled([np.zeros((8, 8, 3), bool)], [np.ones((8, 8, 3), bool)]),
      TypeError, "references[0]: dtype bool is not supported"),
    R("metrics.cfa_psnr-bool", "cfa_psnr(bool, bool, bit_depth=1)",
      lambda f: metrics.cfa_psnr(np.zeros((8, 8), bool), np.ones((8, 8), bool), bit_depth=1),
      TypeError, "reference: dtype bool is not supported"),
    R("metrics.ssim-bool", "ssim(bool, bool)",
      lambda f: metrics.ssim(np.zeros((16, 16), bool), np.ones((16, 16), bool)), TypeError,
      "reference: dtype bool is not supported"),
    R("metrics.ms_ssim-bool", "ms_ssim(bool, bool)",
      lambda f: metrics.ms_ssim(np.zeros((161, 161), bool), np.ones((161, 161), bool)),
      TypeError, "reference: dtype bool is not supported"),
    R("metrics.zipper-bool", "zipper(bool, bool)",
      lambda f: metrics.zipper(np.zeros((8, 8, 3), bool), np.ones((8, 8, 3), bool)), TypeError,
      "reference: dtype bool is not supported"),
    R("metrics.delta_e_map-bool", "delta_e_map(bool, bool)",
      lambda f: metrics.delta_e_map(np.zeros((8, 8, 3), bool), np.ones((8, 8, 3), bool)),
      TypeError, "reference: dtype bool is not supported"),
    R("metrics.all_metrics-bool", "all_metrics(bool, bool)",
      lambda f: metrics.all_metrics(np.zeros((161, 161, 3), bool),
                                    np.ones((161, 161, 3), bool)), TypeError,
      "reference_rgb: dtype bool is not supported"),
    R("metrics.ms_ssim-weights-zero", "ms_ssim(weights=(0, 0, 0, 0, 0))",
      lambda f: metrics.ms_ssim(u8img(), u8img(), weights=(0, 0, 0, 0, 0)), ValueError,
      "weights: expected exponents with a sum > 0, got (0, 0, 0, 0, 0)"),
    R("metrics.ms_ssim-weights-bool", "ms_ssim(weights=(True,) * 5)",
      lambda f: metrics.ms_ssim(u8img(), u8img(), weights=(True,) * 5), TypeError,
      "weights: expected a sequence of real numbers (bool, complex and text are refused)"),
    R("metrics.ms_ssim-weights-complex", "ms_ssim(weights=array of complex)",
      lambda f: metrics.ms_ssim(u8img(), u8img(), weights=np.ones(5, complex)), TypeError,
      "weights: expected a sequence of real numbers"),
    R("metrics.ms_ssim-weights-strings", "ms_ssim(weights=('0.2',) * 5)",
      lambda f: metrics.ms_ssim(u8img(), u8img(), weights=("0.2",) * 5), TypeError,
      "weights: expected a sequence of real numbers"),
    R("metrics.zipper-huge", "zipper(1e300, input='srgb01')",
      lambda f: metrics.zipper(np.full((4, 4, 3), 1e300), np.zeros((4, 4, 3)), input="srgb01"),
      ValueError, "input: reference holds values up to 1e+300 in magnitude, beyond 1e+100"),
    R("metrics.delta_e_map-huge", "delta_e_map(lab 1e200)",
      lambda f: metrics.delta_e_map(np.zeros((4, 4, 3)), np.full((4, 4, 3), 1e200),
                                    input="lab"),
      ValueError, "input: test holds values up to 1e+200 in magnitude, beyond 1e+100"),
    R("metrics.ssim-huge-data", "ssim(data 1e200)",
      lambda f: metrics.ssim(f64((16, 16), 1e200), f64((16, 16)), data_range=1), ValueError,
      "reference: reference holds values up to 1e+200 in magnitude, beyond 1e+150: SSIM "
      "multiplies squares"),
    R("metrics.zipper-small", "zipper(2x2)",
      lambda f: metrics.zipper(np.zeros((2, 2, 3)), np.zeros((2, 2, 3))), ValueError,
      "crop: crop=0 leaves 2 x 2 pixels"),
    R("metrics.zipper-delta", "zipper(delta=-1)",
      lambda f: metrics.zipper(u8img(), u8img(), delta=-1), ValueError,
      "delta: expected a finite number >= 0"),
    R("metrics.zipper-input", "zipper(input='xyz')",
      lambda f: metrics.zipper(u8img(), u8img(), input="xyz"), ValueError,
      "input: expected one of 'srgb8', 'srgb16', 'srgb01', 'lab'"),
    R("metrics.zipper-int-range", "zipper(uint16 300, input='srgb8')",
      lambda f: metrics.zipper(np.full((4, 4, 3), 300, np.uint16),
                               np.full((4, 4, 3), 300, np.uint16)), ValueError,
      "input: reference holds integer values"),
    R("metrics.delta_e_map-ndim", "delta_e_map(2-D)",
      lambda f: metrics.delta_e_map(f64(), f64()), ValueError,
      "reference: expected a 3-D array"),
    R("metrics.all_metrics-small", "all_metrics(16x16)",
      lambda f: metrics.all_metrics(u8img(), u8img()), ValueError,
      "reference: MS-SSIM with 5 scales needs"),
]

test_api_contract = api_tests(ROWS)


def test_psnr_of_finite_images_is_finite_at_every_scale():
    """The PSNR of two different finite images is a finite number of dB, without a warning,
    whatever the scale: squared differences that overflow (1e300) or underflow (1e-200,
    subnormal differences down to the smallest double) and a data_range whose square overflows (1e200) or underflows (1e-200) used to give
    -inf, inf or NaN. Equal images give inf."""
    import warnings

    a = f64((8, 8, 3))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert metrics.cfa_psnr(f64(), f64(value=1e300), data_range=1.0) == \
            pytest.approx(-6000.0)
        one = with_value(1.0, shape=(8, 8, 3), at=(0, 0, 0))
        for scale in (5e-324, 1e-310, 1e-200, 1e-100, 1.0, 1e100, 1e200, 1e300):
            want = 10 * np.log10(192.0)                  # one pixel of 192 off by data_range
            for psnr in (metrics.cpsnr(a, one * scale, data_range=scale),
                         metrics.cfa_psnr(a, one * scale, data_range=scale),
                         metrics.cpsnr_pooled([a, a], [one * scale, one * scale],
                                              data_range=scale)):
                assert psnr == pytest.approx(want, rel=1e-12)
        big = np.finfo(np.float64).max
        assert metrics.cfa_psnr(f64(value=-big), f64(value=big), data_range=big) == \
            pytest.approx(-20 * np.log10(2.0))
        f32 = np.finfo(np.float32).max
        assert np.isfinite(metrics.cpsnr(np.full((4, 4, 3), f32, np.float32),
                                         np.full((4, 4, 3), -f32, np.float32), data_range=1))
        assert metrics.cpsnr(a, a, data_range=1e-300) == np.inf


def test_ssim_data_range_at_its_bounds_is_scale_invariant():
    """Within [1e-100, 1e100] SSIM and MS-SSIM are finite and do not depend on the scale
    of the data (the constants scale with data_range), without any warning."""
    rng = np.random.default_rng(0)
    a = rng.random((161, 161))
    b = np.clip(a + rng.normal(0, 0.05, a.shape), 0, 1)
    want_ssim = metrics.ssim(a, b, data_range=1.0)
    want_ms = metrics.ms_ssim(a, b, data_range=1.0)
    assert 0 < want_ms < 1 and 0 < want_ssim < 1
    for L in metrics.SSIM_DATA_RANGE:
        assert metrics.ssim(a * L, b * L, data_range=L) == pytest.approx(want_ssim, rel=1e-9)
        assert metrics.ms_ssim(a * L, b * L, data_range=L) == pytest.approx(want_ms, rel=1e-9)
    assert metrics.ssim(np.zeros((16, 16)), np.zeros((16, 16)), data_range=1e-100) == 1.0
