"""Tests of rgbz_fast.metrics: known answers, skimage agreement, input checks."""

from __future__ import annotations

import math


import numpy as np  # noqa: E402
import pytest  # noqa: E402
from _support import load_kodak  # noqa: E402
from numpy.testing import assert_allclose  # noqa: E402
from scipy import ndimage as ndi  # noqa: E402
from skimage.metrics import structural_similarity as sk_ssim  # noqa: E402
from skimage.transform import downscale_local_mean  # noqa: E402

from rgbz_fast import mask1, metrics  # noqa: E402
from rgbz_fast.metrics import (all_metrics, cfa_psnr, cpsnr, cpsnr_pooled,  # noqa: E402
                               delta_e_map, ms_ssim, ssim, zipper)

SK_WANG = dict(gaussian_weights=True, sigma=1.5, use_sample_covariance=False)


def _textured(rng, shape, smooth=1.0):
    """uint8 image with structure at several scales (smoothed noise plus a ramp)."""
    noise = ndi.gaussian_filter(rng.normal(0, 1, shape), sigma=(smooth, smooth) + (0,) *
                                (len(shape) - 2))
    noise = (noise - noise.min()) / np.ptp(noise)
    ramp = np.linspace(0, 1, shape[1])[np.newaxis, :]
    if len(shape) == 3:
        ramp = ramp[..., np.newaxis]
    return np.clip(np.rint(255 * (0.7 * noise + 0.3 * ramp)), 0, 255).astype(np.uint8)


def _degrade(rng, img, noise=8.0):
    out = img.astype(np.float64) + rng.normal(0, noise, img.shape)
    return np.clip(np.rint(out), 0, 255).astype(np.uint8)


@pytest.fixture
def pair(rng):
    ref = _textured(rng, (48, 64, 3))
    return ref, _degrade(rng, ref)


def test_public_names():
    assert set(metrics.__all__) <= set(dir(metrics))
    for name in ("cfa_psnr", "cpsnr", "cpsnr_pooled", "ssim", "ms_ssim", "zipper",
                 "all_metrics"):
        assert name in metrics.__all__


# ---------------------------------------------------------------- identical images

def test_identical_images(rng):
    ref = _textured(rng, (161, 170, 3))
    assert cfa_psnr(ref[..., 1], ref[..., 1], data_range=255) == math.inf
    assert cpsnr(ref, ref) == math.inf
    assert cpsnr_pooled([ref, ref[:50]], [ref, ref[:50]]) == math.inf
    assert ssim(ref, ref) == 1.0
    assert ms_ssim(ref, ref) == 1.0
    assert zipper(ref, ref) == 0.0
    assert all_metrics(ref, ref) == {"cpsnr": math.inf, "ssim": 1.0, "ms_ssim": 1.0,
                                     "zipper": 0.0}
    for value in all_metrics(ref, ref).values():
        assert type(value) is float


# ---------------------------------------------------------------- PSNR family

def test_cpsnr_known_mse():
    ref = np.full((16, 16, 3), 100, dtype=np.uint8)
    expected = 10 * math.log10(255 ** 2 / 25)
    assert cpsnr(ref, ref + 5) == pytest.approx(expected, rel=1e-12)
    assert cpsnr(ref + 5, ref) == pytest.approx(expected, rel=1e-12)
    # uint8 subtraction must not wrap around
    assert cpsnr(ref, ref - 5) == pytest.approx(expected, rel=1e-12)
    # the error on one channel only: MSE_C = 25 / 3
    test = ref.copy()
    test[..., 2] += 5
    assert cpsnr(ref, test) == pytest.approx(10 * math.log10(255 ** 2 * 3 / 25), rel=1e-12)


