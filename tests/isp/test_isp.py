"""Colour ISP: stage order, the reference and RGB-Z paths, white balance, defect
correction (planted defects; Z sites never read), sRGB output, bad input."""

from __future__ import annotations

import pickle
import warnings

import numpy as np
import pytest

from _reference.defects import reference_correct_defects  # noqa: E402
from _support import load_kodak  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from rgbz_fast import isp  # noqa: E402
from rgbz_fast.isp import (STAGES, ColourCorrection, ColourISP, DefectCorrection,  # noqa: E402
                           Demosaic, Reconstruction, WhiteBalance, correct_colour,
                           correct_defects, detect_defects, fill_missing, grey_world_gains,
                           srgb_encode, srgb_oetf, white_balance)
from rgbz_fast.isp import demosaic  # noqa: E402
from rgbz_fast.metrics import cpsnr  # noqa: E402
from rgbz_fast.simulation import Scene  # noqa: E402
from rgbz_fast.simulation import simulate  # noqa: E402


def _smooth_scene(shape=(48, 64), seed=0):
    """A smooth colourful linear image in [0.05, 0.9] (no one-pixel details)."""
    rr, cc = np.mgrid[0:shape[0], 0:shape[1]] / max(shape)
    img = np.stack([0.4 + 0.3 * np.sin(3 * rr + 1), 0.5 + 0.3 * np.cos(2 * cc),
                    0.3 + 0.2 * np.sin(2 * rr + 3 * cc)], axis=-1)
    return np.clip(img, 0.05, 0.9)


@pytest.fixture(scope="module")
def sim_frame():
    img = load_kodak(19, crop=(64, 96))
    return simulate(Scene.from_rgb(img), "mask1", seed=3)


# ----------------------------------------------------------------------- the chain
def test_stage_order_and_keys(sim_frame):
    out, st = ColourISP().run(sim_frame, return_stages=True)
    assert [k for k in st if k in STAGES] == list(STAGES)
    assert set(st) == set(STAGES) | {"raw", "defect_mask", "gains", "seconds", "pattern",
                                     "black_level", "white_level"}
    assert list(st["seconds"]) == list(STAGES)
    assert st["output"] is out
    H, W = sim_frame.shape
    assert st["raw"] is sim_frame.data
    assert st["reconstruction"].shape == (H, W) and st["reconstruction"].dtype == np.uint16
    assert st["white_balance"].dtype == np.float32
    assert 0 <= st["white_balance"].min() and st["white_balance"].max() <= 1
    assert st["demosaic"].shape == (H, W, 3)
    assert st["black_level"] == 64 and st["white_level"] == 2047      # from the sensor
    # every stage is its own function: re-running them one by one gives the same image
    bay = sim_frame.pattern.bayer_pattern()
    full = fill_missing(st["defect_correction"], sim_frame.pattern)
    np.testing.assert_array_equal(full, st["reconstruction"])
    wb, g = white_balance(full, bay, black_level=64, white_level=2047)
    np.testing.assert_array_equal(wb, st["white_balance"])
    rgb = demosaic(wb, bay.bayer_phase)
    np.testing.assert_array_equal(srgb_encode(correct_colour(rgb)), out)


def test_reconstruction_fills_only_z_sites(sim_frame):
    _, st = ColourISP(defects=DefectCorrection(enabled=False)).run(sim_frame,
                                                                    return_stages=True)
    z = sim_frame.z_mask
    np.testing.assert_array_equal(st["reconstruction"][~z], sim_frame.data[~z])
    assert np.all(st["reconstruction"][z] > 0)


def test_reference_and_rgbz_paths_identical_without_z_sites():
    frame = simulate(Scene.from_rgb(_smooth_scene()), "bayer", seed=1)
    chain = ColourISP()
    a, sa = chain.run(frame, return_stages=True)
    b, sb = chain.run(frame, reference=True, return_stages=True)
    np.testing.assert_array_equal(a, b)
    assert sa["reconstruction"] is sa["defect_correction"]            # bypassed
    # the same CFA as a plain array takes the same path
    c = chain.run(frame.data, pattern="bayer", black_level=64)
    np.testing.assert_array_equal(a, c)


