"""The metric kernels (csrc/metrics.c) against their NumPy references and outside libraries.

References: tests/_reference/metrics.py (the former NumPy/SciPy/colour-science
implementations of rgbz_fast.metrics), scikit-image's structural_similarity and
colour-science's XYZ_to_Lab(sRGB_to_XYZ(...)) and delta_E.

Tolerances, and why:

* SSIM and MS-SSIM: rtol 1e-12. The kernel filters the moments in scipy's order
  (the same values bit for bit); only the final mean is summed in another order,
  which moves the score by ~1e-16 relative (measured below 2e-15).
* the 2 x 2 decimation: equal bit for bit (the same four additions, same order).
* the MSE of the PSNRs: integer images are summed exactly (equal to the exact
  sum); float images to rtol 1e-13 (a fixed order instead of NumPy's pairwise).
* CIELAB: 1e-12 absolute in L*, a*, b* (0..100 scale). colour's pow is NumPy's
  (SIMD on some CPUs), ours a cube root within 1 ulp, and colour's matrix product
  goes through BLAS (fused multiply-adds): the two differ by a few ulp (measured
  max 1.2e-13 on Kodak images).
* the zipper percentage: equal. Its decisions (the closest neighbour, |psi| >
  delta) only change when two values tie within a few ulp. Ties of identical
  colours are computed identically; over the 240 pairs of the Kodak evaluation
  one pixel differs, an exact tie of two different colours that colour-science's
  rounding breaks against the raster-order rule (see
  test_zipper_exact_tie_takes_the_first_neighbour_in_raster_order).
* one reference compared with many images (the dataset evaluation): the reference's
  SSIM moments and zipper neighbours are computed once and reused; every value equals
  the one of the pair alone bit for bit.
"""

from __future__ import annotations

import numpy as np
import pytest
from _reference import metrics as ref_metrics
from _support import load_kodak
from numpy.testing import assert_allclose
from scipy import ndimage as ndi
from skimage.metrics import structural_similarity as sk_ssim

import rgbz_fast as rz
from rgbz_fast import _kernels
from rgbz_fast.metrics import (all_metrics, cfa_psnr, cpsnr, cpsnr_pooled, delta_e_map,
                               ms_ssim, ssim, zipper)
from rgbz_fast.metrics._combined import COLOUR_METRICS, _colour_metrics
from rgbz_fast.metrics._ssim import _downsample2, _window

SSIM_TOL = dict(rtol=1e-12, atol=0)
LAB_ATOL = 1e-12
SK_WANG = dict(gaussian_weights=True, sigma=1.5, use_sample_covariance=False)


def _pair(rng, shape, dtype=np.uint8, noise=10.0):
    """A smooth-plus-texture image and a noisy copy, in `dtype` (values 0..255)."""
    base = ndi.gaussian_filter(rng.normal(0, 1, shape), sigma=(2, 2) + (0,) * (len(shape) - 2))
    base = 255 * (base - base.min()) / np.ptp(base)
    test = np.clip(base + rng.normal(0, noise, shape), 0, 255)
    base = np.rint(base) if np.issubdtype(dtype, np.integer) else base
    test = np.rint(test) if np.issubdtype(dtype, np.integer) else test
    return base.astype(dtype), test.astype(dtype)


def _chain_pair(n, crop=(256, 320), pattern="mask1", method="bi"):
    """(reference, reconstructed) 8-bit sRGB images of Kodak image n through the colour chain:
    the inputs the evaluation hands to the metrics."""
    img = load_kodak(n, crop=crop)
    lin = rz.simulation.srgb_to_linear(img / 255.0)
    frame = rz.mosaic(lin, pattern, 11)
    frame = rz.RawFrame(frame.data, frame.pattern, 11,
                        reference=rz.mosaic(lin, "bayer", 11).data)
    isp = rz.ColourISP(defects=rz.isp.DefectCorrection(enabled=False),
                       reconstruction=rz.isp.Reconstruction(method=method), black_level=0.0)
    return isp.run_pair(frame)


