"""Learned directional reconstruction: hashed linear filters fitted by regularised least squares.

Every Z site of a pattern is filled in by one dot product: the known pixels of
the 7x7 window (any colour) times the filter of its *bucket*. The bucket is a
cheap hash of the local structure computed from the known pixels only, in the
spirit of RAISR [1]_: mean squared differences of same-colour pixels two apart
along the four directions give a structure tensor, quantised into 8
orientations x 3 strengths x 3 coherences. The filters are fitted per (Z
site of the tile, bucket) on a training set; the ones shipped in
``reconstruction/data/`` were fitted on CBSD68 [2]_ (not Kodak, on which the
library is evaluated). docs/guide/learned.md is the specification.

References
----------
.. [1] Romano et al., "RAISR: Rapid and Accurate Image Super Resolution" (docs/references.bib: romano2017raisr)
.. [2] Martin et al., the BSDS300 test images, "CBSD68" (docs/references.bib: martin2001bsds)
"""

from __future__ import annotations

import hashlib
import io
import math
from functools import lru_cache
from pathlib import Path

import numpy as np

from .._frame import RawFrame
from .._patterns import Pattern, Z, get_pattern
from .._validate import check_bit_depth, check_flag, check_int, check_number
from ..io import atomic_write, read_npz

__all__ = ["LearnedFilters", "train", "default_filters", "learned_geometry",
           "hash_buckets", "N_ANGLES", "FORMAT_VERSION"]

#: version of the .npz layout; a file of another version is refused
FORMAT_VERSION = 1
#: orientation bins of the hash (45 degrees of the doubled angle each)
N_ANGLES = 8
#: the four hash directions: steps between two same-colour pixels (horizontal,
#: vertical, main diagonal, anti-diagonal)
HASH_STEPS = ((0, 2), (2, 0), (2, 2), (2, -2))
_COS, _SIN = math.cos(math.pi / 8), math.sin(math.pi / 8)
_DATA = Path(__file__).resolve().parent / "data"
_MAGIC = "rgbz-fast learned filters"


@lru_cache(maxsize=64)
def learned_geometry(pattern, radius=3, hash_radius=3):
    """Per Z site of the tile: the taps, the target colour and the hash pairs.

    Returns a tuple with one dict per Z position of the tile (row-major):
    ``rc`` (its tile position), ``taps`` ((n, 2) int array of (dy, dx): the
    known pixels of the (2 radius + 1)^2 window, row-major), ``colours``
    (channel of each tap), ``target`` (the colour to fill in), ``base`` (the
    taps of the target colour within 5x5, whose mean the fit starts from) and
    ``pairs`` (for each direction of :data:`HASH_STEPS`, an (m, 2) array of tap
    indices: both pixels known, of one colour, within ``hash_radius``).
    """
    pattern = get_pattern(pattern)
    tile, btile = pattern.tile, pattern.bayer_tile()
    P, Q = pattern.period
    out = []
    for r in range(P):
        for c in range(Q):
            if tile[r, c] != Z:
                continue

            def ch(dy, dx, r=r, c=c):
                return int(tile[(r + dy) % P, (c + dx) % Q])

            taps = [(dy, dx) for dy in range(-radius, radius + 1)
                    for dx in range(-radius, radius + 1) if ch(dy, dx) != Z]
            index = {t: i for i, t in enumerate(taps)}
            colours = np.array([ch(*t) for t in taps], np.int32)
            target = int(btile[r, c])
            base = [i for i, (dy, dx) in enumerate(taps)
                    if abs(dy) <= 2 and abs(dx) <= 2 and colours[i] == target]
            if not base:
                raise ValueError(f"pattern: the Z site ({r}, {c}) of {pattern.name!r} has no "
                                 f"known pixel of its colour ({'RGB'[target]}) in the 5x5 "
                                 "window, so 'learned' cannot reconstruct it")
            pairs = []
            for sy, sx in HASH_STEPS:
                pp = [(i, index[(dy + sy, dx + sx)]) for i, (dy, dx) in enumerate(taps)
                      if (dy + sy, dx + sx) in index
                      and max(abs(dy), abs(dx), abs(dy + sy), abs(dx + sx)) <= hash_radius
                      and colours[i] == colours[index[(dy + sy, dx + sx)]]]
                if not pp:
                    raise ValueError(f"pattern: the Z site ({r}, {c}) of {pattern.name!r} has no "
                                     f"same-colour pair along ({sy}, {sx}) within the hash "
                                     f"radius {hash_radius}")
                pairs.append(np.array(pp, np.int32).reshape(-1, 2))
            out.append({"rc": (r, c), "taps": np.array(taps, np.int32).reshape(-1, 2),
                        "colours": colours, "target": target, "base": np.array(base),
                        "pairs": tuple(pairs)})
    return tuple(out)