def test_cpsnr_pooled_known_mse():
    ref = np.full((8, 8, 3), 100, dtype=np.uint8)
    big = np.full((20, 10, 3), 50, dtype=np.uint8)
    # per-image MSE 1 and 49: pooled over images -> 25
    got = cpsnr_pooled([ref, big], [ref + 1, big + 7])
    assert got == pytest.approx(10 * math.log10(255 ** 2 / 25), rel=1e-12)
    mean_of_values = np.mean([cpsnr(ref, ref + 1), cpsnr(big, big + 7)])
    assert got < mean_of_values
    assert cpsnr_pooled([ref], [ref + 3]) == pytest.approx(cpsnr(ref, ref + 3), rel=1e-12)
    assert cpsnr_pooled((ref,), (ref + 3,), data_range=1000) == pytest.approx(
        cpsnr(ref, ref + 3, data_range=1000), rel=1e-12)


def test_cfa_psnr_counts_masked_pixels_only(rng):
    pattern = mask1()
    shape = (16, 24)
    zmask = pattern.z_mask(shape)
    ref = rng.integers(0, 2048, shape).astype(np.uint16)
    test = ref.copy()
    # errors of known size at the Z sites ...
    err = rng.choice([-7, -3, 4, 9], size=int(zmask.sum()))
    test[zmask] = ref[zmask] + err
    # ... and wild errors everywhere else, which must not count
    test[~zmask] = rng.integers(0, 2048, int((~zmask).sum()))
    expected = 10 * math.log10(2047 ** 2 / np.mean(err.astype(float) ** 2))
    assert cfa_psnr(ref, test, zmask, bit_depth=11) == pytest.approx(expected, rel=1e-12)
    assert cfa_psnr(ref, test, zmask, data_range=2047) == pytest.approx(expected, rel=1e-12)
    # without a mask every pixel counts
    full = 10 * math.log10(2047 ** 2 / np.mean((ref.astype(float) - test) ** 2))
    assert cfa_psnr(ref, test, bit_depth=11) == pytest.approx(full, rel=1e-12)
    # only the masked sites identical -> inf
    test[zmask] = ref[zmask]
    assert cfa_psnr(ref, test, zmask, bit_depth=11) == math.inf


def test_cfa_psnr_colour_with_2d_mask():
    ref = np.full((6, 6, 3), 10.0)
    test = ref.copy()
    mask = np.zeros((6, 6), dtype=bool)
    mask[2, 3] = True
    test[2, 3] = [12.0, 10.0, 7.0]           # squared errors 4, 0, 9 over 3 values
    test[0, 0] = 200.0                       # outside the mask
    expected = 10 * math.log10(1.0 / (13 / 3))
    assert cfa_psnr(ref, test, mask, data_range=1.0) == pytest.approx(expected, rel=1e-12)
    full_mask = np.broadcast_to(mask[..., None], ref.shape)
    assert cfa_psnr(ref, test, full_mask, data_range=1.0) == pytest.approx(expected)


def test_cfa_psnr_needs_peak():
    a = np.zeros((4, 4), dtype=np.uint16)
    with pytest.raises(ValueError, match="data_range.*neither"):
        cfa_psnr(a, a)
    with pytest.raises(ValueError, match="data_range.*both"):
        cfa_psnr(a, a, data_range=255, bit_depth=8)
    with pytest.raises(ValueError, match="data_range.*neither"):
        cfa_psnr(a.astype(float), a.astype(float))
    with pytest.raises(TypeError, match="bit_depth"):
        cfa_psnr(a, a, bit_depth=8.0)
    with pytest.raises(ValueError, match="bit_depth"):
        cfa_psnr(a, a, bit_depth=0)
    # 11-bit values declared as 8-bit
    b = a.copy()
    b[0, 0] = 2000
    with pytest.raises(ValueError, match="bit_depth"):
        cfa_psnr(b, a, bit_depth=8)