# ---------------------------------------------------------------- SSIM / MS-SSIM

@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64, np.int16,
                                   np.float16])
@pytest.mark.parametrize("shape", [(40, 52, 3), (11, 11), (23, 17, 2)])
def test_ssim_matches_reference(rng, dtype, shape):
    ref, test = _pair(rng, shape, dtype)
    assert_allclose(ssim(ref, test), ref_metrics.ssim(ref, test), **SSIM_TOL)


@pytest.mark.parametrize("win_size, sigma, gaussian", [(11, 1.5, True), (7, 1.0, True),
                                                       (1, 1.5, True), (5, 1.5, False),
                                                       (9, 3.0, False)])
def test_ssim_windows_match_reference(rng, win_size, sigma, gaussian):
    ref, test = _pair(rng, (30, 34, 3), np.float64)
    kw = dict(win_size=win_size, sigma=sigma, gaussian_weights=gaussian)
    assert_allclose(ssim(ref, test, crop=2, **kw),
                    ref_metrics.ssim(ref, test, crop=2, **kw), **SSIM_TOL)


def test_ssim_channel_axis_and_data_range_match_reference(rng):
    ref, test = _pair(rng, (3, 29, 31), np.float64)
    for axis in (0, -3):
        assert_allclose(ssim(ref / 255, test / 255, data_range=1.0, channel_axis=axis),
                        ref_metrics.ssim(ref / 255, test / 255, data_range=1.0,
                                         channel_axis=axis), **SSIM_TOL)


@pytest.mark.parametrize("shape", [(161, 161), (170, 193, 3), (200, 167, 3)])
@pytest.mark.parametrize("dtype", [np.uint8, np.float32])
def test_ms_ssim_matches_reference(rng, shape, dtype):
    ref, test = _pair(rng, shape, dtype, noise=25.0)
    assert_allclose(ms_ssim(ref, test), ref_metrics.ms_ssim(ref, test), **SSIM_TOL)
    w = (0.3, 0.7)
    assert_allclose(ms_ssim(ref, test, weights=w, crop=3),
                    ref_metrics.ms_ssim(ref, test, weights=w, crop=3), **SSIM_TOL)


@pytest.mark.parametrize("shape", [(4, 6, 8), (1, 7, 9), (2, 1, 1), (3, 2, 5)])
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
def test_downsample2_is_the_reference_bit_for_bit(rng, shape, dtype):
    a = (rng.random(shape) * 250).astype(dtype)
    got = _downsample2(np.ascontiguousarray(a), 2)
    assert got.dtype == np.float64
    assert np.array_equal(got, ref_metrics.downsample2(a.astype(np.float64)))


def test_ssim_on_chain_images_matches_reference_and_skimage():
    ref, test = _chain_pair(3)
    want = ref_metrics.ssim(ref, test, crop=8)
    assert_allclose(ssim(ref, test, crop=8), want, **SSIM_TOL)
    sk = sk_ssim(ref[8:-8, 8:-8], test[8:-8, 8:-8], data_range=255, channel_axis=-1, **SK_WANG)
    assert_allclose(ssim(ref, test, crop=8), sk, rtol=1e-9)
    assert_allclose(ms_ssim(ref, test, crop=8), ref_metrics.ms_ssim(ref, test, crop=8),
                    **SSIM_TOL)


# ---------------------------------------------------------------- MSE (CFA PSNR, CPSNR)

