"""Bayer demosaic: the C Malvar 2004, bilinear and Menon 2007 kernels against
colour-demosaicing (Malvar to 1e-6, bilinear and Menon bit for bit), borders, dtypes, threads,
and bad input."""

from __future__ import annotations

import warnings
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from _reference.demosaic import reference_demosaic  # noqa: E402
from _support import load_kodak  # noqa: E402

from rgbz_fast import _kernels, bayer, mask1, mosaic  # noqa: E402
from rgbz_fast.isp import DEMOSAIC_METHODS, demosaic
from rgbz_fast._deps import import_colour_demosaicing as _colour_demosaicing  # noqa: E402

PHASES = ["RGGB", "BGGR", "GRBG", "GBRG"]
TOL = {np.float32: dict(rtol=1e-6, atol=1e-6), np.float64: dict(rtol=1e-12, atol=1e-12)}


@pytest.fixture(scope="module")
def cd():
    return _colour_demosaicing()


def test_importing_colour_demosaicing_raises_no_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _colour_demosaicing()


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("phase", PHASES)
def test_malvar_matches_colour_demosaicing_on_random_data(cd, phase, dtype):
    raw = np.random.default_rng(0).random((33, 46)).astype(dtype)
    got = demosaic(raw, phase)
    assert got.dtype == dtype and got.shape == (33, 46, 3)
    want = cd.demosaicing_CFA_Bayer_Malvar2004(raw.astype(np.float64), phase)
    np.testing.assert_allclose(got, want, **TOL[dtype])


@pytest.mark.parametrize("out", [np.float32, np.float64])
@pytest.mark.parametrize("phase", PHASES)
def test_malvar_matches_colour_demosaicing_on_kodak(cd, phase, out):
    img = load_kodak(19, crop=(96, 128))
    cfa = mosaic(img, bayer(phase)).data                      # uint16, 11 bit
    got = demosaic(cfa, phase, dtype=out)
    assert got.dtype == out
    want = cd.demosaicing_CFA_Bayer_Malvar2004(cfa.astype(np.float64), phase)
    # 1e-6 relative to the data range (float32 output carries about 1e-4 DN)
    np.testing.assert_allclose(got / 2047.0, want / 2047.0, rtol=0, atol=1e-6)


@pytest.mark.parametrize("dtype,expected", [(np.uint8, np.float32), (np.uint16, np.float32),
                                            (np.float32, np.float32),
                                            (np.float64, np.float64), (np.int32, np.float32),
                                            (np.int64, np.float32)])
def test_output_dtype_rule(dtype, expected):
    raw = np.random.default_rng(1).integers(0, 200, (8, 10)).astype(dtype)
    got = demosaic(raw)
    assert got.dtype == expected
    np.testing.assert_allclose(got, demosaic(raw.astype(np.float64)), rtol=1e-6, atol=1e-4)


@pytest.mark.parametrize("phase", PHASES)
def test_period_mode_equals_reflect_in_the_interior(phase):
    raw = np.random.default_rng(2).random((30, 40))
    a = demosaic(raw, phase, mode="reflect")
    b = demosaic(raw, phase, mode="period")
    np.testing.assert_array_equal(a[2:-2, 2:-2], b[2:-2, 2:-2])
    assert not np.array_equal(a, b)              # the borders do differ


def test_period_mode_keeps_colours_at_the_border(cd):
    """Period borders equal colour-demosaicing on a CFA padded by whole periods."""
    raw = np.random.default_rng(3).random((20, 26))
    padded = np.pad(raw, 2, mode="reflect")      # not period-preserving ...
    ri = np.r_[[0, 1], np.arange(20), [18, 19]]  # ... this is: -2 -> 0, -1 -> 1, n -> n-2
    ci = np.r_[[0, 1], np.arange(26), [24, 25]]
    padded = raw[ri[:, None], ci[None, :]]
    want = cd.demosaicing_CFA_Bayer_Malvar2004(padded, "GRBG")[2:-2, 2:-2]
    np.testing.assert_allclose(demosaic(raw, "GRBG", mode="period"), want, rtol=1e-12,
                               atol=1e-12)


@pytest.mark.parametrize("phase", PHASES)
@pytest.mark.parametrize("method", ["menon2007", "bilinear"])
def test_colour_demosaicing_methods_match_on_kodak(method, phase):
    """Tolerance 0 on a real image (uint16, 11 bit), both borders, which agree ten pixels
    (Menon 2007) from the edge."""
    img = load_kodak(23, crop=(64, 96))
    cfa = mosaic(img, bayer(phase)).data
    for mode in ("reflect", "period"):
        want = reference_demosaic(cfa, phase, method, mode)
        got = demosaic(cfa, phase, method, mode=mode, dtype=np.float64)
        np.testing.assert_array_equal(got, want, err_msg=mode)
    per = demosaic(cfa, phase, method, mode="period", dtype=np.float64)
    np.testing.assert_array_equal(per[10:-10, 10:-10], want[10:-10, 10:-10])
    assert demosaic(cfa, phase, method).dtype == np.float32


