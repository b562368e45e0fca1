"""Missing-colour reconstruction at the Z sites: RGB-Z frame -> full Bayer CFA.

References
----------
.. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", section 4, eqs. 2-19 and Table 1 (docs/references.bib: rebiere_rgbz)
.. [2] Shi et al., the reconstruction of the missing rows, eqs. 1a-1e of [1] (docs/references.bib: shi_rgbz)
"""

from __future__ import annotations

import contextvars
from contextlib import contextmanager
from functools import lru_cache

import numpy as np

from .. import _kernels
from .._frame import RawFrame, frame_inputs, raw_clip_level
from .._validate import check_choice, check_workers, kernel_threads
from ._fixed import check_fixed_call, run_fixed
from ._fixed_config import check_fields_used, named_fixed_point
from ._fixed_learned import run_fixed_learned
from ._learned import resolve_filters
from ._z_guided import learned_only, resolve_z_filters
from ._z_guided_kernel import guide_source, run_z_guided
from ._params import ReconstructParams, check_domain, warn_small_sigma
from ._plans import METHODS as PLAN_METHODS
from ._plans import build_plans, check_layout

__all__ = ["reconstruct", "METHODS"]

#: every method of :func:`reconstruct`: the plan interpreter's, then the learned filters,
#: then the learned filters guided by the Z pixels' amplitude (``NEEDS_TOF``)
METHODS = (*PLAN_METHODS, "learned", "z_guided")

check_layout(_kernels.plan_layout())

#: the kernels' codes of the precisions and exponentials: {name: code}, from the C enums
#: rgbz_precision and rgbz_exp_mode (csrc/rgbz.h)
_PRECISION_CODES = dict(_kernels.PRECISIONS)
_EXP_CODES = dict(_kernels.EXP_MODES)
#: whether reconstruct() may run the interior sites of Mask1 on the constant plans of
#: csrc/recon_mask1.h (the Mask1 fast path), and SG's Mask2 plans as the straight-line code
#: of csrc/recon_mask2.h, where they apply: False inside :func:`plans_only`, in that thread
#: (or task) only
_FAST_PATH = contextvars.ContextVar("rgbz_fast_mask1_fast_path", default=True)


@contextmanager
def plans_only():
    """Within the block, :func:`reconstruct` runs every Z site on the plans of ``_plans.py``.

    The Mask1 fast path (csrc/recon_mask1.h) is a faster formulation of the
    same plans, equal to them within rounding, and SG on Mask2 runs its plans
    as straight-line code (csrc/recon_mask2.h: float32, the fast exponential),
    equal to them bit for bit; this lets a test run the interpreter they stand
    in for. Only the calling thread is affected, and the
    fast path is back when the block exits, also on an exception.
    """
    token = _FAST_PATH.set(False)
    try:
        yield
    finally:
        _FAST_PATH.reset(token)


def has_mask1_geometry(pattern):
    """True for a 2x2 tile whose single Z site stands in for a green (Mask1, any phase)."""
    if pattern.period != (2, 2) or int((pattern.tile == 3).sum()) != 1:
        return False
    return pattern.bayer_phase is not None and int(
        pattern.bayer_tile()[pattern.tile == 3][0]) == 1


def runs_mask1_fast_path(pattern, method, domain):
    """True where :func:`reconstruct` runs the Mask1 fast path (csrc/recon_mask1.h): a Mask1
    geometry, a plan method other than ``edi_rows``, the intensity domain, outside
    :func:`plans_only`. With a clip level too: the sites with a clipped tap are computed
    again by the clipped-pixel rule on the plans of _plans.py (csrc/recon_loop.template.h)."""
    return bool(_FAST_PATH.get() and domain == "intensity"
                and method != "edi_rows" and has_mask1_geometry(pattern))


@lru_cache(maxsize=128)
def _plans_for(pattern, method, sg_mode, domain):
    plan_map, plans = build_plans(pattern, method, sg_mode, domain)
    plan_map.setflags(write=False)
    raw = plans.view(np.uint8).reshape(-1)
    raw.setflags(write=False)
    return plan_map, raw, len(plans)


