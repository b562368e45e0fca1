"""The colour-guided ToF ISP: the frame's own colour image steers the denoise and the
flying-pixel test, and gives a depth at every pixel (:func:`upsample_depth`).

A monolithic RGB-Z chip's colour image is registered with its Z measurements by
construction, at full resolution and at a far higher SNR. With ``guide=`` the
ToF ISP uses it three ways (C kernels, csrc/tof_guided.c; docs/guide/isp.md):

* **Denoise.** A cross (joint) bilateral mean of the phasors over the Z
  measurements of the window: each neighbour weighs
  ``exp(-max(chi_p - 2F, 0) / (2 h^2) - max(chi_c - 3, 0) / (2 h_c^2))``, with
  ``chi_p`` the phasor disagreement in units of its noise (as without a guide)
  and ``chi_c = |c_m - c_n|^2 / (2 sigma_c^2)`` the colour disagreement in
  units of the guide's own noise (Immerkaer's estimate [1]_, per channel, on
  the colours at the measurements), so a low-signal measurement averages over its
  own surface and never across a colour edge. It runs as a row pass then a
  column pass, twice (the second round guided by the first's output): the
  column pass averages row means of different rows, which share no
  measurement, so the variance of the 2-D mean is exact for the weights at
  ``2L`` instead of ``L^2`` neighbours for an ``L x L`` window.
* **Flying pixels.** A measurement at a depth discontinuity (the second
  differences of :func:`~rgbz_fast.tof.flying_pixels`) is compared with the two
  sides of the discontinuity among its 8 neighbours: when its depth is one
  side's, every cell of its Z pixel has that side's colour and every pixel
  bordering the Z pixel is nearer that side's colour than the other's (a 2x2
  Z pixel, whose cells' colours the colour ISP interpolates, so they place an
  edge to a pixel at best; a 1x1 pixel's colour cannot tell a pure
  measurement from a blend), it is a pure measurement and stays valid; when its depth lies between the sides and
  all its cells have one side's colour, it takes that side's depth and the
  bit :attr:`ToFFlag.RESOLVED` (``ToFDepth.measured`` keeps what was measured);
  otherwise it is flagged flying.
* **Full resolution.** :func:`upsample_depth`.

References
----------
.. [1] Immerkaer, "Fast noise variance estimation" (docs/references.bib: immerkaer1996noise)
"""

from __future__ import annotations

import math
import threading
import weakref

import numpy as np

from .. import _kernels
from .._memory import empty as _empty, empty_like as _empty_like
from .._validate import check_image, check_number, check_workers, finite_range
from ._filters import SiteGrid, check_scale
from ._result import ToFDepth
from ._noise import (collected_scale, dark_noise, delay_fpn_variance, fixed_pattern_args,
                     fixed_pattern_delta, prnu_gain)
from ._validity import (FLAG_FLYING, FLAG_LOW_SIGNAL, FLAG_RESOLVED,
                        FLAG_SATURATED, radiometry_coefficients)

__all__ = ["upsample_depth", "check_guide", "GUIDED_WINDOW", "GUIDED_WINDOW_1X1",
           "UPSAMPLE_COLOUR_SCALE", "UPSAMPLE_AMBIGUITY"]

