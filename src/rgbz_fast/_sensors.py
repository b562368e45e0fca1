"""Descriptions of the RGB-Z chip's pixels: the colour pixels and the i-ToF depth pixels.

:class:`ColourSensor` and :class:`ToFSensor` are frozen sets of parameters
(optics, pixel, readout, noise) with the quantities derived from them (system
gain, white level, wrap ranges, unambiguous range). They describe a chip, so
both the sensor models (:mod:`rgbz_fast.simulation`) and the ISPs, which are
calibrated for their sensor (:mod:`rgbz_fast.tof` reads the noise terms of a
:class:`ToFSensor`), use them; the conventions and sources are in the
:mod:`rgbz_fast.simulation` docstring and docs/guide/sensor.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._sensor_checks import (check_pixel_noise, check_readout, check_spectrum,
                             check_tof_contrast, check_tof_nonideal, store_number)
from ._validate import check_image, check_number

__all__ = ["ColourSensor", "ToFSensor", "SPEED_OF_LIGHT", "DEFAULT_CELL_PITCH_UM"]

#: Speed of light in vacuum, m/s.
SPEED_OF_LIGHT = 299_792_458.0
_PLANCK = 6.62607015e-34
#: Pitch (um) of one Z cell when neither the :class:`ToFSensor` nor the caller gives one: the
#: default colour pixel's (:attr:`ColourSensor.pixel_pitch_um`), whose cells the Z pixels share.
DEFAULT_CELL_PITCH_UM = 2.8


class _Readout:
    """What both sensors derive from their readout fields (conversion gain, swing, bits)."""

    @property
    def system_gain(self):
        """float: DN per electron, ``CG * (2**bit_depth - 1) / voltage_swing``."""
        return self.conversion_gain_uv_per_e * 1e-6 * self.white_level / self.voltage_swing

    @property
    def white_level(self):
        """int: the largest digital number, ``2**bit_depth - 1``."""
        return (1 << self.bit_depth) - 1


# --------------------------------------------------------------------------
# colour sensor
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class ColourSensor(_Readout):
    """Parameters of the colour pixels (paper §5.1.1), ISETCam-style.

    Defaults follow ISETCam's default 2.8 um APS pixel (``pixelCreate``):
    conversion gain 100 uV/e-, voltage swing 1 V (so a 10 000 e- well),
    dark voltage 1 mV/s (10 e-/s) and read noise 1 mV (10 e-). The ADC is
    the paper's 11 bits. Full details and sources: ``docs/guide/sensor.md``.

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
        store_number(self, "pixel_pitch_um", lo=0.1, hi=100)
        check_readout(self)
        try:
            if isinstance(self.qe, (str, bytes)):
                raise TypeError          # '111' was read digit by digit
            given = tuple(self.qe)       # once: an iterator is read once
            if any(isinstance(q, (str, bytes, bool, np.bool_)) for q in given):
                raise TypeError          # True had been read as 1.0
            qe = tuple(float(q) for q in given)
        except (TypeError, ValueError):
            raise TypeError(f"ColourSensor.qe: expected 3 numbers (R, G, B), got {self.qe!r}") \
                from None
        if len(qe) != 3 or not all(0 < q <= 1 for q in qe):
            raise ValueError(f"ColourSensor.qe: expected 3 quantum efficiencies in (0, 1], "
                             f"got {self.qe!r}")
        object.__setattr__(self, "qe", qe)
        store_number(self, "photon_flux", lo=0, lo_open=True)
        check_spectrum(self, "sensitivities", 3)
        check_spectrum(self, "illuminant", 1)
        if isinstance(self.exposure, str):
            if self.exposure != "auto":
                raise ValueError(f"ColourSensor.exposure: expected seconds > 0 or 'auto', got "
                                 f"{self.exposure!r}")
        else:
            store_number(self, "exposure", lo=0, hi=3600, lo_open=True)
        store_number(self, "ae_target", lo=0, hi=1, lo_open=True)
        store_number(self, "ae_percentile", lo=0, hi=100, lo_open=True)
        check_pixel_noise(self)

    @property
    def pixel_area_um2(self):
        return self.pixel_pitch_um ** 2

    def electrons_per_unit(self, exposure):
        """ndarray (3,): signal electrons per unit linear scene value, for R, G, B.

        ``photon_flux * pixel_area * qe[c] * exposure``: the scale that maps
        a scene to mean electrons (before PRNU, dark current and clipping).
        """
        t = check_number(exposure, "exposure", lo=0, hi=3600, lo_open=True)
        return self.photon_flux * self.pixel_area_um2 * np.asarray(self.qe) * t

    def usable_electrons(self):
        """float: electrons at which the pixel stops responding (well or ADC, whichever first)."""
        return min(self.full_well, (self.white_level - self.black_level) / self.system_gain)


