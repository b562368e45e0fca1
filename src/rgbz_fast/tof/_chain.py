"""The ToF ISP chain: taps -> depth, its noise and its validity (:func:`tof_depth`, :class:`ToFISP`).

Paper §5.1.4 and Fig. 17: the depth is computed at the Z measurements only
(no depth is interpolated at the colour sites); the paper's ISP turns its 3x3
averaging filter into a 5x5 kernel in which only the Z sites count
(``denoise="box"``). The default denoise is edge-aware instead.

Chain (:func:`tof_depth`; every stage is also a function of its own)::

    taps (F, 4, n) ─► [calibration: dark offsets, per-measurement phase offsets]
                   ─► I, Q per frequency (demodulate, phasors)
                   ─► denoise_phasors_bilateral (C; default) or denoise_phasors (the
                      paper's box), saturated measurements left out of every mean
                   ─► phase = atan2(Q, I) in [0, 2 pi) ─► [cyclic-error correction]
                   ─► unwrap (C, weights f_i^2): depth, residual, wrap count
                   ─► sigma (predicted depth noise), implied reflectance
                   ─► validity: saturated, low signal, inconsistent, flying, out of range

Without the denoise and the calibration, demodulation and unwrapping run as one
fused C pass (:func:`demodulate_unwrap`); otherwise the atan2 of the averaged
phasors and the unwrapping do.

The tap conventions are in :mod:`._stages`; the choices are explained in docs/guide/isp.md and
measured in docs/reports/isp.md.
"""

from __future__ import annotations

from dataclasses import dataclass
from dataclasses import replace as dc_replace

import numpy as np

from .. import _kernels
from .._validate import check_choice, check_number, check_workers, merge_params
from ._calibration import ToFCalibration, as_taps
from ._filters import _check_odd, check_scale, denoise_phasors_bilateral
from ._guided import _layout_of, check_guide, guided_flying_of, guided_run
from ._noise import dark_noise, delay_fpn_variance, tap_variance
from ._result import ToFDepth
from ._stages import (_check_unwrap_args, _check_window, _phasors_offset, box_mean,
                      demodulate_unwrap, unwrap)
from ._validity import FLAG_LOW_SIGNAL, validity

__all__ = ["ToFISP", "tof_depth"]


_DENOISE = ("bilateral", "box", "none")


def _check_denoise(denoise):
    """'bilateral', 'box' or 'none'; True is the default ('bilateral'), False is 'none'."""
    if isinstance(denoise, (bool, np.bool_)):
        return "bilateral" if denoise else "none"
    return check_choice(denoise, _DENOISE, "denoise")


def _check_calibration(calibration):
    if calibration is not None and not isinstance(calibration, ToFCalibration):
        raise TypeError(f"calibration: expected a ToFCalibration or None, got "
                        f"{type(calibration).__name__}")
    return calibration


