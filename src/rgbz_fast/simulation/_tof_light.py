"""The mean light of the ToF pixels in NumPy, for the models the fused C pass of
:func:`~rgbz_fast.simulation.simulate_tof` does not hold (a non-ideal modulation, optics):
each Z measurement's active phasors and total light, summed over its cells, and from them
the mean tap electrons.

Through optics, the light of the whole frame is blurred at the laser wavelength before the
cells sample it; each frequency's phasor field comes from one C pass
(``_kernels.sim_tof_field``, the bits of :meth:`ToFSensor._returns
<rgbz_fast.ToFSensor>`'s NumPy) and is blurred before the next is made.
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._sensors import SPEED_OF_LIGHT
from .._validate import check_workers
from ._noise import STREAM_TOF_DELAY
from ._optics import _convolve
from ._scene import estimate_ir_reflectance

__all__ = []


def _tof_light_at_cells(scene, sensor, pitch, cr, cc):
    """Active phasors {order: (F, n)} and S + B (n,) of every Z measurement, summed over
    its cells (no optics: each cell sees the surface at its own pixel)."""
    d = scene.depth[cr, cc]
    if scene.ir_reflectance is not None:
        rho = scene.ir_reflectance[cr, cc]
    else:
        rho = estimate_ir_reflectance(scene.image[cr, cc], scene.wavelengths)
    # a depth of 0 is only allowed where unknown: no surface, no laser return there
    surface = d > 0
    d_safe = np.where(surface, d, 1.0)
    s, b = sensor._cell_electrons(d_safe, rho, pitch)
    s = np.where(surface, s, 0.0)
    cells, active = sensor._returns(d_safe, s)
    return {h: p.sum(axis=-1) for h, p in cells.items()}, (active + b).sum(axis=-1)


def _tof_light_through(scene, sensor, pitch, cr, cc, optics, workers):
    """As :func:`_tof_light_at_cells`, the light of the whole frame first blurred through
    ``optics`` at the laser wavelength and the ToF lens's f-number: a pixel near a depth
    edge receives both surfaces' returns (lens-induced mixing)."""
    d = scene.depth
    rho = scene.ir_map()
    surface = d > 0
    d_safe = np.where(surface, d, 1.0)
    s, b = sensor._cell_electrons(d_safe, rho, pitch)
    s = np.where(surface, s, 0.0)
    kernel = optics.psf(sensor.wavelength_nm, pixel_pitch_um=pitch, f_number=sensor.f_number)
    nthreads = check_workers(workers)

    def blur_at_cells(plane, signed=False):
        return _convolve(plane, kernel, signed=signed, workers=nthreads)[cr, cc].sum(axis=-1)

    phasors = {}
    if sensor.multipath is None:
        # each frequency's field in one C pass (sim_tof_field: the bits of _returns' NumPy),
        # blurred before the next is made: two real planes at a time instead of the (F, H, W)
        # complex fields and phases of every frequency
        d64 = np.ascontiguousarray(d_safe, np.float64).reshape(-1)
        s64 = np.ascontiguousarray(s, np.float64).reshape(-1)
        four_pi_f = 4 * np.pi * np.asarray(sensor.frequencies, np.float64)
        for h, _ in sensor._orders():
            planes = []
            for kf in four_pi_f:
                re, im = np.empty(d_safe.shape), np.empty(d_safe.shape)
                _kernels.sim_tof_field(d64, s64, float(kf), SPEED_OF_LIGHT, 2 * np.pi, h,
                                       re.reshape(-1), im.reshape(-1), nthreads)
                planes.append(blur_at_cells(re, True) + 1j * blur_at_cells(im, True))
                del re, im
            phasors[h] = np.stack(planes)
        return phasors, blur_at_cells(s + b)
    fields, active = sensor._returns(d_safe, s)
    for h, field in fields.items():
        phasors[h] = np.stack([blur_at_cells(f.real, True) + 1j * blur_at_cells(f.imag, True)
                               for f in field])
    return phasors, blur_at_cells(active + b)


def _pixel_delays(sensor, rows, cols, positional=True):
    """Delay (ps) of every Z measurement: the global one plus the fixed per-pixel pattern,
    drawn from ``fpn_seed`` on a stream of its own (so the PRNU/DSNU maps do not change).

    ``positional`` (``rng_version=2``): the normal of the Z pixel at (row, col) is number col
    of the counter-based stream's row ``row``, so a pixel keeps its delay in a frame of any
    size, as its PRNU and DSNU do; else (``rng_version=1``) NumPy's normals in site order
    (which followed the site's index, not its place: H80)."""
    rows, cols = np.asarray(rows), np.asarray(cols)
    delay = np.full(rows.size, sensor.delay_ps)
    if not sensor.delay_fpn_ps:
        return delay
    if not positional:
        rng = np.random.default_rng([sensor.fpn_seed, STREAM_TOF_DELAY])
        return delay + sensor.delay_fpn_ps * rng.standard_normal(rows.size)
    from ._noise import _seed_words

    key = np.array(_kernels.sim_key(_seed_words(int(sensor.fpn_seed)), STREAM_TOF_DELAY),
                   np.uint32)
    z = np.empty(rows.size)
    order = np.argsort(rows, kind="stable")
    starts = np.flatnonzero(np.diff(rows[order], prepend=-1))
    for a, b in zip(starts, list(starts[1:]) + [order.size]):
        at = order[a:b]                                      # the sites of one row
        normals = np.empty(int(cols[at].max()) + 1)
        _kernels.sim_variates(0, np.empty(0), int(rows[at[0]]), 0, key, normals, 1)
        z[at] = normals[cols[at]]
    return delay + sensor.delay_fpn_ps * z


def _tof_mean(scene, sensor, pitch, rows, cols, block, optics, workers, positional=True):
    """The mean tap electrons (F, 4, n) of every model of the ToF pixels (the non-ideal
    modulation, the optics), in NumPy; with the suppressed charge per site (or None), the
    true depth, validity and beyond-range flag of every site and the largest valid depth."""
    # cells of every measurement: (n_sites, block*block)
    offs = [(dr, dc) for dr in range(block) for dc in range(block)]
    cr = np.stack([rows + dr for dr, _ in offs], axis=1)
    cc = np.stack([cols + dc for _, dc in offs], axis=1)
    d = scene.depth[cr, cc]
    cell_valid = scene.depth_valid[cr, cc]
    if optics is None:
        phasors, total = _tof_light_at_cells(scene, sensor, pitch, cr, cc)
    else:
        phasors, total = _tof_light_through(scene, sensor, pitch, cr, cc, optics, workers)
    if sensor.delay_ps or sensor.delay_fpn_ps:
        phasors = sensor._delayed(phasors, _pixel_delays(sensor, rows, cols, positional))
    mean = sensor._taps_from(phasors, total)                                # (F, 4, n)
    suppress = sensor._suppressed(total) if sensor.ambient_suppression else None
    beyond = np.any(cell_valid & (d >= sensor.unambiguous_range), axis=1)
    dmax = float(d[cell_valid].max()) if beyond.any() else -np.inf
    return mean, suppress, d.mean(axis=1), cell_valid.all(axis=1), beyond, dmax


