"""Sensor models of the RGB-Z imager: colour pixels, i-ToF depth pixels, the RGB-Z build.

Paper §5.1 (Figs. 16, 18, 19), with ISETCam's sensor model [2]_ as the
yardstick for what a credible model contains. Three stages, each a plain
function of a :class:`~rgbz_fast.scene.Scene` and a frozen dataclass of
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
Per pixel (colour) or per tap (ToF), in electrons ``e``:

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
.. [1] V. Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z
       CMOS imager", §5.1.
.. [2] J. E. Farrell, P. B. Catrysse, B. A. Wandell, "Digital camera
       simulation", Applied Optics 51(4) (2012) -- ISETCam.
.. [3] EMVA Standard 1288, "Standard for characterization of image sensors
       and cameras", release 4.0 (2021) -- photon transfer, DSNU, PRNU.
.. [4] R. Lange, P. Seitz, "Solid-state time-of-flight range camera",
       IEEE J. Quantum Electron. 37(3) (2001) -- four-phase demodulation and
       its noise.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from ._frame import RawFrame
from ._patterns import Z, get_pattern
from ._validate import check_bit_depth, check_flag, check_seed
from .scene import Scene, estimate_ir_reflectance, load_scene

__all__ = [
    "ColourSensor", "ToFSensor", "ToFTaps", "UnambiguousRangeWarning",
    "simulate", "simulate_colour", "simulate_tof", "SPEED_OF_LIGHT",
]

#: Speed of light in vacuum, m/s.
SPEED_OF_LIGHT = 299_792_458.0
_PLANCK = 6.62607015e-34

# sub-stream keys of the random generators: temporal noise follows the frame
# seed, fixed-pattern noise the sensor's fpn_seed; each model has its own
# stream so that running (or not running) one never changes the other.
_STREAM_COLOUR_TEMPORAL = 0
_STREAM_COLOUR_FPN = 1
_STREAM_TOF_TEMPORAL = 2
_STREAM_TOF_FPN = 3


class UnambiguousRangeWarning(RuntimeWarning):
    """A scene depth lies beyond the unambiguous range of the ToF frequencies."""


# --------------------------------------------------------------------------
# parameter checks
# --------------------------------------------------------------------------

def _check_readout(obj):
    """Well, conversion gain, swing, ADC bits and black level: shared by both sensors."""
    _num(obj, "full_well", lo=0, lo_open=True, allow_inf=True)
    _num(obj, "conversion_gain_uv_per_e", lo=0, hi=1e4, lo_open=True)
    _num(obj, "voltage_swing", lo=0, hi=100, lo_open=True)
    object.__setattr__(obj, "bit_depth",
                       check_bit_depth(obj.bit_depth, f"{type(obj).__name__}.bit_depth"))
    _num(obj, "black_level", lo=0, hi=(1 << obj.bit_depth) - 1, hi_open=True)


def _check_pixel_noise(obj):
    """The noise terms and the fixed-pattern seed: shared by both sensors."""
    _flag(obj, "shot_noise")
    _num(obj, "dark_current", lo=0, hi=1e7)
    _num(obj, "read_noise", lo=0, hi=1e5)
    _num(obj, "dsnu", lo=0, hi=1e5)
    _num(obj, "prnu", lo=0, hi=1, hi_open=True)
    _flag(obj, "quantise")
    object.__setattr__(obj, "fpn_seed", _seed(obj.fpn_seed, f"{type(obj).__name__}.fpn_seed"))

def _num(obj, name, *, lo=None, hi=None, lo_open=False, hi_open=False, allow_inf=False):
    value = getattr(obj, name)
    label = f"{type(obj).__name__}.{name}"
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{label}: expected a number, got {value!r}")
    v = float(value)
    if math.isnan(v) or (math.isinf(v) and not allow_inf):
        raise ValueError(f"{label}: expected a finite number, got {value!r}")
    bad = ((lo is not None and (v < lo or (lo_open and v == lo)))
           or (hi is not None and (v > hi or (hi_open and v == hi))))
    if bad:
        lo_s = "" if lo is None else ("(" if lo_open else "[") + f"{lo:g}"
        hi_s = "inf)" if hi is None else f"{hi:g}" + (")" if hi_open else "]")
        raise ValueError(f"{label}: {value!r} is out of the physical range {lo_s}, {hi_s}")
    object.__setattr__(obj, name, v)
    return v


def _flag(obj, name):
    value = check_flag(getattr(obj, name), f"{type(obj).__name__}.{name}")
    object.__setattr__(obj, name, value)


_seed = check_seed   # one seed check for the sensors, simulate and EvalConfig (_validate.py)


def _spectrum_param(obj, name, ncols):
    """A colour-science name, or (wavelengths, values) turned into hashable tuples."""
    value = getattr(obj, name)
    label = f"{type(obj).__name__}.{name}"
    if isinstance(value, str):
        return
    try:
        wl, vals = value
        wl = np.asarray(wl, dtype=np.float64)
        vals = np.asarray(vals, dtype=np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"{label}: expected a colour-science dataset name or a "
                        f"(wavelengths, values) pair, got {type(value).__name__}") from None
    if vals.ndim == 1 and ncols == 1:
        vals = vals[:, None]
    if wl.ndim != 1 or vals.shape != (wl.size, ncols) or wl.size < 2:
        raise ValueError(f"{label}: expected wavelengths (N,) and values (N, {ncols}), got "
                         f"{wl.shape} and {vals.shape}")
    if not (np.all(np.isfinite(wl)) and np.all(np.isfinite(vals))):
        raise ValueError(f"{label}: holds NaN or infinite values")
    if np.any(np.diff(wl) <= 0):
        raise ValueError(f"{label}: wavelengths must be strictly increasing")
    if vals.min() < 0:
        raise ValueError(f"{label}: a spectral sensitivity or power is >= 0, got {vals.min()}")
    object.__setattr__(obj, name, (tuple(wl.tolist()), tuple(map(tuple, vals.tolist()))))


def _system_gain(conversion_gain_uv_per_e, voltage_swing, bit_depth):
    return conversion_gain_uv_per_e * 1e-6 * ((1 << bit_depth) - 1) / voltage_swing


# --------------------------------------------------------------------------
# colour sensor
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class ColourSensor:
    """Parameters of the colour pixels (paper §5.1.1), ISETCam-style.

    Defaults follow ISETCam's default 2.8 um APS pixel (``pixelCreate``):
    conversion gain 100 uV/e-, voltage swing 1 V (so a 10 000 e- well),
    dark voltage 1 mV/s (10 e-/s) and read noise 1 mV (10 e-). The ADC is
    the paper's 11 bits. Full details and sources: ``docs/sensor.md``.

    Parameters
    ----------
    pixel_pitch_um : float
        Pixel pitch in um (2.8). The pixel area collects the light.
    full_well : float
        Full-well capacity in electrons (10 000); ``inf`` disables well
        saturation (the ADC still clips).
    conversion_gain_uv_per_e : float
        Sense-node conversion gain in uV per electron (100).
    voltage_swing : float
        ADC input range in volts (1.0): ``voltage_swing`` maps to
        ``2**bit_depth - 1`` DN. System gain ``K = CG * (2**b - 1) / swing``
        DN/e- (0.2047 with the defaults).
    bit_depth : int
        ADC bits (11, the paper).
    black_level : float
        Offset added before the ADC, in DN (64, as ISETCam's IMX490 presets
        and most phone raws).
    qe : tuple of 3 floats
        Effective quantum efficiency of the R, G, B pixels (fill factor,
        microlens, colour filter and silicon together) for RGB scenes
        (0.40, 0.50, 0.35): typical values for a 2-3 um CMOS pixel, not from
        a datasheet. For spectral scenes they scale the spectral
        sensitivities (each normalised to a peak of 1).
    photon_flux : float
        Photons per um^2 per second reaching a pixel, through its colour
        filter's passband, from a scene point of linear value 1.0
        (2.0e5, about 50 lx at the focal plane: a 500 cd/m^2 scene seen
        at f/2.8). For spectral scenes: the flux of a perfect white
        reflector in the green passband. With auto-exposure it only sets the
        exposure time, hence the dark signal.
    sensitivities : str or (wavelengths, values (N, 3))
        Camera spectral sensitivities for spectral scenes: a key of
        ``colour.MSDS_CAMERA_SENSITIVITIES`` (default ``"Nikon 5100 (NPL)"``,
        measured by NPL) or arrays, wavelengths in nm.
    illuminant : str or (wavelengths, values (N,))
        Illuminant of a spectral (reflectance) scene: a key of
        ``colour.SDS_ILLUMINANTS`` (default ``"D65"``) or arrays. Use ``"E"``
        for a cube that already holds radiance.
    exposure : float or "auto"
        Exposure time in seconds, or "auto": the ``ae_percentile``
        percentile of the noise-free signal reaches ``ae_target`` of the
        usable range (``min(full_well, (white - black) / K)`` electrons).
    ae_target : float
        Fraction of the usable range for auto-exposure (0.8).
    ae_percentile : float
        Percentile of the CFA signal that auto-exposure places at the
        target (99: highlights above it may clip).
    shot_noise : bool
        Photon and dark-current shot noise (Poisson).
    dark_current : float
        Dark current in e-/s (10; 0 disables it).
    read_noise : float
        Read noise in e- rms (10; 0 disables it).
    dsnu : float
        Dark-signal non-uniformity, a fixed offset per pixel, e- rms (5,
        about 1 LSB at 11 bits, the "less than 1 LSB" of ISETCam's vendor
        sensor models; 0 disables it).
    prnu : float
        Photo-response non-uniformity, a fixed gain per pixel, as a fraction
        (0.01 = 1 %; 0 disables it).
    quantise : bool
        Round to integer DN (uint16 output); False keeps float DN.
    fpn_seed : int
        Seed of the fixed-pattern maps (the identity of the sensor).

    Examples
    --------
    >>> s = ColourSensor()
    >>> round(s.system_gain, 4), s.white_level
    (0.2047, 2047)
    """

    pixel_pitch_um: float = 2.8
    full_well: float = 10_000.0
    conversion_gain_uv_per_e: float = 100.0
    voltage_swing: float = 1.0
    bit_depth: int = 11
    black_level: float = 64.0
    qe: tuple = (0.40, 0.50, 0.35)
    photon_flux: float = 2.0e5
    sensitivities: object = "Nikon 5100 (NPL)"
    illuminant: object = "D65"
    exposure: object = "auto"
    ae_target: float = 0.8
    ae_percentile: float = 99.0
    shot_noise: bool = True
    dark_current: float = 10.0
    read_noise: float = 10.0
    dsnu: float = 5.0
    prnu: float = 0.01
    quantise: bool = True
    fpn_seed: int = 0

    def __post_init__(self):
        _num(self, "pixel_pitch_um", lo=0.1, hi=100)
        _check_readout(self)
        try:
            qe = tuple(float(q) for q in self.qe)
        except (TypeError, ValueError):
            raise TypeError(f"ColourSensor.qe: expected 3 numbers (R, G, B), got {self.qe!r}") \
                from None
        if len(qe) != 3 or not all(0 < q <= 1 for q in qe):
            raise ValueError(f"ColourSensor.qe: expected 3 quantum efficiencies in (0, 1], "
                             f"got {self.qe!r}")
        object.__setattr__(self, "qe", qe)
        _num(self, "photon_flux", lo=0, lo_open=True)
        _spectrum_param(self, "sensitivities", 3)
        _spectrum_param(self, "illuminant", 1)
        if isinstance(self.exposure, str):
            if self.exposure != "auto":
                raise ValueError(f"ColourSensor.exposure: expected seconds > 0 or 'auto', got "
                                 f"{self.exposure!r}")
        else:
            _num(self, "exposure", lo=0, hi=3600, lo_open=True)
        _num(self, "ae_target", lo=0, hi=1, lo_open=True)
        _num(self, "ae_percentile", lo=0, hi=100, lo_open=True)
        _check_pixel_noise(self)

    @property
    def system_gain(self):
        """float: DN per electron, ``CG * (2**bit_depth - 1) / voltage_swing``."""
        return _system_gain(self.conversion_gain_uv_per_e, self.voltage_swing, self.bit_depth)

    @property
    def white_level(self):
        return (1 << self.bit_depth) - 1

    @property
    def pixel_area_um2(self):
        return self.pixel_pitch_um ** 2

    def electrons_per_unit(self, exposure):
        """ndarray (3,): signal electrons per unit linear scene value, for R, G, B.

        ``photon_flux * pixel_area * qe[c] * exposure``: the scale that maps
        a scene to mean electrons (before PRNU, dark current and clipping).
        """
        t = float(exposure)
        if not (math.isfinite(t) and t > 0):
            raise ValueError(f"exposure: expected seconds > 0, got {exposure!r}")
        return self.photon_flux * self.pixel_area_um2 * np.asarray(self.qe) * t

    def usable_electrons(self):
        """float: electrons at which the pixel stops responding (well or ADC, whichever first)."""
        return min(self.full_well, (self.white_level - self.black_level) / self.system_gain)


def _resolve_spectrum(value, kind):
    """(wavelengths, values) arrays from a colour-science name or explicit arrays."""
    if not isinstance(value, str):
        wl, vals = value
        return np.asarray(wl, np.float64), np.asarray(vals, np.float64)
    with warnings.catch_warnings():
        # colour-science may warn about optional dependencies when loaded
        warnings.filterwarnings("ignore", module=r"colour(\.|$)")
        import colour

        table = (colour.MSDS_CAMERA_SENSITIVITIES if kind == "sensitivities"
                 else colour.SDS_ILLUMINANTS)
        if value not in table:
            table_name = ("MSDS_CAMERA_SENSITIVITIES" if kind == "sensitivities"
                          else "SDS_ILLUMINANTS")
            raise ValueError(f"ColourSensor.{kind}: {value!r} is not in colour-science's "
                             f"{table_name} (known: {', '.join(sorted(table))[:300]})")
        sd = table[value]
        wl = np.asarray(sd.wavelengths, np.float64)
        vals = np.asarray(sd.values, np.float64)
    if vals.ndim == 1:
        vals = vals[:, None]
    return wl, vals


def _band_widths(wl):
    """Trapezoid weights of a wavelength sampling (nm)."""
    if wl.size == 1:
        return np.ones(1)
    d = np.diff(wl)
    w = np.empty_like(wl)
    w[0] = d[0] / 2
    w[-1] = d[-1] / 2
    w[1:-1] = (d[:-1] + d[1:]) / 2
    return w


def _spectral_weights(sensor, wavelengths):
    """Weights (K, 3): relative channel response per band of a reflectance cube.

    ``w_c(l) = S_c(l) E(l) dl / sum_l S_G(l) E(l) dl`` with ``S_c`` the
    sensitivities (per unit energy, each normalised to a peak of 1) and ``E``
    the illuminant, both interpolated linearly onto the scene's bands (0
    outside their range). A perfect white reflector gives 1 in green and the
    camera's white-balance ratios in red and blue.
    """
    swl, svals = _resolve_spectrum(sensor.sensitivities, "sensitivities")
    iwl, ivals = _resolve_spectrum(sensor.illuminant, "illuminant")
    svals = svals / np.maximum(svals.max(axis=0, keepdims=True), 1e-300)
    s = np.stack([np.interp(wavelengths, swl, svals[:, c], left=0.0, right=0.0)
                  for c in range(3)], axis=1)
    e = np.interp(wavelengths, iwl, ivals[:, 0], left=0.0, right=0.0)
    w = s * (e * _band_widths(wavelengths))[:, None]
    green_white = w[:, 1].sum()
    if not green_white > 0:
        raise ValueError("ColourSensor.sensitivities: the green sensitivity times the "
                         "illuminant is zero over the scene's wavelengths "
                         f"({wavelengths[0]:g}-{wavelengths[-1]:g} nm)")
    return w / green_white


def _spectral_integrate(cube, weights, colour_map):
    """Relative channel value at every CFA site: ``cube[r, c, :] @ weights[:, colour]``.

    Integrates only the channel each site needs (one dot product per site).
    """
    out = np.empty(colour_map.shape, np.float64)
    for c in range(3):
        m = colour_map == c
        if m.any():
            out[m] = cube[m].astype(np.float64, copy=False) @ weights[:, c]
    return out


def _colour_signal_rate(scene, sensor, colour_map):
    """Mean signal electrons per second at every CFA site (noise-free, no PRNU)."""
    per_unit = sensor.electrons_per_unit(1.0)
    if scene.is_spectral:
        weights = _spectral_weights(sensor, scene.wavelengths)
        value = _spectral_integrate(scene.image, weights, colour_map)
    else:
        value = np.take_along_axis(scene.image, colour_map[..., None].astype(np.intp),
                                   axis=2)[..., 0].astype(np.float64)
    return value * per_unit[colour_map]


def _auto_exposure(rate, sensor):
    level = float(np.percentile(rate, sensor.ae_percentile))
    if not level > 0:
        raise ValueError(f"scene: the {sensor.ae_percentile:g}th percentile of the signal is 0 "
                         "(a black scene); auto-exposure needs light -- set "
                         "ColourSensor(exposure=...) instead")
    return sensor.ae_target * sensor.usable_electrons() / level


def _fpn_maps(seed, stream, shape, dsnu, prnu):
    """Fixed-pattern maps (PRNU gain, DSNU offset), None when off.

    Both standard-normal maps are always drawn, in a fixed order, so that
    turning one term off leaves the other's pattern unchanged.
    """
    if dsnu == 0 and prnu == 0:
        return None, None
    rng = np.random.default_rng([seed, stream])
    n = rng.standard_normal((2,) + tuple(shape))
    gain = 1.0 + prnu * n[0] if prnu else None
    offset = dsnu * n[1] if dsnu else None
    return gain, offset


def _expose(mean_e, dark_e, sensor, *, noise, seed, temporal_stream, fpn_stream,
            fpn_shape=None):
    """Mean electrons -> DN through the noise chain of the module docstring.

    ``mean_e`` is the mean signal (before PRNU), ``dark_e`` the mean dark
    signal. The fixed-pattern maps have shape ``fpn_shape`` (default
    ``mean_e.shape``) and broadcast against ``mean_e`` from the right: the
    ToF draws one map per physical tap, (4, n), shared by every frequency.
    Returns the DN array and a bool array of the samples at full well or
    full scale.
    """
    gain = offset = None
    if noise:
        gain, offset = _fpn_maps(sensor.fpn_seed, fpn_stream,
                                 mean_e.shape if fpn_shape is None else fpn_shape,
                                 sensor.dsnu, sensor.prnu)
    e = mean_e if gain is None else np.maximum(mean_e * gain, 0.0)
    e = e + dark_e
    rng = None
    if noise and (sensor.shot_noise or sensor.read_noise > 0):
        rng = np.random.default_rng([seed, temporal_stream])
    if rng is not None and sensor.shot_noise:
        e = rng.poisson(e).astype(np.float64)
    if offset is not None:
        e = e + offset
    well_full = e >= sensor.full_well
    e = np.minimum(e, sensor.full_well)
    if rng is not None and sensor.read_noise > 0:
        e = e + sensor.read_noise * rng.standard_normal(e.shape)
    dn = sensor.black_level + sensor.system_gain * e
    if sensor.quantise:
        dn = np.floor(dn + 0.5)
    top = sensor.white_level
    saturated = well_full | (dn >= top)
    dn = np.clip(dn, 0, top)
    return (dn.astype(np.uint16) if sensor.quantise else dn), saturated


def _as_scene(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, (str, Path)):
        return load_scene(scene)
    if isinstance(scene, np.ndarray):
        return Scene(scene)
    raise TypeError(f"scene: expected a Scene, an image array or a path, got "
                    f"{type(scene).__name__}")


def simulate_colour(scene, pattern="bayer", sensor=None, *, seed=0, noise=True):
    """Simulate the colour pixels: the plain Bayer CFA of a scene (paper §5.1.1).

    Parameters
    ----------
    scene : Scene, ndarray or path
        The scene (an array becomes ``Scene(array)``, a path goes through
        :func:`~rgbz_fast.scene.load_scene`).
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

    Returns
    -------
    RawFrame
        On the plain Bayer pattern, ``bit_depth = sensor.bit_depth``, uint16
        (float64 if ``sensor.quantise`` is False); ``meta`` holds
        ``exposure`` (s), ``system_gain`` (DN/e-), ``saturated`` (fraction of
        sites at full well or full scale) and ``spectral``.
    """
    scene = _as_scene(scene)
    pattern = get_pattern(pattern)
    sensor = ColourSensor() if sensor is None else sensor
    if not isinstance(sensor, ColourSensor):
        raise TypeError(f"colour_sensor: expected a ColourSensor, got {type(sensor).__name__}")
    seed = _seed(seed, "seed")
    shape = pattern.check_shape(scene.shape, "scene")
    colour_map = pattern.bayer_map(shape)
    rate = _colour_signal_rate(scene, sensor, colour_map)
    exposure = _auto_exposure(rate, sensor) if sensor.exposure == "auto" else sensor.exposure
    dn, saturated = _expose(rate * exposure, sensor.dark_current * exposure, sensor,
                            noise=bool(noise), seed=seed,
                            temporal_stream=_STREAM_COLOUR_TEMPORAL,
                            fpn_stream=_STREAM_COLOUR_FPN)
    meta = {"exposure": float(exposure), "system_gain": sensor.system_gain,
            "saturated": float(saturated.mean()), "spectral": scene.is_spectral,
            "noise": bool(noise), "seed": seed, "scene": scene.name}
    return RawFrame(dn, pattern.bayer_pattern(), sensor.bit_depth, meta=meta)


# --------------------------------------------------------------------------
# ToF sensor
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class ToFSensor:
    """Parameters of the i-ToF depth pixels and their light source (paper §5.1.2).

    Radiometry: the source spreads ``optical_power_w`` uniformly over the
    camera's field of view ``fov_deg``, so the irradiance at distance ``d`` is
    ``P / (4 d^2 tan(h/2) tan(v/2))`` (the 1/d^2 fall-off); a Lambertian
    surface of NIR reflectance ``rho`` sends ``rho * E * T / (4 N^2)`` to
    the focal plane (lens f-number ``N``, transmission ``T``); the ambient
    in-band irradiance adds ``rho * E_amb * T / (4 N^2)``. Photons are
    converted at ``hc / wavelength`` and the effective ``qe``.

    Parameters
    ----------
    frequencies : tuple of float
        Modulation frequencies in Hz (80, 100, 120 MHz: unambiguous to
        7.495 m together, see :attr:`unambiguous_range`). One acquisition of
        ``integration_time`` per frequency.
    integration_time : float
        Seconds per frequency (1e-3).
    wavelength_nm : float
        Laser wavelength (940 nm: a common VCSEL band, where sunlight is
        weakened by water absorption).
    optical_power_w : float
        Mean emitted optical power in W (0.5).
    modulation_contrast : float
        Demodulation contrast in (0, 1] (0.8): tap amplitude over the
        active-light part of the offset.
    fov_deg : (float, float)
        Horizontal and vertical field of view lit by the source, degrees
        (60, 45).
    f_number : float
        Lens f-number (1.2).
    optics_transmission : float
        Lens and NIR band-pass transmission (0.9).
    qe : float
        Effective quantum efficiency at the laser wavelength, fill factor
        included (0.3).
    ambient_irradiance : float
        Ambient irradiance on the scene within the band-pass, W/m^2 (0.1,
        indoor; direct sunlight in a 940 +- 25 nm band is about 15).
    pixel_pitch_um : float, optional
        The colour-pixel pitch (a Z cell). None: the colour sensor's in
        :func:`simulate` (2.8 um in :func:`simulate_tof` alone).
    z_block : {None, 1, 2}
        Z pixel size in colour pixels. None: 2 when the pattern's Z sites
        form aligned 2x2 squares (Mask2, rows), else 1.
    full_well, conversion_gain_uv_per_e, voltage_swing, bit_depth, black_level
        The readout of each tap, as for :class:`ColourSensor` (10 000 e-,
        100 uV/e-, 1 V, 11 bits, 64 DN: the same column readout as the
        colour pixels).
    shot_noise, dark_current, read_noise, dsnu, prnu, quantise, fpn_seed
        Noise terms per tap, as for :class:`ColourSensor` (dark current
        10 e-/s, read noise 10 e-, DSNU 5 e-, PRNU 1 %); DSNU and PRNU are
        drawn per tap and Z site (tap mismatch included).
    """

    frequencies: tuple = (80e6, 100e6, 120e6)
    integration_time: float = 1e-3
    wavelength_nm: float = 940.0
    optical_power_w: float = 0.5
    modulation_contrast: float = 0.8
    fov_deg: tuple = (60.0, 45.0)
    f_number: float = 1.2
    optics_transmission: float = 0.9
    qe: float = 0.3
    ambient_irradiance: float = 0.1
    pixel_pitch_um: float | None = None
    z_block: int | None = None
    full_well: float = 10_000.0
    conversion_gain_uv_per_e: float = 100.0
    voltage_swing: float = 1.0
    bit_depth: int = 11
    black_level: float = 64.0
    shot_noise: bool = True
    dark_current: float = 10.0
    read_noise: float = 10.0
    dsnu: float = 5.0
    prnu: float = 0.01
    quantise: bool = True
    fpn_seed: int = 0

    def __post_init__(self):
        try:
            freqs = tuple(float(f) for f in np.atleast_1d(self.frequencies))
        except (TypeError, ValueError):
            raise TypeError(f"ToFSensor.frequencies: expected numbers in Hz, got "
                            f"{self.frequencies!r}") from None
        if not freqs or not all(math.isfinite(f) and 1e5 <= f <= 1e9 for f in freqs):
            raise ValueError(f"ToFSensor.frequencies: expected 1 or more frequencies in "
                             f"[100 kHz, 1 GHz], got {self.frequencies!r}")
        if len(set(round(f) for f in freqs)) != len(freqs):
            raise ValueError(f"ToFSensor.frequencies: repeated frequency in {freqs}")
        object.__setattr__(self, "frequencies", freqs)
        _num(self, "integration_time", lo=0, hi=10, lo_open=True)
        _num(self, "wavelength_nm", lo=700, hi=1700)
        _num(self, "optical_power_w", lo=0, hi=1e3, lo_open=True)
        _num(self, "modulation_contrast", lo=0, hi=1, lo_open=True)
        try:
            fov = tuple(float(v) for v in self.fov_deg)
        except (TypeError, ValueError):
            raise TypeError(f"ToFSensor.fov_deg: expected (horizontal, vertical) degrees, got "
                            f"{self.fov_deg!r}") from None
        if len(fov) != 2 or not all(0 < v < 180 for v in fov):
            raise ValueError(f"ToFSensor.fov_deg: expected two angles in (0, 180) degrees, got "
                             f"{self.fov_deg!r}")
        object.__setattr__(self, "fov_deg", fov)
        _num(self, "f_number", lo=0.5, hi=64)
        _num(self, "optics_transmission", lo=0, hi=1, lo_open=True)
        _num(self, "qe", lo=0, hi=1, lo_open=True)
        _num(self, "ambient_irradiance", lo=0, hi=1e4)
        if self.pixel_pitch_um is not None:
            _num(self, "pixel_pitch_um", lo=0.1, hi=100)
        if self.z_block is not None and (isinstance(self.z_block, bool)
                                         or self.z_block not in (1, 2)):
            raise ValueError(f"ToFSensor.z_block: expected None, 1 or 2, got {self.z_block!r}")
        _check_readout(self)
        _check_pixel_noise(self)

    @property
    def system_gain(self):
        """float: DN per electron of a tap."""
        return _system_gain(self.conversion_gain_uv_per_e, self.voltage_swing, self.bit_depth)

    @property
    def white_level(self):
        return (1 << self.bit_depth) - 1

    @property
    def wrap_ranges(self):
        """tuple of float: ``c / (2 f)`` in metres, where each frequency's phase wraps."""
        return tuple(SPEED_OF_LIGHT / (2 * f) for f in self.frequencies)

    @property
    def unambiguous_range(self):
        """float: ``c / (2 gcd(f))`` in metres (frequencies rounded to whole Hz)."""
        g = 0
        for f in self.frequencies:
            g = math.gcd(g, int(round(f)))
        return SPEED_OF_LIGHT / (2 * g)

    def tap_electrons(self, distance, ir_reflectance, *, pixel_pitch_um=2.8):
        """Mean electrons per tap of one-cell Z pixels (noise-free, no FPN).

        Parameters
        ----------
        distance, ir_reflectance : array_like, same shape (...)
            Metres (> 0) and NIR reflectance of the surface seen.
        pixel_pitch_um : float
            Cell pitch (the colour-pixel pitch).

        Returns
        -------
        ndarray, shape (F, 4, ...)
            ``O + a cos(phi + k pi/2)`` of the module docstring, dark
            current included.
        """
        d = np.asarray(distance, np.float64)
        rho = np.broadcast_to(np.asarray(ir_reflectance, np.float64), d.shape)
        s, b = self._cell_electrons(d, rho, float(pixel_pitch_um))
        phasor = s[None] * np.exp(1j * self._phase(d))
        return self._taps_from(phasor, s + b) + self.dark_current * self.integration_time

    # -- internals ------------------------------------------------------------
    def _cell_electrons(self, d, rho, pitch_um):
        """Active (S) and ambient (B) electrons collected by one cell over one integration."""
        area = (pitch_um * 1e-6) ** 2
        photon_energy = _PLANCK * SPEED_OF_LIGHT / (self.wavelength_nm * 1e-9)
        th = math.tan(math.radians(self.fov_deg[0]) / 2)
        tv = math.tan(math.radians(self.fov_deg[1]) / 2)
        k = (self.optics_transmission * area / (4 * self.f_number ** 2) / photon_energy
             * self.qe * self.integration_time)
        irradiance = self.optical_power_w / (4 * d * d * th * tv)
        return rho * irradiance * k, rho * self.ambient_irradiance * k

    def _phase(self, d):
        f = np.asarray(self.frequencies).reshape((-1,) + (1,) * d.ndim)
        return np.mod(4 * np.pi * f * d[None] / SPEED_OF_LIGHT, 2 * np.pi)

    def _taps_from(self, phasor, total):
        """Tap photo-electrons (F, 4, ...) from the summed active phasor (F, ...) and S+B (...).

        ``(S + B)/4 + C/4 * Re(P * e^{i k pi/2})`` with ``P = sum_cells S e^{i phi}``
        -- for one cell ``S/4 (1 + C cos(phi + k pi/2)) + B/4``. No dark signal.
        """
        shifts = np.exp(1j * np.pi / 2 * np.arange(4))            # e^{i k pi/2}
        ac = (phasor[:, None] * shifts.reshape((1, 4) + (1,) * (phasor.ndim - 1))).real
        return 0.25 * total[None, None] + 0.25 * self.modulation_contrast * ac