# -- Menon 2007 (csrc/demosaic_menon.c) --------------------------------------------------------
MENON_SHAPES = [(2, 2), (2, 3), (3, 2), (3, 3), (2, 9), (9, 2), (4, 5), (5, 4), (6, 6), (7, 11),
                (16, 17), (33, 46), (64, 97)]


def _menon_cfa(shape, dtype, content, seed):
    """A CFA of ``dtype``: uniform noise over the type's range (float64: signed, in
    [-1000, 1000)), or smooth content with steps (a vertical, a horizontal and a diagonal
    edge, whose directions the decision has to find) and a little noise."""
    rng = np.random.default_rng(seed)
    top = {np.uint8: 255.0, np.uint16: 2047.0, np.float32: 1.0, np.float64: 1000.0}[dtype]
    if content == "noise":
        v = rng.random(shape) * top
        if dtype == np.float64:
            v = v * 2 - top
    else:
        y, x = np.mgrid[:shape[0], :shape[1]].astype(np.float64)
        v = 0.4 + 0.15 * np.sin(x / 3.1 + y / 4.7)
        v += 0.25 * (x > shape[1] / 2) - 0.2 * (y > shape[0] / 3) + 0.15 * (x + y > shape[0])
        v = np.clip(v + 0.02 * rng.standard_normal(shape), 0, 1) * top
    return (np.round(v) if np.dtype(dtype).kind == "u" else v).astype(dtype)


@pytest.mark.parametrize("content", ["noise", "edges"])
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
@pytest.mark.parametrize("shape", MENON_SHAPES)
def test_menon_is_colour_demosaicing_bit_for_bit(shape, dtype, content):
    """Tolerance 0: the kernel is colour-demosaicing's demosaicing_CFA_Bayer_Menon2007 (refining
    step on) of the CFA as float64 bit for bit, every phase, both borders (period: the
    reference on the CFA padded by 8 pixels by whole periods, cropped, as the library gave it
    before the kernel), and its float32 output is that result rounded once. The kernel
    repeats the reference's operations in its order (csrc/demosaic_menon.c), so a wrong tap,
    weight, order or border rule shows; frames from 2x2 up, where the mirror of an axis of 2
    or 3 repeats it and every pixel is a border pixel. (Not the signs of zeros: the kernel
    leaves out the taps of weight 0, which add +-0.)"""
    raw = _menon_cfa(shape, dtype, content, seed=sum(shape) + len(content))
    for phase in PHASES:
        for mode in ("reflect", "period"):
            want = reference_demosaic(raw, phase, "menon2007", mode)
            for out in (np.float32, np.float64):
                got = demosaic(raw, phase, "menon2007", mode=mode, dtype=out)
                assert got.dtype == out and got.shape == shape + (3,)
                np.testing.assert_array_equal(got, want.astype(out),
                                              err_msg=f"{phase} {mode} {np.dtype(out)}")


@pytest.mark.parametrize("shape", [(2, 5), (9, 13), (37, 21)])
def test_menon_any_thread_count_gives_the_reference(shape):
    """Tolerance 0 with 1 to 5 threads on small frames, through the kernel itself, which takes
    the count as given (demosaic gives a thread 2**18 pixels at least): bands of 1 row and
    up, whose margins reach the frame's borders."""
    raw = _menon_cfa(shape, np.uint16, "edges", seed=7)
    codes = np.array([1, 0, 2, 1], np.int32)
    for mode in ("reflect", "period"):
        want = reference_demosaic(raw, "GRBG", "menon2007", mode)
        for workers in range(1, 6):
            got = np.empty(shape + (3,))
            _kernels.demosaic_kernel(_kernels.DEMOSAIC_KERNELS["menon2007"], raw, got, codes,
                                     _kernels.DEMOSAIC_MODES[mode], workers)
            np.testing.assert_array_equal(got, want, err_msg=f"{mode} {workers}")


def test_menon_one_two_three_threads_give_the_same_image():
    """Tolerance 0 between 1, 2 and 3 threads on a frame of 3 threads' worth, and against
    the reference."""
    raw = _menon_cfa((1001, 800), np.uint16, "edges", seed=8)
    want = reference_demosaic(raw, "RGGB", "menon2007")
    for workers in (1, 2, 3):
        got = demosaic(raw, "RGGB", "menon2007", dtype=np.float64, workers=workers)
        np.testing.assert_array_equal(got, want, err_msg=str(workers))


