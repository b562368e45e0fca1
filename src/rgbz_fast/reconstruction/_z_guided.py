"""Colour reconstruction guided by what the Z pixels see (``method="z_guided"``).

A monolithic RGB-Z chip measures, at every Z site, the scene's near-infrared
reflectance: the demodulated i-ToF amplitude, exactly where the colour is
missing. ``z_guided`` is the learned method (:mod:`._learned`: the known
pixels of the 7x7 window, a bucket from a cheap hash of their structure, one
dot product) with a second, small dot product over *guide features* made from
that amplitude. Only the amplitude at the Z sites is read, never a NIR value
at a colour site; on Mask2 one 2x2 Z pixel gives one value for its four
sites.

Guide features of a Z site (its target colour t, its Z measurement m0 and the
3 x 3 measurements around it, one pattern period apart; at the frame's edge
the nearest measurement inside stands in):

* the *relative* amplitude ``u_m = N_m / mean(N) - 1`` (0 when the mean is 0),
  so that any positive scale of the guide gives the same result, and its
  relative noise ``nu = mean(V_m) / mean(N)^2`` (``V_m``: the noise variance
  of N_m, estimated from the disagreement of the modulation frequencies; 0
  for a ``nir=`` image, taken as exact);
* ``base * s * u_m`` for the 9 measurements, ``base`` being the mean of the
  target-colour taps of the 5x5 window (the learned method's baseline) and
  ``s = U / (U + 9 nu)``, ``U = sum_m u_m^2``, the share of the amplitude's
  variation that is not noise;
* a local linear model of the colour against the amplitude: ``C_m``, the
  mean of the known target-colour pixels in the box of the Z pixel m and the
  two pixels around it, ``a = sum_m u_m (C_m - mean C) / (U + 9 (lam +
  nu))``, and the two features ``mean C + a u_0 - base`` and ``a u_0 - (C_0 -
  mean C)``.

The bucket is the learned hash's, times a level of the guide's noise: ``nu``
above each of the noise thresholds. The colour weights (the learned filters'
weights plus a fitted correction) and the 11 guide weights are fitted per (Z
site of the tile, noise level, bucket) by :func:`._z_guided_fit.train_z_guided`
on frames whose true colour and NIR are known. docs/guide/z_guided.md is the
specification.
"""

from __future__ import annotations

import hashlib
import io
from pathlib import Path

import numpy as np

from .. import _kernels
from .._frame import ToFTaps
from .._patterns import Z, get_pattern
from .._validate import check_number
from ..io import atomic_write, read_npz
from ._learned import (FILE_ERRORS, FilterIdentity, LearnedFilters, check_filters, check_meta,
                       file_error, float_field, int_field, pattern_transform, read_meta)
from ._learned_hash import (N_ANGLES, extend_index, gather_windows, hash_buckets, hash_features,
                            mirror_octants)

__all__ = ["ZGuidedFilters", "z_layout", "guide_grid", "guide_features", "N_GUIDE",
           "NEEDS_TOF", "default_z_filters"]

#: the methods of :func:`rgbz_fast.reconstruct` that read what the Z pixels measured: a
#: frame with ToF taps (or ``nir=``); a plain array alone cannot feed them
NEEDS_TOF = frozenset({"z_guided"})
#: guide features per site: 9 relative amplitudes times the baseline, 2 of the local model
N_GUIDE = 11
#: the neighbourhood of measurements: (2 K + 1)^2, one pattern period apart
_K = 1
#: version of the .npz layout; a file of another version is refused
FORMAT_VERSION = 1
_MAGIC = "rgbz-fast z_guided filters"
#: the shipped filters: reconstruction/data/z_guided_*.npz
_DATA = Path(__file__).resolve().parent / "data"
_SHIPPED = {}


