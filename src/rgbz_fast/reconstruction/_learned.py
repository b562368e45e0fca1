"""Learned directional reconstruction: hashed linear filters fitted by regularised least squares.

Every Z site of a pattern is filled in by one dot product: the known pixels of
the 7x7 window (any colour) times the filter of its *bucket*. The bucket is a
cheap hash of the local structure computed from the known pixels only, in the
spirit of RAISR [1]_: mean squared differences of same-colour pixels two apart
along the four directions give a structure tensor (8 orientations x 3
strengths x 3 coherences), and the spread of those energies across R, G and B
says how far the channels move together (3 levels). The filters are fitted
per (Z site of the tile, bucket) on a training set; the ones shipped in
``reconstruction/data/`` were fitted on CBSD68 [2]_, Manga109 pages [3]_ and
the Sun-Hays photographs [4]_ (not Kodak, on which the library is
evaluated), in both encodings a user feeds (linear and sRGB values).
docs/guide/learned.md is the specification.

References
----------
.. [1] Romano et al., "RAISR: Rapid and Accurate Image Super Resolution" (docs/references.bib: romano2017raisr)
.. [2] Martin et al., the BSDS300 test images, "CBSD68" (docs/references.bib: martin2001bsds)
.. [3] Matsui et al., "Sketch-based Manga Retrieval using Manga109 Dataset" (docs/references.bib: matsui2017manga109)
.. [4] Sun and Hays, "Super-resolution from Internet-scale Scene Matching" (docs/references.bib: sun2012superres)
"""

from __future__ import annotations

import ast
import hashlib
import io
import threading
from functools import lru_cache
from pathlib import Path

import numpy as np

from .._patterns import _PRESETS, Pattern, Z, _parse_tile, bayer, get_pattern
from .._validate import (ReadOnlyDict, check_bit_depth, check_int, read_only_state,
                         real_array)
from ..io import atomic_write, read_npz
from ._learned_hash import N_ANGLES, learned_geometry, mirror_octants
from ._learned_train import train

__all__ = ["LearnedFilters", "train", "default_filters", "resolve_filters", "check_filters",
           "FORMAT_VERSION"]

#: version of the .npz layout. 2 added the channel-spread level of the hash
#: (``spread_thresholds``); a version-1 file loads as filters with one spread level.
FORMAT_VERSION = 2
_READS = (1, 2)
_DATA = Path(__file__).resolve().parent / "data"
_MAGIC = "rgbz-fast learned filters"


class FilterIdentity:
    """A filter set is its weights: equality, hash and repr by their digest (``digest``),
    with the pattern, bit depth, bucket count and training set in the repr.

    Immutable once made (:meth:`_freeze` at the end of the constructor): an attribute
    assigned afterwards had skipped the constructor's checks (NaN weights ran), kept the
    digest (the evaluation's cache served the old weights' numbers) and was ignored by the
    kernel's cached arrays (H100). The derived state -- the kernel's arrays (``_kernel``) and
    the learned geometry, both rebuilt from the rest -- is not pickled (H101)."""

    #: the attributes a pickle leaves out (rebuilt on demand or by ``_rebuild``)
    _DERIVED = ("_kernel",)

    def _freeze(self):
        object.__setattr__(self, "_frozen", True)

    def __setattr__(self, name, value):
        if self.__dict__.get("_frozen"):
            raise AttributeError(f"{type(self).__name__} is immutable: {name} cannot be set "
                                 "(make new filters with the constructor or train)")
        object.__setattr__(self, name, value)

    def __delattr__(self, name):
        raise AttributeError(f"{type(self).__name__} is immutable: {name} cannot be deleted")

    def __getstate__(self):
        return {k: v for k, v in self.__dict__.items() if k not in self._DERIVED}

    def _rebuild(self):
        """The derived attributes a pickle left out (none here)."""

    def __repr__(self):
        src = self.meta.get("training_set", "?")
        return (f"{type(self).__name__}(pattern={self.pattern.name!r}, "
                f"bit_depth={self.bit_depth}, buckets={self.n_buckets}, trained on {src!r}, "
                f"digest={self.digest})")

    __str__ = __repr__

    def __setstate__(self, state):      # a pickled or deep-copied copy stays read-only: its
        if type(state.get("meta")) is dict:                 # a pickle of an earlier version
            state = {**state, "meta": FilterMeta(state["meta"])}
        read_only_state(self, state)    # identity is a digest computed once
        self._rebuild()
        self._freeze()                  # a pickle of a version before _frozen, too

    def __eq__(self, other):
        return isinstance(other, type(self)) and other.digest == self.digest

    def __hash__(self):
        return hash(self.digest)


