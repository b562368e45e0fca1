"""Sensor models of the RGB-Z imager: colour pixels, i-ToF depth pixels, the RGB-Z build.

Paper §5.1 (Figs. 16, 18, 19), with ISETCam's sensor model [2]_ as the
yardstick for what a credible model contains. Three stages, each a plain
function of a :class:`~rgbz_fast.simulation.Scene` and a frozen dataclass of
parameters:

* :func:`simulate_colour` -- :class:`ColourSensor` (§5.1.1): the plain Bayer
  CFA of a scene, in 11-bit digital numbers (DN).
* :func:`simulate_tof` -- :class:`ToFSensor` (§5.1.2): four taps per Z pixel
  and per modulation frequency, as the chip reads them (:class:`ToFTaps`).
* :func:`simulate` -- the RGB-Z build (§5.1.3): a :class:`~rgbz_fast.RawFrame`
  with the colour CFA at the colour sites, 0 at the Z sites, the taps in
  ``frame.tof``, and ``frame.reference`` = the plain Bayer CFA of the *same*
  exposure and noise draw (the paper's green path).

Only what the scene needs is simulated: no depth map (or no Z site in the
pattern) -> no ToF model runs, ``frame.tof is None`` and ``frame.meta["tof"]``
says why; an RGB scene runs no spectral integration; ``noise=False`` draws no
random numbers at all.

ToF tap convention (what a demodulation kernel must assume)
-----------------------------------------------------------
For every modulation frequency ``f`` (index ``i`` of ``ToFTaps.frequencies``)
and every Z measurement ``n`` (index into ``ToFTaps.sites``), the four taps
``A_k = ToFTaps.taps[i, k, n]``, k = 0, 1, 2, 3, hold in expectation::

    A_k = black_level + K * (O + a * cos(phi + k * pi / 2))

    phi = 4 * pi * f * d / c   (mod 2 pi)     d: distance in metres, c = 299792458 m/s
    O   = (S + B) / 4 + dark_current * integration_time     (electrons per tap)
    a   = modulation_contrast * S / 4                        (electrons)

with ``S`` the active (laser) photo-electrons and ``B`` the ambient ones
collected by the whole Z pixel over one integration time, and ``K`` the
system gain in DN/e- (:attr:`ToFSensor.system_gain`). Tap k's demodulation
gate is therefore shifted by ``-k * 90`` degrees, and

    I = A_0 - A_2 = 2 K a cos(phi)
    Q = A_3 - A_1 = 2 K a sin(phi)
    phi = atan2(A_3 - A_1, A_0 - A_2)  wrapped to [0, 2 pi)
    depth = c * phi / (4 pi f)  +  m * c / (2 f),  m = 0, 1, 2, ... (the wrap count)
    amplitude (DN) = sqrt(I**2 + Q**2) / 2 = K * a
    offset (DN)    = (A_0 + A_1 + A_2 + A_3) / 4 = black_level + K * O

The black level cancels in I and Q. Each frequency wraps at ``c / (2 f)``;
together the frequencies are unambiguous up to ``c / (2 * gcd(f_i))``
(:attr:`ToFSensor.unambiguous_range`). The defaults 80, 100 and 120 MHz wrap
at 1.874, 1.499 and 1.249 m and are unambiguous to 7.495 m. Depths beyond
it raise an :class:`UnambiguousRangeWarning` and are marked invalid.

A Z measurement of a Mask2 pattern is one 2x2 Z pixel (four colour-pixel
cells, four times the light-collecting area); its taps are the sums of the
four cells' phasors, so a depth edge inside the pixel mixes the two
returns as a real pixel does ("flying pixels").

Noise model (both sensors)
--------------------------
Per pixel (colour) or per tap (ToF), in electrons ``e``
(:func:`rgbz_fast.simulation._noise.expose`):

1. mean signal ``mu``; PRNU multiplies it by a fixed gain ``1 + prnu * N1``;
2. dark current adds ``dark_current * t``; shot noise draws
   ``Poisson(mu * gain + dark)`` -- the sum of the photon and dark-current
   shot noises, which are independent Poisson variables;
3. DSNU adds a fixed offset ``dsnu * N2`` (e-);
4. the well saturates: ``e = min(e, full_well)``;
5. read noise adds ``read_noise * N3`` (e-);
6. the ADC: ``DN = black_level + K * e``, rounded half up (quantisation),
   clipped to ``[0, 2**bit_depth - 1]``.

``N1``, ``N2`` are standard normal maps fixed by the sensor's ``fpn_seed``
(the same sensor gives the same fixed pattern in every frame); shot and read
noise come from the frame's ``seed``. Every term can be turned off
(``shot_noise=False``, ``dark_current=0``, ``read_noise=0``, ``dsnu=0``,
``prnu=0``, ``quantise=False``, ``full_well=inf``); ``noise=False`` turns off
all the random and fixed-pattern terms at once and gives the exact noise-free
frame.

References
----------
.. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", section 5.1 (docs/references.bib: rebiere_rgbz)
.. [2] Farrell, Catrysse and Wandell, "Digital camera simulation" -- ISETCam (docs/references.bib: farrell2012isetcam)
.. [3] EMVA Standard 1288 -- photon transfer, DSNU, PRNU (docs/references.bib: emva1288)
.. [4] Lange and Seitz, "Solid-state time-of-flight range camera" -- four-phase demodulation and its noise (docs/references.bib: lange2001tof)
"""