def hash_features(X, pairs):
    """The structure-tensor terms ``(a, b, t)`` of windows ``X`` (n_sites, n_taps), float64.

    ``E_d`` is the mean of the squared differences of the pairs of direction
    d; ``a = E_h - E_v``, ``b = (E_d1 - E_d2) / 2`` (the doubled-angle vector)
    and ``t = (E_h + E_v) / 2 + (E_d1 + E_d2) / 4`` (the energy).
    """
    E = []
    for pp in pairs:
        d = X[:, pp[:, 0]] - X[:, pp[:, 1]]
        E.append((d * d).sum(1) * (1.0 / len(pp)))
    eh, ev, ed1, ed2 = E
    return eh - ev, (ed1 - ed2) * 0.5, (eh + ev) * 0.5 + (ed1 + ed2) * 0.25


def hash_buckets(a, b, t, strength_thresholds, coherence_thresholds):
    """Bucket of every site: ``(angle * n_strength + strength) * n_coherence + coherence``.

    Angle: the octant of the doubled-angle vector ``(a, b)`` rotated by 22.5
    degrees (8 bins of 22.5 degrees of edge orientation, the first centred on
    the horizontal gradient), by sign tests and one comparison -- no
    arctangent; a flat window (``a = b = 0``) is in octant 0. Strength: how many thresholds ``t`` exceeds. Coherence: how
    many thresholds ``c`` satisfy ``a^2 + b^2 > c^2 (t t)`` (coherence
    ``sqrt(a^2 + b^2) / t`` without a root or a division), as the C kernel
    computes it.
    """
    ar = _COS * a - _SIN * b
    br = _SIN * a + _COS * b
    neg = br < 0
    ar, br = np.where(neg, -ar, ar), np.where(neg, -br, br)
    left = ar < 0
    ar, br = np.where(left, br, ar), np.where(left, -ar, br)
    octant = 4 * neg + 2 * left + (br > ar)
    s = np.zeros(a.shape, np.int64)
    for thr in strength_thresholds:
        s += t > thr
    m2 = a * a + b * b
    t2 = t * t
    c = np.zeros(a.shape, np.int64)
    for thr in coherence_thresholds:
        c += m2 > (thr * thr) * t2
    ns, nc = len(strength_thresholds) + 1, len(coherence_thresholds) + 1
    return (octant * ns + s) * nc + c