def test_cfa_psnr_bad_mask():
    a = np.zeros((4, 4))
    with pytest.raises(TypeError, match="mask"):
        cfa_psnr(a, a, np.ones((4, 4), dtype=np.uint8), data_range=1.0)
    with pytest.raises(ValueError, match="mask"):
        cfa_psnr(a, a, np.ones((4, 5), dtype=bool), data_range=1.0)
    with pytest.raises(ValueError, match="mask: selects no pixel"):
        cfa_psnr(a, a, np.zeros((4, 4), dtype=bool), data_range=1.0)


# ---------------------------------------------------------------- SSIM

@pytest.mark.parametrize("shape", [(48, 64, 3), (37, 41, 3), (33, 50)])
@pytest.mark.parametrize("dtype", [np.uint8, np.float64])
def test_ssim_matches_skimage(rng, shape, dtype):
    ref = _textured(rng, shape)
    test = _degrade(rng, ref, noise=12)
    ref, test = ref.astype(dtype), test.astype(dtype)
    channel_axis = -1 if len(shape) == 3 else None
    expected = sk_ssim(ref, test, data_range=255, channel_axis=channel_axis, **SK_WANG)
    assert ssim(ref, test) == pytest.approx(expected, abs=1e-9)


def test_ssim_uniform_window_matches_skimage(pair):
    ref, test = pair
    expected = sk_ssim(ref, test, data_range=255, channel_axis=-1, gaussian_weights=False,
                       win_size=7, use_sample_covariance=False)
    got = ssim(ref, test, gaussian_weights=False, win_size=7)
    assert got == pytest.approx(expected, abs=1e-9)


def test_ssim_single_window_is_eqs_25_to_27(rng):
    """An image the size of one uniform window: eqs. 25-27 on global moments."""
    d = rng.uniform(0, 255, (7, 7))
    r = np.clip(d + rng.normal(0, 30, d.shape), 0, 255)
    L = 255.0
    c1, c2 = (0.01 * L) ** 2, (0.03 * L) ** 2
    c3 = c2 / 2
    mu_d, mu_r = d.mean(), r.mean()
    s_d, s_r = d.std(), r.std()
    s_dr = np.mean((d - mu_d) * (r - mu_r))
    lum = (2 * mu_d * mu_r + c1) / (mu_d ** 2 + mu_r ** 2 + c1)
    con = (2 * s_d * s_r + c2) / (s_d ** 2 + s_r ** 2 + c2)
    struct = (s_dr + c3) / (s_d * s_r + c3)
    got = ssim(d, r, data_range=L, gaussian_weights=False, win_size=7)
    assert got == pytest.approx(lum * con * struct, rel=1e-12)


@pytest.mark.parametrize("channel_axis", [0, 1, 2, -1, -3])
def test_ssim_channel_axis(rng, channel_axis):
    grey = _textured(rng, (44, 46))
    grey_test = _degrade(rng, grey)
    expected = ssim(grey, grey_test)
    axis = channel_axis % 3
    ref = np.stack([grey] * 3, axis=axis)
    test = np.stack([grey_test] * 3, axis=axis)
    assert ssim(ref, test, channel_axis=channel_axis) == pytest.approx(expected, rel=1e-12)
    three_scales = (0.2, 0.3, 0.5)
    assert ms_ssim(ref, test, channel_axis=channel_axis, weights=three_scales) == \
        pytest.approx(ms_ssim(grey, grey_test, weights=three_scales), rel=1e-12)


def test_ssim_colour_is_mean_over_channels(pair):
    ref, test = pair
    per_channel = [ssim(ref[..., k], test[..., k]) for k in range(3)]
    assert ssim(ref, test) == pytest.approx(np.mean(per_channel), rel=1e-12)


def test_ssim_real_image_matches_skimage(rng):
    ref = load_kodak(1, crop=(128, 192))
    test = _degrade(rng, ndi.gaussian_filter(ref, sigma=(1.0, 1.0, 0)), noise=3)
    expected = sk_ssim(ref, test, data_range=255, channel_axis=-1, **SK_WANG)
    assert ssim(ref, test) == pytest.approx(expected, abs=1e-9)
    assert 0.3 < expected < 0.99


