"""Non-idealities of the i-ToF pixel: harmonics (cyclic error), tap contrasts,
per-frequency contrast, delays, multipath, ambient suppression and burst illumination.
Every one is off by default, and then the taps are the ideal model's."""

from __future__ import annotations

import numpy as np
import pytest

from rgbz_fast.simulation import SPEED_OF_LIGHT, Scene, ToFSensor, simulate_tof
from rgbz_fast.tof import tof_depth

C = SPEED_OF_LIGHT
F = np.array([80e6, 100e6, 120e6])


def _wall(depth, sensor, shape=(8, 8), pattern="mask1", noise=False, seed=0, ir=0.5):
    depth = np.broadcast_to(np.asarray(depth, float), shape)
    scene = Scene(np.full(shape + (3,), 0.5), depth=depth, ir_reflectance=np.full(shape, ir))
    return simulate_tof(scene, pattern, sensor, noise=noise, seed=seed)


def _phase(taps):
    t = np.asarray(taps, float)
    return np.mod(np.arctan2(t[:, 3] - t[:, 1], t[:, 0] - t[:, 2]), 2 * np.pi)


def _phase_error(sensor, distances):
    """Per-frequency phase error (rad) of noise-free one-cell taps at ``distances``."""
    t = sensor.tap_electrons(np.asarray(distances, float), 0.5)
    true = np.mod(4 * np.pi * F[:, None] * np.asarray(distances)[None] / C, 2 * np.pi)
    return np.angle(np.exp(1j * (_phase(t) - true)))


def test_defaults_are_ideal():
    s = ToFSensor()
    assert s.is_ideal and s.harmonics == () and s.multipath is None
    assert s.ambient_suppression == 0 and s.duty_cycle == 1
    np.testing.assert_array_equal(s.contrasts, [0.8, 0.8, 0.8])
    d = np.linspace(0.3, 3, 50)
    assert np.abs(_phase_error(s, d)).max() < 1e-12


@pytest.mark.parametrize("order,amp,theta", [(3, 0.05, 0.0), (3, 0.02, 1.0), (5, 0.04, -0.5)])
def test_cyclic_error_follows_the_harmonic_amplitude(order, amp, theta):
    """Four taps alias harmonic 3 onto -1 and 5 onto +1 (order h -> h mod 4 = 3 or 1):
    ``I + iQ = e^{i phi} + b e^{-+i(h phi + theta)}``, a phase error of peak ``asin(b)`` and
    period ``2 pi / (h -+ 1)``, i.e. 4 cycles per wrap for orders 3 and 5."""
    s = ToFSensor(quantise=False, harmonics=((order, amp, theta),))
    d = (np.arange(2000) + 0.5) * (C / (2 * 80e6)) / 2000          # one wrap of 80 MHz
    err = _phase_error(s, d)[0]
    assert np.abs(err).max() == pytest.approx(np.arcsin(amp), rel=1e-3)
    spectrum = np.abs(np.fft.rfft(err))
    assert np.argmax(spectrum) == 4                            # 4 cycles per 2 pi
    # even harmonics cancel in I = A0 - A2 and Q = A3 - A1
    even = ToFSensor(quantise=False, harmonics=((2, 0.1, 0.3), (4, 0.05, 0.0)))
    assert np.abs(_phase_error(even, d)).max() < 1e-12


def test_tap_contrast_mismatch_gives_an_error_at_twice_the_phase():
    s = ToFSensor(tap_contrast=(1.0, 0.95, 1.05, 1.0))
    d = (np.arange(2000) + 0.5) * (C / (2 * 80e6)) / 2000
    err = _phase_error(s, d)[0]
    assert np.argmax(np.abs(np.fft.rfft(err))) == 2
    assert 0.01 < np.abs(err).max() < 0.06


def test_contrast_per_frequency():
    s = ToFSensor(modulation_contrast=(0.9, 0.7, 0.5), quantise=False, dark_current=0.0)
    t = s.tap_electrons(np.array([1.3]), 0.5)[..., 0]
    i, q = t[:, 0] - t[:, 2], t[:, 3] - t[:, 1]
    amp = np.hypot(i, q) / 2
    active = 4 * t.mean(axis=1) - ToFSensor()._cell_electrons(np.array(1.3), 0.5, 2.8)[1]
    np.testing.assert_allclose(amp / (active / 4), [0.9, 0.7, 0.5], rtol=1e-12)
    with pytest.raises(ValueError, match="modulation_contrast: expected one number or one per"):
        ToFSensor(modulation_contrast=(0.9, 0.7))