class LearnedFilters(FilterIdentity):
    """Hashed linear filters of one pattern (``method="learned"``).

    Made by :func:`train` or read by :meth:`load`; :func:`default_filters`
    gives the ones shipped with the package. Immutable; equal when their
    contents are (:attr:`digest`). :meth:`for_pattern` gives the same filters
    for a mirrored or shifted pattern (another Bayer phase of Mask1 or Mask2).

    Parameters
    ----------
    pattern : Pattern or str
        The pattern the filters reconstruct.
    bit_depth : int
        Bits of the frames they were fitted to. The strength thresholds of
        the hash are in those digital numbers; a frame of another bit depth
        uses them scaled by the ratio of the white levels (squared: they are
        energies), so the filters serve every bit depth.
    weights : ndarray, shape (n_phases, n_buckets, n_taps_max)
        The filter of each (Z site of the tile, bucket): weights of the taps
        of :func:`learned_geometry` (zeros past a phase's own tap count).
    strength_thresholds, coherence_thresholds : ndarray, shape (n_phases, k)
        The hash thresholds of each phase (increasing).
    spread_thresholds : ndarray, shape (n_phases, k), optional
        The channel-spread thresholds of each phase (increasing, >= 1); None:
        one spread level (a version-1 hash).
    radius, hash_radius : int
        Window radius of the taps (3: 7x7) and of the hash pairs.
    meta : dict, optional
        What they were fitted on: ``training_set``, ``n_images``, ``noise``,
        ``encoding``, ``ridge``, ``prior``, ``library_version``... (strings
        and numbers, kept in the file).

    Examples
    --------
    >>> from rgbz_fast.reconstruction import default_filters
    >>> f = default_filters("mask1")
    >>> f.pattern.name, f.n_buckets, f.meta["encoding"]
    ('mask1', 216, 'linear+srgb')
    >>> default_filters("mask2_rggb").pattern.name          # Mask2 mirrored left-right
    'mask2_rggb'
    """

    def __init__(self, pattern, bit_depth, weights, strength_thresholds, coherence_thresholds,
                 spread_thresholds=None, *, radius=3, hash_radius=3, meta=None):
        self.pattern = get_pattern(pattern)
        self.bit_depth = check_bit_depth(bit_depth)
        self.radius = check_int(radius, "radius", lo=2, hi=5)
        self.hash_radius = check_int(hash_radius, "hash_radius", lo=2, hi=self.radius)
        self.geometry = learned_geometry(self.pattern, self.radius, self.hash_radius)
        n_ph = len(self.geometry)
        n_taps = max(len(g["taps"]) for g in self.geometry)
        s_thr = np.array(real_array(strength_thresholds, "filters: strength_thresholds"),
                         ndmin=2)
        c_thr = np.array(real_array(coherence_thresholds, "filters: coherence_thresholds"),
                         ndmin=2)
        k_thr = (np.zeros((n_ph, 0)) if spread_thresholds is None
                 else np.array(real_array(spread_thresholds, "filters: spread_thresholds"),
                               ndmin=2))
        for label, a in (("strength_thresholds", s_thr), ("coherence_thresholds", c_thr),
                         ("spread_thresholds", k_thr)):
            if a.ndim != 2:     # the kernel reads (phases, thresholds); 3-D had failed in it
                raise ValueError(f"filters: {label} must be 2-D (phases, thresholds), got "
                                 f"shape {a.shape}")
        # kept at float32 precision, as the file stores them: a fit and its file are equal
        w = real_array(weights, "filters: weights").astype(np.float32).astype(np.float64)
        if w.ndim != 3:
            raise ValueError(f"filters: weights must be 3-D (phases, buckets, taps), got shape "
                             f"{w.shape}")
        if any(a.shape[0] != n_ph for a in (s_thr, c_thr, k_thr)):
            raise ValueError(f"filters: expected thresholds for {n_ph} phases, got "
                             f"{s_thr.shape[0]}, {c_thr.shape[0]} and {k_thr.shape[0]}")
        nb = N_ANGLES * (s_thr.shape[1] + 1) * (c_thr.shape[1] + 1) * (k_thr.shape[1] + 1)
        if w.shape != (n_ph, nb, n_taps):
            raise ValueError(f"filters: expected weights of shape {(n_ph, nb, n_taps)} for "
                             f"pattern {self.pattern.name!r} and these thresholds, got {w.shape}")
        for name, a in (("weights", w), ("strength_thresholds", s_thr),
                        ("coherence_thresholds", c_thr), ("spread_thresholds", k_thr)):
            if not np.all(np.isfinite(a)):
                raise ValueError(f"filters: {name} holds NaN or infinity")
        if any(np.any(np.diff(a, axis=1) < 0) for a in (s_thr, c_thr, k_thr)):
            raise ValueError("filters: hash thresholds must be increasing")
        if np.any(k_thr < 1):
            raise ValueError("filters: spread thresholds must be >= 1 (a ratio of the largest "
                             "to the smallest channel energy)")
        for a in (w, s_thr, c_thr, k_thr):
            a.setflags(write=False)
        self.weights, self.strength_thresholds = w, s_thr
        self.coherence_thresholds, self.spread_thresholds = c_thr, k_thr
        self.meta = check_meta(meta)
        h = hashlib.sha1()
        for part in (self.pattern.tile_string, self.bit_depth, self.radius, self.hash_radius):
            h.update(repr(part).encode())
        for a in (w, s_thr, c_thr, k_thr):
            h.update(repr(a.shape).encode())
            h.update(np.ascontiguousarray(a).tobytes())
        self.digest = h.hexdigest()[:16]
        self._kernel = {}
        self._freeze()

    _DERIVED = ("_kernel", "geometry")

    def _rebuild(self):
        object.__setattr__(self, "geometry",
                           learned_geometry(self.pattern, self.radius, self.hash_radius))
        object.__setattr__(self, "_kernel", {})

    @property
    def n_buckets(self):
        return self.weights.shape[1]

    @property
    def n_strength(self):
        return self.strength_thresholds.shape[1] + 1

    @property
    def n_coherence(self):
        return self.coherence_thresholds.shape[1] + 1

    @property
    def n_spread(self):
        return self.spread_thresholds.shape[1] + 1

    def thresholds(self, bit_depth=None):
        """``(strength, coherence, spread)`` thresholds, per phase, for frames of
        ``bit_depth`` (default: the fit's): the strength ones scaled by the squared
        ratio of the white levels."""
        s = self.strength_thresholds
        if bit_depth is not None and bit_depth != self.bit_depth:
            s = s * (((1 << bit_depth) - 1) / ((1 << self.bit_depth) - 1)) ** 2
        return s, self.coherence_thresholds, self.spread_thresholds

    def for_pattern(self, pattern):
        """These filters for ``pattern``: themselves, the same filters mirrored or shifted
        when ``pattern`` is this one's tile flipped left-right and/or up-down and moved by
        whole pixels (Mask1 and Mask2 of every Bayer phase from the GRBG ones), or None."""
        pattern = get_pattern(pattern)
        if pattern == self.pattern:
            return self                  # the cache would give an equal fit: itself
        d = _derived(self, pattern)
        if d is None:
            return d
        # the cache serves equal filters (same digest, which leaves meta out) the filters
        # derived from the first of them: these carry their own meta (training set...)
        meta = {**self.meta, "derived_from": d.meta["derived_from"]}
        if d.meta != meta:
            import copy

            d = copy.copy(d)                     # its own kernel cache (not copied)
            object.__setattr__(d, "meta", meta)
        return d

    def reconstruct(self, data, bit_depth=None):
        """NumPy reconstruction of a frame ``data`` (unclipped, unrounded, float64).

        The slow path that scores a fit; the C kernel of :func:`rgbz_fast.reconstruct`
        computes the same in one pass.
        """
        from ._learned_hash import gather_windows, hash_buckets, hash_features
        out = np.array(data, dtype=np.float64)
        thr = self.thresholds(bit_depth)
        for k, (X, (r, c, ny, nx)) in enumerate(
                gather_windows(data, self.pattern, self.radius, self.geometry)):
            bk = hash_buckets(hash_features(X, self.geometry[k]), *(t[k] for t in thr))
            w = self.weights[k][:, :X.shape[0]]
            out[r::self.pattern.period[0], c::self.pattern.period[1]][:ny, :nx] = \
                np.einsum("ji,ij->i", X, w[bk]).reshape(ny, nx)
        return out

    def kernel_arrays(self, bit_depth=None):
        """The arrays of the C kernel's ``rgbz_learned_filters`` (csrc/learned.h) for frames of
        ``bit_depth``, made once per bit depth (read-only: the filters keep them)."""
        bd = self.bit_depth if bit_depth is None else check_bit_depth(bit_depth)
        if bd not in self._kernel:
            self._kernel[bd] = _kernel_arrays(self, bd)
        return self._kernel[bd]

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
                 spread_thresholds=self.spread_thresholds,
                 meta_keys=np.array(list(self.meta), dtype=str),
                 meta_values=np.array([repr(v) for v in self.meta.values()], dtype=str))
        return buf.getvalue()

    def save(self, path):
        """Write the filters to ``path`` (.npz, atomically, format version
        :data:`FORMAT_VERSION`): weights in float32, the pattern, the bit depth, the hash
        thresholds and the metadata (training set, ...)."""
        atomic_write(path, self.to_bytes())

    @classmethod
    def load(cls, path, name="filters", *, max_bytes=None):
        """Read a file written by :meth:`save` (format version 1 or 2); ValueError naming
        ``name`` if it is not one. ``max_bytes``: the read limit
        (:func:`rgbz_fast.io.read_limits`)."""
        p = Path(path)
        z = read_npz(p, name, max_bytes=max_bytes)   # bounded, no pickles, zip bombs refused
        if "format" not in z or z["format"].dtype.kind not in "US" or str(z["format"]) != _MAGIC:
            raise ValueError(f"{name}: {p} is not a rgbz-fast filters file")
        try:
            return cls._from_arrays(z, p, name)
        except FILE_ERRORS as e:
            raise file_error(e, p, name) from None

    @classmethod
    def _from_arrays(cls, z, p, name):
        version = int_field(z, "version", p, name)
        if version not in _READS:
            raise ValueError(f"{name}: {p} has format version {version}, this library reads "
                             f"versions {', '.join(map(str, _READS))} (a newer rgbz-fast wrote "
                             "it: upgrade, or refit with `rgbz-fast train`)")
        meta = read_meta(z, p, name)
        n_angles = int_field(z, "n_angles", p, name)
        if n_angles != N_ANGLES:
            raise ValueError(f"{name}: {p} has {n_angles} angle bins, expected {N_ANGLES}")
        try:
            pattern = Pattern(str(z["pattern"]), name=str(z["pattern_name"]), bayer=str(z["bayer"]))
            named = _preset_or_none(pattern.name)
        except (ValueError, TypeError) as e:
            raise ValueError(f"{name}: {p} holds an invalid pattern ({e})") from None
        if named is not None and named.tile_string != pattern.tile_string:
            # a preset's name on another tile would be reported as that preset
            raise ValueError(f"{name}: {p} names its pattern {pattern.name!r}, whose tile is "
                             f"{named.tile_string}, but holds the tile {pattern.tile_string} "
                             "(a damaged filters file)")
        spread = z["spread_thresholds"] if version >= 2 else None
        arrays = [z["weights"], z["strength_thresholds"], z["coherence_thresholds"], spread]
        keep = _phases_at_smallest_period(str(z["pattern"]), pattern)
        if keep is not None:
            arrays = [None if a is None else np.asarray(a)[keep] for a in arrays]
        return cls(pattern, int_field(z, "bit_depth", p, name), *arrays,
                   radius=int_field(z, "radius", p, name),
                   hash_radius=int_field(z, "hash_radius", p, name), meta=meta)