@dataclass(frozen=True, eq=False)
class ToFTaps:
    """The four taps of every Z measurement at every frequency, as the chip reads them.

    Attributes
    ----------
    taps : ndarray, shape (F, 4, n_sites)
        Digital numbers (uint16; float64 when the sensor does not quantise):
        ``taps[i, k, n]`` is tap k (at ``-k * 90`` degrees, see the module
        docstring for the convention) of measurement n at frequency i.
    frequencies : ndarray, shape (F,)
        Modulation frequencies in Hz.
    sites : (rows, cols) tuple of int64 arrays, shape (n_sites,)
        Top-left pixel of each Z measurement in the frame, row-major order.
    block : int
        Z pixel size in colour pixels (1: Mask1; 2: Mask2, one measurement
        per 2x2 Z pixel).
    bit_depth : int
        ADC bits of the taps.
    depth_true : ndarray of float64, shape (n_sites,)
        Ground-truth distance in metres (mean over the block's cells).
    valid : ndarray of bool, shape (n_sites,)
        False where the scene's depth is unknown (e.g. invalid disparity) or
        beyond :attr:`unambiguous_range`.
    saturated : ndarray of bool, shape (n_sites,)
        True where a tap at some frequency reached full well or full scale.
    sensor : ToFSensor
        The parameters used (with ``pixel_pitch_um`` resolved).
    shape : tuple (rows, cols)
        Frame shape.
    meta : dict
    """

    taps: np.ndarray
    frequencies: np.ndarray
    sites: tuple
    block: int
    bit_depth: int
    depth_true: np.ndarray
    valid: np.ndarray
    saturated: np.ndarray
    sensor: ToFSensor
    shape: tuple
    meta: dict = field(default_factory=dict)

    def __post_init__(self):
        taps = np.asarray(self.taps)
        if taps.ndim != 3 or taps.shape[1] != 4:
            raise ValueError(f"taps: expected shape (F, 4, n_sites), got {taps.shape}")
        F, _, n = taps.shape
        freqs = np.asarray(self.frequencies, np.float64)
        if freqs.shape != (F,):
            raise ValueError(f"frequencies: expected {F} values, got shape {freqs.shape}")
        rows, cols = (np.asarray(a, np.int64) for a in self.sites)
        for name, a in (("sites", rows), ("sites", cols), ("depth_true", self.depth_true),
                        ("valid", self.valid), ("saturated", self.saturated)):
            if np.shape(a) != (n,):
                raise ValueError(f"{name}: expected shape ({n},), got {np.shape(a)}")
        if self.block not in (1, 2):
            raise ValueError(f"block: expected 1 or 2, got {self.block!r}")
        for a in (taps, freqs, rows, cols):
            a.setflags(write=False)
        object.__setattr__(self, "taps", taps)
        object.__setattr__(self, "frequencies", freqs)
        object.__setattr__(self, "sites", (rows, cols))
        object.__setattr__(self, "shape", tuple(int(s) for s in self.shape))

    @property
    def n_sites(self):
        return int(self.taps.shape[2])

    @property
    def black_level(self):
        return self.sensor.black_level

    @property
    def white_level(self):
        return (1 << self.bit_depth) - 1

    @property
    def unambiguous_range(self):
        return self.sensor.unambiguous_range

    def to_frame(self, values, fill=0.0):
        """Paint one value per measurement onto the frame (every cell of its block).

        Parameters
        ----------
        values : array_like, shape (n_sites,)
        fill : scalar
            Value of the pixels that are no Z measurement.

        Returns
        -------
        ndarray, shape ``self.shape``
        """
        v = np.asarray(values)
        if v.shape != (self.n_sites,):
            raise ValueError(f"values: expected shape ({self.n_sites},), got {v.shape}")
        out = np.full(self.shape, fill, dtype=np.result_type(v.dtype, np.min_scalar_type(fill)))
        r, c = self.sites
        for dr in range(self.block):
            for dc in range(self.block):
                out[r + dr, c + dc] = v
        return out

    def __repr__(self):
        mhz = ", ".join(f"{f / 1e6:g}" for f in self.frequencies)
        return (f"ToFTaps({self.n_sites} sites, block {self.block}, {mhz} MHz, "
                f"{self.bit_depth}-bit, {int(self.valid.sum())} valid)")


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


