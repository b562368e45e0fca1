"""Missing-colour reconstruction at the Z sites: RGB-Z frame -> full Bayer CFA.

References
----------
.. [1] V. Rebiere, A. Drouot, B. Granado, A. Bourge, A. Pinna, "Color pixel
       reconstruction for a monolithic RGB-Z CMOS imager", section 4,
       eqs. 2-19 and Table 1.
.. [2] L. Shi et al., directional interpolation of the missing rows of an
       RGB-Z matrix (eqs. 1a-1e of [1]).
"""

from __future__ import annotations

import inspect
from functools import lru_cache

import numpy as np

from . import _kernels
from ._frame import RawFrame, validate_frame
from ._patterns import get_pattern
from ._plans import METHODS, build_plans, check_layout
from ._validate import check_bit_depth, check_choice, check_workers

__all__ = ["reconstruct", "METHODS", "PRECISIONS"]

check_layout(_kernels.plan_layout())

PRECISIONS = {"float32": 0, "float64": 1}
EXP_MODES = {"libm": 0, "fast": 1}
SG_MODES = ("auto", "pure", "combined")
#: use the Mask1 fast path (csrc/recon_mask1.h) where it applies; tests switch it off to
#: compare it with the generic plan interpreter
_MASK1_FAST = True


def has_mask1_geometry(pattern):
    """True for a 2x2 tile whose single Z site stands in for a green (Mask1, any phase)."""
    if pattern.period != (2, 2) or int((pattern.tile == 3).sum()) != 1:
        return False
    return pattern.bayer_phase is not None and int(
        pattern.bayer_tile()[pattern.tile == 3][0]) == 1
DOMAINS = ("colour_difference", "intensity")


@lru_cache(maxsize=128)
def _plans_for(pattern, method, sg_mode, domain):
    phase_map, plans = build_plans(pattern, method, sg_mode, domain)
    phase_map.setflags(write=False)
    raw = plans.view(np.uint8).reshape(-1)
    raw.setflags(write=False)
    return phase_map, raw, len(plans)


def _prepare(frame, pattern, bit_depth):
    """Return (data, pattern, bit_depth) from a RawFrame or an array plus pattern."""
    if isinstance(frame, RawFrame):
        if pattern is not None and get_pattern(pattern) != frame.pattern:
            raise ValueError(f"pattern: {get_pattern(pattern).name!r} differs from the "
                             f"frame's pattern {frame.pattern.name!r}")
        if bit_depth is not None and check_bit_depth(bit_depth) != frame.bit_depth:
            raise ValueError(f"bit_depth: {bit_depth} differs from the frame's {frame.bit_depth}")
        return frame.data, frame.pattern, frame.bit_depth
    if pattern is None:
        raise TypeError("pattern: required when frame is a plain array "
                        "(pass a RawFrame, or pattern='mask1', ...)")
    pattern = get_pattern(pattern)
    bd = check_bit_depth(11 if bit_depth is None else bit_depth)
    return validate_frame(frame, pattern, bd, "frame"), pattern, bd


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


def _exp_mode(exp, precision):
    """The exponential a call runs: ``"auto"`` is the polynomial in float32, libm in float64."""
    if exp == "auto":
        return "fast" if precision == "float32" else "libm"
    return exp