def _phases_at_smallest_period(tile_text, pattern):
    """The phases of a file's filters that its pattern keeps, or None (all of them).

    A file fitted on a tile written at a multiple of its period (``ZRZR/BGBG/ZRZR/BGBG``,
    kept as written before the patterns were reduced to their smallest period, H104) holds
    one filter per Z site of the long tile, row-major; the sites of one class of the
    smaller period are the same site of the mosaic, so the first of each, the one inside
    the small tile, is kept (the file had no longer loaded: "expected thresholds for 1
    phases, got 4")."""
    tile = _parse_tile(tile_text)
    if tile.shape == tuple(pattern.period):
        return None
    P, Q = pattern.period
    sites = np.argwhere(tile == Z)                                   # row-major
    return [i for i, (r, c) in enumerate(sites) if r < P and c < Q]


#: the longest repr of a meta value a file keeps (the loader reads no more of it)
_META_REPR_MAX = 100_000
#: the errors of reading a damaged file that :func:`file_error` reports
FILE_ERRORS = (KeyError, TypeError, ValueError, SyntaxError, RecursionError, MemoryError)


class FilterMeta(ReadOnlyDict):
    """The ``meta`` of filters: read-only, as the filters are (the shipped filters are one
    object per process: an edit of one caller's ``meta`` had changed every caller's repr and
    what ``save`` writes, the digest unchanged)."""

    _what = ("the filters' meta is read-only (the filters are immutable): dict(filters.meta) "
             "is a copy to edit; the constructor's or train's meta= makes new filters")