def _z_sites(pattern, shape, block):
    zmask = pattern.z_mask(shape)
    if block == 1:
        r, c = np.nonzero(zmask)
        return r, c
    if _z_block(pattern) != 2:
        raise ValueError(f"ToFSensor.z_block: 2 needs Z sites in aligned 2x2 squares; pattern "
                         f"{pattern.name!r} has none")
    H, W = shape
    top = zmask[0:H - 1:2, 0:W - 1:2]       # blocks cut by the frame edge are dropped
    r, c = np.nonzero(top)
    return r * 2, c * 2


def simulate_tof(scene, pattern, sensor=None, *, seed=0, noise=True, pixel_pitch_um=None,
                 _stacklevel=2):
    """Simulate the i-ToF taps at the Z sites of a pattern (paper §5.1.2).

    Parameters
    ----------
    scene : Scene
        Must hold a depth map. The NIR reflectance is the scene's or the
        estimate of :func:`~rgbz_fast.scene.estimate_ir_reflectance`,
        evaluated at the Z sites only.
    pattern : Pattern or str
        Must hold Z sites.
    sensor : ToFSensor, optional
        Default ``ToFSensor()``.
    seed : int
        Seed of the temporal noise.
    noise : bool
        False: noise-free taps, no random number drawn.
    pixel_pitch_um : float, optional
        Cell pitch when ``sensor.pixel_pitch_um`` is None (default 2.8).

    Returns
    -------
    ToFTaps

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
        raise TypeError(f"tof_sensor: expected a ToFSensor, got {type(sensor).__name__}")
    seed = _seed(seed, "seed")
    if not scene.has_depth:
        raise ValueError("scene: has no depth map, so there is nothing for the ToF pixels "
                         "to measure")
    if not pattern.has_z:
        raise ValueError(f"pattern: {pattern.name!r} has no Z site")
    shape = pattern.check_shape(scene.shape, "scene")
    pitch = sensor.pixel_pitch_um
    if pitch is None:
        pitch = 2.8 if pixel_pitch_um is None else float(pixel_pitch_um)
        sensor = replace(sensor, pixel_pitch_um=pitch)
    block = sensor.z_block if sensor.z_block is not None else _z_block(pattern)
    rows, cols = _z_sites(pattern, shape, block)
    if rows.size == 0:
        raise ValueError(f"scene: a {shape[0]}x{shape[1]} frame holds no complete "
                         f"{block}x{block} Z pixel of pattern {pattern.name!r}")
    # cells of every measurement: (n_sites, block*block)
    offs = [(dr, dc) for dr in range(block) for dc in range(block)]
    cr = np.stack([rows + dr for dr, _ in offs], axis=1)
    cc = np.stack([cols + dc for _, dc in offs], axis=1)
    d = scene.depth[cr, cc]
    cell_valid = scene.depth_valid[cr, cc]
    if scene.ir_reflectance is not None:
        rho = scene.ir_reflectance[cr, cc]
    else:
        rho = estimate_ir_reflectance(scene.image[cr, cc], scene.wavelengths)
    # a depth of 0 is only allowed where unknown: no surface, no laser return there
    surface = d > 0
    d_safe = np.where(surface, d, 1.0)
    s, b = sensor._cell_electrons(d_safe, rho, pitch)
    s = np.where(surface, s, 0.0)
    phasor = (s[None] * np.exp(1j * sensor._phase(d_safe))).sum(axis=-1)   # (F, n)
    mean = sensor._taps_from(phasor, (s + b).sum(axis=-1))                  # (F, 4, n)

    depth_true = d.mean(axis=1)
    valid = cell_valid.all(axis=1)
    beyond = np.any(cell_valid & (d >= sensor.unambiguous_range), axis=1)
    if beyond.any():
        warnings.warn(
            f"{int(beyond.sum())} of {rows.size} Z sites see depths up to "
            f"{d[cell_valid].max():.3g} m, "
            f"beyond the {sensor.unambiguous_range:.4g} m unambiguous range of "
            f"{', '.join(f'{f / 1e6:g}' for f in sensor.frequencies)} MHz; they are marked "
            "invalid (ToFTaps.valid)", UnambiguousRangeWarning, stacklevel=_stacklevel)
        valid = valid & ~beyond

    taps, sat = _expose(mean, sensor.dark_current * sensor.integration_time, sensor,
                        noise=bool(noise), seed=seed, temporal_stream=_STREAM_TOF_TEMPORAL,
                        fpn_stream=_STREAM_TOF_FPN, fpn_shape=mean.shape[1:])
    meta = {"noise": bool(noise), "seed": seed, "pattern": pattern.name,
            "integration_time": sensor.integration_time,
            "system_gain": sensor.system_gain,
            "wrap_ranges": sensor.wrap_ranges}
    return ToFTaps(taps, np.asarray(sensor.frequencies), (rows, cols), block,
                   sensor.bit_depth, depth_true, valid, sat.any(axis=(0, 1)), sensor, shape,
                   meta)


# --------------------------------------------------------------------------
# RGB-Z build
# --------------------------------------------------------------------------
def simulate(scene, pattern, colour_sensor=None, tof_sensor=None, *, seed=0, noise=True):
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

    Returns
    -------
    RawFrame
        ``data``: colour CFA at colour sites, 0 at Z sites; ``reference``:
        the plain Bayer CFA; ``tof``: :class:`ToFTaps` or None; ``meta``:
        ``exposure`` (s), ``system_gain``, ``saturated``, ``spectral``,
        ``noise``, ``seed``, ``scene``, ``colour_sensor``, ``tof_sensor``
        and ``tof`` (a sentence saying whether and why the ToF model ran).

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.scene import Scene
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

    ref = simulate_colour(scene, pattern, colour_sensor, seed=seed, noise=noise)
    zmask = pattern.z_mask(scene.shape)
    data = ref.data.copy()
    data[zmask] = 0

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
        tof = simulate_tof(scene, pattern, used, seed=seed, noise=noise, _stacklevel=3)
        status = (f"simulated: {len(used.frequencies)} frequencies, {tof.n_sites} Z "
                  f"measurements of {tof.block}x{tof.block} pixels")
    meta = dict(ref.meta)
    meta.update(colour_sensor=colour_sensor, tof_sensor=used, tof=status,
                pattern=pattern.name)
    return RawFrame(data, pattern, colour_sensor.bit_depth, reference=ref.data, tof=tof,
                    meta=meta)
