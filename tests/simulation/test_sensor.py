"""Sensor models: colour pixels (PTC, noise-free = mosaic), i-ToF taps (convention,
1/d^2, depth noise against the analytic bound), the RGB-Z build, and what runs when."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from _support import load_kodak, shared_path  # noqa: E402

import rgbz_fast.simulation._simulate as sensor_mod  # noqa: E402
from rgbz_fast import G, RawFrame, bayer, mosaic  # noqa: E402
from rgbz_fast.simulation import Scene, load_spectral  # noqa: E402
from rgbz_fast.simulation import (SPEED_OF_LIGHT, ColourSensor, ToFSensor, ToFTaps,  # noqa: E402
                              UnambiguousRangeWarning, simulate, simulate_colour,
                              simulate_tof)

C = SPEED_OF_LIGHT


def _flat(shape=(64, 64), value=0.5, depth=None, ir=0.5):
    kw = {}
    if depth is not None:
        kw = dict(depth=np.broadcast_to(depth, shape).astype(float),
                  ir_reflectance=np.full(shape, ir))
    return Scene(np.full(shape + (3,), value), **kw)


def _phase(taps):
    """The documented convention: phi = atan2(A3 - A1, A0 - A2) in [0, 2 pi)."""
    t = np.asarray(taps, np.float64)
    return np.mod(np.arctan2(t[:, 3] - t[:, 1], t[:, 0] - t[:, 2]), 2 * np.pi)


# -- parameters ----------------------------------------------------------------------
def test_colour_defaults():
    s = ColourSensor()
    assert s.bit_depth == 11 and s.white_level == 2047
    assert s.system_gain == pytest.approx(100e-6 * 2047 / 1.0)
    assert s.usable_electrons() == pytest.approx((2047 - 64) / s.system_gain)
    np.testing.assert_allclose(s.electrons_per_unit(0.01),
                               2e5 * 2.8 ** 2 * np.array([0.40, 0.50, 0.35]) * 0.01)
    hash(s)                                            # frozen and hashable
    with pytest.raises(AttributeError):
        s.full_well = 5.0


def test_tof_defaults_and_ranges():
    t = ToFSensor()
    assert t.frequencies == (80e6, 100e6, 120e6)
    np.testing.assert_allclose(t.wrap_ranges, [C / 160e6, C / 200e6, C / 240e6])
    assert t.unambiguous_range == pytest.approx(C / (2 * 20e6))      # 7.495 m
    assert ToFSensor(frequencies=(100e6,)).unambiguous_range == pytest.approx(1.49896229)


@pytest.mark.parametrize("cls,kwargs,name", [
    (ColourSensor, dict(pixel_pitch_um=0), "pixel_pitch_um"),
    (ColourSensor, dict(full_well=-1), "full_well"),
    (ColourSensor, dict(conversion_gain_uv_per_e=0), "conversion_gain_uv_per_e"),
    (ColourSensor, dict(voltage_swing=float("nan")), "voltage_swing"),
    (ColourSensor, dict(bit_depth=20), "bit_depth"),
    (ColourSensor, dict(black_level=2047), "black_level"),
    (ColourSensor, dict(qe=(0.5, 1.2, 0.4)), "qe"),
    (ColourSensor, dict(qe=(0.5, 0.4)), "qe"),
    (ColourSensor, dict(photon_flux=0), "photon_flux"),
    (ColourSensor, dict(exposure=0.0), "exposure"),
    (ColourSensor, dict(exposure=-1e-3), "exposure"),
    (ColourSensor, dict(exposure="manual"), "exposure"),
    (ColourSensor, dict(ae_target=1.5), "ae_target"),
    (ColourSensor, dict(dark_current=-1), "dark_current"),
    (ColourSensor, dict(read_noise=-1), "read_noise"),
    (ColourSensor, dict(dsnu=-1), "dsnu"),
    (ColourSensor, dict(prnu=1.0), "prnu"),
    (ColourSensor, dict(fpn_seed=-1), "fpn_seed"),
    (ColourSensor, dict(sensitivities=([400, 500], [[1, 1, 1]])), "sensitivities"),
    (ToFSensor, dict(frequencies=(0.0,)), "frequencies"),
    (ToFSensor, dict(frequencies=(100e6, 100e6)), "frequencies"),
    (ToFSensor, dict(integration_time=0), "integration_time"),
    (ToFSensor, dict(wavelength_nm=500), "wavelength_nm"),
    (ToFSensor, dict(optical_power_w=-0.1), "optical_power_w"),
    (ToFSensor, dict(modulation_contrast=1.5), "modulation_contrast"),
    (ToFSensor, dict(fov_deg=(60, 190)), "fov_deg"),
    (ToFSensor, dict(f_number=0.1), "f_number"),
    (ToFSensor, dict(qe=0), "qe"),
    (ToFSensor, dict(ambient_irradiance=-1), "ambient_irradiance"),
    (ToFSensor, dict(z_block=3), "z_block"),
    (ToFSensor, dict(read_noise=float("inf")), "read_noise"),
])
def test_out_of_range_parameters_name_themselves(cls, kwargs, name):
    with pytest.raises(ValueError, match=f"{cls.__name__}.{name}"):
        cls(**kwargs)


def test_explicit_spectra_are_hashable():
    wl = np.arange(400, 701, 10.0)
    sens = np.ones((wl.size, 3))
    s = ColourSensor(sensitivities=(wl, sens), illuminant=(wl, np.ones(wl.size)))
    hash(s)
    assert s == ColourSensor(sensitivities=(wl, sens), illuminant=(wl, np.ones(wl.size)))


# -- colour sensor ---------------------------------------------------------------------
def test_photon_transfer_curve_recovers_conversion_gain():
    """EMVA 1288 photon transfer: temporal variance of frame pairs against mean signal.

    The slope is the system gain K (DN/e-), K = CG * (2**b - 1) / voltage_swing,
    so CG = K * swing / (2**b - 1). Differences of two frames cancel DSNU and
    PRNU; read noise and quantisation only add an intercept.
    """
    scene = _flat((256, 256), 0.5)
    base = ColourSensor()
    rate_g = base.electrons_per_unit(1.0)[1] * 0.5
    green = bayer().bayer_map(scene.shape) == G
    means, variances = [], []
    for i, frac in enumerate(np.linspace(0.05, 0.8, 8)):
        s = replace(base, exposure=frac * base.usable_electrons() / rate_g)
        a = simulate_colour(scene, "bayer", s, seed=2 * i).data[green].astype(float)
        b = simulate_colour(scene, "bayer", s, seed=2 * i + 1).data[green].astype(float)
        means.append(0.5 * (a.mean() + b.mean()) - base.black_level)
        variances.append(np.var(a - b) / 2)
    k, _ = np.polyfit(means, variances, 1)
    cg = k * base.voltage_swing / base.white_level * 1e6
    assert cg == pytest.approx(base.conversion_gain_uv_per_e, rel=0.05)


def test_noise_free_equals_mosaic_of_the_scaled_scene():
    img = load_kodak(19, crop=(96, 128))
    scene = Scene(img)
    s = ColourSensor(black_level=0, dark_current=0, exposure=4e-3)
    frame = simulate(scene, "mask1", s, noise=False)
    scale = s.electrons_per_unit(4e-3) * s.system_gain / s.white_level
    scaled = np.minimum(scene.image * scale, 1.0)
    assert scaled.max() < 1                                    # no clipping in this case
    expected = mosaic(scaled, "mask1")
    np.testing.assert_array_equal(frame.data, expected.data)
    np.testing.assert_array_equal(frame.reference, mosaic(scaled, "bayer").data)


def test_noise_free_with_black_level_dark_signal_and_saturation():
    scene = Scene(load_kodak(3, crop=(64, 96)))
    s = ColourSensor()                                        # auto-exposure, black 64
    frame = simulate(scene, "mask2", s, noise=False)
    t = frame.meta["exposure"]
    e = np.minimum(scene.image * s.electrons_per_unit(t) + s.dark_current * t, s.full_well)
    scaled = np.minimum((s.black_level + s.system_gain * e) / s.white_level, 1.0)
    np.testing.assert_array_equal(frame.data, mosaic(scaled, "mask2").data)
    # auto-exposure: the 99th percentile of the signal sits at 80 % of the usable range
    rate = frame.reference.astype(float) - s.black_level
    assert np.percentile(rate, 99) == pytest.approx(0.8 * (2047 - 64), rel=0.01)


def test_same_seed_same_frame_and_fixed_pattern_per_sensor():
    scene = Scene(load_kodak(5, crop=(64, 64)))
    a = simulate(scene, "mask1", seed=7)
    b = simulate(scene, "mask1", seed=7)
    c = simulate(scene, "mask1", seed=8)
    np.testing.assert_array_equal(a.data, b.data)
    np.testing.assert_array_equal(a.reference, b.reference)
    assert np.any(a.data != c.data)
    # with the temporal noise off only the fixed pattern is left: it follows fpn_seed
    fpn_only = ColourSensor(shot_noise=False, read_noise=0, exposure=5e-3)
    f1 = simulate(scene, "bayer", fpn_only, seed=1).data
    f2 = simulate(scene, "bayer", fpn_only, seed=2).data
    f3 = simulate(scene, "bayer", replace(fpn_only, fpn_seed=1), seed=1).data
    np.testing.assert_array_equal(f1, f2)
    assert np.any(f1 != f3)
    clean = simulate(scene, "bayer", fpn_only, noise=False).data
    assert np.any(f1 != clean)


@pytest.mark.parametrize("term", ["shot_noise", "read_noise", "dsnu", "prnu", "dark_current"])
def test_each_noise_term_can_be_switched_off(term):
    scene = _flat((64, 64), 0.3)
    off = dict(shot_noise=False, read_noise=0.0, dsnu=0.0, prnu=0.0, dark_current=0.0,
               exposure=5e-3)
    quiet = ColourSensor(**off)
    base = simulate_colour(scene, "bayer", quiet, seed=3).data
    np.testing.assert_array_equal(base, simulate_colour(scene, "bayer", quiet,
                                                        noise=False).data)
    on = {"shot_noise": True, "read_noise": 10.0, "dsnu": 5.0, "prnu": 0.05,
          "dark_current": 2e4}[term]
    noisy = simulate_colour(scene, "bayer", replace(quiet, **{term: on}), seed=3).data
    assert np.any(noisy != base)


def test_quantise_off_gives_float_dn_and_saturation_clips():
    scene = _flat((32, 32), 1.0)
    s = ColourSensor(quantise=False, exposure=1.0)             # far beyond full well
    f = simulate_colour(scene, "bayer", s, noise=False)
    assert f.data.dtype == np.float64 and f.meta["saturated"] == 1.0
    np.testing.assert_allclose(f.data, 2047)


def test_spectral_scene_runs_spectral_integration_only_when_needed(monkeypatch):
    calls = []
    real = sensor_mod._spectral_integrate

    def counting(*args, **kw):
        calls.append(1)
        return real(*args, **kw)

    monkeypatch.setattr(sensor_mod, "_spectral_integrate", counting)
    simulate(_flat((16, 16)), "mask1", noise=False)
    assert calls == []                                         # RGB scene: none
    cube = np.full((16, 16, 31), 0.5)
    spec = Scene.from_spectral(cube, np.arange(400, 701, 10))
    f = simulate(spec, "mask1", noise=False)
    assert calls == [1] and f.meta["spectral"]


def test_spectral_balloons_white_balance_and_grey():
    path = shared_path("multispectral", "balloons_ms", "balloons_ms.mat")
    scene = load_spectral(path)
    crop = Scene.from_spectral(scene.image[96:160, 96:160], scene.wavelengths)
    f = simulate(crop, "mask2", seed=0)
    assert f.data.dtype == np.uint16 and f.reference.max() <= 2047
    # a flat grey reflector under D65: green at the AE target, R and B at the camera's
    # white-balance ratios, which for the Nikon 5100 sensitivities are below green
    grey = Scene.from_spectral(np.full((8, 8, 31), 0.5), scene.wavelengths)
    g = simulate_colour(grey, "bayer", ColourSensor(black_level=0), noise=False)
    cmap = bayer().bayer_map((8, 8))
    r_, g_, b_ = (g.data[cmap == c].astype(float).mean() for c in range(3))
    assert g_ == pytest.approx(0.8 * 2047, rel=0.01)
    assert 0.2 < r_ / g_ < 1.0 and 0.2 < b_ / g_ < 1.0
    with pytest.raises(ValueError, match="sensitivities"):
        simulate_colour(grey, "bayer", ColourSensor(sensitivities="No such camera"))


def test_auto_exposure_of_a_black_scene_raises():
    with pytest.raises(ValueError, match="exposure"):
        simulate(_flat((8, 8), 0.0), "mask1")
    # an explicit exposure works on a black frame: black level plus dark signal
    f = simulate(_flat((8, 8), 0.0), "mask1", ColourSensor(exposure=1e-3), noise=False)
    assert f.reference.min() == 64


# -- the RGB-Z build -------------------------------------------------------------------
@pytest.mark.parametrize("pattern", ["mask1", "mask2", "rows"])
def test_build_shares_exposure_and_noise_with_the_reference(pattern):
    scene = Scene(load_kodak(23, crop=(48, 64)))
    f = simulate(scene, pattern, seed=11)
    ref = simulate(scene, "bayer", seed=11)
    assert isinstance(f, RawFrame) and f.pattern.name == pattern
    np.testing.assert_array_equal(f.reference, ref.data)
    np.testing.assert_array_equal(f.data[~f.z_mask], f.reference[~f.z_mask])
    assert np.all(f.data[f.z_mask] == 0)
    assert f.meta["exposure"] == ref.meta["exposure"]
    assert f.tof is None and "no depth map" in f.meta["tof"]


def test_no_depth_runs_no_tof_model(monkeypatch):
    calls = []
    real = sensor_mod.simulate_tof

    def counting(*args, **kw):
        calls.append(1)
        return real(*args, **kw)

    monkeypatch.setattr(sensor_mod, "simulate_tof", counting)
    f = simulate(_flat((16, 16)), "mask2", tof_sensor=ToFSensor())
    assert calls == [] and f.tof is None and f.meta["tof_sensor"] is None
    assert f.meta["tof"] == "not simulated: the scene has no depth map"
    f = simulate(_flat((16, 16), depth=1.0), "bayer")
    assert calls == [] and f.tof is None and "no Z site" in f.meta["tof"]
    f = simulate(_flat((16, 16), depth=1.0), "mask2")
    assert calls == [1] and isinstance(f.tof, ToFTaps) and f.meta["tof"].startswith("simulated")


def test_noise_free_draws_no_random_numbers(monkeypatch):
    scene = Scene(load_kodak(1, crop=(32, 32)), depth=np.full((32, 32), 1.5))
    drawn, keyed = [], []
    real, real_keys = np.random.default_rng, sensor_mod.stream_keys

    def counting(*args, **kw):
        drawn.append(args)
        return real(*args, **kw)

    def counting_keys(*args, **kw):
        keyed.append(args)
        return real_keys(*args, **kw)

    monkeypatch.setattr(np.random, "default_rng", counting)
    monkeypatch.setattr(sensor_mod, "stream_keys", counting_keys)
    for version in (1, 2):
        f = simulate(scene, "mask2", noise=False, rng_version=version)
        assert drawn == [] and keyed == [] and f.tof is not None
    # version 1: NumPy's generators, colour: temporal + FPN; ToF: temporal + FPN
    simulate(scene, "mask2", noise=True, rng_version=1)
    assert len(drawn) == 4 and keyed == []
    # version 2: the keys of the colour streams and of the ToF streams
    simulate(scene, "mask2", noise=True)
    assert len(drawn) == 4 and len(keyed) == 2


def test_mask2_and_mask1_sites():
    scene = _flat((16, 24), depth=1.0)
    m2 = simulate(scene, "mask2", noise=False).tof
    assert m2.block == 2 and m2.n_sites == (16 // 4) * (24 // 4) and m2.taps.shape == (3, 4, 24)
    np.testing.assert_array_equal(np.unique(m2.sites[0] % 4), [0])
    m1 = simulate(scene, "mask1", noise=False).tof
    assert m1.block == 1 and m1.n_sites == 16 * 24 // 4
    z = simulate(scene, "mask1", noise=False).z_mask
    assert np.all(z[m1.sites])
    painted = m2.to_frame(np.arange(m2.n_sites), fill=-1)
    np.testing.assert_array_equal(painted >= 0, simulate(scene, "mask2", noise=False).z_mask)
    rows = simulate(scene, "rows", noise=False).tof
    assert rows.block == 2
    single = simulate(scene, "mask2", tof_sensor=ToFSensor(z_block=1), noise=False).tof
    assert single.block == 1 and single.n_sites == 4 * m2.n_sites
    with pytest.raises(ValueError, match="z_block"):
        simulate(scene, "mask1", tof_sensor=ToFSensor(z_block=2))


# -- i-ToF model -----------------------------------------------------------------------
def test_tap_convention_and_fall_off():
    tof = ToFSensor(quantise=False, ambient_irradiance=0.0, dark_current=0.0)
    depth = np.linspace(0.3, 7.0, 32 * 32).reshape(32, 32)
    taps = simulate_tof(Scene(np.full((32, 32, 3), 0.5), depth=depth,
                              ir_reflectance=np.full((32, 32), 0.5)),
                        "mask1", tof, noise=False)
    true = np.mod(4 * np.pi * taps.frequencies[:, None] * taps.depth_true / C, 2 * np.pi)
    err = np.angle(np.exp(1j * (_phase(taps.taps) - true)))
    assert np.abs(err).max() < 1e-9
    # depth = c phi / (4 pi f) within one wrap
    near = taps.depth_true < min(tof.wrap_ranges)
    d = C * _phase(taps.taps)[:, near] / (4 * np.pi * taps.frequencies[:, None])
    np.testing.assert_allclose(d, np.broadcast_to(taps.depth_true[near], d.shape), atol=1e-9)
    # amplitude and offset in DN follow 1/d^2, and amplitude / offset-above-black = C
    t = taps.taps - tof.black_level
    amp = 0.5 * np.hypot(t[:, 0] - t[:, 2], t[:, 3] - t[:, 1])
    off = t.mean(axis=1)
    np.testing.assert_allclose(amp / off, tof.modulation_contrast)
    np.testing.assert_allclose(amp * taps.depth_true ** 2, amp[0, 0] * taps.depth_true[0] ** 2)


def test_mask2_pixel_collects_four_cells():
    tof = ToFSensor(quantise=False, dark_current=0.0)
    scene = _flat((16, 16), depth=1.3)
    m1 = simulate_tof(scene, "mask1", tof, noise=False)
    m2 = simulate_tof(scene, "mask2", tof, noise=False)
    np.testing.assert_allclose(m2.taps[:, :, 0] - tof.black_level,
                               4 * (m1.taps[:, :, 0] - tof.black_level))
    e = tof.tap_electrons(1.3, 0.5)
    np.testing.assert_allclose(m1.taps[:, :, 0], tof.black_level + tof.system_gain * e)


def _analytic_sigma_phi(mean_dn, sensor):
    """First-order noise of phi = atan2(Q, I), I = A0 - A2, Q = A3 - A1 (per frequency).

    Each tap: Var(A_k) = K^2 (n_k + sigma_read^2) + 1/12 DN^2, with n_k the mean
    electrons of the tap (photon + ambient + dark shot noise are Poisson, so their
    variance is n_k), K the system gain and 1/12 the quantisation noise. Then

        sigma_phi^2 = (Q^2 Var(I) + I^2 Var(Q)) / (I^2 + Q^2)^2,
        Var(I) = Var(A0) + Var(A2),  Var(Q) = Var(A1) + Var(A3),

    and sigma_d = c / (4 pi f) * sigma_phi.
    """
    k = sensor.system_gain
    n = (mean_dn - sensor.black_level) / k
    var = k * k * (n + sensor.read_noise ** 2) + 1.0 / 12.0
    i = mean_dn[:, 0] - mean_dn[:, 2]
    q = mean_dn[:, 3] - mean_dn[:, 1]
    var_i = var[:, 0] + var[:, 2]
    var_q = var[:, 1] + var[:, 3]
    return np.sqrt(q * q * var_i + i * i * var_q) / (i * i + q * q)


@pytest.mark.parametrize("pattern,shape,distances", [
    ("mask1", (96, 96), (0.5, 1.0, 2.0)),
    ("mask2", (128, 128), (1.0, 2.0, 3.0)),
])
def test_depth_noise_matches_the_analytic_bound(pattern, shape, distances):
    """On a flat wall, the spread of the depth from the simulated taps is within 20 %
    of sigma_d = c / (4 pi f) sigma_phi, sigma_phi derived from the tap means and
    noise (see _analytic_sigma_phi). FPN is off: the bound is for temporal noise."""
    tof = ToFSensor(optical_power_w=2.0, dsnu=0.0, prnu=0.0)
    for d in distances:
        scene = _flat(shape, depth=d)
        noisy = simulate_tof(scene, pattern, tof, seed=5)
        mean = simulate_tof(scene, pattern, replace(tof, quantise=False), noise=False)
        assert not noisy.saturated.any()
        mean_dn = mean.taps[:, :, 0]
        true = _phase(mean.taps)[:, :1]
        err = np.angle(np.exp(1j * (_phase(noisy.taps) - true)))
        scale = C / (4 * np.pi * noisy.frequencies)
        sigma_d_sim = scale * err.std(axis=1)
        sigma_d_bound = scale * _analytic_sigma_phi(mean_dn, tof)
        assert np.all(sigma_d_bound < 0.05)                   # the linear regime
        np.testing.assert_allclose(sigma_d_sim / sigma_d_bound, 1.0, atol=0.2,
                                   err_msg=f"{pattern} at {d} m")


def test_depth_beyond_the_unambiguous_range_warns_and_is_marked():
    depth = np.full((16, 16), 3.0)
    depth[:, 8:] = 9.0
    scene = _flat((16, 16), depth=depth)
    with pytest.warns(UnambiguousRangeWarning, match="7.495 m") as record:
        f = simulate(scene, "mask1", seed=0)
    assert record[0].filename == __file__                    # points at the caller
    with pytest.warns(UnambiguousRangeWarning) as record:
        simulate_tof(scene, "mask1", noise=False)
    assert record[0].filename == __file__
    beyond = f.tof.depth_true >= f.tof.unambiguous_range
    assert beyond.any() and not f.tof.valid[beyond].any() and f.tof.valid[~beyond].all()
    assert issubclass(UnambiguousRangeWarning, RuntimeWarning)


def test_unknown_depth_is_marked_invalid_but_still_simulated():
    depth = np.full((16, 16), 1.5)
    valid = np.ones((16, 16), bool)
    valid[0, 0] = False                                       # inside the first Mask2 pixel
    scene = Scene(np.full((16, 16, 3), 0.5), depth=depth, depth_valid=valid)
    taps = simulate(scene, "mask2", noise=False).tof
    assert not taps.valid[0] and taps.valid[1:].all()
    np.testing.assert_array_equal(taps.taps[..., 0], taps.taps[..., 1])


def test_zero_depth_where_unknown_gives_no_return():
    depth = np.full((8, 8), 1.5)
    depth[0, 0] = 0.0
    scene = Scene(np.full((8, 8, 3), 0.5), depth=depth, depth_valid=depth > 0)
    taps = simulate_tof(scene, "mask1", ToFSensor(quantise=False), noise=False)
    assert not taps.valid[0] and taps.valid[1:].all()
    t = taps.taps[:, :, 0]
    np.testing.assert_allclose(t, np.broadcast_to(t[:, :1], t.shape))   # no modulation
    assert np.all(t < taps.taps[:, :, 1].mean())


def test_tof_saturation_is_flagged():
    scene = _flat((16, 16), depth=0.1, ir=1.0)
    taps = simulate(scene, "mask2", tof_sensor=ToFSensor(optical_power_w=50.0)).tof
    assert taps.saturated.all() and taps.taps.max() == taps.white_level


def test_tof_same_seed_same_taps():
    scene = _flat((32, 32), depth=1.2)
    a = simulate(scene, "mask1", seed=3).tof.taps
    b = simulate(scene, "mask1", seed=3).tof.taps
    c = simulate(scene, "mask1", seed=4).tof.taps
    np.testing.assert_array_equal(a, b)
    assert np.any(a != c) and a.dtype == np.uint16


# -- bad input ----------------------------------------------------------------------------
def test_bad_input_to_simulate():
    scene = _flat((16, 16), depth=1.0)
    with pytest.raises(ValueError, match="scene"):
        simulate(_flat((3, 3)), "mask2")                      # smaller than a period
    with pytest.raises(ValueError, match="seed"):
        simulate(scene, "mask1", seed=-1)
    with pytest.raises(TypeError, match="colour_sensor"):
        simulate(scene, "mask1", ToFSensor())
    with pytest.raises(TypeError, match="tof_sensor"):
        simulate(scene, "mask1", None, ColourSensor())
    with pytest.raises(ValueError, match="pixel_pitch_um"):
        simulate(scene, "mask1", ColourSensor(), ToFSensor(pixel_pitch_um=5.0))
    with pytest.raises(ValueError, match="depth"):
        simulate_tof(_flat((16, 16)), "mask1")
    with pytest.raises(ValueError, match="no Z site"):
        simulate_tof(scene, "bayer")
    with pytest.raises(ValueError, match="pattern"):
        simulate(scene, "kite")
    with pytest.raises(ValueError, match="exposure"):
        ColourSensor().electrons_per_unit(0.0)
    with pytest.raises(ValueError, match="depth"):
        Scene(np.full((4, 4, 3), 0.5), depth=np.full((4, 4), -2.0))


def test_quantum_efficiencies_from_any_iterable():
    """An iterator is read once: the check of the entries' types must not use it up (it had
    left nothing for the conversion, and the error blamed the values)."""
    from rgbz_fast.simulation import ColourSensor

    assert ColourSensor(qe=iter([0.5, 0.6, 0.4])).qe == (0.5, 0.6, 0.4)
    assert ColourSensor(qe=(q for q in (0.5, 0.6, 0.4))).qe == (0.5, 0.6, 0.4)
    assert ColourSensor(qe=np.array([0.5, 0.6, 0.4], np.float32)).qe[0] == 0.5