def reconstruct(frame, method="sg", *, pattern=None, bit_depth=None, precision="float32",
                workers=None, sigma_floor=1e-3, sigma_rel=0.5, edge_ratio=0.5, sg_mode="auto", exp="auto",
                domain="intensity", clip_level=None, out=None):
    """Fill in the colour missing at every Z site: RGB-Z raw frame -> full Bayer CFA.

    Parameters
    ----------
    frame : RawFrame or ndarray, shape (rows, cols)
        The raw frame. A plain array needs ``pattern`` (and ``bit_depth`` if
        not 11). uint8, uint16, float32 and float64 are read directly.
    method : {"sg", "edi_line", "edi_central", "bi", "bilinear", "edi_rows"}
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
    pattern : Pattern or str, optional
        The pattern of a plain-array frame.
    bit_depth : int, optional
        Bits of a plain-array frame (default 11). Outputs are clipped to
        [0, 2**bit_depth - 1].
    precision : {"float32", "float64"}
        Arithmetic of the kernel. float32 is faster; float64 agrees with the
        NumPy reference to 1e-9 relative.
    workers : int, optional
        Threads (rows are split across them). None or -1: all cores. The
        result is identical for every value.
    sigma_floor : float
        Floor of sigma in eq. 7 (DN), used when the smallest gradient is 0.
    edge_ratio : float
        ``edi_rows`` only: an edge is dominant when its difference is below
        ``edge_ratio`` times the vertical one.
    sg_mode : {"auto", "pure", "combined"}
        ``sg`` only: ``"pure"`` is the paper's Mask1 method (semi-gradient
        weights alone), ``"combined"`` multiplies them by the EDILine weights;
        ``"auto"`` uses pure where every candidate lies on a diagonal (Mask1)
        and combined elsewhere (Mask2).
    exp : {"auto", "libm", "fast"}
        Exponential of eq. 7: the C library's, or a range-reduced polynomial
        (relative error below 3e-7 in float32, 1e-8 in float64; results below
        the normal range flush to 0) that is faster and vectorises.
        ``"auto"`` (default) is ``"fast"`` in float32 -- its error is of the
        order of float32's own rounding, and it changes the mean CFA PSNR on
        Kodak by less than 1e-5 dB (docs/tradeoff.md) -- and ``"libm"`` in
        float64, so that float64 stays the accurate reference.
    domain : {"intensity", "colour_difference"}
        Interpolate the candidates themselves (eq. 13, the default) or their
        differences to an estimate of the other channel(s) (eq. 5).
    clip_level : float, "auto" or None
        The level at which the sensor saturates, in the frame's digital
        numbers. Known pixels at or above it are *clipped*: their value is a
        lower bound of the light. It is still interpolated as a value; in the
        weights (gradients, semi-gradients, the terms of beta, the directions
        of ``edi_rows``) a difference between two clipped pixels is unknown and
        skipped, while one between a clipped and an unclipped pixel is a true
        lower bound of the difference and is kept. A site whose candidates are
        all clipped stays at or above the smallest of them.
        The rule per method is in docs/raw.md ("Near clipping").
        None (default): nothing is clipped. ``"auto"``: the level that
        :func:`rgbz_fast.rawio.read_raw` recorded for a frame read from a raw
        file (:func:`rgbz_fast.rawio.frame_clip_level`); None for any other
        frame. If no colour pixel reaches the level, the result is exactly
        that of ``clip_level=None``; otherwise Mask1 runs on the generic plan
        interpreter instead of its fast path.
    out : ndarray, optional
        Where to write the result: C-contiguous, writeable, the frame's shape
        and dtype, not overlapping the frame. On an error nothing is written
        to it. (Reusing a buffer bounds the memory of a stream of frames; it
        was not measurably faster than a new output on Linux, 12-megapixel
        frames: docs/benchmarks.md.)

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
        NaN or inf, a ``clip_level`` that is not a positive finite number.
    TypeError
        A ``clip_level`` that is not a number, None or ``"auto"``.

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
    :math:`\\sigma` the smallest gradient, floored at ``sigma_floor``; if every
    weight underflows the plain mean is used. The Mask2 SG variant, which the
    paper does not spell out, is
    :math:`\\omega = \\alpha\\beta\\gamma_{line}(ori)\\,\\overline{SG}(pos)`:
    EDILine's weights times the mean of the discriminated semi-gradients
    covering the candidate's position (12 exponentials, as in Table 1).
    Every choice made where the paper is vague is in docs/interpretation.md.

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
    data, pattern, bd = _prepare(frame, pattern, bit_depth)
    method = check_choice(method, tuple(METHODS), "method")
    precision = check_choice(precision, tuple(PRECISIONS), "precision")
    nthreads = check_workers(workers)
    sg_mode, exp, domain, sigma_floor, sigma_rel, edge_ratio = _check_tuning(
        sg_mode=sg_mode, exp=exp, domain=domain, sigma_floor=sigma_floor, sigma_rel=sigma_rel,
        edge_ratio=edge_ratio)
    clip = _clip_level(clip_level, frame)
    out = _check_out(out, data)
    if not pattern.has_z:
        out[...] = data
        return out
    if pattern.bayer_phase is None:
        raise ValueError(f"pattern: tile {pattern.tile_string!r} fits no Bayer phase, so its Z "
                         "sites stand in for no defined colour")
    phase_map, plans, n_plans = _plans_for(pattern, method, sg_mode, domain)
    src = np.ascontiguousarray(data)
    if clip is not None and not _reaches(src, pattern, clip):
        clip = None          # nothing clipped: exactly the clip_level=None call
    # the Mask1 fast path knows nothing of clipping: clipped frames take the interpreter
    fast = int(_MASK1_FAST and clip is None and domain == "intensity" and method != "edi_rows"
               and has_mask1_geometry(pattern))
    _kernels.reconstruct(src, out, PRECISIONS[precision], pattern.period[0], pattern.period[1],
                         phase_map, plans, n_plans, sigma_floor, sigma_rel, edge_ratio,
                         float((1 << bd) - 1), EXP_MODES[_exp_mode(exp, precision)], nthreads,
                         mask1_fast=fast, clip_level=clip)
    return out


def _clip_level(value, frame):
    """Validate ``clip_level``; resolve ``"auto"``. Returns a positive float or None."""
    if value is None:
        return None
    if isinstance(value, str):
        if value == "auto":
            if not isinstance(frame, RawFrame):
                return None
            from .rawio import frame_clip_level
            return frame_clip_level(frame)
        raise TypeError(f"clip_level: expected a positive number, None or 'auto', got {value!r}")
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"clip_level: expected a positive number, None or 'auto', got {value!r}")
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise TypeError(f"clip_level: expected a positive number, None or 'auto', "
                        f"got {value!r}") from None
    if not np.isfinite(v) or v <= 0:
        raise ValueError(f"clip_level: expected a positive finite number (DN), got {value!r}")
    return v


def _reaches(data, pattern, level):
    """True if a colour site of ``data`` is at or above ``level`` (strided views, no copy)."""
    P, Q = pattern.period
    for r in range(P):
        for c in range(Q):
            if pattern.tile[r, c] != 3 and r < data.shape[0] and c < data.shape[1]:
                v = data[r::P, c::Q]
                if v.size and v.max() >= level:
                    return True
    return False


def _check_tuning(*, sg_mode, exp, domain, sigma_floor, sigma_rel, edge_ratio):
    """The options of :func:`reconstruct` that tune its kernels, checked (and normalised).

    Shared by :func:`reconstruct` and :func:`check_reconstruct_options`, so a
    configuration is checked by the same code before any frame exists.
    """
    sg_mode = check_choice(sg_mode, SG_MODES, "sg_mode")
    exp = check_choice(exp, ("auto",) + tuple(EXP_MODES), "exp")
    domain = check_choice(domain, DOMAINS, "domain")
    sigma_floor = _positive(sigma_floor, "sigma_floor")
    edge_ratio = _positive(edge_ratio, "edge_ratio")
    try:
        sigma_rel = float(sigma_rel)
    except (TypeError, ValueError):
        raise TypeError(f"sigma_rel: expected a number in [0, 10], got {sigma_rel!r}") from None
    if not 0 <= sigma_rel <= 10:
        raise ValueError(f"sigma_rel: expected a number in [0, 10], got {sigma_rel!r}")
    return sg_mode, exp, domain, sigma_floor, sigma_rel, edge_ratio


#: arguments of :func:`reconstruct` that a batch caller (evaluate) sets itself
CALLER_ARGS = ("frame", "method", "pattern", "bit_depth", "precision", "workers", "out")


def tuning_options():
    """Names of the keyword arguments of :func:`reconstruct` other than :data:`CALLER_ARGS`."""
    return tuple(k for k in inspect.signature(reconstruct).parameters if k not in CALLER_ARGS)


def check_reconstruct_options(options, name="reconstruct_options", *, by="the caller"):
    """Extra keyword arguments of :func:`reconstruct`, checked before any frame exists.

    Parameters
    ----------
    options : mapping or iterable of (name, value) pairs
        Options such as ``sigma_floor``, ``sg_mode``, ``exp``, ``domain``.
    name : str
        The parameter named in the error messages.
    by : str
        Who sets the arguments of :data:`CALLER_ARGS` (for the message).

    Returns
    -------
    tuple of (str, object)
        The pairs sorted by name (hashable and picklable), values as given.

    Raises
    ------
    TypeError
        Not a mapping or pairs, a name that is not a string, a value of the
        wrong type (``"{name}: sigma_floor: ..."``).
    ValueError
        An argument of :data:`CALLER_ARGS`, an unknown option, a bad value.
    """
    if isinstance(options, (str, bytes)):
        opts = None
    else:
        try:
            opts = dict(options)
        except (TypeError, ValueError):
            opts = None
    if opts is None:
        raise TypeError(f"{name}: expected a mapping or (name, value) pairs of keyword "
                        f"arguments of reconstruct, got {options!r}")
    if not all(isinstance(k, str) for k in opts):
        raise TypeError(f"{name}: keys must be argument names, got {list(opts)!r}")
    for k in CALLER_ARGS:
        if k in opts:
            raise ValueError(f"{name}: {k!r} is set by {by}, not through {name}")
    tunable = tuning_options()
    unknown = sorted(k for k in opts if k not in tunable)
    if unknown:
        raise ValueError(f"{name}: unknown option(s) {unknown}; expected some of {list(tunable)}")
    params = inspect.signature(reconstruct).parameters
    values = {k: params[k].default for k in tunable}
    values.update(opts)
    try:
        _check_tuning(**{k: v for k, v in values.items() if k != "clip_level"})
        if values.get("clip_level") != "auto":
            _clip_level(values.get("clip_level"), None)
    except (TypeError, ValueError) as exc:
        raise type(exc)(f"{name}: {exc}") from None
    return tuple(sorted(opts.items()))


def _positive(value, name):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a positive number, got {value!r}") from None
    if not np.isfinite(v) or v <= 0:
        raise ValueError(f"{name}: expected a positive finite number, got {value!r}")
    return v
