"""Round 22: a calibration's cyclic-error coefficients and dark offsets are bounded where it
is made (coefficients of 1e308 overflowed later in ``tof_depth``, dark offsets of 1e5 DN
silently changed sigma), and ``calibrate(dark=)`` refuses dark frames of another layout
(other sites, frame shape or block) as the sweep's frames are refused (any frequencies)."""

from __future__ import annotations

import warnings
from dataclasses import replace

import numpy as np
import pytest

from rgbz_fast.simulation import Scene, ToFSensor, simulate_tof
from _support import calibration_fields
from rgbz_fast.tof import ToFCalibration, calibrate




def test_coefficients_and_dark_offsets_beyond_physics_are_refused(tmp_path):
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # no overflow RuntimeWarning leaks out
        for coef in (np.full((2, 2, 2), 1e308), np.full((2, 2, 2), 1.2)):
            with pytest.raises(ValueError, match=r"^coefficients: the cyclic error at 80 MHz "
                                                 r"reaches sum_k \|\(a_k, b_k\)\| (> 1\.8e\+308"
                                                 r"|= 3\.39) rad; a phase correction is at "
                                                 r"most pi \(a half turn\)$"):
                ToFCalibration(**calibration_fields(coefficients=coef))
        for value, shown in ((1e5, "1e+05"), (-1e308, "1e+308")):
            with pytest.raises(ValueError, match=rf"^dark: offsets of up to {re_num(shown)} "
                                                 r"DN; .* lies within \[-65536, 65536\] DN"):
                ToFCalibration(**calibration_fields(dark=np.full((4, 3), value)))
    # the bounds themselves are accepted: sum_k |(a_k, b_k)| = pi, offsets of 2**16 DN
    coef = np.zeros((2, 2, 2))
    coef[:, 0, 0], coef[:, 1, 1] = np.pi / 2, -np.pi / 2
    cal = ToFCalibration(**calibration_fields(coefficients=coef, dark=np.full((4, 3), -65536.0)))
    # an edited file is refused by load, naming the path and the field
    cal.save(tmp_path / "cal.npz")
    arrays = dict(np.load(tmp_path / "cal.npz"))
    arrays["coefficients"] = np.full((2, 2, 2), 1e308)
    np.savez(tmp_path / "bad.npz", **arrays)
    with pytest.raises(ValueError, match=r"^path: .*bad\.npz is a damaged ToF calibration "
                                         r"file \(ValueError: coefficients: the cyclic error"):
        ToFCalibration.load(tmp_path / "bad.npz")


def re_num(text):
    return text.replace("+", r"\+").replace(".", r"\.")


def _wall(d, shape, sensor, seed, pattern="mask1"):
    scene = Scene(np.full(shape + (3,), 0.5), depth=np.full(shape, float(d)),
                  ir_reflectance=np.full(shape, 0.8))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return simulate_tof(scene, pattern, sensor, seed=seed)


def test_dark_frames_of_another_layout_are_refused():
    sensor = ToFSensor()
    ds = np.linspace(0.6, 2.6, 12)
    sweep = [_wall(d, (16, 24), sensor, k) for k, d in enumerate(ds)]
    capped = replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0)
    right = [_wall(1.0, (16, 24), capped, 900 + k) for k in range(2)]
    other = replace(capped, frequencies=(20e6,))
    cases = {       # each as many Z measurements as the sweep's 96 (16x24, block 1)
        "sites": ([_wall(1.0, (24, 16), capped, 900)],
                  r"a 24x16 frame, not 16x24; Z measurements at other sites"),
        "block": ([_wall(1.0, (32, 48), capped, 900, "mask2")],
                  r"a 32x48 frame, not 16x24; block 2, not 1; Z measurements at other "
                  r"sites"),
    }
    for name, (dark, why) in cases.items():
        k = len(dark) - 1
        with pytest.raises(ValueError, match=r"^dark: every frame must hold the same "
                                             r"Z measurements as the sweep "
                                             rf"\(frame {k}: {why}\)$"):
            calibrate(sweep, ds, orders=3, dark=dark)
    # the sweep's own check gives the same message (naming sweep), now with what differs
    with pytest.raises(ValueError, match=r"^sweep: every frame must hold the same frequencies "
                                         r"and Z measurements \(frame 11: a 24x16 frame"):
        calibrate(sweep[:-1] + [_wall(2.6, (24, 16), sensor, 99)], ds, orders=3)
    # dark frames of the sweep's layout are accepted, also with another black level (each
    # offset is measured above its own frame's black level)
    cal = calibrate(sweep, ds, orders=3, dark=right)
    assert cal.dark.shape == (4, 96)
    # at any frequencies (a capped lens passes no modulated light; the review of
    # 2026-11-27 found one-frequency dark frames refused by the first form of this check)
    one = calibrate(sweep, ds, orders=3, dark=[_wall(1.0, (16, 24), other, 900 + k)
                                               for k in range(2)])
    assert one.dark.shape == (4, 96) and np.allclose(one.dark, cal.dark, atol=5.0)
    lifted = [_wall(1.0, (16, 24), replace(capped, black_level=200.0), 900 + k)
              for k in range(2)]
    assert np.allclose(calibrate(sweep, ds, orders=3, dark=lifted).dark, cal.dark, atol=5.0)