def z_layout(pattern, name="pattern"):
    """``(zr, zc, block)``: the top-left tile cell of the pattern's one Z pixel and its size.

    ``z_guided`` reads one amplitude per Z pixel: a pattern must hold one Z
    pixel per tile, a single Z site (Mask1, block 1) or one aligned 2x2 square
    of them (Mask2, block 2), in a tile of a Bayer phase.
    """
    pattern = get_pattern(pattern)
    z = np.argwhere(pattern.tile == Z)
    if pattern.bayer_phase is None or len(z) not in (1, 4):
        raise ValueError(f"{name}: method 'z_guided' needs a pattern of a Bayer phase with one "
                         f"Z pixel per tile (one Z site, or one 2x2 square of them); "
                         f"{pattern.name!r} ({pattern.tile_string}) is not one")
    zr, zc = (int(v) for v in z.min(axis=0))
    if len(z) == 4 and not (np.array_equal(z.max(axis=0) - z.min(axis=0), [1, 1])
                            and zr % 2 == 0 and zc % 2 == 0):
        raise ValueError(f"{name}: the 4 Z sites of {pattern.name!r} ({pattern.tile_string}) "
                         "are not one aligned 2x2 Z pixel, which 'z_guided' needs")
    return zr, zc, 1 if len(z) == 1 else 2


def _grid_shape(shape, pattern):
    """Rows and columns of the measurement grid: one Z pixel per tile of the frame."""
    (P, Q), (zr, zc, _) = pattern.period, z_layout(pattern)
    return len(range(zr, shape[0], P)), len(range(zc, shape[1], Q))


def _complete(shape, pattern):
    """Bool grid: the Z pixel of the tile lies wholly inside the frame (a measurement exists)."""
    rows, cols = _complete_lines(shape, pattern)
    return rows[:, None] & cols[None, :]


def _complete_lines(shape, pattern):
    """The grid's rows and columns whose Z pixels lie wholly inside the frame (bool vectors):
    the complete cells are their crossings."""
    (P, Q), (zr, zc, b) = pattern.period, z_layout(pattern)
    gy, gx = _grid_shape(shape, pattern)
    return (zr + P * np.arange(gy) + b - 1 < shape[0], zc + Q * np.arange(gx) + b - 1 < shape[1])


def _fill_cut(grid, complete):
    """A Z pixel cut by the frame's edge has no measurement: it takes the one a period inwards.

    The complete cells are the first rows and columns of the grid (``_complete``), so the cut
    ones are its last rows and columns: filled in place from the last complete row and
    column (no copy of the grid). Returns ``grid``.
    """
    if not complete.any():
        raise ValueError("shape: the frame holds no complete Z pixel")
    ny = int(complete.any(axis=1).sum())
    nx = int(complete.any(axis=0).sum())
    grid[:ny, nx:] = grid[:ny, nx - 1:nx]
    grid[ny:, :] = grid[ny - 1:ny, :]
    return grid


def guide_grid(shape, pattern, *, tof=None, nir=None, name="nir", workers=1):
    """The NIR value of every Z pixel and its noise variance, on the grid of the tiles.

    From ``nir`` (an array of the frame's shape; only its Z sites are read, the
    mean of the four on a 2x2 Z pixel; any positive scale; taken as exact:
    noise variance 0) or else from ``tof``: the mean over the F frequencies of
    :meth:`ToFTaps.amplitude` ``A_f``, and the variance of that mean estimated
    from their disagreement, ``sum_f (A_f / r_f - mean_f A_f / r_f)^2 / (F (F -
    1))`` (``r_f``: the median of ``A_f`` over the mean over the lit Z pixels,
    mean > 0, of a sample, every (N // 16384 + 1)-th Z pixel in row-major order;
    1 if none; 0 with one frequency), demodulated by the
    C kernel (csrc/z_guided_guide.c) in ``workers`` threads, the same result
    for any number (tests/_reference/z_guided.py holds the NumPy path). A Z
    pixel cut by the frame's edge (no measurement) takes the values a pattern
    period inwards. ValueError naming ``name`` when neither is given or the
    values cannot be a NIR image.

    Returns
    -------
    grid, var : ndarray of float64, shape (tile rows, tile columns)
    """
    pattern = get_pattern(pattern)
    (P, Q), (zr, zc, b) = pattern.period, z_layout(pattern)
    gy, gx = _grid_shape(shape, pattern)
    complete = _complete(shape, pattern)
    if nir is not None:
        a = np.asarray(nir)
        if a.dtype == object or not (np.issubdtype(a.dtype, np.floating)
                                     or np.issubdtype(a.dtype, np.integer)):
            raise TypeError(f"{name}: expected a real numeric array of the frame's shape, got "
                            f"dtype {a.dtype}")
        if a.shape != tuple(shape):
            raise ValueError(f"{name}: expected the frame's shape {tuple(shape)}, got {a.shape}")
        grid = np.zeros((gy, gx))
        for dy in range(b):
            for dx in range(b):
                cell = a[zr + dy::P, zc + dx::Q].astype(np.float64)
                grid[:cell.shape[0], :cell.shape[1]] += cell / (b * b)
        vals = grid[complete]
        if not np.all(np.isfinite(vals)):
            raise ValueError(f"{name}: holds NaN or infinite values at Z sites")
        if vals.min() < 0:
            raise ValueError(f"{name}: holds negative values at Z sites (min {vals.min():g}); "
                             "a NIR image or amplitude is >= 0")
        return _fill_cut(grid, complete), np.zeros((gy, gx))
    grid, var = np.zeros((gy, gx)), np.zeros((gy, gx))
    taps, rows, cols, gyc, gxc = tof_taps(shape, pattern, tof, name,
                                          lambda *a: _kernels.z_guided_guide(*a, grid, var,
                                                                             workers))
    return _fill_cut(grid, complete), _fill_cut(var, complete)