from __future__ import annotations

import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np

from .. import _kernels
from .._frame import RawFrame, ToFTaps, _Adopt
from .._patterns import Z, get_pattern
from .._sensors import ColourSensor, ToFSensor
from .._validate import check_flag, check_number, check_seed, check_workers
from . import _pixels
from ._loaders import load_scene
from ._noise import (RNG_VERSION, STREAM_COLOUR_FPN, STREAM_COLOUR_TEMPORAL,
                     STREAM_TOF_FPN, STREAM_TOF_TEMPORAL, check_rng_version, expose,
                     noise_fields, stream_keys)
from ._optics import Optics, apply_optics
from ._scene import Scene
from ._spectral import _spectral_integrate, _spectral_weights
from ._tof_light import _tof_mean

__all__ = ["UnambiguousRangeWarning", "simulate", "simulate_colour", "simulate_tof"]

class UnambiguousRangeWarning(RuntimeWarning):
    """A scene depth lies beyond the unambiguous range of the ToF frequencies."""


def _colour_values(scene, sensor, colour_map, optics=None, workers=None):
    """What the colour pixels see, before the per-unit signal: the scene's linear RGB image
    (through ``optics`` when given), or for a spectral scene the channel value of every
    site (one dot product per site)."""
    image = scene.image
    if optics is not None:
        image = apply_optics(image, optics, pixel_pitch_um=sensor.pixel_pitch_um,
                             wavelengths=scene.wavelengths, workers=workers)
    if scene.is_spectral:
        return _spectral_integrate(image, _spectral_weights(sensor, scene.wavelengths),
                                   colour_map)
    return image


def _colour_signal_rate(values, sensor, colour_map):
    """Mean signal electrons per second at every CFA site (noise-free, no PRNU), in NumPy:
    the reference of the C kernels (csrc/sim.c) and the path of ``rng_version=1``."""
    per_unit = sensor.electrons_per_unit(1.0)
    if values.ndim == 2:
        value = values
    else:
        value = np.take_along_axis(values, colour_map[..., None].astype(np.intp),
                                   axis=2)[..., 0].astype(np.float64)
    return value * per_unit[colour_map]


def _exposure(level, sensor):
    """The auto-exposure time from the ``ae_percentile`` percentile of the signal rate."""
    if not level > 0:
        raise ValueError(f"scene: the {sensor.ae_percentile:g}th percentile of the signal is 0 "
                         "(a black scene); auto-exposure needs light -- set "
                         "ColourSensor(exposure=...) instead")
    exposure = sensor.ae_target * sensor.usable_electrons() / level
    if not exposure <= _MAX_EXPOSURE:
        raise ValueError(f"scene: too dark for auto-exposure, which would need {exposure:g} s "
                         f"(more than {_MAX_EXPOSURE:g} s); brighten the scene or set "
                         "ColourSensor(exposure=...)")
    return exposure