def check_meta(meta, name="meta"):
    """The ``meta`` of filters as they keep it (a :class:`FilterMeta`): string keys; NumPy
    scalars made Python ones; ints, floats and strings kept, anything else as its ``str``. A
    value a file cannot give back (NaN, infinity, a number whose repr ``ast.literal_eval``
    cannot read) is a ValueError naming ``name`` and the key: saved, it had made a file that
    does not load."""
    if meta is None:
        return FilterMeta()
    if not isinstance(meta, dict):
        raise TypeError(f"{name}: expected a dict, got {type(meta).__name__}")
    out = {}
    for k, v in meta.items():
        k = str(k)
        if isinstance(v, np.generic):
            v = v.item()                      # np.float64(0.5) -> 0.5: a repr the file reads
        if isinstance(v, bool):
            v = bool(v)
        elif isinstance(v, int):
            v = int(v)
        elif isinstance(v, float):
            v = float(v)
        elif not isinstance(v, str):
            v = str(v)
        if isinstance(v, float) and not np.isfinite(v):
            raise ValueError(f"{name}: {k!r} is {v!r}, which a filters file cannot hold; give "
                             "a finite number or a string")
        text = repr(v)
        if len(text) > _META_REPR_MAX:
            raise ValueError(f"{name}: {k!r} is {len(text)} characters long, more than a "
                             f"filters file keeps ({_META_REPR_MAX})")
        if np.array([k], dtype=str)[0] != k:
            raise ValueError(f"{name}: the key {k!r} ends in NUL characters, which a filters "
                             "file drops")
        try:
            back = ast.literal_eval(text)
        except (ValueError, SyntaxError, RecursionError, MemoryError):
            back = None
        if type(back) is not type(v) or back != v:
            raise ValueError(f"{name}: {k!r} is {text[:100]}, which a filters file cannot give "
                             "back; give a number or a string")
        out[k] = v
    return FilterMeta(out)