def tof_taps(shape, pattern, tof, name, call):
    """The checked taps of ``tof`` for the guide: ``call(taps, rows, cols, P, Q, zr, zc, gyc,
    gxc)`` (a C call of the guide's, False when the sites are not the complete Z pixels in
    row-major order) with the taps as they are, else with their sites checked and put in that
    order. Returns the arguments of the call that succeeded, ``(taps, rows, cols, gyc, gxc)``."""
    pattern = get_pattern(pattern)
    (P, Q), (zr, zc, b) = pattern.period, z_layout(pattern)
    gy, gx = _grid_shape(shape, pattern)
    complete_rows, complete_cols = _complete_lines(shape, pattern)
    if tof is None:
        raise ValueError(f"{name}: method 'z_guided' is guided by the NIR amplitude the Z pixels "
                         "measured, and this frame carries no ToF taps: pass nir=, a float "
                         "array of the frame's shape (read at the Z sites only), or a RawFrame "
                         "with its taps (rgbz_fast.simulation.simulate, rgbz_fast.io.load_frame)")
    if not isinstance(tof, ToFTaps):
        raise TypeError(f"frame.tof: expected ToFTaps, got {type(tof).__name__}")
    if tof.block != b:
        raise ValueError(f"frame.tof: taps of {tof.block}x{tof.block} Z pixels, pattern "
                         f"{pattern.name!r} has {b}x{b} Z pixels")
    if not (complete_rows.any() and complete_cols.any()):
        raise ValueError("shape: the frame holds no complete Z pixel")
    if tof.taps.shape[0] > _kernels.TOF_MAX_FREQS:
        raise ValueError(f"frame.tof: the guide reads at most {_kernels.TOF_MAX_FREQS} "
                         f"frequencies, the taps hold {tof.taps.shape[0]}")
    gyc, gxc = int(complete_rows.sum()), int(complete_cols.sum())
    taps = tof.taps if tof.taps.dtype in (np.uint8, np.uint16, np.float32, np.float64) else \
        tof.taps.astype(np.float64)
    taps = np.ascontiguousarray(taps)
    rows, cols = (np.ascontiguousarray(a, np.int64) for a in tof.sites)
    if tof.n_sites and call(taps, rows, cols, P, Q, zr, zc, gyc, gxc):
        return taps, rows, cols, gyc, gxc
    # sites in another order (or not the frame's Z pixels): checked, then row-major
    iy, ry = np.divmod(rows - zr, P)
    ix, rx = np.divmod(cols - zc, Q)
    at = iy * gx + ix
    order = np.argsort(at, kind="stable")
    complete = complete_rows[:, None] & complete_cols[None, :]
    if np.any(ry) or np.any(rx) or not np.array_equal(at[order], np.flatnonzero(complete)):
        raise ValueError(f"frame.tof: its sites are not the Z pixels of pattern "
                         f"{pattern.name!r} in a {shape[0]}x{shape[1]} frame")
    args = (np.ascontiguousarray(taps[:, :, order]), np.ascontiguousarray(rows[order]),
            np.ascontiguousarray(cols[order]), P, Q, zr, zc, gyc, gxc)
    call(*args)
    return args[:3] + args[-2:]


