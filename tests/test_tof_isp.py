"""ToF ISP: demodulation, the pattern-aware denoise (Fig. 17), unwrapping over the whole
unambiguous range, validity flags, noisy walls and planes, and the RGB-D scenes."""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from conftest import SHARED_DATA, shared_path  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from rgbz_fast.scene import Scene, load_rgbd  # noqa: E402
from rgbz_fast.sensor import (SPEED_OF_LIGHT, ToFSensor, ToFTaps, simulate,  # noqa: E402
                              simulate_tof)
from rgbz_fast.tof_isp import (FLAG_INCONSISTENT, FLAG_LOW_SIGNAL, FLAG_SATURATED,  # noqa: E402
                               ToFDepth, ToFISP, demodulate, denoise_phasors, phasors,
                               tof_depth, unwrap)

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
    n = rows.size
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
    """Fig. 17: the 5x5 window of a Mask1 Z site holds 9 Z sites; Mask2 uses 3x3 Z pixels."""
    for pattern in ("mask1", "mask2"):
        tof = _wall(1.0, pattern, (40, 40), noise=False)
        res = tof_depth(tof)
        r, c = tof.sites
        interior = (r >= 8) & (r < 32) & (c >= 8) & (c < 32)
        assert np.all(res.count[interior] == 9)
        assert res.count.min() == 4                       # corners
        assert np.all(tof_depth(tof, window=1).count == 1)
        assert np.all(tof_depth(tof, denoise=False).count == 1)


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


@pytest.mark.parametrize("pattern,near,far", [("mask1", 2.0, 2.5), ("mask2", 3.5, 4.5)])
def test_noisy_flat_walls_unwrap_correctly(pattern, near, far):
    """Prints the wall table of docs/isp.md: ``pytest tests/test_tof_isp.py -k walls -s``."""
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
    # and there is a usable share up to `far`
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
    assert valid > 0.3 * total


# --------------------------------------------------------------------------- flags
def test_flags_saturation_low_signal_and_inconsistency():
    near = _wall(0.2, "mask2", (16, 16), noise=False)         # taps at full scale
    res = tof_depth(near)
    assert np.all(res.flags & FLAG_SATURATED) and not res.valid.any()

    far = _wall(7.0, "mask1", (16, 16), seed=1)
    res = tof_depth(far)
    assert np.mean(res.flags & FLAG_LOW_SIGNAL > 0) > 0.9
    assert tof_depth(far, min_snr=0, max_residual=100).valid.all()

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
    chain = ToFISP(window=3, min_snr=2.0)
    hash(chain)
    a = chain.run(frame.tof, workers=1)
    b = tof_depth(frame.tof, window=3, min_snr=2.0, workers=2)
    np.testing.assert_array_equal(a.depth, b.depth)
    np.testing.assert_array_equal(a.flags, b.flags)
    assert "valid" in repr(res)


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
        (lambda: tof_depth(tof, denoise="yes"), TypeError, "denoise"),
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


def test_rgbd_scenes_depth_rmse_and_wrong_unwraps():
    """Prints the numbers of docs/isp.md: ``pytest tests/test_tof_isp.py -k rgbd -s``."""
    shared_path("rgbd")
    print(f"\n{'scene':<11}{'pattern':<8}{'depth m':>12}{'valid':>8}{'RMSE cm':>9}"
          f"{'median cm':>10}{'wrong/valid':>12}{'wrong/all':>10}")
    summary = {}
    for name in RGBD:
        scene = load_rgbd(SHARED_DATA / "rgbd" / name)
        for pattern in ("mask1", "mask2"):
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                tof = simulate_tof(scene, pattern, seed=1)
            res = tof_depth(tof)
            known = tof.valid
            ok = res.valid & known
            err = res.depth - tof.depth_true
            wrong = np.abs(err) > WRONG
            rmse = float(np.sqrt(np.mean(err[ok] ** 2)))
            frac_valid = ok.sum() / known.sum()
            wrong_valid = wrong[ok].mean()
            wrong_all = wrong[known].mean()
            d = tof.depth_true[known]
            print(f"{name:<11}{pattern:<8}{d.min():>6.2f}-{d.max():<5.2f}{frac_valid:>8.3f}"
                  f"{100 * rmse:>9.2f}{100 * np.median(np.abs(err[ok])):>10.2f}"
                  f"{wrong_valid:>12.5f}{wrong_all:>10.4f}")
            summary[name, pattern] = (frac_valid, rmse, wrong_valid)
            assert wrong_valid <= 0.001
            assert rmse < 0.05
            assert frac_valid > (0.5 if pattern == "mask1" else 0.95)
    assert len(summary) == 2 * len(RGBD)