@dataclass(frozen=True)
class ToFISP:
    """The parameters of the ToF ISP, checked once; :meth:`run` runs the chain with them.

    :func:`tof_depth` takes one (``params=``) and keyword overrides of its
    fields; ``ToFISP(**fields).run(tof)`` is the same call.

    Parameters
    ----------
    denoise : {"bilateral", "box", "none"}
        ``"bilateral"`` (default): the edge-aware mean of the phasors over the
        Z measurements of the window, two passes
        (:func:`~rgbz_fast.tof.denoise_phasors_bilateral`); ``"box"``: the
        paper's plain mean (Fig. 17, :func:`~rgbz_fast.tof.denoise_phasors`);
        ``"none"``. True and False mean ``"bilateral"`` and ``"none"``.
    window : int or None
        Odd window size in Z-pixel cells; None: 9 for the bilateral denoise
        (the 5x5 nearest Z measurements), 21 for the bilateral denoise with a
        guide (the 11x11 nearest, whose colour keeps the mean on one surface;
        31, the 15x15 nearest, for 1x1 Z pixels such as Mask1's, each of which
        collects a quarter of a 2x2 one's light)
        and 5 for the box (the paper's 5x5-pixel kernel: 3x3 Z measurements).
        A measurement enters when it lies within ``(window // 2) * block``
        pixels in rows and columns, so on patterns whose Z measurements are
        two cells apart (Mask1, Mask2) window 3 takes none but the centre, as
        1 does, and 7 the same 3x3 as 5. Refused with ``denoise="none"``.
    range_scale : float
        Range scale ``h`` of the bilateral weights (2; larger smooths across
        weaker edges), in [1e-6, 1e6].
    colour_scale : float
        With a guide: range scale ``h_c`` of the colour weights
        ``exp(-max(chi_c - 3, 0) / (2 h_c^2))``, ``chi_c`` the colour
        difference of two measurements in units of the guide's noise (5: a
        colour step of a few noise levels, texture, still averages; a colour
        edge does not), in [1e-6, 1e6]. Without a guide it is not used.
    min_snr : float
        Smallest per-frequency ``|I + iQ| / sigma_I`` of a valid measurement
        (4: on noisy walls the unwrapping errs on 0.07 % of the measurements
        at SNR 4-5 and on 1 of 154 000 above 5, see docs/reports/isp.md).
    min_amplitude : float
        Smallest per-frequency amplitude (DN) of a valid measurement (0: only
        the SNR test).
    max_residual : float
        Largest unwrapping residual (m) of a valid measurement (0.15: a wrong
        wrap combination of 80/100/120 MHz leaves about 0.17 m or more).
        Retune it for other frequency sets.
    max_sigma : float or None
        Largest predicted depth noise (m) of a valid measurement (0.015: a
        5 cm error is then a 3.3-sigma event, 0.1 % of the valid
        measurements); None: no limit.
    flying_step : float or None
        Depth jump (m) that marks a discontinuity (0.05; see
        :func:`~rgbz_fast.tof.flying_pixels`); None: no flying-pixel test.
    min_reflectance : float
        Smallest NIR reflectance a valid measurement may imply (0.05; 0: no
        test). Depths beyond the unambiguous range alias to shorter ones and
        imply much darker surfaces (:func:`tof_depth`, Notes).
    max_reflectance : float or None
        Largest NIR reflectance a valid measurement may imply (4; None: no
        test, at least 1). A depth unwrapped to a wrong, farther alias implies
        a surface ``(D_alias / D)^2`` times brighter than it is: with a
        frequency set whose aliases lie close in phase (80/100/120.1 MHz) a
        0.8 m wall read valid at 8.3 m (reflectance 54) and 1492 m. A
        Lambertian surface implies at most 1; the margin keeps glossy
        surfaces facing the sensor and a radiometric model off by a few
        times; retroreflectors and mirrors (far above) need None.
    max_range : float or None
        Unwrapping range in metres (see :func:`~rgbz_fast.tof.unwrap`); None:
        the taps' unambiguous range, unless that spans more than
        :data:`~rgbz_fast.tof.MAX_WRAPS` wraps of the lowest frequency (nearly
        coprime frequencies), in which case a ValueError naming
        ``frequencies`` asks for an explicit one; at most the unambiguous
        range. Depths found beyond it are flagged out of range.
    calibration : ToFCalibration or None
        Per-measurement phase offsets and per-frequency cyclic error
        (:func:`~rgbz_fast.tof.calibrate`), and the taps' dark offsets when
        it holds them. It must have been made for these frequencies and Z
        measurements.
    low_signal_window : int or None
        An odd window for the measurements the ISP flags low-signal alone:
        the chain runs twice, and such a measurement takes the wider
        window's result where its depth agrees with the first's within the
        first's sigma (None: one run). For photon-limited scenes: on the
        Middlebury 2005 scene art, Mask1 guided, 41 keeps 88.1 % of the
        measurements valid instead of 85.7 %, 0.040 % valid and more than
        5 cm off, where a window of 41 for every measurement flags textured
        slanted surfaces (docs/reports/isp.md); twice the time.

    Examples
    --------
    >>> isp = ToFISP(denoise="box")
    >>> isp.window, isp.replace(min_snr=3).min_snr
    (None, 3.0)
    >>> ToFISP(window=4)
    Traceback (most recent call last):
    ...
    ValueError: window: expected an odd positive integer (5 = the paper's 5x5 kernel), got 4
    """

    denoise: str | bool = "bilateral"
    window: int | None = None
    range_scale: float = 2.0
    colour_scale: float = 5.0
    min_snr: float = 4.0
    min_amplitude: float = 0.0
    max_residual: float = 0.15
    max_sigma: float | None = 0.015
    flying_step: float | None = 0.05
    min_reflectance: float = 0.05
    max_range: float | None = None
    calibration: ToFCalibration | None = None
    low_signal_window: int | None = None
    max_reflectance: float | None = 4.0

    def __post_init__(self):
        put = object.__setattr__
        put(self, "denoise", _check_denoise(self.denoise))
        if self.window is not None:
            put(self, "window", _check_window(self.window))
        put(self, "range_scale", check_scale(self.range_scale, "range_scale"))
        put(self, "colour_scale", check_scale(self.colour_scale, "colour_scale"))
        put(self, "min_snr", check_number(self.min_snr, "min_snr", lo=0))
        put(self, "min_amplitude", check_number(self.min_amplitude, "min_amplitude", lo=0))
        put(self, "max_residual", check_number(self.max_residual, "max_residual", lo=0,
                                               lo_open=True))
        put(self, "max_sigma", check_number(self.max_sigma, "max_sigma", lo=0, lo_open=True,
                                            allow_none=True))
        put(self, "flying_step", check_number(self.flying_step, "flying_step", lo=0,
                                              lo_open=True, allow_none=True))
        put(self, "min_reflectance", check_number(self.min_reflectance, "min_reflectance",
                                                  lo=0, hi=1))
        put(self, "max_range", check_number(self.max_range, "max_range", lo=0, lo_open=True,
                                            allow_none=True))
        put(self, "calibration", _check_calibration(self.calibration))
        if self.low_signal_window is not None:
            put(self, "low_signal_window", _check_odd(self.low_signal_window,
                                                      "low_signal_window"))
        if self.denoise == "none":
            # a window without a denoise had run the chain (twice, with low_signal_window)
            # and changed nothing
            for name in ("window", "low_signal_window"):
                if getattr(self, name) is not None:
                    raise ValueError(f"{name}: sets the denoise's window, and denoise='none' "
                                     "averages nothing; give a denoise or leave it out")
        put(self, "max_reflectance", check_number(self.max_reflectance, "max_reflectance",
                                                  lo=1, allow_none=True))

    @property
    def _window_cells(self):
        """The window the denoise runs with: ``window``, or 9 (bilateral) / 5 (box) if None."""
        if self.window is not None:
            return self.window
        return 9 if self.denoise == "bilateral" else 5

    def replace(self, **changes):
        """A copy with some fields changed (and checked)."""
        return merge_params(ToFISP, self, changes, caller="replace()")

    def run(self, tof, *, guide=None, workers=None):
        """Depth, amplitude and validity of every Z measurement of ``tof`` (a ToFTaps or a
        RawFrame with taps); ``guide``: the frame's colour image (:func:`tof_depth`);
        ``workers``: threads of the C kernels."""
        return _run(as_taps(tof, "tof"), self, check_workers(workers), guide)


