"""Phase calibration from a flat-wall sweep: known offsets and harmonics are
recovered, the residual cyclic error on a sweep the fit did not see is below 1 mm, the file
round-trips, and mismatched or malformed input is refused."""

from __future__ import annotations

import warnings
from dataclasses import replace

import numpy as np
import pytest

from rgbz_fast.simulation import SPEED_OF_LIGHT, Scene, ToFSensor, simulate_tof
from rgbz_fast.tof import ToFCalibration, calibrate, tof_depth

C = SPEED_OF_LIGHT


def _wall(d, sensor, shape=(24, 32), *, seed=0, noise=True, ir=0.8, pattern="mask2"):
    scene = Scene(np.full(shape + (3,), 0.5), depth=np.full(shape, float(d)),
                  ir_reflectance=np.full(shape, ir))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return simulate_tof(scene, pattern, sensor, seed=seed, noise=noise)


def _sweep(sensor, distances, **kw):
    return [_wall(d, sensor, seed=k, **kw) for k, d in enumerate(distances)]


def test_calibration_recovers_known_offsets_and_harmonics():
    """Noise-free taps of a sensor with per-pixel delays and a 3rd harmonic: the offsets are
    2 pi f tau for every pixel and frequency, and the fitted cyclic error is the one the
    harmonic gives (``phi - g(phi)`` undoes it)."""
    sensor = ToFSensor(quantise=False, delay_ps=40.0, delay_fpn_ps=30.0,
                       harmonics=((3, 0.05, 0.4),), optical_power_w=0.2)
    ds = np.linspace(0.6, 2.6, 40)
    cal = calibrate(_sweep(sensor, ds, noise=False), ds)
    from rgbz_fast.simulation._tof_light import _pixel_delays
    rows, cols = _wall(1.0, sensor, noise=False).sites
    tau = _pixel_delays(sensor, rows, cols) * 1e-12
    f = np.array(sensor.frequencies)[:, None]
    want = np.angle(np.exp(1j * 2 * np.pi * f * tau[None]))
    # the offsets absorb a little of the cyclic error (its slope, weighted by the near
    # walls' brighter returns): within 5 mrad of the delays (0.8 mm at 100 MHz)
    np.testing.assert_allclose(cal.offsets, want, atol=5e-3)
    # and the correction as a whole: unseen noise-free walls, every pixel within 1 mm (the
    # model takes g of the phase less the per-pixel deviation, not of the phase itself: a
    # residual of g' times the deviation), their mean within 0.2 mm
    for d in (0.73, 1.41, 2.22):
        res = tof_depth(_wall(d, sensor, noise=False), calibration=cal, denoise="none")
        np.testing.assert_allclose(res.depth, d, atol=1e-3)
        assert abs(res.depth.mean() - d) < 2e-4
        assert np.abs(tof_depth(_wall(d, sensor, noise=False), denoise="none").depth
                      - d).max() > 5e-3
    # the cyclic error of harmonic 3 acts on the phase the pixel sees, u = phi + o: it
    # measures the phase of e^{i u} + b e^{-i(3 u + theta)}; for a pixel of mean offset the
    # correction gives back phi = u - mean(o)
    u = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    measured = np.mod(np.angle(np.exp(1j * u) + 0.05 * np.exp(-1j * (3 * u + 0.4))),
                      2 * np.pi)
    corrected = cal.correct_phase(np.tile(measured, (3, 1)))
    err = np.angle(np.exp(1j * (corrected - (u[None] - cal.mean_offset[:, None]))))
    assert np.sqrt(np.mean(err ** 2)) < 2e-3
    assert np.abs(err).max() < 1e-2        # between the 40 phases the sweep sampled
    assert cal.meta["frames"] == 40 and cal.orders == 8
    assert max(cal.meta["fit_rms_m"]) < 1e-3


def test_residual_cyclic_error_below_a_millimetre_on_unseen_walls():
    """Noisy sweep (48 positions x 2 frames) with harmonics 3 and 5, a tap-contrast mismatch
    and delays; checked on 20 other positions x 3 frames: the mean depth error per position
    (the cyclic error) drops to <= 1 mm RMS."""
    sensor = ToFSensor(harmonics=((3, 0.04, 0.3), (5, 0.015, -0.5)),
                       tap_contrast=(1.0, 0.97, 1.02, 0.99), delay_ps=300.0, delay_fpn_ps=20.0)
    fit_d = np.repeat(np.linspace(0.6, 2.6, 48), 2)
    cal = calibrate([_wall(d, sensor, (48, 64), seed=100 + k) for k, d in enumerate(fit_d)],
                    fit_d)
    check_d = np.linspace(0.65, 2.55, 20)

    def per_position(calibration):
        means = []
        for k, d in enumerate(check_d):
            errs = []
            for j in range(3):
                res = tof_depth(_wall(d, sensor, (48, 64), seed=5000 + 10 * k + j),
                                calibration=calibration)
                errs.append(res.depth[res.valid] - d)
            means.append(np.concatenate(errs).mean())
        return np.array(means)

    before = per_position(None)
    after = per_position(cal)
    assert np.sqrt(np.mean(before ** 2)) > 0.04           # 300 ps: 4.5 cm
    assert np.sqrt(np.mean((before - before.mean()) ** 2)) > 2e-3
    assert np.sqrt(np.mean(after ** 2)) < 1e-3