@pytest.mark.parametrize("shape, mask_shape", [((40, 52), (40, 52)), ((30, 20, 3), (30, 20)),
                                               ((30, 20, 3), (30, 20, 3)), ((9, 7, 2), None)])
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
def test_cfa_psnr_mse_matches_reference(rng, shape, mask_shape, dtype):
    from rgbz_fast.metrics._psnr import _sq_diff_sum

    top = 2047 if dtype is np.uint16 else 255
    a = (rng.random(shape) * top).astype(dtype)
    b = (rng.random(shape) * top).astype(dtype)
    mask = None if mask_shape is None else rng.random(mask_shape) < 0.3
    want = ref_metrics.mse(a, b, mask)
    assert_allclose(cfa_psnr(a, b, mask, data_range=top), 10 * np.log10(top ** 2 / want),
                    rtol=1e-13)
    if np.issubdtype(dtype, np.integer):            # exact: the sum of the int64 squares
        flat = mask is not None and mask.ndim == 3   # one flag per element
        args = [x.reshape(x.shape[0], -1) for x in (a, b, mask)] if flat else [a, b, mask]
        total, count = _sq_diff_sum(*args, 2)
        full = np.ones(a.shape, bool) if mask is None else np.broadcast_to(
            mask if mask.shape == a.shape else mask[..., np.newaxis], a.shape)
        d = a.astype(np.int64)[full] - b.astype(np.int64)[full]
        assert total == int(np.sum(d * d)) and count == np.count_nonzero(full)


def test_cpsnr_matches_reference_on_chain_images():
    ref, test = _chain_pair(5)
    want = 10 * np.log10(255 ** 2 / ref_metrics.mse(ref[8:-8, 8:-8], test[8:-8, 8:-8]))
    assert_allclose(cpsnr(ref, test, crop=8), want, rtol=1e-13)
    assert_allclose(cpsnr_pooled([ref, test], [test, ref], crop=8), want, rtol=1e-13)


# ---------------------------------------------------------------- CIELAB

def _colour_lab(rgb, full_scale):
    return ref_metrics.to_lab(rgb, full_scale)


def _lab_of(rgb, input):
    """The kernel's Lab, through the public delta_e_map's conversion."""
    from rgbz_fast.metrics._zipper import _to_lab

    return _to_lab(np.asarray(rgb), input, 2)


def test_lab_matches_colour_on_every_grey_and_random_colours(rng):
    grey = np.repeat(np.arange(256, dtype=np.uint8)[:, np.newaxis, np.newaxis], 3, axis=2)
    colours = rng.integers(0, 256, (300, 400, 3), dtype=np.uint8)
    for img in (grey, colours):
        assert np.abs(_lab_of(img, "srgb8") - _colour_lab(img, 255.0)).max() <= LAB_ATOL


@pytest.mark.parametrize("input, scale, dtype", [("srgb16", 65535.0, np.uint16),
                                                 ("srgb01", 1.0, np.float64),
                                                 ("srgb01", 1.0, np.float32),
                                                 ("srgb8", 255.0, np.float64)])
def test_lab_matches_colour_other_encodings(rng, input, scale, dtype):
    img = (rng.random((64, 80, 3)) * scale).astype(dtype)
    if dtype is np.uint16:     # a small image: per-pixel EOTF, not the table
        assert np.abs(_lab_of(img[:8, :8], input) - _colour_lab(img[:8, :8], scale)).max() \
            <= LAB_ATOL
    assert np.abs(_lab_of(img, input) - _colour_lab(img, scale)).max() <= LAB_ATOL


def test_lab_out_of_range_floats_match_colour(rng):
    """Float sRGB outside [0, 1] is converted as it is: negative values (the linear segment),
    values far above white (X/Xn >= 8: the cube root's slow path)."""
    img = rng.uniform(-0.5, 1.5, (40, 50, 3))
    img[0, :10] = [[v, v, v] for v in (2.0, 3.0, 5.0, 9.0, 20.0, 100.0, 1e3, 1e5, 1e8, 0.0)]
    got, want = _lab_of(img, "srgb01"), _colour_lab(img, 1.0)
    # a* = 500 (f(X/Xn) - f(Y/Yn)) cancels: its error is a few ulp of f ~ L*/116, so the
    # bound grows with L* (1e8 gives L* = 2.9e8 and an error of 2e-7 in a*)
    err = np.abs(got - want).max(axis=-1)
    assert np.all(err <= LAB_ATOL + 1e-14 * np.abs(want[..., 0])), err.max()
    assert np.abs(got - want)[1:].max() <= LAB_ATOL