def _with_low_signal_window(tof, p, nthreads, guide):
    """The chain twice, at ``p``'s window and at ``p.low_signal_window``: a measurement the
    first flags low-signal alone takes the second's result where the two depths agree within
    the first's sigma (docs/reports/isp.md, "The guided ISP on photon-limited scenes")."""
    from ._guided import GUIDED_WINDOW, GUIDED_WINDOW_1X1

    window = p.window if p.window is not None else \
        p._window_cells if guide is None or p.denoise != "bilateral" else \
        GUIDED_WINDOW_1X1 if tof.block == 1 else GUIDED_WINDOW
    if p.low_signal_window <= window:
        # a second run at the same window changed nothing, at a narrower one it gave the
        # low-signal measurements less than the first (the guided default of 1x1 Z pixels
        # is 31 since 2026-11-27)
        raise ValueError(f"low_signal_window: {p.low_signal_window} is not wider than the "
                         f"window the chain runs with here ({window}"
                         f"{', with the guide' if guide is not None else ''}); give a "
                         "wider one")
    base = _run(tof, dc_replace(p, low_signal_window=None), nthreads, guide)
    wide = _run(tof, dc_replace(p, window=p.low_signal_window, low_signal_window=None),
                nthreads, guide)
    with np.errstate(invalid="ignore"):
        take = (base.flags == FLAG_LOW_SIGNAL) & (np.abs(wide.depth - base.depth)
                                                  <= base.sigma)
    fields = {}
    for name in base.__dataclass_fields__:
        a, b = getattr(base, name), getattr(wide, name)
        if isinstance(a, np.ndarray) and a.ndim >= 1 and a.shape[-1] == take.size \
                and name not in ("frequencies",):
            a = np.where(take, b, a).astype(a.dtype, copy=False)
        fields[name] = a
    return ToFDepth(**fields)


