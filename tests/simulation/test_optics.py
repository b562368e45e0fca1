"""The optics stage: PSF normalisation, the MTF against theory, and where it is applied
(colour model, ToF model, evaluation), off by default."""

from __future__ import annotations

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast import _kernels
from rgbz_fast._sensors import SPEED_OF_LIGHT
from rgbz_fast.evaluation import EvalConfig, image_frames
from rgbz_fast.simulation import (Optics, Scene, ToFSensor, apply_optics, simulate,
                                  simulate_colour, simulate_tof)
from rgbz_fast.tof import tof_depth

from _reference import simulation as ref_sim

CONFIGS = [dict(), dict(f_number=1.2), dict(f_number=8.0), dict(olpf=1.0),
           dict(defocus_um=12.0), dict(fill_factor=0.5)]


def _diffraction_mtf(s):
    """Goodman eq. 6-32: the OTF of a circular pupil at s = nu / nu_c."""
    s = np.minimum(np.asarray(s, float), 1.0)
    return (2 / np.pi) * (np.arccos(s) - s * np.sqrt(1 - s * s))


def _pupil_autocorrelation(s, n=801):
    """The same OTF as the overlap area of two unit disks whose centres are 2 s apart
    (the pupil autocorrelation), counted on a grid: an independent check of the formula."""
    x = np.linspace(-1, 1, n)
    xx, yy = np.meshgrid(x, x)
    disk = xx ** 2 + yy ** 2 <= 1
    out = []
    for v in np.atleast_1d(s):
        shifted = (xx - 2 * v) ** 2 + yy ** 2 <= 1
        out.append((disk & shifted).sum() / disk.sum())
    return np.array(out)


@pytest.mark.parametrize("kw", CONFIGS)
@pytest.mark.parametrize("band", [540.0, (490.0, 580.0), 940.0])
def test_psf_is_a_normalised_symmetric_kernel(kw, band):
    k = Optics(**kw).psf(band, pixel_pitch_um=2.8)
    assert k.ndim == 2 and k.shape[0] == k.shape[1] and k.shape[0] % 2 == 1
    assert k.sum() == pytest.approx(1.0, abs=1e-12)
    assert k.min() >= 0
    np.testing.assert_array_equal(k, k[::-1, ::-1])
    np.testing.assert_allclose(k, k.T, atol=1e-15)
    c = k.shape[0] // 2
    assert k[c, c] == k.max()


def test_diffraction_otf_matches_the_pupil_autocorrelation():
    s = np.linspace(0, 0.98, 15)
    np.testing.assert_allclose(_diffraction_mtf(s), _pupil_autocorrelation(s), atol=4e-3)
    # Optics.otf with no OLPF, defocus or pixel (a fill factor -> 0 is a point sample)
    o = Optics(f_number=4.0, fill_factor=1e-12)
    cutoff = 2.8 / (0.55 * 4.0)                       # cycles per pixel at 550 nm
    got = o.otf(s * cutoff, 0.0, 550.0, pixel_pitch_um=2.8)
    np.testing.assert_allclose(got, _diffraction_mtf(s), atol=1e-12)
    assert o.otf(1.01 * cutoff, 0.0, 550.0, pixel_pitch_um=2.8) == 0.0
    # at half the cut-off: (2/pi)(pi/3 - sqrt(3)/4) = 0.391
    assert o.mtf(0.5 * cutoff, 550.0, pixel_pitch_um=2.8) == pytest.approx(0.3910, abs=1e-4)


