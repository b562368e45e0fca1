"""RGB-Z colour-depth filter array patterns (CDFA).

A pattern is a small tile of channel codes (R=0, G=1, B=2, Z=3) repeated over
the frame. Every preset is derived from a Bayer mosaic by turning some colour
sites into depth (Z) sites, and every Z site stands in for the colour of that
underlying Bayer: the colour that the reconstruction has to fill in.

References
----------
.. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", Figs. 1 and 4 (Mask1, Mask2) (docs/references.bib: rebiere_rgbz)
.. [2] Shi et al., the RGB-Z matrix with two rows of Z every four rows (docs/references.bib: shi_rgbz)
"""

from __future__ import annotations

import numpy as np

from ._validate import as_array, check_entries, read_only_state

__all__ = [
    "R", "G", "B", "Z", "CHANNELS", "BAYER_PHASES", "MAX_PERIOD",
    "Pattern", "bayer", "mask1", "mask2", "rows", "get_pattern", "check_z_patterns",
]

R, G, B, Z = 0, 1, 2, 3
CHANNELS = "RGBZ"
BAYER_PHASES = ("GRBG", "RGGB", "BGGR", "GBRG")
#: the largest tile, in rows and in columns. The paper's patterns repeat every 6 rows or
#: fewer; each Z site of a tile costs a reconstruction plan (a 256x256 tile: 7 s, 200 MB).
MAX_PERIOD = 32


def _check_period(rows_, cols):
    if rows_ > MAX_PERIOD or cols > MAX_PERIOD:
        raise ValueError(f"tile: {rows_}x{cols} sites, more than the largest tile "
                         f"({MAX_PERIOD}x{MAX_PERIOD})")


def _bayer_tile(bayer):
    bayer = str(bayer).upper()
    if bayer not in BAYER_PHASES:
        raise ValueError(
            f"phase: expected one of {', '.join(BAYER_PHASES)}, got {bayer!r}")
    return np.array([[CHANNELS.index(bayer[0]), CHANNELS.index(bayer[1])],
                     [CHANNELS.index(bayer[2]), CHANNELS.index(bayer[3])]],
                    dtype=np.int8)


def _parse_tile(tile):
    """Return an int8 array of channel codes from a tile string or array."""
    if isinstance(tile, str):
        text = tile.replace(" ", "").upper()
        rows_ = [r for r in text.replace("\n", "/").replace(",", "/").split("/")]
        if not text or any(len(r) == 0 for r in rows_):
            raise ValueError(f"tile: empty row in {tile!r}; expected rows such as 'ZR/BG'")
        widths = {len(r) for r in rows_}
        _check_period(len(rows_), max(widths))
        if len(widths) != 1:
            raise ValueError(f"tile: ragged rows {rows_} (lengths {sorted(widths)}); "
                             "every row must have the same length")
        bad = sorted({c for r in rows_ for c in r if c not in CHANNELS})
        if bad:
            raise ValueError(f"tile: unknown channel letter(s) {bad} in {tile!r}; "
                             "use R, G, B and Z")
        arr = np.array([[CHANNELS.index(c) for c in r] for r in rows_], dtype=np.int8)
    else:
        arr = as_array(tile, "tile")
        if arr.ndim != 2 or arr.size == 0:
            raise ValueError(f"tile: expected a non-empty 2-D array of channel codes, "
                             f"got shape {arr.shape}")
        if not np.issubdtype(arr.dtype, np.integer):
            raise TypeError(f"tile: expected integer channel codes, got dtype {arr.dtype}")
        _check_period(*arr.shape)
        if arr.min() < 0 or arr.max() > 3:
            raise ValueError("tile: channel codes must be 0 (R), 1 (G), 2 (B) or 3 (Z)")
        arr = arr.astype(np.int8)
    if not np.any(arr != Z):
        raise ValueError("tile: the tile holds no colour site (only Z)")
    return arr


def _lcm(a, b):
    return a * b // np.gcd(a, b)