def test_delays_shift_the_depth_by_c_tau_over_2():
    sensor = ToFSensor(quantise=False, delay_ps=150.0, optical_power_w=0.05)
    res = tof_depth(_wall(1.2, sensor), denoise="none")
    np.testing.assert_allclose(res.depth, 1.2 + C * 150e-12 / 2, atol=1e-9)
    fpn = ToFSensor(quantise=False, delay_fpn_ps=25.0, optical_power_w=0.05)
    a = _wall(1.2, fpn, shape=(32, 32))
    off_a = tof_depth(a, denoise="none").depth - 1.2
    assert off_a.std() == pytest.approx(C * 25e-12 / 2, rel=0.2)      # 256 draws
    # a fixed pattern of the sensor (fpn_seed): the same in a frame of another noise seed
    # (only the delays vary here), another with another fpn_seed
    quiet = dict(shot_noise=False, read_noise=0.0, dsnu=0.0, prnu=0.0)
    b = _wall(1.2, ToFSensor(**{**fpn.__dict__, **quiet}), shape=(32, 32), noise=True, seed=4)
    np.testing.assert_allclose(tof_depth(b, denoise="none").depth - 1.2, off_a, atol=1e-12)
    other = ToFSensor(**{**fpn.__dict__, "fpn_seed": 7})
    off_c = tof_depth(_wall(1.2, other, shape=(32, 32)), denoise="none").depth - 1.2
    assert abs(np.corrcoef(off_a, off_c)[0, 1]) < 0.3
    # and its own stream: PRNU/DSNU maps are unchanged by it
    plain = _wall(1.2, ToFSensor(), shape=(32, 32), noise=True, seed=4)
    zero = _wall(1.2, ToFSensor(delay_fpn_ps=0.0), shape=(32, 32), noise=True, seed=4)
    np.testing.assert_array_equal(plain.taps, zero.taps)


def test_two_path_multipath():
    r, extra = 0.3, 0.5
    s = ToFSensor(quantise=False, multipath=(r, extra), optical_power_w=0.05)
    res = tof_depth(_wall(1.0, s), denoise="none")
    phi1 = 4 * np.pi * F * 1.0 / C
    phi2 = 4 * np.pi * F * (1.0 + extra) / C
    want = np.mod(np.angle(np.exp(1j * phi1) + r * np.exp(1j * phi2)), 2 * np.pi)
    np.testing.assert_allclose(res.phase[:, 0], want, atol=1e-9)
    # the frequencies disagree on the distance: a depth between the two paths, a residual
    assert 1.0 < res.depth[0] < 1.5 and res.residual[0] > 0.01


def test_ambient_suppression_and_burst_keep_the_taps_out_of_saturation():
    sun = dict(ambient_irradiance=15.0)
    assert _wall(1.0, ToFSensor(**sun), noise=True, pattern="mask2").saturated.all()
    s = 0.9
    sbi = ToFSensor(**sun, ambient_suppression=s, quantise=False)
    plain = ToFSensor(**sun, quantise=False, full_well=np.inf, bit_depth=16)
    t_sbi = sbi.tap_electrons(np.array([1.0]), 0.5)[..., 0]
    t_plain = plain.tap_electrons(np.array([1.0]), 0.5)[..., 0]
    # the differences (I, Q) are kept, the common mode is drained
    np.testing.assert_allclose(t_sbi[:, 0] - t_sbi[:, 2], t_plain[:, 0] - t_plain[:, 2])
    np.testing.assert_allclose(t_sbi.mean(axis=1), (1 - s) * t_plain.mean(axis=1))
    assert not _wall(1.0, ToFSensor(**sun, ambient_suppression=s), noise=True,
                     pattern="mask2").saturated.any()
    # burst: the laser energy is kept, ambient light and dark current scale with the duty
    burst = ToFSensor(**sun, duty_cycle=0.1)
    s1, b1 = ToFSensor(**sun)._cell_electrons(np.array(1.0), 0.5, 2.8)
    s2, b2 = burst._cell_electrons(np.array(1.0), 0.5, 2.8)
    assert s2 == s1 and b2 == pytest.approx(0.1 * b1)
    assert burst._dark_electrons == pytest.approx(0.1 * ToFSensor()._dark_electrons)


def test_a_tap_drained_below_the_adc_floor_is_flagged():
    """A suppression that drains the weakest tap below the ADC's floor (0 DN) had passed the
    measurement as valid, its depth biased by 20 mm and its reflectance read low."""
    for quantise in (True, False):
        sensor = ToFSensor(ambient_suppression=0.9, quantise=quantise)
        for noise in (False, True):
            tof = _wall(0.27, sensor, shape=(24, 24), pattern="mask1", noise=noise, seed=1)
            assert tof.saturated.all()
            assert not tof_depth(tof).valid.any()