def test_lab_matches_colour_on_a_kodak_image():
    img = load_kodak(9)
    assert np.abs(_lab_of(img, "srgb8") - _colour_lab(img, 255.0)).max() <= LAB_ATOL


def test_delta_e_map_matches_colour_delta_e(rng):
    import colour

    ref, test = _pair(rng, (33, 47, 3))
    want = colour.delta_E(_colour_lab(ref, 255.0), _colour_lab(test, 255.0), method="CIE 1976")
    assert_allclose(delta_e_map(ref, test), want, rtol=0, atol=LAB_ATOL * 4)


# ---------------------------------------------------------------- zipper

@pytest.mark.parametrize("dtype, input, scale", [(np.uint8, "srgb8", 255.0),
                                                 (np.float64, "srgb8", 255.0),
                                                 (np.float32, "srgb8", 255.0),
                                                 (np.uint16, "srgb16", 65535.0)])
def test_zipper_matches_reference(rng, dtype, input, scale):
    ref, test = _pair(rng, (37, 45, 3), np.float64, noise=6.0)
    if dtype is np.uint16:
        ref, test = ref * 257, test * 257
    ref = np.rint(ref).astype(dtype) if np.issubdtype(dtype, np.integer) else ref.astype(dtype)
    test = np.rint(test).astype(dtype) if np.issubdtype(dtype, np.integer) else \
        test.astype(dtype)
    got = zipper(ref, test, input=input, crop=1)
    assert got == ref_metrics.zipper(ref, test, crop=1, full_scale=scale)
    assert 0 < got < 100


def test_zipper_lab_input_and_ties_match_reference(rng):
    # a quantised Lab image: many exact ties between neighbours
    lab = np.rint(rng.normal(50, 3, (30, 40, 3)))
    test = lab + np.rint(rng.normal(0, 2, lab.shape))
    for delta in (0.0, 1.0, 2.3, 5.0):
        assert zipper(lab, test, input="lab", delta=delta) == \
            ref_metrics.zipper_lab(lab, test, delta)


def test_zipper_exact_tie_takes_the_first_neighbour_in_raster_order():
    """Kodak kodim11, Mask2 SG, pixel (139, 312): centre (28, 13, 8), left neighbour
    (28, 13, 9), bottom one (28, 13, 7). All three sit on the linear segments of the sRGB
    EOTF and of CIELAB's f, so the two dE are equal exactly (0.40368506525549440596 to 25
    digits in 50-digit arithmetic); eq. 30 with the raster-order rule takes the left one, as
    the kernel does. colour-science's rounding breaks the tie by its last bits, which depend
    on the OpenBLAS kernel behind its matrix products (chosen from the CPU, or by
    OPENBLAS_CORETYPE): with the SkylakeX kernels (an AVX-512 CPU left alone) the left one
    comes out 4.3e-15 larger and the reference takes the bottom one (the one pixel of the 240
    Kodak evaluation pairs where the two zipper maps differed on the Intel host of
    docs/reports/benchmarks.md); with the Haswell ones (an AVX2 CPU, or
    OPENBLAS_CORETYPE=Haswell, as on the host of 2026-11-28) 5.5e-15 smaller, and it takes
    the left one. The kernel's answer is the same on both."""
    far = (200, 200, 200)
    ref = np.array([[far, far, far], [(28, 13, 9), (28, 13, 8), far],
                    [far, (28, 13, 7), far]], dtype=np.uint8)
    test = ref.copy()
    test[2, 1] = (90, 13, 7)          # only the bottom neighbour changes
    assert zipper(ref, test) == 0.0   # the left one is chosen: psi = 0
    # colour's Lab: whichever neighbour its rounding on this CPU makes nearer
    assert ref_metrics.zipper(ref, test) in (0.0, 100.0)