def test_run_pair_shares_the_reference_gains(sim_frame):
    chain = ColourISP()
    ref, test, rs, ts = chain.run_pair(sim_frame, return_stages=True)
    np.testing.assert_array_equal(rs["gains"], ts["gains"])
    alone = chain.run(sim_frame, reference=True)
    np.testing.assert_array_equal(ref, alone)
    assert rs["pattern"] == rz.bayer() and ts["pattern"] == rz.mask1()
    np.testing.assert_array_equal(test, chain.run(sim_frame, gains=rs["gains"]))
    # the two paths differ by the reconstruction only: close, not equal
    psnr = cpsnr(ref, test, crop=4)
    assert 25 < psnr < 80


def test_noise_free_reference_chain_recovers_the_scene():
    """Noise-free Bayer frame of a smooth linear image: identity CCM, unit gains -> the image."""
    lin = _smooth_scene((64, 64))
    frame = rz.mosaic(lin, rz.bayer(), dtype=np.float64)
    chain = ColourISP(white_balance=WhiteBalance(method="none"))
    out = chain.run(frame)
    want = srgb_encode(lin)
    diff = np.abs(out.astype(int) - want)[4:-4, 4:-4]
    assert diff.max() <= 2


@pytest.mark.parametrize("bits,dtype", [(8, np.uint8), (16, np.uint16)])
def test_output_bits(sim_frame, bits, dtype):
    out, st = ColourISP(output_bits=bits).run(sim_frame, return_stages=True)
    assert out.dtype == dtype and out.shape == sim_frame.shape + (3,)
    top = (1 << bits) - 1
    np.testing.assert_array_equal(out, np.floor(st["gamma"] * top + 0.5).astype(dtype))
    if bits == 16:
        eight = ColourISP().run(sim_frame)
        assert np.abs(out / 257.0 - eight).max() <= 0.51


def test_precision_float64(sim_frame):
    a, st = ColourISP(precision="float64").run(sim_frame, return_stages=True)
    assert st["demosaic"].dtype == np.float64
    b = ColourISP().run(sim_frame)
    assert np.abs(a.astype(int) - b).max() <= 1


# ----------------------------------------------------------------------- white balance
def test_grey_world_gains_of_a_grey_scene_with_colour_cast():
    cfa = rz.mosaic(np.full((16, 16, 3), [0.2, 0.4, 0.1]), rz.bayer("RGGB"),
                    dtype=np.float64).data
    g = grey_world_gains(cfa, "RGGB")
    np.testing.assert_allclose(g, [2.0, 1.0, 4.0])
    # black level is removed first, clipped pixels are left out
    g2 = grey_world_gains(cfa + 64, "RGGB", black_level=64)
    np.testing.assert_allclose(g2, [2.0, 1.0, 4.0])
    wb, used = white_balance(cfa, "RGGB")
    np.testing.assert_allclose(used, g)
    np.testing.assert_allclose(wb, 0.4 * 1.0 * 2047 / 2047, rtol=1e-6)


def test_given_gains_override_and_clip():
    cfa = np.full((4, 4), 1500.0)
    wb, g = white_balance(cfa, "GRBG", gains=(2.0, 1.0, 1.5))
    np.testing.assert_array_equal(g, [2.0, 1.0, 1.5])
    assert wb.max() == 1.0                                  # 1500 * 2 / 2047 clipped
    wb2, _ = white_balance(cfa, "GRBG", WhiteBalance(clip=False), gains=(2.0, 1.0, 1.5))
    assert wb2.max() > 1
    wb3, g3 = white_balance(cfa, "GRBG", WhiteBalance(gains=(1.0, 1.0, 1.0), method="none"))
    np.testing.assert_allclose(wb3, 1500 / 2047, rtol=1e-6)
    chain = ColourISP(white_balance=WhiteBalance(gains=(1.5, 1.0, 2.0)))
    _, st = chain.run(rz.mosaic(_smooth_scene(), "mask1"), return_stages=True)
    np.testing.assert_array_equal(st["gains"], [1.5, 1.0, 2.0])