def read_meta(z, p, name):
    """The meta of a filters file's arrays ``z`` (``meta_keys``, ``meta_values``)."""
    keys, values = z["meta_keys"].tolist(), z["meta_values"].tolist()
    if not isinstance(keys, list) or not isinstance(values, list):
        raise TypeError("meta_keys and meta_values must be 1-d arrays")
    if len(keys) != len(values):                # zip had dropped the keys past the values
        raise ValueError(f"{name}: {p} holds {len(keys)} meta keys and {len(values)} "
                         "values (a damaged filters file)")
    return {str(k): ast.literal_eval(str(v)[:_META_REPR_MAX]) for k, v in zip(keys, values)}


def int_field(z, key, p, name):
    """The integer ``z[key]`` of a filters file: a 0-d integral number, else a ValueError
    naming the file and the field (``int()`` had read a version 2.7 as 2)."""
    a = np.asarray(z[key])
    if a.shape != () or a.dtype.kind not in "iuf" or not np.isfinite(a) or a != np.trunc(a):
        got = repr(a.tolist()) if a.shape == () else f"an array of shape {a.shape}"
        raise ValueError(f"{name}: {p} holds {key} {got}, not an integer (a damaged filters "
                         "file)")
    return int(a)


def float_field(z, key, p, name):
    """The number ``z[key]`` of a filters file: a 0-d real number, else a ValueError naming the
    file and the field."""
    a = np.asarray(z[key])
    if a.shape != () or a.dtype.kind not in "iuf":
        got = repr(a.tolist()) if a.shape == () else f"an array of shape {a.shape}"
        raise ValueError(f"{name}: {p} holds {key} {got}, not a number (a damaged filters "
                         "file)")
    return float(a)