#: the window (Z-pixel cells) of the guided denoise when ``window`` is None: 11 Z
#: measurements per axis (radius 10 cells) for 2x2 Z pixels (Mask2) ...
GUIDED_WINDOW = 21
#: ... and 15 for 1x1 ones (Mask1; radius 15 pixels, the sites 2 apart), each of which
#: collects a quarter of the light: with the range kernel that knows the fixed pattern
#: (2026-11-27) it keeps the photon-limited scenes' measurements valid (art 81.7 -> 85.7 %,
#: the twenty real-NIR pairs 85.4 -> 89.3 %) and catches as many wrong ones over the six
#: scenes (97.1 %), at the cost of textured slanted surfaces (docs/reports/isp.md, "The
#: guided ISP on photon-limited scenes")
GUIDED_WINDOW_1X1 = 31
#: the colour contrast (``|c_1 - c_2|^2 / (2 sigma_c^2)``) between the two sides of a depth
#: discontinuity above which the colour may say which side a measurement is on (25 sigma^2)
EDGE_CONTRAST = 12.5
#: a cell is on a side when its colour lies within this share of the contrast of it
SIDE_SHARE = 0.15
#: the smallest noise of a guide taken (sigma_c, in [0, 1] units): half a step of 8 bits
NOISE_FLOOR = 0.5 / 255.0
#: the range scale of the upsampling's colour kernel (units of the guide's noise, as the
#: guided denoise's ``colour_scale``); wider than the denoise's, because the choice between
#: the surfaces of a pixel's four measurements and the abstention (UPSAMPLE_AMBIGUITY) keep
#: it from blending them
UPSAMPLE_COLOUR_SCALE = 20.0
#: upsampling: a pixel gets no depth when the measurements off the surface it would take hold
#: more than this share of its weight
UPSAMPLE_AMBIGUITY = 0.15
#: upsampling: a measurement flagged low-signal alone whose predicted sigma is at most this (m)
#: takes part as a measurement. The ISP flags every sigma above ``ToFISP.max_sigma`` (1.5 cm),
#: which keeps its valid measurements within 5 cm but for 0.05 %; the map allows 0.5 % of its
#: pixels more than 5 cm off, and at 2 cm a 5 cm error is 2.5 sigma (docs/reports/isp.md,
#: "Measured: full resolution")
UPSAMPLE_MAX_SIGMA = 0.02
#: upsampling: a measurement counts as another surface than the chosen one when its depth
#: lies more than this (m) from it (or than the mean's tolerance, if wider): the neighbouring
#: measurements of a slanted surface differ by more than that tolerance
_UP_GAP = 0.05
#: upsampling: a node whose own measurement is low-signal takes only the candidates within
#: this many of its sigma of that measurement
_UP_OWN_K = 2.0
#: upsampling: depths within max(3 sigma, 2 cm) of the heaviest candidate are averaged
_UP_TOL_K, _UP_TOL_MIN = 3.0, 0.02
#: upsampling in a hole: the measurements within 4 grid lines, Gaussian weights of this spread
#: (grid spacings)
_FILL_REACH, _FILL_SPREAD = 4, 2.0


def check_guide(guide, shape, name="guide"):
    """The frame's colour image as the kernels read it: (rows, cols, 3), C order, uint8,
    uint16, float32 or float64 (other real types as float64), and its scale to [0, 1]."""
    if guide is None:
        raise TypeError(f"{name}: expected the frame's colour image (rows, cols, 3), got None")
    g = check_image(guide, name, finite=False)            # floats: finite_range below
    if g.dtype == np.bool_:
        raise TypeError(f"{name}: expected colour values, got dtype bool")
    if g.ndim != 3 or g.shape[2] != 3:
        raise ValueError(f"{name}: expected a colour image of shape (rows, cols, 3), got "
                         f"shape {g.shape}")
    if g.shape[:2] != tuple(shape):
        raise ValueError(f"{name}: the image is {g.shape[0]}x{g.shape[1]}, the frame "
                         f"{shape[0]}x{shape[1]}; expected the frame's own colour image")
    if g.dtype == np.uint8:
        scale = 1.0 / 255.0
    elif g.dtype == np.uint16:
        scale = 1.0 / 65535.0
    elif g.dtype.kind in "iu":                   # its type would not say its range
        raise TypeError(f"{name}: an image of {g.dtype}; expected uint8 or uint16 sRGB, or "
                        "floats in [0, 1]")
    else:
        if g.dtype not in (np.float32, np.float64):
            g = g.astype(np.float64)
        lo, hi = finite_range(g, name)
        if lo < 0.0 or hi > 1.0:
            raise ValueError(f"{name}: float values span [{lo:g}, {hi:g}]; expected sRGB in "
                             f"[0, 1] (or uint8 / uint16)")
        scale = 1.0
    return np.ascontiguousarray(g), scale


