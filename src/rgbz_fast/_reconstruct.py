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


def reconstruct(frame, method="sg", *, pattern=None, bit_depth=None, precision="float32",
                workers=None, sigma_floor=1e-3, sigma_rel=0.5, edge_ratio=0.5, sg_mode="auto", exp="libm",
                domain="intensity"):
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
    exp : {"libm", "fast"}
        Exponential of eq. 7: the C library's, or a range-reduced polynomial
        (relative error below 3e-7 in float32, 1e-8 in float64; results below
        the normal range flush to 0) that is faster.

    Returns
    -------
    cfa : ndarray, shape (rows, cols)
        The full Bayer CFA of the underlying Bayer phase, same dtype as the
        input: colour sites copied unchanged, Z sites reconstructed (integer
        types rounded half up).

    Raises
    ------
    ValueError
        Unknown method or option, a method that does not apply to the
        pattern, a frame smaller than one period, values beyond the bit depth,
        NaN or inf.

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
    out = np.empty(data.shape, data.dtype)
    if not pattern.has_z:
        out[...] = data
        return out
    if pattern.bayer_phase is None:
        raise ValueError(f"pattern: tile {pattern.tile_string!r} fits no Bayer phase, so its Z "
                         "sites stand in for no defined colour")
    phase_map, plans, n_plans = _plans_for(pattern, method, sg_mode, domain)
    src = np.ascontiguousarray(data)
    fast = int(_MASK1_FAST and domain == "intensity" and method != "edi_rows"
               and has_mask1_geometry(pattern))
    _kernels.reconstruct(src, out, PRECISIONS[precision], pattern.period[0], pattern.period[1],
                         phase_map, plans, n_plans, sigma_floor, sigma_rel, edge_ratio,
                         float((1 << bd) - 1), EXP_MODES[exp], nthreads, mask1_fast=fast)
    return out


def _check_tuning(*, sg_mode, exp, domain, sigma_floor, sigma_rel, edge_ratio):
    """The options of :func:`reconstruct` that tune its kernels, checked (and normalised).

    Shared by :func:`reconstruct` and :func:`check_reconstruct_options`, so a
    configuration is checked by the same code before any frame exists.
    """
    sg_mode = check_choice(sg_mode, SG_MODES, "sg_mode")
    exp = check_choice(exp, tuple(EXP_MODES), "exp")
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
CALLER_ARGS = ("frame", "method", "pattern", "bit_depth", "precision", "workers")


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
        _check_tuning(**values)
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
