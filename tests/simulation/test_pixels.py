"""The C kernels of the sensor models (csrc/sim.c): the generator against Random123's
known answers, its normals and Poisson variates against their distributions, the
noise-free frames against the NumPy reference bit for bit, and the properties of the
counter-based random numbers (thread count, position, version 1)."""

from __future__ import annotations

import warnings
from dataclasses import replace

import numpy as np
import pytest
from scipy import stats

from _reference import simulation as ref
from _support import load_kodak

import rgbz_fast as rz
from rgbz_fast import _kernels
from rgbz_fast.simulation import (ColourSensor, Scene, ToFSensor, simulate, simulate_colour,
                                  simulate_tof)
from rgbz_fast.simulation import _pixels, _simulate, _tof_light
from rgbz_fast.simulation._noise import stream_keys

KEY = np.array(_kernels.sim_key(np.array([12345], np.uint64), 0), np.uint32)


# -- the generator --------------------------------------------------------------------
@pytest.mark.parametrize("ctr,key,want", [
    ((0, 0, 0, 0), (0, 0, 0, 0), (0x9C6CA96A, 0xE17EAE66, 0xFC10ECD4, 0x5256A7D8)),
    ((0xFFFFFFFF,) * 4, (0xFFFFFFFF,) * 4, (0x2A881696, 0x57012287, 0xF6C7446E, 0xA16A6732)),
    ((0x243F6A88, 0x85A308D3, 0x13198A2E, 0x03707344),
     (0xA4093822, 0x299F31D0, 0x082EFA98, 0xEC4E6C89),
     (0x59CD1DBB, 0xB8879579, 0x86B5D00C, 0xAC8B6D84)),
])
def test_threefry_known_answers(ctr, key, want):
    """Random123's kat_vectors for threefry4x32 with 20 rounds."""
    out = np.empty((1, 4), np.uint32)
    _kernels.sim_blocks(*ctr, np.array(key, np.uint32), out)
    assert tuple(int(v) for v in out[0]) == want


def test_keys_differ_by_seed_and_stream():
    keys = {tuple(stream_keys(s, f, t, p)) for s in (0, 1, 2**64 + 1) for f in (0, 1)
            for t, p in ((0, 1), (2, 3))}
    assert len(keys) == 12
    assert not np.array_equal(stream_keys(2**64, 0, 0, 1), stream_keys(0, 0, 0, 1))


def test_box_muller_functions_within_an_ulp_of_libm():
    x = np.concatenate([np.random.default_rng(0).uniform(2.0 ** -53, 1, 100_000),
                        2.0 ** -np.arange(54.0), [1.0, 0.7071067811865476]])
    got = np.empty_like(x)
    _kernels.sim_math(0, x, got)
    assert np.all(np.abs(got - np.log(x)) <= np.spacing(np.abs(np.log(x))))
    u = np.concatenate([np.random.default_rng(1).uniform(0, 1, 100_000), np.arange(64) / 64])
    s, c = np.empty_like(u), np.empty_like(u)
    _kernels.sim_math(1, u, s)
    _kernels.sim_math(2, u, c)
    assert np.abs(s - np.sin(2 * np.pi * u)).max() < 1e-15
    assert np.abs(c - np.cos(2 * np.pi * u)).max() < 1e-15


def test_normals_are_standard_normal():
    z = np.empty(400_000)
    _kernels.sim_variates(0, np.empty(0), 7, 9, KEY, z, 2)
    assert abs(z.mean()) < 5 / np.sqrt(z.size) and abs(z.std() - 1) < 5 / np.sqrt(2 * z.size)
    assert stats.kstest(z, "norm").pvalue > 1e-3
    assert stats.skew(z) == pytest.approx(0, abs=0.02)
    assert stats.kurtosis(z) == pytest.approx(0, abs=0.05)