class _Layout:
    """The Z measurements on a full row-major grid (R, C): holes of an irregular layout are
    scattered cells the kernels never use."""

    def __init__(self, sites, block, shape):
        self.grid = SiteGrid(sites, block)
        self.block = block
        self.R, self.C = self.grid.shape
        self.N = self.R * self.C
        self.full = self.grid.full
        self.present = np.ascontiguousarray(self.grid.present.reshape(-1))
        self.rows = np.ascontiguousarray(self.grid.rows_u, np.int64)
        self.cols = np.ascontiguousarray(self.grid.cols_u, np.int64)

    def to_grid(self, values, fill=0):
        v = np.asarray(values)
        return v if self.full else self.grid.to_grid(v, fill).reshape(v.shape[:-1] + (-1,))

    def from_grid(self, values):
        v = np.asarray(values)
        return v if self.full else self.grid.from_grid(v.reshape(v.shape[:-1] + (self.R,
                                                                                 self.C)))


#: the layouts of the last few site arrays (_layout_of): (id(rows), id(cols), block, shape) ->
#: (weak references to rows and cols, the _Layout)
_LAYOUTS = {}
_LAYOUTS_KEPT = 4
_LAYOUTS_LOCK = threading.Lock()


def _layout_of(sites, block, shape):
    """The _Layout of ``sites``, made once per pair of read-only site arrays (a ToFTaps' own,
    which its results share): proving a 3 M-site layout a grid costs about 10 ms a call. Arrays
    a caller may still write are checked every time."""
    rows, cols = sites if isinstance(sites, tuple) and len(sites) == 2 else (None, None)
    if not (isinstance(rows, np.ndarray) and isinstance(cols, np.ndarray)
            and not rows.flags.writeable and not cols.flags.writeable):
        return _Layout(sites, block, shape)
    key = (id(rows), id(cols), int(block), tuple(shape))
    with _LAYOUTS_LOCK:
        hit = _LAYOUTS.get(key)
    if hit is not None and hit[0]() is rows and hit[1]() is cols:
        return hit[2]
    layout = _Layout(sites, block, shape)
    with _LAYOUTS_LOCK:
        for k in [k for k, v in _LAYOUTS.items() if v[0]() is None or v[1]() is None]:
            del _LAYOUTS[k]
        while len(_LAYOUTS) >= _LAYOUTS_KEPT:
            del _LAYOUTS[next(iter(_LAYOUTS))]
        _LAYOUTS[key] = (weakref.ref(rows), weakref.ref(cols), layout)
    return layout


def guide_colours(g, scale, layout, nthreads, col=None):
    """The guide at the measurements, in units of ``sqrt(2)`` times its noise: colours (3, N)
    (into ``col`` when given), cells (block^2, 3, N) or None (1x1 Z pixels), and the noise
    sigma_c (3,)."""
    N, b = layout.N, layout.block
    col = _empty((3, N), np.float32) if col is None else col
    cells = _empty((b * b, 3, N), np.float32) if b > 1 else None
    lap, sigma = np.zeros(3), np.empty(3)
    # Immerkaer (1996): sigma = sqrt(pi / 2) / (6 (R - 2)(C - 2)) sum |L * image|, at least
    # NOISE_FLOOR; the kernel divides col and cells by sqrt(2) sigma
    _kernels.tofg_colour(g, layout.rows, layout.cols, b, scale, col, cells, lap, nthreads,
                         NOISE_FLOOR, sigma)
    return col, cells, sigma


def guide_ring(g, scale, layout, sigma, nthreads):
    """The guide at the pixels bordering each Z pixel, in the units of :func:`guide_colours`:
    (4 block + 4, 3, N) float32, or None for 1x1 Z pixels (whose colour cannot tell a pure
    measurement from a blend). A ring pixel off the frame repeats the nearest one on it (a
    pixel of the ring or of the Z pixel, so it adds no test). One C pass (``tofg_ring``; its
    NumPy reference is in tests/_reference/tof.py)."""
    b = layout.block
    if b == 1:
        return None
    inv = np.ascontiguousarray(scale / (math.sqrt(2.0) * np.asarray(sigma, np.float64)))
    ring = _empty((4 * b + 4, 3, layout.N), np.float32)
    _kernels.tofg_ring(g, layout.rows, layout.cols, b, inv, ring, nthreads)
    return ring