def colour_grids(data, pattern, channels):
    """For each channel: the mean of its known pixels in the box of every Z pixel and the two
    pixels around it, on the grid of the tiles (borders: whole periods, as every kernel)."""
    pattern = get_pattern(pattern)
    (P, Q), (zr, zc, b) = pattern.period, z_layout(pattern)
    H, W = data.shape
    gy, gx = _grid_shape(data.shape, pattern)
    ext = 2
    yi, xi = extend_index(H, ext + P, P), extend_index(W, ext + Q, Q)
    pad = np.asarray(data, np.float64)[yi][:, xi]
    chan = pattern.channel_map((P, Q))[(yi % P)[:, None], (xi % Q)[None, :]]
    out = {}
    for t in channels:
        s = np.zeros((gy, gx))
        n = 0
        for dy in range(-ext, b + ext):
            for dx in range(-ext, b + ext):
                y0, x0 = ext + P + zr + dy, ext + Q + zc + dx
                if chan[y0, x0] != t:
                    continue
                s += pad[y0::P, x0::Q][:gy, :gx]
                n += 1
        if not n:
            raise ValueError(f"pattern: no {'RGB'[t]} pixel within two pixels of the Z pixel "
                             f"of {pattern.name!r}, which 'z_guided' needs")
        out[t] = s / n
    return out


def _neighbours(grid, iy, ix):
    """The (2 K + 1)^2 values around grid cells (iy, ix), row-major (edges: clamped)."""
    gy, gx = grid.shape
    cols = []
    for dy in range(-_K, _K + 1):
        for dx in range(-_K, _K + 1):
            cols.append(grid[np.clip(iy + dy, 0, gy - 1), np.clip(ix + dx, 0, gx - 1)])
    return np.stack(cols, axis=1)


def guide_features(N, V, C, base, lam):
    """The guide features (n, 11) and the relative noise ``nu`` (n,) of each site, from the
    amplitudes ``N``, their noise variances ``V`` and the colour means ``C`` (n, 9) of the
    measurements around it and its baseline ``base`` (n,); float64. ``nu`` is 1 where no
    light came back (every amplitude 0)."""
    T, nu = cell_terms(N, V, C, lam)
    return np.hstack([base[:, None] * T[:, :9], (T[:, 9] - base)[:, None], T[:, 10:]]), nu


def cell_terms(N, V, C, lam):
    """What the guide features of a site take from its Z pixels alone, (n, 11), and ``nu``:
    ``share * u_m`` (9), ``mean C + a u_0`` and ``a u_0 - (C_0 - mean C)`` (the features are
    these with the first 9 times ``base`` and ``base`` taken from the 10th)."""
    c = N.shape[1] // 2
    Nb = N.mean(axis=1)
    lit = Nb > 0
    inv = 1.0 / np.where(lit, Nb, 1.0)
    u = np.where(lit[:, None], N * inv[:, None] - 1.0, 0.0)
    nu = np.where(lit, V.mean(axis=1) * inv * inv, 1.0)
    U = (u * u).sum(axis=1)
    share = U / (U + N.shape[1] * nu + np.finfo(float).tiny)
    Cb = C.mean(axis=1)
    dc = C - Cb[:, None]
    a = (u * dc).sum(axis=1) / (U + N.shape[1] * (lam + nu))
    au = a * u[:, c]
    return np.hstack([share[:, None] * u, (Cb + au)[:, None], (au - dc[:, c])[:, None]]), nu