# ---------------------------------------------------------------- MS-SSIM

def _ms_ssim_reference(ref, test, weights=metrics.MS_SSIM_WEIGHTS):
    """MS-SSIM from skimage SSIMs, for grey images whose sides divide by 2**(M-1).

    c*s is skimage's SSIM with a huge K1 (which makes the luminance term 1);
    the 2x2 mean decimation is skimage's downscale_local_mean.
    """
    x, y = ref.astype(np.float64), test.astype(np.float64)
    value = 1.0
    for j, w in enumerate(weights):
        if j == len(weights) - 1:
            factor = sk_ssim(x, y, data_range=255, **SK_WANG)
        else:
            factor = sk_ssim(x, y, data_range=255, K1=1e4, **SK_WANG)
            x, y = downscale_local_mean(x, (2, 2)), downscale_local_mean(y, (2, 2))
        value *= max(factor, 0.0) ** w
    return value


def test_ms_ssim_matches_reference_construction(rng):
    ref = _textured(rng, (176, 192), smooth=2.0)
    test = _degrade(rng, ref, noise=20)
    assert ms_ssim(ref, test) == pytest.approx(_ms_ssim_reference(ref, test), abs=1e-7)


def test_ms_ssim_single_scale_is_ssim(pair):
    ref, test = pair
    assert ms_ssim(ref, test, weights=(1.0,)) == pytest.approx(ssim(ref, test), rel=1e-12)
    # colour: the mean over channels of the per-channel MS-SSIM
    per_channel = [ssim(ref[..., k], test[..., k]) ** 0.5 for k in range(3)]
    assert ms_ssim(ref, test, weights=(0.5,)) == pytest.approx(np.mean(per_channel),
                                                               rel=1e-12)


def test_ms_ssim_decreases_with_blur(rng):
    ref = _textured(rng, (192, 192, 3), smooth=1.0)
    values = [ms_ssim(ref, ndi.gaussian_filter(ref.astype(float), sigma=(s, s, 0)))
              for s in (0.5, 1.0, 2.0, 4.0)]
    assert values[0] < 1.0
    assert all(a > b for a, b in zip(values, values[1:])), values
    assert values[-1] > 0.0


def test_ms_ssim_negative_structure_is_clipped(rng):
    ref = _textured(rng, (161, 161), smooth=1.0)
    value = ms_ssim(ref, 255 - ref)          # anti-correlated: mean c*s < 0 at scale 1
    assert value == 0.0
    assert not math.isnan(value)


def test_ms_ssim_minimum_size(rng):
    ref = _textured(rng, (161, 200, 3))
    assert 0.0 < ms_ssim(ref, _degrade(rng, ref)) < 1.0
    with pytest.raises(ValueError, match=r"reference: .*5 scales.*161 x 161.*crop=1"):
        ms_ssim(ref, ref, crop=1)
    with pytest.raises(ValueError, match=r"reference: .*5 scales.*161 x 161"):
        ms_ssim(ref[:160], ref[:160])
    # fewer scales need less: 3 scales -> 41 pixels
    small = ref[:41, :41]
    assert ms_ssim(small, small, weights=(0.2, 0.3, 0.5)) == 1.0
    with pytest.raises(ValueError, match="41 x 41"):
        ms_ssim(small[:40], small[:40], weights=(0.2, 0.3, 0.5))


@pytest.mark.parametrize("weights, exc", [((), ValueError), ((0.5, -0.1), ValueError),
                                          ((0.5, np.nan), ValueError), ("abc", TypeError),
                                          (0.5, TypeError), ((("a",),), TypeError),
                                          (((0.1, 0.2),), ValueError)])
def test_ms_ssim_bad_weights(weights, exc):
    a = np.zeros((200, 200))
    with pytest.raises(exc, match="weights"):
        ms_ssim(a, a, weights=weights)