def _radiometry(tof, f):
    """(sigma_scale (F,), refl_coef (F,)) of the validity kernel: the weights of the depth
    noise and the reciprocal amplitude of a reflectance-1 surface at 1 m."""
    sensor = tof.sensor
    sigma_scale, coef = radiometry_coefficients(sensor, f)
    s1 = float(sensor.active_electrons(1.0))
    model = coef * (s1 * tof.block * tof.block)
    return sigma_scale, np.ascontiguousarray(1.0 / model)


def guided_flags(depth, sigma, flags, layout, col, cells, ring, step, max_range, nthreads,
                 usable=None, valid=None):
    """The flying-pixel test with colour edges on measurements in grid order: adds FLYING and
    RESOLVED to ``flags`` (in place); returns the depths with the resolved ones replaced.
    ``usable``: the measurements the test may use (:data:`USABLE_BITS`; None: made here);
    ``valid`` (N,) bool, when given, takes ``flags == 0`` of the final flags.

    A resolved depth is a side's, and a side may hold measurements flagged out of range (an
    aliased surface) or inconsistent: one the range test of the validity would flag (below 0,
    within 5 sigma of ``max_range`` or beyond) is flagged OUT_OF_RANGE too (H76), so that
    :func:`upsample_depth` leaves it out."""
    if usable is None:
        usable = _empty(layout.N, np.uint8)
        _kernels.tofg_usable(flags, depth, sigma, _present(layout), USABLE_BITS, usable,
                             nthreads)
    out = _empty_like(depth)
    # the resolved depths under the validity's range test in the kernel (FLAG_OUT_OF_RANGE
    # where d < 0 or d > max_range - 5 sigma)
    _kernels.tofg_flying(depth, sigma, usable, col, cells, ring, layout.R,
                         layout.C, step, 2.0, EDGE_CONTRAST, SIDE_SHARE, 1, flags, out,
                         nthreads, float(max_range),
                         None if valid is None else valid.view(np.uint8))
    return out


#: the validity bits that keep a measurement out of the flying test's sides
USABLE_BITS = FLAG_SATURATED | FLAG_LOW_SIGNAL


def _present(layout):
    """The measurements a layout's grid holds, as uint8 (None: every one)."""
    return None if layout.full else layout.present.view(np.uint8)