#: the longest exposure, in seconds: what ColourSensor(exposure=...) accepts, and what
#: auto-exposure may choose (a longer one turns the dark current alone into ~1e50 electrons)
_MAX_EXPOSURE = 3600.0


def _check_optics(optics):
    if optics is not None and not isinstance(optics, Optics):
        raise TypeError(f"optics: expected an Optics or None, got {type(optics).__name__}")
    return optics


def _as_scene(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, (str, Path)):
        return load_scene(scene)
    if isinstance(scene, np.ndarray):
        return Scene(scene)
    raise TypeError(f"scene: expected a Scene, an image array or a path, got "
                    f"{type(scene).__name__}")


def simulate_colour(scene, pattern="bayer", sensor=None, *, seed=0, noise=True, optics=None,
                    rng_version=RNG_VERSION, workers=None):
    """Simulate the colour pixels: the plain Bayer CFA of a scene (paper §5.1.1).

    Parameters
    ----------
    scene : Scene, ndarray or path
        The scene (an array becomes ``Scene(array)``, a path goes through
        :func:`~rgbz_fast.simulation.load_scene`).
    pattern : Pattern or str
        Its underlying Bayer phase gives the colour of every site (Z sites
        are simulated as the colour they replace: this is the reference CFA).
    sensor : ColourSensor, optional
        Default ``ColourSensor()``.
    seed : int
        Seed of the temporal noise (shot, read).
    noise : bool
        False: no random and no fixed-pattern term (and no random number is
        drawn): the exact noise-free CFA.
    optics : Optics, optional
        Blur the scene through the lens and the pixel aperture before the
        pixels sample it (:mod:`rgbz_fast.simulation._optics`); None (the
        default): the scene's values reach the pixels as they are.
    rng_version : {2, 1}
        The random numbers (:mod:`rgbz_fast.simulation._noise`): 2, the
        default, counter-based (the same frame on any number of threads); 1,
        NumPy's streams of rgbz-fast 0.1 (its frames bit for bit). The same
        noise-free frame either way, but for a ToF delay pattern
        (``delay_fpn_ps``), which version 1 draws in the sites' order.
    workers : int, optional
        Threads (None or -1: all cores). The frame does not depend on it.

    Returns
    -------
    RawFrame
        On the plain Bayer pattern, ``bit_depth = sensor.bit_depth``, uint16
        (float64 if ``sensor.quantise`` is False); ``meta`` holds
        ``exposure`` (s), ``system_gain`` (DN/e-), ``saturated`` (fraction of
        sites clipped: at full well, at full scale or at the ADC's floor of 0
        DN), ``spectral``, ``rng_version``,
        ``colour_black_level`` (the sensor's black level, DN),
        ``colour_saturation_level`` when the well fills below the ADC's top
        (:func:`saturation_level`, DN: the colour ISP's white level) and, for a
        spectral scene, ``white_gains`` (R, G, B) and ``colour_matrix`` (nine
        numbers, row by row): the sensor's white balance and its matrix to
        linear sRGB (:func:`~rgbz_fast.simulation.white_gains`,
        :func:`~rgbz_fast.simulation.colour_matrix`), which the colour ISP
        applies.
    """
    scene = _as_scene(scene)
    pattern = get_pattern(pattern)
    sensor = ColourSensor() if sensor is None else sensor
    if not isinstance(sensor, ColourSensor):
        raise TypeError(f"sensor: expected a ColourSensor, got {type(sensor).__name__}")
    seed = check_seed(seed, "seed")
    dn, _, meta = _colour_frames(scene, pattern, sensor, seed, check_flag(noise, "noise"),
                                 _check_optics(optics), check_rng_version(rng_version), workers,
                                 rgbz=False)
    return RawFrame(_Adopt(dn), pattern.bayer_pattern(), sensor.bit_depth, meta=meta)


def _keys(noise, seed, sensor, temporal_stream, fpn_stream):
    """The random streams' keys of a noisy frame; none (zeros, never read) without noise."""
    if not noise:
        return np.zeros(8, np.uint32)
    return stream_keys(seed, sensor.fpn_seed, temporal_stream, fpn_stream)