def test_a_lit_frame_is_refused_as_a_dark_one():
    """A frame of a lit wall given as dark had its taps' means subtracted as dark offsets:
    the calibration was written, its fit residual tripled."""
    sensor = ToFSensor(harmonics=((3, 0.05, 0.4),))
    ds = list(np.linspace(0.6, 2.6, 8))
    with pytest.raises(ValueError, match=r"^dark: frame 1 holds modulated light \(its phasors "
                                         r"carry .* times the power of its noise\)"):
        calibrate(_sweep(sensor, ds), ds, orders=2,
                  dark=[_wall(1.0, replace(sensor, optical_power_w=1e-12,
                                           ambient_irradiance=0.0), seed=0),
                        _wall(1.5, sensor, seed=1)])


def test_dark_frames_remove_the_tap_offsets():
    # 1 W: every wall of the sweep above the SNR floor (with 0.2 W the walls beyond 1.5 m gave
    # the fit nothing, calibrate now refuses the sweep's gap, and 1.7 m lay outside it)
    sensor = ToFSensor(dsnu=50.0, optical_power_w=1.0, quantise=False, shot_noise=False,
                       read_noise=0.0)
    ds = np.linspace(0.6, 2.6, 24)
    capped = replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0)
    dark = [_wall(1.0, capped, seed=k) for k in range(4)]
    cal = calibrate(_sweep(sensor, ds), ds, orders=4, dark=dark)
    assert cal.dark is not None and cal.dark.shape == (4, cal.offsets.shape[1])
    # the dark offset of each tap is its DSNU (in DN) plus the dark signal
    k = sensor.system_gain
    assert np.std(cal.dark) == pytest.approx(50.0 * k, rel=0.25)
    plain = calibrate(_sweep(sensor, ds), ds, orders=4)
    err = [np.abs(tof_depth(_wall(1.7, sensor, seed=99), calibration=c, denoise="none").depth
                  - 1.7).mean() for c in (plain, cal)]
    assert err[1] < 0.5 * err[0]
    # the dark frame takes the DSNU off the taps, and sigma no longer holds it: the spread of
    # the depths shrinks with it (the ISP's model keeps the shot noise the sensor leaves out)
    wall = _wall(1.7, sensor, seed=98)
    res = {c: tof_depth(wall, calibration=x) for c, x in
           (("dark", cal), ("kept", replace(cal, dark=None)))}
    s_dark, s_kept = (float(np.median(res[c].sigma)) for c in ("dark", "kept"))
    assert s_dark < 0.8 * s_kept
    assert np.std(res["dark"].depth - 1.7) < 0.5 * np.std(res["kept"].depth - 1.7)


def test_dark_offsets_know_their_own_noise():
    """The dark offsets are a mean of noisy frames: their error is a fixed offset per tap,
    the same at every frequency, which the ISP's sigma takes in place of the DSNU they
    remove (meta["dark_noise_dn2"]); two dark sets of other seeds differ by twice it."""
    from rgbz_fast.tof._calibration import _dark_offsets

    sensor = ToFSensor()
    capped = replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0)
    first = _wall(1.0, sensor, (48, 64), seed=0)
    sets = [_dark_offsets([_wall(1.0, capped, (48, 64), seed=10 * j + k) for k in range(4)],
                          first) for j in range(2)]
    (d1, v1), (d2, v2) = sets
    assert v1 == pytest.approx(v2, rel=0.05)
    assert np.var(d1 - d2) / 2 == pytest.approx(v1, rel=0.15)
    # the DSNU (5 e-) the offsets hold, beside their own error
    k = sensor.system_gain
    assert np.var(d1) == pytest.approx((5.0 * k) ** 2 + v1, rel=0.2)