def tof_depth(tof, *, params=None, guide=None, workers=None, **options):
    """The ToF ISP: taps of every Z measurement -> depth, amplitude, validity.

    Parameters
    ----------
    tof : ToFTaps or RawFrame
        The taps (``frame.tof`` of :func:`rgbz_fast.simulate`). The noise
        model and the radiometry use ``tof.sensor`` (system gain, read noise,
        DSNU, PRNU, black level, ambient suppression; source power, lens,
        pixel): the ISP is calibrated for its sensor.
    params : ToFISP or dict, optional
        The parameters (default ``ToFISP()``; a dict holds some of its
        fields).
    guide : ndarray, shape (rows, cols, 3), optional
        The frame's own colour image (``ColourISP().run(frame)``: uint8 or
        uint16 sRGB, or float in [0, 1]). The bilateral denoise then also
        weighs neighbours by colour similarity (window 21 by default, 31 for 1x1
        Z pixels) and the flying-pixel test uses colour edges, resolving mixed
        measurements to their side (:mod:`rgbz_fast.tof` guide, docs/guide/isp.md). None: the
        unguided ISP.
    workers : int, optional
        Threads of the C kernels (None or -1: all cores). The result does
        not depend on it.
    **options
        Fields of :class:`ToFISP` (``denoise="box"``, ``min_snr=3``,
        ``calibration=cal``, ...), applied over ``params``: ``denoise``,
        ``window``, ``range_scale``, ``colour_scale``, ``min_snr``, ``min_amplitude``,
        ``max_residual``, ``max_sigma``, ``flying_step``, ``min_reflectance``,
        ``max_range``, ``calibration``.

    Returns
    -------
    ToFDepth

    Raises
    ------
    ValueError, TypeError
        A frame without taps, malformed taps, an unknown option, thresholds
        out of range, a calibration of another sensor layout, a ``max_range``
        the unwrapping cannot search (:class:`ToFISP`), or a ``guide`` that
        is not the frame's colour image (wrong shape, 2-D, NaN, floats beyond
        [0, 1]).

    Notes
    -----
    Validity. A measurement is flagged

    * saturated when a tap reached the white level at some frequency, or
      the sensor flagged it (``tof.saturated``): its phase is biased;
    * low-signal when ``snr < min_snr``, the amplitude is below
      ``min_amplitude`` at some frequency, or ``sigma > max_sigma``.
      ``snr = |I + iQ| / sigma_I`` with ``sigma_I^2`` the variance of the
      (averaged) component: ``2 var(A)`` per measurement, ``var(A) = K^2 c +
      K^2 (read^2 + dsnu^2) + 1/12 + (prnu K c)^2`` (shot noise and PRNU of
      the charge ``c`` the tap collected, ``e / (1 - s)`` of the ``e`` it holds
      after an ambient suppression ``s``; read noise, DSNU, quantisation; in
      DN^2), through the denoise's weights;
      ``sigma`` is the depth noise of the unwrapping's weighted mean, with
      the DSNU and PRNU correlated across the frequencies (one offset and
      gain per tap; a calibration's dark frame takes the DSNU off and leaves
      its own error, ``meta["dark_noise_dn2"]``), and without a calibration
      the per-pixel delay pattern (``(c delay_fpn / 2)^2``);
    * inconsistent when the unwrapping residual exceeds ``max_residual``:
      the frequencies disagree (a wrong unwrap, a mixed return);
    * flying when the depth jumps by more than ``max(flying_step, 2 sigma)``
      within one Z measurement of it (second differences along rows, columns
      and diagonals, usable measurements only; slopes do not count): the
      measurement may mix the two surfaces of a depth edge;
    * out of range when the depth is < 0 or beyond ``max_range - 5 sigma``
      (a guard: a surface just beyond the range reads either ~0 m or, through
      the noise, just below the end), or the implied reflectance is below
      ``min_reflectance`` or above ``max_reflectance`` (a wrong, farther alias
      of the unwrapping implies a surface far brighter than any). A surface at ``D``
      beyond the unambiguous range ``U`` gives the phases of ``D - kU`` at
      every frequency -- no test on the phases can see it -- but its
      amplitude is that of a surface ``((D - kU) / D)^2`` times darker: with
      ``rho <= 1`` every ``D < U / (1 - sqrt(min_reflectance))`` (9.66 m for
      80/100/120 MHz and 0.05) is flagged; farther ones only when their signal
      is too low to be valid (docs/reports/isp.md measures both).

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.simulation import Scene
    >>> from rgbz_fast.simulation import simulate
    >>> scene = Scene(np.full((16, 16, 3), 0.5), depth=np.full((16, 16), 1.5))
    >>> result = tof_depth(simulate(scene, "mask1", noise=False).tof)
    >>> bool(np.allclose(result.depth, 1.5, atol=2e-3)), bool(result.valid.all())
    (True, True)
    >>> tof_depth(simulate(scene, "mask1").tof, params=ToFISP(denoise="box"), min_snr=3)
    ToFDepth(64 measurements, block 1, 60 valid)
    """
    tof = as_taps(tof, "tof")
    params = merge_params(ToFISP, params, options, caller="tof_depth()")
    return _run(tof, params, check_workers(workers), guide)