def _check_out(out, data):
    """A new output array, or ``out`` after checking it can take the result of ``data``."""
    if out is None:
        return np.empty(data.shape, data.dtype)
    if not isinstance(out, np.ndarray):
        raise TypeError(f"out: expected a numpy array, got {type(out).__name__}")
    if out.shape != data.shape or out.dtype != data.dtype:
        raise ValueError(f"out: expected shape {data.shape} and dtype {data.dtype}, got "
                         f"shape {out.shape} and dtype {out.dtype}")
    if not out.flags.c_contiguous or not out.flags.writeable:
        raise ValueError("out: expected a C-contiguous, writeable array")
    if np.may_share_memory(out, data):
        raise ValueError("out: overlaps the input frame; pass a separate array")
    return out


def reconstruct(frame, method="sg", *, params=None, pattern=None, bit_depth=None, workers=None,
                out=None, nir=None, tof=None, **options):
    """Fill in the colour missing at every Z site: RGB-Z raw frame -> full Bayer CFA.

    Parameters
    ----------
    frame : RawFrame or ndarray, shape (rows, cols)
        The raw frame. A plain array needs ``pattern`` (and ``bit_depth`` if
        not 11). uint8, uint16, float32 and float64 are read directly.
    method : {"sg", "edi_line", "edi_central", "bi", "bilinear", "edi_rows", "learned", "z_guided"}
        * ``"bilinear"``: mean of the same-colour known pixels of the 5x5
          window (the baseline).
        * ``"bi"``: bilateral interpolation, eqs. 2-5 (sigma = 1).
        * ``"edi_central"``: edge-directed, gradients by central symmetry over
          four non-overlapping areas, eqs. 6-7 (Fig. 7).
        * ``"edi_line"``: edge-directed, gradients along the kernel's symmetry
          axes, eqs. 8-13 (Fig. 9).
        * ``"sg"``: semi-gradients, eqs. 14-19 (Figs. 13, 15). On Mask1 the
          weights are the semi-gradients alone, as in the paper; on Mask2 and
          other patterns they multiply the EDILine weights (see Notes).
        * ``"edi_rows"``: Shi et al.'s five-direction method for row
          patterns, eqs. 1a-1e.
        * ``"learned"``: not the paper's: one linear filter of the 7x7
          window's known pixels per (Z site of the tile, bucket of a cheap
          gradient hash), fitted by least squares on a training set
          (``filters``; by default the ones shipped for Mask1 and Mask2,
          fitted on CBSD68). docs/guide/learned.md.
        * ``"z_guided"``: ``"learned"`` plus a few weights on the NIR
          amplitude the Z pixels measured around the site (the frame's ToF
          taps, or ``nir``); docs/guide/z_guided.md. Its filters are given
          with ``filters`` (:func:`~rgbz_fast.reconstruction.train_z_guided`).
    params : ReconstructParams, optional
        How to compute: precision, the sigma floors of eq. 7, the SG mode, the
        exponential, the domain, the clip level, the learned filters (see
        :class:`~rgbz_fast.ReconstructParams`). Default ``ReconstructParams()``.
    pattern : Pattern or str, optional
        The pattern of a plain-array frame.
    bit_depth : int, optional
        Bits of a plain-array frame (default 11). Outputs are clipped to
        [0, 2**bit_depth - 1].
    workers : int, optional
        Threads at most (rows are split across them). None or -1: all cores.
        A frame gets one thread per 2**18 pixels at most (a smaller frame takes
        longer to start a thread than to compute). The result is identical for
        every value. ``precision="fixed"`` streams the frame through one
        model, as a chip does: one thread.
    out : ndarray, optional
        Where to write the result: C-contiguous, writeable, the frame's shape
        and dtype, not overlapping the frame. On an error nothing is written
        to it. (Reusing a buffer bounds the memory of a stream of frames; it
        was not measurably faster than a new output on Linux, 12-megapixel
        frames: docs/reports/benchmarks.md.)
    nir : ndarray, shape (rows, cols), optional
        ``"z_guided"`` only (other methods do not read it): the NIR image the
        Z pixels saw, any positive scale, read at the Z sites only (the mean
        of the four sites of a 2x2 Z pixel). Default: the amplitude of the
        frame's ToF taps (``frame.tof``); a frame without taps needs it.
    tof : ToFTaps, optional
        ``"z_guided"`` only: the ToF taps of a plain-array frame (what a
        :class:`~rgbz_fast.RawFrame` carries as ``frame.tof``; an ISP stage
        that works on the CFA alone passes them so). Default: ``frame.tof``.
    **options
        Fields of :class:`~rgbz_fast.ReconstructParams` (``precision="float64"``,
        ``sigma_rel=0``, ``filters="my_filters.npz"``, ...), applied over
        ``params``.

    Returns
    -------
    cfa : ndarray, shape (rows, cols)
        The full Bayer CFA of the underlying Bayer phase, same dtype as the
        input: colour sites copied unchanged, Z sites reconstructed (integer
        types rounded half up). ``out`` itself when given.

    Raises
    ------
    ValueError
        Unknown method or option, a method that does not apply to the
        pattern, a frame smaller than one period, values beyond the bit depth,
        NaN or inf, a ``clip_level`` that is not a positive finite number,
        ``"learned"`` filters fitted for another pattern or bit depth (or none
        shipped for this one); with ``precision="fixed"``, a method it does not
        model, a frame wider than its line buffers, widths of ``fixed_point``
        that cannot hold a register of this plan and bit depth.
    TypeError
        A ``clip_level`` that is not a number, None or ``"auto"``; a float frame
        with ``precision="fixed"``.

    Notes
    -----
    Every missing pixel is a weighted mean of the *candidates*, the known
    pixels of its colour in the 5x5 window (4 on Mask1; 11 for green and 8
    for red/blue on Mask2):

    .. math:: I(p, q) = \\sum_k \\omega'_k I_k, \\quad
              \\omega'_k = \\omega_k / \\sum_m \\omega_m \\quad (12, 13)

    with :math:`\\omega = \\alpha\\beta` (BI, eq. 2),
    :math:`\\omega = \\alpha\\beta\\gamma(ori)` (EDI, eq. 6) and, for SG on
    Mask1, :math:`\\omega_6 = SG_N + SG_W + SG_{NW}` etc. (eq. 19, each SG
    discriminated by eq. 7). :math:`\\gamma = \\exp(-G^2 / 2\\sigma^2)` with
    :math:`\\sigma` the smallest gradient, floored at ``sigma_floor`` and at
    ``sigma_rel`` times the mean gradient (0.5 by default; ``sigma_rel=0`` is eq. 7 as
    printed, :meth:`ReconstructParams.paper` the paper-literal preset); if every
    weight underflows the plain mean is used. The Mask2 SG variant, which the
    paper does not spell out, is
    :math:`\\omega = \\alpha\\beta\\gamma_{line}(ori)\\,\\overline{SG}(pos)`:
    EDILine's weights times the mean of the discriminated semi-gradients
    covering the candidate's position (12 exponentials, as in Table 1).
    Every choice made where the paper is vague is in docs/guide/interpretation.md.

    Borders are extended by whole pattern periods, so that every kernel pixel
    keeps its colour.

    Examples
    --------
    >>> import numpy as np
    >>> import rgbz_fast as rz
    >>> img = np.full((8, 8, 3), 128, np.uint8)
    >>> frame = rz.mosaic(img, rz.mask1())
    >>> cfa = rz.reconstruct(frame, "sg")
    >>> cfa.dtype, int(cfa[0, 0]), bool(np.all(cfa == cfa[1, 1]))
    (dtype('uint16'), 1028, True)
    """
    named = named_fixed_point(params, options)
    params = ReconstructParams.build(params, options)
    data, pattern, bd = frame_inputs(frame, pattern, bit_depth)
    method = check_choice(method, METHODS, "method")
    if params.precision == "fixed":
        # fields named for this call that the method's datapath does not read: refused, as
        # hardware_cost and the command line refuse them (a design's FixedPointConfig object
        # may carry other methods' fields)
        check_fields_used(method, named)
    elif named is not None:
        # named for a float run it had been ignored: the float kernels ran with no word (a
        # ReconstructParams object carrying a design's configuration into a float reference
        # run is taken)
        raise ValueError(f"fixed_point: the fixed-point model's widths and tables "
                         f"(precision='fixed'); precision={params.precision!r} runs the "
                         f"float kernels")
    nthreads = check_workers(workers)
    clip = _resolve_clip(params.clip_level, frame)
    out = _check_out(out, data)
    if pattern.bayer_phase is None:
        # before the Bayer frame's shortcut: RR/RR had come back as "the full Bayer CFA"
        raise ValueError(f"pattern: tile {pattern.tile_string!r} fits no Bayer phase, so "
                         + ("its Z sites stand in for no defined colour" if pattern.has_z
                            else "it is no Bayer CFA to return"))
    if not pattern.has_z:
        out[...] = data
        return out
    src = np.ascontiguousarray(data)
    if params.precision == "fixed":
        check_fixed_call(src, pattern, method)
        if method == "learned":
            filters = resolve_filters(learned_only(params.filters), pattern)
            return run_fixed_learned(src, out, pattern, filters, params.fixed_point, bd)
        return run_fixed(src, out, pattern, method, params, bd)
    warn_small_sigma(params, method)
    check_domain(method, params.domain)          # the plan methods' in build_plans too
    if method == "learned":
        filters = resolve_filters(learned_only(params.filters), pattern)
        _refuse_clipped("learned", src, pattern, clip)
        run_learned(src, out, pattern, filters, params.precision, bd, nthreads)
        return out
    if method == "z_guided":
        filters = resolve_z_filters(params.filters, pattern, bd)
        if tof is None and isinstance(frame, RawFrame):
            tof = frame.tof
        grids = guide_source(src.shape, pattern, nir=nir, tof=tof, workers=nthreads)
        _refuse_clipped("z_guided", src, pattern, clip)
        run_z_guided(src, out, pattern, filters, grids, params.precision, bd, nthreads)
        return out
    plan_map, plans, n_plans = _plans_for(pattern, method, params.sg_mode, params.domain)
    if clip is not None and not _reaches(src, pattern, clip):
        clip = None          # nothing clipped: exactly the clip_level=None call
    _run_kernel(src, out, pattern, method, params, plan_map, plans, n_plans, bd, clip,
                kernel_threads(nthreads, src.size))
    return out