@pytest.mark.parametrize("n, pattern, method", [(9, "mask1", "bi"), (19, "mask2", "sg"),
                                                (23, "mask2", "bilinear")])
def test_zipper_on_chain_images_matches_reference(n, pattern, method):
    ref, test = _chain_pair(n, pattern=pattern, method=method)
    want = ref_metrics.zipper(ref, test, crop=8)
    assert zipper(ref, test, crop=8) == want
    assert all_metrics(ref, test, crop=8)["zipper"] == want


# ---------------------------------------------------------------- one reference, many images

@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
def test_a_reference_reused_gives_the_values_of_each_pair_alone(rng, dtype):
    ref, first = _pair(rng, (190, 170, 3), dtype, noise=6.0)
    tests = [first] + [_pair(rng, (190, 170, 3), dtype, noise=n)[1] for n in (2.0, 12.0)]
    tests[1] = np.clip(ref.astype(np.float64) + rng.normal(0, 2, ref.shape), 0, 255)
    tests[1] = np.rint(tests[1]).astype(dtype) if np.issubdtype(dtype, np.integer) else \
        tests[1].astype(dtype)
    memo = {}
    for test in tests + [ref]:
        got = _colour_metrics(ref, test, COLOUR_METRICS, 255, 3, 2, memo=memo)
        assert got == all_metrics(ref, test, crop=3, workers=2)
    assert {k[0] for k in memo} == {"cropped", "ssim", "zipper"}


@pytest.mark.parametrize("ntaps, gaussian", [(11, True), (7, True), (5, False), (1, True)])
@pytest.mark.parametrize("dtype", [np.uint8, np.float64])
def test_ssim_sums_from_the_reference_moments_are_those_computed_anew(rng, ntaps, gaussian,
                                                                      dtype):
    ref, test = _pair(rng, (3, 41, 37), dtype)
    w = _window(ntaps, 1.5, gaussian)
    moments = np.empty((3 * (41 - ntaps + 1), 2, 37 - ntaps + 1))
    _kernels.ssim_reference(ref, w, moments, 2)
    sums = [(np.empty(3), np.empty(3)) for _ in range(2)]
    for mom, (s, c) in zip((None, moments), sums):
        _kernels.ssim_sums(ref, test, mom, w, 6.5, 58.5, s, c, 2)
    assert np.array_equal(sums[0][0], sums[1][0]) and np.array_equal(sums[0][1], sums[1][1])
    # the moments are the local means and population variances of the reference
    mean = ndi.correlate1d(ndi.correlate1d(ref[0].astype(np.float64), w, axis=0), w, axis=1)
    sq = ndi.correlate1d(ndi.correlate1d(ref[0].astype(np.float64) ** 2, w, axis=0), w, axis=1)
    r = ntaps // 2
    inner = (slice(r, 41 - r), slice(r, 37 - r))
    assert np.array_equal(moments[:41 - ntaps + 1, 0], mean[inner])
    assert np.array_equal(moments[:41 - ntaps + 1, 1], sq[inner] - mean[inner] ** 2)
    with pytest.raises(ValueError, match="x_moments"):
        _kernels.ssim_sums(ref, test, moments[1:], w, 6.5, 58.5, *sums[0], 1)
    # without the SSIM sums (MS-SSIM's middle scales): the same contrast-structure sums
    for mom in (None, moments):
        cs = np.empty(3)
        _kernels.ssim_sums(ref, test, mom, w, 6.5, 58.5, None, cs, 2)
        assert np.array_equal(cs, sums[0][1])


@pytest.mark.parametrize("dtype, scale", [(np.uint8, 255.0), (np.float64, 255.0),
                                          (np.float64, 0.0)])
