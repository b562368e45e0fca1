"""The fused colour chain (csrc/colour_isp.c, isp/_fused.py) against the stages.

``ColourISP.run(frame)`` and ``render(cfa)`` without stages run the C passes; with
``return_stages`` they run the NumPy stages (the bilinear demosaic's stage is itself a C
kernel, held to colour-demosaicing bit for bit in test_demosaic.py). Menon 2007 runs its own
kernel (the stage's) between the C white balance (ci_balance) and the render's C tail
(ci_encode_rgb), which the tests hold to the stages as the row pass of Malvar and bilinear.
Tolerance: none (the same codes) on integer
CFAs with the identity colour matrix, the library's default; with a colour matrix one code
where NumPy's matmul rounds the linear value differently (a few ulp). The NumPy reference
of tests/_reference/colour_isp.py (colour-demosaicing's Malvar, np.power) agrees to one code.
"""

from __future__ import annotations

import numpy as np
import pytest
from _reference.colour_isp import reference_render

import rgbz_fast as rz
from rgbz_fast import _kernels
from rgbz_fast.isp import ColourISP, DefectCorrection
from rgbz_fast.isp import _defects, _fused
from rgbz_fast.isp._encode_table import encode_by_table, encode_thresholds
from rgbz_fast.isp._stages import grey_world_gains