def _refuse_clipped(method, src, pattern, clip):
    """The filter methods have no clipped-pixel rule: refuse a frame that reaches ``clip``."""
    if clip is not None and _reaches(src, pattern, clip):
        raise ValueError(f"clip_level: method {method!r} has no clipped-pixel rule; the frame "
                         f"reaches the clip level {clip:g}, use another method or "
                         "clip_level=None")


def _run_kernel(src, out, pattern, method, params, plan_map, plans, n_plans, bit_depth, clip,
                nthreads, opcounts=None, kernels=None):
    """One call of the C reconstruction (``kernels``: the counting extension for opcount)."""
    fast = int(runs_mask1_fast_path(pattern, method, params.domain)
               and (kernels is None or clip is None))     # the counting module: one or other
    k = _kernels if kernels is None else kernels
    extra = {} if opcounts is None else {"opcounts": opcounts}
    k.reconstruct(src, out, _PRECISION_CODES[params.precision], pattern.period[0],
                  pattern.period[1], plan_map, plans, n_plans, params.sigma_floor,
                  params.sigma_rel, params.edge_ratio, float((1 << bit_depth) - 1),
                  _EXP_CODES[params.exp_mode], nthreads, mask1_fast=fast, clip_level=clip,
                  mask2_fast=int(_FAST_PATH.get()), **extra)