# ---------------------------------------------------------------- zipper

def _domino_lab(rows, cols):
    """CIELAB image of 1x2 'dominoes': each pixel's closest neighbour is its partner.

    Pixel (r, c) pairs with (r, c ^ 1). The two halves of a domino differ by
    0.5 in L*; neighbouring dominoes differ by at least 15 in L*, so the argmin
    of eq. 30 is unique everywhere.
    """
    r, c = np.mgrid[0:rows, 0:cols]
    lab = np.zeros((rows, cols, 3))
    lab[..., 0] = 20.0 + 15.0 * ((r + 2 * (c // 2)) % 4) + 0.5 * (c % 2)
    lab[..., 1] = 3.0
    lab[..., 2] = -4.0
    return lab


def test_zipper_counts_known_pixels():
    ref = _domino_lab(10, 12)
    test = ref.copy()
    test[..., 0] += 3.0                       # a uniform shift changes no difference
    # break four dominoes: the right half moves by 5 in a* -> |psi| = 5.025 - 0.5
    for r, c in [(3, 3), (5, 7), (0, 5), (4, 11)]:
        test[r, c, 1] += 5.0
    # a sub-threshold change: |psi| = sqrt(0.25 + 4) - 0.5 = 1.56 < 2.3
    test[7, 5, 1] += 2.0
    # evaluated: rows 1..8, cols 1..10 (80 pixels). (3, 2-3) and (5, 6-7) count
    # twice, (4, 10) once (its partner (4, 11) is on the border ring), row 0 never.
    assert zipper(ref, test, input="lab") == pytest.approx(100 * 5 / 80, abs=1e-12)
    # crop=1: rows 2..7, cols 2..9 of the original (48 pixels); (4, 10) is now ring
    assert zipper(ref, test, input="lab", crop=1) == pytest.approx(100 * 4 / 48, abs=1e-12)
    # the threshold: delta above |psi| = 4.525 of the broken dominoes -> 0
    assert zipper(ref, test, input="lab", delta=4.6) == 0.0
    # delta below the sub-threshold change: (7, 4-5) count too
    assert zipper(ref, test, input="lab", delta=1.5) == pytest.approx(100 * 7 / 80)
    # psi is symmetric in sign: swapping the images gives the same count here
    assert zipper(test, ref, input="lab") == pytest.approx(100 * 5 / 80, abs=1e-12)


def test_zipper_tie_break_is_raster_order():
    """Flat reference: every neighbour ties and the top-left one is used."""
    ref = np.full((5, 5, 3), 128, dtype=np.uint8)
    test = ref.copy()
    test[2, 2] = 0
    # (2, 2) itself and (3, 3), whose top-left neighbour is (2, 2): 2 of 9
    assert zipper(ref, test) == pytest.approx(100 * 2 / 9, abs=1e-12)


def test_zipper_srgb_matches_lab_input(pair):
    import colour

    ref, test = pair
    lab_ref = colour.XYZ_to_Lab(colour.sRGB_to_XYZ(ref / 255.0))
    lab_test = colour.XYZ_to_Lab(colour.sRGB_to_XYZ(test / 255.0))
    expected = zipper(lab_ref, lab_test, input="lab")
    assert 0.0 < expected < 100.0
    assert zipper(ref, test) == expected
    assert zipper(ref.astype(np.uint16) * 257, test.astype(np.uint16) * 257,
                  input="srgb16") == pytest.approx(expected, abs=1e-9)
    assert_allclose(delta_e_map(ref, test), np.linalg.norm(lab_ref - lab_test, axis=-1),
                    rtol=1e-12, atol=1e-12)


def test_zipper_real_image(rng):
    ref = load_kodak(9, crop=(96, 128))
    blurred = ndi.gaussian_filter(ref.astype(float), sigma=(1.5, 1.5, 0))
    value = zipper(ref, blurred)
    assert 0.0 < value < 100.0
    assert zipper(ref, ref) == 0.0


def test_delta_e_map_black_white():
    black = np.zeros((2, 3, 3), dtype=np.uint8)
    white = np.full((2, 3, 3), 255, dtype=np.uint8)
    assert_allclose(delta_e_map(black, white), 100.0, atol=1e-6)
    assert delta_e_map(black, white).shape == (2, 3)
    assert_allclose(delta_e_map(black / 255, white / 255, input="srgb01"), 100.0, atol=1e-6)


def test_zipper_respects_colour_domain_range_scale(pair):
    import colour

    ref, test = pair
    expected = zipper(ref, test)
    with colour.utilities.domain_range_scale("1"):
        assert zipper(ref, test) == expected
    assert colour.utilities.get_domain_range_scale() == "reference"


# ---------------------------------------------------------------- dtypes and crop

def test_float_and_uint_inputs_agree(rng):
    ref = _textured(rng, (170, 176, 3))
    test = _degrade(rng, ref)
    ref_f, test_f = ref.astype(np.float64), test.astype(np.float64)
    ref_01, test_01 = ref / 255.0, test / 255.0
    ref_16, test_16 = ref.astype(np.uint16), test.astype(np.uint16)
    ref_32, test_32 = ref.astype(np.float32), test.astype(np.float32)
    for f in (cpsnr, ssim, ms_ssim):
        expected = f(ref, test)
        assert f(ref_f, test_f) == pytest.approx(expected, rel=1e-12)
        assert f(ref_16, test_16) == pytest.approx(expected, rel=1e-12)
        assert f(ref_32, test_32) == pytest.approx(expected, rel=1e-12)
        assert f(ref_01, test_01, data_range=1.0) == pytest.approx(expected, rel=1e-9)
    expected = zipper(ref, test)
    assert zipper(ref_f, test_f) == expected
    assert zipper(ref_01, test_01, input="srgb01") == pytest.approx(expected)
    got = all_metrics(ref_01, test_01, data_range=1.0)
    want = all_metrics(ref, test)
    assert got.keys() == want.keys() == {"cpsnr", "ssim", "ms_ssim", "zipper"}
    for key in want:
        assert got[key] == pytest.approx(want[key], rel=1e-9)
    assert cfa_psnr(ref[..., 1], test[..., 1], bit_depth=8) == pytest.approx(
        cfa_psnr(ref_01[..., 1], test_01[..., 1], data_range=1.0), rel=1e-9)


def test_all_metrics_matches_individual_functions(rng):
    ref = _textured(rng, (165, 171, 3))
    test = _degrade(rng, ref)
    got = all_metrics(ref, test, crop=2)
    assert got["cpsnr"] == cpsnr(ref, test, crop=2)
    assert got["ssim"] == ssim(ref, test, crop=2)
    assert got["ms_ssim"] == ms_ssim(ref, test, crop=2)
    assert got["zipper"] == pytest.approx(zipper(ref, test, crop=2), abs=1e-12)


def test_crop(pair):
    ref, test = pair
    inner = (slice(4, -4), slice(4, -4))
    assert cpsnr(ref, test, crop=4) == cpsnr(ref[inner], test[inner])
    assert ssim(ref, test, crop=4) == ssim(ref[inner], test[inner])
    assert zipper(ref, test, crop=4) == zipper(ref[inner], test[inner])
    # differences confined to the border disappear once cropped
    edged = ref.copy()
    edged[:2] = 0
    edged[:, -2:] = 255
    assert cpsnr(ref, edged, crop=2) == math.inf
    assert ssim(ref, edged, crop=2) == 1.0
    assert zipper(ref, edged, crop=2) == 0.0
    assert cpsnr(ref, edged) < 30


# ---------------------------------------------------------------- bad input

@pytest.mark.parametrize("func", [cpsnr, ssim, ms_ssim, zipper, all_metrics])
def test_shape_mismatch(func):
    a = np.zeros((200, 200, 3))
    with pytest.raises(ValueError, match=r"test.*shape|test_rgb.*shape"):
        func(a, a[:, :199])


@pytest.mark.parametrize("func", [cpsnr, ssim, ms_ssim, zipper])
def test_non_finite_and_non_real(func):
    a = np.zeros((200, 200, 3))
    b = a.copy()
    b[5, 5, 1] = np.nan
    with pytest.raises(ValueError, match="reference"):
        func(b, a)
    with pytest.raises(ValueError, match="test"):
        func(a, b)
    with pytest.raises(TypeError, match="reference"):
        func(a.astype(complex), a.astype(complex))
    with pytest.raises(TypeError, match="reference"):
        func(None, a)
    with pytest.raises(ValueError, match="reference"):
        func(a[None], a[None])


@pytest.mark.parametrize("func", [cpsnr, zipper, all_metrics])
def test_colour_functions_need_three_channels(func):
    a = np.zeros((200, 200))
    with pytest.raises(ValueError, match="reference"):
        func(a, a)
    with pytest.raises(ValueError, match=r"reference.*\(rows, cols, 3\)"):
        func(np.zeros((200, 200, 4)), np.zeros((200, 200, 4)))


@pytest.mark.parametrize("func", [cpsnr, ssim, ms_ssim, zipper, all_metrics])
@pytest.mark.parametrize("crop, exc", [(-1, ValueError), (1.5, TypeError), (True, TypeError),
                                       (100, ValueError), (np.int64(100), ValueError)])
def test_bad_crop(func, crop, exc):
    a = np.zeros((200, 200, 3), dtype=np.uint8)
    with pytest.raises(exc, match="crop"):
        func(a, a, crop=crop)


@pytest.mark.parametrize("func", [cpsnr, ssim, ms_ssim, all_metrics])
@pytest.mark.parametrize("data_range, exc", [(0, ValueError), (-1.0, ValueError),
                                             (np.inf, ValueError), (True, TypeError),
                                             ("255", TypeError), (None, TypeError)])
def test_bad_data_range(func, data_range, exc):
    a = np.zeros((200, 200, 3))
    with pytest.raises(exc, match="data_range"):
        func(a, a, data_range=data_range)


@pytest.mark.parametrize("func", [cpsnr, ssim, ms_ssim, all_metrics])
def test_integer_values_beyond_data_range(func):
    """11-bit data in uint16 scored with the 8-bit default is caught."""
    a = np.zeros((200, 200, 3), dtype=np.uint16)
    b = a.copy()
    b[3, 4, 0] = 2047
    with pytest.raises(ValueError, match=r"data_range: .*\[0, 2047\]"):
        func(a, b)
    func(b, b, data_range=2047)              # the right range is accepted


def test_zipper_bad_arguments():
    a = np.zeros((8, 8, 3), dtype=np.uint8)
    with pytest.raises(ValueError, match="input"):
        zipper(a, a, input="rgb")
    with pytest.raises(ValueError, match="input"):
        zipper(a.astype(np.uint16) + 300, a.astype(np.uint16))
    with pytest.raises(ValueError, match="delta"):
        zipper(a, a, delta=-1)
    with pytest.raises(TypeError, match="delta"):
        zipper(a, a, delta="2.3")
    with pytest.raises(ValueError, match="crop"):
        zipper(a, a, crop=3)                 # 2 x 2 left: no pixel has 8 neighbours
    assert zipper(a, a, crop=2) == 0.0


def test_ssim_bad_arguments(pair):
    ref, test = pair
    with pytest.raises(ValueError, match="win_size"):
        ssim(ref, test, win_size=8)
    with pytest.raises(TypeError, match="win_size"):
        ssim(ref, test, win_size=7.0)
    with pytest.raises(ValueError, match="sigma"):
        ssim(ref, test, sigma=0)
    with pytest.raises(ValueError, match="channel_axis"):
        ssim(ref, test, channel_axis=None)
    with pytest.raises(ValueError, match="channel_axis"):
        ssim(ref, test, channel_axis=3)
    with pytest.raises(TypeError, match="channel_axis"):
        ssim(ref, test, channel_axis=1.0)
    with pytest.raises(ValueError, match="crop.*win_size=11"):
        ssim(ref, test, crop=19)             # 10 rows left, window of 11
    assert ssim(ref[:11, :11], test[:11, :11]) <= 1.0


def test_cpsnr_pooled_bad_arguments():
    a = np.zeros((8, 8, 3))
    with pytest.raises(ValueError, match="tests"):
        cpsnr_pooled([a, a], [a])
    with pytest.raises(ValueError, match="references"):
        cpsnr_pooled([], [])
    with pytest.raises(TypeError, match="references"):
        cpsnr_pooled(a, a)
    with pytest.raises(TypeError, match="references"):
        cpsnr_pooled(iter([a]), [a])
    with pytest.raises(ValueError, match=r"tests\[1\]"):
        cpsnr_pooled([a, a], [a, a[:4]])


# ---------------------------------------------------------------- robustness

def test_random_shapes_do_not_crash():
    pytest.importorskip("hypothesis")
    from hypothesis import given, settings
    from hypothesis import strategies as st

    @settings(max_examples=25, deadline=None)
    @given(rows=st.integers(11, 40), cols=st.integers(11, 40), seed=st.integers(0, 2 ** 16))
    def check(rows, cols, seed):
        r = np.random.default_rng(seed)
        ref = r.integers(0, 256, (rows, cols, 3), dtype=np.uint8)
        test = r.integers(0, 256, (rows, cols, 3), dtype=np.uint8)
        assert -1.0 <= ssim(ref, test) <= 1.0
        assert 0.0 <= zipper(ref, test) <= 100.0
        assert cpsnr(ref, test) > 0
        assert 0.0 <= ms_ssim(ref, test, weights=(1.0,)) <= 1.0

    check()


def test_floats_within_unit_range_scored_as_8_bit_codes_are_warned_about(rng):
    """sRGB floats in [0, 1] with the 8-bit default inflate every score (70.4 dB CPSNR for
    22.3, SSIM 0.9999 for 0.964): said, as scikit-image refuses them; with data_range=1 (or
    8-bit codes) nothing is said."""
    import warnings

    from rgbz_fast.metrics import all_metrics, cpsnr, delta_e_map, ms_ssim, ssim, zipper

    ref = rng.random((170, 170, 3))
    test = np.clip(ref + rng.normal(0, 0.05, ref.shape), 0, 1)
    for f in (cpsnr, ssim, ms_ssim, all_metrics):
        with pytest.warns(UserWarning, match=r"images are floats within \[0, 1\], scored "
                                             r"as data_range=255; pass the data's range"):
            f(ref, test)
    # zipper takes an encoding, not a range: its warning names the encoding to pass
    with pytest.warns(UserWarning, match=r'images are floats within \[0, 1\], scored as '
                                         r'input="srgb8"; pass input="srgb01" for \[0, 1\] '
                                         r'floats'):
        zipper(ref, test)
    big = (ref * 65535).astype(np.uint16)
    for f in (zipper, delta_e_map):
        with pytest.raises(ValueError, match=r'^input: reference holds integer values in .*, '
                                             r'outside \[0, 255\]; pass the encoding of the '
                                             r'data: input="srgb16" for 16-bit sRGB codes'):
            f(big, big)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cpsnr(ref, test, data_range=1.0)
        ssim(ref, test, data_range=1.0)
        zipper(ref, test, input="srgb01")
        cpsnr((ref * 255).astype(np.uint8), (test * 255).astype(np.uint8))
        cpsnr(np.zeros((8, 8, 3)), np.zeros((8, 8, 3)))          # black: no range to guess