def _extend_index(n, pad, period):
    """Indices -pad..n+pad-1 moved inside [0, n) by whole periods (the kernels' border rule)."""
    i = np.arange(-pad, n + pad)
    out = i.copy()
    lo, hi = i < 0, i >= n
    out[lo] = i[lo] + period * (-(i[lo] // period))
    out[hi] = i[hi] - period * (-(-(i[hi] - n + 1) // period))
    return out


def gather_windows(data, pattern, radius, geometry):
    """For each phase: (windows (n_sites, n_taps) float64, (row0, col0, n_rows, n_cols))."""
    P, Q = pattern.period
    H, W = data.shape
    pad = data[_extend_index(H, radius, P)][:, _extend_index(W, radius, Q)].astype(np.float64)
    out = []
    for ph in geometry:
        r, c = ph["rc"]
        ny, nx = len(range(r, H, P)), len(range(c, W, Q))
        X = np.empty((ny * nx, len(ph["taps"])))
        for t, (dy, dx) in enumerate(ph["taps"]):
            X[:, t] = pad[radius + r + dy::P, radius + c + dx::Q][:ny, :nx].reshape(-1)
        out.append((X, (r, c, ny, nx)))
    return out


class LearnedFilters:
    """Hashed linear filters of one pattern and bit depth (``method="learned"``).

    Made by :func:`train` or read by :meth:`load`; :func:`default_filters`
    gives the ones shipped with the package. Immutable; equal when their
    contents are (:attr:`digest`).

    Parameters
    ----------
    pattern : Pattern or str
        The pattern the filters reconstruct.
    bit_depth : int
        Bits of the frames they were fitted to (the hash thresholds are in
        those digital numbers).
    weights : ndarray, shape (n_phases, n_buckets, n_taps_max)
        The filter of each (Z site of the tile, bucket): weights of the taps
        of :func:`learned_geometry` (zeros past a phase's own tap count).
    strength_thresholds, coherence_thresholds : ndarray, shape (n_phases, k)
        The hash thresholds of each phase (increasing).
    radius, hash_radius : int
        Window radius of the taps (3: 7x7) and of the hash pairs.
    meta : dict, optional
        What they were fitted on: ``training_set``, ``n_images``, ``noise``,
        ``encoding``, ``ridge``, ``prior``, ``library_version``... (strings
        and numbers, kept in the file).

    Examples
    --------
    >>> from rgbz_fast.reconstruction import default_filters
    >>> f = default_filters("mask1", 11)
    >>> f.pattern.name, f.bit_depth, f.n_buckets, f.meta["training_set"]
    ('mask1', 11, 72, 'cbsd68')
    """

    def __init__(self, pattern, bit_depth, weights, strength_thresholds, coherence_thresholds,
                 *, radius=3, hash_radius=3, meta=None):
        self.pattern = get_pattern(pattern)
        self.bit_depth = check_bit_depth(bit_depth)
        self.radius = check_int(radius, "radius", lo=2, hi=5)
        self.hash_radius = check_int(hash_radius, "hash_radius", lo=2, hi=self.radius)
        self.geometry = learned_geometry(self.pattern, self.radius, self.hash_radius)
        n_ph = len(self.geometry)
        n_taps = max(len(g["taps"]) for g in self.geometry)
        s_thr = np.array(strength_thresholds, np.float64, ndmin=2)
        c_thr = np.array(coherence_thresholds, np.float64, ndmin=2)
        # kept at float32 precision, as the file stores them: a fit and its file are equal
        w = np.array(weights, np.float64).astype(np.float32).astype(np.float64)
        if s_thr.shape[0] != n_ph or c_thr.shape[0] != n_ph:
            raise ValueError(f"filters: expected thresholds for {n_ph} phases, got "
                             f"{s_thr.shape[0]} and {c_thr.shape[0]}")
        nb = N_ANGLES * (s_thr.shape[1] + 1) * (c_thr.shape[1] + 1)
        if w.shape != (n_ph, nb, n_taps):
            raise ValueError(f"filters: expected weights of shape {(n_ph, nb, n_taps)} for "
                             f"pattern {self.pattern.name!r} and these thresholds, got {w.shape}")
        for name, a in (("weights", w), ("strength_thresholds", s_thr),
                        ("coherence_thresholds", c_thr)):
            if not np.all(np.isfinite(a)):
                raise ValueError(f"filters: {name} holds NaN or infinity")
        if np.any(np.diff(s_thr, axis=1) < 0) or np.any(np.diff(c_thr, axis=1) < 0):
            raise ValueError("filters: hash thresholds must be increasing")
        for a in (w, s_thr, c_thr):
            a.setflags(write=False)
        self.weights, self.strength_thresholds, self.coherence_thresholds = w, s_thr, c_thr
        self.meta = {str(k): (v if isinstance(v, (int, float)) else str(v))
                     for k, v in dict(meta or {}).items()}
        h = hashlib.sha1()
        for part in (self.pattern.tile_string, self.bit_depth, self.radius, self.hash_radius):
            h.update(repr(part).encode())
        for a in (w, s_thr, c_thr):
            h.update(np.ascontiguousarray(a).tobytes())
        self.digest = h.hexdigest()[:16]
        self._kernel = None

    @property
    def n_buckets(self):
        return self.weights.shape[1]

    @property
    def n_strength(self):
        return self.strength_thresholds.shape[1] + 1

    @property
    def n_coherence(self):
        return self.coherence_thresholds.shape[1] + 1

    def __repr__(self):
        src = self.meta.get("training_set", "?")
        return (f"LearnedFilters(pattern={self.pattern.name!r}, bit_depth={self.bit_depth}, "
                f"buckets={self.n_buckets}, trained on {src!r}, digest={self.digest})")

    __str__ = __repr__

    def __eq__(self, other):
        return isinstance(other, LearnedFilters) and other.digest == self.digest

    def __hash__(self):
        return hash(self.digest)

    def check_frame(self, pattern, bit_depth, name="filters"):
        """ValueError naming ``name`` unless the filters fit a frame of ``pattern`` and bits."""
        if get_pattern(pattern) != self.pattern:
            raise ValueError(f"{name}: fitted for pattern {self.pattern.name!r} "
                             f"({self.pattern.tile_string}), the frame's is "
                             f"{get_pattern(pattern).name!r}")
        if bit_depth != self.bit_depth:
            raise ValueError(f"{name}: fitted for {self.bit_depth}-bit frames, the frame has "
                             f"{bit_depth} bits")

    def reconstruct(self, data, dtype=np.float64):
        """NumPy reconstruction of a frame ``data`` (unclipped, unrounded, float64).

        The slow path of :func:`train` (to score a fit); the C kernel of
        :func:`rgbz_fast.reconstruct` computes the same in one pass.
        """
        out = np.array(data, dtype=dtype)
        for k, (X, (r, c, ny, nx)) in enumerate(
                gather_windows(data, self.pattern, self.radius, self.geometry)):
            ph = self.geometry[k]
            bk = hash_buckets(*hash_features(X, ph["pairs"]), self.strength_thresholds[k],
                              self.coherence_thresholds[k])
            w = self.weights[k][:, :X.shape[1]]
            out[r::self.pattern.period[0], c::self.pattern.period[1]][:ny, :nx] = \
                np.einsum("ij,ij->i", X, w[bk]).reshape(ny, nx)
        return out

    def kernel_arrays(self):
        """The arrays of the C kernel's ``rgbz_learned_filters`` (csrc/learned.h), made once."""
        if self._kernel is None:
            g = self.geometry
            n_ph, nt = self.weights.shape[0], self.weights.shape[2]
            npmax = max(len(pp) for ph in g for pp in ph["pairs"])
            n_taps = np.array([len(ph["taps"]) for ph in g], np.int32)
            tap_dy = np.zeros((n_ph, nt), np.int32)
            tap_dx = np.zeros((n_ph, nt), np.int32)
            n_pairs = np.zeros((n_ph, 4), np.int32)
            pair_a = np.zeros((n_ph, 4, npmax), np.int32)
            pair_b = np.zeros((n_ph, 4, npmax), np.int32)
            for k, ph in enumerate(g):
                tap_dy[k, :n_taps[k]], tap_dx[k, :n_taps[k]] = ph["taps"].T
                for d, pp in enumerate(ph["pairs"]):
                    n_pairs[k, d] = len(pp)
                    pair_a[k, d, :len(pp)], pair_b[k, d, :len(pp)] = pp.T
            w64 = np.ascontiguousarray(self.weights.transpose(0, 2, 1))
            self._kernel = dict(
                n_taps=n_taps, tap_dy=tap_dy, tap_dx=tap_dx, n_pairs=n_pairs, pair_a=pair_a,
                pair_b=pair_b, str_thr=np.ascontiguousarray(self.strength_thresholds),
                coh_thr2=np.ascontiguousarray(self.coherence_thresholds ** 2),
                w_f32=w64.astype(np.float32), w_f64=w64, radius=self.radius,
                hash_radius=self.hash_radius)
            if self.radius <= 3:
                # the kernel's fast path: each window row as 8 weights, 0 off the taps
                R = self.radius
                dense = np.zeros((n_ph, self.n_buckets, 2 * R + 1, 8))
                for k, ph in enumerate(g):
                    # (advanced indices around a slice put the tap axis first)
                    dense[k, :, ph["taps"][:, 0] + R, ph["taps"][:, 1] + R] = \
                        self.weights[k, :, :len(ph["taps"])].T
                self._kernel.update(wd_f32=dense.astype(np.float32), wd_f64=dense)
        return self._kernel

    # -- files ------------------------------------------------------------------
    def to_bytes(self):
        """The .npz file's content (see :meth:`save`)."""
        buf = io.BytesIO()
        np.savez(buf, format=np.array(_MAGIC), version=np.array(FORMAT_VERSION),
                 pattern=np.array(self.pattern.tile_string),
                 pattern_name=np.array(self.pattern.name),
                 bayer=np.array(self.pattern.bayer_phase), bit_depth=np.array(self.bit_depth),
                 radius=np.array(self.radius), hash_radius=np.array(self.hash_radius),
                 n_angles=np.array(N_ANGLES),
                 weights=self.weights.astype(np.float32),
                 strength_thresholds=self.strength_thresholds,
                 coherence_thresholds=self.coherence_thresholds,
                 meta_keys=np.array(list(self.meta), dtype=str),
                 meta_values=np.array([repr(v) for v in self.meta.values()], dtype=str))
        return buf.getvalue()

    def save(self, path):
        """Write the filters to ``path`` (.npz, atomically): weights in float32, the pattern,
        the bit depth, the hash thresholds and the metadata (training set, ...)."""
        atomic_write(path, self.to_bytes())

    @classmethod
    def load(cls, path, name="filters", *, max_bytes=None):
        """Read a file written by :meth:`save`; ValueError naming ``name`` if it is not one.
        ``max_bytes``: the read limit (:func:`rgbz_fast.io.read_limits`)."""
        p = Path(path)
        z = read_npz(p, name, max_bytes=max_bytes)   # bounded, no pickles, zip bombs refused
        if "format" not in z or z["format"].dtype.kind not in "US" or str(z["format"]) != _MAGIC:
            raise ValueError(f"{name}: {p} is not a rgbz-fast filters file")
        try:
            return cls._from_arrays(z, p, name)
        except KeyError as e:
            raise ValueError(f"{name}: {p} lacks {e} (a damaged filters file)") from None
        except (TypeError, ValueError, SyntaxError, RecursionError, MemoryError) as e:
            msg = str(e)
            if msg.startswith(f"{name}: "):
                raise ValueError(msg) from None
            raise ValueError(f"{name}: {p} is a damaged filters file ({type(e).__name__}: "
                             f"{msg[:200]})") from None

    @classmethod
    def _from_arrays(cls, z, p, name):
        if int(z["version"]) != FORMAT_VERSION:
            raise ValueError(f"{name}: {p} has format version {int(z['version'])}, this "
                             f"library reads version {FORMAT_VERSION}")
        import ast
        keys, values = z["meta_keys"].tolist(), z["meta_values"].tolist()
        if not isinstance(keys, list) or not isinstance(values, list):
            raise TypeError("meta_keys and meta_values must be 1-d arrays")
        meta = {str(k): ast.literal_eval(str(v)[:100_000]) for k, v in zip(keys, values)}
        if int(z["n_angles"]) != N_ANGLES:
            raise ValueError(f"{name}: {p} has {int(z['n_angles'])} angle bins, expected "
                             f"{N_ANGLES}")
        try:
            pattern = Pattern(str(z["pattern"]), name=str(z["pattern_name"]), bayer=str(z["bayer"]))
        except (ValueError, TypeError) as e:
            raise ValueError(f"{name}: {p} holds an invalid pattern ({e})") from None
        return cls(pattern, int(z["bit_depth"]), z["weights"].astype(np.float64),
                   z["strength_thresholds"], z["coherence_thresholds"],
                   radius=int(z["radius"]), hash_radius=int(z["hash_radius"]), meta=meta)


def resolve_filters(filters, pattern, bit_depth, name="filters"):
    """The :class:`LearnedFilters` for a frame: ``filters`` (one, a file, or several to pick
    from by pattern and bit depth) or, when None, the shipped ones."""
    if filters is None:
        f = default_filters(pattern, bit_depth)
        if f is None:
            from ..io import ParameterError, Setting      # the settings, in the caller's words

            raise ParameterError(name, f"no filters ship for pattern {pattern.name!r} at "
                                 f"{bit_depth} bits; fit some with ",
                                 Setting("train", "rgbz_fast.reconstruction.train"),
                                 " and pass ", Setting("filters", "filters=FILE"))
        return f
    cands = filters if isinstance(filters, tuple) else (filters,)
    for f in cands:
        if f.pattern == pattern and f.bit_depth == bit_depth:
            return f
    if len(cands) == 1:
        cands[0].check_frame(pattern, bit_depth, name)
    have = ", ".join(f"{f.pattern.name} {f.bit_depth}-bit" for f in cands)
    raise ValueError(f"{name}: none fits pattern {pattern.name!r} at {bit_depth} bits "
                     f"(given: {have})")


def check_filters(value, name="filters"):
    """``filters`` of ReconstructParams: None, a LearnedFilters, a path, or a sequence of them
    -> None or a tuple of LearnedFilters (files read now, so a bad one fails early)."""
    if value is None:
        return None
    items = [value] if isinstance(value, (str, Path, LearnedFilters)) else value
    try:
        items = list(items)
    except TypeError:
        raise TypeError(f"{name}: expected a LearnedFilters, a path to a filters file, a "
                        f"sequence of them or None, got {type(value).__name__}") from None
    if not items:
        raise ValueError(f"{name}: empty sequence")
    out = []
    for v in items:
        if isinstance(v, LearnedFilters):
            out.append(v)
        elif isinstance(v, (str, Path)):
            out.append(LearnedFilters.load(v, name))
        else:
            raise TypeError(f"{name}: expected a LearnedFilters or a path, got "
                            f"{type(v).__name__}")
    return tuple(out)


_SHIPPED = {}


def default_filters(pattern, bit_depth=11):
    """The filters shipped for a pattern and bit depth, or None.

    The package ships Mask1 and Mask2 (GRBG) filters for 11-bit linear frames
    (the evaluation's protocol) and for 8-bit sRGB-encoded frames, fitted on
    CBSD68 (``reconstruction/data/``; ``rgbz-fast train`` made them, with the
    command in their metadata).

    Examples
    --------
    >>> from rgbz_fast.reconstruction import default_filters
    >>> default_filters("mask2", 8).meta["encoding"]
    'srgb'
    >>> default_filters("rows", 11) is None
    True
    """
    pattern = get_pattern(pattern)
    bit_depth = check_bit_depth(bit_depth)
    key = (pattern.tile_string, bit_depth)
    if key not in _SHIPPED:
        found = None
        for f in sorted(_DATA.glob("learned_*.npz")):
            lf = LearnedFilters.load(f)
            if lf.pattern == pattern and lf.bit_depth == bit_depth:
                found = lf
                break
        _SHIPPED[key] = found
    return _SHIPPED[key]


def train(frames, *, radius=3, hash_radius=3, n_strength=3, n_coherence=3, ridge=1e-3,
          prior=50.0, meta=None, z_guided=False, **z_options):
    """Fit :class:`LearnedFilters` to frames whose true colour at the Z sites is known.

    Parameters
    ----------
    frames : iterable of RawFrame
        Frames of one pattern and bit depth, each with its ``reference`` (the
        complete Bayer CFA: :func:`rgbz_fast.simulation.simulate` sets it;
        :func:`rgbz_fast.evaluation.train_filters` makes them from a folder
        of images with the evaluation's protocol).
    radius : int
        Window radius of the taps, 2..5 (3: 7x7, 40 taps on Mask1 and Mask2).
    hash_radius : int
        Radius of the pixel pairs of the hash, 2..radius.
    n_strength, n_coherence : int
        Levels of the strength and coherence of the hash, 1..8 (thresholds at
        the quantiles of the training sites). Buckets: 8 x n_strength x
        n_coherence.
    ridge : float
        Ridge term of every least-squares fit, relative to the mean diagonal
        of its normal matrix (>= 0).
    prior : float
        Weight of the phase-wide filter in each bucket's fit, in training
        sites (>= 0): a bucket with few sites stays close to the filter fitted
        on all of them (rare buckets merge into the common filter).
    meta : dict, optional
        Extra metadata kept with the filters (the training set's name...).
    z_guided : bool
        True: fit the filters of ``method="z_guided"`` instead
        (:func:`~rgbz_fast.reconstruction.train_z_guided`, with ``ridge``,
        ``prior``, ``meta`` and its own options ``**z_options``; the taps and
        hash are those of its ``base`` learned filters, so ``radius`` ...
        ``n_coherence`` keep their defaults).

    Returns
    -------
    LearnedFilters (ZGuidedFilters with ``z_guided``)

    Notes
    -----
    For each Z site of the tile the fit predicts the residual over the mean
    of the target-colour pixels of the 5x5 window (the bilinear baseline)
    from the taps minus the mean of their own colour in the window. Any
    filter of that form reproduces a flat colour exactly, and the ridge term
    pulls it towards the baseline. The fitted weights are folded into one
    weight per tap, so a reconstruction is one dot product per site.

    Examples
    --------
    >>> import dataclasses
    >>> import numpy as np
    >>> import rgbz_fast as rz
    >>> from rgbz_fast.reconstruction import train
    >>> rng = np.random.default_rng(0)
    >>> img = np.cumsum(rng.random((48, 48, 3)), axis=1) / 48
    >>> frame = rz.mosaic(img, "mask1")
    >>> frames = [dataclasses.replace(frame, reference=rz.mosaic(img, "bayer").data)]
    >>> f = train(frames, n_strength=1, n_coherence=1)
    >>> f.n_buckets, f.meta["n_images"]
    (8, 1)
    """
    if check_flag(z_guided, "z_guided"):
        from ._z_guided_fit import train_z_guided
        given = [k for k, v in (("radius", radius), ("hash_radius", hash_radius),
                                ("n_strength", n_strength), ("n_coherence", n_coherence))
                 if v != 3]
        if given:
            raise ValueError(f"{given[0]}: z_guided filters take the taps and hash of their "
                             "base learned filters; pass base= instead")
        return train_z_guided(frames, ridge=ridge, prior=prior, meta=meta, **z_options)
    if z_options:
        raise TypeError(f"{next(iter(z_options))}: not an option of train() without "
                        "z_guided=True")
    radius = check_int(radius, "radius", lo=2, hi=5)
    hash_radius = check_int(hash_radius, "hash_radius", lo=2, hi=radius)
    n_strength = check_int(n_strength, "n_strength", lo=1, hi=8)
    n_coherence = check_int(n_coherence, "n_coherence", lo=1, hi=8)
    ridge = check_number(ridge, "ridge", lo=0)
    prior = check_number(prior, "prior", lo=0)
    frames = list(frames)
    if not frames:
        raise ValueError("frames: no frames to train on")
    pattern, bit_depth = None, None
    for i, fr in enumerate(frames):
        if not isinstance(fr, RawFrame):
            raise TypeError(f"frames: expected RawFrame entries, got {type(fr).__name__} at {i}")
        if fr.reference is None:
            raise ValueError(f"frames: frame {i} has no reference CFA to learn from")
        if pattern is None:
            pattern, bit_depth = fr.pattern, fr.bit_depth
        elif fr.pattern != pattern or fr.bit_depth != bit_depth:
            raise ValueError(f"frames: frame {i} is {fr.pattern.name!r} at {fr.bit_depth} bits, "
                             f"frame 0 {pattern.name!r} at {bit_depth} bits")
    if not pattern.has_z:
        raise ValueError(f"frames: pattern {pattern.name!r} has no Z site to reconstruct")
    if pattern.bayer_phase is None:
        raise ValueError(f"frames: pattern {pattern.name!r} fits no Bayer phase")
    geometry = learned_geometry(pattern, radius, hash_radius)
    n_taps = max(len(g["taps"]) for g in geometry)
    P, Q = pattern.period
    per_phase = [([], []) for _ in geometry]
    for fr in frames:
        ref = np.asarray(fr.reference, np.float64)
        for k, (X, (r, c, ny, nx)) in enumerate(
                gather_windows(fr.data, pattern, radius, geometry)):
            per_phase[k][0].append(X)
            per_phase[k][1].append(ref[r::P, c::Q][:ny, :nx].reshape(-1))
    nb = N_ANGLES * n_strength * n_coherence
    weights = np.zeros((len(geometry), nb, n_taps))
    s_thr, c_thr, counts = [], [], []
    for k, ph in enumerate(geometry):
        X = np.concatenate(per_phase[k][0])
        y = np.concatenate(per_phase[k][1])
        a, b, t = hash_features(X, ph["pairs"])
        coh = np.sqrt(a * a + b * b) / np.maximum(t, np.finfo(float).tiny)
        st = np.quantile(t, np.arange(1, n_strength) / n_strength)
        ct = np.quantile(np.minimum(coh, 1.0), np.arange(1, n_coherence) / n_coherence)
        s_thr.append(st)
        c_thr.append(ct)
        bk = hash_buckets(a, b, t, st, ct)
        F, base = _features(X, ph)
        w = _fit(F, y - base, bk, nb, ridge, prior)
        weights[k, :, :X.shape[1]] = _fold(w, ph)
        counts.append(np.bincount(bk, minlength=nb))
    info = {"n_images": len(frames), "n_sites": int(sum(c.sum() for c in counts)),
            "empty_buckets": int(sum((c == 0).sum() for c in counts)),
            "ridge": ridge, "prior": prior}
    from .._build_config import VERSION
    info["library_version"] = VERSION
    info.update(meta or {})
    return LearnedFilters(pattern, bit_depth, weights, np.array(s_thr).reshape(len(geometry), -1),
                          np.array(c_thr).reshape(len(geometry), -1), radius=radius,
                          hash_radius=hash_radius, meta=info)


def _features(X, ph):
    """Taps minus the mean of their colour in the window, and the baseline (5x5 target mean)."""
    base = X[:, ph["base"]].mean(1)
    F = X.copy()
    for col in np.unique(ph["colours"]):
        m = ph["colours"] == col
        F[:, m] -= X[:, m].mean(1, keepdims=True)
    return F, base


def _fold(w, ph):
    """Weights on the features -> weights on the taps (prediction = weights . taps)."""
    eff = np.array(w, np.float64)
    eff[:, ph["base"]] += 1.0 / len(ph["base"])
    for col in np.unique(ph["colours"]):
        m = ph["colours"] == col
        eff[:, m] -= w[:, m].sum(1, keepdims=True) / m.sum()
    return eff


def _fit(F, y, buckets, nb, ridge, prior):
    """Ridge fits: one on every site, then one per bucket shrunk towards it by ``prior``."""
    p = F.shape[1]
    A = F.T @ F
    scale = max(np.trace(A) / p, np.finfo(float).tiny)
    eye = np.eye(p)
    wg = np.linalg.solve(A + ridge * scale * eye, F.T @ y)
    per_site = scale / len(y)
    W = np.empty((nb, p))
    order = np.argsort(buckets, kind="stable")
    bounds = np.searchsorted(buckets[order], np.arange(nb + 1))
    for j in range(nb):
        idx = order[bounds[j]:bounds[j + 1]]
        Fj = F[idx]
        Aj = Fj.T @ Fj
        lam = prior * per_site + ridge * np.trace(Aj) / p
        if lam <= 0:
            lam = ridge * scale + np.finfo(float).tiny
        W[j] = np.linalg.solve(Aj + lam * eye, Fj.T @ y[idx] + lam * wg)
    return W