def test_olpf_defocus_and_pixel_factors():
    p = 2.8
    base = Optics(f_number=2.8)
    xi = np.linspace(0, 0.5, 6)
    ref = base.otf(xi, 0.0, 540.0, pixel_pitch_um=p)
    # pixel aperture: sinc of the fill factor's side
    np.testing.assert_allclose(ref, _diffraction_mtf(xi * 0.54 * 2.8 / p) * np.sinc(xi),
                               atol=1e-12)
    olpf = Optics(f_number=2.8, olpf=1.0).otf(xi, 0.0, 540.0, pixel_pitch_um=p)
    np.testing.assert_allclose(olpf, ref * np.cos(np.pi * xi), atol=1e-12)
    assert abs(olpf[-1]) < 1e-12                       # the first zero at Nyquist
    # defocus: 2 J1(x) / x, first zero at pi b nu = 3.8317
    b = 12.0
    nu0 = 3.8317 / (np.pi * b)                          # cycles per um
    de = Optics(f_number=2.8, defocus_um=b)
    assert abs(de.otf(nu0 * p, 0.0, 540.0, pixel_pitch_um=p)) < 1e-4
    def spread(k):
        r = np.arange(k.shape[0]) - k.shape[0] // 2
        return float((k * (r[:, None] ** 2 + r[None] ** 2)).sum())

    assert spread(de.psf(540.0, pixel_pitch_um=p)) > 2 * spread(base.psf(540.0, pixel_pitch_um=p))


@pytest.mark.parametrize("kw", CONFIGS)
def test_kernel_response_matches_the_aliased_otf(kw):
    """The DTFT of the kernel is the continuous OTF aliased by the pixel sampling,
    ``sum_j H(xi + j, eta + k)``, normalised at 0; the kernel's cut-off at 1 % of the
    energy (the Airy tails) keeps it within 0.012 of it."""
    o = Optics(**kw)
    band = (490.0, 580.0)
    k = o.psf(band, pixel_pitch_um=2.8)
    r = k.shape[0] // 2
    m = np.arange(-r, r + 1)
    xi = np.linspace(0, 0.5, 11)
    dtft = (k.sum(axis=0)[None] * np.cos(2 * np.pi * xi[:, None] * m[None])).sum(axis=1)
    js = range(-6, 7)
    alias = sum(o.otf(xi + a, 0.0 * xi + b, band, pixel_pitch_um=2.8) for a in js for b in js)
    at0 = sum(o.otf(float(a), float(b), band, pixel_pitch_um=2.8) for a in js for b in js)
    np.testing.assert_allclose(dtft, alias / at0, atol=0.012)


def test_apply_optics_conserves_the_signal_and_keeps_flat_fields():
    img = np.zeros((33, 33, 3))
    img[16, 16] = 1.0
    out = apply_optics(img, Optics(), pixel_pitch_um=2.8)
    np.testing.assert_allclose(out.sum(axis=(0, 1)), 1.0, atol=1e-12)
    assert np.all(out[16, 16] < 1.0) and np.all(out >= 0)
    # blue is sharper than red (diffraction scales with the wavelength)
    assert out[16, 16, 2] > out[16, 16, 0]
    flat = np.full((20, 24, 3), 0.37)
    np.testing.assert_allclose(apply_optics(flat, Optics(olpf=1.0), pixel_pitch_um=2.8), 0.37,
                               rtol=1e-12)
    cube = np.random.default_rng(0).random((16, 16, 4))
    wl = [450.0, 550.0, 650.0, 750.0]
    out = apply_optics(cube, Optics(), pixel_pitch_um=2.8, wavelengths=wl)
    for b, w in enumerate(wl):
        np.testing.assert_allclose(out[..., b], apply_optics(cube[..., b], Optics(),
                                                             pixel_pitch_um=2.8, wavelengths=w))


def test_simulate_applies_optics_only_when_asked():
    rng = np.random.default_rng(1)
    img = rng.random((32, 32, 3))
    depth = np.where(np.arange(32)[None, :] < 16, 1.0, 1.5) * np.ones((32, 1))
    scene = Scene(img, depth=depth)
    plain = simulate(scene, "mask1", noise=False)
    again = simulate(scene, "mask1", noise=False, optics=None)
    np.testing.assert_array_equal(plain.data, again.data)
    np.testing.assert_array_equal(plain.tof.taps, again.tof.taps)
    assert "optics" not in plain.meta
    blurred = simulate(scene, "mask1", noise=False, optics=Optics(f_number=8.0))
    assert blurred.meta["optics"] == Optics(f_number=8.0)
    assert not np.array_equal(plain.data, blurred.data)
    # less pixel-to-pixel contrast: the blur is a low-pass filter
    contrast = [np.abs(np.diff(f.reference.astype(float)[:, ::2], axis=1)).mean()
                for f in (plain, blurred)]
    assert contrast[1] < 0.8 * contrast[0]
    # the colour model alone gives the same reference CFA
    alone = simulate_colour(scene, "mask1", noise=False, optics=Optics(f_number=8.0))
    np.testing.assert_array_equal(alone.data, blurred.reference)
    # a uniform scene is unchanged
    flat = Scene(np.full((16, 16, 3), 0.5))
    np.testing.assert_array_equal(simulate(flat, "mask1", noise=False).data,
                                  simulate(flat, "mask1", noise=False, optics=Optics()).data)