def test_zipper_in_two_halves_is_the_fused_count(rng, dtype, scale):
    ref, test = _pair(rng, (37, 45, 3), np.float64, noise=6.0)
    if scale == 0.0:                                  # quantised Lab: many exact ties
        ref, test = np.rint(ref / 4), np.rint(test / 4)
    ref, test = ref.astype(dtype), test.astype(dtype)
    best = np.empty((35, 43))
    nearest = np.empty((35, 43), dtype=np.uint8)
    _kernels.zipper_reference(ref, scale, best, nearest, 2)
    assert nearest.max() <= 7
    for delta in (0.0, 1.0, 2.3):
        assert _kernels.zipper_count_reference(test, scale, best, nearest, delta, 2) == \
            _kernels.zipper_count(ref, test, scale, delta, 2)
    want = ref_metrics.zipper(ref, test, full_scale=scale) if scale else \
        ref_metrics.zipper_lab(ref, test, 2.3)
    assert 100.0 * _kernels.zipper_count_reference(test, scale, best, nearest, 2.3, 1) \
        / (35 * 43) == want
    nearest[3, 4] = 8                                 # no neighbour: refused
    with pytest.raises(RuntimeError, match="rejected its arguments"):
        _kernels.zipper_count_reference(test, scale, best, nearest, 2.3, 1)


# ---------------------------------------------------------------- threads and instruction sets

def _all_values(ref, test, workers):
    memo = {}
    return (all_metrics(ref, test, crop=2, workers=workers),
            ssim(ref, test, workers=workers, win_size=7, gaussian_weights=False),
            delta_e_map(ref, test, workers=workers),
            [_colour_metrics(ref, t, COLOUR_METRICS, 255, 2, workers, memo=memo)
             for t in (test, ref)])


def test_results_do_not_depend_on_threads(rng):
    ref, test = _pair(rng, (190, 170, 3))
    first = _all_values(ref, test, 1)
    for workers in (2, 3, 7, None):
        again = _all_values(ref, test, workers)
        assert again[0] == first[0] and again[1] == first[1] and again[3] == first[3]
        assert np.array_equal(again[2], first[2])


def test_every_instruction_set_gives_the_same_bits(rng):
    ref, test = _pair(rng, (190, 170, 3), noise=4.0)
    isas = _kernels.metrics_isas_available()
    assert isas[0] == "generic" and _kernels.metrics_isa() == isas[-1]
    results = {}
    try:
        for isa in isas:
            _kernels.metrics_use_isa(isa)
            assert _kernels.metrics_isa() == isa
            results[isa] = _all_values(ref, test, 2)
    finally:
        _kernels.metrics_use_isa(None)
    assert _kernels.metrics_isa() == isas[-1]
    for isa, values in results.items():
        assert values[0] == results["generic"][0] and values[1] == results["generic"][1], isa
        assert values[3] == results["generic"][3], isa
        assert np.array_equal(values[2], results["generic"][2]), isa


def test_unknown_instruction_set_is_refused():
    unavailable = [n for n in _kernels.METRICS_ISAS if n not in
                   _kernels.metrics_isas_available()]
    for name in unavailable:
        with pytest.raises(RuntimeError):
            _kernels.metrics_use_isa(name)
    assert _kernels.metrics_isa() == _kernels.metrics_isas_available()[-1]