def guided_run(tof, p, g, scale, nthreads, f, w, max_range, unwrap_iq):
    """The chain with the colour-guided denoise (``p.denoise == "bilateral"``); ``unwrap_iq(i,
    q)`` gives depth, residual, wraps, phase and amplitude of the denoised phasors (F, N)."""
    layout = _layout_of(tof.sites, tof.block, tof.shape)
    N, F = layout.N, f.size
    taps = tof.taps
    cal = p.calibration
    saturated = np.asarray(tof.saturated, np.uint8)
    if cal is not None and cal.dark is not None:
        # the white level is the raw taps': tested before the dark offsets come off (after,
        # a clipped tap read below it, and the measurement came out valid at a wrong depth)
        saturated = saturated | (tof.taps.max(axis=(0, 1)) >= tof.white_level)
        taps = np.asarray(taps, np.float64) - cal.dark[None]
    if taps.dtype not in (np.uint16, np.float32, np.float64):
        taps = taps.astype(np.float64)
    sat = np.ascontiguousarray(layout.to_grid(saturated.astype(np.uint8), 1), np.uint8)
    if not layout.full:
        full = np.zeros(taps.shape[:2] + (N,), taps.dtype)
        full[..., layout.grid.ri * layout.C + layout.grid.ci] = taps
        taps = full
    taps = np.ascontiguousarray(taps)
    sensor = tof.sensor
    k = sensor.system_gain
    supp = collected_scale(sensor)
    const_var = k * k * (sensor.read_noise ** 2 + sensor.dsnu ** 2) + 1.0 / 12.0
    offset = _empty((F, N))
    # the colours, and with a fixed pattern (DSNU, PRNU) each measurement's share of it in
    # its variance: the range kernel's distance then knows that pattern's one error in every
    # frequency (tofg_xp in csrc/tof_guided.c)
    # (not with a calibration: it turns each frequency's phasors by its own offset before
    # the denoise, so the fixed pattern's error is no longer one offset in every frequency)
    fixed = bool(sensor.dsnu or sensor.prnu) and cal is None
    colp = _empty((4 if fixed else 3, N), np.float32)
    dn = dark_noise(cal)
    prepare = np.array([k, float(sensor.black_level), supp, const_var, prnu_gain(sensor),
                        float(tof.white_level),
                        k * k * float(sensor.dsnu) ** 2 if dn is None else dn], np.float64)
    # the use of each measurement before the prepare stage's taps at full scale (which it
    # leaves out itself)
    use = sat == 0
    if not layout.full:
        use &= layout.present
    use = use.view(np.uint8)
    zr = zi = v = None
    if cal is not None:
        # the prepare stage over the frame (taps -> phasors, their variance, offset, sat),
        # then each measurement's phasors turned by its phase offset's deviation (the ISP
        # removes it before it averages neighbours); without a calibration the denoise makes
        # the stage row by row as it reads them (no whole-frame planes of phasors)
        zr, zi = np.empty((F, N), np.float32), np.empty((F, N), np.float32)
        v = np.empty(N, np.float32)
        _kernels.tofg_prepare(taps, *prepare[:6], zr, zi, v, sat, offset, nthreads,
                              prepare[6], None)
        use &= sat == 0
        turn = np.exp(-1j * layout.to_grid(cal.deviations, 0.0))
        z = (zr + 1j * zi) * turn
        zr, zi = np.ascontiguousarray(z.real, np.float32), np.ascontiguousarray(z.imag,
                                                                                np.float32)
    col, cells, sigma_c = guide_colours(g, scale, layout, nthreads, colp[:3])
    window = p.window if p.window is not None else \
        GUIDED_WINDOW_1X1 if tof.block == 1 else GUIDED_WINDOW
    radius = (window // 2) * tof.block
    reach_r, reach_c = layout.grid.reach(radius)
    inv2h2 = 1.0 / (2.0 * p.range_scale ** 2)
    inv2hc2 = 1.0 / (2.0 * p.colour_scale ** 2)
    # the four passes (rows, columns, rows guided by the columns' output, columns) in one C
    # call, row by row through rings of a few rows: no intermediate plane of the whole frame;
    # without a calibration (whose cyclic-error correction acts on the phases) the means are
    # unwrapped there as they are made, and each unwrapped row's validity (with the fixed
    # pattern's correction of sigma) is made while the row is in the cache: the values
    # tofg_validity and tof_fixed_pattern give after the call, bit for bit but sigma (the
    # pattern's cosines from the mean phasors, within 2 ulps; tests/tof/test_guided.py)
    # n_eff comes in count's public dtype, float64, from the kernel
    var, count = _empty(N, np.float32), _empty(N)
    snr, sigma, refl = _empty(N), _empty(N), _empty(N)
    flags = _empty(N, np.uint8)
    sigma_scale, refl_coef = _radiometry(tof, f)
    limits = np.array([p.min_snr, p.min_amplitude, -1.0 if p.max_sigma is None else p.max_sigma,
                       p.max_residual, p.min_reflectance, max_range,
                       np.inf if p.max_reflectance is None else p.max_reflectance], np.float64)
    args = (zr, zi, v, colp, use, layout.rows, layout.cols, reach_r, reach_c, radius, inv2h2,
            inv2hc2)
    # the flying test's usable measurements, made with each row's validity (the same as
    # tofg_usable after it)
    usable = _empty(N, np.uint8) if p.flying_step is not None and cal is None else None
    if cal is None:
        depth, residual, wraps = _empty(N), _empty(N), _empty(N, np.int32)
        phase, amp = _empty((F, N)), _empty((F, N))
        if not _kernels.tofg_denoise(*args, None, None, var, None, nthreads,
                                     np.ascontiguousarray(f, np.float64),
                                     np.ascontiguousarray(w, np.float64), max_range, depth,
                                     residual, wraps, phase, amp, count=count, sat=sat,
                                     sigma_scale=sigma_scale, refl_coef=refl_coef,
                                     limits=limits, snr=snr, sigma=sigma, refl=refl,
                                     flags=flags, offset=offset,
                                     fixed=fixed_pattern_args(
                                         sensor, None, delay_fpn_variance(sensor, None)),
                                     taps=taps, prepare=prepare, usable=usable,
                                     present=_present(layout), usable_bits=USABLE_BITS):
            raise ValueError("taps: the averaged phasors overflow (|I|, |Q| > 1.8e308)")
    else:
        mr, mi = np.empty((F, N)), np.empty((F, N))
        _kernels.tofg_denoise(*args, mr, mi, var, None, nthreads, count=count)
        depth, residual, wraps, phase, amp = unwrap_iq(mr, mi)
        # the fixed pattern acts on the phasors in the taps' own frame (before the
        # calibration turned them); its correlation across the frequencies corrects sigma
        delta = fixed_pattern_delta(np.arctan2(mi, mr) + layout.to_grid(cal.deviations, 0.0),
                                    amp, offset, count, sensor, sigma_scale, shared=True,
                                    dark_noise=dark_noise(cal),
                                    delay_var=delay_fpn_variance(sensor, cal),
                                    workers=nthreads)
        _kernels.tofg_validity(amp, var, depth, residual, sat, sigma_scale, refl_coef,
                               *limits[:6], snr, sigma, refl, flags, nthreads, delta,
                               limits[6])
    measured = depth
    valid = None
    if p.flying_step is not None:
        valid = _empty(N, bool)                 # flags == 0, made by the flying test's rows
        depth = guided_flags(measured, sigma, flags, layout, col, cells,
                             guide_ring(g, scale, layout, sigma_c, nthreads), p.flying_step,
                             max_range, nthreads, usable=usable, valid=valid)
    back = layout.from_grid
    return ToFDepth(depth=back(depth), residual=back(residual), wraps=back(wraps),
                    phase=back(phase), amplitude=back(amp), offset=back(offset),
                    snr=back(snr), sigma=back(sigma), reflectance=back(refl),
                    count=back(count), valid=back(flags == 0 if valid is None else valid),
                    flags=back(flags), frequencies=np.asarray(tof.frequencies, np.float64).copy(),
                    sites=tuple(np.asarray(a) for a in tof.sites), block=int(tof.block),
                    shape=tuple(tof.shape), measured=back(measured))


def guided_flying_of(result, g, scale, step, max_range, nthreads):
    """The colour-guided flying-pixel test applied to a result of the unguided denoise (box or
    none) whose flying test was left out: a new ToFDepth."""
    layout = _layout_of(result.sites, result.block, result.shape)
    col, cells, sigma_c = guide_colours(g, scale, layout, nthreads)
    flags = np.ascontiguousarray(layout.to_grid(result.flags, FLAG_SATURATED), np.uint8)
    measured = np.ascontiguousarray(layout.to_grid(result.depth, np.nan), np.float64)
    sigma = np.ascontiguousarray(layout.to_grid(result.sigma, np.inf), np.float64)
    depth = guided_flags(measured, sigma, flags, layout, col, cells,
                         guide_ring(g, scale, layout, sigma_c, nthreads), step, max_range,
                         nthreads)
    back = layout.from_grid
    fields = {k: getattr(result, k) for k in result.__dataclass_fields__}
    fields.update(depth=back(depth), measured=result.depth, flags=back(flags),
                  valid=back(flags) == 0)
    return ToFDepth(**fields)


def upsample_depth(result, guide, *, colour_scale=UPSAMPLE_COLOUR_SCALE,
                   ambiguity=UPSAMPLE_AMBIGUITY, max_sigma=UPSAMPLE_MAX_SIGMA, workers=None):
    """A depth at every pixel of the frame, from the measurements guided by its colour image.

    Joint bilateral upsampling [1]_ that chooses rather than averages: a pixel
    takes the four Z measurements around it, each weighted bilinearly by its
    distance and by how close its colour is to the pixel's (in units of the
    guide's noise, as the guided denoise); the depth of the heaviest one,
    averaged with those of the four within ``max(3 sigma, 2 cm)`` of it, so a
    pixel takes the depth of one surface, never a blend across a depth edge.
    Where those more than 5 cm from that depth (another surface) hold more
    than ``ambiguity`` of the weight, the colour cannot tell which surface
    the pixel is on and it gets NaN. Valid measurements, resolved ones
    (:attr:`ToFFlag.RESOLVED`, with the depth of their side; flagged nothing
    else but flying), those flagged
    flying alone and those flagged low-signal alone with a sigma of at most
    ``max_sigma`` take part: the flying-pixel test flags both sides of every
    depth edge, and the measurements right at an edge are the ones that give
    its position (the colour picks the side); a measurement the ISP finds
    too noisy for its own 0.05 % (sigma above ``ToFISP.max_sigma``) is still
    good enough for a map that allows 0.5 % (measured on the Middlebury
    scenes, docs/reports/isp.md). A Z pixel without a usable measurement
    takes the same rule over the measurements within 1, 2 or 4 grid lines
    (Gaussian weights) at a quarter of the weight; when it has a low-signal
    measurement of its own (other flags besides, as inconsistent, count too),
    only the candidates within 2 of its sigma of that measurement, and none
    when none is (it then counts as a surface of unknown depth: the pixels
    it would win get NaN).

    Parameters
    ----------
    result : ToFDepth
        The ToF ISP's output for the frame (ideally guided by the same image).
    guide : ndarray, shape (rows, cols, 3)
        The frame's colour image: uint8 or uint16 sRGB, or float in [0, 1]
        (``ColourISP().run(frame)``).
    colour_scale : float
        Range scale ``h_c`` of the colour kernel ``exp(-max(chi_c - 3, 0) /
        (2 h_c^2))``, ``chi_c`` in units of the guide's noise (20), in
        [1e-6, 1e6].
    ambiguity : float
        The largest share of a pixel's weight the measurements off its chosen
        surface may hold (0.15); 1 gives a depth wherever a measurement reaches
        but for the pixels a low-signal measurement without an agreeing
        neighbour wins.
    max_sigma : float or None
        The largest predicted sigma (m) of a measurement flagged low-signal
        alone that takes part as a measurement (0.02); None or 0: none does
        (each then only vetoes the surfaces it disagrees with, as the other
        low-signal ones do).
    workers : int, optional
        Threads (None or -1: all cores); the result does not depend on it.

    Returns
    -------
    depth : ndarray of float32, shape (rows, cols)
        Metres; NaN where no measurement reaches.
    confidence : ndarray of float32, shape (rows, cols)
        The summed weight of the measurements the depth comes from, in
        [0, 1]: 1 where the four around the pixel are valid and of its
        colour, lower at colour edges, near unusable measurements and in
        holes (at most 0.25 there); 0 where the depth is NaN.

    The defaults were chosen on four Middlebury scenes and checked on two held
    out (docs/reports/isp.md, "Measured: full resolution").

    Raises
    ------
    TypeError, ValueError
        ``result`` that is not a ToFDepth; a ``guide`` of the wrong shape,
        2-D, not finite, or float values outside [0, 1] (the message names
        ``guide``).

    References
    ----------
    .. [1] Kopf et al., "Joint bilateral upsampling" (docs/references.bib: kopf2007jbu)

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.simulation import Scene, simulate
    >>> from rgbz_fast.isp import ColourISP
    >>> from rgbz_fast.tof import tof_depth
    >>> img = np.full((24, 32, 3), 0.4)
    >>> img[:, 16:] = (0.1, 0.5, 0.2)                         # a green box ...
    >>> z = np.where(np.arange(32) < 16, 2.0, 1.5) * np.ones((24, 1))   # ... in front
    >>> frame = simulate(Scene(img, depth=z), "mask2", noise=False)
    >>> guide = ColourISP().run(frame)
    >>> depth, conf = upsample_depth(tof_depth(frame.tof, guide=guide), guide)
    >>> depth.shape, depth[12, 12:20].round(2)              # the edge at column 16
    ((24, 32), array([2. , 2. , 2. , 2. , 1.5, 1.5, 1.5, 1.5], dtype=float32))
    """
    if not isinstance(result, ToFDepth):
        raise TypeError(f"result: expected a ToFDepth (tof_depth's output), got "
                        f"{type(result).__name__}")
    cs = check_scale(colour_scale, "colour_scale")
    amb = check_number(ambiguity, "ambiguity", lo=0, hi=1)
    max_sigma = check_number(max_sigma, "max_sigma", lo=0, allow_none=True, allow_inf=True)
    nthreads = check_workers(workers)
    g, scale = check_guide(guide, result.shape)
    layout = _layout_of(result.sites, result.block, result.shape)
    result._check_sites("result", layout.rows, layout.cols)     # the distinct rows and columns
    col, _, sigma_c = guide_colours(g, scale, layout, nthreads)
    flags = result.flags
    # valid, flying alone, resolved (and flying): a resolved measurement flagged out of range
    # or inconsistent besides is no side's depth (H76)
    rest = flags & ~np.uint8(FLAG_RESOLVED)
    usable = (rest == 0) | (rest == FLAG_FLYING)
    depth = np.ascontiguousarray(layout.to_grid(np.where(usable, result.depth, np.nan),
                                                np.nan), np.float64)
    sigma = np.ascontiguousarray(layout.to_grid(result.sigma, np.inf), np.float64)
    # the low-signal measurements' own depths: too noisy to give a depth alone, enough to
    # reject the neighbours' surfaces they disagree with; those below max_sigma that agree
    # with a usable neighbour give theirs
    low = np.ascontiguousarray(layout.to_grid(np.where(
        ((flags & FLAG_LOW_SIGNAL) > 0) & ~usable, result.depth, np.nan), np.nan), np.float64)
    if max_sigma:
        lone = layout.to_grid((flags == FLAG_LOW_SIGNAL) & (result.sigma <= max_sigma), False)
        # one that lies at a depth edge mixing the two surfaces (a 2x2 Z pixel straddling it,
        # which the flying-pixel test does not see) agrees with neither
        _kernels.tofg_agree(depth, low, np.ascontiguousarray(lone).view(np.uint8), sigma,
                            layout.R, layout.C, _UP_TOL_K, _UP_TOL_MIN, nthreads)
    own = low
    half = 0.5 * (result.block - 1)
    rc = np.ascontiguousarray(layout.rows + half, np.float64)
    cc = np.ascontiguousarray(layout.cols + half, np.float64)
    steps = np.diff(rc) if rc.size > 1 else np.diff(cc)
    spacing = float(np.median(steps)) if steps.size else 1.0
    out = _empty(result.shape, np.float32)
    conf = _empty(result.shape, np.float32)
    cscale = np.ascontiguousarray(1.0 / (math.sqrt(2.0) * sigma_c))
    _kernels.tofg_upsample(g, scale, cscale, depth, sigma, col, layout.R, layout.C, rc, cc,
                           spacing, _FILL_REACH, 1.0 / (2.0 * _FILL_SPREAD ** 2),
                           1.0 / (2.0 * cs * cs), _UP_TOL_K, _UP_TOL_MIN, own, _UP_OWN_K, amb,
                           _UP_GAP, out, conf, nthreads)
    return out, conf