def test_frames_through_optics_do_not_depend_on_the_thread_count():
    """The FFTs run on the simulation's threads (pocketfft transforms each line alone):
    the same frame, colour and taps, on 1 and 2 threads; a frame large enough for two."""
    rng = np.random.default_rng(4)
    shape = (720, 760)
    img = rng.random(shape + (3,))
    depth = np.where(np.arange(shape[1])[None, :] < 380, 1.0, 1.6) * np.ones((shape[0], 1))
    scene = Scene(img, depth=depth)
    a, b = (simulate(scene, "mask2", seed=3, optics=Optics(f_number=4.0), workers=w)
            for w in (1, 2))
    np.testing.assert_array_equal(a.data, b.data)
    np.testing.assert_array_equal(a.tof.taps, b.tof.taps)
    np.testing.assert_array_equal(apply_optics(img, Optics(), pixel_pitch_um=2.8, workers=1),
                                  apply_optics(img, Optics(), pixel_pitch_um=2.8, workers=2))


HARMONICS = ((2, 0.1, 0.3), (3, 0.05, 1.0))


@pytest.mark.parametrize("workers", [1, 2])
def test_tof_field_kernel_equals_the_numpy_returns_bit_for_bit(workers):
    """``_kernels.sim_tof_field`` gives ``ToFSensor._returns``' fields, s e^{i h phi}, bit for
    bit, the sign of every zero included: every order of a sensor with harmonics, five
    frequencies, depths from the smallest double to 1e6 m, no light (s = 0) at every
    seventh."""
    rng = np.random.default_rng(workers)
    d = np.concatenate([rng.uniform(0.05, 12.0, 40_000), rng.uniform(0, 1e-3, 1000),
                        [5e-324, 1e-300, 1.0, 7.49, 12.5, 1e6]])
    s = rng.uniform(0, 3e4, d.size)
    s[::7] = 0.0
    sensor = ToFSensor(frequencies=(20e6, 80e6, 100e6, 120e6, 150e6), harmonics=HARMONICS)
    fields, _ = sensor._returns(d, s)
    assert sorted(fields) == [1, 2, 3]
    for h, field in fields.items():
        for k, f in enumerate(sensor.frequencies):
            re, im = np.empty_like(d), np.empty_like(d)
            _kernels.sim_tof_field(d, s, float(4 * np.pi * np.float64(f)), SPEED_OF_LIGHT,
                                   2 * np.pi, h, re, im, workers)
            for got, want in ((re, field[k].real), (im, field[k].imag)):
                np.testing.assert_array_equal(got, want)
                np.testing.assert_array_equal(np.signbit(got), np.signbit(want))
    with pytest.raises(ValueError, match="inconsistent"):
        _kernels.sim_tof_field(d, s[:-1], 1.0, SPEED_OF_LIGHT, 2 * np.pi, 1, re, im, 1)


@pytest.mark.parametrize("sensor", [ToFSensor(), ToFSensor(harmonics=HARMONICS, z_block=1)],
                         ids=["default", "harmonics-1x1"])