def smallest_period(tile):
    """``tile`` cut to its smallest period (rows, then columns): the tile that repeats to the
    same mosaic (``ZRZR/BGBG/ZRZR/BGBG`` -> ``ZR/BG``)."""
    P, Q = tile.shape
    p = next(d for d in range(1, P + 1) if P % d == 0 and np.array_equal(tile, np.roll(tile, d, 0)))
    q = next(d for d in range(1, Q + 1) if Q % d == 0 and np.array_equal(tile, np.roll(tile, d, 1)))
    return tile[:p, :q]


class Pattern:
    """A colour-depth filter array: a tile of channel codes repeated over a frame.

    Parameters
    ----------
    tile : str or array_like of int, shape (P, Q)
        Rows of channel letters separated by ``/`` (``"ZR/BG"``), or an array
        of channel codes R=0, G=1, B=2, Z=3. A tile that repeats within itself
        is kept at its smallest period (``"ZRZR/BGBG/ZRZR/BGBG"`` is
        ``"ZR/BG"``): the same layout is the same pattern everywhere.
    name : str, optional
        A short name used in reports (defaults to the tile string).
    bayer : {"GRBG", "RGGB", "BGGR", "GBRG"}, optional
        The underlying Bayer phase. By default it is inferred from the colour
        sites of the tile (GRBG first when several phases agree, e.g. when
        every green of a phase is replaced by Z).

    Examples
    --------
    >>> from rgbz_fast import mask1
    >>> p = mask1()
    >>> p.period
    (2, 2)
    >>> str(p)
    'ZR/BG'
    >>> p.z_mask((2, 4)).astype(int)
    array([[1, 0, 1, 0],
           [0, 0, 0, 0]])
    """

    def __init__(self, tile, *, name=None, bayer=None):
        # one layout, one pattern: a tile written at a multiple of its period (Mask1 as
        # ZRZR/BGBG/ZRZR/BGBG) had moved the border taps by that multiple, not the period,
        # and reconstructed the frame's edges otherwise (up to 449 DN at 230 of 4096 sites),
        # costed more line buffers and found no shipped learned filters (H104)
        self._tile = np.ascontiguousarray(smallest_period(_parse_tile(tile)))
        self._tile.setflags(write=False)
        # the tile is read-only: its period and whether it holds Z are fixed, and asked at
        # every kernel call of a frame
        self._period = tuple(int(s) for s in self._tile.shape)
        self._has_z = bool(np.any(self._tile == Z))
        self.name = str(name) if name is not None else self.tile_string
        self._bayer = self._infer_bayer(bayer)

    def __setstate__(self, state):          # a pickled or deep-copied tile stays read-only
        read_only_state(self, state)

    # -- basic properties -------------------------------------------------
    @property
    def tile(self):
        """ndarray of int8, shape (P, Q): the channel codes (read-only)."""
        return self._tile

    @property
    def period(self):
        """tuple (rows, cols): the repetition period of the tile."""
        return self._period

    @property
    def tile_string(self):
        return "/".join("".join(CHANNELS[c] for c in row) for row in self._tile)

    @property
    def bayer_phase(self):
        """str or None: the underlying Bayer phase, None if the colour sites fit none."""
        return self._bayer

    @property
    def has_z(self):
        return self._has_z

    @property
    def z_fraction(self):
        """float: fraction of the sites that are Z."""
        return float(np.mean(self._tile == Z))

    def __repr__(self):
        return f"Pattern({self.tile_string!r}, name={self.name!r}, bayer={self._bayer!r})"

    def __str__(self):
        return self.tile_string

    def __eq__(self, other):
        return (isinstance(other, Pattern) and self.period == other.period
                and np.array_equal(self._tile, other._tile) and self._bayer == other._bayer)

    def __hash__(self):
        return hash((self._tile.tobytes(), self.period, self._bayer))

    # -- Bayer inference ----------------------------------------------------
    def _infer_bayer(self, bayer):
        if bayer is not None:
            bayer = str(bayer).upper()
            if bayer not in BAYER_PHASES:
                raise ValueError(f"bayer: expected one of {', '.join(BAYER_PHASES)}, got {bayer!r}")
            if not self._fits(bayer):          # the phases it fits, to say so
                fits = [c for c in BAYER_PHASES if self._fits(c)]
                raise ValueError(f"bayer: the colour sites of tile {self.tile_string!r} do not "
                                 f"fit the Bayer phase {bayer!r} (they fit {fits or 'none'})")
            return bayer
        return next((c for c in BAYER_PHASES if self._fits(c)), None)

    def _fits(self, candidate):
        """Whether every colour site of the tile is that of the Bayer phase ``candidate``."""
        P, Q = self.period
        LP, LQ = _lcm(P, 2), _lcm(Q, 2)
        ext = np.tile(self._tile, (LP // P, LQ // Q))
        b = np.tile(_bayer_tile(candidate), (LP // 2, LQ // 2))
        known = ext != Z
        return bool(np.array_equal(ext[known], b[known]))

    # -- maps over a frame --------------------------------------------------
    def check_shape(self, shape, name="shape"):
        """Raise ValueError unless ``shape`` is a 2-D frame shape holding at least one period."""
        try:
            ok = all(isinstance(s, (int, np.integer)) and not isinstance(s, (bool, np.bool_))
                     for s in shape)
        except TypeError:
            ok = False
        if not ok:                  # 4.9 had been truncated to 4, '4' parsed as 4
            raise TypeError(f"{name}: expected a (rows, cols) tuple of integers, got {shape!r}")
        shape = tuple(int(s) for s in shape)
        if len(shape) != 2:
            raise ValueError(f"{name}: expected a 2-D (rows, cols) frame shape, got {shape}")
        P, Q = self.period
        if shape[0] < P or shape[1] < Q:
            raise ValueError(f"{name}: frame {shape[0]}x{shape[1]} is smaller than one period "
                             f"({P}x{Q}) of pattern {self.name!r}")
        return shape

    def channel_map(self, shape):
        """ndarray of int8, shape (rows, cols): the channel code of every site."""
        rows_, cols = self.check_shape(shape)
        P, Q = self.period
        return np.tile(self._tile, (-(-rows_ // P), -(-cols // Q)))[:rows_, :cols]

    def z_mask(self, shape):
        """ndarray of bool, shape (rows, cols): True at the Z (depth) sites."""
        return self.channel_map(shape) == Z

    def bayer_tile(self):
        """ndarray of int8: the underlying Bayer colours over one period of this tile."""
        if self._bayer is None:
            raise ValueError(f"pattern: tile {self.tile_string!r} fits no Bayer phase, "
                             "so its Z sites stand in for no defined colour")
        P, Q = self.period
        LP, LQ = _lcm(P, 2), _lcm(Q, 2)
        return np.tile(_bayer_tile(self._bayer), (LP // 2, LQ // 2))[:P, :Q]

    def bayer_pattern(self):
        """The plain Bayer :class:`Pattern` underlying this one (the reference path)."""
        return bayer(self._bayer) if self._bayer is not None else self.bayer_tile()

    def missing_colour(self, shape):
        """ndarray of int8, shape (rows, cols): the colour each Z site stands in for, -1 elsewhere."""
        rows_, cols = self.check_shape(shape)
        P, Q = self.period
        tile = np.where(self._tile == Z, self.bayer_tile(), -1).astype(np.int8)
        return np.tile(tile, (-(-rows_ // P), -(-cols // Q)))[:rows_, :cols]

    def bayer_map(self, shape):
        """ndarray of int8, shape (rows, cols): the underlying Bayer colour of every site."""
        rows_, cols = self.check_shape(shape)
        P, Q = self.period
        return np.tile(self.bayer_tile(), (-(-rows_ // P), -(-cols // Q)))[:rows_, :cols]


def bayer(phase="GRBG"):
    """The plain Bayer pattern (no Z) of the given phase; GRBG is the paper's."""
    t = _bayer_tile(phase)
    return Pattern(t, name=f"bayer_{str(phase).lower()}", bayer=str(phase).upper())


def mask1(phase="GRBG"):
    """Mask1 (1x1 Z pixel, paper Fig. 4a): the green on the red row of each Bayer quad is Z.

    For the default GRBG phase the tile is ``Z R / B G``: a quarter of the
    pixels are Z and rows and columns holding Z hold no green.
    """
    t = _bayer_tile(phase).copy()
    # the green that shares its row with red
    r_row = int(np.argwhere(t == R)[0][0])
    g_col = int(np.argwhere(t[r_row] == G)[0][0])
    t[r_row, g_col] = Z
    name = "mask1" if str(phase).upper() == "GRBG" else f"mask1_{str(phase).lower()}"
    return Pattern(t, name=name, bayer=str(phase).upper())


def mask2(phase="GRBG"):
    """Mask2 (2x2 Z pixel, paper Fig. 4b): a 4x4 Bayer tile whose top-left quad is one Z pixel.

    Each 4x4 tile loses one G, R, B, G quad (a quarter of the colour sites);
    one depth measurement covers the four Z sites.
    """
    t = np.tile(_bayer_tile(phase), (2, 2))
    t[:2, :2] = Z
    name = "mask2" if str(phase).upper() == "GRBG" else f"mask2_{str(phase).lower()}"
    return Pattern(t, name=name, bayer=str(phase).upper())


def rows(phase="GRBG"):
    """Shi et al.'s row pattern (paper Fig. 1b): four Bayer rows then two rows of Z (period 6x2)."""
    t = np.tile(_bayer_tile(phase), (3, 1))
    t[4:, :] = Z
    name = "rows" if str(phase).upper() == "GRBG" else f"rows_{str(phase).lower()}"
    return Pattern(t, name=name, bayer=str(phase).upper())


_PRESETS = {"mask1": mask1, "mask2": mask2, "rows": rows, "bayer": bayer}


def get_pattern(pattern):
    """Coerce a :class:`Pattern`, a preset name ("mask1", "bayer_rggb", ...) or a tile string.

    Raises
    ------
    ValueError
        If the name is neither a preset nor a valid tile.
    """
    if isinstance(pattern, Pattern):
        return pattern
    if not isinstance(pattern, str):
        raise TypeError(f"pattern: expected a Pattern, a preset name or a tile string, "
                        f"got {type(pattern).__name__}")
    key = pattern.strip().lower()
    base, sep, phase = key.partition("_")
    if base in _PRESETS and (not sep or phase.upper() in BAYER_PHASES):
        return _PRESETS[base](phase.upper() or "GRBG")
    if key.upper() in BAYER_PHASES:
        return bayer(key.upper())
    try:
        return Pattern(pattern)
    except ValueError as exc:
        raise ValueError(
            f"pattern: {pattern!r} is neither a preset (mask1, mask2, rows, bayer, "
            f"optionally with _grbg/_rggb/_bggr/_gbrg) nor a valid tile ({exc})") from None


def check_z_patterns(patterns, name="patterns", why=None):
    """``patterns`` (names, tiles or Patterns; a comma-separated string is split) as a tuple:
    at least one, none twice (``mask1`` and ``mask1_grbg`` are one pattern: it would be run
    and counted twice), each with Z sites (without one, a measurement of what is made at the
    Z sites failed deep in a metric, a plan or the ToF ISP); else a ValueError naming
    ``name``. ``why``: what needs the Z sites, said in the error."""
    patterns = check_entries(patterns, name, key=get_pattern, strings=False)
    for p in patterns:
        pat = get_pattern(p)
        if not pat.has_z:
            given = p if isinstance(p, str) else pat.name
            advice = "give an RGB-Z pattern such as 'mask1'"
            raise ValueError(f"{name}: {given!r} has no Z site; "
                             + (f"{why} ({advice})" if why else advice))
    return patterns
