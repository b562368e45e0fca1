"""The per-pixel work of the sensor models, in C (csrc/sim.c): the colour pixels, the exact
auto-exposure percentile, the taps of ideal Z pixels and the noise chain of given taps.

The noise-free arithmetic is that of the NumPy code of :mod:`._simulate` and
:mod:`._noise`, operation by operation (tests/simulation/test_pixels.py compares them bit
for bit); the random numbers are those of ``rng_version`` 2 (:mod:`._noise`).
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._patterns import Z
from .._sensors import SPEED_OF_LIGHT
from .._validate import check_workers

__all__ = ["colour_source", "rate_percentile", "colour_dn", "z_sites", "tof_ideal",
           "tof_expose"]


def colour_source(values):
    """A float image (rows, cols, C) or a map (rows, cols) as the kernels read it:
    ``(flat, rows, cols, row_stride, col_stride, chan_off)`` (channel offsets of R, G, B;
    0 for a map, whose value serves every colour)."""
    a = values if values.dtype in (np.float32, np.float64) else values.astype(np.float64)
    a = np.ascontiguousarray(a)
    rows, cols = a.shape[:2]
    if a.ndim == 2:
        return a.reshape(-1), rows, cols, cols, 1, np.zeros(3, np.intp)
    c = a.shape[2]
    return a.reshape(-1), rows, cols, cols * c, c, np.arange(3, dtype=np.intp)


def _tiles(pattern):
    """The Bayer colour of every tile site (int32) and the Z flags (uint8), one period."""
    tile = np.ascontiguousarray(pattern.bayer_tile(), np.int32)
    return tile, np.ascontiguousarray(pattern.tile == Z, np.uint8)


def rate_percentile(source, pattern, per_unit, q, workers=None):
    """``np.percentile(rate, q)`` of the signal rate ``value * per_unit[colour]`` of every site,
    bit for bit, without the frame-size array of rates: the two order statistics its linear
    interpolation needs are found by a histogram of the rates' top 16 bits and the rates of
    the bins that hold them, then interpolated by NumPy itself."""
    flat, rows, cols, rs, cs, off = source
    tile, _ = _tiles(pattern)
    pu = np.ascontiguousarray(per_unit, np.float64)
    nth = check_workers(workers)
    n = rows * cols
    # NumPy's "linear" method: virtual index (n - 1) q / 100, its floor and the next one
    virtual = (n - 1) * np.true_divide(np.asanyarray(q, np.float64), 100)
    if virtual >= n - 1:
        ranks = (n - 1, n - 1)
    else:
        lo = int(np.floor(virtual))
        ranks = (lo, lo + 1)
    hist = np.empty(65536, np.uint64)
    _kernels.sim_rate_hist(flat, rows, cols, rs, cs, off, tile, pu, hist, nth)
    below = np.cumsum(hist, dtype=np.int64)
    bins = [int(np.searchsorted(below, r, side="right")) for r in ranks]
    start = int(below[bins[0] - 1]) if bins[0] else 0
    size = int(below[bins[1]]) - start
    values = np.empty(size, np.float64)
    got = _kernels.sim_rate_gather(flat, rows, cols, rs, cs, off, tile, pu, bins[0], bins[1],
                                   values, nth)
    if got != size:
        raise RuntimeError(f"rate_percentile: gathered {got} rates, the histogram said {size}")
    values.sort()
    a, b = values[ranks[0] - start], values[ranks[1] - start]
    if ranks[0] == ranks[1]:
        return float(a)
    gamma = virtual - np.floor(virtual)
    return float(np.quantile(np.array([a, b]), gamma))


def colour_dn(source, pattern, per_unit, exposure, fields, keys, *, rgbz=False, workers=None):
    """The colour pixels' digital numbers: ``(reference, data or None, saturated count)``.

    ``data`` (with ``rgbz``) is the reference with 0 at the Z sites of ``pattern``."""
    flat, rows, cols, rs, cs, off = source
    tile, tile_z = _tiles(pattern)
    dt = np.uint16 if fields["quantise"] else np.float64
    ref = np.empty((rows, cols), dt)
    data = np.empty((rows, cols), dt) if rgbz else None
    nsat = _kernels.sim_colour(flat, rows, cols, rs, cs, off, tile, tile_z,
                               np.ascontiguousarray(per_unit, np.float64), float(exposure),
                               fields, keys, ref, data, check_workers(workers))
    return ref, data, nsat


def z_sites(pattern, shape, block, workers=1):
    """(rows, cols) int64 of the Z measurements, row-major: every Z site (block 1), or the
    top-left cell of every 2x2 Z square inside the frame (block 2); on ``workers`` threads
    (a checked count)."""
    tile_z = np.ascontiguousarray(pattern.tile == Z, np.uint8)
    return _kernels.sim_z_sites(tile_z, int(shape[0]), int(shape[1]), int(block),
                                int(workers))


def _light(sensor, pitch):
    """The light model of an ideal ToF sensor as csrc/sim.h's rgbz_sim_tof_light, with the
    constants formed as :class:`~rgbz_fast.ToFSensor` forms them."""
    import math

    from .._sensors import _PLANCK

    area = (pitch * 1e-6) ** 2
    photon_energy = _PLANCK * SPEED_OF_LIGHT / (sensor.wavelength_nm * 1e-9)
    th = math.tan(math.radians(sensor.fov_deg[0]) / 2)
    tv = math.tan(math.radians(sensor.fov_deg[1]) / 2)
    k = (sensor.optics_transmission * area / (4 * sensor.f_number ** 2) / photon_energy
         * sensor.qe * sensor.integration_time)
    vals = np.array([k, sensor.optical_power_w, th, tv, sensor.ambient_irradiance,
                     sensor.duty_cycle, 0.25 * sensor.modulation_contrast,
                     sensor.ambient_suppression, sensor.unambiguous_range, SPEED_OF_LIGHT,
                     2 * np.pi], np.float64)
    four_pi_f = 4 * np.pi * np.asarray(sensor.frequencies, np.float64)
    shifts = np.exp(1j * np.pi / 2 * np.arange(4))
    return vals, four_pi_f, np.ascontiguousarray(shifts.real), np.ascontiguousarray(shifts.imag)


def tof_ideal(scene, sensor, pitch, sites, block, fields, keys, workers=None):
    """The taps of ideal Z pixels (no harmonics, tap contrasts, delays or multipath; no
    optics): ``(taps (F, 4, n), depth_true, valid, beyond, sat, max valid cell depth)``."""
    from ._scene import estimate_ir_reflectance

    rows, cols = sites
    n = rows.size
    if scene.ir_reflectance is not None:
        ir, estimate = scene.ir_reflectance, 0
    elif scene.wavelengths is None:
        ir, estimate = scene.image, 1              # the estimate from channel 0, the red
    else:
        ir, estimate = estimate_ir_reflectance(scene.image, scene.wavelengths), 0
    flat, _, _, ir_rs, ir_cs, _ = colour_source(ir)
    vals, four_pi_f, sre, sim = _light(sensor, pitch)
    F = four_pi_f.size
    taps = np.empty((F, 4, n), np.uint16 if fields["quantise"] else np.float64)
    depth_true = np.empty(n)
    valid = np.empty(n, np.uint8)
    beyond = np.empty(n, np.uint8)
    sat = np.empty(n, np.uint8)
    dvalid = np.ascontiguousarray(scene.depth_valid).view(np.uint8)
    dmax = _kernels.sim_tof(np.ascontiguousarray(scene.depth), dvalid, flat, ir_rs, ir_cs,
                            estimate, rows, cols, int(block), vals, four_pi_f, sre, sim, fields,
                            keys, taps, depth_true, valid, beyond, sat, check_workers(workers))
    return taps, depth_true, valid.view(bool), beyond.view(bool), sat.view(bool), dmax


def tof_expose(mean, suppress, sites, fields, keys, workers=None):
    """The noise chain of taps whose mean electrons (F, 4, n) are given: ``(taps, sat)``;
    ``suppress``: the electrons drained from every tap of a site (n,), or None."""
    rows, cols = sites
    mean = np.ascontiguousarray(mean, np.float64)
    taps = np.empty(mean.shape, np.uint16 if fields["quantise"] else np.float64)
    sat = np.empty(mean.shape[2], np.uint8)
    sup = None if suppress is None else np.ascontiguousarray(
        np.broadcast_to(suppress, (mean.shape[2],)), np.float64)
    _kernels.sim_tof_expose(mean, sup, rows, cols, fields, keys, taps, sat,
                            check_workers(workers))
    return taps, sat.view(bool)