@pytest.mark.parametrize("workers", [1, 2])
def test_tof_light_through_optics_equals_the_numpy_fields(sensor, workers):
    """The optics path's phasors and light per measurement, each frequency's field from the
    C pass, equal those of the whole-frame NumPy fields (tests/_reference) bit for bit."""
    from rgbz_fast.simulation import _tof_light
    from rgbz_fast.simulation._simulate import _z_block, _z_sites
    from rgbz_fast._patterns import get_pattern

    rng = np.random.default_rng(11)
    shape = (60, 72)
    depth = np.where(np.arange(shape[1])[None, :] < 30, 1.2, 3.4) + 0.2 * rng.random(shape)
    depth[:5, :7] = 0.0                                   # no surface: no return
    valid = depth > 0
    scene = Scene(rng.random(shape + (3,)), depth=depth, depth_valid=valid)
    pattern = get_pattern("mask2")
    block = sensor.z_block or _z_block(pattern)
    rows, cols = _z_sites(pattern, shape, block)
    offs = [(a, c) for a in range(block) for c in range(block)]
    cr = np.stack([rows + a for a, _ in offs], axis=1)
    cc = np.stack([cols + c for _, c in offs], axis=1)
    optics = Optics(f_number=2.0, defocus_um=8.0)
    got = _tof_light._tof_light_through(scene, sensor, 2.8, cr, cc, optics, workers)
    want = ref_sim.tof_light_through(scene, sensor, 2.8, cr, cc, optics, workers)
    assert sorted(got[0]) == sorted(want[0])
    for h in want[0]:
        np.testing.assert_array_equal(got[0][h], want[0][h])
    np.testing.assert_array_equal(got[1], want[1])


def test_tof_optics_mixes_returns_at_depth_edges_only():
    """Defocus blurs the returned light across a 1 m -> 2 m edge: the measurements next to
    it mix the two surfaces (lens-induced flying pixels), the ISP flags them, and the far
    ones keep their depth."""
    shape = (32, 64)
    depth = np.where(np.arange(64)[None, :] < 32, 1.0, 2.0) * np.ones((32, 1))
    scene = Scene(np.full(shape + (3,), 0.5), depth=depth, ir_reflectance=np.full(shape, 0.5))
    sensor = ToFSensor(quantise=False)
    sharp = simulate_tof(scene, "mask2", sensor, noise=False)
    blur = simulate_tof(scene, "mask2", sensor, noise=False, optics=Optics(defocus_um=30.0))
    d_sharp = tof_depth(sharp, denoise="none").depth
    res = tof_depth(blur)
    d_blur = tof_depth(blur, denoise="none").depth
    cols = blur.sites[1]
    far = np.abs(cols - 31.5) > 12
    np.testing.assert_allclose(d_blur[far], d_sharp[far], atol=2e-3)
    near = np.abs(cols - 31.5) < 4
    # the far side next to the edge takes the bright near surface's light: 0.93 m for 2 m
    behind = near & (cols > 31.5)
    assert np.all(np.abs(d_blur[behind] - 2.0) > 0.5)
    assert np.all(np.abs(d_sharp[behind] - 2.0) < 2e-3)
    assert not res.valid[near].any()


def test_evaluation_blurs_before_the_mosaic():
    img = (np.random.default_rng(2).random((24, 24, 3)) * 255).astype(np.uint8)
    cfg = EvalConfig(metrics=("cfa_psnr",), methods=("bi",))
    frame, ref = image_frames(img, "mask1", cfg)
    frame_o, ref_o = image_frames(img, "mask1", EvalConfig(metrics=("cfa_psnr",),
                                                           methods=("bi",), optics=Optics()))
    assert not np.array_equal(ref, ref_o)
    np.testing.assert_array_equal(frame_o.data[~frame_o.z_mask], ref_o[~frame_o.z_mask])
    assert "optics f/2.8" in EvalConfig(optics=Optics()).label()
    # optics enter the cache key (a configuration without them leaves the field out)
    assert EvalConfig().key("mask1", "sg") != EvalConfig(optics=Optics()).key("mask1", "sg")
    flat = np.full((16, 16, 3), 128, np.uint8)
    np.testing.assert_array_equal(image_frames(flat, "mask1", cfg)[1],
                                  image_frames(flat, "mask1", EvalConfig(optics=Optics()))[1])


