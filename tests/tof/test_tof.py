"""ToF ISP: demodulation, the denoise (edge-aware, and the paper's Fig. 17 box), unwrapping
over the whole unambiguous range, validity flags, noisy walls and planes, the RGB-D scenes."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from _support import SHARED_DATA, shared_path  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from rgbz_fast import _kernels  # noqa: E402
from rgbz_fast.simulation import Scene, load_rgbd  # noqa: E402
from rgbz_fast.simulation import (SPEED_OF_LIGHT, ToFSensor, ToFTaps, simulate,  # noqa: E402
                              simulate_tof)
from rgbz_fast._devtools._numpy_tof import numpy_tof_depth, numpy_unwrap  # noqa: E402
from rgbz_fast.tof import (FLAG_INCONSISTENT, FLAG_LOW_SIGNAL,  # noqa: E402
                           FLAG_OUT_OF_RANGE, FLAG_SATURATED, MAX_WRAPS, ToFDepth, ToFISP,
                           demodulate, demodulate_unwrap, denoise_phasors, phasors, tof_depth,
                           unambiguous_range, unwrap)

C = SPEED_OF_LIGHT
U = ToFSensor().unambiguous_range                       # 7.495 m
WRONG = 0.5 * min(ToFSensor().wrap_ranges)             # 0.62 m: far above the noise,
# far below the smallest error of a wrong wrap combination (about 1.4 m)


def _wall(depth, pattern, shape=(32, 32), *, sensor=None, noise=True, seed=0, ir=0.5):
    depth = np.broadcast_to(np.asarray(depth, float), shape)
    scene = Scene(np.full(shape + (3,), 0.5), depth=depth, ir_reflectance=np.full(shape, ir))
    return simulate_tof(scene, pattern, sensor, noise=noise, seed=seed)


def _wrong(result, tof):
    return np.abs(result.depth - tof.depth_true) > WRONG


# --------------------------------------------------------------------------- stages
def test_demodulate_matches_numpy():
    taps = np.random.default_rng(0).integers(0, 2048, (3, 4, 500)).astype(np.uint16)
    phase, amp, off = demodulate(taps, workers=2)
    t = taps.astype(np.float64)
    i, q = t[:, 0] - t[:, 2], t[:, 3] - t[:, 1]
    np.testing.assert_allclose(phase, np.mod(np.arctan2(q, i), 2 * np.pi), atol=1e-12)
    np.testing.assert_allclose(amp, np.hypot(i, q) / 2, rtol=1e-14)
    np.testing.assert_allclose(off, t.mean(axis=1), rtol=1e-14)
    pi, pq = phasors(taps)
    np.testing.assert_array_equal(pi, i)
    np.testing.assert_array_equal(pq, q)
    for dt in (np.float32, np.float64, np.int32):
        p2, _, _ = demodulate(taps.astype(dt))
        np.testing.assert_allclose(p2, phase, atol=1e-12)


def _brute_denoise(i, q, rows, cols, radius, use):
    near = ((np.abs(rows[:, None] - rows[None]) <= radius)
            & (np.abs(cols[:, None] - cols[None]) <= radius) & use[None])
    cnt = near.sum(axis=1)
    with np.errstate(invalid="ignore"):
        im = np.where(cnt > 0, (near[None] * i[:, None, :]).sum(-1) / cnt, 0)
        qm = np.where(cnt > 0, (near[None] * q[:, None, :]).sum(-1) / cnt, 0)
    return im, qm, cnt.astype(float)


@pytest.mark.parametrize("pattern,block", [("mask1", 1), ("mask2", 2), ("rows", 2),
                                           ("ZRGG/BGBZ", 1), ("mask2", 1)])
def test_denoise_matches_a_brute_force_window(pattern, block):
    pat = rz.get_pattern(pattern)
    shape = (24, 28)
    z = pat.z_mask(shape)
    if block == 1:
        rows, cols = np.nonzero(z)
    else:
        top = z[0:shape[0] - 1:2, 0:shape[1] - 1:2]
        rows, cols = (a * 2 for a in np.nonzero(top))
    rng = np.random.default_rng(1)
    n = rows.size
    i, q = rng.normal(size=(2, 3, n))
    use = rng.random(n) > 0.2
    got_i, got_q, cnt, _ = denoise_phasors(i, q, (rows, cols), block=block, use=use)
    want_i, want_q, want_c = _brute_denoise(i, q, rows, cols, 2 * block, use)
    np.testing.assert_allclose(got_i, want_i, atol=1e-12)
    np.testing.assert_allclose(got_q, want_q, atol=1e-12)
    np.testing.assert_array_equal(cnt, want_c)


def test_denoise_window_holds_nine_z_measurements():
    """Fig. 17: the 5x5 window of a Mask1 Z site holds 9 Z sites; Mask2 uses 3x3 Z pixels.
    The box denoise (the paper's) takes window 5 by default; the bilateral one window 9, the
    5x5 nearest Z measurements, all of weight 1 on a noise-free wall."""
    for pattern in ("mask1", "mask2"):
        tof = _wall(1.0, pattern, (40, 40), noise=False)
        res = tof_depth(tof, denoise="box")
        r, c = tof.sites
        interior = (r >= 8) & (r < 32) & (c >= 8) & (c < 32)
        assert np.all(res.count[interior] == 9)
        assert res.count.min() == 4                       # corners
        assert np.all(tof_depth(tof, denoise="box", window=1).count == 1)
        assert np.all(tof_depth(tof, denoise=False).count == 1)
        assert np.all(tof_depth(tof, denoise="none").count == 1)
        bil = tof_depth(tof)
        inner = (r >= 16) & (r < 24) & (c >= 16) & (c < 24)
        np.testing.assert_allclose(bil.count[inner], 25, rtol=1e-12)
        np.testing.assert_allclose(tof_depth(tof, window=5).count[interior], 9, rtol=1e-12)
        assert bil.count.min() == pytest.approx(9)        # corners


def test_denoise_averages_phasors_not_wrapped_phases():
    """Phases on both sides of 0 / 2 pi average to ~0, not to pi."""
    n = 9
    rows, cols = np.repeat(np.arange(3) * 2, 3), np.tile(np.arange(3) * 2, 3)
    ph = np.where(np.arange(n) % 2 == 0, 0.05, 2 * np.pi - 0.05)[None]
    i, q, _, _ = denoise_phasors(np.cos(ph), np.sin(ph), (rows, cols))
    mean_phase = np.mod(np.arctan2(q, i), 2 * np.pi)
    assert np.all((mean_phase < 0.05) | (mean_phase > 2 * np.pi - 0.05))


def test_unwrap_is_exact_on_ideal_phases_over_the_whole_range():
    f = np.array([80e6, 100e6, 120e6])
    d = np.linspace(0.0, U - 1e-6, 20001)
    phase = np.mod(4 * np.pi * f[:, None] * d[None] / C, 2 * np.pi)
    depth, residual, wraps = unwrap(phase, f, workers=2)
    np.testing.assert_allclose(depth, d, atol=1e-9)
    assert residual.max() < 1e-9
    np.testing.assert_array_equal(wraps, np.floor(d / (C / 160e6)).astype(np.int32))
    # custom weights and a shorter search range
    d2, _, _ = unwrap(phase[:, :100], f, weights=[1, 1, 1], max_range=3.0)
    np.testing.assert_allclose(d2, d[:100], atol=1e-9)


def _random_taps(shape, dtype, seed=0):
    rng = np.random.default_rng(seed)
    if np.issubdtype(dtype, np.integer):
        return rng.integers(0, 2048, shape).astype(dtype)
    return rng.uniform(0, 2047, shape).astype(dtype)


def test_fast_atan2_matches_numpy_to_one_ulp():
    """tof.c's atan2 (no libm; Cephes' rational core) against numpy.arctan2 wrapped to
    [0, 2 pi): at most one ulp of 2 pi (8.9e-16 rad) on random phasors at every scale,
    the axes, the diagonals, zero and infinite components."""
    rng = np.random.default_rng(7)
    parts = [rng.normal(size=(2, 200_000)) * s for s in (1.0, 1e-300, 1e-310, 1e300, 2047.0)]
    axes = np.array([[1, 0], [0, 1], [-1, 0], [0, -1], [1, 1], [-1, 1], [-1, -1], [1, -1],
                     [0, 0], [3, 4], [1e-17, 1], [-1e-17, 1], [-1e-17, -1], [1, 0.66],
                     [0.66, 1], [1e308, 1], [1, 1e308], [1e308, 1e308], [-1e308, 2],
                     [-1e308, -1e308]], float).T[::-1]        # rows: Q, I
    q, i = np.concatenate(parts + [axes], axis=1)
    taps = np.zeros((1, 4, q.size))
    taps[0, 0], taps[0, 3] = i, q                             # I = A0, Q = A3
    big = np.abs(taps) == 1e308                               # I = A0 - A2 = 2e308 = inf
    taps[0, 2], taps[0, 1] = -taps[0, 0] * big[0, 0], -taps[0, 3] * big[0, 3]
    with np.errstate(over="ignore"):
        i, q = taps[0, 0] - taps[0, 2], taps[0, 3] - taps[0, 1]
    assert np.isinf(i).sum() >= 3 and np.isinf(q).sum() >= 3
    # the kernel itself: demodulate refuses taps beyond TAP_MAX, whose sums overflow
    phase, amp, off = (np.empty((1, q.size)) for _ in range(3))
    _kernels.tof_demodulate(np.ascontiguousarray(taps), phase, amp, off, 1)
    with pytest.raises(ValueError, match="^taps: values up to 1e.308 in magnitude"):
        demodulate(taps)
    want = np.arctan2(q, i)
    want[want < 0] += 2 * np.pi
    want[want >= 2 * np.pi] = 0.0
    err = np.abs(phase[0] - want)
    err = np.minimum(err, 2 * np.pi - err)                    # 0 and 2 pi are one phase
    assert err.max() <= np.spacing(2 * np.pi), err.max()
    assert np.all((phase >= 0) & (phase < 2 * np.pi))


@pytest.mark.parametrize("f,weights,max_range", [
    ([80e6, 100e6, 120e6], None, None),
    ([80e6, 100e6, 120e6], [1, 1, 1], 3.0),
    ([100e6, 80e6], None, None),                      # the base frequency second
    ([20e6, 100e6, 120e6, 150e6], None, 12.0),
    ([100e6], None, None),
    ([1e6, 2.5e15], None, None),                      # x beyond 2^30: libm's floor path
])
def test_unwrap_kernel_equals_its_numpy_twin_bit_for_bit(f, weights, max_range):
    """C unwrap vs rgbz_fast._devtools._numpy_tof.numpy_unwrap (the same arithmetic, whole-array
    NumPy): identical depth, residual and wrap counts from the same phases."""
    rng = np.random.default_rng(3)
    phase = rng.uniform(0, 2 * np.pi, (len(f), 5003))
    phase[:, :3] = 0.0
    phase[:, 3] = np.nextafter(2 * np.pi, 0)
    got = unwrap(phase, f, weights=weights, max_range=max_range, workers=2)
    want = numpy_unwrap(phase, f, weights, max_range)
    for a, b in zip(got, want):
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("dtype", [np.uint16, np.float32, np.float64, np.int32])
def test_fused_demodulate_unwrap_matches_numpy(dtype):
    """demodulate_unwrap (one C pass) against the NumPy implementation (np.arctan2 +
    the same unwrapping): same wrap counts, depth to 1e-9 m, phase to 1e-15 rad,
    amplitude to 1e-12 relative, offset exact; and against demodulate + unwrap
    (the C stages) bit for bit."""
    f = [80e6, 100e6, 120e6]
    taps = _random_taps((3, 4, 20_011), dtype)
    got = demodulate_unwrap(taps, f, workers=2)
    depth, residual, wraps, phase, amp, off = numpy_tof_depth(taps, f)
    np.testing.assert_array_equal(got[2], wraps)
    np.testing.assert_allclose(got[0], depth, rtol=0, atol=1e-9)
    np.testing.assert_allclose(got[1], residual, rtol=0, atol=1e-9)
    np.testing.assert_allclose(got[3], phase, rtol=0, atol=1e-15)
    np.testing.assert_allclose(got[4], amp, rtol=1e-12)
    np.testing.assert_array_equal(got[5], off)
    ph, am, of = demodulate(taps)
    for a, b in zip(got, unwrap(ph, f) + (ph, am, of)):
        np.testing.assert_array_equal(a, b)
    # the workers never change a bit; nor does an empty input fail
    for w in (1, 3):
        for a, b in zip(got, demodulate_unwrap(taps, f, workers=w)):
            np.testing.assert_array_equal(a, b)
    empty = demodulate_unwrap(taps[:, :, :0], f)
    assert [a.shape for a in empty] == [(0,), (0,), (0,), (3, 0), (3, 0), (3, 0)]


def test_tof_depth_uses_the_fused_kernel_without_denoise():
    tof = _wall(np.tile(np.linspace(0.5, 6, 48), (24, 1)), "mask1", (24, 48), seed=2)
    res = tof_depth(tof, denoise=False)
    ph, am, of = demodulate(tof.taps)
    depth, residual, wraps = unwrap(ph, tof.frequencies)
    for a, b in ((res.depth, depth), (res.residual, residual), (res.wraps, wraps),
                 (res.phase, ph), (res.amplitude, am), (res.offset, of)):
        np.testing.assert_array_equal(a, b)


def test_denoised_phasors_unwrap_like_numpy():
    """The denoise path's C pass (atan2 + amplitude + unwrapping of the averaged phasors)
    against np.arctan2 / np.hypot and the NumPy unwrapping."""
    tof = _wall(np.tile(np.linspace(0.5, 6, 48), (24, 1)), "mask2", (24, 48), seed=4)
    res = tof_depth(tof, denoise="box")
    i, q = phasors(tof.taps)
    sat = np.asarray(tof.saturated) | np.any(tof.taps >= tof.white_level, axis=(0, 1))
    i, q, _, _ = denoise_phasors(i, q, tof.sites, block=tof.block, use=~sat)
    phase = np.arctan2(q, i)
    phase[phase < 0] += 2 * np.pi
    phase[phase >= 2 * np.pi] = 0.0
    np.testing.assert_allclose(res.phase, phase, rtol=0, atol=1e-15)
    np.testing.assert_allclose(res.amplitude, 0.5 * np.hypot(i, q), rtol=1e-12)
    depth, residual, wraps = numpy_unwrap(phase, tof.frequencies)
    np.testing.assert_array_equal(res.wraps, wraps)
    np.testing.assert_allclose(res.depth, depth, rtol=0, atol=1e-9)


def test_phase_of_phasors_is_the_fused_passs_phase_bit_for_bit():
    """The calibrated chain takes atan2 and amplitude alone (it unwraps after the cyclic-error
    correction): the same bits as the fused phasor pass, and non-finite phasors refused."""
    from rgbz_fast import _kernels

    rng = np.random.default_rng(0)
    i, q = rng.normal(size=(2, 3, 1000)) * 100
    i[:, :5], q[:, :3], i[0, 7] = 0.0, 0.0, 1e-310
    f = np.array([80e6, 100e6, 120e6])
    d, r, k = np.empty(1000), np.empty(1000), np.empty(1000, np.int32)
    ph1, am1, ph2, am2 = (np.empty_like(i) for _ in range(4))
    assert _kernels.tof_depth_iq(i, q, f, f ** 2, 7.4, d, r, k, ph1, am1, workers=2)
    assert _kernels.tof_phase_iq(i, q, ph2, am2, 2)
    np.testing.assert_array_equal(ph1, ph2)
    np.testing.assert_array_equal(am1, am2)
    i[1, 5] = np.nan
    assert not _kernels.tof_phase_iq(i, q, ph2, am2, 1)


# --------------------------------------------------------------------------- domain of the unwrapping
def test_max_range_is_bounded_by_the_unambiguous_range_and_the_wrap_count():
    """max_range beyond the unambiguous range (the search would repeat) or beyond
    MAX_WRAPS wraps of the lowest frequency is refused, before any kernel runs."""
    f = [80e6, 100e6, 120e6]
    assert unambiguous_range(f) == pytest.approx(C / (2 * 20e6))
    phase = np.zeros((3, 4))
    for bad in (U * 1.001, 1e8, 1e12, 1e300):
        with pytest.raises(ValueError, match="max_range: .* is beyond the 7.49481 m "
                                             "unambiguous range"):
            unwrap(phase, f, max_range=bad)
    unwrap(phase, f, max_range=U)                     # the range itself is fine
    # nearly coprime: 1.5e7 m of range, a search capped at MAX_WRAPS wraps of 1.874 m
    near = [80e6 + 10, 100e6]
    cap = MAX_WRAPS * C / (2 * near[0])
    with pytest.raises(ValueError, match="frequencies: the unambiguous range"):
        unwrap(np.zeros((2, 4)), near)
    with pytest.raises(ValueError, match="max_range: .* wraps"):
        unwrap(np.zeros((2, 4)), near, max_range=cap * 1.01)
    d = np.array([0.5, 3.0, 100.0, 1500.0])
    ph = np.mod(4 * np.pi * np.array(near)[:, None] * d[None] / C, 2 * np.pi)
    depth, residual, _ = unwrap(ph, near, max_range=cap)
    np.testing.assert_allclose(depth, d, atol=1e-6)
    # a tiny range still searches the first wrap (no residual of inf)
    depth, residual, wraps = unwrap(np.full((3, 2), 0.1), f, max_range=1e-9)
    assert np.all(np.isfinite(residual)) and np.all(wraps == 0)


def test_nearly_coprime_sensor_needs_an_explicit_max_range():
    """The default range of a nearly coprime set (1.5e8 m) is refused before the search
    starts (it would take days), naming the frequencies; an explicit max_range within the cap unwraps."""
    sensor = ToFSensor(frequencies=(80e6 + 1, 100e6, 120e6), quantise=False,
                       optical_power_w=0.05)
    tof = _wall(1.5, "mask1", (12, 12), sensor=sensor, noise=False)
    assert tof.unambiguous_range > 1e8
    with pytest.raises(ValueError, match="frequencies: .* pass max_range="):
        tof_depth(tof)
    with pytest.raises(ValueError, match="frequencies"):
        ToFISP().run(tof)
    res = tof_depth(tof, max_range=500.0)
    np.testing.assert_allclose(res.depth, 1.5, atol=1e-6)


@pytest.mark.parametrize("offset_hz", [0.4, -0.4, 1e-3])
def test_frequencies_a_fraction_of_a_hz_off_whole_numbers_unwrap_as_whole_ones(offset_hz):
    """The unambiguous range is taken from whole Hz (80 MHz + 0.4 Hz: 7.49 m), which put it
    2e-8 of a wrap above 4 wraps of the exact lowest frequency: the kernel searched a fifth
    wrap, whose aliases cost the same, and 75 % of a wall came out 7.49 m too far (19 % valid
    against 94 %). The search stops at the whole wraps the range holds."""
    off = ToFSensor(frequencies=(80e6 + offset_hz, 100e6, 120e6))
    want = tof_depth(_wall(1.5, "mask1", sensor=ToFSensor()))
    got = tof_depth(_wall(1.5, "mask1", sensor=off))
    assert want.valid.mean() > 0.9 and abs(got.valid.mean() - want.valid.mean()) < 0.02
    assert np.all(got.wraps == 0)
    np.testing.assert_allclose(got.depth[got.valid], 1.5, atol=0.05)
    # an explicit max_range of the unambiguous range itself is the same search
    again = tof_depth(_wall(1.5, "mask1", sensor=off), max_range=unambiguous_range(off.frequencies))
    np.testing.assert_array_equal(again.depth, got.depth)


def test_phases_outside_zero_two_pi_are_refused():
    """Checked inside the kernel (no extra pass); the message names the phase."""
    f = [80e6, 100e6, 120e6]
    good = np.random.default_rng(0).uniform(0, 2 * np.pi, (3, 1000))
    for value in (-1e-300, -0.1, 2 * np.pi, 7.0, 1e300, np.nan, np.inf, -np.inf):
        bad = good.copy()
        bad[1, 637] = value
        msg = "phase: holds NaN" if not np.isfinite(value) else "phase: values span"
        with pytest.raises(ValueError, match=msg):
            unwrap(bad, f, workers=2)
    unwrap(np.full((3, 1), np.nextafter(2 * np.pi, 0)), f)   # just below 2 pi is fine


# --------------------------------------------------------------------------- noise-free
@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_noise_free_walls_unwrap_exactly_over_the_unambiguous_range(pattern):
    # float taps (no quantisation) and a weak source, so that nothing saturates at 0.2 m
    sensor = ToFSensor(quantise=False, optical_power_w=0.05)
    for d in np.r_[np.linspace(0.2, U - 0.01, 61), U - 1e-3]:
        tof = _wall(d, pattern, (12, 12), sensor=sensor, noise=False)
        for denoise in (True, False):
            res = tof_depth(tof, denoise=denoise, workers=1)
            np.testing.assert_allclose(res.depth, d, atol=1e-7, err_msg=f"{d} m")
            assert res.residual.max() < 1e-7
            assert not (res.flags & (FLAG_SATURATED | FLAG_INCONSISTENT)).any()


def test_noise_free_slanted_plane_unwraps_without_denoise():
    sensor = ToFSensor(quantise=False, optical_power_w=0.05)
    depth = np.tile(np.linspace(0.2, U - 0.01, 64), (8, 1))
    tof = _wall(depth, "mask1", (8, 64), sensor=sensor, noise=False)
    res = tof_depth(tof, denoise=False)
    np.testing.assert_allclose(res.depth, tof.depth_true, atol=1e-7)


def test_noise_free_quantised_taps_never_unwrap_wrongly_where_valid():
    for pattern in ("mask1", "mask2"):
        for d in np.linspace(0.35, U - 0.05, 12):
            tof = _wall(d, pattern, (16, 16), noise=False)
            res = tof_depth(tof)
            assert not np.any(_wrong(res, tof) & res.valid), (pattern, d)


# --------------------------------------------------------------------------- noisy
def _collect(tofs, **kw):
    wrong = valid = total = 0
    for tof in tofs:
        res = tof_depth(tof, **kw)
        ok = res.valid & tof.valid
        wrong += int(np.sum(_wrong(res, tof) & ok))
        valid += int(ok.sum())
        total += int(tof.valid.sum())
    return wrong, valid, total


@pytest.mark.parametrize("pattern,near,far", [("mask1", 1.8, 2.2), ("mask2", 3.2, 3.9)])
def test_noisy_flat_walls_unwrap_correctly(pattern, near, far):
    """Prints the wall table of docs/reports/isp.md: ``pytest tests/tof/test_tof.py -k walls -s``."""
    tofs = [_wall(d, pattern, (96, 96), seed=k) for k, d in
            enumerate(np.linspace(0.3, U - 0.1, 16))]
    print(f"\n{pattern}: distance m, valid share, depth std cm (valid), wrong unwraps "
          "valid/all")
    for tof in tofs:
        res = tof_depth(tof)
        w = _wrong(res, tof)
        std = 100 * np.std(res.depth[res.valid]) if res.valid.sum() > 1 else float("nan")
        print(f"  {tof.depth_true[0]:5.2f}  {res.valid.mean():6.3f}  {std:6.2f}  "
              f"{int(np.sum(w & res.valid))}/{int(w.sum())}")
    wrong, valid, total = _collect(tofs)
    assert valid > 0 and wrong <= 0.001 * valid, (wrong, valid)
    # and the validity map is no blanket rejection: walls up to `near` are ~all valid,
    # and there is a usable share up to `far` (max_sigma = 1.5 cm sets the reach)
    for d, keep in ((near, 0.97), (far, 0.3)):
        tof = _wall(d, pattern, (96, 96), seed=99)
        assert tof_depth(tof).valid.mean() > keep, (pattern, d)
    # without the denoise the SNR test still keeps the valid pixels right
    wrong, valid, _ = _collect(tofs, denoise=False)
    assert wrong <= 0.001 * max(valid, 1)


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_noisy_slanted_planes_unwrap_correctly(pattern):
    H, W = 96, 192
    tofs = []
    for k, (lo, hi) in enumerate([(0.3, 3.0), (1.0, 5.0), (0.5, U - 0.1)]):
        ramp = np.linspace(lo, hi, W)
        tofs.append(_wall(np.tile(ramp, (H, 1)), pattern, (H, W), seed=10 + k))
        ramp = np.linspace(lo, hi, H)[:, None]
        tofs.append(_wall(np.tile(ramp, (1, W)), pattern, (H, W), seed=20 + k))
    wrong, valid, total = _collect(tofs)
    assert wrong <= 0.001 * valid, (wrong, valid)
    # the planes reach 3-7.4 m, beyond what max_sigma = 1.5 cm keeps; slopes are no edges
    assert valid > 0.1 * total
    wrong, valid, total = _collect(tofs, max_sigma=None)
    assert wrong <= 0.001 * valid and valid > 0.3 * total, (wrong, valid, total)


# --------------------------------------------------------------------------- flags
def test_flags_saturation_low_signal_and_inconsistency():
    near = _wall(0.2, "mask2", (16, 16), noise=False)         # taps at full scale
    res = tof_depth(near)
    assert np.all(res.flags & FLAG_SATURATED) and not res.valid.any()

    far = _wall(7.0, "mask1", (16, 16), seed=1)
    res = tof_depth(far)
    assert np.mean(res.flags & FLAG_LOW_SIGNAL > 0) > 0.9
    loose = tof_depth(far, min_snr=0, max_residual=100, max_sigma=None, flying_step=None,
                      min_reflectance=0)
    # only the guard at the end of the range is left: 7 m is within 5 sigma of 7.495 m,
    # and a site whose noise carries it past the end wraps to just below 0
    assert np.all((loose.flags & ~np.uint8(FLAG_OUT_OF_RANGE)) == 0)
    assert np.all(loose.valid | (loose.depth > U - 5 * loose.sigma) | (loose.depth < 0))

    # three frequencies that see three different distances: inconsistent
    base = _wall(1.0, "mask1", (8, 8), noise=False)
    other = _wall(1.3, "mask1", (8, 8), noise=False)
    taps = base.taps.copy()
    taps[2] = other.taps[2]
    mixed = ToFTaps(taps, base.frequencies, base.sites, base.block, base.bit_depth,
                    base.depth_true, base.valid, base.saturated, base.sensor, base.shape)
    res = tof_depth(mixed)
    assert np.all(res.flags & FLAG_INCONSISTENT) and np.all(res.residual > 0.15)
    assert tof_depth(mixed, max_residual=10).valid.all()

    # an amplitude floor
    res = tof_depth(base, min_amplitude=1e6)
    assert np.all(res.flags == FLAG_LOW_SIGNAL)


def test_saturated_measurements_stay_out_of_their_neighbours_means():
    depth = np.full((24, 24), 1.0)
    depth[:8, :8] = 0.12                                      # saturates on Mask1
    tof = _wall(depth, "mask1", (24, 24), noise=False)
    res = tof_depth(tof)
    sat = (res.flags & FLAG_SATURATED) > 0
    assert sat.any()
    ok = ~sat & (tof.depth_true == 1.0)
    np.testing.assert_allclose(res.depth[ok], 1.0, atol=5e-3)


def test_result_maps_and_the_parameter_object():
    frame = simulate(Scene(np.full((16, 24, 3), 0.4), depth=np.full((16, 24), 1.7)),
                     "mask2", noise=False)
    res = tof_depth(frame)                                    # a RawFrame is accepted
    assert isinstance(res, ToFDepth) and res.n_sites == frame.tof.n_sites
    dm = res.depth_map()
    assert dm.shape == (16, 24)
    np.testing.assert_array_equal(np.isnan(dm), ~frame.z_mask)
    np.testing.assert_allclose(dm[frame.z_mask], 1.7, atol=1e-2)        # quantised taps
    amp = res.to_frame("amplitude")
    assert amp.shape == (3, 16, 24)
    valid = res.to_frame("valid", fill=False)
    assert valid.dtype == bool and valid.sum() == 4 * res.valid.sum()
    np.testing.assert_array_equal(res.to_frame(np.arange(res.n_sites), fill=-1),
                                  frame.tof.to_frame(np.arange(res.n_sites), fill=-1))
    # a fill of 0 keeps a bool map bool (uint8 before: its ~ was 254/255, never false); the
    # taps paint (F, n) as the result does, and bool with their float fill as float32
    for fill in (0, False, 1, np.int64(0)):
        assert res.to_frame("valid", fill=fill).dtype == bool
        assert frame.tof.to_frame(res.valid, fill=fill).dtype == bool
    np.testing.assert_array_equal(~res.to_frame("valid", fill=0), ~valid)
    assert frame.tof.to_frame(res.valid).dtype == np.float32
    np.testing.assert_array_equal(frame.tof.to_frame(frame.tof.amplitude(frequency="all")),
                                  res.to_frame(frame.tof.amplitude(frequency="all"), fill=0.0))
    chain = ToFISP(window=3, min_snr=2.0)
    hash(chain)
    a = chain.run(frame.tof, workers=1)
    b = tof_depth(frame.tof, window=3, min_snr=2.0, workers=2)
    np.testing.assert_array_equal(a.depth, b.depth)
    np.testing.assert_array_equal(a.flags, b.flags)
    assert "valid" in repr(res)


def test_one_parameter_rule_params_plus_overrides():
    """tof_depth takes a ToFISP (or a dict of its fields) and keyword overrides of its fields,
    checked once by ToFISP; unknown names and bad params are TypeErrors naming them."""
    tof = _wall(np.tile(np.linspace(0.8, 2.5, 32), (32, 1)), "mask2", (32, 32), seed=5)
    want = ToFISP(denoise="box", min_snr=3.0, flying_step=None).run(tof)
    for got in (tof_depth(tof, params=ToFISP(denoise="box"), min_snr=3, flying_step=None),
                tof_depth(tof, params={"denoise": "box", "min_snr": 3}, flying_step=None),
                tof_depth(tof, params=ToFISP(denoise="box", min_snr=9, flying_step=None),
                          min_snr=3.0)):
        np.testing.assert_array_equal(got.depth, want.depth)
        np.testing.assert_array_equal(got.flags, want.flags)
    assert ToFISP().replace(min_snr=3).min_snr == 3.0
    with pytest.raises(TypeError, match=r"tof_depth\(\) got an unexpected keyword argument "
                                        r"'snr' \(fields of ToFISP: denoise, window"):
        tof_depth(tof, snr=3)
    with pytest.raises(TypeError, match="params: expected a ToFISP, a dict of its fields or "
                                        "None, got str"):
        tof_depth(tof, params="box")
    with pytest.raises(ValueError, match="min_snr: expected a finite number >= 0, got -1"):
        tof_depth(tof, params=ToFISP(), min_snr=-1)


def test_thread_count_does_not_change_the_result():
    tof = _wall(np.tile(np.linspace(0.5, 4, 64), (64, 1)), "mask1", (64, 64), seed=3)
    a, b = tof_depth(tof, workers=1), tof_depth(tof, workers=2)
    for name in ("depth", "residual", "snr", "flags", "phase", "amplitude"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name))


# --------------------------------------------------------------------------- bad input
def test_bad_input_names_the_parameter():
    tof = _wall(1.0, "mask1", (8, 8), noise=False)
    no_tof = rz.mosaic(np.full((8, 8, 3), 0.5), "mask1")
    cases = [
        (lambda: tof_depth(no_tof), ValueError, "tof"),
        (lambda: tof_depth(np.zeros((3, 4, 5))), TypeError, "tof"),
        (lambda: tof_depth(tof, window=4), ValueError, "window"),
        (lambda: tof_depth(tof, window=0), ValueError, "window"),
        (lambda: tof_depth(tof, min_snr=-1), ValueError, "min_snr"),
        (lambda: tof_depth(tof, min_amplitude="x"), TypeError, "min_amplitude"),
        (lambda: tof_depth(tof, max_residual=0), ValueError, "max_residual"),
        (lambda: tof_depth(tof, max_range=-2), ValueError, "max_range"),
        (lambda: tof_depth(tof, denoise="yes"), ValueError, "denoise"),
        (lambda: tof_depth(tof, denoise=1), ValueError, "denoise"),
        (lambda: tof_depth(tof, range_scale=0), ValueError, "range_scale"),
        (lambda: tof_depth(tof, max_sigma=-1), ValueError, "max_sigma"),
        (lambda: tof_depth(tof, flying_step=0), ValueError, "flying_step"),
        (lambda: tof_depth(tof, min_reflectance=2), ValueError, "min_reflectance"),
        (lambda: tof_depth(tof, calibration="cal.npz"), TypeError, "calibration"),
        (lambda: ToFISP(denoise="median"), ValueError, "denoise"),
        (lambda: ToFISP(max_sigma=0), ValueError, "max_sigma"),
        (lambda: tof_depth(tof, workers=0), ValueError, "workers"),
        (lambda: ToFISP(window=2), ValueError, "window"),
        (lambda: ToFISP(max_residual=float("inf")), ValueError, "max_residual"),
        (lambda: demodulate(np.zeros((3, 3, 5))), ValueError, "taps"),
        (lambda: demodulate(np.full((1, 4, 2), np.nan)), ValueError, "taps"),
        (lambda: demodulate(np.zeros((1, 4, 2), complex)), TypeError, "taps"),
        (lambda: unwrap(np.zeros((2, 4)), [1e8]), ValueError, "frequencies"),
        (lambda: unwrap(np.zeros((1, 4)), [1e8], weights=[-1]), ValueError, "weights"),
        (lambda: unwrap(np.full((1, 4), np.inf), [1e8]), ValueError, "phase"),
        (lambda: denoise_phasors(np.zeros((1, 3)), np.zeros((1, 3)), ([0, 2], [0, 2])),
         ValueError, "sites"),
        (lambda: denoise_phasors(np.zeros((1, 2)), np.zeros((1, 2)), ([0, 2], [0, 2]),
                                 block=3), ValueError, "block"),
        (lambda: ToFDepth.to_frame(tof_depth(tof), "nothing"), ValueError, "values"),
        (lambda: tof_depth(tof).to_frame(np.zeros(3)), ValueError, "values"),
    ]
    for make, exc, name in cases:
        with pytest.raises(exc, match=name):
            make()


# --------------------------------------------------------------------------- RGB-D scenes
RGBD = ("art", "aloe", "baby1", "bowling1", "flowerpots", "rocks1")


def test_rgbd_scenes_meet_the_depth_targets():
    """The six Middlebury scenes at default settings: over all six, at most 0.1 % of
    the known measurements are valid and more than 5 cm off, and at least 95 % of those more
    than 5 cm off are flagged; no valid measurement unwraps wrongly. The full table is
    ``rgbz-fast evaluate-depth --sections scenes`` (docs/reports/isp.md)."""
    shared_path("rgbd")
    for pattern in ("mask1", "mask2"):
        known = wrong = wrong_valid = unwrap_valid = valid = 0
        for name in RGBD:
            scene = load_rgbd(SHARED_DATA / "rgbd" / name)
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                tof = simulate_tof(scene, pattern, seed=1)
            res = tof_depth(tof)
            k = tof.valid
            err = np.abs(res.depth - tof.depth_true)
            off = (err > 0.05) & k
            known += int(k.sum())
            valid += int((res.valid & k).sum())
            wrong += int(off.sum())
            wrong_valid += int((off & res.valid).sum())
            unwrap_valid += int(((err > WRONG) & res.valid & k).sum())
            ok = res.valid & k
            assert np.sqrt(np.mean((res.depth - tof.depth_true)[ok] ** 2)) < 0.02, (name, pattern)
        assert unwrap_valid == 0, pattern
        assert wrong_valid <= 0.001 * known, (pattern, wrong_valid, known)
        assert wrong - wrong_valid >= 0.95 * wrong, (pattern, wrong_valid, wrong)
        assert valid > (0.6 if pattern == "mask1" else 0.85) * known, (pattern, valid, known)


def test_an_alias_implying_a_bright_surface_is_out_of_range():
    """E1 of the probes (2026-11-27): with 80/100/120.1 MHz, whose wrong wrap combinations lie
    close in phase, a 0.8 m wall of reflectance 0.5 read valid at 8.3 m and 1492 m (implied
    reflectance 54 and 1.7e6), residual and SNR unremarkable. max_reflectance (4) flags them
    out of range; None keeps them (retroreflectors), and the default set is unaffected."""
    from rgbz_fast import ToFSensor
    from rgbz_fast.simulation import Scene, simulate_tof
    from rgbz_fast.tof import FLAG_OUT_OF_RANGE, ToFISP

    scene = Scene(np.full((64, 64, 3), 0.5), depth=np.full((64, 64), 0.8),
                  ir_reflectance=np.full((64, 64), 0.5))
    taps = simulate_tof(scene, "mask2", ToFSensor(frequencies=(80e6, 100e6, 120.1e6)), seed=2)
    loose = ToFISP(max_reflectance=None).run(taps)
    off = loose.valid & (np.abs(loose.depth - 0.8) > 0.05)
    assert off.sum() >= 5 and loose.reflectance[off].min() > 4
    r = ToFISP().run(taps)
    assert not (r.valid & (np.abs(r.depth - 0.8) > 0.05)).any()
    assert np.all(r.flags[off] & FLAG_OUT_OF_RANGE)
    np.testing.assert_array_equal(r.valid, loose.valid & ~off)     # nothing else changes
    plain = simulate_tof(scene, "mask2", seed=2)
    np.testing.assert_array_equal(ToFISP().run(plain).flags,
                                  ToFISP(max_reflectance=None).run(plain).flags)


@pytest.mark.parametrize("field", ["window", "low_signal_window"])
def test_a_window_without_a_denoise_is_refused(field):
    """E4 of the probes (2026-11-27): denoise='none' with a window (or low_signal_window, which
    ran the chain twice) had changed nothing, without a word."""
    from rgbz_fast.tof import ToFISP

    with pytest.raises(ValueError, match=rf"^{field}: sets the denoise's window"):
        ToFISP(denoise="none", **{field: 41})
    ToFISP(denoise="box", window=7, low_signal_window=41)