def test_the_suppression_drains_at_most_what_a_tap_holds():
    """H87: the suppression took s times the DC charge from every tap whatever it held, so
    the weakest tap of a deeply modulated pixel held down to -300 e- and read as valid data
    between the black level and the ADC's floor (Mask1 at 1 m with s = 0.5: a quarter of the
    taps negative, none flagged). It now empties such a tap, which is flagged; taps that
    hold more are drained as before."""
    s = ToFSensor(ambient_suppression=0.5, quantise=False)
    electrons = s.tap_electrons(np.array([1.0]), 0.5)[..., 0]
    emptied = electrons.min() <= 0                 # the model's tap before the drain's clip
    tof = _wall(1.0, s, shape=(24, 24), pattern="mask1", noise=False)
    assert emptied and tof.taps.min() >= s.black_level - 1e-9
    assert tof.saturated.all() and not tof_depth(tof).valid.any()
    held = ToFSensor(ambient_suppression=0.5, quantise=False, duty_cycle=0.1,
                     ambient_irradiance=15.0)
    tof = _wall(1.0, held, shape=(24, 24), pattern="mask1", noise=False)
    assert not tof.saturated.any() and tof_depth(tof).valid.all()


def test_sunlight_configuration_gives_mask2_depth_to_2_m():
    """Sunlight: Mask2 gives valid depth at 15 W/m^2 ambient up to 2 m for reflectance 0.5
    with burst illumination (duty 0.1), with or without a moderate ambient suppression
    (0.5); the default continuous-wave sensor saturates."""
    for sun in (ToFSensor(ambient_irradiance=15.0, duty_cycle=0.1),
                ToFSensor(ambient_irradiance=15.0, duty_cycle=0.1, ambient_suppression=0.5)):
        _valid_to_2_m(sun)
    res = tof_depth(_wall(1.0, ToFSensor(ambient_irradiance=15.0), shape=(64, 96),
                          pattern="mask2", noise=True, seed=3))
    assert not res.valid.any()


def _valid_to_2_m(sun):
    for d in (0.5, 1.0, 2.0):
        res = tof_depth(_wall(d, sun, shape=(64, 96), pattern="mask2", noise=True, seed=3))
        assert res.valid.mean() > 0.97, d
        assert np.abs(res.depth[res.valid] - d).max() < 0.05


def test_ambient_suppression_keeps_the_noise_model_right():
    """The ISP's noise model counts the drained charge's shot noise: on a flat wall the
    predicted sigma matches the spread of the depths."""
    sensor = ToFSensor(ambient_irradiance=5.0, ambient_suppression=0.9, dsnu=0.0, prnu=0.0)
    tof = _wall(1.0, sensor, shape=(96, 128), pattern="mask2", noise=True, seed=5)
    res = tof_depth(tof, denoise="none", max_sigma=None)
    assert res.depth.std() / np.sqrt(np.mean(res.sigma ** 2)) == pytest.approx(1.0, abs=0.15)


@pytest.mark.parametrize("kw,exc,name", [
    (dict(harmonics=((1, 0.1, 0.0),)), ValueError, "ToFSensor.harmonics order"),
    (dict(harmonics=((3, 1.5, 0.0),)), ValueError, "ToFSensor.harmonics amplitude"),
    (dict(harmonics=((3, 0.1),)), ValueError, "ToFSensor.harmonics"),
    (dict(harmonics=((3, 0.1, 0.0), (3, 0.1, 0.0))), ValueError, "ToFSensor.harmonics"),
    (dict(harmonics=3), TypeError, "ToFSensor.harmonics"),
    (dict(tap_contrast=(1, 1, 1)), ValueError, "ToFSensor.tap_contrast"),
    (dict(tap_contrast=(1, 1, 1, 0)), ValueError, "ToFSensor.tap_contrast"),
    (dict(delay_ps=np.nan), ValueError, "ToFSensor.delay_ps"),
    (dict(delay_fpn_ps=-1), ValueError, "ToFSensor.delay_fpn_ps"),
    (dict(multipath=(0.5,)), TypeError, "ToFSensor.multipath"),
    (dict(multipath=(0.5, 0.0)), ValueError, "ToFSensor.multipath extra path"),
    (dict(multipath=(2.0, 1.0)), ValueError, "ToFSensor.multipath amplitude"),
    (dict(ambient_suppression=1.0), ValueError, "ToFSensor.ambient_suppression"),
    (dict(duty_cycle=0.0), ValueError, "ToFSensor.duty_cycle"),
    (dict(modulation_contrast=(0.5, 0.5, 1.5)), ValueError, "ToFSensor.modulation_contrast"),
])
def test_bad_nonideality_names_the_parameter(kw, exc, name):
    with pytest.raises(exc, match=name):
        ToFSensor(**kw)
