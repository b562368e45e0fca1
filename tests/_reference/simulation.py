"""NumPy reference of the sensor models' per-pixel work (csrc/sim.c), noise-free.

Whole-array NumPy, written from the module docstring of rgbz_fast.simulation._simulate
(the tap convention, the radiometry and the noise chain), in the order of operations of
the package's NumPy code of rgbz-fast 0.1, which the C kernels reproduce bit for bit:
the colour pixels (signal rate, auto-exposure percentile, the chain) and the taps of
ideal Z pixels. No random number: with noise the C kernels are checked by the
statistics of their draws (tests/simulation/test_pixels.py).
"""

from __future__ import annotations

import math

import numpy as np

from rgbz_fast._sensors import _PLANCK, SPEED_OF_LIGHT


def chain(mean_e, dark_e, sensor, suppress=None):
    """Mean electrons -> (DN, saturated) without noise: dark signal, the suppressed charge,
    well, ADC."""
    e = mean_e + dark_e
    drained = np.zeros(np.shape(e), bool)
    if suppress is not None:
        # at most what a tap holds: an emptied tap is flagged (H87)
        drained = e < suppress
        e = np.where(drained, 0.0, e - suppress)
    well_full = (e >= sensor.full_well) | drained
    e = np.minimum(e, sensor.full_well)
    dn = sensor.black_level + sensor.system_gain * e
    if sensor.quantise:
        dn = np.floor(dn + 0.5)
    saturated = well_full | (dn >= sensor.white_level) | (dn < 0)
    dn = np.clip(dn, 0, sensor.white_level)
    return (dn.astype(np.uint16) if sensor.quantise else dn), saturated


def colour_rate(values, sensor, colour_map):
    """Signal electrons per second of every site: the channel of its colour times the
    per-unit signal (``values``: (H, W, 3) image or (H, W) map)."""
    per_unit = sensor.electrons_per_unit(1.0)
    if values.ndim == 3:
        value = np.take_along_axis(values, colour_map[..., None].astype(np.intp),
                                   axis=2)[..., 0].astype(np.float64)
    else:
        value = values
    return value * per_unit[colour_map]


def colour_frame(values, sensor, colour_map):
    """The noise-free colour CFA: (DN, saturated fraction, exposure)."""
    rate = colour_rate(values, sensor, colour_map)
    if sensor.exposure == "auto":
        level = float(np.percentile(rate, sensor.ae_percentile))
        exposure = sensor.ae_target * sensor.usable_electrons() / level
    else:
        exposure = sensor.exposure
    dn, sat = chain(rate * exposure, sensor.dark_current * exposure, sensor)
    return dn, float(sat.mean()), exposure


def tof_taps(depth, valid, ir, sensor, pitch, rows, cols, block):
    """The noise-free taps (F, 4, n) of ideal Z pixels of ``block`` x ``block`` cells whose
    top-left cells are (rows, cols), ``ir`` the NIR reflectance map; with the true depth,
    validity and saturation of every site."""
    offs = [(dr, dc) for dr in range(block) for dc in range(block)]
    cr = np.stack([rows + dr for dr, _ in offs], axis=1)
    cc = np.stack([cols + dc for _, dc in offs], axis=1)
    d, rho, cell_valid = depth[cr, cc], ir[cr, cc], valid[cr, cc]
    surface = d > 0
    ds = np.where(surface, d, 1.0)
    area = (pitch * 1e-6) ** 2
    photon_energy = _PLANCK * SPEED_OF_LIGHT / (sensor.wavelength_nm * 1e-9)
    th = math.tan(math.radians(sensor.fov_deg[0]) / 2)
    tv = math.tan(math.radians(sensor.fov_deg[1]) / 2)
    k = (sensor.optics_transmission * area / (4 * sensor.f_number ** 2) / photon_energy
         * sensor.qe * sensor.integration_time)
    irradiance = sensor.optical_power_w / (4 * ds * ds * th * tv)
    ambient = rho * sensor.ambient_irradiance * k
    if sensor.duty_cycle != 1.0:
        ambient = ambient * sensor.duty_cycle
    s = np.where(surface, rho * irradiance * k, 0.0)
    f = np.asarray(sensor.frequencies).reshape(-1, 1, 1)
    phase = np.mod(4 * np.pi * f * ds[None] / SPEED_OF_LIGHT, 2 * np.pi)
    phasor = (s[None] * np.exp(1j * phase)).sum(axis=-1)                   # (F, n)
    total = (s + ambient).sum(axis=-1)
    shifts = np.exp(1j * np.pi / 2 * np.arange(4)).reshape(1, 4, 1)
    ac = (phasor[:, None] * shifts).real
    mean = 0.25 * total[None, None] + 0.25 * sensor.modulation_contrast * ac
    dark = sensor.dark_current * sensor.integration_time * sensor.duty_cycle
    suppress = (sensor.ambient_suppression * (0.25 * total + dark)
                if sensor.ambient_suppression else None)
    taps, sat = chain(mean, dark, sensor, suppress)
    return taps, d.mean(axis=1), cell_valid.all(axis=1), sat.any(axis=(0, 1))


def tof_light_through(scene, sensor, pitch, cr, cc, optics, workers):
    """The active phasors {order: (F, n)} and S + B (n,) of every Z measurement through
    ``optics``, as rgbz-fast computed them before the C field pass: every frequency's complex
    field of the whole frame from ``ToFSensor._returns`` (NumPy), its real and imaginary
    parts blurred, then summed over each measurement's cells."""
    from rgbz_fast.simulation._optics import _convolve

    d = scene.depth
    surface = d > 0
    d_safe = np.where(surface, d, 1.0)
    s, b = sensor._cell_electrons(d_safe, scene.ir_map(), pitch)
    s = np.where(surface, s, 0.0)
    fields, active = sensor._returns(d_safe, s)
    kernel = optics.psf(sensor.wavelength_nm, pixel_pitch_um=pitch, f_number=sensor.f_number)

    def blur_at_cells(plane, signed=False):
        return _convolve(plane, kernel, signed=signed, workers=workers)[cr, cc].sum(axis=-1)

    phasors = {h: np.stack([blur_at_cells(f.real, True) + 1j * blur_at_cells(f.imag, True)
                            for f in field]) for h, field in fields.items()}
    return phasors, blur_at_cells(active + b)
