"""The colour ISP of an RGB-Z sensor (paper §5.1.4, Figs. 18-19), stage by stage.

::

    raw CFA (DN) ─► correct_defects ─► fill_missing (reconstruct the Z sites)
        ─► white_balance (black level, grey-world gains, clip) ─► demosaic
        ─► correct_colour (3x3) ─► srgb_encode (sRGB OETF, 8 or 16 bit)

The defect correction comes first so that a defective pixel never feeds the
reconstruction, and it never reads a Z site; the reconstruction comes before
the white balance, which then sees a complete Bayer CFA, and before the
demosaic (paper §5.1.4). Every stage is a plain function of arrays plus a
small frozen dataclass of parameters; :class:`ColourISP` chains them.

The same chain serves both paths of Fig. 19: ``isp.run(frame)`` reconstructs
only when the frame's pattern has Z sites, and ``isp.run(frame,
reference=True)`` runs the plain Bayer reference CFA (``frame.reference``)
with the reconstruction bypassed. For a fair comparison the white-balance
gains estimated on the reference are reused on the RGB-Z path
(``run(frame, gains=...)``, or :meth:`ColourISP.run_pair`), so that the two
outputs differ by the reconstruction only. The ToF ISP is in
:mod:`rgbz_fast.tof_isp` (re-exported here).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from ._frame import RawFrame
from ._patterns import Z, get_pattern
from ._reconstruct import reconstruct
from ._validate import (FRAME_DTYPES, check_bit_depth, check_choice, check_dtype,
                        check_flag, check_image, check_number)
from .demosaic import DEMOSAIC_METHODS, DEMOSAIC_MODES, demosaic
from .tof_isp import ToFDepth, ToFISP, tof_depth

__all__ = [
    "ColourISP", "DefectCorrection", "Reconstruction", "WhiteBalance", "Demosaic",
    "ColourCorrection", "STAGES",
    "detect_defects", "correct_defects", "fill_missing", "grey_world_gains", "white_balance",
    "correct_colour", "srgb_oetf", "srgb_encode",
    "ToFISP", "ToFDepth", "tof_depth",
]

#: the stages of :meth:`ColourISP.run`, in order (keys of ``return_stages``)
STAGES = ("defect_correction", "reconstruction", "white_balance", "demosaic",
          "colour_correction", "gamma", "output")

_PRECISIONS = {"float32": np.float32, "float64": np.float64}


_real = check_number   # one validator for every numeric parameter (_validate.py)
_flag = check_flag     # and one for every True/False parameter


# =========================================================================== parameters
@dataclass(frozen=True)
class DefectCorrection:
    """Dynamic defect-pixel correction (before the reconstruction; Z sites never read).

    A colour pixel ``p`` is compared with its *same-colour non-Z neighbours*
    ``N_p`` in the 5x5 window inside the frame (12 for green and 8 for red
    and blue on a Bayer CFA, fewer on RGB-Z patterns). It is **hot** when
    all of

    1. ``v_p - max(N_p) > threshold * white_level`` (it stands out),
    2. ``v_p - max(N_p) > spread_factor * (max(N_p) - min(N_p))`` (more than
       the local texture),
    3. no adjacent non-Z pixel ``q`` (8-neighbourhood, any colour) rises with
       it: ``v_q - mean'(N_q) < cross_factor * (v_p - max(N_p))``, with
       ``mean'`` the mean without the largest and the smallest value (so a
       second defect nearby does not move it). A real detail, blurred by the
       optics, lifts its neighbours in every channel; a defect is one pixel,

    and **cold** in the mirror case. Flagged pixels take the median of
    ``N_p`` (rounded half up for integer CFAs). On the 24 noise-free Kodak
    mosaics (11 bit; scanned film has no lens blur at the pixel scale, so a
    few real one-pixel details exist) the defaults flag 5 pixels in all on
    the Bayer CFA, 18 on Mask1 and 26 on Mask2, of 9.4 million each; they
    find about 70 % of the planted defects that deviate by more than
    500 DN from a noisy frame (docs/isp.md).

    Attributes
    ----------
    enabled : bool
        False: the stage returns its input.
    threshold : float
        Fraction of the white level (0.15).
    spread_factor : float
        (1.0).
    cross_factor : float
        (0.1).
    """

    enabled: bool = True
    threshold: float = 0.15
    spread_factor: float = 1.0
    cross_factor: float = 0.1

    def __post_init__(self):
        _flag(self.enabled, "DefectCorrection.enabled")
        _real(self.threshold, "DefectCorrection.threshold", lo=0, lo_open=True, hi=1)
        _real(self.spread_factor, "DefectCorrection.spread_factor", lo=0)
        _real(self.cross_factor, "DefectCorrection.cross_factor", lo=0)


@dataclass(frozen=True)
class Reconstruction:
    """Missing-colour reconstruction at the Z sites (:func:`rgbz_fast.reconstruct`).

    Attributes
    ----------
    method : str
        ``"sg"`` (default), ``"edi_line"``, ``"edi_central"``, ``"bi"``,
        ``"bilinear"`` or ``"edi_rows"``.
    precision : {"float32", "float64"}
    options : mapping or tuple of (name, value) pairs
        More keyword arguments of :func:`rgbz_fast.reconstruct`
        (``sigma_floor``, ``sg_mode``, ``exp``, ...); stored as a sorted tuple
        of pairs, so that the parameters stay hashable and picklable.
    """

    method: str = "sg"
    precision: str = "float32"
    options: tuple = ()

    def __post_init__(self):
        # names and values checked now, by the code reconstruct runs, not at the first frame
        from ._reconstruct import check_reconstruct_options
        object.__setattr__(self, "options", check_reconstruct_options(
            self.options, "Reconstruction.options", by="the chain"))
        if not isinstance(self.method, str):
            raise ValueError(f"Reconstruction.method: expected a method name, got "
                             f"{self.method!r}")
        object.__setattr__(self, "precision", check_choice(
            self.precision, ("float32", "float64"), "Reconstruction.precision"))


@dataclass(frozen=True)
class WhiteBalance:
    """Black level, white-balance gains and highlight clipping, on the complete CFA.

    The output is the normalised linear CFA
    ``(v - black) / (white - black) * gain[colour]``, clipped to [0, 1] when
    ``clip`` (a saturated white then stays white instead of turning pink).

    Attributes
    ----------
    method : {"grey_world", "none"}
        How the gains are found when none are given: grey world
        (:func:`grey_world_gains`) or unit gains.
    gains : (float, float, float) or None
        Fixed R, G, B gains; they override ``method``.
    clip : bool
        Clip to [0, 1] after the gains (True).
    """

    method: str = "grey_world"
    gains: tuple | None = None
    clip: bool = True

    def __post_init__(self):
        object.__setattr__(self, "method", check_choice(self.method, ("grey_world", "none"),
                                                        "WhiteBalance.method"))
        if self.gains is not None:
            object.__setattr__(self, "gains", tuple(_check_gains(self.gains,
                                                                 "WhiteBalance.gains")))
        _flag(self.clip, "WhiteBalance.clip")


@dataclass(frozen=True)
class Demosaic:
    """Bayer demosaic (:func:`rgbz_fast.demosaic.demosaic`).

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
        None: the identity, right for the RGB scenes of
        :mod:`rgbz_fast.sensor` (their camera channels are the scene's
        linear sRGB up to the gains the white balance removes).
    """

    matrix: tuple | None = None

    def __post_init__(self):
        if self.matrix is not None:
            m = _check_matrix(self.matrix, "ColourCorrection.matrix")
            object.__setattr__(self, "matrix", tuple(tuple(float(v) for v in r) for r in m))


def _check_gains(gains, name):
    try:
        g = np.asarray(gains, np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected three numbers (R, G, B), got {gains!r}") from None
    if g.shape != (3,) or not np.all(np.isfinite(g)) or np.any(g <= 0):
        raise ValueError(f"{name}: expected three positive finite gains (R, G, B), got "
                         f"{gains!r}")
    return g


def _check_matrix(matrix, name):
    try:
        m = np.asarray(matrix, np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a 3x3 matrix of numbers, got {matrix!r}") from None
    if m.shape != (3, 3) or not np.all(np.isfinite(m)):
        raise ValueError(f"{name}: expected a finite 3x3 matrix, got shape {m.shape}")
    return m


# =========================================================================== stages
def _colour_offsets(tile, py, px):
    """Offsets (dy, dx) of the 5x5 window holding the colour of tile site (py, px)."""
    P, Q = tile.shape
    c = tile[py, px]
    return [(dy, dx) for dy in range(-2, 3) for dx in range(-2, 3)
            if (dy, dx) != (0, 0) and tile[(py + dy) % P, (px + dx) % Q] == c]


#: NaN cells around every phase plane (enough for the 5x5 window's reach of +-2 pixels
#: on any tile, including phases one row or column shorter than others)
_PAD = 3


def _phase_planes(data, tile):
    """The colour phases of the tile as contiguous float32 sub-images, NaN-padded.

    ``planes[py, px]`` holds ``data[py::P, px::Q]`` (converted to float32, as
    the detection works in float32) inside a border of :data:`_PAD` NaN cells,
    so that every same-colour neighbour of a phase is a shifted, unit-stride
    view of one plane and a neighbour outside the frame is NaN. Z phases are
    left out (no colour pixel has a Z neighbour of its colour, and a Z site is
    never read).
    """
    H, W = data.shape
    P, Q = tile.shape
    planes = {}
    for py in range(min(P, H)):
        for px in range(min(Q, W)):
            if tile[py, px] == Z:
                continue
            sub = data[py::P, px::Q]
            buf = np.empty((sub.shape[0] + 2 * _PAD, sub.shape[1] + 2 * _PAD), np.float32)
            buf[:_PAD] = buf[-_PAD:] = buf[:, :_PAD] = buf[:, -_PAD:] = np.nan
            buf[_PAD:-_PAD, _PAD:-_PAD] = sub
            planes[py, px] = buf
    return planes


def _phase_extremes(planes, tile, py, px, mx, mn):
    """Max and min (float32) of the same-colour neighbours of every pixel of phase (py, px),
    into the buffers ``mx`` and ``mn`` (of the phase's shape).

    Neighbours outside the frame do not count (NaN, skipped by fmax / fmin); a
    pixel without any neighbour gets NaN, which no test passes.
    """
    P, Q = tile.shape
    h, w = mx.shape
    views = []
    for dy, dx in _colour_offsets(tile, py, px):
        target = planes.get(((py + dy) % P, (px + dx) % Q))
        if target is None:                        # a phase the (tiny) frame does not hold
            continue
        sy, sx = _PAD + (py + dy) // P, _PAD + (px + dx) // Q
        views.append(target[sy:sy + h, sx:sx + w])
    if not views:
        mx.fill(np.nan)
        mn.fill(np.nan)
    elif len(views) == 1:
        np.copyto(mx, views[0])
        np.copyto(mn, views[0])
    else:
        np.fmax(views[0], views[1], out=mx)
        np.fmin(views[0], views[1], out=mn)
        for nb in views[2:]:
            np.fmax(mx, nb, out=mx)
            np.fmin(mn, nb, out=mn)
    return mx, mn


def _site_values(data, tile, rr, cc, dtype, hidden=None):
    """``data[rr, cc]`` as ``dtype`` (then float64), NaN at Z sites and where ``hidden``."""
    P, Q = tile.shape
    v = data[rr, cc].astype(dtype).astype(np.float64)
    drop = tile[rr % P, cc % Q] == Z
    if hidden is not None:
        drop |= hidden[rr, cc]
    v[drop] = np.nan
    return v


def _gather_neighbours(data, tile, rr, cc, dtype, hidden=None):
    """Same-colour neighbours of the sites (rr, cc): (len(rr), 24) float64, NaN-padded.

    The values are ``data`` converted to ``dtype``; NaN stands for no
    neighbour: outside the frame, a Z site, or a pixel of ``hidden``.
    """
    H, W = data.shape
    P, Q = tile.shape
    out = np.full((rr.size, 24), np.nan)
    phase = (rr % P) * Q + (cc % Q)
    for ph in np.unique(phase):
        sel = np.nonzero(phase == ph)[0]
        offs = np.array(_colour_offsets(tile, ph // Q, ph % Q), np.int64).reshape(-1, 2)
        r = rr[sel, None] + offs[:, 0]
        c = cc[sel, None] + offs[:, 1]
        inside = (r >= 0) & (r < H) & (c >= 0) & (c < W)
        nb = np.full(r.shape, np.nan)
        nb[inside] = _site_values(data, tile, r[inside], c[inside], dtype, hidden)
        out[sel, :offs.shape[0]] = nb
    return out


def _prepare_cfa(cfa, pattern, name="cfa"):
    data = check_image(cfa, name, ndim=2)
    pattern = get_pattern(pattern)
    pattern.check_shape(data.shape, name)
    return data, pattern


def detect_defects(cfa, pattern, params=DefectCorrection(), *, white_level=2047):
    """Boolean map of the defective colour pixels (see :class:`DefectCorrection`).

    Parameters
    ----------
    cfa : ndarray, shape (rows, cols)
        Raw frame in DN (the values at Z sites are never read).
    pattern : Pattern or str
        The frame's pattern.
    params : DefectCorrection
    white_level : float
        Full scale in DN (``2**bit_depth - 1``).

    Returns
    -------
    ndarray of bool, shape (rows, cols)
        False at every Z site.
    """
    data, pattern = _prepare_cfa(cfa, pattern)
    if not isinstance(params, DefectCorrection):
        raise TypeError(f"params: expected DefectCorrection, got {type(params).__name__}")
    white_level = _real(white_level, "white_level", lo=0, lo_open=True)
    found = np.zeros(data.shape, bool)
    if params.enabled:
        rr, cc = _detect_sites(data, pattern.tile, params, white_level)
        found[rr, cc] = True
    return found


def _detect_sites(data, tile, params, white_level):
    """Rows and columns of the defects :func:`detect_defects` flags (validated input).

    Tests 1 and 2 run on every colour pixel, one tile phase at a time on
    contiguous NaN-padded sub-images (:func:`_phase_planes`: Z sites are never
    read), test 1 first on the whole phase and the rest on the few pixels that
    pass it; test 3 on the candidates only.
    """
    P, Q = tile.shape
    thr = np.float32(params.threshold * white_level)
    k = np.float32(params.spread_factor)
    planes = _phase_planes(data, tile)
    hmax = max(b.shape[0] for b in planes.values()) - 2 * _PAD if planes else 0
    wmax = max(b.shape[1] for b in planes.values()) - 2 * _PAD if planes else 0
    bufs = [np.empty((hmax, wmax), np.float32) for _ in range(4)]
    rr, cc, e_hot, e_cold, spread = [], [], [], [], []
    for (py, px), buf in planes.items():
        v = buf[_PAD:-_PAD, _PAD:-_PAD]
        h, w = v.shape
        mx, mn, hot, cold = (b[:h, :w] for b in bufs)
        _phase_extremes(planes, tile, py, px, mx, mn)
        with np.errstate(invalid="ignore"):
            np.subtract(v, mx, out=hot)
            np.subtract(mn, v, out=cold)
            # test 1 (thr > 0), which the rest needs, on the whole phase
            cand = np.greater(hot, thr)
            cand |= np.greater(cold, thr)
        i, j = np.nonzero(cand)
        if i.size == 0:
            continue
        # test 2 on the few that pass (a pixel without neighbours has NaN: never passes)
        ht, cd = hot[i, j], cold[i, j]
        sp = mx[i, j] - mn[i, j]
        ksp = k * sp
        with np.errstate(invalid="ignore"):
            keep = ((ht > thr) & (ht > ksp)) | ((cd > thr) & (cd > ksp))
        rr.append(py + i[keep] * P)
        cc.append(px + j[keep] * Q)
        e_hot.append(ht[keep])
        e_cold.append(cd[keep])
        spread.append(sp[keep])
    if not rr:
        return np.zeros(0, np.intp), np.zeros(0, np.intp)
    rr = np.concatenate(rr)
    cc = np.concatenate(cc)
    if rr.size == 0:
        return rr, cc
    e_hot = np.concatenate(e_hot).astype(np.float64)
    e_cold = np.concatenate(e_cold).astype(np.float64)
    spread = np.concatenate(spread)
    # test 3 on the few candidates: high-pass of the adjacent pixels
    H, W = data.shape
    adj = np.array([(dy, dx) for dy in (-1, 0, 1) for dx in (-1, 0, 1) if dy or dx])
    qr = rr[:, None] + adj[:, 0]
    qc = cc[:, None] + adj[:, 1]
    inside = (qr >= 0) & (qr < H) & (qc >= 0) & (qc < W)
    qr, qc = np.where(inside, qr, 0), np.where(inside, qc, 0)
    uq, inv = np.unique(qr * W + qc, return_inverse=True)
    ur, uc = uq // W, uq % W
    nb = _gather_neighbours(data, tile, ur, uc, np.float32)
    cnt = np.sum(~np.isnan(nb), axis=1)
    tot = np.nansum(nb, axis=1)
    trim = cnt >= 3                        # trimmed mean: one defect nearby does not move it
    with np.errstate(invalid="ignore", divide="ignore"):
        big = np.where(cnt > 0, np.nanmax(np.where(cnt[:, None] > 0, nb, 0), axis=1), 0)
        small = np.where(cnt > 0, np.nanmin(np.where(cnt[:, None] > 0, nb, 0), axis=1), 0)
        mean = np.where(trim, (tot - big - small) / np.maximum(cnt - 2, 1),
                        tot / np.maximum(cnt, 1))
        hp = np.where(cnt > 0, _site_values(data, tile, ur, uc, np.float32) - mean,
                      np.nan)                                   # NaN at Z sites
    hp = hp[inv.reshape(qr.shape)]
    hp[~inside] = np.nan
    f = params.cross_factor
    with np.errstate(invalid="ignore"):
        adj_hi = np.nanmax(np.where(np.isnan(hp), -np.inf, hp), axis=1)
        adj_lo = np.nanmin(np.where(np.isnan(hp), np.inf, hp), axis=1)
        is_hot = (e_hot > thr) & (e_hot > k * spread) & (adj_hi < f * e_hot)
        is_cold = (e_cold > thr) & (e_cold > k * spread) & (adj_lo > -f * e_cold)
    ok = is_hot | is_cold
    return rr[ok], cc[ok]


def correct_defects(cfa, pattern, params=DefectCorrection(), *, white_level=2047, known=None,
                    return_mask=False):
    """Replace defective colour pixels by the median of their same-colour neighbours.

    Parameters
    ----------
    cfa : ndarray, shape (rows, cols)
        Raw frame in DN. The values at Z sites are neither read nor changed.
    pattern : Pattern or str
    params : DefectCorrection
    white_level : float
        Full scale in DN.
    known : ndarray of bool, shape (rows, cols), optional
        Known defects (a factory defect map), corrected in addition to the
        detected ones (Z sites in it are ignored).
    return_mask : bool
        Also return the map of corrected pixels.

    Returns
    -------
    out : ndarray, same shape and dtype as ``cfa``
        A copy (the input is never modified).
    mask : ndarray of bool
        Only with ``return_mask``.
    """
    data, pattern = _prepare_cfa(cfa, pattern)
    if not isinstance(params, DefectCorrection):
        raise TypeError(f"params: expected DefectCorrection, got {type(params).__name__}")
    white_level = _real(white_level, "white_level", lo=0, lo_open=True)
    if known is not None:
        kn = np.asarray(known)
        if kn.shape != data.shape or kn.dtype != np.bool_:
            raise ValueError(f"known: expected a bool map of shape {data.shape}, got "
                             f"{kn.dtype} {kn.shape}")
    mask = np.zeros(data.shape, bool)
    rr, cc = (_detect_sites(data, pattern.tile, params, white_level) if params.enabled
              else (np.zeros(0, np.intp),) * 2)
    mask[rr, cc] = True
    if known is not None:
        mask |= kn & ~pattern.z_mask(data.shape)
        rr, cc = np.nonzero(mask)
    out = data.copy()
    if rr.size:
        # a defect never repairs another one: the flagged pixels are hidden, as Z sites are
        nb = _gather_neighbours(data, pattern.tile, rr, cc, np.float64, hidden=mask)
        ok = ~np.isnan(nb)
        m = ok.sum(axis=1)
        srt = np.sort(nb, axis=1)             # NaN sorts last
        idx = np.arange(rr.size)
        lo = srt[idx, np.maximum(m - 1, 0) // 2]
        hi = srt[idx, m // 2]
        values = np.where(m > 0, 0.5 * (lo + hi), data[rr, cc])   # no neighbour: kept
        if np.issubdtype(out.dtype, np.integer):
            values = np.floor(values + 0.5)
        out[rr, cc] = values.astype(out.dtype)
        mask[rr[m == 0], cc[m == 0]] = False
    return (out, mask) if return_mask else out


def fill_missing(cfa, pattern, params=Reconstruction(), *, bit_depth=11, workers=None):
    """Reconstruct the colour missing at the Z sites: RGB-Z CFA -> full Bayer CFA.

    Delegates to :func:`rgbz_fast.reconstruct`. A pattern without Z sites
    returns a copy of its input (the reference path).

    Returns
    -------
    cfa : ndarray, same dtype
        The CFA of the underlying Bayer phase.
    """
    data, pattern = _prepare_cfa(cfa, pattern)
    if not isinstance(params, Reconstruction):
        raise TypeError(f"params: expected Reconstruction, got {type(params).__name__}")
    if not pattern.has_z:
        return data.copy()
    return reconstruct(data, params.method, pattern=pattern, bit_depth=bit_depth,
                       precision=params.precision, workers=workers, **dict(params.options))


def _black_white(black_level, white_level):
    white = _real(white_level, "white_level", lo=0, lo_open=True)
    black = _real(black_level, "black_level", lo=0)
    if black >= white:
        raise ValueError(f"black_level: {black:g} must be below the white level {white:g}")
    return black, white


def grey_world_gains(cfa, phase="GRBG", *, black_level=0.0, white_level=2047):
    """Grey-world white-balance gains of a Bayer CFA: ``mean(G) / mean(c)``, green = 1.

    Means of the black-subtracted values of each colour over the pixels
    below the white level (clipped pixels carry no colour). A colour with no
    signal keeps the gain 1.

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
    data = check_image(cfa, "cfa", ndim=2)
    pattern = get_pattern(phase)
    if pattern.has_z:
        raise ValueError(f"phase: the white balance needs a complete Bayer CFA, got pattern "
                         f"{pattern.name!r} with Z sites (fill_missing first)")
    black, white = _black_white(black_level, white_level)
    tile = pattern.bayer_tile()                      # 2x2
    sums, counts = np.zeros(3), np.zeros(3)
    for py in range(2):
        for px in range(2):
            sub = data[py::2, px::2]
            ok = sub < white                             # clipped pixels carry no colour
            sums[tile[py, px]] += np.sum(sub[ok], dtype=np.float64) - black * ok.sum()
            counts[tile[py, px]] += ok.sum()
    means = np.divide(sums, counts, out=np.zeros(3), where=counts > 0)
    gains = np.ones(3)
    if means[1] > 0:
        good = means > 0
        gains[good] = means[1] / means[good]
    return gains


def white_balance(cfa, phase="GRBG", params=WhiteBalance(), *, black_level=0.0,
                  white_level=2047, gains=None, dtype=np.float32):
    """Normalise a Bayer CFA and apply white-balance gains.

    ``(v - black) / (white - black) * gain[colour]``, clipped to [0, 1] when
    ``params.clip``.

    Parameters
    ----------
    cfa : ndarray, shape (rows, cols)
        Complete Bayer CFA in DN.
    phase : str or Pattern
    params : WhiteBalance
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
    data = check_image(cfa, "cfa", ndim=2)
    if not isinstance(params, WhiteBalance):
        raise TypeError(f"params: expected WhiteBalance, got {type(params).__name__}")
    pattern = get_pattern(phase)
    if pattern.has_z:
        raise ValueError(f"phase: the white balance needs a complete Bayer CFA, got pattern "
                         f"{pattern.name!r} with Z sites (fill_missing first)")
    black, white = _black_white(black_level, white_level)
    if gains is not None:
        g = _check_gains(gains, "gains")
    elif params.gains is not None:
        g = np.asarray(params.gains, np.float64)
    elif params.method == "grey_world":
        g = grey_world_gains(data, pattern, black_level=black, white_level=white)
    else:
        g = np.ones(3)
    scale = (g / (white - black)).astype(dt)
    out = data.astype(dt)
    out -= dt.type(black)
    tile = pattern.bayer_tile()                      # 2x2
    for py in range(2):
        for px in range(2):
            out[py::2, px::2] *= scale[tile[py, px]]
    if params.clip:
        np.clip(out, 0, 1, out=out)
    return out, g


def correct_colour(rgb, params=ColourCorrection()):
    """Apply the 3x3 colour correction and clip to [0, 1].

    Parameters
    ----------
    rgb : ndarray, shape (rows, cols, 3)
        Linear, white-balanced camera RGB.
    params : ColourCorrection

    Returns
    -------
    ndarray, same shape and float dtype (a new array)
    """
    a = check_image(rgb, "rgb", ndim=3)
    if a.shape[2] != 3:
        raise ValueError(f"rgb: expected 3 channels in the last axis, got shape {a.shape}")
    if not isinstance(params, ColourCorrection):
        raise TypeError(f"params: expected ColourCorrection, got {type(params).__name__}")
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
    a = check_image(linear, "linear")
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
    """Linear RGB in [0, 1] -> 8- or 16-bit sRGB: ``floor(oetf(v) * (2**bits - 1) + 0.5)``."""
    if bits not in (8, 16) or isinstance(bits, bool):
        raise ValueError(f"bits: expected 8 or 16, got {bits!r}")
    return _quantise(srgb_oetf(linear), bits)


def _quantise(encoded, bits):
    """floor(v * (2**bits - 1) + 0.5) as uint8 / uint16, for v in [0, 1]."""
    t = encoded.dtype.type
    x = encoded * t((1 << bits) - 1)
    x += t(0.5)
    np.floor(x, out=x)
    return x.astype(np.uint8 if bits == 8 else np.uint16)


# =========================================================================== the chain
@dataclass(frozen=True)
class ColourISP:
    """The colour ISP chain (paper Fig. 18): a frozen set of stage parameters.

    Attributes
    ----------
    defects : DefectCorrection
    reconstruction : Reconstruction
        Used only when the frame's pattern has Z sites.
    white_balance : WhiteBalance
    demosaicing : Demosaic
    colour_correction : ColourCorrection
    output_bits : {8, 16}
        Bits of the sRGB output.
    black_level : float or None
        DN. None: ``frame.meta["colour_sensor"].black_level`` when the frame
        comes from :func:`rgbz_fast.sensor.simulate`, else 0.
    precision : {"float32", "float64"}
        Float type from the white balance on.

    Examples
    --------
    >>> import numpy as np
    >>> import rgbz_fast as rz
    >>> from rgbz_fast.isp import ColourISP
    >>> frame = rz.mosaic(np.full((8, 8, 3), 0.5), "mask1")
    >>> out, stages = ColourISP().run(frame, return_stages=True)
    >>> out.shape, out.dtype, int(out[4, 4, 1])
    ((8, 8, 3), dtype('uint8'), 188)
    >>> [k for k in stages if k in rz.isp.STAGES] == list(rz.isp.STAGES)
    True
    """

    defects: DefectCorrection = DefectCorrection()
    reconstruction: Reconstruction = Reconstruction()
    white_balance: WhiteBalance = WhiteBalance()
    demosaicing: Demosaic = Demosaic()
    colour_correction: ColourCorrection = ColourCorrection()
    output_bits: int = 8
    black_level: float | None = None
    precision: str = "float32"

    def __post_init__(self):
        for name, cls in (("defects", DefectCorrection), ("reconstruction", Reconstruction),
                          ("white_balance", WhiteBalance), ("demosaicing", Demosaic),
                          ("colour_correction", ColourCorrection)):
            if not isinstance(getattr(self, name), cls):
                raise TypeError(f"ColourISP.{name}: expected {cls.__name__}, got "
                                f"{type(getattr(self, name)).__name__}")
        if isinstance(self.output_bits, bool) or self.output_bits not in (8, 16):
            raise ValueError(f"ColourISP.output_bits: expected 8 or 16, got "
                             f"{self.output_bits!r}")
        if self.black_level is not None:
            _real(self.black_level, "ColourISP.black_level", lo=0)
        object.__setattr__(self, "precision", check_choice(self.precision, tuple(_PRECISIONS),
                                                           "ColourISP.precision"))

    # ------------------------------------------------------------------ helpers
    def _inputs(self, frame, pattern, bit_depth, black_level, reference):
        if isinstance(frame, RawFrame):
            if pattern is not None and get_pattern(pattern) != frame.pattern:
                raise ValueError(f"pattern: {get_pattern(pattern).name!r} differs from the "
                                 f"frame's pattern {frame.pattern.name!r}")
            if bit_depth is not None and check_bit_depth(bit_depth) != frame.bit_depth:
                raise ValueError(f"bit_depth: {bit_depth} differs from the frame's "
                                 f"{frame.bit_depth}")
            bd = frame.bit_depth
            if reference:
                if frame.reference is None:
                    raise ValueError("reference: the frame holds no reference Bayer CFA "
                                     "(frame.reference is None)")
                data, pat = frame.reference, frame.pattern.bayer_pattern()
            else:
                data, pat = frame.data, frame.pattern
            sensor = frame.meta.get("colour_sensor")
            meta_black = getattr(sensor, "black_level", None)
        else:
            if reference:
                raise ValueError("reference: needs a RawFrame with a reference CFA")
            if pattern is None:
                raise TypeError("pattern: required when frame is a plain array "
                                "(pass a RawFrame, or pattern='bayer', 'mask1', ...)")
            data = check_image(frame, "frame", ndim=2, dtypes=FRAME_DTYPES)
            pat = get_pattern(pattern)
            bd = check_bit_depth(11 if bit_depth is None else bit_depth)
            RawFrame(data, pat, bd)                       # shape, range, finiteness
            meta_black = None
        if pat.bayer_phase is None:
            raise ValueError(f"pattern: {pat.name!r} fits no Bayer phase; the chain needs "
                             "a Bayer-derived pattern")
        if black_level is None:
            black_level = self.black_level
        if black_level is None:
            black_level = meta_black if meta_black is not None else 0.0
        black, white = _black_white(black_level, (1 << bd) - 1)
        return data, pat, bd, black, white

    # ------------------------------------------------------------------ run
    def run(self, frame, *, pattern=None, bit_depth=None, black_level=None, gains=None,
            reference=False, defects=None, workers=None, return_stages=False):
        """Run the chain: raw frame -> 8- or 16-bit sRGB image.

        Parameters
        ----------
        frame : RawFrame or ndarray, shape (rows, cols)
            The raw frame. A plain array needs ``pattern`` (and ``bit_depth``
            if not 11).
        pattern : Pattern or str, optional
            The pattern of a plain-array frame. The reconstruction runs only
            when it has Z sites, so a Bayer frame takes the reference path.
        bit_depth : int, optional
            Bits of a plain-array frame (11).
        black_level : float, optional
            DN; overrides :attr:`black_level`.
        gains : array_like (3,), optional
            White-balance gains (R, G, B) to use instead of estimating them:
            pass the reference path's gains (``stages["gains"]``) to the RGB-Z
            path for the paper's comparison (Fig. 19).
        reference : bool
            Run ``frame.reference`` (the plain Bayer CFA of the same
            exposure) on the frame's underlying Bayer pattern: the reference
            path, no reconstruction.
        defects : ndarray of bool, optional
            Known defects, corrected in addition to the detected ones.
        workers : int, optional
            Threads of the C kernels (None or -1: all cores).
        return_stages : bool
            Also return a dict of every intermediate result.

        Returns
        -------
        image : ndarray of uint8 or uint16, shape (rows, cols, 3)
            sRGB.
        stages : dict
            Only with ``return_stages``. In order: ``"raw"`` (input CFA, DN),
            ``"defect_mask"`` (bool), ``"defect_correction"`` (CFA, DN),
            ``"reconstruction"`` (full Bayer CFA, DN; the same array as the
            previous stage when the pattern has no Z), ``"gains"`` (R, G, B),
            ``"white_balance"`` (normalised CFA in [0, 1]), ``"demosaic"``
            (linear RGB, not clipped), ``"colour_correction"`` (linear RGB in
            [0, 1]), ``"gamma"`` (sRGB-encoded floats in [0, 1]),
            ``"output"`` (the returned image), ``"seconds"`` (time per
            stage), ``"pattern"``, ``"black_level"``, ``"white_level"``.
        """
        data, pat, bd, black, white = self._inputs(frame, pattern, bit_depth, black_level,
                                                   reference)
        dt = _PRECISIONS[self.precision]
        bayer = pat.bayer_pattern()
        seconds = {}
        t0 = time.perf_counter()

        def tick(name):
            nonlocal t0
            t1 = time.perf_counter()
            seconds[name] = t1 - t0
            t0 = t1

        fixed, mask = correct_defects(data, pat, self.defects, white_level=white,
                                      known=defects, return_mask=True)
        tick("defect_correction")
        full = fill_missing(fixed, pat, self.reconstruction, bit_depth=bd,
                            workers=workers) if pat.has_z else fixed
        tick("reconstruction")
        balanced, used = white_balance(full, bayer, self.white_balance, black_level=black,
                                       white_level=white, gains=gains, dtype=dt)
        tick("white_balance")
        rgb = demosaic(balanced, bayer.bayer_phase, self.demosaicing.method,
                       mode=self.demosaicing.mode, dtype=dt, workers=workers)
        tick("demosaic")
        corrected = correct_colour(rgb, self.colour_correction)
        tick("colour_correction")
        encoded = srgb_oetf(corrected)
        tick("gamma")
        out = _quantise(encoded, self.output_bits)
        tick("output")
        if not return_stages:
            return out
        stages = {"raw": data, "defect_mask": mask, "defect_correction": fixed,
                  "reconstruction": full, "gains": used, "white_balance": balanced,
                  "demosaic": rgb, "colour_correction": corrected, "gamma": encoded,
                  "output": out, "seconds": seconds, "pattern": pat,
                  "black_level": black, "white_level": white}
        return out, stages

    def run_pair(self, frame, *, workers=None, return_stages=False):
        """Both paths of Fig. 19 with the same white balance: (reference, RGB-Z) images.

        The gains are estimated on the reference CFA (or taken from
        ``white_balance``) and reused on the RGB-Z frame, so the two images
        differ by the missing-colour reconstruction only.

        Returns
        -------
        reference_image, rgbz_image : ndarray
        reference_stages, rgbz_stages : dict
            Only with ``return_stages``.
        """
        if not isinstance(frame, RawFrame):
            raise TypeError(f"frame: expected a RawFrame with a reference CFA, got "
                            f"{type(frame).__name__}")
        ref, ref_st = self.run(frame, reference=True, workers=workers, return_stages=True)
        test, test_st = self.run(frame, gains=ref_st["gains"], workers=workers,
                                 return_stages=True)
        if return_stages:
            return ref, test, ref_st, test_st
        return ref, test