def _site_features(data, pattern, grids, colour, lam, noise_thresholds):
    """Per phase of ``colour`` (LearnedFilters): windows X (sites, taps), buckets (noise
    level * the hash's buckets + the hash's bucket), guide features G, and where the sites
    are."""
    grid, var = grids
    cg = colour_grids(data, pattern, sorted({ph["target"] for ph in colour.geometry}))
    thr = colour.thresholds()
    out = []
    for k, (X, (r, c, ny, nx)) in enumerate(
            gather_windows(data, pattern, colour.radius, colour.geometry)):
        ph = colour.geometry[k]
        bk = hash_buckets(hash_features(X, ph), *(t[k] for t in thr))
        X = np.ascontiguousarray(X.T)
        # the site's tile index is its Z pixel's index on the grid
        iy, ix = np.divmod(np.arange(ny * nx), nx)
        G, nu = guide_features(_neighbours(grid, iy, ix), _neighbours(var, iy, ix),
                               _neighbours(cg[ph["target"]], iy, ix),
                               X[:, ph["base"]].mean(axis=1), lam)
        level = np.zeros(len(nu), np.int64)
        for t in noise_thresholds:
            level += nu > t
        out.append((X, level * colour.n_buckets + bk, G, (r, c, ny, nx)))
    return out