def file_error(e, p, name):
    """The ValueError of a damaged filters file ``p`` (one of :data:`FILE_ERRORS` raised while
    reading its arrays): ``"{name}: {p}: ..."`` for a check's message (the file named once),
    or what failed."""
    if isinstance(e, KeyError):
        return ValueError(f"{name}: {p} lacks {e} (a damaged filters file)")
    msg = str(e)
    if msg.startswith(f"{name}: "):                   # a check's message: the file named, once
        rest = msg.removeprefix(f"{name}: ")
        return ValueError(msg if rest.startswith(str(p)) else f"{name}: {p}: {rest}")
    return ValueError(f"{name}: {p} is a damaged filters file ({type(e).__name__}: "
                      f"{msg[:200]})")


def _preset_or_none(label):
    """The preset Pattern a pattern label names (``mask2``, ``mask1_rggb``), or None for a
    label of a custom tile."""
    try:
        return get_pattern(label) if label.split("_")[0].lower() in _PRESETS else None
    except ValueError:
        return None


def _kernel_arrays(f, bit_depth):
    g = f.geometry
    n_ph, nt = f.weights.shape[0], f.weights.shape[2]
    npmax = max(len(pp) for ph in g for pp in ph["pairs"])
    n_taps = np.array([len(ph["taps"]) for ph in g], np.int32)
    tap_dy = np.zeros((n_ph, nt), np.int32)
    tap_dx = np.zeros((n_ph, nt), np.int32)
    n_pairs = np.zeros((n_ph, 4), np.int32)
    pair_a = np.zeros((n_ph, 4, npmax), np.int32)
    pair_b = np.zeros((n_ph, 4, npmax), np.int32)
    pair_c = np.zeros((n_ph, 4, npmax), np.int32)
    inv_col = np.zeros((n_ph, 3))
    for k, ph in enumerate(g):
        tap_dy[k, :n_taps[k]], tap_dx[k, :n_taps[k]] = ph["taps"].T
        for d, (pp, pc) in enumerate(zip(ph["pairs"], ph["pair_colours"])):
            n_pairs[k, d] = len(pp)
            pair_a[k, d, :len(pp)], pair_b[k, d, :len(pp)] = pp.T
            pair_c[k, d, :len(pp)] = pc
        inv_col[k] = 1.0 / ph["colour_pairs"]
    s_thr, c_thr, k_thr = f.thresholds(bit_depth)
    w64 = np.ascontiguousarray(f.weights.transpose(0, 2, 1))
    out = dict(n_taps=n_taps, tap_dy=tap_dy, tap_dx=tap_dx, n_pairs=n_pairs, pair_a=pair_a,
               pair_b=pair_b, pair_col=pair_c, inv_col=inv_col,
               str_thr=np.ascontiguousarray(s_thr), coh_thr2=np.ascontiguousarray(c_thr ** 2),
               spr_thr=np.ascontiguousarray(k_thr), w_f32=w64.astype(np.float32), w_f64=w64,
               bayer=np.ascontiguousarray(bayer(f.pattern.bayer_phase).tile.reshape(-1),
                                          np.int32),
               radius=f.radius, hash_radius=f.hash_radius)
    if f.radius <= 3:
        # the kernel's fast path: each window row as 8 weights, 0 off the taps
        R = f.radius
        dense = np.zeros((n_ph, f.n_buckets, 2 * R + 1, 8))
        for k, ph in enumerate(g):
            # (advanced indices around a slice put the tap axis first)
            dense[k, :, ph["taps"][:, 0] + R, ph["taps"][:, 1] + R] = \
                f.weights[k, :, :len(ph["taps"])].T
        out.update(wd_f32=dense.astype(np.float32), wd_f64=dense)
    return _read_only(out)