def _image(shape, seed=0):
    """A textured linear image in [0, 1]: smooth colour, fine detail and saturated patches."""
    rng = np.random.default_rng(seed)
    rr, cc = np.mgrid[0:shape[0], 0:shape[1]] / max(shape)
    img = np.stack([0.4 + 0.4 * np.sin(9 * rr + 1), 0.5 + 0.4 * np.cos(7 * cc),
                    0.3 + 0.3 * np.sin(5 * rr + 8 * cc)], axis=-1)
    img += rng.normal(0, 0.02, img.shape)
    img[: shape[0] // 6, : shape[1] // 5] = 1.0                       # saturated highlights
    return np.clip(img, 0, 1)


def _frame(pattern, shape=(60, 84), seed=0, defects=40):
    """A mosaic with hot and cold pixels planted on colour sites (so the defect pass has
    work), as a RawFrame with its black level."""
    fr = rz.mosaic(_image(shape, seed), pattern)
    data = fr.data.copy()
    rng = np.random.default_rng(seed + 1)
    ok = np.argwhere(~fr.z_mask)
    pick = ok[rng.choice(len(ok), defects, replace=False)]
    data[pick[: defects // 2, 0], pick[: defects // 2, 1]] = 2047
    data[pick[defects // 2:, 0], pick[defects // 2:, 1]] = 0
    return data, fr.pattern


def _both(chain, data, pattern, **kw):
    fused = chain.run(data, pattern=pattern, **kw)
    staged = chain.run(data, pattern=pattern, return_stages=True, **kw)[0]
    return fused, staged


@pytest.mark.parametrize("pattern", ["bayer", "mask1", "mask2"])
@pytest.mark.parametrize("precision", ["float32", "float64"])
@pytest.mark.parametrize("bits", [8, 16])
@pytest.mark.parametrize("demosaicing", [{}, {"method": "bilinear"},
                                         {"method": "bilinear", "mode": "period"},
                                         {"method": "menon2007"},
                                         {"method": "menon2007", "mode": "period"}])
def test_run_is_the_stages(pattern, precision, bits, demosaicing):
    data, pat = _frame(pattern)
    chain = ColourISP(precision=precision, output_bits=bits, black_level=40,
                      demosaicing=demosaicing)
    assert chain._fused(data)
    fused, staged = _both(chain, data, pat)
    assert fused.dtype == staged.dtype and fused.shape == staged.shape
    np.testing.assert_array_equal(fused, staged)


@pytest.mark.parametrize("changes", [
    {"demosaicing": {"mode": "period"}},
    {"white_balance": {"clip": False}},
    {"white_balance": {"method": "none"}},
    {"white_balance": {"gains": (1.5, 1.0, 2.25)}},
    {"defects": {"enabled": False}},
    {"defects": {"threshold": 0.02, "spread_factor": 0.5}},
])
@pytest.mark.parametrize("method", ["malvar2004", "menon2007"])
def test_run_is_the_stages_for_every_setting(changes, method):
    data, pat = _frame("mask1", seed=2)
    chain = ColourISP(demosaicing={"method": method}).replace(**changes)
    fused, staged = _both(chain, data, pat)
    np.testing.assert_array_equal(fused, staged)


@pytest.mark.parametrize("shape", [(2, 2), (3, 5), (5, 2), (7, 9), (13, 11)])
@pytest.mark.parametrize("method", ["malvar2004", "bilinear", "menon2007"])
def test_small_and_odd_frames(shape, method):
    rng = np.random.default_rng(sum(shape))
    data = rng.integers(0, 2048, shape).astype(np.uint16)
    for mode in ("reflect", "period"):
        chain = ColourISP(demosaicing={"method": method, "mode": mode})
        fused, staged = _both(chain, data, "bayer")
        np.testing.assert_array_equal(fused, staged)
        # gains that clip much of red and blue, the last column of an odd width too
        fused, staged = _both(chain, data, "bayer", gains=(2.2, 1.0, 2.6))
        np.testing.assert_array_equal(fused, staged)


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
@pytest.mark.parametrize("method", ["malvar2004", "menon2007"])
def test_every_frame_type(dtype, method):
    data, pat = _frame("mask1", seed=4)
    bits = 8 if dtype == np.uint8 else 11
    cfa = (data >> 3).astype(dtype) if dtype == np.uint8 else data.astype(dtype)
    chain = ColourISP(demosaicing={"method": method})
    fused, staged = _both(chain, cfa, pat, bit_depth=bits)
    if np.issubdtype(dtype, np.floating):
        # grey-world sums of floats in another order: gains a few ulp apart
        assert np.max(np.abs(fused.astype(int) - staged)) <= 1
        assert np.mean(fused != staged) < 1e-3
    else:
        np.testing.assert_array_equal(fused, staged)
    # given gains: the same white balance, so the same codes on every type
    fused, staged = _both(chain, cfa, pat, bit_depth=bits, gains=(1.7, 1.0, 1.3))
    np.testing.assert_array_equal(fused, staged)


@pytest.mark.parametrize("method", ["malvar2004", "menon2007"])
def test_known_defects_and_given_gains(method):
    data, pat = _frame("mask2", seed=5)
    known = np.zeros(data.shape, bool)
    known[10:14, 20:23] = True
    chain = ColourISP(demosaicing={"method": method})
    kw = {"defects": known, "gains": (2.0, 1.0, 1.5), "black_level": 12}
    fused, staged = _both(chain, data, pat, **kw)
    np.testing.assert_array_equal(fused, staged)


@pytest.mark.parametrize("method", ["malvar2004", "menon2007"])
def test_render_is_the_stages(method):
    data, _ = _frame("bayer", seed=6)
    chain = ColourISP(output_bits=16, demosaicing={"method": method})
    np.testing.assert_array_equal(chain.render(data, "GRBG"),
                                  chain.render(data, "GRBG", return_stages=True)[0])


@pytest.mark.parametrize("phase", ["GRBG", "RGGB", "BGGR", "GBRG"])
@pytest.mark.parametrize("mode", ["reflect", "period"])
@pytest.mark.parametrize("precision", ["float32", "float64"])
@pytest.mark.parametrize("bits", [8, 16])
def test_menon_every_phase_and_border(phase, mode, precision, bits):
    """Menon 2007's fused path (C white balance, Menon's kernel, C tail) on a Bayer frame
    read in each phase: the stages' image, run and render."""
    data, _ = _frame("bayer", shape=(46, 62), seed=14)
    chain = ColourISP(demosaicing={"method": "menon2007", "mode": mode}, precision=precision,
                      output_bits=bits, black_level=24)
    assert chain._fused(data)
    fused, staged = _both(chain, data, phase)
    np.testing.assert_array_equal(fused, staged)
    np.testing.assert_array_equal(chain.render(data, phase, gains=(1.9, 1.0, 1.4)),
                                  chain.render(data, phase, gains=(1.9, 1.0, 1.4),
                                               return_stages=True)[0])


@pytest.mark.parametrize("method", ["malvar2004", "menon2007"])
@pytest.mark.parametrize("precision", ["float32", "float64"])
def test_colour_matrix_within_one_code(method, precision):
    data, pat = _frame("mask1", seed=7)
    m = ((1.6, -0.4, -0.2), (-0.3, 1.5, -0.2), (0.0, -0.5, 1.5))
    for bits in (8, 16):
        chain = ColourISP(colour_correction={"matrix": m}, output_bits=bits,
                          demosaicing={"method": method}, precision=precision)
        fused, staged = _both(chain, data, pat)
        diff = np.abs(fused.astype(np.int64) - staged)
        assert diff.max() <= 1 and np.mean(diff > 0) < 1e-3


def test_menon_identity_matrix_is_exact():
    """An explicit identity matrix runs the C tail's matrix and NumPy's matmul: both exact."""
    data, pat = _frame("mask2", seed=15)
    chain = ColourISP(colour_correction={"matrix": tuple(map(tuple, np.eye(3)))},
                      demosaicing={"method": "menon2007"})
    fused, staged = _both(chain, data, pat)
    np.testing.assert_array_equal(fused, staged)


def test_menon_white_balance_beyond_the_precision():
    """A float64 CFA beyond float32's range in a float32 chain: the stage balances in float64
    (its _fits), and so does Menon's fused path (it hands the white balance to the stage)."""
    data, _ = _frame("bayer", shape=(20, 24), seed=16)
    cfa = data.astype(np.float64)
    cfa[5, 7] = 1e39
    chain = ColourISP(demosaicing={"method": "menon2007"})
    np.testing.assert_array_equal(chain.render(cfa, "GRBG"),
                                  chain.render(cfa, "GRBG", return_stages=True)[0])


@pytest.mark.parametrize("method", ["malvar2004", "bilinear", "menon2007"])
def test_thread_count_does_not_change_the_image(method):
    data, pat = _frame("mask1", shape=(1030, 520), seed=8)       # two threads' worth
    chain = ColourISP(demosaicing={"method": method})
    np.testing.assert_array_equal(chain.run(data, pattern=pat, workers=1),
                                  chain.run(data, pattern=pat, workers=2))


def test_menon_takes_the_fused_path(monkeypatch):
    """run and render of a Menon 2007 chain go through _fused.render (C white balance,
    Menon's kernel, C tail), not through the stages."""
    data, pat = _frame("bayer", shape=(20, 24))
    chain = ColourISP(demosaicing={"method": "menon2007"})
    assert chain._fused(data)
    calls = []
    monkeypatch.setattr(_kernels, "ci_encode_rgb",
                        lambda *a, _f=_kernels.ci_encode_rgb: calls.append(1) or _f(*a))
    monkeypatch.setattr(ColourISP, "_render", lambda *a, **k: pytest.fail("the stages ran"))
    chain.run(data, pattern=pat)
    chain.render(data, "GRBG")
    assert len(calls) == 2


@pytest.mark.parametrize("pattern", ["bayer", "mask1", "mask2"])
def test_defect_candidates_are_the_numpy_ones(pattern):
    data, pat = _frame(pattern, seed=9, defects=60)
    params = DefectCorrection(threshold=0.05, spread_factor=0.8)
    want = _defects._candidates(data, pat.tile, params, 2047)
    got = _fused._candidates(np.ascontiguousarray(data), pat.tile, params, 2047, 2)
    assert want[0].size > 30

    def table(c):
        order = np.lexsort((c[1], c[0]))
        return [np.asarray(a)[order] for a in c]
    for a, b in zip(table(got), table(want)):
        np.testing.assert_array_equal(a, b)


def test_defect_candidates_beyond_the_first_room(monkeypatch):
    data, pat = _frame("bayer", seed=10, defects=200)
    params = DefectCorrection(threshold=0.05, spread_factor=0.5)
    monkeypatch.setattr(_fused, "_CANDIDATE_ROOM", 8)
    got = _fused._candidates(data, pat.tile, params, 2047, 1)
    assert got[0].size == _defects._candidates(data, pat.tile, params, 2047)[0].size > 8


def _all_candidates(data, tile, rng):
    """Candidates for test 3 at every colour pixel of a small frame (its own pixels at the
    borders too), with random test-1 and test-2 values around the thresholds."""
    P, Q = tile.shape
    rr, cc = np.nonzero(tile[np.arange(data.shape[0])[:, None] % P,
                             np.arange(data.shape[1])[None, :] % Q] != rz.Z)
    n = rr.size
    hot, cold, spread = (rng.uniform(0, 400, n).astype(np.float32) for _ in range(3))
    return rr.astype(np.intp), cc.astype(np.intp), hot, cold, spread


@pytest.mark.parametrize("pattern", ["bayer", "mask1", "mask2", "rows"])
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
@pytest.mark.parametrize("cross", [0.0, 0.1, 0.7])
def test_defect_test3_is_the_numpy_one(pattern, dtype, cross):
    # the C test 3 (ci_defect_confirm) against _defects._confirm: every colour pixel of small
    # frames as a candidate (the borders, Z neighbours, neighbourhoods of 1, 2 or more pixels);
    # float frames with NaN and inf pixels and values whose sums round
    rng = np.random.default_rng(hash((pattern, np.dtype(dtype).name, cross)) % 2**32)
    pat = rz.get_pattern(pattern)
    for shape in ((5, 7), (12, 16), (23, 18)):
        if np.issubdtype(dtype, np.integer):
            top = np.iinfo(dtype).max
            data = rng.integers(0, top + 1, shape).astype(dtype)
            data[rng.random(shape) < 0.1] = top
        else:
            data = (rng.random(shape) * 10.0 ** rng.integers(-9, 4, shape)).astype(dtype)
            data[rng.random(shape) < 0.03] = np.nan
            data[rng.random(shape) < 0.02] = np.inf
        params = DefectCorrection(threshold=0.05, spread_factor=0.8, cross_factor=cross)
        cands = _all_candidates(data, pat.tile, rng)
        want = _defects._confirm(data, pat.tile, params, 100.0, cands)
        got = _fused._confirmed(np.ascontiguousarray(data), pat.tile, params, 100.0, cands)
        for a, b in zip(got, want):
            np.testing.assert_array_equal(a, b)


def test_defect_test3_rejects_bad_arguments():
    data, pat = _frame("bayer", shape=(12, 12), seed=3)
    noff, offs = _fused._tile_neighbours(np.ascontiguousarray(pat.tile, np.int64).tobytes(),
                                         pat.tile.shape)
    one = np.ones(1, np.float32)
    ok = np.zeros(1, np.uint8)
    with pytest.raises(ValueError, match="ci_defect_confirm"):
        _kernels.ci_defect_confirm(data, noff, offs, np.zeros(2, np.int64), np.zeros(1, np.int64),
                                   one, one, one, 1.0, 1.0, 0.1, ok)
    with pytest.raises(RuntimeError, match="rejected its arguments"):   # outside the frame
        _kernels.ci_defect_confirm(data, noff, offs, np.array([12], np.int64),
                                   np.zeros(1, np.int64), one, one, one, 1.0, 1.0, 0.1, ok)


@pytest.mark.parametrize("dtype", [np.uint16, np.float32, np.float64])
def test_phase_sums_give_the_grey_world_gains(dtype):
    data, pat = _frame("bayer", seed=11)
    cfa = data.astype(dtype)
    want = grey_world_gains(cfa, "GRBG", black_level=30, white_level=2047)
    got = _fused.gains(cfa, pat, ColourISP().white_balance, 30.0, 2047.0, None, 2)
    if dtype == np.uint16:
        np.testing.assert_array_equal(got, want)
    else:
        np.testing.assert_allclose(got, want, rtol=1e-13)


@pytest.mark.parametrize("bits", [8, 16])
@pytest.mark.parametrize("precision", [np.float32, np.float64])
def test_render_against_the_numpy_reference(bits, precision):
    data, pat = _frame("bayer", seed=12, defects=0)
    gains = (1.7, 1.0, 1.3)
    m = ((1.2, -0.1, -0.1), (-0.1, 1.2, -0.1), (0.0, -0.2, 1.2))
    chain = ColourISP(colour_correction={"matrix": m}, output_bits=bits, precision=precision.__name__,
                      defects={"enabled": False})
    got = chain.render(data, "GRBG", black_level=20, gains=gains)
    want = reference_render(data, "GRBG", black=20.0, white=2047.0, gains=gains, matrix=m,
                            bits=bits, dtype=precision)
    diff = np.abs(got.astype(np.int64) - want)
    assert diff.max() <= 1 and np.mean(diff > 0) < 1e-3


def test_kernel_rejects_inconsistent_shapes():
    cfa = np.zeros((4, 4), np.uint16)
    out = np.zeros((4, 4, 3), np.uint8)
    with pytest.raises(ValueError, match="ci_render"):
        _kernels.ci_render(cfa, np.array([1, 0, 2, 1], np.int32), 0, np.ones(3, np.float32),
                           np.float32(0), 1, np.zeros(0, np.float32), np.zeros(16, np.float32),
                           out, 1)


def test_tail_kernels_reject_inconsistent_shapes():
    phase = np.array([1, 0, 2, 1], np.int32)
    cfa = np.zeros((4, 4), np.uint16)
    t8 = np.array(encode_thresholds(np.dtype(np.float32), 8))
    rgb = np.zeros((4, 4, 3), np.float32)
    none = np.zeros(0, np.float32)
    for bad in ((cfa, phase[:3], np.ones(3, np.float32), np.zeros((4, 4), np.float32)),
                (cfa, phase, np.ones(2, np.float32), np.zeros((4, 4), np.float32)),
                (cfa, phase, np.ones(3, np.float32), np.zeros((4, 5), np.float32))):
        with pytest.raises(ValueError, match="ci_balance"):
            _kernels.ci_balance(bad[0], bad[1], bad[2], np.float32(0), 1, bad[3], 1)
    for bad in ((rgb, none, t8[:16], np.zeros((4, 4, 3), np.uint8)),           # table size
                (rgb, np.ones(4, np.float32), t8, np.zeros((4, 4, 3), np.uint8)),
                (rgb, none, t8, np.zeros((4, 3, 3), np.uint8)),
                (np.zeros((4, 4, 2), np.float32), none, t8, np.zeros((4, 4, 3), np.uint8)),
                (rgb, none, t8, np.zeros((4, 4, 3), np.uint16))):           # 16 bits, 8's table
        with pytest.raises(ValueError, match="ci_encode_rgb"):
            _kernels.ci_encode_rgb(*bad, 1)
    # a table that is not one (decreasing): the C check
    with pytest.raises(RuntimeError, match="rejected its arguments"):
        _kernels.ci_encode_rgb(rgb, none, t8[::-1].copy(), np.zeros((4, 4, 3), np.uint8), 1)


@pytest.mark.parametrize("precision", [np.float32, np.float64])
@pytest.mark.parametrize("bits", [8, 16])
def test_encode_rgb_is_the_table(precision, bits):
    """ci_encode_rgb on values around every threshold, odd pixel counts and several chunks:
    encode_by_table's codes (the stages' _encode), and clip(M @ rgb) within one code."""
    t = encode_thresholds(np.dtype(precision), bits)
    near = np.concatenate([t, np.nextafter(t, precision(-1)), [-0.5, -0.0, 1.0, 1.5, 2.0]])
    rng = np.random.default_rng(bits)
    v = rng.permutation(np.concatenate([near, rng.random(30001)]).astype(precision))
    rgb = v[: v.size // 3 * 3 - 3 * 7].reshape(-1, 1, 3)            # an odd number of pixels
    code = np.uint8 if bits == 8 else np.uint16
    for workers in (1, 2):
        out = np.empty(rgb.shape, code)
        _kernels.ci_encode_rgb(rgb, np.zeros(0, precision), t, out, workers)
        np.testing.assert_array_equal(out, encode_by_table(rgb, bits))
    m = np.array([[1.6, -0.4, -0.2], [-0.3, 1.5, -0.2], [0.0, -0.5, 1.5]], precision)
    out = np.empty(rgb.shape, code)
    _kernels.ci_encode_rgb(rgb, m.reshape(-1), t, out, 1)
    want = encode_by_table(np.matmul(rgb, m.T), bits)
    assert np.abs(out.astype(np.int64) - want).max() <= 1


@pytest.mark.parametrize("method", ["malvar2004", "menon2007"])
def test_recorded_gains_and_matrix_of_a_frame(method):
    """A frame's as-shot gains and colour matrix (its meta) reach the fused path as the
    stages: the same gains; the matrix within one code (NumPy's matmul)."""
    data, pat = _frame("mask1", seed=13)
    m = (1.5, -0.3, -0.2, -0.2, 1.4, -0.2, 0.0, -0.4, 1.4)
    frame = rz.RawFrame(data, pat, 11, meta={"white_gains": (1.8, 1.0, 1.4),
                                             "colour_matrix": m, "colour_black_level": 16.0})
    chain = ColourISP(demosaicing={"method": method})
    fused = chain.run(frame)
    staged, st = chain.run(frame, return_stages=True)
    np.testing.assert_array_equal(st["gains"], [1.8, 1.0, 1.4])
    diff = np.abs(fused.astype(np.int64) - staged)
    assert diff.max() <= 1 and np.mean(diff > 0) < 1e-3
    cfa = st["reconstruction"]
    a = chain.render(cfa, "GRBG", gains=(1.8, 1.0, 1.4), colour_matrix=np.reshape(m, (3, 3)))
    b = chain.render(cfa, "GRBG", gains=(1.8, 1.0, 1.4), colour_matrix=np.reshape(m, (3, 3)),
                     return_stages=True)[0]
    assert np.abs(a.astype(np.int64) - b).max() <= 1


def test_a_frame_saturating_below_full_scale_renders_its_saturation_white():
    """A sensor whose well fills below the ADC's top (and a raw file's clip level): the chain
    had taken 2**bit_depth - 1 as white, so grey world counted the saturated pixels (a grey
    card came out tinted) and a blown highlight rendered grey."""
    from rgbz_fast.isp import ColourISP, recorded_rendering
    from rgbz_fast.simulation import ColourSensor, Scene, simulate

    img = np.full((64, 64, 3), 0.2)
    img[:, 32:] = 5.0                                    # a grey card and a blown highlight
    frames = {fw: simulate(Scene(img), "bayer", ColourSensor(full_well=fw, exposure=0.01),
                           noise=False) for fw in (5000, 10000)}
    assert "colour_saturation_level" not in frames[10000].meta   # saturates at the top
    low = frames[5000]
    assert low.meta["colour_saturation_level"] == 64 + low.meta["system_gain"] * 5000
    assert recorded_rendering(low)["white_level"] == low.meta["colour_saturation_level"]
    gains = {fw: ColourISP().run(f, return_stages=True)[1]["gains"] for fw, f in frames.items()}
    np.testing.assert_allclose(gains[5000], gains[10000], rtol=1e-9)
    for fused in (False, True):
        out = ColourISP().run(low) if fused else ColourISP().run(low, return_stages=True)[0]
        card, highlight = out[10, 10].astype(int), out[10, 50]
        assert card.max() - card.min() <= 1 and np.all(highlight == 255)
    cfa = low.data
    white = recorded_rendering(low)["white_level"]
    chain = ColourISP()
    np.testing.assert_allclose(chain.white_balance_gains(cfa, "GRBG", bit_depth=11,
                                                         black_level=64, white_level=white),
                               gains[5000], rtol=1e-12)
    with pytest.raises(ValueError, match="white_level: expected a finite number > 0 and <= 2047"):
        chain.render(cfa, "GRBG", white_level=4095)


def test_a_raw_files_clip_level_is_its_white_level():
    """openISP's frame clips at 1020 of 1023 (9.8 % of its pixels): grey world had counted them
    (R gain 1.499 for 1.290 without them)."""
    from _support import shared_path

    from rgbz_fast.io import read_raw
    from rgbz_fast.isp import ColourISP, recorded_rendering

    f = read_raw(shared_path("raw", "openisp_test.RAW"), shape=(1080, 1920), phase="RGGB",
                 black_level=0, bit_depth_in=10, clip_level=1020)
    white = recorded_rendering(f)["white_level"]
    assert white == 2041.0
    g = ColourISP().white_balance_gains(f.data, "RGGB", bit_depth=11, white_level=white)
    np.testing.assert_allclose(g, [1.290, 1.0, 0.926], atol=5e-4)
    _, st = ColourISP().run(f, return_stages=True)
    np.testing.assert_allclose(st["gains"], g, rtol=1e-12)
    assert st["white_level"] == white