class ZGuidedFilters(FilterIdentity):
    """The filters of ``method="z_guided"``: colour and guide weights per (phase, level, bucket).

    Made by :func:`~rgbz_fast.reconstruction.train_z_guided` or read by
    :meth:`load`. Immutable; equal when their contents are (:attr:`digest`).

    Parameters
    ----------
    base : LearnedFilters
        The learned filters they build on: the taps, the hash and its
        thresholds (their own weights are kept, not used).
    weights : ndarray, shape (n_phases, n_levels * n_buckets, n_taps_max)
        The colour weights of every (Z site of the tile, noise level, bucket of
        the hash), taps as in ``base`` (zeros past a phase's own tap count).
    guide_weights : ndarray, shape (n_phases, n_levels * n_buckets, 11)
        The weights of the guide features (module docstring).
    noise_thresholds : sequence of float
        The levels of the guide's relative noise ``nu`` (increasing, > 0):
        ``n_levels - 1`` of them.
    lam : float
        Regularisation of the local linear model (> 0, in squared relative
        amplitude).
    meta : dict, optional
        What they were fitted on (strings and numbers, kept in the file).
    """

    def __init__(self, base, weights, guide_weights, noise_thresholds, lam, *, meta=None):
        if not isinstance(base, LearnedFilters):
            raise TypeError(f"base: expected LearnedFilters, got {type(base).__name__}")
        z_layout(base.pattern, "filters")
        self.base = base
        self.lam = check_number(lam, "lam", lo=0, lo_open=True)
        thr = np.array(noise_thresholds, np.float64)
        if thr.ndim > 1:
            raise ValueError(f"filters: noise thresholds must be a 1-D sequence, got shape "
                             f"{thr.shape}")
        thr = thr.reshape(-1)
        if not np.all(np.isfinite(thr)) or np.any(thr <= 0) or np.any(np.diff(thr) <= 0):
            raise ValueError(f"filters: noise thresholds must be increasing and > 0, got "
                             f"{thr.tolist()}")
        n_rows = (len(thr) + 1) * base.n_buckets
        arrays = []
        for label, a, cols in (("weights", weights, base.weights.shape[2]),
                               ("guide weights", guide_weights, N_GUIDE)):
            a = np.array(a, np.float64).astype(np.float32).astype(np.float64)
            shape = (len(base.geometry), n_rows, cols)
            if a.shape != shape:
                raise ValueError(f"filters: expected {label} of shape {shape}, got {a.shape}")
            if not np.all(np.isfinite(a)):
                raise ValueError(f"filters: {label} hold NaN or infinity")
            a.setflags(write=False)
            arrays.append(a)
        thr.setflags(write=False)
        self.weights, self.guide_weights = arrays
        self.noise_thresholds = thr
        self.meta = check_meta(meta)
        h = hashlib.sha1(base.digest.encode())
        h.update(repr(self.lam).encode())
        for a in (thr, *arrays):
            h.update(a.tobytes())
        self.digest = h.hexdigest()[:16]
        self._freeze()

    pattern = property(lambda self: self.base.pattern)
    bit_depth = property(lambda self: self.base.bit_depth)
    #: buckets per phase: noise levels x the hash's buckets
    n_buckets = property(lambda self: self.weights.shape[1])

    def check_frame(self, pattern, bit_depth, name="filters"):
        """ValueError naming ``name`` unless the filters fit a frame of ``pattern`` and bits."""
        check_base(self.base, pattern, bit_depth, name)

    def sites(self, data, grids):
        """Per phase: the windows, buckets and guide features of every Z site of ``data`` and
        where the sites are (the intermediate values of :meth:`reconstruct`)."""
        return _site_features(data, self.pattern, grids, self.base, self.lam,
                              self.noise_thresholds)

    def for_pattern(self, pattern):
        """These filters for ``pattern``: themselves, or mirrored/shifted as
        :meth:`LearnedFilters.for_pattern` mirrors their base (Mask1 and Mask2 of every Bayer
        phase from the GRBG ones), or None."""
        return _derived(self, get_pattern(pattern))

    def reconstruct(self, data, grids):
        """NumPy reconstruction (float64, unclipped) of ``data`` guided by ``grids``
        (:func:`guide_grid`): the colour sites copied, the Z sites filled in."""
        P, Q = self.pattern.period
        out = np.array(data, np.float64)
        for k, (X, bk, G, (r, c, ny, nx)) in enumerate(self.sites(data, grids)):
            v = np.einsum("ij,ij->i", X, self.weights[k][:, :X.shape[1]][bk]) + \
                np.einsum("ij,ij->i", G, self.guide_weights[k][bk])
            out[r::P, c::Q][:ny, :nx] = v.reshape(ny, nx)
        return out

    # -- files ------------------------------------------------------------------
    def to_bytes(self):
        """The .npz file's content (see :meth:`save`)."""
        with np.load(io.BytesIO(self.base.to_bytes())) as z:
            base = {f"base_{k}": z[k] for k in z.files}
        buf = io.BytesIO()
        np.savez(buf, format=np.array(_MAGIC), version=np.array(FORMAT_VERSION),
                 weights=self.weights.astype(np.float32),
                 guide_weights=self.guide_weights.astype(np.float32),
                 noise_thresholds=self.noise_thresholds, lam=np.array(self.lam),
                 n_guide=np.array(N_GUIDE), meta_keys=np.array(list(self.meta), dtype=str),
                 meta_values=np.array([repr(v) for v in self.meta.values()], dtype=str),
                 **base)
        return buf.getvalue()

    def save(self, path):
        """Write the filters to ``path`` (.npz, atomically)."""
        atomic_write(path, self.to_bytes())

    @classmethod
    def load(cls, path, name="filters", *, max_bytes=None):
        """Read a file written by :meth:`save`; ValueError naming ``name`` if it is not one.
        ``max_bytes``: the read limit (:func:`rgbz_fast.io.read_limits`)."""
        p = Path(path)
        z = read_npz(p, name, max_bytes=max_bytes)
        if not is_z_guided_file(z):
            raise ValueError(f"{name}: {p} is not a rgbz-fast z_guided filters file")
        try:
            version = int_field(z, "version", p, name)
            if version != FORMAT_VERSION:
                raise ValueError(f"{name}: {p} has format version {version}, this "
                                 f"library reads version {FORMAT_VERSION}")
            n_guide = int_field(z, "n_guide", p, name)
            if n_guide != N_GUIDE:
                raise ValueError(f"{name}: {p} has {n_guide} guide features, expected "
                                 f"{N_GUIDE}")
            base = LearnedFilters._from_arrays(
                {k[len("base_"):]: v for k, v in z.items() if k.startswith("base_")}, p, name)
            meta = read_meta(z, p, name)
            return cls(base, z["weights"], z["guide_weights"], z["noise_thresholds"],
                       float_field(z, "lam", p, name), meta=meta)
        except FILE_ERRORS as e:            # the learned loader's form: the file named once
            raise file_error(e, p, name) from None