def run_learned(src, out, pattern, filters, precision, bit_depth, nthreads, opcounts=None,
                kernels=None):
    """One call of the learned kernel (csrc/learned.c); ``kernels``: the counting extension."""
    P, Q = pattern.period
    plan_map = np.full(P * Q, -1, np.int32)
    for k, ph in enumerate(filters.geometry):
        r, c = ph["rc"]
        plan_map[r * Q + c] = k
    k = _kernels if kernels is None else kernels
    extra = {} if opcounts is None else {"opcounts": opcounts}
    k.learned(src, out, _PRECISION_CODES[precision], P, Q, plan_map,
              maxval=float((1 << bit_depth) - 1), workers=nthreads,
              **filters.kernel_arrays(bit_depth),
              **extra)


def _resolve_clip(value, frame):
    """The clip level of a call: ``"auto"`` resolved from the frame's raw metadata."""
    if value == "auto":
        return raw_clip_level(frame) if isinstance(frame, RawFrame) else None
    return value


def _reaches(data, pattern, level):
    """True if a colour site of ``data`` is at or above ``level`` (strided views, no copy)."""
    if data.size and data.dtype.kind in "ui" and not data.max() >= level:
        return False          # one contiguous pass (Z sites too) settles most frames
    P, Q = pattern.period
    for r in range(P):
        for c in range(Q):
            if pattern.tile[r, c] != 3 and r < data.shape[0] and c < data.shape[1]:
                v = data[r::P, c::Q]
                if v.size and v.max() >= level:
                    return True
    return False