@pytest.mark.parametrize("make,exc,name", [
    (lambda: Optics(f_number=0), ValueError, "Optics.f_number"),
    (lambda: Optics(olpf=3), ValueError, "Optics.olpf"),
    (lambda: Optics(defocus_um=-1), ValueError, "Optics.defocus_um"),
    (lambda: Optics(fill_factor=0), ValueError, "Optics.fill_factor"),
    (lambda: Optics(bands_nm=((500, 600),)), ValueError, "Optics.bands_nm"),
    (lambda: Optics(bands_nm=((600, 500), (1, 2), (3, 4))), ValueError, "Optics.bands_nm"),
    (lambda: Optics(bands_nm=5), TypeError, "Optics.bands_nm"),
    (lambda: Optics().psf(100.0, pixel_pitch_um=2.8), ValueError, "wavelength_nm"),
    (lambda: Optics().psf(540.0, pixel_pitch_um=0), ValueError, "pixel_pitch_um"),
    (lambda: apply_optics(np.zeros((4, 4, 3)), "f/2", pixel_pitch_um=2.8), TypeError, "optics"),
    (lambda: apply_optics(np.zeros((4, 4, 5)), Optics(), pixel_pitch_um=2.8), ValueError,
     "wavelengths"),
    (lambda: simulate(np.full((8, 8, 3), 0.5), "mask1", optics="f/2"), TypeError, "optics"),
    (lambda: EvalConfig(optics=2.8), TypeError, "optics"),
])
def test_bad_optics_input_names_the_parameter(make, exc, name):
    with pytest.raises(exc, match=name):
        make()
    assert rz.simulation.Optics is Optics


def test_the_kernel_holds_a_wide_airy_disc():
    """G1 of the probes (2026-11-27): the kernel's period was sized on the defocus and the
    OLPF alone, so at f/64 on a 0.5 um pitch (the Airy disc's first zero at 89 pixels) it
    was a flat 63 x 63 box whose MTF passed what the lens cuts (0.464 at 0.01 cycles/pixel
    for the OTF's 0.162). The kernel's MTF now follows the OTF (within the 1 % of energy the
    cut leaves out), and a disc no grid holds is refused naming the Airy disc."""
    for n, p in ((64, 1.0), (32, 1.0), (2.8, 2.8)):
        o = Optics(f_number=n)
        k = o.psf(570.0, pixel_pitch_um=p)
        x = np.arange(k.shape[0]) - k.shape[0] // 2
        for f in (0.005, 0.01, 0.02):
            mtf = float((k.sum(0) * np.cos(2 * np.pi * f * x)).sum())
            want = float(o.otf(np.array([f]), np.array([0.0]), 570.0, pixel_pitch_um=p)[0])
            assert abs(mtf - want) < 0.05, (n, p, f, mtf, want)
    with pytest.raises(ValueError, match=r"Airy disc's first zero at 445 pixels"):
        Optics(f_number=64).psf(570.0, pixel_pitch_um=0.1)


@pytest.mark.parametrize("bands", [1, 2])
def test_a_spectral_scene_of_fewer_than_three_bands_is_refused(bands):
    """G2 (2026-11-27): one or two bands made a Scene, and simulate failed after its whole run
    blaming 'wavelengths', which the caller had not given it."""
    cube = np.full((8, 8, bands), 0.5)
    with pytest.raises(ValueError, match=r"^image: a spectral scene needs at least 3 bands"):
        Scene(cube, depth=np.full((8, 8), 1.0), wavelengths=500.0 + 50.0 * np.arange(bands))


def test_load_spectral_says_where_its_wavelengths_came_from(tmp_path):
    """G5 (2026-11-27): a cube of 80 bands without band centres took CAVE's 400 + 10 k nm and
    was refused for 'wavelengths' the caller had not given, without saying so."""
    from rgbz_fast.simulation import load_spectral

    from scipy.io import savemat

    savemat(tmp_path / "cube.mat", {"cube": np.full((8, 8, 80), 0.5)})
    with pytest.raises(ValueError, match=r"^wavelengths: .*\(from CAVE's convention 400 \+ 10 "
                                         r"k nm for its 80 bands \(none given\); pass "
                                         r"wavelengths=\)$"):
        load_spectral(tmp_path / "cube.mat", depth=1.0)
    savemat(tmp_path / "b.mat", {"cube": np.full((8, 8, 31), 0.5), "bands": np.arange(1, 32)})
    with pytest.raises(ValueError, match=r"\(from the file's variable 'bands'; pass "):
        load_spectral(tmp_path / "b.mat", depth=1.0)