def _derived(f, pattern):
    """:meth:`ZGuidedFilters.for_pattern`: the taps and buckets moved as the base's are, the
    guide weights of the 3 x 3 measurements flipped with the window."""
    if pattern == f.pattern:
        return f
    tr = pattern_transform(f.pattern, pattern)
    base = f.base.for_pattern(pattern)
    if tr is None or base is None:
        return None
    try:
        z_layout(pattern)
    except ValueError:
        return None
    fy, fx, oy, ox = tr
    P, Q = pattern.period
    src_geom = f.base.geometry
    src_index = {ph["rc"]: k for k, ph in enumerate(src_geom)}
    nb = f.base.n_buckets
    octant = mirror_octants() if fy * fx < 0 else np.arange(N_ANGLES)
    per_angle = nb // N_ANGLES
    bmap = (octant[:, None] * per_angle + np.arange(per_angle)[None, :]).reshape(-1)
    levels = f.n_buckets // nb
    bmap = (np.arange(levels)[:, None] * nb + bmap[None, :]).reshape(-1)
    # the measurement (dy, dx) of the 3 x 3, row-major, is (fy dy, fx dx) of the source
    cells = [(fy * dy + _K) * (2 * _K + 1) + fx * dx + _K
             for dy in range(-_K, _K + 1) for dx in range(-_K, _K + 1)]
    gmap = np.array(cells + list(range(len(cells), N_GUIDE)))
    weights = np.zeros_like(f.weights)
    gw = np.zeros_like(f.guide_weights)
    for k, ph in enumerate(base.geometry):
        r, c = ph["rc"]
        ks = src_index[((fy * r + oy) % P, (fx * c + ox) % Q)]
        taps = {tuple(t): i for i, t in enumerate(src_geom[ks]["taps"])}
        idx = np.array([taps[(fy * dy, fx * dx)] for dy, dx in ph["taps"]])
        weights[k, :, :len(idx)] = f.weights[ks][bmap][:, idx]
        gw[k] = f.guide_weights[ks][bmap][:, gmap]
    meta = {**f.meta, "derived_from": f"{f.pattern.name}, digest {f.digest}"}
    return ZGuidedFilters(base, weights, gw, f.noise_thresholds, f.lam, meta=meta)


def check_base(base, pattern, bit_depth, name):
    """ValueError naming ``name`` unless learned filters ``base`` are for ``pattern`` and
    ``bit_depth`` exactly (z_guided filters are fitted on one pattern and bit depth)."""
    if get_pattern(pattern) != base.pattern:
        raise ValueError(f"{name}: fitted for pattern {base.pattern.name!r} "
                         f"({base.pattern.tile_string}), the frame's is "
                         f"{get_pattern(pattern).name!r}")
    if bit_depth != base.bit_depth:
        raise ValueError(f"{name}: fitted for {base.bit_depth}-bit frames, the frame has "
                         f"{bit_depth} bits")


def is_z_guided_file(arrays):
    """True if the arrays of an .npz are a z_guided filters file (its format tag)."""
    f = arrays.get("format")
    return f is not None and f.dtype.kind in "US" and str(f) == _MAGIC


def check_any_filters(value, name="filters", *, max_bytes=None):
    """``filters`` of ReconstructParams: as :func:`._learned.check_filters`, and z_guided
    filters (:class:`ZGuidedFilters` or their files) beside the learned ones. ``max_bytes``:
    the read limit of the files."""
    if value is None:
        return None
    items = [value] if isinstance(value, (str, Path, LearnedFilters, ZGuidedFilters)) else value
    try:
        items = list(items)
    except TypeError:
        raise TypeError(f"{name}: expected a LearnedFilters, a ZGuidedFilters, a path to a "
                        f"filters file, a sequence of them or None, got "
                        f"{type(value).__name__}") from None
    out = []
    for v in items:
        if isinstance(v, ZGuidedFilters):
            out.append(v)
        elif isinstance(v, (str, Path)) and Path(v).suffix.lower() == ".npz" and \
                Path(v).is_file() and is_z_guided_file(read_npz(v, name, keys=("format",),
                                                                max_bytes=max_bytes)):
            out.append(ZGuidedFilters.load(v, name, max_bytes=max_bytes))
        else:
            out.extend(check_filters(v, name, max_bytes=max_bytes))
    if not out:
        raise ValueError(f"{name}: empty sequence")
    return tuple(out)