@pytest.mark.parametrize("dtype, bits", [(np.uint8, 8), (np.uint16, 16)])
def test_every_instruction_set_gives_the_lab_of_the_divisions(rng, dtype, bits):
    # integer codes reach the white point's divisions as x * (1 / c) corrected by an FMA
    # where the set has one (metrics.c, MT_QFMA): every 8-bit colour (2**24, in blocks of
    # 2**20), and 10**6 random 16-bit ones, give the Lab of the generic build, which divides
    if bits == 8:
        blocks = [np.arange(k << 20, (k + 1) << 20, dtype=np.uint32) for k in range(16)]
        blocks = [np.stack([c >> 16, (c >> 8) & 255, c & 255], axis=-1).astype(dtype)
                  for c in blocks]
    else:
        blocks = [rng.integers(0, 1 << 16, (10**6, 3)).astype(dtype)]
    isas = _kernels.metrics_isas_available()
    try:
        for rgb in blocks:
            lab = {}
            for isa in isas:
                _kernels.metrics_use_isa(isa)
                lab[isa] = np.empty(rgb.shape)
                _kernels.srgb_to_lab(rgb, float((1 << bits) - 1), lab[isa], 2)
            for isa in isas:
                assert np.array_equal(lab[isa], lab["generic"]), (isa, rgb[0])
    finally:
        _kernels.metrics_use_isa(None)


def _lab_rows(rgb, scale):
    """The Lab of rgb (rows, cols, 3) both ways the kernels compute it: pixel by pixel into an
    (n, 3) array (srgb_to_lab), and row by row into planes (the zipper's best dE, which needs
    the Lab of every pixel and its neighbours)."""
    lab = np.empty((rgb.shape[0] * rgb.shape[1], 3))
    _kernels.srgb_to_lab(np.ascontiguousarray(rgb.reshape(-1, 3)), scale, lab, 1)
    best = np.empty((rgb.shape[0] - 2, rgb.shape[1] - 2))
    nearest = np.empty(best.shape, np.uint8)
    _kernels.zipper_reference(np.ascontiguousarray(rgb), scale, best, nearest, 1)
    return lab, best, nearest


@pytest.mark.parametrize("dtype, scale", [(np.uint8, 255.0), (np.uint16, 65535.0),
                                          (np.float32, 1.0), (np.float64, 1.0)])
def test_every_instruction_set_gives_the_same_lab_at_every_row_length(rng, dtype, scale):
    # the AVX-512 Lab loop (metrics_lab512.h) does 8 pixels at a time and leaves the last
    # n % 8 to the C loop; floats reach it with NaN, infinities, negative values and ratios
    # >= 8 (the slow path)
    isas = _kernels.metrics_isas_available()
    shapes = [(3, cols) for cols in range(3, 42)] + [(5, 517)]
    try:
        for rows, cols in shapes:
            if np.issubdtype(dtype, np.integer):
                rgb = rng.integers(0, int(scale) + 1, (rows, cols, 3)).astype(dtype)
            else:
                rgb = rng.uniform(-0.2, 1.3, (rows, cols, 3))
                special = [np.nan, np.inf, -np.inf, 9.0, 1e6, -1.0, 0.0]
                rgb.reshape(-1)[rng.choice(rgb.size, min(rgb.size // 4, 40), replace=False)] = \
                    rng.choice(special, min(rgb.size // 4, 40))
                rgb = rgb.astype(dtype)
            got = {}
            for isa in isas:
                _kernels.metrics_use_isa(isa)
                got[isa] = _lab_rows(rgb, scale)
            for isa in isas:
                for a, b in zip(got[isa], got["generic"]):
                    assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), (isa, cols)
    finally:
        _kernels.metrics_use_isa(None)


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
@pytest.mark.parametrize("channels", [1, 2, 3, 4])
def test_planar_copy_is_numpy_moveaxis(rng, dtype, channels):
    img = rng.integers(0, 256, (37, 41, channels)).astype(dtype)
    for src in (img, img[2:-3, 1:-4]):                    # contiguous, and a crop
        out = np.empty((channels,) + src.shape[:2], dtype)
        _kernels.planar(src, out, 3)
        assert np.array_equal(out, np.moveaxis(src, -1, 0))
    with pytest.raises(ValueError, match="src: expected contiguous pixels"):
        _kernels.planar(img[:, ::2], np.empty((channels, 37, 21), dtype), 1)
    with pytest.raises(ValueError, match="dst: not the"):
        _kernels.planar(img, np.empty((channels, 41, 37), dtype), 1)