# ----------------------------------------------------------------------- defects
@pytest.mark.parametrize("pattern", ["bayer", "mask1", "mask2"])
def test_defect_correction_changes_nothing_on_noise_free_smooth_data(pattern):
    frame = rz.mosaic(_smooth_scene(), pattern)
    out, mask = correct_defects(frame.data, pattern, return_mask=True)
    assert not mask.any()
    np.testing.assert_array_equal(out, frame.data)


@pytest.mark.parametrize("pattern", ["bayer", "mask1", "mask2"])
def test_defect_correction_changes_nothing_on_a_noise_free_kodak_crop(pattern):
    img = load_kodak(7, crop=(96, 128))
    frame = rz.mosaic(img, pattern)
    assert not detect_defects(frame.data, pattern).any()


@pytest.mark.parametrize("pattern", ["bayer", "mask1", "mask2"])
def test_defect_correction_fixes_planted_hot_and_dead_pixels(pattern):
    frame = simulate(Scene.from_rgb(_smooth_scene()), pattern, seed=2)
    data = frame.data.copy()
    z = frame.z_mask
    sites = [(20, 31), (21, 30), (9, 9), (40, 50), (0, 5), (47, 62)]
    sites = [(r, c) for r, c in sites if not z[r, c]]
    original = data[tuple(np.array(sites).T)].copy()
    for r, c in sites:                            # hot on dark pixels, dead on bright ones
        data[r, c] = 2047 if data[r, c] < 1024 else 0
    assert len(set(data[tuple(np.array(sites).T)])) == 2
    out, mask = correct_defects(data, pattern, return_mask=True)
    assert set(zip(*np.nonzero(mask))) == set(sites)
    fixed = out[tuple(np.array(sites).T)].astype(int)
    assert np.all(np.abs(fixed - original) < 120)
    untouched = ~mask
    np.testing.assert_array_equal(out[untouched], data[untouched])
    assert data[sites[0]] in (0, 2047)                              # input not modified


def test_defect_correction_never_reads_z_sites():
    pattern = rz.mask2()
    frame = simulate(Scene.from_rgb(_smooth_scene()), pattern, seed=4)
    data = frame.data.copy()
    data[30, 30] = 2047                                            # one real defect
    garbage = data.copy()
    z = frame.z_mask
    garbage[z] = np.random.default_rng(0).integers(0, 65535, int(z.sum()))
    a, ma = correct_defects(data, pattern, return_mask=True)
    b, mb = correct_defects(garbage, pattern, return_mask=True)
    np.testing.assert_array_equal(ma, mb)
    assert ma[30, 30] and not ma[z].any()
    np.testing.assert_array_equal(a[~z], b[~z])
    np.testing.assert_array_equal(b[z], garbage[z])                # Z sites passed through
    # and the whole chain ignores them too
    chain = ColourISP()
    np.testing.assert_array_equal(chain.run(data, pattern=pattern, black_level=64),
                                  chain.run(garbage, pattern=pattern, black_level=64))


def test_tiny_frames_and_lonely_pixels_are_left_alone():
    data = np.array([[100, 2000], [5, 1000]], np.uint16)       # no same-colour neighbour
    out, mask = correct_defects(data, "bayer", return_mask=True)
    assert not mask.any()
    np.testing.assert_array_equal(out, data)
    img = ColourISP().run(data, pattern="bayer")
    assert img.shape == (2, 2, 3)


def test_known_defects_and_disabled_stage():
    data = rz.mosaic(_smooth_scene(), "bayer").data
    known = np.zeros(data.shape, bool)
    known[10, 10] = True
    out, mask = correct_defects(data, "bayer", DefectCorrection(enabled=False), known=known,
                                return_mask=True)
    assert mask.sum() == 1 and abs(int(out[10, 10]) - int(data[10, 10])) < 40
    same, m2 = correct_defects(data, "bayer", DefectCorrection(enabled=False),
                               return_mask=True)
    assert not m2.any() and same is not data
    np.testing.assert_array_equal(same, data)


