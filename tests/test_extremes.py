"""Extreme inputs for every kernel (docs/reports/robustness.md, "Extremes").

Flat, zero and saturated frames, the full 16-bit range, denormal-range floats,
a huge dynamic range and one-pixel features, for the reconstruction (every
method, pattern, dtype and precision), the Malvar demosaic, the ToF
demodulation and unwrapping, and the sensor and ISP stages around them. The
promise is the numerical contract (docs/guide/interpretation.md): finite input never gives NaN
or inf, outputs stay in [0, 2**b - 1], a flat input stays exactly flat, and a
feature only influences the 5x5 window around it.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest


import rgbz_fast as rz  # noqa: E402
from rgbz_fast import simulation as sensor  # noqa: E402
from rgbz_fast import tof as tof_isp  # noqa: E402
from rgbz_fast.isp import demosaic  # noqa: E402
from rgbz_fast.simulation import Scene  # noqa: E402

PATTERNS = {"mask1": rz.mask1, "mask2": rz.mask2, "rows": rz.rows}
METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "edi_rows")
CASES = [(p, m) for p in PATTERNS for m in METHODS if m != "edi_rows" or p != "mask1"]
CASE_IDS = [f"{p}-{m}" for p, m in CASES]
DTYPES = (np.uint8, np.uint16, np.float32, np.float64)
OPTIONS = [dict(precision=pr, exp=ex, domain=do) for pr in ("float32", "float64")
           for ex in ("libm", "fast") for do in ("intensity", "colour_difference")]
SHAPE = (26, 30)          # a few periods of every preset, not a multiple of 4 or 6


def options_for(method):
    """OPTIONS that ``method`` takes: bilinear and edi_rows refuse the colour-difference
    domain (H75)."""
    return [kw for kw in OPTIONS
            if kw["domain"] == "intensity" or method not in ("bilinear", "edi_rows")]


def top(bit_depth):
    return (1 << bit_depth) - 1


def run_all(frame, pattern, method, bit_depth):
    """The reconstruction under every precision, exponential and domain; yields outputs."""
    for kw in options_for(method):
        out = rz.reconstruct(frame, method, pattern=pattern, bit_depth=bit_depth, **kw)
        assert out.dtype == frame.dtype and out.shape == frame.shape
        assert np.all(np.isfinite(out)), kw
        assert out.min() >= 0 and out.max() <= top(bit_depth), kw
        z = pattern.z_mask(frame.shape)
        np.testing.assert_array_equal(out[~z], frame[~z])
        yield kw, out


# --------------------------------------------------------------------------- reconstruction
@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("level", ["zero", "saturated", "mid"])
@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_reconstruct_flat_zero_saturated(pname, method, level, dtype):
    """Zero, saturated (2**b - 1) and flat frames stay exactly flat; Z sites hold junk."""
    pattern = PATTERNS[pname]()
    bit_depth = 8 if dtype == np.uint8 else 16
    value = {"zero": 0, "saturated": top(bit_depth), "mid": 77}[level]
    frame = np.full(SHAPE, value, dtype)
    frame[pattern.z_mask(SHAPE)] = top(bit_depth) - value    # ignored by the contract
    for kw, out in run_all(frame, pattern, method, bit_depth):
        assert np.all(out == value), (kw, np.unique(out))


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("pname", ["mask1", "mask2"])
@pytest.mark.parametrize("method", ["learned", "z_guided"])
def test_learned_methods_keep_a_flat_frame_flat_to_their_weights_rounding(method, pname,
                                                                          dtype):
    """The learned filters are float32 and sum to 1 only to their rounding, so a flat float
    frame comes back within 5e-7 of its value (2.4e-7 measured, both precisions), not
    exactly as the paper's methods do; an integer frame rounds that away: exactly flat.
    (The probe of H82 read robustness.md's "every method" as including them.)"""
    pattern = PATTERNS[pname]()
    bit_depth = 8 if dtype == np.uint8 and method == "learned" else 11
    if dtype == np.uint8 and bit_depth > 8:
        pytest.skip("no z_guided filters ship for 8 bits")
    kw = dict(nir=np.full(SHAPE, 0.5)) if method == "z_guided" else {}
    z = pattern.z_mask(SHAPE)
    for value in (0, 1, 77, top(bit_depth)):
        frame = np.full(SHAPE, value, dtype)
        frame[z] = top(bit_depth) - value
        for precision in ("float32", "float64"):
            out = rz.reconstruct(frame, method, pattern=pattern, bit_depth=bit_depth,
                                 precision=precision, **kw)
            if np.issubdtype(dtype, np.integer):
                assert np.all(out == value), (precision, np.unique(out))
            else:
                np.testing.assert_allclose(out, value, rtol=5e-7, atol=0)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_reconstruct_max_16bit_checkerboards(pname, method):
    """0/65535 patterns (the largest gradients there are) in uint16 at 16 bits."""
    pattern = PATTERNS[pname]()
    yy, xx = np.indices(SHAPE)
    for board in ((yy + xx) % 2, (yy // 2 + xx // 2) % 2, yy % 2, xx % 3 == 0, yy % 4 < 2):
        frame = (board.astype(np.uint16) * np.uint16(65535))
        for _ in run_all(frame, pattern, method, 16):
            pass


@pytest.mark.parametrize("bit_depth", [1, 2])
@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_reconstruct_denormal_range_floats(pname, method, bit_depth):
    """Values around 1e-310 in float64 frames (and 1e-40 in float32) of tiny bit depths.

    The gradients are denormal, sigma is floored (at sigma_floor, or at 1e-300
    where sigma**2 underflows to 0 and every gamma would be 0/0): the weights
    must fall back to the plain mean, never give NaN.
    """
    pattern = PATTERNS[pname]()
    rng = np.random.default_rng(3)
    for dtype, tiny in ((np.float64, 1e-310), (np.float32, 1e-40)):
        frame = (rng.integers(0, 5, SHAPE) * tiny).astype(dtype)
        known = frame[~pattern.z_mask(SHAPE)]
        for sigma_floor in (1e-3, 1e-300):
            for kw in options_for(method):
                # sigma_floor 1e-300 in the fast exponential: sigma**2 underflows, every
                # exponent is NaN, which must take the clamp to 0 (no NaN-to-integer
                # conversion, undefined behaviour that tools/sanitize.sh would stop on)
                out = rz.reconstruct(frame, method, pattern=pattern, bit_depth=bit_depth,
                                     sigma_floor=sigma_floor, sigma_rel=0.0, **kw)
                assert np.all(np.isfinite(out)), (dtype, sigma_floor, kw)
                assert out.min() >= 0 and out.max() <= top(bit_depth), (dtype, kw)
                if kw["domain"] == "intensity":          # a mean of the known values
                    assert out.max() <= known.max(), (dtype, sigma_floor, kw)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_reconstruct_huge_dynamic_range(pname, method):
    """1e-300 next to 65535 in one window (float64, 16 bits): finite and inside the range."""
    pattern = PATTERNS[pname]()
    rng = np.random.default_rng(4)
    frame = np.where(rng.random(SHAPE) < 0.5, 1e-300, 65535.0)
    frame[rng.random(SHAPE) < 0.1] = 0.0
    for kw, out in run_all(frame, pattern, method, 16):
        pass
    # and sigma_floor / sigma_rel at their extremes
    for sigma_floor, sigma_rel in ((1e-300, 0.0), (1e300, 0.0), (1e-3, 10.0)):
        out = rz.reconstruct(frame, method, pattern=pattern, bit_depth=16,
                             sigma_floor=sigma_floor, sigma_rel=sigma_rel)
        assert np.all(np.isfinite(out)) and out.min() >= 0 and out.max() <= 65535


@pytest.mark.parametrize("dtype", [np.uint16, np.float64])
@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_reconstruct_one_pixel_feature_stays_local(pname, method, dtype):
    """A single saturated pixel changes only the Z sites whose 5x5 window holds it.

    edi_rows reads rows +-2 and columns +-4; the colour-difference domain reads
    the 4-neighbours of the window's pixels (one pixel more).
    """
    pattern = PATTERNS[pname]()
    shape = (30, 34)
    base = np.full(shape, 100, dtype)
    z = pattern.z_mask(shape)
    colour_sites = np.argwhere(~z)
    y, x = colour_sites[np.argmin(np.abs(colour_sites - (15, 17)).sum(1))]
    spike = base.copy()
    spike[y, x] = 65535
    reach_y, reach_x = (2, 4) if method == "edi_rows" else (2, 2)
    for kw in options_for(method):
        extra = 1 if kw["domain"] == "colour_difference" else 0
        a = rz.reconstruct(base, method, pattern=pattern, bit_depth=16, **kw)
        b = rz.reconstruct(spike, method, pattern=pattern, bit_depth=16, **kw)
        changed = np.argwhere(a != b)
        assert np.all(np.abs(changed[:, 0] - y) <= reach_y + extra), kw
        assert np.all(np.abs(changed[:, 1] - x) <= reach_x + extra), kw
        # a mean of values >= 100 (intensity domain), up to float32 cancellation near the
        # white level (c0 + sum w (c - c0) / sum w with c0 = 65535: a few ulp of 65535)
        slack = 8 * 65535 * 2.0 ** -23 if kw["precision"] == "float32" else 0.0
        assert b.max() <= 65535 and b.min() >= (100 - slack if kw["domain"] == "intensity"
                                                  else 0)


@pytest.mark.parametrize("bit_depth", [1, 8, 16])
def test_reconstruct_value_at_the_white_level_rounds_into_range(bit_depth):
    """Integer outputs round half up and are clipped: never 2**b (which would wrap in uint8)."""
    dtype = np.uint8 if bit_depth <= 8 else np.uint16
    frame = np.full(SHAPE, top(bit_depth), dtype)
    frame[::2, 1::2] = top(bit_depth) - (bit_depth > 1)    # just below white on the R sites
    for method in ("bilinear", "sg", "edi_line"):
        for kw, out in run_all(frame, rz.mask1(), method, bit_depth):
            assert out.max() <= top(bit_depth)


# --------------------------------------------------------------------------- Malvar demosaic
@pytest.mark.parametrize("mode", ["reflect", "period"])
@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("phase", rz.BAYER_PHASES)
def test_malvar_flat_zero_saturated(phase, dtype, mode):
    for value in (0, 1, np.iinfo(dtype).max if np.issubdtype(dtype, np.integer) else 65535.0):
        cfa = np.full((9, 11), value, dtype)
        for out_dtype in (np.float32, np.float64):
            rgb = demosaic(cfa, phase, mode=mode, dtype=out_dtype)
            assert np.all(rgb == float(value)), (value, out_dtype)


@pytest.mark.parametrize("mode", ["reflect", "period"])
def test_malvar_extremes_are_finite_and_bounded(mode):
    rng = np.random.default_rng(5)
    cases = {
        "max16": (rng.integers(0, 2, (12, 14)) * 65535).astype(np.uint16),
        "denormal": rng.integers(0, 4, (12, 14)) * 1e-310,
        "dynamic": np.where(rng.random((12, 14)) < 0.5, 1e-300, 65535.0),
        "huge_float": np.where(rng.random((12, 14)) < 0.5, 0.0, 1e300),
        "tiny_2x2": np.array([[0, 65535], [65535, 0]], np.uint16),
    }
    for name, cfa in cases.items():
        for out_dtype in (np.float32, np.float64):
            if name == "huge_float" and out_dtype == np.float32:
                # 1e300 does not fit float32: refused, not cast to inf
                with pytest.raises(ValueError, match="^cfa: values up to 1e.300 .*float32"):
                    demosaic(cfa, "GRBG", mode=mode, dtype=out_dtype)
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("error", RuntimeWarning)
                rgb = demosaic(cfa, "GRBG", mode=mode, dtype=out_dtype)
            assert np.all(np.isfinite(rgb)), (name, out_dtype)
            lo, hi = float(cfa.min()), float(cfa.max())
            assert rgb.min() >= lo - 0.75 * (hi - lo) * (1 + 1e-6), name
            assert rgb.max() <= lo + 1.75 * (hi - lo) * (1 + 1e-6), name


def test_demosaic_near_the_largest_float_is_finite_or_refused():
    """Finite values near the float maximum: every method and border gives finite values up
    to 1/32 of the output type's largest float (NaN from inf - inf before), and refuses
    larger ones naming the CFA."""
    rng = np.random.default_rng(3)
    for dtype in (np.float32, np.float64):
        limit = float(np.finfo(dtype).max) / 32
        cfa = ((rng.random((12, 12)) * 2 - 1) * limit).astype(dtype)
        for method in ("malvar2004", "menon2007", "bilinear"):
            for mode in ("reflect", "period"):
                with warnings.catch_warnings():
                    warnings.simplefilter("error", RuntimeWarning)
                    assert np.all(np.isfinite(demosaic(cfa, "RGGB", method, mode=mode)))
        with pytest.raises(ValueError, match="^cfa: values up to .* in magnitude"):
            demosaic(np.full((4, 4), np.finfo(dtype).max, dtype), "RGGB")


def test_malvar_one_pixel_feature_stays_local():
    cfa = np.zeros((20, 22))
    cfa[9, 10] = 65535.0
    rgb = demosaic(cfa, "RGGB")
    ys, xs = np.nonzero(np.any(rgb != 0, axis=2))
    assert np.abs(ys - 9).max() <= 2 and np.abs(xs - 10).max() <= 2


# --------------------------------------------------------------------------- ToF kernels
def _taps(amplitude, phase, offset, dtype=np.float64):
    k = np.arange(4)[None, :, None]
    t = offset + amplitude * np.cos(np.asarray(phase)[:, None, :] + k * np.pi / 2)
    return np.ascontiguousarray(t.astype(dtype))


def test_demodulate_zero_amplitude():
    """Equal taps: amplitude exactly 0, phase 0 (atan2(0, 0)), offset the tap value."""
    for dtype, value in ((np.uint16, 2047), (np.uint16, 0), (np.float32, 1e-40),
                         (np.float64, 1e-310), (np.float64, 65535.0)):
        taps = np.full((3, 4, 17), value, dtype)
        phase, amp, off = tof_isp.demodulate(taps)
        assert np.all(amp == 0) and np.all(phase == 0)
        np.testing.assert_array_equal(off, float(np.asarray(value, dtype)))


def test_demodulate_saturated_taps_and_extreme_phases():
    """Saturated taps clip the cosine; phases at 0, pi/2, pi, 3pi/2 and just below 2 pi."""
    taps = np.full((1, 4, 3), 2047, np.uint16)
    taps[0, 1, 1] = 0                                       # three saturated, one dark
    phase, amp, _ = tof_isp.demodulate(taps)
    assert np.all(np.isfinite(phase)) and np.all((phase >= 0) & (phase < 2 * np.pi))
    want = np.array([0, np.pi / 2, np.pi, 1.5 * np.pi, 2 * np.pi - 1e-12, 1e-12])
    phase, amp, off = tof_isp.demodulate(_taps(500.0, want[None], 1000.0))
    got = phase[0]
    assert np.all((got >= 0) & (got <= 2 * np.pi))
    err = np.abs(np.angle(np.exp(1j * (got - want))))
    assert err.max() < 1e-9
    np.testing.assert_allclose(amp, 500.0)
    np.testing.assert_allclose(off, 1000.0)


def test_demodulate_phase_is_below_two_pi():
    """Q = A3 - A1 = -1e-17, I = 1: atan2 is -1e-17, and -1e-17 + 2 pi == 2 pi in float64."""
    phase, _, _ = tof_isp.demodulate(np.array([[[1.0], [1e-17], [0.0], [0.0]]]))
    assert phase[0, 0] < 2 * np.pi


def test_unwrap_at_the_edges_of_the_unambiguous_range():
    """0 m, a hair above 0, a hair below the unambiguous range, and every wrap boundary."""
    c = 299_792_458.0
    f = np.array([80e6, 100e6, 120e6])
    rng_max = c / (2 * 20e6)                                # gcd 20 MHz: 7.4948 m
    amb = c / (2 * f)
    d = np.concatenate([[0.0, 1e-9, 1e-3, rng_max - 1e-3, rng_max - 1e-6],
                        np.outer(np.arange(1, 4), amb).ravel() - 1e-6,
                        np.outer(np.arange(1, 4), amb).ravel() + 1e-6])
    d = d[d < rng_max]
    phase = np.mod(4 * np.pi * f[:, None] * d[None] / c, 2 * np.pi)
    depth, residual, wraps = tof_isp.unwrap(phase, f)
    err = np.abs(depth - d)
    err = np.minimum(err, np.abs(err - rng_max))            # 0 and rng_max are the same phase
    assert err.max() < 1e-6, (d[np.argmax(err)], depth[np.argmax(err)])
    assert np.all(np.isfinite(residual)) and residual.max() < 1e-6
    # phase exactly 0 and exactly just below 2 pi on every frequency
    for p in (0.0, np.nextafter(2 * np.pi, 0)):
        depth, residual, _ = tof_isp.unwrap(np.full((3, 1), p), f)
        assert np.isfinite(depth[0]) and 0 <= depth[0] <= rng_max + 1e-6


def test_unwrap_single_frequency_and_zero_weight():
    f = np.array([100e6])
    depth, residual, wraps = tof_isp.unwrap(np.array([[np.pi]]), f)
    np.testing.assert_allclose(depth, 299_792_458.0 / (4 * 100e6), rtol=1e-12)   # half a wrap
    assert np.isfinite(depth[0]) and residual[0] == 0 and wraps[0] == 0
    # a frequency with weight 0 does not move the depth
    f3 = np.array([80e6, 100e6, 120e6])
    d = 3.0
    phase = np.mod(4 * np.pi * f3[:, None] * d / 299_792_458.0, 2 * np.pi)
    phase_bad = phase.copy()
    phase_bad[2] = (phase_bad[2] + 1.0) % (2 * np.pi)
    depth, _, _ = tof_isp.unwrap(phase_bad, f3, weights=[1.0, 1.0, 0.0])
    np.testing.assert_allclose(depth, d, atol=1e-9)


# --------------------------------------------------------------------------- ToF chain
def _tof_scene(depth, ir=0.5, shape=(16, 16)):
    return Scene(np.full(shape + (3,), 0.5), depth=np.full(shape, float(depth)),
                 ir_reflectance=np.full(shape, float(ir)))


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_tof_depth_near_zero_and_near_the_range_edge(pattern):
    """Noise-free depths of 30 cm and 7.49 m come back (the edge of the 7.495 m range)."""
    for d in (0.3, 7.49):
        frame = sensor.simulate(_tof_scene(d), pattern, noise=False)
        res = tof_isp.tof_depth(frame)
        assert np.all(np.isfinite(res.depth))
        np.testing.assert_allclose(res.depth[res.valid], d, atol=5e-3)


def test_tof_depth_beyond_the_range_is_flagged():
    """At or beyond the unambiguous range: UnambiguousRangeWarning and invalid sites."""
    for d in (sensor.ToFSensor().unambiguous_range, 7.6, 20.0):
        with pytest.warns(sensor.UnambiguousRangeWarning):
            frame = sensor.simulate(_tof_scene(d), "mask1", noise=False)
        assert not frame.tof.valid.any()
        res = tof_isp.tof_depth(frame)
        assert np.all(np.isfinite(res.depth))
        assert np.all((res.depth >= 0) & (res.depth <= 7.4948 + 1e-6))


def test_tof_depth_zero_amplitude_is_low_signal():
    """No NIR return (reflectance 0): amplitude 0, finite depth, flagged low-signal."""
    frame = sensor.simulate(_tof_scene(2.0, ir=0.0), "mask1", noise=False)
    res = tof_isp.tof_depth(frame)
    assert np.all(res.amplitude == 0) and np.all(np.isfinite(res.depth))
    assert np.all(res.flags & tof_isp.FLAG_LOW_SIGNAL) and not res.valid.any()


def test_tof_depth_saturated_taps_are_flagged():
    """A bright target at 5 cm saturates the taps: finite output, FLAG_SATURATED, invalid."""
    frame = sensor.simulate(_tof_scene(0.05, ir=1.0), "mask1", noise=False)
    assert frame.tof.saturated.all()
    assert int(frame.tof.taps.max()) == frame.tof.white_level
    res = tof_isp.tof_depth(frame)
    assert np.all(np.isfinite(res.depth)) and np.all(np.isfinite(res.amplitude))
    assert np.all(res.flags & tof_isp.FLAG_SATURATED) and not res.valid.any()


# --------------------------------------------------------------------------- sensor and ISP
@pytest.mark.parametrize("bit_depth", [1, 11, 16])
def test_simulate_extreme_scenes(bit_depth):
    """Black (fixed exposure), over-exposed and 1e300-bright scenes: valid frames."""
    cs = dict(bit_depth=bit_depth, black_level=0, dark_current=0.0)
    cases = [
        (np.zeros((8, 8, 3)), sensor.ColourSensor(exposure=0.01, **cs), 0),
        (np.ones((8, 8, 3)), sensor.ColourSensor(exposure=3600.0, **cs), top(bit_depth)),
        (np.full((8, 8, 3), 1e300), sensor.ColourSensor(**cs), None),
    ]
    for image, cs_, expect in cases:
        for noise in (False, True):
            frame = sensor.simulate(Scene(image), "mask1", cs_, noise=noise)
            assert frame.data.dtype == np.uint16
            assert frame.reference.max() <= top(bit_depth)
            if expect is not None and not noise:
                assert np.all(frame.reference == expect)
            out = rz.reconstruct(frame, "sg")
            assert out.max() <= top(bit_depth)


def test_colour_isp_on_extreme_frames():
    from rgbz_fast.isp import ColourISP

    for value in (0, 2047):
        frame = rz.RawFrame(np.full((16, 16), value, np.uint16), "mask1")
        out = ColourISP().run(frame)
        assert out.dtype == np.uint8 and np.all(out == (0 if value == 0 else 255))


@pytest.mark.parametrize("dtype", ["uint16", "float32", "float64"])
def test_big_endian_input_gives_the_same_results(dtype):
    """A big-endian array (as some files hold) is read as its values: reconstruct and
    fill_missing refused '>u2' as 'not supported; expected one of uint8, uint16, ...' while
    the metrics and demosaic took it."""
    from rgbz_fast.isp import correct_colour, fill_missing
    from rgbz_fast.isp._stages import srgb_oetf

    img = np.random.default_rng(5).random((16, 16, 3))
    cfa = rz.mosaic(img, "mask1", dtype=np.dtype(dtype)).data
    big = cfa.astype(np.dtype(dtype).newbyteorder(">"))
    assert not big.dtype.isnative and np.array_equal(big, cfa)
    np.testing.assert_array_equal(rz.reconstruct(big, pattern="mask1"),
                                  rz.reconstruct(cfa, pattern="mask1"))
    np.testing.assert_array_equal(fill_missing(big, "mask1"), fill_missing(cfa, "mask1"))
    if dtype != "uint16":
        rgb = img.astype(dtype)
        big_rgb = rgb.astype(rgb.dtype.newbyteorder(">"))
        np.testing.assert_array_equal(srgb_oetf(big_rgb), srgb_oetf(rgb))
        np.testing.assert_array_equal(correct_colour(big_rgb), correct_colour(rgb))