@pytest.mark.parametrize("lam", [0.0, 0.01, 0.7, 3.0, 9.99, 10.0, 37.5, 300.0, 8000.0, 1e6])
def test_poisson_variates_follow_the_distribution(lam):
    """Both samplers (inversion below 10, PTRS from 10) against the Poisson pmf."""
    n = 300_000
    x = np.empty(n)
    _kernels.sim_variates(1, np.full(n, lam), 11, int(lam * 100) % 1000, KEY, x, 2)
    assert np.all(x == np.floor(x)) and x.min() >= 0
    if lam == 0:
        assert not x.any()
        return
    se = np.sqrt(lam / n)
    assert abs(x.mean() - lam) < 5 * se
    # the sample variance's relative spread for a Poisson law: sqrt((2 + 1 / lam) / n)
    assert abs(x.var() / lam - 1) < 5 * np.sqrt((2 + 1 / lam) / n)
    vals, cnt = np.unique(x, return_counts=True)
    expect = stats.poisson.pmf(vals, lam) * n
    keep = expect > 30
    if keep.sum() > 2:
        p = stats.chisquare(cnt[keep], expect[keep] * cnt[keep].sum() / expect[keep].sum())
        assert p.pvalue > 1e-4


def test_a_poisson_variate_does_not_depend_on_its_neighbours_means():
    """Each draw is a function of the key and its sample's counter alone: the same samples
    beside means below 10 (the inversion) or beside zeros give the same variates, and the
    bright ones keep the Poisson variance (the inversion had overwritten the candidates of
    PTRS's slow test in a chunk of both: a variance of 800 for a mean of 1000 beside 5 e-)."""
    rng = np.random.default_rng(7)
    n = 200_000
    big = rng.uniform(10, 2000, n)
    dim = rng.random(n) < 0.5                        # every chunk mixes both
    mixed = np.where(dim, rng.uniform(0.1, 9.9, n), big)
    alone = np.where(dim, 0.0, big)
    a, b = np.empty(n), np.empty(n)
    _kernels.sim_variates(1, mixed, 5, 6, KEY, a, 2)
    _kernels.sim_variates(1, alone, 5, 6, KEY, b, 2)
    np.testing.assert_array_equal(a[~dim], b[~dim])
    z = (a[~dim] - big[~dim]) / np.sqrt(big[~dim])
    assert abs(z.var() - 1) < 5 * np.sqrt(2 / z.size)
    small = mixed[dim]
    assert abs((a[dim] - small).mean()) < 5 * np.sqrt(small.mean() / small.size)


def test_variates_do_not_depend_on_the_thread_count():
    lam = np.random.default_rng(2).uniform(0, 50, 50_000)
    for kind in (0, 1):
        a, b = np.empty_like(lam), np.empty_like(lam)
        _kernels.sim_variates(kind, lam, 3, 4, KEY, a, 1)
        _kernels.sim_variates(kind, lam, 3, 4, KEY, b, 2)
        np.testing.assert_array_equal(a, b)