@pytest.mark.parametrize("pattern", ["bayer", "mask1", "mask2", "rows", "ZR/BG", "ZRGG/BGBZ",
                                     "RGZ/GBG/ZRB"])
@pytest.mark.parametrize("dtype", [np.uint16, np.float32, np.float64])
def test_defect_correction_equals_the_pixel_by_pixel_reference(pattern, dtype):
    """The per-position implementation (contiguous sub-images, no full-frame
    temporaries) against the pixel-by-pixel reference of tests/_reference/defects.py:
    the same defect map and the same corrected values, bit for bit, on noisy frames
    with planted hot, cold and clustered defects, known defects, other thresholds,
    and frames smaller than or barely larger than a period."""
    rng = np.random.default_rng(11)
    pat = rz.get_pattern(pattern)
    for shape in ((37, 53), (12, 12), (5, 7), (2, 3), (1, 4)):
        try:
            pat.check_shape(shape, "cfa")
        except ValueError:
            continue
        data = np.clip(rng.normal(900, 40, shape), 0, 2047)
        n = max(1, data.size // 40)
        r, c = rng.integers(0, shape[0], n), rng.integers(0, shape[1], n)
        data[r, c] = rng.choice([0.0, 2047.0, 1500.0], n)
        data[r[:2], np.minimum(c[:2] + 1, shape[1] - 1)] = 2047.0      # a cluster
        data = data.astype(dtype) if dtype != np.uint16 else np.round(data).astype(dtype)
        known = rng.random(shape) < 0.01
        for params, kn in ((DefectCorrection(), None), (DefectCorrection(), known),
                           (DefectCorrection(threshold=0.02, spread_factor=0.5,
                                             cross_factor=0.25), None)):
            got = correct_defects(data, pat, params, known=kn, return_mask=True)
            want = reference_correct_defects(data, pat, params, known=kn, return_mask=True)
            np.testing.assert_array_equal(got[1], want[1], err_msg=f"{shape} {params}")
            np.testing.assert_array_equal(got[0], want[0], err_msg=f"{shape} {params}")
            assert got[0].dtype == data.dtype


def test_defect_correction_equals_the_reference_on_a_simulated_frame():
    frame = simulate(Scene.from_rgb(load_kodak(19, crop=(120, 160))), "mask2", seed=5)
    data = frame.data.copy()
    data[::17, ::13] = 2047
    got = correct_defects(data, "mask2", white_level=2047, return_mask=True)
    want = reference_correct_defects(data, "mask2", white_level=2047, return_mask=True)
    assert got[1].sum() > 20
    np.testing.assert_array_equal(got[1], want[1])
    np.testing.assert_array_equal(got[0], want[0])


# ----------------------------------------------------------------------- pieces
def test_srgb_oetf_is_the_standard_curve():
    v = np.array([0.0, 0.0031308, 0.01, 0.18, 0.5, 1.0, 1.5, -0.2])
    want = np.where(np.clip(v, 0, 1) <= 0.0031308, 12.92 * np.clip(v, 0, 1),
                    1.055 * np.clip(v, 0, 1) ** (1 / 2.4) - 0.055)
    np.testing.assert_allclose(srgb_oetf(v), want, rtol=1e-15)
    assert srgb_oetf(np.float32([0.5])).dtype == np.float32
    # 128/255 in sRGB is 0.2158605 linear
    np.testing.assert_array_equal(srgb_encode(np.array([0.0, 1.0, 0.2158605, 0.2140])),
                                  [0, 255, 128, 127])
    assert srgb_encode(np.array([1.0]), 16)[0] == 65535


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_srgb_oetf_equals_the_plain_formula_bit_for_bit(dtype):
    """srgb_oetf keeps the linear segment's inputs (zeros above all) out of np.power;
    the result is the plain two-branch formula to the last bit."""
    rng = np.random.default_rng(5)
    v = rng.random(200_003).astype(dtype) * dtype(1.2) - dtype(0.1)
    v[rng.random(v.size) < 0.2] = 0
    v[rng.random(v.size) < 0.05] = dtype(0.0031308)
    c = np.clip(v, 0, 1)
    t = np.dtype(dtype).type
    want = np.power(c, t(1 / 2.4))
    want *= t(1.055)
    want -= t(0.055)
    want = np.where(c <= t(0.0031308), c * t(12.92), want)
    got = srgb_oetf(v)
    assert got.dtype == dtype
    np.testing.assert_array_equal(got, want)


def test_colour_correction_matrix():
    rgb = np.random.default_rng(0).random((4, 5, 3)).astype(np.float32) * 0.5
    np.testing.assert_array_equal(correct_colour(rgb), rgb)
    m = ((1.2, -0.1, -0.1), (-0.2, 1.3, -0.1), (0.0, -0.3, 1.3))
    got = correct_colour(rgb, ColourCorrection(matrix=m))
    np.testing.assert_allclose(got, np.clip(rgb @ np.array(m).T, 0, 1), rtol=1e-6)
    assert got.dtype == np.float32


def test_parameters_are_frozen_hashable_and_picklable():
    chain = ColourISP(reconstruction=Reconstruction("edi_line", {"sigma_floor": 0.01}))
    assert chain.reconstruction.params == rz.ReconstructParams(sigma_floor=0.01)
    hash(chain)
    assert pickle.loads(pickle.dumps(chain)) == chain
    with pytest.raises(AttributeError):
        chain.output_bits = 16


def test_reconstruction_options_reach_reconstruct(sim_frame):
    a = fill_missing(sim_frame.data, "mask1", Reconstruction("bilinear"))
    b = rz.reconstruct(sim_frame, "bilinear")
    np.testing.assert_array_equal(a, b)
    c = fill_missing(sim_frame.data, "mask1", Reconstruction(
        "sg", rz.ReconstructParams(precision="float64", sg_mode="combined")))
    np.testing.assert_array_equal(c, rz.reconstruct(sim_frame, "sg", precision="float64",
                                                    sg_mode="combined"))


def test_stages_take_params_and_keyword_overrides(sim_frame):
    """The parameter rule of every stage: ``params=`` plus keyword overrides of its fields,
    the same result as the object with those fields; unknown names are a TypeError."""
    cfa = rz.reconstruct(sim_frame, "sg")
    np.testing.assert_array_equal(
        white_balance(cfa, "GRBG", clip=False, method="none")[0],
        white_balance(cfa, "GRBG", WhiteBalance(method="none", clip=False))[0])
    np.testing.assert_array_equal(
        white_balance(cfa, "GRBG", WhiteBalance(method="none"), clip=False)[0],
        white_balance(cfa, "GRBG", {"method": "none", "clip": False})[0])
    m = ((1.2, -0.1, -0.1), (-0.2, 1.3, -0.1), (0.0, -0.3, 1.3))
    rgb = np.random.default_rng(0).random((4, 5, 3))
    np.testing.assert_array_equal(correct_colour(rgb, matrix=m),
                                  correct_colour(rgb, ColourCorrection(matrix=m)))
    np.testing.assert_array_equal(detect_defects(sim_frame.data, "mask1", threshold=0.02),
                                  detect_defects(sim_frame.data, "mask1",
                                                 DefectCorrection(threshold=0.02)))
    np.testing.assert_array_equal(fill_missing(sim_frame.data, "mask1", method="bi"),
                                  rz.reconstruct(sim_frame, "bi"))
    with pytest.raises(TypeError, match=r"^white_balance\(\) got an unexpected keyword "
                                        r"argument 'gain' \(fields of WhiteBalance: "):
        white_balance(cfa, "GRBG", gain=(1, 1, 1))
    with pytest.raises(ValueError, match="^DefectCorrection.threshold"):
        correct_defects(sim_frame.data, "mask1", threshold=2)


def test_colour_isp_takes_stage_dicts_and_overrides():
    """A stage field takes a dict of the stage's fields (over the stage's defaults);
    build/replace override fields of a chain, a dict changing some fields of its stage."""
    assert ColourISP(demosaicing={"method": "menon2007"}) == ColourISP(
        demosaicing=Demosaic(method="menon2007"))
    base = ColourISP(white_balance=WhiteBalance(method="none"), precision="float64")
    changed = base.replace(white_balance={"clip": False}, output_bits=16)
    assert changed.white_balance == WhiteBalance(method="none", clip=False)
    assert (changed.precision, changed.output_bits) == ("float64", 16)
    assert ColourISP.build(base, {"white_balance": WhiteBalance()}).white_balance == \
        WhiteBalance()
    assert ColourISP.build(None, {"precision": "float64"}) == ColourISP(precision="float64")
    assert ColourISP.build(base) is base
    with pytest.raises(TypeError, match=r"^ColourISP.replace\(\) got an unexpected keyword "
                                        r"argument 'demosaic'"):
        base.replace(demosaic="menon2007")
    with pytest.raises(TypeError, match=r"^ColourISP.white_balance got an unexpected keyword "
                                        r"argument 'gain'"):
        base.replace(white_balance={"gain": 2})
    with pytest.raises(ValueError, match="^Demosaic.method"):
        ColourISP(demosaicing={"method": "ahd"})
    with pytest.raises(TypeError, match="^ColourISP.defects: expected DefectCorrection"):
        ColourISP(defects=None)


def test_the_colour_isp_does_not_reexport_the_tof_isp():
    """One home per name: the ToF ISP is rgbz_fast.tof (and rgbz_fast.tof_depth)."""
    from rgbz_fast.tof import ToFISP, tof_depth
    assert not hasattr(isp, "ToFISP") and rz.ToFISP is ToFISP and rz.tof_depth is tof_depth


# ----------------------------------------------------------------------- bad input
@pytest.mark.parametrize("make,exc,name", [
    (lambda: DefectCorrection(threshold=0), ValueError, "threshold"),
    (lambda: DefectCorrection(threshold=float("nan")), ValueError, "threshold"),
    (lambda: DefectCorrection(enabled=1), TypeError, "enabled"),
    (lambda: Reconstruction(params={"precision": "float16"}), ValueError, "precision"),
    (lambda: Reconstruction(params={"workers": 2}), TypeError, "params"),
    (lambda: Reconstruction(params=3), TypeError, "params"),
    (lambda: Reconstruction(method="nope"), ValueError, "method"),
    (lambda: WhiteBalance(method="retinex"), ValueError, "method"),
    (lambda: WhiteBalance(gains=(1, 0, 1)), ValueError, "gains"),
    (lambda: WhiteBalance(gains=(1, 1)), ValueError, "gains"),
    (lambda: Demosaic(method="ahd"), ValueError, "method"),
    (lambda: Demosaic(mode="wrap"), ValueError, "mode"),
    (lambda: ColourCorrection(matrix=np.eye(4)), ValueError, "matrix"),
    (lambda: ColourCorrection(matrix=[[1, 0, 0], [0, np.inf, 0], [0, 0, 1]]), ValueError,
     "matrix"),
    (lambda: ColourISP(output_bits=12), ValueError, "output_bits"),
    (lambda: ColourISP(precision="half"), ValueError, "precision"),
    (lambda: ColourISP(black_level=-1), ValueError, "black_level"),
    (lambda: ColourISP(demosaicing="malvar2004"), TypeError, "demosaicing"),
])
def test_bad_parameters_name_themselves(make, exc, name):
    with pytest.raises(exc, match=name):
        make()


def test_bad_run_input(sim_frame):
    chain = ColourISP()
    with pytest.raises(TypeError, match="pattern"):
        chain.run(sim_frame.data)
    with pytest.raises(ValueError, match="pattern"):
        chain.run(sim_frame, pattern="mask2")
    with pytest.raises(ValueError, match="reference"):
        chain.run(rz.mosaic(_smooth_scene(), "mask1"), reference=True)
    with pytest.raises(ValueError, match="frame"):
        chain.run(np.zeros((8, 8, 3), np.uint16), pattern="bayer")
    with pytest.raises(ValueError, match="^frame: values span"):
        chain.run(np.full((8, 8), 5000, np.uint16), pattern="bayer")
    with pytest.raises(ValueError, match="gains"):
        chain.run(sim_frame, gains=(1, -1, 1))
    with pytest.raises(ValueError, match="black_level"):
        chain.run(sim_frame, black_level=4000)
    with pytest.raises(TypeError, match="frame"):
        chain.run_pair(sim_frame.data)
    with pytest.raises(ValueError, match="known"):
        correct_defects(sim_frame.data, "mask1", known=np.zeros((3, 3), bool))
    with pytest.raises(ValueError, match="phase"):
        white_balance(sim_frame.data, "mask1")
    with pytest.raises(ValueError, match="bits"):
        srgb_encode(np.zeros(3), 12)
    with pytest.raises(ValueError, match="rgb"):
        correct_colour(np.zeros((4, 4, 4)))


@pytest.mark.slow
def test_defect_detection_on_the_kodak_set(request):
    """False positives (noise-free and noisy) and detection of planted defects, 24 images.

    About 30 s, so it runs only when asked for (``-m slow``). Prints the numbers quoted
    in docs/reports/isp.md: ``pytest tests/isp/test_isp.py -m slow -k kodak_set -s``.
    """
    if "slow" not in (request.config.getoption("markexpr") or ""):
        pytest.skip("full Kodak run: select it with -m slow")
    shared = load_kodak(1)                                   # skips without the data
    assert shared.shape[2] == 3
    rng = np.random.default_rng(0)
    print()
    for name in ("bayer", "mask1", "mask2"):
        pattern = rz.get_pattern(name)
        free = noisy = found = planted = 0
        for n in range(1, 25):
            img = load_kodak(n)
            clean = rz.mosaic(img, pattern).data
            frame = simulate(Scene.from_rgb(img), pattern, seed=n).data
            free += int(detect_defects(clean, pattern).sum())
            noisy += int(detect_defects(frame, pattern).sum())
            z = pattern.z_mask(clean.shape)
            rr = rng.integers(0, clean.shape[0], 300)
            cc = rng.integers(0, clean.shape[1], 300)
            keep = ~z[rr, cc]
            rr, cc = rr[keep], cc[keep]
            data = frame.copy()
            kind = rng.integers(0, 3, rr.size)
            vals = np.where(kind == 0, 2047, np.where(
                kind == 1, 0, np.clip(frame[rr, cc].astype(int) + 600, 0, 2047)))
            data[rr, cc] = vals
            big = np.abs(vals - frame[rr, cc].astype(int)) > 500
            found += int(detect_defects(data, pattern)[rr, cc][big].sum())
            planted += int(big.sum())
        print(f"{name}: flagged on noise-free {free}, on noisy {noisy} (of "
              f"{24 * clean.size} pixels); planted defects > 500 DN found "
              f"{found}/{planted} = {found / planted:.3f}")
        assert free <= 40 and noisy <= 120 and found / planted > 0.6


def test_a_cfa_mostly_above_its_white_level_is_warned_about():
    """H81: a CFA whose values mostly exceed 2**bit_depth - 1 (an 11-bit CFA rendered with
    bit_depth=8) renders nearly white: render and white_balance_gains warn, naming the CFA;
    a few saturated pixels do not."""
    cfa = np.tile(np.array([[800, 400], [300, 800]], np.uint16), (4, 4))
    chain = ColourISP()
    with pytest.warns(UserWarning, match=r"cfa: 100 % of the pixels are above the white level "
                                         r"255 DN \(bit_depth=8\)"):
        chain.render(cfa, "GRBG", bit_depth=8)
    with pytest.warns(UserWarning, match="is bit_depth the CFA's"):
        chain.white_balance_gains(cfa, "GRBG", bit_depth=8)
    few = cfa.copy()
    few[0, :3] = 2047
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        chain.render(few, "GRBG", bit_depth=11)