def _colour_frames(scene, pattern, sensor, seed, noise, optics, rng_version, workers, rgbz):
    """The colour pixels of validated arguments: ``(reference CFA, RGB-Z data or None,
    meta)``; ``rgbz``: also the data, the reference with 0 at the Z sites."""
    shape = pattern.check_shape(scene.shape, "scene")
    colour_map = pattern.bayer_map(shape) if scene.is_spectral else None
    values = _colour_values(scene, sensor, colour_map, optics, workers)
    per_unit = sensor.electrons_per_unit(1.0)
    legacy = noise and rng_version == 1
    if legacy:
        colour_map = pattern.bayer_map(shape) if colour_map is None else colour_map
        rate = _colour_signal_rate(values, sensor, colour_map)
    else:
        source = _pixels.colour_source(values)
    if sensor.exposure != "auto":
        exposure = sensor.exposure
    elif legacy:
        exposure = _exposure(float(np.percentile(rate, sensor.ae_percentile)), sensor)
    else:
        exposure = _exposure(_pixels.rate_percentile(source, pattern, per_unit,
                                                     sensor.ae_percentile, workers), sensor)
    if legacy:
        dn, saturated = expose(rate * exposure, sensor.dark_current * exposure, sensor,
                               noise=True, seed=seed, temporal_stream=STREAM_COLOUR_TEMPORAL,
                               fpn_stream=STREAM_COLOUR_FPN)
        saturated = float(saturated.mean())
        data = None
        if rgbz:
            data = dn.copy()
            data[pattern.z_mask(shape)] = 0
    else:
        fields = noise_fields(sensor, noise=noise, dark_e=sensor.dark_current * exposure)
        keys = _keys(noise, seed, sensor, STREAM_COLOUR_TEMPORAL, STREAM_COLOUR_FPN)
        dn, data, nsat = _pixels.colour_dn(source, pattern, per_unit, exposure, fields, keys,
                                           rgbz=rgbz, workers=workers)
        saturated = nsat / dn.size
    meta = {"exposure": float(exposure), "system_gain": sensor.system_gain,
            "saturated": saturated, "spectral": scene.is_spectral,
            "noise": noise, "seed": seed, "scene": scene.name, "rng_version": rng_version,
            "colour_black_level": float(sensor.black_level)}
    level = saturation_level(sensor, noise)
    if level < sensor.white_level:
        # the well fills below the ADC's top: the colour ISP takes this as its white level
        # (grey world leaves these pixels out, the highlights clip white); frames that
        # saturate at the top record nothing (2**bit_depth - 1 is the default)
        meta["colour_saturation_level"] = level
    if scene.is_spectral:
        # the camera RGB of spectral sensitivities is not sRGB: the gains and the matrix
        # that render it, which the colour ISP takes from the frame
        from ._colour import colour_matrix, white_gains

        meta["white_gains"] = tuple(float(g) for g in white_gains(sensor, scene.wavelengths))
        meta["colour_matrix"] = tuple(float(v) for v in
                                      colour_matrix(sensor, scene.wavelengths).ravel())
    if optics is not None:
        meta["optics"] = optics
    return dn, data, meta