# --------------------------------------------------------------------------
# ToF sensor
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class ToFSensor(_Readout):
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
    modulation_contrast : float or tuple of float
        Demodulation contrast in (0, 1] (0.8): tap amplitude over the
        active-light part of the offset; one value per frequency when the
        contrast changes with the frequency (it falls at high frequencies).
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

    Non-idealities (every one off or ideal by default; docs/guide/sensor.md,
    "Non-idealities of the i-ToF pixel")

    harmonics : tuple of (order, amplitude, phase)
        Harmonics of the correlation of the emitted light with the
        demodulation gate, relative to the fundamental: tap k reads
        ``O + a sum_h b_h cos(h (phi + k pi/2) + theta_h)`` (``b_1 = 1``,
        ``theta_1 = 0``). Order >= 2, amplitude in [0, 1], phase in radians.
        Four taps alias the odd orders onto the fundamental: order 3 (and 5)
        gives a cyclic depth error of period a quarter of the wrap range and
        peak ``~b c / (4 pi f)``. Default () -- a pure sinusoid.
    tap_contrast : 4 floats
        Demodulation contrast of each tap relative to ``modulation_contrast``
        (a systematic mismatch between the four gates), each in (0, 2].
        Unequal contrasts give a cyclic error at twice the phase. Default
        (1, 1, 1, 1).
    delay_ps : float
        Delay of the returned light against the demodulation, common to every
        pixel (driver and laser latency), in ps: a phase offset ``2 pi f tau``
        at every frequency, i.e. a distance offset ``c tau / 2``. Default 0.
    delay_fpn_ps : float
        Per-pixel delay, a fixed pattern (``fpn_seed``) of this rms in ps:
        the per-pixel phase offset of the clock tree. Default 0.
    multipath : (float, float) or None
        A second return of every surface: ``(relative_amplitude,
        extra_path_m)``, amplitude in [0, 1] relative to the direct return and
        the extra one-way distance in metres (> 0). Default None.
    ambient_suppression : float
        Share of each tap's common-mode (DC) charge that an in-pixel circuit
        drains during the integration (background-light suppression), in
        [0, 1): the taps keep the shot noise of all the light collected but
        their wells fill ``1 / (1 - s)`` times more slowly. Default 0.
    duty_cycle : float
        Burst illumination: the source emits ``optical_power_w / duty_cycle``
        during this share of the integration time and the pixel integrates
        only then, in (0, 1]. The laser energy is unchanged; ambient light and
        dark current are collected ``duty_cycle`` times as long. Default 1
        (continuous wave).
    """

    frequencies: tuple = (80e6, 100e6, 120e6)
    integration_time: float = 1e-3
    wavelength_nm: float = 940.0
    optical_power_w: float = 0.5
    modulation_contrast: float | tuple[float, ...] = 0.8
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
    harmonics: tuple = ()
    tap_contrast: tuple = (1.0, 1.0, 1.0, 1.0)
    delay_ps: float = 0.0
    delay_fpn_ps: float = 0.0
    multipath: tuple | None = None
    ambient_suppression: float = 0.0
    duty_cycle: float = 1.0

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
        store_number(self, "integration_time", lo=0, hi=10, lo_open=True)
        store_number(self, "wavelength_nm", lo=700, hi=1700)
        store_number(self, "optical_power_w", lo=0, hi=1e3, lo_open=True)
        check_tof_contrast(self, len(freqs))
        try:
            fov = tuple(float(v) for v in self.fov_deg)
        except (TypeError, ValueError):
            raise TypeError(f"ToFSensor.fov_deg: expected (horizontal, vertical) degrees, got "
                            f"{self.fov_deg!r}") from None
        if len(fov) != 2 or not all(0 < v < 180 for v in fov):
            raise ValueError(f"ToFSensor.fov_deg: expected two angles in (0, 180) degrees, got "
                             f"{self.fov_deg!r}")
        object.__setattr__(self, "fov_deg", fov)
        store_number(self, "f_number", lo=0.5, hi=64)
        store_number(self, "optics_transmission", lo=0, hi=1, lo_open=True)
        store_number(self, "qe", lo=0, hi=1, lo_open=True)
        store_number(self, "ambient_irradiance", lo=0, hi=1e4)
        if self.pixel_pitch_um is not None:
            store_number(self, "pixel_pitch_um", lo=0.1, hi=100)
        if self.z_block is not None and (isinstance(self.z_block, bool) or not isinstance(
                self.z_block, (int, np.integer)) or self.z_block not in (1, 2)):
            raise ValueError(f"ToFSensor.z_block: expected None, 1 or 2, got {self.z_block!r}")
        check_readout(self)
        check_pixel_noise(self)
        check_tof_nonideal(self)

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

    @property
    def contrasts(self):
        """ndarray (F,): the modulation contrast at every frequency."""
        c = self.modulation_contrast
        return np.broadcast_to(np.asarray(c, np.float64), (len(self.frequencies),)).copy()

    @property
    def is_ideal(self):
        """bool: no non-ideality of the modulation (harmonics, tap contrasts, delays, multipath)."""
        return (not self.harmonics and self.tap_contrast == (1.0, 1.0, 1.0, 1.0)
                and not isinstance(self.modulation_contrast, tuple) and self.delay_ps == 0
                and self.delay_fpn_ps == 0 and self.multipath is None)

    def tap_electrons(self, distance, ir_reflectance, *, pixel_pitch_um=DEFAULT_CELL_PITCH_UM):
        """Mean electrons per tap of one-cell Z pixels (noise-free, no FPN, no per-pixel delay).

        Parameters
        ----------
        distance, ir_reflectance : array_like, same shape (...)
            Metres (> 0) and NIR reflectance of the surface seen.
        pixel_pitch_um : float
            Cell pitch (the colour-pixel pitch).

        Returns
        -------
        ndarray, shape (F, 4, ...)
            ``O + a cos(phi + k pi/2)`` of the module docstring (with the
            harmonics, tap contrasts, global delay and multipath when set),
            dark current included, less the suppressed common mode.
        """
        d = check_image(distance, "distance").astype(np.float64)
        if not (d.min() >= 1e-100 and d.max() <= 1e100):
            raise ValueError(f"distance: expected metres in [1e-100, 1e100] (the light falls "
                             f"off as 1 / distance**2), got [{d.min():g}, {d.max():g}]")
        rho = check_image(ir_reflectance, "ir_reflectance").astype(np.float64)
        if rho.min() < 0 or rho.max() > 1:
            raise ValueError(f"ir_reflectance: expected values in [0, 1], got "
                             f"[{rho.min():g}, {rho.max():g}]")
        try:
            rho = np.broadcast_to(rho, d.shape)
        except ValueError:
            raise ValueError(f"ir_reflectance: shape {rho.shape} does not match distance "
                             f"{d.shape}") from None
        pitch = check_number(pixel_pitch_um, "pixel_pitch_um", lo=0.01, hi=1000)
        s, b = self._cell_electrons(d, rho, pitch)
        phasors, active = self._returns(d, s)
        if self.delay_ps:
            phasors = self._delayed(phasors, np.full(d.shape, self.delay_ps))
        total = active + b
        mean = self._taps_from(phasors, total) + self._dark_electrons
        if self.ambient_suppression:
            mean = mean - self._suppressed(total)[None, None]
        return mean

    def active_electrons(self, distance, ir_reflectance=1.0, *, pixel_pitch_um=None):
        """Electrons of the source's light that one Z cell collects over one integration.

        The radiometry of the class docstring, noise-free: ``rho P / (4 d^2
        tan(h/2) tan(v/2)) * T A / (4 N^2) / (h c / lambda) * qe * t`` for a
        cell of area ``A``; no ambient light, dark signal or modulation
        contrast.

        Parameters
        ----------
        distance : array_like
            Metres (> 0).
        ir_reflectance : float or array_like
            NIR reflectance of the surface (1: the reference a measured
            amplitude is compared with).
        pixel_pitch_um : float, optional
            Cell pitch; default :attr:`pixel_pitch_um`, or
            :data:`DEFAULT_CELL_PITCH_UM` when that is None.

        Returns
        -------
        ndarray of float64, the broadcast shape of the arguments

        Examples
        --------
        >>> s = ToFSensor().active_electrons([1.0, 2.0])
        >>> [round(float(v)) for v in s], round(float(s[0] / s[1]), 6)   # 1 / d^2
        ([909, 227], 4.0)
        """
        if pixel_pitch_um is None:
            pixel_pitch_um = self.pixel_pitch_um or DEFAULT_CELL_PITCH_UM
        s, _ = self._cell_electrons(np.asarray(distance, np.float64), ir_reflectance,
                                    float(pixel_pitch_um))
        return s

    # -- internals ------------------------------------------------------------
    @property
    def _dark_electrons(self):
        """Dark electrons per tap over one integration (only while the pixel integrates)."""
        return self.dark_current * self.integration_time * self.duty_cycle

    def _suppressed(self, total):
        """Charge drained from each tap by the ambient suppression: a share of its DC part."""
        return self.ambient_suppression * (0.25 * total + self._dark_electrons)

    def _cell_constants(self, pitch_um):
        """(tan(h/2), tan(v/2), k): the field of view's half-angle tangents and the electrons
        per unit irradiance of one cell of pitch ``pitch_um`` (the radiometry of
        :meth:`_cell_electrons`; the unguided ToF ISP's C validity takes them as they are)."""
        area = (pitch_um * 1e-6) ** 2
        photon_energy = _PLANCK * SPEED_OF_LIGHT / (self.wavelength_nm * 1e-9)
        th = math.tan(math.radians(self.fov_deg[0]) / 2)
        tv = math.tan(math.radians(self.fov_deg[1]) / 2)
        k = (self.optics_transmission * area / (4 * self.f_number ** 2) / photon_energy
             * self.qe * self.integration_time)
        return th, tv, k

    def _cell_electrons(self, d, rho, pitch_um):
        """Active (S) and ambient (B) electrons collected by one cell over one integration.

        The burst illumination (``duty_cycle``) keeps the laser energy and
        collects ambient light only while the pixel integrates.
        """
        th, tv, k = self._cell_constants(pitch_um)
        irradiance = self.optical_power_w / (4 * d * d * th * tv)
        ambient = rho * self.ambient_irradiance * k
        if self.duty_cycle != 1.0:
            ambient = ambient * self.duty_cycle
        return rho * irradiance * k, ambient

    def _phase(self, d):
        f = np.asarray(self.frequencies).reshape((-1,) + (1,) * d.ndim)
        return np.mod(4 * np.pi * f * d[None] / SPEED_OF_LIGHT, 2 * np.pi)

    def _orders(self):
        """(order, complex weight) of the correlation's terms, the fundamental first."""
        return [(1, 1.0)] + [(h, a * np.exp(1j * th)) for h, a, th in self.harmonics]

    def _returns(self, d, s):
        """Active phasors ``{order h: S e^{i h phi}}`` (F, ...) of each cell, and the active light.

        With ``multipath`` every cell adds a return of ``r S`` from ``d + extra``.
        """
        phase = self._phase(d)
        out = {}
        for h, _ in self._orders():
            out[h] = s[None] * np.exp(1j * phase) if h == 1 else \
                s[None] * np.exp(1j * (h * phase))
        active = s
        if self.multipath is not None:
            r, extra = self.multipath
            phase2 = self._phase(d + extra)
            for h in out:
                out[h] = out[h] + (r * s)[None] * np.exp(1j * (h * phase2))
            active = s * (1.0 + r)
        return out, active

    def _delayed(self, phasors, delay_ps):
        """The phasors of every order turned by the delays (ps, shape (...)) of each pixel."""
        f = np.asarray(self.frequencies).reshape((-1,) + (1,) * np.ndim(delay_ps))
        turn = 2 * np.pi * f * (np.asarray(delay_ps, np.float64)[None] * 1e-12)
        return {h: p * np.exp(1j * (h * turn)) for h, p in phasors.items()}

    def _taps_from(self, phasors, total):
        """Tap photo-electrons (F, 4, ...) from the summed active phasors and S+B (...).

        ``(S + B)/4 + C/4 * Re(P * e^{i k pi/2})`` with ``P = sum_cells S e^{i phi}``
        -- for one cell ``S/4 (1 + C cos(phi + k pi/2)) + B/4``. No dark signal.
        With harmonics, tap contrasts or per-frequency contrasts:
        ``(S + B)/4 + C_f c_k / 4 * Re(sum_h w_h P_h e^{i h k pi/2})``, clipped at 0
        (a tap never holds negative charge).
        """
        if not isinstance(phasors, dict):
            phasors = {1: phasors}
        p1 = phasors[1]
        shape = (1, 4) + (1,) * (p1.ndim - 1)
        shifts = np.exp(1j * np.pi / 2 * np.arange(4))            # e^{i k pi/2}
        if (len(phasors) == 1 and self.tap_contrast == (1.0, 1.0, 1.0, 1.0)
                and not isinstance(self.modulation_contrast, tuple)):
            ac = (p1[:, None] * shifts.reshape(shape)).real
            return 0.25 * total[None, None] + 0.25 * self.modulation_contrast * ac
        ac = np.zeros((p1.shape[0], 4) + p1.shape[1:])
        for h, w in self._orders():
            sh = shifts if h == 1 else np.exp(1j * np.pi / 2 * np.mod(h * np.arange(4), 4))
            ac += (w * phasors[h][:, None] * sh.reshape(shape)).real
        gain = (self.contrasts.reshape((-1, 1) + (1,) * (p1.ndim - 1))
                * np.asarray(self.tap_contrast).reshape(shape))
        return np.maximum(0.25 * total[None, None] + 0.25 * gain * ac, 0.0)