def _unwrap_phasors(i, q, f, w, max_range, calibration, nthreads):
    """Depth, residual, wraps, phase and amplitude of (denoised) phasors (F, n): atan2,
    amplitude and unwrapping in one C pass, or with a calibration atan2 and amplitude, the
    cyclic-error correction of the phase, then the unwrapping."""
    n = i.shape[1]
    phase, amp = np.empty_like(i), np.empty_like(i)
    i, q = np.ascontiguousarray(i), np.ascontiguousarray(q)
    if calibration is None:
        depth, residual, wraps = np.empty(n), np.empty(n), np.empty(n, np.int32)
        ok = _kernels.tof_depth_iq(i, q, f, w, max_range, depth, residual, wraps, phase, amp,
                                   workers=nthreads)
    else:
        ok = _kernels.tof_phase_iq(i, q, phase, amp, nthreads)
    if not ok:
        raise ValueError("taps: the averaged phasors overflow (|I|, |Q| > 1.8e308)")
    if calibration is not None:
        phase = calibration.correct_phase(phase)
        depth, residual, wraps = unwrap(phase, f, max_range=max_range, workers=nthreads)
    return depth, residual, wraps, phase, amp


def _run(tof, p, nthreads, guide=None):
    """The chain on checked taps with checked parameters ``p`` (a ToFISP)."""
    if p.low_signal_window is not None:
        return _with_low_signal_window(tof, p, nthreads, guide)
    if guide is not None:
        return _run_guided(tof, p, nthreads, guide)
    denoise, window, calibration = p.denoise, p._window_cells, p.calibration
    taps = tof.taps
    n = tof.n_sites
    sensor = tof.sensor
    f, w, max_range = _check_unwrap_args(taps.shape[0], tof.frequencies, None, p.max_range)
    if calibration is not None:
        calibration.check(tof)
    # max over the 4F taps (uint16 reductions), then one comparison: = any(tap >= white)
    saturated = np.asarray(tof.saturated, bool) | (taps.max(axis=(0, 1)) >= tof.white_level)
    if calibration is not None and calibration.dark is not None:
        taps = np.asarray(taps, np.float64) - calibration.dark[None]
    grid = None                     # the grid of the Z measurements, built once when needed

    def site_grid():                # kept for a ToFTaps' own (read-only) sites: _layout_of
        return _layout_of(tof.sites, tof.block, tof.shape).grid

    dark = dark_noise(calibration)      # the fixed offset a dark frame leaves, or None
    if denoise == "none" and calibration is None:
        depth, residual, wraps, phase, amp, offset = demodulate_unwrap(
            taps, f, max_range=max_range, workers=nthreads)
        count = np.ones(n)
        var = tap_variance(offset, sensor, scale=2.0, workers=nthreads)
        fixed_pattern = (phase, offset, None, dark, delay_fpn_variance(sensor, None))
    else:
        # one pass over the taps in NumPy (I, Q and the offset exactly as the C kernel
        # computes them), the calibration's offsets, the mean over the window, then one C
        # pass from the phasors
        i, q, offset = _phasors_offset(taps, nthreads)
        if calibration is not None:
            z = (i + 1j * q) * np.exp(-1j * calibration.deviations)
            i, q = np.ascontiguousarray(z.real), np.ascontiguousarray(z.imag)
        fp_offset = offset                 # the offset the fixed pattern scales
        if denoise == "box":
            grid = site_grid()
            # box_mean: denoise_phasors without its checks (these phasors come from taps
            # checked finite and within TAP_MAX)
            i, q, count, (off_mean,) = box_mean(
                np.ascontiguousarray(i, np.float64), np.ascontiguousarray(q, np.float64),
                grid, tof.block, _check_window(window), ~np.asarray(saturated, bool),
                [np.ascontiguousarray(offset, np.float64)], nthreads)
            noise_offset = np.where(count > 0, off_mean, offset)
            var = tap_variance(noise_offset, sensor, scale=2.0, count=count, workers=nthreads)
            fp_offset = noise_offset
        elif denoise == "bilateral":
            var = tap_variance(offset, sensor, scale=2.0, workers=nthreads)
            grid = site_grid()
            i, q, var, count = denoise_phasors_bilateral(
                i, q, var, grid, block=tof.block, window=window, use=~saturated,
                range_scale=p.range_scale, workers=nthreads)
        else:
            count = np.ones(n)
            var = tap_variance(offset, sensor, scale=2.0, workers=nthreads)
        depth, residual, wraps, phase, amp = _unwrap_phasors(i, q, f, w, max_range,
                                                             calibration, nthreads)
        # the fixed pattern acts on the phasors in the taps' own frame: before the
        # calibration turned them by its deviations
        fp_phase = phase if calibration is None else \
            np.arctan2(q, i) + calibration.deviations
        fixed_pattern = (fp_phase, fp_offset, count, dark,
                         delay_fpn_variance(sensor, calibration))
    snr, sigma, reflectance, flags = validity(
        depth, residual, amp, var, saturated, sensor, tof.block, f,
        grid if grid is not None else site_grid,
        min_snr=p.min_snr, min_amplitude=p.min_amplitude, max_sigma=p.max_sigma,
        max_residual=p.max_residual, flying_step=p.flying_step,
        min_reflectance=p.min_reflectance, max_range=max_range, workers=nthreads,
        fixed_pattern=fixed_pattern, max_reflectance=p.max_reflectance)
    return ToFDepth(depth=depth, residual=residual, wraps=wraps, phase=phase, amplitude=amp,
                    offset=offset, snr=snr, sigma=sigma, reflectance=reflectance, count=count,
                    valid=flags == 0, flags=flags,
                    frequencies=np.asarray(tof.frequencies, np.float64).copy(),
                    sites=tuple(np.asarray(a) for a in tof.sites), block=int(tof.block),
                    shape=tuple(tof.shape))


def _run_guided(tof, p, nthreads, guide):
    """The chain with the frame's colour image: the guided denoise (``"bilateral"``) or the
    unguided one, then the flying-pixel test with colour edges."""
    g, scale = check_guide(guide, tof.shape)
    f, w, max_range = _check_unwrap_args(tof.taps.shape[0], tof.frequencies, None, p.max_range)
    if p.calibration is not None:
        p.calibration.check(tof)
    if p.denoise == "bilateral":
        return guided_run(tof, p, g, scale, nthreads, f, w, max_range,
                          lambda i, q: _unwrap_phasors(i, q, f, w, max_range, p.calibration,
                                                       nthreads))
    res = _run(tof, dc_replace(p, flying_step=None), nthreads)
    if p.flying_step is None:
        return res
    return guided_flying_of(res, g, scale, p.flying_step, max_range, nthreads)