def _read_only(arrays):
    """``arrays`` (a dict of the kernel's arrays, kept on the filters) with every array
    read-only: :meth:`LearnedFilters.kernel_arrays` hands out the cache itself, and a
    caller's write into it had changed every later call's output, digest unchanged (H101)."""
    for v in arrays.values():
        if isinstance(v, np.ndarray):
            v.setflags(write=False)
    return arrays


def pattern_transform(src, dst):
    """``(fy, fx, oy, ox)`` with ``dst`` at (r, c) = ``src`` at ((fy r + oy) mod P,
    (fx c + ox) mod Q) for every site, colours and the Bayer colour of the Z sites alike
    (fy, fx = -1: a flip); None when there is none. Identity first."""
    if src.period != dst.period or src.bayer_phase is None or dst.bayer_phase is None:
        return None
    P, Q = src.period
    rr, cc = np.indices((P, Q))
    st = np.where(src.tile == Z, 4 + src.bayer_tile(), src.tile)
    dt = np.where(dst.tile == Z, 4 + dst.bayer_tile(), dst.tile)
    for fy, fx in ((1, 1), (1, -1), (-1, 1), (-1, -1)):
        for oy in range(P):
            for ox in range(Q):
                if np.array_equal(dt, st[(fy * rr + oy) % P, (fx * cc + ox) % Q]):
                    return fy, fx, oy, ox
    return None


@lru_cache(maxsize=64)
def _derived(f, pattern):
    if pattern == f.pattern:
        return f
    tr = pattern_transform(f.pattern, pattern)
    if tr is None:
        return None
    fy, fx, oy, ox = tr
    P, Q = pattern.period
    src_geom = f.geometry
    src_index = {ph["rc"]: k for k, ph in enumerate(src_geom)}
    geom = learned_geometry(pattern, f.radius, f.hash_radius)
    nb, nk = f.n_buckets, f.n_spread
    # a single flip mirrors the orientation; two flips turn the window by 180 degrees
    octant = mirror_octants() if fy * fx < 0 else np.arange(N_ANGLES)
    per_angle = nb // N_ANGLES
    bucket_map = (octant[:, None] * per_angle + np.arange(per_angle)[None, :]).reshape(-1)
    weights = np.zeros_like(f.weights)
    order = []
    for k, ph in enumerate(geom):
        r, c = ph["rc"]
        ks = src_index[((fy * r + oy) % P, (fx * c + ox) % Q)]
        order.append(ks)
        taps = {tuple(t): i for i, t in enumerate(src_geom[ks]["taps"])}
        idx = np.array([taps[(fy * dy, fx * dx)] for dy, dx in ph["taps"]])
        weights[k, :, :len(idx)] = f.weights[ks][bucket_map][:, idx]
    flip = {(1, 1): "shifted", (1, -1): "mirrored left-right", (-1, 1): "mirrored up-down",
            (-1, -1): "turned 180 degrees"}[(fy, fx)]
    meta = {**f.meta, "derived_from": f"{f.pattern.name} ({flip}), digest {f.digest}"}
    return LearnedFilters(pattern, f.bit_depth, weights, f.strength_thresholds[order],
                          f.coherence_thresholds[order],
                          f.spread_thresholds[order] if nk > 1 else None,
                          radius=f.radius, hash_radius=f.hash_radius, meta=meta)