def test_save_load_and_check(tmp_path):
    sensor = ToFSensor(delay_ps=20.0)
    ds = np.linspace(0.6, 2.6, 20)
    cal = calibrate(_sweep(sensor, ds), ds, orders=4)
    path = cal.save(tmp_path / "cal.npz")
    back = ToFCalibration.load(path)
    np.testing.assert_array_equal(back.offsets, cal.offsets)
    np.testing.assert_array_equal(back.coefficients, cal.coefficients)
    assert back.shape == cal.shape and back.block == cal.block
    assert back.meta["fit_rms_m"] == cal.meta["fit_rms_m"]
    tof = _wall(1.3, sensor, seed=5)
    a, b = tof_depth(tof, calibration=cal), tof_depth(tof, calibration=back)
    np.testing.assert_array_equal(a.depth, b.depth)
    assert "ToFCalibration(" in repr(cal)
    # another layout or frequency set is refused, naming the calibration
    with pytest.raises(ValueError, match="calibration: made for"):
        tof_depth(_wall(1.3, sensor, shape=(24, 36)), calibration=cal)
    with pytest.raises(ValueError, match="calibration: measured at"):
        tof_depth(_wall(1.3, ToFSensor(frequencies=(80e6, 100e6))), calibration=cal)
    with pytest.raises(ValueError, match="calibration: made for"):
        tof_depth(_wall(1.3, sensor, pattern="mask1"), calibration=cal)


def test_bad_calibration_input(tmp_path):
    sensor = ToFSensor()
    sweep = _sweep(sensor, [1.0, 1.5, 2.0])
    (tmp_path / "junk.npz").write_bytes(b"not a zip")
    np.savez(tmp_path / "other.npz", a=np.zeros(2))
    cases = [
        (lambda: calibrate(sweep[:1], [1.0]), ValueError, "sweep: expected at least 2"),
        (lambda: calibrate(5, [1.0]), TypeError, "sweep"),
        (lambda: calibrate([1, 2], [1.0, 2.0]), TypeError, "sweep"),
        (lambda: calibrate(sweep, [1.0, 2.0]), ValueError, "distances: expected 3"),
        (lambda: calibrate(sweep, [1.0, -2.0, 3.0]), ValueError, "distances: entry 1"),
        (lambda: calibrate(sweep, [1.0, np.zeros(5), 3.0]), ValueError, "distances: entry 1"),
        (lambda: calibrate(sweep, [1.0, 1.5, 2.0]), ValueError, "distances: 3 distinct"),
        (lambda: calibrate(sweep, [1.0, 1.5, 2.0], orders=0), ValueError, "orders"),
        (lambda: calibrate(sweep, [1.0, 1.5, 2.0], orders=1, iterations=0), ValueError,
         "iterations"),
        (lambda: calibrate(sweep + [_wall(1.0, sensor, shape=(24, 36))], [1, 1.5, 2, 2.5]),
         ValueError, "sweep: every frame"),
        (lambda: calibrate(sweep, [1.0, 1.5, 2.0], orders=1, dark=[]), ValueError, "dark"),
        (lambda: calibrate(_sweep(sensor, [0.05, 0.06, 0.07]), [0.05, 0.06, 0.07], orders=1),
         ValueError, "sweep: .* no usable frame"),
        (lambda: ToFCalibration.load(tmp_path / "missing.npz"), FileNotFoundError, "path"),
        (lambda: ToFCalibration.load(tmp_path / "junk.npz"), ValueError, "path"),
        (lambda: ToFCalibration.load(tmp_path / "other.npz"), ValueError, "path"),
        (lambda: ToFCalibration([80e6, 100e6, 120e6], np.zeros((2, 4)), np.zeros((3, 2, 2)),
                                ([0, 0, 0, 0], [0, 1, 2, 3]), 1, (4, 4)), ValueError,
         "offsets"),
        (lambda: ToFCalibration(np.ones(1), np.zeros((1, 2)), np.zeros((1, 2)),
                                ([0, 0], [0, 1]), 1, (4, 4)), ValueError, "coefficients"),
        (lambda: ToFCalibration(np.ones(1), np.full((1, 2), np.nan), np.zeros((1, 2, 2)),
                                ([0, 0], [0, 1]), 1, (4, 4)), ValueError, "offsets"),
    ]
    for make, exc, name in cases:
        with pytest.raises(exc, match=name):
            make()


def test_a_sweep_that_leaves_the_phase_circle_open_is_refused():
    """17 walls over 0.6-1.2 m (a third of the 1.874 m wrap of 80 MHz) had fitted
    coefficients of 1000 rad, reported a residual of 0.64 mm and put a wall at 1.25 m 3.4 m
    away, valid."""
    sensor = ToFSensor(harmonics=((3, 0.04, 0.3),), delay_ps=300.0, delay_fpn_ps=20.0)
    ds = np.linspace(0.6, 1.2, 17)
    with pytest.raises(ValueError, match=r"^distances: the walls leave 68 % of the phase "
                                         r"circle of 80 MHz unmeasured"):
        calibrate(_sweep(sensor, ds), ds)
    ds = np.linspace(0.6, 2.6, 17)                     # over a wrap: accepted
    assert calibrate(_sweep(sensor, ds), ds).coefficients.shape[1] == 8
