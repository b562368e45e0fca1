"""The stages of the colour ISP after the defect correction, each a function plus its parameters.

::

    fill_missing (reconstruct the Z sites) -> white_balance (black level, grey-world
    gains, clip) -> demosaic -> correct_colour (3x3) -> srgb_encode (sRGB OETF, 8/16 bit)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from .. import _kernels
from .._patterns import get_pattern
from .._validate import (FLOAT_DTYPES, check_choice, check_dtype, check_flag, check_image,
                         check_number, merge_params)
from ..reconstruction import ReconstructParams, reconstruct
from ..reconstruction import METHODS
from ._demosaic import DEMOSAIC_METHODS, DEMOSAIC_MODES

__all__ = ["Reconstruction", "WhiteBalance", "Demosaic", "ColourCorrection", "fill_missing",
           "grey_world_gains", "white_balance", "correct_colour", "srgb_oetf", "srgb_encode"]


def stage_params(cls, params, overrides=None, *, name="params", caller=None, allow_none=True):
    """The parameters of one stage call: ``params`` (a ``cls``, a dict of its fields or None,
    the defaults) with keyword ``overrides`` of its fields (:func:`~rgbz_fast._validate.merge_params`,
    checked once by ``cls``). Another type is a TypeError naming ``name``."""
    if not (isinstance(params, (cls, Mapping)) or (allow_none and params is None)):
        raise TypeError(f"{name}: expected {cls.__name__} or a dict of its fields"
                        f"{' (or None)' if allow_none else ''}, got {type(params).__name__}")
    return merge_params(cls, params, overrides, name=name, caller=caller)


@dataclass(frozen=True)
class Reconstruction:
    """Missing-colour reconstruction at the Z sites (:func:`rgbz_fast.reconstruct`).

    Attributes
    ----------
    method : str
        ``"sg"`` (default), ``"edi_line"``, ``"edi_central"``, ``"bi"``,
        ``"bilinear"``, ``"edi_rows"``, ``"learned"`` or ``"z_guided"`` (guided by the
        frame's ToF taps: :meth:`ColourISP.run` passes them through).
    params : ReconstructParams
        How the kernel computes (precision, sigma floors, SG mode, exponential,
        domain, clip level), checked when the stage is made.
    """

    method: str = "sg"
    params: ReconstructParams = field(default_factory=ReconstructParams)

    def __post_init__(self):
        object.__setattr__(self, "method", check_choice(self.method, tuple(METHODS),
                                                        "Reconstruction.method"))
        object.__setattr__(self, "params", ReconstructParams.build(
            self.params, name="Reconstruction.params"))


@dataclass(frozen=True)
class WhiteBalance:
    """Black level, white-balance gains and highlight clipping, on the complete CFA.

    The output is the normalised linear CFA
    ``(v - black) / (white - black) * gain[colour]``, clipped to [0, 1] when
    ``clip`` (a saturated white then stays white instead of turning pink).

    Attributes
    ----------
    method : {"as_shot", "grey_world", "none"}
        How the gains are found when none are given: ``"as_shot"`` (the
        default) takes the gains the frame records
        (``frame.meta["white_gains"]``: a camera raw file's as-shot white
        balance, a simulated spectral sensor's white under its illuminant)
        and falls back to grey world when it records none (every frame of an
        RGB scene, every plain array); ``"grey_world"``
        (:func:`grey_world_gains`); ``"none"``: unit gains.
    gains : (float, float, float) or None
        Fixed R, G, B gains, each in [1e-6, 1e6]; they override ``method``.
    clip : bool
        Clip to [0, 1] after the gains (True).
    """

    method: str = "as_shot"
    gains: tuple | None = None
    clip: bool = True

    def __post_init__(self):
        object.__setattr__(self, "method", check_choice(self.method,
                                                        ("grey_world", "none", "as_shot"),
                                                        "WhiteBalance.method"))
        if self.gains is not None:
            object.__setattr__(self, "gains", tuple(_check_gains(self.gains,
                                                                 "WhiteBalance.gains")))
        check_flag(self.clip, "WhiteBalance.clip")


@dataclass(frozen=True)
class Demosaic:
    """Bayer demosaic (:func:`rgbz_fast.isp.demosaic`).

    Attributes
    ----------
    method : {"malvar2004", "menon2007", "bilinear"}
    mode : {"reflect", "period"}
        Borders.
    """

    method: str = "malvar2004"
    mode: str = "reflect"

    def __post_init__(self):
        object.__setattr__(self, "method",
                           check_choice(self.method, DEMOSAIC_METHODS, "Demosaic.method"))
        object.__setattr__(self, "mode",
                           check_choice(self.mode, tuple(DEMOSAIC_MODES), "Demosaic.mode"))


@dataclass(frozen=True)
class ColourCorrection:
    """3x3 colour correction: ``out = M @ rgb`` per pixel, then clipped to [0, 1].

    Attributes
    ----------
    matrix : 3x3 nested tuple or None
        Camera RGB (white balanced) -> linear sRGB, rows giving R, G, B.
        None: the matrix the frame records (``frame.meta["colour_matrix"]``:
        a camera raw file's, a simulated spectral sensor's), else the
        identity, right for the RGB scenes of :mod:`rgbz_fast.simulation`
        (their camera channels are the scene's linear sRGB up to the gains
        the white balance removes).
    """

    matrix: tuple | None = None

    def __post_init__(self):
        if self.matrix is not None:
            m = _check_matrix(self.matrix, "ColourCorrection.matrix")
            object.__setattr__(self, "matrix", tuple(tuple(float(v) for v in r) for r in m))


#: the range of a white-balance gain: a camera's lie within about 0.2-10; a gain beyond it
#: overflowed float32 inside the fused ISP (1e308 became inf) while the stages took it, and
#: one below it became 0 in float32
GAIN_RANGE = (1e-6, 1e6)


def _real_numbers(value, name, what):
    """float64 array of ``value``; text, booleans and complex numbers are a TypeError naming
    ``name`` (NumPy read numbers out of text, True as 1 and dropped an imaginary part)."""
    try:
        raw = np.asarray(value)
        bad = raw.dtype.kind in "bcUSMmV" or (raw.dtype.kind == "O" and any(
            isinstance(v, (bool, np.bool_, str, bytes, complex)) for v in raw.reshape(-1)))
        if bad:
            raise TypeError
        return np.asarray(raw, np.float64)
    except OverflowError:
        raise ValueError(f"{name}: holds a number too large for float64") from None
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected {what}, got {value!r:.60}") from None


def _check_gains(gains, name):
    g = _real_numbers(gains, name, "three real numbers (R, G, B)")
    if g.shape != (3,) or not np.all(np.isfinite(g)) or np.any(g <= 0):
        raise ValueError(f"{name}: expected three positive finite gains (R, G, B), got "
                         f"{gains!r}")
    lo, hi = GAIN_RANGE
    if np.any(g < lo) or np.any(g > hi):
        raise ValueError(f"{name}: expected gains within [{lo:g}, {hi:g}] (a camera's lie "
                         f"within about 0.2-10), got {gains!r}")
    return g


def _check_matrix(matrix, name):
    m = _real_numbers(matrix, name, "a 3x3 matrix of real numbers")
    if m.shape != (3, 3) or not np.all(np.isfinite(m)):
        raise ValueError(f"{name}: expected a finite 3x3 matrix, got shape {m.shape}")
    if np.max(np.abs(m)) > MATRIX_MAX:
        raise ValueError(f"{name}: entries up to {np.max(np.abs(m)):g} in magnitude, beyond "
                         f"{MATRIX_MAX:g} (a camera's lie within about 10); float32 images "
                         "would overflow to inf and NaN")
    return m


#: the largest colour-matrix entry: three products with values in [0, 1] stay far inside
#: float32 (3.4e38), whose cast of a larger entry is inf (and inf * 0 NaN)
MATRIX_MAX = 1e30


def _check_cfa(cfa, name="cfa"):
    """A raw 2-D CFA of real values in DN (``check_image``); a bool array is a mask, not
    values (True would be read as 1 DN), so it is refused as ``reconstruct`` refuses it."""
    return check_image(cfa, name, ndim=2, values="raw values in DN")


def _prepare_cfa(cfa, pattern, name="cfa"):
    data = _check_cfa(cfa, name)
    pattern = get_pattern(pattern)
    pattern.check_shape(data.shape, name)
    return data, pattern


def fill_missing(cfa, pattern, params=None, *, bit_depth=11, workers=None, tof=None, nir=None,
                 **overrides):
    """Reconstruct the colour missing at the Z sites: RGB-Z CFA -> full Bayer CFA.

    Delegates to :func:`rgbz_fast.reconstruct`. A pattern without Z sites
    returns a copy of its input (the reference path). ``params`` is a
    :class:`Reconstruction` (default ``Reconstruction()``); keyword
    ``overrides`` replace its fields (``method="bi"``). ``tof`` (the frame's
    ToF taps) and ``nir`` are the guide of the methods of
    :data:`rgbz_fast.NEEDS_TOF` (:func:`rgbz_fast.reconstruct`); the other
    methods do not read them.

    Returns
    -------
    cfa : ndarray, same dtype
        The CFA of the underlying Bayer phase.
    """
    data, pattern = _prepare_cfa(cfa, pattern)
    params = stage_params(Reconstruction, params, overrides, caller="fill_missing()")
    if not pattern.has_z:
        return data.copy()
    return reconstruct(data, params.method, params=params.params, pattern=pattern,
                       bit_depth=bit_depth, workers=workers, tof=tof, nir=nir)


#: the white level's range: the stages work in float32, where 1e300 became inf (a white
#: balance of all zeros) and 1e-300 a division by zero
WHITE_LEVEL_RANGE = (1e-6, 1e30)


def check_white_level(white_level):
    """``white_level`` as a float within :data:`WHITE_LEVEL_RANGE`, or an error naming it."""
    lo, hi = WHITE_LEVEL_RANGE
    return check_number(white_level, "white_level", lo=lo, hi=hi)


def _black_white(black_level, white_level):
    white = check_white_level(white_level)
    black = check_number(black_level, "black_level", lo=0)
    if black >= white:
        raise ValueError(f"black_level: {black:g} must be below the white level {white:g}")
    return black, white


def grey_world_gains(cfa, phase="GRBG", *, black_level=0.0, white_level=2047):
    """Grey-world white-balance gains of a Bayer CFA: ``mean(G) / mean(c)``, green = 1.

    Means of the black-subtracted values of each colour over the pixels
    below the white level (clipped pixels carry no colour). A colour with no
    signal keeps the gain 1; a gain beyond :data:`GAIN_RANGE` (a colour a
    million times below green: no real white balance) is clamped to it, so
    that the estimate is one ``render(..., gains=)`` takes back.

    Parameters
    ----------
    cfa : ndarray, shape (rows, cols)
        A complete Bayer CFA (reconstruct an RGB-Z frame first).
    phase : str or Pattern
        Bayer phase of the CFA.
    black_level, white_level : float
        DN.

    Returns
    -------
    ndarray of float64, shape (3,)
        R, G, B gains.
    """
    data = _check_cfa(cfa)
    pattern = get_pattern(phase)
    if pattern.has_z:
        raise ValueError(f"phase: the white balance needs a complete Bayer CFA, got pattern "
                         f"{pattern.name!r} with Z sites (fill_missing first)")
    black, white = _black_white(black_level, white_level)
    totals, counts = [], []
    with np.errstate(over="ignore", invalid="ignore"):
        for py in range(2):
            for px in range(2):
                sub = data[py::2, px::2]
                ok = sub < white                             # clipped pixels carry no colour
                totals.append(np.sum(sub[ok], dtype=np.float64))
                counts.append(ok.sum())
    return _gains_from_sums(totals, counts, pattern.bayer_tile(), black, data, white)


def _gains_from_sums(totals, counts, tile, black, data, white):
    """Grey-world gains from the sum (float64) and the count (an integer) of the values below
    the white level of each 2x2 phase, in raster order: the arithmetic of
    :func:`grey_world_gains`, which the fused chain reaches with its own sums. ``data`` (the
    CFA) is read again only when a sum overflows (:func:`_scaled_means`)."""
    sums, n = np.zeros(3), np.zeros(3)
    with np.errstate(over="ignore", invalid="ignore"):
        for (py, px), total, count in zip(((0, 0), (0, 1), (1, 0), (1, 1)), totals, counts):
            count = np.int64(count)
            sums[tile[py, px]] += np.float64(total) - black * count
            n[tile[py, px]] += count
    counts = n
    means = np.divide(sums, counts, out=np.zeros(3), where=counts > 0)
    if not np.all(np.isfinite(sums)):
        means = _scaled_means(data, tile, white, black)
    gains = np.ones(3)
    if means[1] > 0:
        good = means > 0
        with np.errstate(over="ignore"):
            ratio = means[1] / means[good]
        # a colour so far below green that the ratio overflows has no signal: gain 1
        gains[good] = np.where(np.isfinite(ratio), ratio, 1.0)
    # within GAIN_RANGE, the gains a caller may give: an estimate of 4e7 (a frame with almost
    # no red) was refused when run_pair handed it back as gains=, and 1e43 overflowed the
    # fused chain's float32 scale (the stages took it in float64)
    return np.clip(gains, *GAIN_RANGE)


def _scaled_means(data, tile, white, black):
    """The black-subtracted mean of each colour below ``white``, for values whose sums
    overflow (near the largest float): summed after a scaling by a power of two (exact)."""
    means = np.zeros(3)
    for c in range(3):
        vals = [data[py::2, px::2] for py in range(2) for px in range(2) if tile[py, px] == c]
        vals = np.concatenate([v[v < white].astype(np.float64).ravel() for v in vals])
        if vals.size:
            exp = math.frexp(max(float(np.max(np.abs(vals))), black))[1]
            with np.errstate(over="ignore"):
                means[c] = np.ldexp(float(np.mean(np.ldexp(vals, -exp)))
                                    - math.ldexp(black, -exp), exp)
    return means


def white_balance(cfa, phase="GRBG", params=None, *, black_level=0.0, white_level=2047,
                  gains=None, dtype=np.float32, **overrides):
    """Normalise a Bayer CFA and apply white-balance gains.

    ``(v - black) / (white - black) * gain[colour]``, clipped to [0, 1] when
    ``params.clip``.

    Parameters
    ----------
    cfa : ndarray, shape (rows, cols)
        Complete Bayer CFA in DN.
    phase : str or Pattern
    params : WhiteBalance, optional
        Default ``WhiteBalance()``; keyword ``overrides`` replace its fields
        (``clip=False``, ``method="none"``).
    black_level, white_level : float
        DN.
    gains : array_like (3,), optional
        R, G, B gains; override ``params`` (e.g. the reference path's).
    dtype : float32 or float64
        The output is normalised to [0, 1] (white = 1), so only floats hold
        it; an integer dtype raises TypeError, as in :func:`demosaic`.

    Returns
    -------
    balanced : ndarray, shape (rows, cols), ``dtype``
    gains : ndarray of float64, shape (3,)
        The gains used.
    """
    dt = check_dtype(dtype, (np.float32, np.float64))
    data = _check_cfa(cfa)
    params = stage_params(WhiteBalance, params, overrides, caller="white_balance()")
    pattern = get_pattern(phase)
    if pattern.has_z:
        raise ValueError(f"phase: the white balance needs a complete Bayer CFA, got pattern "
                         f"{pattern.name!r} with Z sites (fill_missing first)")
    black, white = _black_white(black_level, white_level)
    if gains is not None:
        g = _check_gains(gains, "gains")
    elif params.gains is not None:
        g = np.asarray(params.gains, np.float64)
    elif params.method in ("grey_world", "as_shot"):      # an array records no gains
        g = grey_world_gains(data, pattern, black_level=black, white_level=white)
    else:
        g = np.ones(3)
    tile = pattern.bayer_tile()                      # 2x2
    with np.errstate(over="ignore", under="ignore"):
        scale = (g / (white - black)).astype(dt)
    if _fits(data, dt, black, white, scale):
        out = data.astype(dt)
        out -= dt.type(black)
        for py in range(2):
            for px in range(2):
                out[py::2, px::2] *= scale[tile[py, px]]
    else:
        # levels or values beyond the output type (near its largest float): in float64, in an
        # order that never makes NaN -- (v - black) / (white - black) is finite or +-inf
        out = data.astype(np.float64) - black
        with np.errstate(over="ignore"):
            out /= white - black
            for py in range(2):
                for px in range(2):
                    out[py::2, px::2] *= g[tile[py, px]]
    if params.clip:
        np.clip(out, 0, 1, out=out)
    elif out.dtype != dt or out.dtype.kind == "f" and not np.all(np.isfinite(out)):
        with np.errstate(over="ignore"):
            out = out.astype(dt)
        if not np.all(np.isfinite(out)):
            raise ValueError(f"cfa: the balanced values (v - black_level) / (white_level - "
                             f"black_level) * gains overflow {dt} (levels {black:g}, {white:g}, "
                             f"gains {tuple(float(v) for v in g)}); clip them (clip=True) or "
                             "pass the levels of the data")
    return out.astype(dt, copy=False), g


def _fits(data, dt, black, white, scale):
    """Whether :func:`white_balance` may compute in ``dt`` without an inf or a NaN: the
    levels and the three scales are normal numbers of ``dt``, and the data fits it."""
    info = np.finfo(dt)
    if not (white <= info.max and np.all(scale >= info.tiny) and np.all(scale <= info.max)):
        return False
    if data.dtype.kind == "f" and data.dtype.itemsize > dt.itemsize:
        return bool(max(-data.min(), data.max()) <= info.max / 2)
    return True


def correct_colour(rgb, params=None, **overrides):
    """Apply the 3x3 colour correction and clip to [0, 1].

    Parameters
    ----------
    rgb : ndarray, shape (rows, cols, 3)
        Linear, white-balanced camera RGB.
    params : ColourCorrection, optional
        Default ``ColourCorrection()`` (the identity); keyword ``overrides``
        replace its fields (``matrix=M``).

    Returns
    -------
    ndarray, same shape and float dtype (a new array)
    """
    a = check_image(rgb, "rgb", ndim=3, dtypes=FLOAT_DTYPES)
    if a.shape[2] != 3:
        raise ValueError(f"rgb: expected 3 channels in the last axis, got shape {a.shape}")
    params = stage_params(ColourCorrection, params, overrides, caller="correct_colour()")
    dt = a.dtype if a.dtype in (np.float32, np.float64) else np.dtype(np.float64)
    if params.matrix is None:
        out = a.astype(dt, copy=True)
    else:
        m = np.asarray(params.matrix, dt)
        out = np.matmul(a.astype(dt, copy=False), m.T)
    return np.clip(out, 0, 1, out=out)


def srgb_oetf(linear):
    """The exact sRGB encoding (IEC 61966-2-1) of linear values, clipped to [0, 1].

    ``12.92 v`` for ``v <= 0.0031308``, else ``1.055 v^(1/2.4) - 0.055``.
    """
    a = check_image(linear, "linear", dtypes=FLOAT_DTYPES)
    dt = a.dtype if a.dtype in (np.float32, np.float64) else np.dtype(np.float64)
    out = np.empty(a.shape, dt)
    flat_in, flat_out = a.reshape(-1), out.reshape(-1)
    # element-wise, so blocks of 256 K values give the same result with every
    # temporary in cache: on a 12-megapixel RGB image the frame-size temporaries
    # cost more in page faults than the arithmetic
    step = 1 << 18
    for i in range(0, flat_in.size, step):
        _oetf_block(flat_in[i:i + step], flat_out[i:i + step])
    return out


def _oetf_block(a, out):
    t = out.dtype.type
    v = np.clip(a.astype(out.dtype, copy=False), 0, 1)
    low = v <= t(0.0031308)
    # The linear segment overwrites these values below, so the power never sees them:
    # NumPy's SIMD power leaves its fast path for a vector holding a 0 (the clipped
    # blacks; 4.5x slower with 20 % zeros), and every other element is unchanged.
    np.copyto(out, v)
    out[low] = t(1)
    np.power(out, t(1 / 2.4), out=out)
    out *= t(1.055)
    out -= t(0.055)
    np.multiply(v, t(12.92), out=out, where=low)


def srgb_encode(linear, bits=8):
    """Linear RGB in [0, 1] -> 8- or 16-bit sRGB: ``floor(oetf(v) * (2**bits - 1) + 0.5)``.

    The values are clipped to [0, 1] first. The same codes as
    ``_quantise(srgb_oetf(linear), bits)`` bit for bit, without their
    frame-size temporaries (:func:`_encode`).
    """
    if isinstance(bits, bool) or not isinstance(bits, (int, np.integer)) or bits not in (8, 16):
        raise ValueError(f"bits: expected 8 or 16, got {bits!r}")
    a = check_image(linear, "linear", dtypes=FLOAT_DTYPES)
    return _encode(a.astype(a.dtype if a.dtype in (np.float32, np.float64) else np.float64,
                            copy=False), bits)


#: values per pass of :func:`_encode` (its scratch stays in cache)
_ENCODE_BLOCK = 1 << 18


def _encode(linear, bits):
    """8- or 16-bit sRGB codes of float32/float64 linear values: the clip of
    :func:`correct_colour`, :func:`srgb_oetf` and :func:`_quantise` bit for bit.

    Two C passes (csrc/srgb.c) around NumPy's power, which stays the power of
    :func:`srgb_oetf` (the same function on the same values): the first clips and
    puts 1 where the linear segment applies, the second finishes the OETF and
    quantises, with the same operations in the same order as the NumPy stages.
    Blocks of 256 K values, so the one scratch block stays in cache.
    """
    x = np.ascontiguousarray(linear).reshape(-1)
    t = x.dtype.type
    code = np.empty(x.size, np.uint8 if bits == 8 else np.uint16)
    scratch = np.empty(min(x.size, _ENCODE_BLOCK), x.dtype)
    exponent = t(1 / 2.4)
    for i in range(0, x.size, _ENCODE_BLOCK):
        xs = x[i:i + _ENCODE_BLOCK]
        ps = scratch[:xs.size]
        _kernels.oetf_prepare(xs, ps, 1)
        np.power(ps, exponent, out=ps)
        _kernels.oetf_finish(xs, ps, code[i:i + _ENCODE_BLOCK], 1)
    return code.reshape(np.shape(linear))


def _quantise(encoded, bits):
    """floor(v * (2**bits - 1) + 0.5) as uint8 / uint16, for v in [0, 1]."""
    t = encoded.dtype.type
    x = encoded * t((1 << bits) - 1)
    x += t(0.5)
    np.floor(x, out=x)
    return x.astype(np.uint8 if bits == 8 else np.uint16)