_SHIPPED = []
_SHIPPED_LOCK = threading.Lock()


def _shipped():
    """The filters shipped in reconstruction/data/ (read once, by one thread: the list had
    been extended file by file while another thread read it, and a first call on Mask2
    beside another one found Mask1's alone: "none fits pattern 'mask2'", M-03)."""
    if not _SHIPPED:
        with _SHIPPED_LOCK:
            if not _SHIPPED:
                loaded = [LearnedFilters.load(p) for p in sorted(_DATA.glob("learned_*.npz"))]
                _SHIPPED.extend(loaded)              # whole, under the GIL
    return tuple(_SHIPPED)


def resolve_filters(filters, pattern, name="filters"):
    """The :class:`LearnedFilters` for a frame of ``pattern``: the first of ``filters`` (one,
    or a tuple) that fits it as it is or mirrored/shifted (:meth:`LearnedFilters.for_pattern`),
    or, when none are given, the first of the shipped ones. Given filters of which none fits
    are a ValueError naming ``name``, as z_guided's (the shipped ones had been used in their
    place without a word, the user's file unused)."""
    pattern = get_pattern(pattern)
    cands = (filters if isinstance(filters, tuple) else (filters,)) if filters is not None \
        else ()
    for f in cands or _shipped():
        d = f.for_pattern(pattern)
        if d is not None:
            return d
    from ..io import ParameterError, Setting      # the settings, in the caller's words

    if cands:
        have = ", ".join(dict.fromkeys(f.pattern.name for f in cands))
        raise ParameterError(name, f"none of the given learned filters fits pattern "
                                   f"{pattern.name!r} (given: {have}) nor its other Bayer "
                                   "phases; give filters fitted for it, or none for the "
                                   "shipped ones")
    given = ""
    shipped = ", ".join(dict.fromkeys(f.pattern.name for f in _shipped()))
    raise ParameterError(name, f"none fits pattern {pattern.name!r}{given}; filters ship for "
                         f"{shipped} and their other Bayer phases; fit some with ",
                         Setting("train", "rgbz_fast.reconstruction.train"), " and pass ",
                         Setting("filters", "filters=FILE"))


def check_filters(value, name="filters", *, max_bytes=None):
    """``filters`` of ReconstructParams: None, a LearnedFilters, a path, or a sequence of them
    -> None or a tuple of LearnedFilters (files read now, so a bad one fails early, each
    within ``max_bytes``)."""
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
            out.append(LearnedFilters.load(v, name, max_bytes=max_bytes))
        else:
            raise TypeError(f"{name}: expected a LearnedFilters or a path, got "
                            f"{type(v).__name__}")
    return tuple(out)


def default_filters(pattern):
    """The shipped filters for a pattern (mirrored or shifted to it when needed), or None.

    The package ships Mask1 and Mask2 (GRBG) filters fitted on noise-free
    11-bit frames of CBSD68, Manga109 pages and Sun-Hays photographs, each
    image mosaicked both linearised and as sRGB values (``reconstruction/data/``;
    ``rgbz-fast train`` made them, with the command in their metadata). They
    serve both encodings, every bit depth and, mirrored, the RGGB, BGGR and
    GBRG phases.

    Examples
    --------
    >>> from rgbz_fast.reconstruction import default_filters
    >>> default_filters("mask2_bggr").meta["derived_from"].split(" (")[0]
    'mask2'
    >>> default_filters("rows") is None
    True
    """
    pattern = get_pattern(pattern)
    for f in _shipped():
        d = f.for_pattern(pattern)
        if d is not None:
            return d
    return None