def test_dark_frames_of_another_bit_depth_or_gain_are_refused():
    """Dark offsets are in the dark frame's DN: a dark frame read out at another bit depth or
    system gain than the sweep had its offsets subtracted from the sweep's taps as they were
    (a 12-bit capped lens under a 10-bit sweep: offsets about 4x too large, no word)."""
    sensor = ToFSensor()
    ds = np.linspace(0.6, 2.6, 12)
    sweep = [_wall(d, (16, 24), sensor, k) for k, d in enumerate(ds)]
    capped = replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0)
    deeper = replace(capped, bit_depth=sensor.bit_depth + 2)
    with pytest.raises(ValueError, match=rf"^dark: frame 1 was read out differently from the "
                                         rf"sweep \({deeper.bit_depth}-bit, not "
                                         rf"{sensor.bit_depth}-bit\)"):
        calibrate(sweep, ds, orders=3, dark=[_wall(1.0, (16, 24), capped, 900),
                                            _wall(1.0, (16, 24), deeper, 901)])
    gained = replace(capped, conversion_gain_uv_per_e=2 * sensor.conversion_gain_uv_per_e)
    with pytest.raises(ValueError, match=r"^dark: frame 0 was read out differently from the "
                                         r"sweep \([0-9.]+ DN per electron, not [0-9.]+\)"):
        calibrate(sweep, ds, orders=3, dark=[_wall(1.0, (16, 24), gained, 900)])
    # the same readout with another black level or optical power is a dark frame
    assert calibrate(sweep, ds, orders=3,
                     dark=[_wall(1.0, (16, 24), replace(capped, black_level=100.0), 900)]
                     ).dark.shape == (4, 96)


def test_a_dark_calibration_refuses_taps_of_another_readout(tmp_path):
    """The dark offsets are in the sweep's DN: the ISP refuses taps read out at another bit
    depth or gain than the calibration's (they had been subtracted as they were), also after
    a save and load; a calibration without dark frames takes any readout."""
    from rgbz_fast import ToFISP

    sensor = ToFSensor()
    ds = np.linspace(0.6, 2.6, 12)
    sweep = [_wall(d, (16, 24), sensor, k) for k, d in enumerate(ds)]
    capped = replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0)
    cal = calibrate(sweep, ds, orders=3, dark=[_wall(1.0, (16, 24), capped, 900)])
    assert cal.meta["dark_bit_depth"] == sensor.bit_depth
    cal.save(tmp_path / "cal.npz")
    loaded = ToFCalibration.load(tmp_path / "cal.npz")
    deeper = _wall(1.5, (16, 24), replace(sensor, bit_depth=sensor.bit_depth + 2), 7)
    gained = _wall(1.5, (16, 24), replace(sensor, conversion_gain_uv_per_e=2
                                          * sensor.conversion_gain_uv_per_e), 7)
    for c in (cal, loaded):
        with pytest.raises(ValueError, match=rf"^calibration: its dark offsets were measured "
                                             rf"at another readout \({sensor.bit_depth}-bit, "
                                             rf"the taps {sensor.bit_depth + 2}-bit\)"):
            ToFISP(calibration=c).run(deeper)
        with pytest.raises(ValueError, match=r"^calibration: its dark offsets were measured "
                                             r"at another readout \([0-9.]+ DN per electron"):
            ToFISP(calibration=c).run(gained)
        assert ToFISP(calibration=c).run(sweep[3]).depth.shape == (96,)
    undark = calibrate(sweep, ds, orders=3)
    assert ToFISP(calibration=undark).run(deeper).depth.shape == (96,)