def learned_only(filters, name="filters"):
    """The LearnedFilters of a checked ``filters`` value (which may hold z_guided filters beside
    them, as an evaluation of both methods passes); None (the shipped ones) for None, and a
    ValueError naming ``name`` when it holds z_guided filters only (:func:`check_kind`)."""
    if filters is None:
        return None
    out = tuple(f for f in filters if isinstance(f, LearnedFilters))
    if not out:
        check_kind(filters, "learned", name)
    return out or None


def holds_kind(filters, method):
    """Whether the checked ``filters`` (None: the shipped ones) hold one of ``method``'s kind
    (``"learned"`` or ``"z_guided"``)."""
    kind = LearnedFilters if method == "learned" else ZGuidedFilters
    return filters is None or any(isinstance(f, kind) for f in filters)


def check_kind(filters, method, name="filters"):
    """ValueError naming ``name`` when the checked ``filters`` hold none of ``method``'s kind
    (``"learned"`` or ``"z_guided"``): the method's shipped filters had run in their place,
    the given ones unused (the CLI's ``--filters`` check, in the API's words)."""
    if holds_kind(filters, method):
        return
    have = " and ".join(sorted({"learned" if isinstance(f, LearnedFilters) else "z_guided"
                                for f in filters}))
    fit = "train" if method == "learned" else "train_z_guided"
    raise ValueError(f"{name}: the given filters hold {have} filters; method {method!r} takes "
                     f"its own kind (rgbz_fast.reconstruction.{fit})")


def default_z_filters(pattern, bit_depth=11):
    """The :class:`ZGuidedFilters` shipped for a pattern and bit depth, or None.

    The package ships Mask1 and Mask2 (GRBG) filters for 11-bit linear frames,
    fitted on the 20 RGB-NIR pairs on top of the shipped ``learned`` filters
    (``reconstruction/data/z_guided_*.npz``; the command that made them is in
    their metadata, ``meta["command"]``); mirrored, they serve the RGGB, BGGR
    and GBRG phases (:meth:`ZGuidedFilters.for_pattern`).
    """
    pattern = get_pattern(pattern)
    key = (pattern.tile_string, int(bit_depth))
    if key not in _SHIPPED:
        found = None
        for f in sorted(_DATA.glob("z_guided_*.npz")):
            zf = ZGuidedFilters.load(f).for_pattern(pattern)
            if zf is not None and zf.bit_depth == bit_depth:
                found = zf
                break
        _SHIPPED[key] = found
    return _SHIPPED[key]


def resolve_z_filters(filters, pattern, bit_depth, name="filters"):
    """The :class:`ZGuidedFilters` for a frame: one of ``filters`` fitted for its pattern (or
    mirrored to it) and bit depth, or the shipped ones (:func:`default_z_filters`) when none
    of ``filters`` are."""
    check_kind(filters, "z_guided", name)
    # the layout first: a pattern z_guided cannot read (2x2 Z sites off the quads) had been
    # told to fit filters, which no fit could give
    z_layout(pattern)
    cands = () if filters is None else tuple(f for f in filters if isinstance(f, ZGuidedFilters))
    if not cands:
        shipped = default_z_filters(pattern, bit_depth)
        if shipped is not None:
            return shipped
        raise ValueError(f"{name}: method 'z_guided' needs z_guided filters, and none ship for "
                         f"pattern {pattern.name!r} at {bit_depth} bits: fit some with "
                         "rgbz_fast.reconstruction.train_z_guided and pass filters=FILE")
    for f in cands:
        d = f.for_pattern(pattern)
        if d is not None and d.bit_depth == bit_depth:
            return d
    if len(cands) == 1:
        cands[0].check_frame(pattern, bit_depth, name)
    have = ", ".join(f"{f.pattern.name} {f.bit_depth}-bit" for f in cands)
    raise ValueError(f"{name}: no z_guided filters fit pattern {pattern.name!r} at "
                     f"{bit_depth} bits (given: {have})")