# -- noise-free frames against the NumPy reference ------------------------------------
def _depth_scene(rgb, ir=True, scale=1.0):
    H, W = rgb.shape[:2]
    yy, xx = np.mgrid[:H, :W]
    depth = (1.0 + 0.02 * xx + 0.01 * yy) * scale
    depth[H // 5:H // 2, W // 4:W // 2] = 0.8
    valid = np.ones((H, W), bool)
    valid[:, -3:] = False
    irm = 0.3 + 0.4 * np.random.default_rng(7).random((H, W)) if ir else None
    return Scene(rgb, depth=depth, depth_valid=valid, ir_reflectance=irm)


@pytest.mark.parametrize("pattern", ["mask1", "mask2", "rows", "bayer", "GZGR/BGBG"])
@pytest.mark.parametrize("kind", ["uint8", "float32", "spectral", "explicit"])
def test_noise_free_colour_is_the_reference_bit_for_bit(pattern, kind):
    rgb = load_kodak(3, crop=(46, 62))                 # not a multiple of every period
    sensor = ColourSensor()
    if kind == "float32":
        rgb = (rgb / 255.0).astype(np.float32)
    elif kind == "explicit":
        sensor = ColourSensor(exposure=0.02, quantise=False, full_well=3000.0)
    if kind == "spectral":
        cube = np.random.default_rng(3).random((46, 62, 31))
        scene = Scene.from_spectral(cube, np.arange(400, 701, 10))
        cmap = rz.get_pattern(pattern).bayer_map(scene.shape)
        values = _simulate._colour_values(scene, sensor, cmap)
    else:
        scene = Scene(rgb)
        cmap = rz.get_pattern(pattern).bayer_map(scene.shape)
        values = scene.image
    want, sat, exposure = ref.colour_frame(values, sensor, cmap)
    got = simulate_colour(scene, pattern, sensor, noise=False)
    assert got.data.dtype == want.dtype
    np.testing.assert_array_equal(got.data, want)
    assert got.meta["exposure"] == exposure and got.meta["saturated"] == sat


def test_auto_exposure_percentile_is_numpys():
    rng = np.random.default_rng(4)
    for shape, levels, q in (((30, 40), None, 99.0), ((31, 17), 5, 50.0), ((8, 8), 3, 100.0),
                             ((2, 2), None, 1.0), ((64, 48), 2, 99.9)):
        img = rng.random(shape + (3,)) if levels is None else \
            rng.integers(0, levels, shape + (3,)) / max(levels - 1, 1)
        scene = Scene(img)
        pat = rz.get_pattern("mask1" if shape[0] > 2 else "bayer")
        sensor = ColourSensor(ae_percentile=q)
        rate = ref.colour_rate(scene.image, sensor, pat.bayer_map(shape))
        got = _pixels.rate_percentile(_pixels.colour_source(scene.image), pat,
                                      sensor.electrons_per_unit(1.0), q, workers=2)
        assert got == float(np.percentile(rate, q))


@pytest.mark.parametrize("pattern,block", [("mask1", None), ("mask2", None), ("rows", None),
                                           ("mask2", 1), ("GZGR/BGBG", None)])
@pytest.mark.parametrize("variant", ["ir", "estimate", "far", "suppress", "float"])
def test_noise_free_tof_is_the_reference(pattern, block, variant):
    """The noise-free taps of ideal Z pixels are the NumPy model's: equal codes once
    quantised; without quantisation (``float``) within 1e-14 of the largest tap, as the C
    light takes the phasor's sine and cosine by its own vectorised code (sim_tof_phasors),
    a few units in the last place from the C library's that NumPy calls."""
    rgb = load_kodak(5, crop=(48, 64))
    scene = _depth_scene(rgb, ir=variant != "estimate", scale=6.0 if variant == "far" else 1.0)
    sensor = ToFSensor(z_block=block, pixel_pitch_um=2.8)
    if variant == "suppress":
        sensor = replace(sensor, ambient_suppression=0.6, duty_cycle=0.25,
                         ambient_irradiance=15.0)
    elif variant == "float":
        sensor = replace(sensor, quantise=False, full_well=400.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        got = _simulate.simulate_tof(scene, pattern, sensor, noise=False)
    pat = rz.get_pattern(pattern)
    b = got.block
    rows, cols = got.sites
    ir = scene.ir_map()
    taps, depth_true, valid, sat = ref.tof_taps(scene.depth, scene.depth_valid, ir, sensor,
                                                2.8, rows, cols, b)
    beyond = np.zeros(rows.size, bool)
    if variant == "far":
        d = np.stack([scene.depth[rows + i // b, cols + i % b] for i in range(b * b)], 1)
        v = np.stack([scene.depth_valid[rows + i // b, cols + i % b] for i in range(b * b)], 1)
        beyond = np.any(v & (d >= sensor.unambiguous_range), axis=1)
        assert beyond.any()
    if variant == "float":
        np.testing.assert_allclose(got.taps, taps, rtol=0, atol=1e-14 * np.abs(taps).max())
    else:
        np.testing.assert_array_equal(got.taps, taps)
    np.testing.assert_array_equal(got.depth_true, depth_true)
    np.testing.assert_array_equal(got.valid, valid & ~beyond)
    np.testing.assert_array_equal(got.saturated, sat)
    assert pat.has_z


def test_non_ideal_taps_noise_free_match_numpys_chain():
    """The C chain of given means (non-ideal sensors, optics) is NumPy's noise-free chain."""
    scene = _depth_scene(load_kodak(5, crop=(48, 64)))
    sensor = ToFSensor(harmonics=((3, 0.04, 0.3),), tap_contrast=(1.0, 0.97, 1.02, 0.99),
                       ambient_suppression=0.9, ambient_irradiance=15.0, pixel_pitch_um=2.8)
    got = _simulate.simulate_tof(scene, "mask2", sensor, noise=False)
    rows, cols = got.sites
    mean, suppress, *_ = _tof_light._tof_mean(scene, sensor, 2.8, rows, cols, 2, None, 1)
    want, sat = ref.chain(mean, sensor._dark_electrons, sensor, suppress)
    np.testing.assert_array_equal(got.taps, want)
    np.testing.assert_array_equal(got.saturated, sat.any(axis=(0, 1)))


def test_taps_the_suppression_empties_match_numpys_chain():
    """H87: the C chain empties a tap holding less than the suppressed charge and flags it,
    as the NumPy reference does (suppression 0.5 and deep modulation: the weakest taps of
    the near surfaces)."""
    scene = _depth_scene(load_kodak(5, crop=(48, 64)))
    sensor = ToFSensor(ambient_suppression=0.5, pixel_pitch_um=2.8, quantise=False)
    got = _simulate.simulate_tof(scene, "mask1", sensor, noise=False)
    rows, cols = got.sites
    mean, suppress, *_ = _tof_light._tof_mean(scene, sensor, 2.8, rows, cols, 1, None, 1)
    want, sat = ref.chain(mean, sensor._dark_electrons, sensor, suppress)
    drained = (mean + sensor._dark_electrons < suppress).any(axis=(0, 1))
    assert 0 < drained.sum() < drained.size
    np.testing.assert_allclose(got.taps, want, rtol=0, atol=1e-9)
    np.testing.assert_array_equal(got.saturated, sat.any(axis=(0, 1)))
    assert got.saturated[drained].all()


@pytest.mark.parametrize("pattern", ["mask1", "mask2", "rows", "GZGR/BGBG",
                                     "GRGR/BGBG/GRZR/BGBG"])
def test_z_sites_are_the_z_mask_in_row_order(pattern):
    pat = rz.get_pattern(pattern)
    for shape in ((12, 16), (13, 17), (25, 30)):
        zm = pat.z_mask(shape)
        np.testing.assert_array_equal(np.stack(_pixels.z_sites(pat, shape, 1)),
                                      np.stack(np.nonzero(zm)))
        H, W = shape
        top = np.stack(np.nonzero(zm[0:H - 1:2, 0:W - 1:2])) * 2
        np.testing.assert_array_equal(np.stack(_pixels.z_sites(pat, shape, 2)), top)


# -- the random numbers of the frames ---------------------------------------------------
def test_noisy_frame_is_the_same_on_any_thread_count():
    scene = _depth_scene(load_kodak(2, crop=(64, 96)))
    one = simulate(scene, "mask1", seed=5, workers=1)
    two = simulate(scene, "mask1", seed=5, workers=2)
    np.testing.assert_array_equal(one.data, two.data)
    np.testing.assert_array_equal(one.tof.taps, two.tof.taps)
    assert one.meta["rng_version"] == 2 and one.tof.meta["rng_version"] == 2
    other = simulate(scene, "mask1", seed=6)
    assert np.any(other.data != one.data) and np.any(other.tof.taps != one.tof.taps)


def test_fixed_pattern_belongs_to_the_pixel_not_the_frame():
    """Version 2 keys the fixed pattern by pixel position: a larger frame of the same
    sensor has the same offsets and gains where the two overlap."""
    sensor = ColourSensor(shot_noise=False, read_noise=0.0, dsnu=20.0, prnu=0.05,
                          exposure=5e-3)
    small = simulate_colour(Scene(np.full((32, 40, 3), 0.4)), "bayer", sensor, seed=1)
    large = simulate_colour(Scene(np.full((64, 80, 3), 0.4)), "bayer", sensor, seed=2)
    np.testing.assert_array_equal(small.data, large.data[:32, :40])
    assert len(np.unique(small.data)) > 20


def test_delay_pattern_belongs_to_the_pixel_not_the_frame():
    """H80: version 2 keys the per-pixel delay (delay_fpn_ps) by the Z pixel's position, as
    the PRNU and DSNU: a frame of another size gives the same taps where the two overlap
    (before, the delays followed the sites' order: 97 % of the shared pixels differed)."""
    sensor = ToFSensor(delay_fpn_ps=50.0)

    def taps(shape, version):
        scene = Scene(np.full(shape + (3,), 0.4), depth=np.full(shape, 1.3))
        return simulate_tof(scene, "mask2", sensor, noise=False, rng_version=version)

    small, large = taps((32, 40), 2), taps((64, 80), 2)
    where = {(int(r), int(c)): k for k, (r, c) in enumerate(zip(*large.sites))}
    at = [where[(int(r), int(c))] for r, c in zip(*small.sites)]
    np.testing.assert_array_equal(small.taps, large.taps[..., at])
    assert len(np.unique(small.taps[0, 0])) > 3                  # the pattern is there
    # version 1 keeps NumPy's normals in the sites' order (rgbz-fast 0.1's frames): they follow
    # the site's index, so the same pixel differs between the two sizes, and from version 2
    small1, large1 = taps((32, 40), 1), taps((64, 80), 1)
    assert np.any(small1.taps != large1.taps[..., at])
    assert np.any(small1.taps != small.taps)
    rng = np.random.default_rng([sensor.fpn_seed, 4])                 # STREAM_TOF_DELAY
    delays = _tof_light._pixel_delays(sensor, *small1.sites, positional=False)
    np.testing.assert_array_equal(delays, 50.0 * rng.standard_normal(small1.sites[0].size))


def test_noisy_flat_field_has_the_models_variance():
    """Photon transfer of a flat grey field: variance = K^2 (mean e- + read^2 + dsnu^2 +
    (prnu mean e-)^2) + 1/12 (quantisation), per colour, within 5 %."""
    sensor = ColourSensor(exposure=2e-3, dark_current=0.0)
    f = simulate_colour(Scene(np.full((256, 256, 3), 0.3)), "bayer", sensor, seed=3)
    cmap = rz.bayer().bayer_map((256, 256))
    mean_e = 0.3 * sensor.electrons_per_unit(2e-3)
    for c in range(3):
        dn = f.data[cmap == c].astype(float)
        e = mean_e[c]
        var = sensor.system_gain ** 2 * (e + sensor.read_noise ** 2 + sensor.dsnu ** 2
                                         + (sensor.prnu * e) ** 2) + 1 / 12
        assert dn.mean() == pytest.approx(sensor.black_level + sensor.system_gain * e, abs=0.1)
        assert dn.var() == pytest.approx(var, rel=0.05)


def test_rng_version_1_is_numpys_streams():
    scene = _depth_scene(load_kodak(2, crop=(32, 48)))
    a = simulate(scene, "mask2", seed=4, rng_version=1)
    rng = np.random.default_rng([4, 0])                  # STREAM_COLOUR_TEMPORAL
    assert a.meta["rng_version"] == 1
    b = simulate(scene, "mask2", seed=4, rng_version=1)
    np.testing.assert_array_equal(a.data, b.data)
    np.testing.assert_array_equal(a.tof.taps, b.tof.taps)
    assert rng.bit_generator.state["bit_generator"] == "PCG64"
    c = simulate(scene, "mask2", seed=4)
    assert np.any(c.data != a.data)
    free = [simulate(scene, "mask2", noise=False, rng_version=v) for v in (1, 2)]
    np.testing.assert_array_equal(free[0].data, free[1].data)
    np.testing.assert_array_equal(free[0].tof.taps, free[1].tof.taps)


@pytest.mark.parametrize("value", [0, 3, True, "2", 2.5, None])
def test_rng_version_is_checked(value):
    with pytest.raises(ValueError, match="rng_version"):
        simulate(Scene(np.full((8, 8, 3), 0.5)), "mask1", rng_version=value)