@pytest.mark.parametrize("shape", [(2, 2), (3, 5), (7, 2), (2, 9), (33, 46), (64, 97)])
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64, np.int32])
def test_bilinear_is_colour_demosaicing_bit_for_bit(cd, shape, dtype):
    """The C kernel's bilinear is the reference's bits (with their signs), every phase,
    both output types, both borders: the reflect border masks before it mirrors, so a
    border pixel's mirrored taps of another colour add nothing (tested on frames of one
    and two periods, where every pixel is a border pixel)."""
    rng = np.random.default_rng(sum(shape))
    raw = (rng.standard_normal(shape) * 1e3 if dtype == np.float64
           else (rng.random(shape) * 200).astype(dtype))
    for phase in PHASES:
        want = cd.demosaicing_CFA_Bayer_bilinear(raw.astype(np.float64), phase)
        per = reference_demosaic(raw, phase, "bilinear", "period")
        for out in (np.float32, np.float64):
            for mode, ref in (("reflect", want), ("period", per)):
                got = demosaic(raw, phase, "bilinear", mode=mode, dtype=out)
                assert got.dtype == out
                np.testing.assert_array_equal(got, ref.astype(out), err_msg=f"{phase} {mode}")
                np.testing.assert_array_equal(np.signbit(got), np.signbit(ref.astype(out)))


def test_bilinear_borders_differ_from_the_direct_formula():
    """The reflect border's rule has an effect (else the test above would not see a wrong
    border): a flat CFA is not flat at the reflect border, and is flat with periods."""
    cfa = np.full((6, 8), 100.0)
    rgb = demosaic(cfa, "GRBG", "bilinear", dtype=np.float64)
    assert np.all(rgb[2:-2, 2:-2] == 100) and np.any(rgb[0] != 100)
    np.testing.assert_array_equal(demosaic(cfa, "GRBG", "bilinear", mode="period"), 100)


def test_menon_beats_bilinear_and_malvar_is_close_on_kodak():
    img = load_kodak(19, crop=(128, 128))
    cfa = mosaic(img, bayer()).data
    truth = img.astype(np.float64) / 255 * 2047
    err = {m: np.sqrt(np.mean((demosaic(cfa, method=m) - truth)[8:-8, 8:-8] ** 2))
           for m in DEMOSAIC_METHODS}
    assert err["menon2007"] < err["bilinear"] and err["malvar2004"] < err["bilinear"]


def test_flat_cfa_gives_flat_image_with_period_borders():
    cfa = np.full((6, 8), 321, np.uint16)
    cfa.setflags(write=False)                    # read-only input is accepted, not modified
    for m in DEMOSAIC_METHODS:
        np.testing.assert_allclose(demosaic(cfa, method=m, mode="period"), 321, rtol=1e-6)
    # colour-demosaicing's reflect border mirrors colours: only Malvar stays flat there
    np.testing.assert_allclose(demosaic(cfa), 321, rtol=1e-6)


@pytest.mark.parametrize("method", ["malvar2004", "bilinear", "menon2007"])
def test_pattern_object_as_phase_and_workers_do_not_change_the_result(method):
    raw = np.random.default_rng(4).random((1100, 480))        # two threads' worth
    a = demosaic(raw, bayer("GBRG"), method, workers=1)
    b = demosaic(raw, "gbrg", method, workers=2)
    np.testing.assert_array_equal(a, b)
    with ThreadPoolExecutor(4) as ex:
        outs = list(ex.map(lambda _: demosaic(raw, "GBRG", method), range(4)))
    for o in outs:
        np.testing.assert_array_equal(o, a)


@pytest.mark.parametrize("kwargs,exc,name", [
    (dict(cfa=np.zeros((4, 4, 3))), ValueError, "cfa"),
    (dict(cfa=np.zeros((1, 8))), ValueError, "cfa"),
    (dict(cfa=np.full((4, 4), np.nan)), ValueError, "cfa"),
    (dict(cfa=np.zeros((4, 4), complex)), TypeError, "cfa"),
    (dict(cfa=np.zeros((4, 4)), phase="RGBG"), ValueError, "phase"),
    (dict(cfa=np.zeros((4, 4)), phase=mask1()), ValueError, "phase"),
    (dict(cfa=np.zeros((4, 4)), method="ahd"), ValueError, "method"),
    (dict(cfa=np.zeros((4, 4)), mode="wrap"), ValueError, "mode"),
    (dict(cfa=np.zeros((4, 4)), dtype=np.int16), TypeError, "dtype"),
    (dict(cfa=np.zeros((4, 4)), workers=0), ValueError, "workers"),
])
def test_bad_input_names_the_parameter(kwargs, exc, name):
    kwargs = dict(kwargs)
    cfa = kwargs.pop("cfa")
    with pytest.raises(exc, match=name):
        demosaic(cfa, **kwargs)