def _z_block(pattern):
    """2 if the Z sites of the tile form aligned 2x2 squares (Mask2, rows), else 1."""
    tile = pattern.tile == Z
    P, Q = tile.shape
    if P % 2 or Q % 2:
        return 1
    quads = tile.reshape(P // 2, 2, Q // 2, 2)
    full = quads.all(axis=(1, 3))
    empty = ~quads.any(axis=(1, 3))
    return 2 if np.all(full | empty) and full.any() else 1


def _z_sites(pattern, shape, block, workers=None):
    """(rows, cols) of the Z measurements' top-left cells, row-major (a 2x2 block cut by
    the frame edge is dropped), on ``workers`` threads."""
    if block == 2 and _z_block(pattern) != 2:
        raise ValueError(f"ToFSensor.z_block: 2 needs Z sites in aligned 2x2 squares; pattern "
                         f"{pattern.name!r} has none")
    return _pixels.z_sites(pattern, shape, block, check_workers(workers))


def simulate_tof(scene, pattern, sensor=None, *, seed=0, noise=True, pixel_pitch_um=None,
                 optics=None, rng_version=RNG_VERSION, workers=None, _stacklevel=2):
    """Simulate the i-ToF taps at the Z sites of a pattern (paper §5.1.2).

    Parameters
    ----------
    scene : Scene
        Must hold a depth map. The NIR reflectance is the scene's or the
        estimate of :func:`~rgbz_fast.simulation.estimate_ir_reflectance`,
        evaluated at the Z sites only.
    pattern : Pattern or str
        Must hold Z sites.
    sensor : ToFSensor, optional
        Default ``ToFSensor()``.
    seed : int
        Seed of the temporal noise.
    noise : bool
        False: noise-free taps (no shot, read, dark or fixed-pattern noise).
        The systematic non-idealities of ``sensor`` (harmonics, tap
        contrasts, delays, multipath) stay: they are the sensor's response,
        the same in every frame (the per-pixel delays come from ``fpn_seed``).
    pixel_pitch_um : float, optional
        Cell pitch when ``sensor.pixel_pitch_um`` is None (default 2.8).
    optics : Optics, optional
        Blur the returned light (and the ambient light) through the lens
        before the pixels collect it: :class:`Optics` with the laser's
        ``sensor.wavelength_nm`` and the ToF lens's ``sensor.f_number``
        (its OLPF, defocus and fill factor as given). None: no blur.
    rng_version : {2, 1}
        The random numbers, as in :func:`simulate_colour`.
    workers : int, optional
        Threads (None or -1: all cores). The taps do not depend on it.

    Returns
    -------
    ToFTaps
        ``meta`` holds ``rng_version`` beside the run's settings.

    Warns
    -----
    UnambiguousRangeWarning
        If a depth lies beyond ``sensor.unambiguous_range`` (those sites are
        marked invalid; their taps wrap as a real chip's would).
    """
    scene = _as_scene(scene)
    pattern = get_pattern(pattern)
    sensor = ToFSensor() if sensor is None else sensor
    if not isinstance(sensor, ToFSensor):
        raise TypeError(f"sensor: expected a ToFSensor, got {type(sensor).__name__}")
    seed = check_seed(seed, "seed")
    optics = _check_optics(optics)
    rng_version = check_rng_version(rng_version)
    noise = check_flag(noise, "noise")
    if not scene.has_depth:
        raise ValueError("scene: has no depth map, so there is nothing for the ToF pixels "
                         "to measure")
    if not pattern.has_z:
        raise ValueError(f"pattern: {pattern.name!r} has no Z site")
    shape = pattern.check_shape(scene.shape, "scene")
    pitch = sensor.pixel_pitch_um
    if pixel_pitch_um is not None:
        given = check_number(pixel_pitch_um, "pixel_pitch_um", lo=0, lo_open=True)
        if pitch is not None and given != pitch:
            raise ValueError(f"pixel_pitch_um: {given:g} um differs from the sensor's "
                             f"pixel_pitch_um {pitch:g} um; give one of them")
        pitch = given
    if sensor.pixel_pitch_um is None:
        pitch = 2.8 if pitch is None else pitch
        sensor = replace(sensor, pixel_pitch_um=pitch)
    block = sensor.z_block if sensor.z_block is not None else _z_block(pattern)
    rows, cols = _z_sites(pattern, shape, block, workers)
    if rows.size == 0:
        raise ValueError(f"scene: a {shape[0]}x{shape[1]} frame holds no complete "
                         f"{block}x{block} Z pixel of pattern {pattern.name!r}")
    legacy = noise and rng_version == 1
    if not legacy:
        fields = noise_fields(sensor, noise=noise, dark_e=sensor._dark_electrons)
        keys = _keys(noise, seed, sensor, STREAM_TOF_TEMPORAL, STREAM_TOF_FPN)
    if (optics is None and sensor.is_ideal and not legacy
            and len(sensor.frequencies) <= _kernels.TOF_MAX_FREQS):
        taps, depth_true, valid, beyond, sat, dmax = _pixels.tof_ideal(
            scene, sensor, pitch, (rows, cols), block, fields, keys, workers)
    else:
        mean, suppress, depth_true, valid, beyond, dmax = _tof_mean(
            scene, sensor, pitch, rows, cols, block, optics, workers,
            positional=rng_version != 1)
        if legacy:
            taps, sat = expose(mean, sensor._dark_electrons, sensor, noise=True, seed=seed,
                               temporal_stream=STREAM_TOF_TEMPORAL, fpn_stream=STREAM_TOF_FPN,
                               fpn_shape=mean.shape[1:], suppress=suppress)
            sat = sat.any(axis=(0, 1))
        else:
            taps, sat = _pixels.tof_expose(mean, suppress, (rows, cols), fields, keys, workers)
    if beyond.any():
        warnings.warn(
            f"{int(beyond.sum())} of {rows.size} Z sites see depths up to {dmax:.3g} m, "
            f"beyond the {sensor.unambiguous_range:.4g} m unambiguous range of "
            f"{', '.join(f'{f / 1e6:g}' for f in sensor.frequencies)} MHz; they are marked "
            "invalid (ToFTaps.valid)", UnambiguousRangeWarning, stacklevel=_stacklevel)
        valid = valid & ~beyond
    meta = {"noise": noise, "seed": seed, "pattern": pattern.name,
            "integration_time": sensor.integration_time, "system_gain": sensor.system_gain,
            "wrap_ranges": sensor.wrap_ranges, "rng_version": rng_version,
            "ir_estimated": scene.ir_reflectance is None}   # NIR from the RGB: a leaking guide
    return ToFTaps(_Adopt(taps), np.asarray(sensor.frequencies), _Adopt((rows, cols)), block,
                   sensor.bit_depth, *map(_Adopt, (depth_true, valid, sat)), sensor, shape, meta)


# --------------------------------------------------------------------------
# RGB-Z build
# --------------------------------------------------------------------------
def saturation_level(sensor, noise=True):
    """The DN from which a pixel of ``sensor`` may be saturated: its full well after the ADC,
    less three read-noise sigmas when the noise runs (a full well's codes spread by the read
    noise added after it), at most the ADC's top ``2**bit_depth - 1``."""
    well = float(sensor.full_well)
    if noise and sensor.read_noise > 0:
        well -= 3.0 * float(sensor.read_noise)
    return float(min(sensor.white_level, sensor.black_level + sensor.system_gain * well))


def simulate(scene, pattern, colour_sensor=None, tof_sensor=None, *, seed=0, noise=True,
             optics=None, rng_version=RNG_VERSION, workers=None):
    """Simulate a raw RGB-Z frame and its reference Bayer frame (paper §5.1.3, Fig. 16).

    The colour model runs once over every site of the pattern's underlying
    Bayer mosaic: that CFA is ``frame.reference`` (the paper's green path).
    The RGB-Z build copies it and replaces the colour at the Z sites by 0, so
    the colour sites of ``frame.data`` and ``frame.reference`` hold the very
    same exposure and noise draw and only the build differs. The ToF model
    runs when the scene has a depth map and the pattern has Z sites; its
    taps go to ``frame.tof``.

    Parameters
    ----------
    scene : Scene, ndarray or path
        The scene; its (H, W) is the frame shape.
    pattern : Pattern or str
        The CDFA (``"mask1"``, ``"mask2"``, ``"rows"``, a tile, ``"bayer"``).
    colour_sensor : ColourSensor, optional
        Default ``ColourSensor()``.
    tof_sensor : ToFSensor, optional
        Default ``ToFSensor()`` (used only if the ToF model runs). Its
        ``pixel_pitch_um`` is the colour sensor's unless set (and then it
        must agree: one matrix has one pitch).
    seed : int
        Seed of the temporal noise of both models (independent streams).
    noise : bool
        False: the exact noise-free frame; no random number is drawn.
    optics : Optics, optional
        The lens in front of the matrix: it blurs the scene for the colour
        pixels (each channel over its band, :func:`simulate_colour`) and the
        returned light for the Z pixels (at the laser wavelength and
        ``tof_sensor.f_number``, :func:`simulate_tof`). None (the default):
        no blur: the scene's values reach the pixels as they are.
    rng_version : {2, 1}
        The random numbers (:mod:`rgbz_fast.simulation._noise`): 2, the
        default, counter-based, computed in C (the same frame on any number
        of threads); 1, NumPy's streams of rgbz-fast 0.1 (its frames bit for
        bit). The same noise-free frame either way, but for a ToF delay pattern
        (``delay_fpn_ps``), which version 1 draws in the sites' order.
    workers : int, optional
        Threads (None or -1: all cores). The frame does not depend on it.

    Returns
    -------
    RawFrame
        ``data``: colour CFA at colour sites, 0 at Z sites; ``reference``:
        the plain Bayer CFA; ``tof``: :class:`ToFTaps` or None; ``meta``:
        ``exposure`` (s), ``system_gain``, ``saturated``, ``spectral``,
        ``noise``, ``seed``, ``scene``, ``rng_version``, ``colour_sensor``,
        ``tof_sensor`` and ``tof`` (a sentence saying whether and why the ToF
        model ran).

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.simulation import Scene
    >>> scene = Scene(np.full((8, 8, 3), 0.5), depth=np.full((8, 8), 1.2))
    >>> frame = simulate(scene, "mask2", noise=False)
    >>> frame.tof.taps.shape, frame.tof.block
    ((3, 4, 4), 2)
    >>> int(frame.data[0, 0]), bool((frame.data == frame.reference)[~frame.z_mask].all())
    (0, True)
    """
    scene = _as_scene(scene)
    pattern = get_pattern(pattern)
    colour_sensor = ColourSensor() if colour_sensor is None else colour_sensor
    if not isinstance(colour_sensor, ColourSensor):
        raise TypeError(f"colour_sensor: expected a ColourSensor, got "
                        f"{type(colour_sensor).__name__}")
    if tof_sensor is not None and not isinstance(tof_sensor, ToFSensor):
        raise TypeError(f"tof_sensor: expected a ToFSensor, got {type(tof_sensor).__name__}")
    pattern.check_shape(scene.shape, "scene")
    if pattern.bayer_phase is None:
        raise ValueError(f"pattern: {pattern.name!r} fits no Bayer phase, so there is no "
                         "reference Bayer CFA to simulate")

    optics = _check_optics(optics)
    seed, noise = check_seed(seed, "seed"), check_flag(noise, "noise")
    rng_version = check_rng_version(rng_version)
    ref, data, colour_meta = _colour_frames(scene, pattern, colour_sensor, seed, noise,
                                            optics, rng_version, workers, rgbz=True)

    if not scene.has_depth:
        tof, status, used = None, "not simulated: the scene has no depth map", None
    elif not pattern.has_z:
        tof, status, used = None, f"not simulated: pattern {pattern.name!r} has no Z site", None
    else:
        used = ToFSensor() if tof_sensor is None else tof_sensor
        if used.pixel_pitch_um is None:
            used = replace(used, pixel_pitch_um=colour_sensor.pixel_pitch_um)
        elif used.pixel_pitch_um != colour_sensor.pixel_pitch_um:
            raise ValueError(f"tof_sensor.pixel_pitch_um: {used.pixel_pitch_um} um differs from "
                             f"colour_sensor.pixel_pitch_um {colour_sensor.pixel_pitch_um} um; "
                             "Z and colour pixels share one matrix (leave it None)")
        tof = simulate_tof(scene, pattern, used, seed=seed, noise=noise, optics=optics,
                           rng_version=rng_version, workers=workers, _stacklevel=3)
        status = (f"simulated: {len(used.frequencies)} frequencies, {tof.n_sites} Z "
                  f"measurements of {tof.block}x{tof.block} pixels")
    meta = dict(colour_meta)
    meta.update(colour_sensor=colour_sensor, tof_sensor=used, tof=status,
                pattern=pattern.name)
    return RawFrame(_Adopt(data), pattern, colour_sensor.bit_depth, reference=_Adopt(ref),
                    tof=tof, meta=meta)
