"""The candidate layouts of ``rgbz-fast pattern-study``: presets, tiles the user gives and
generated families, checked and de-duplicated.

Two tiles are **the same layout** when one becomes the other by a shift of a
whole number of Bayer periods (an even number of rows and of columns) and by
one of the flips or transposes that map the underlying Bayer mosaic onto
itself: the vertical and horizontal flips and the half turn always do (a flip
about a pixel keeps every row's and column's parity); the transpose and the
quarter turns only when red and blue lie on the same diagonal (RGGB, BGGR),
since on GRBG and GBRG they swap red and blue. A shift by an odd number of
rows or columns changes the Bayer phase, so layouts on different phases stay
distinct (a tile keeps its phase: the colour sites fix it). The key of a
layout (:func:`canonical_key`) is its phase and the smallest, in a fixed
order, of the Z masks of its equivalents, each at its own minimal period.

The Z pixel of a layout (:func:`z_pixel`) is what the sensor simulation
measures: 2x2 when its Z sites tile into 2x2 squares aligned on the Bayer
quads (Mask2, rows), else 1x1. Z sites that form other rectangles (a 2x1
Z pixel) are **not supported** by the sensor and the ToF ISP
(``ToFSensor.z_block`` takes 1 or 2, square): such a layout is studied for its
colour and cost and its depth is reported as not supported.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from math import gcd

import numpy as np

from .._patterns import (BAYER_PHASES, CHANNELS, MAX_PERIOD, Z, Pattern, get_pattern,
                         smallest_period)
from ..simulation._simulate import _z_block

__all__ = ["Candidate", "check_tile", "canonical_key", "z_pixel", "generate", "candidates",
           "parse_generate", "PRESETS", "GENERATE_KEYS", "UNSUPPORTED"]

#: the preset layouts a study may name
PRESETS = ("mask1", "mask2", "rows")
#: the fields of a --generate specification, and their defaults
GENERATE_KEYS = {"block": ("1", "2"), "period": ("4", "8"),
                 "arrangement": ("aligned", "staggered"), "density": None}
UNSUPPORTED = ("not supported: {h}x{w} Z pixels (the sensor and the ToF ISP take square "
               "Z pixels of 1x1 or 2x2 sites aligned on the Bayer quads, ToFSensor.z_block)")

# the eight symmetries of the square grid: (swap rows and columns, sign of rows, of columns)
_D4 = [(t, sy, sx) for t in (False, True) for sy in (1, -1) for sx in (1, -1)]


@dataclass
class Candidate:
    """One layout of a study: ``name``, ``pattern``, where it came from (``source``:
    preset, tile or generated), its Z pixel (``block``, 1 or 2; None: not supported, see
    ``note``), its Z pixel's size in sites (``z_size``) and its ``key``
    (:func:`canonical_key`)."""

    name: str
    pattern: Pattern
    source: str
    block: int | None
    z_size: tuple
    key: str
    note: str = ""
    same_as: list = field(default_factory=list)


def _lcm(a, b):
    return a * b // gcd(a, b)


def _z_on_even_period(pattern):
    """The Z mask over an even number of rows and columns (the tile repeated to them)."""
    P, Q = pattern.period
    return np.tile(pattern.tile == Z, (_lcm(P, 2) // P, _lcm(Q, 2) // Q))


def _components(mask):
    """Sizes (rows, cols) of the 4-connected Z groups of a periodic mask, and whether each
    fills its bounding box; a group that wraps around the whole period (a row of Z) counts
    as one, as wide as the period."""
    from scipy import ndimage

    P, Q = mask.shape
    big = np.tile(mask, (3, 3))
    lab, n = ndimage.label(big)
    out = []
    seen = set()
    for k, sl in enumerate(ndimage.find_objects(lab), start=1):
        r0, c0 = sl[0].start, sl[1].start
        # one representative per group: the copy whose top-left corner is in the centre tile
        if not (P <= r0 < 2 * P and Q <= c0 < 2 * Q):
            h, w = sl[0].stop - r0, sl[1].stop - c0
            if not (h >= 3 * P or w >= 3 * Q):
                continue
        box = lab[sl] == k
        h, w = box.shape
        key = (r0 % P, c0 % Q, h, w)
        if key in seen:
            continue
        seen.add(key)
        out.append((min(h, P) if h >= 3 * P else h, min(w, Q) if w >= 3 * Q else w,
                    bool(box.all())))
    return out


def check_tile(spec, name="tiles"):
    """The :class:`~rgbz_fast.Pattern` of a tile string (or a preset name); a ValueError naming
    ``name`` when the tile cannot be a layout of the study: unreadable, larger than
    32x32, no colour site, no Z site, colour sites that fit no Bayer phase, or a group of
    Z sites that is not a rectangle."""
    try:
        pattern = get_pattern(spec) if isinstance(spec, str) else Pattern(spec)
    except (ValueError, TypeError) as exc:
        raise ValueError(f"{name}: {spec!r} is not a tile ({exc})") from None
    if pattern.period[0] > MAX_PERIOD or pattern.period[1] > MAX_PERIOD:
        raise ValueError(f"{name}: {spec!r} is larger than {MAX_PERIOD}x{MAX_PERIOD}")
    if not pattern.has_z:
        raise ValueError(f"{name}: {spec!r} has no Z site, so no depth")
    if pattern.bayer_phase is None:
        raise ValueError(f"{name}: the colour sites of {spec!r} fit no Bayer phase (expected "
                         f"one of {', '.join(BAYER_PHASES)} with some sites turned into Z)")
    bad = [(h, w) for h, w, full in _components(_z_on_even_period(pattern)) if not full]
    if bad:
        raise ValueError(f"{name}: the Z sites of {spec!r} form a group that is not a "
                         f"rectangle (within a {bad[0][0]}x{bad[0][1]} box); a Z pixel is a "
                         "rectangle of sites")
    return pattern


def z_pixel(pattern):
    """(block, (rows, cols) of the Z pixel, note): block 2 when the Z sites tile into 2x2
    squares on the Bayer quads, 1 when every Z site stands alone, None (with the note why)
    for other rectangles."""
    if _z_block(pattern) == 2:
        return 2, (2, 2), ""
    sizes = {(h, w) for h, w, _ in _components(_z_on_even_period(pattern))}
    if sizes == {(1, 1)}:
        return 1, (1, 1), ""
    h, w = max(sizes, key=lambda s: s[0] * s[1])
    return None, (h, w), UNSUPPORTED.format(h=h, w=w)


def _bayer_keeps(phase, t, sy, sx):
    """True when the symmetry (t, sy, sx) about a site maps the Bayer mosaic ``phase`` onto
    itself."""
    b = np.array([[CHANNELS.index(phase[0]), CHANNELS.index(phase[1])],
                  [CHANNELS.index(phase[2]), CHANNELS.index(phase[3])]])
    for y in range(2):
        for x in range(2):
            v = (x, y) if t else (y, x)
            if b[(sy * v[0]) % 2, (sx * v[1]) % 2] != b[y, x]:
                return False
    return True


def _transformed(mask, A, t, sy, sx):
    """The periodic mask seen through the symmetry, on an A x A grid (A a common period)."""
    P, Q = mask.shape
    yy, xx = np.meshgrid(np.arange(A), np.arange(A), indexing="ij")
    if t:
        yy, xx = xx, yy
    return mask[(sy * yy) % P, (sx * xx) % Q]


def canonical_key(pattern):
    """The key two equivalent layouts share (see the module's text): the Bayer phase and
    the smallest of the minimal-period Z masks of the layout's equivalents."""
    pattern = get_pattern(pattern)
    phase = pattern.bayer_phase
    mask = smallest_period(_z_on_even_period(pattern))
    A = _lcm(_lcm(mask.shape[0], mask.shape[1]), 2)
    best = None
    for t, sy, sx in _D4:
        if not _bayer_keeps(phase, t, sy, sx):
            continue
        m = _transformed(mask, A, t, sy, sx)
        for dy in range(0, A, 2):
            for dx in range(0, A, 2):
                r = smallest_period(np.roll(m, (-dy, -dx), (0, 1)))
                code = (r.shape, r.astype(np.uint8).tobytes())
                if best is None or code < best:
                    best = code
    (p, q), bits = best
    rows = ["".join("Z" if v else "." for v in bits[i * q:(i + 1) * q]) for i in range(p)]
    return f"{phase}:{'/'.join(rows)}"


# --------------------------------------------------------------------------- generated
def parse_generate(spec, name="generate"):
    """A family specification, ``"block=1,2 period=4,8 arrangement=aligned,staggered
    density=0.02:0.3"`` (fields separated by spaces or ``;``, any left out at its default),
    as a dict of tuples; a ValueError naming ``name`` for anything else."""
    if isinstance(spec, dict):
        items = dict(spec)
    else:
        items = {}
        for part in re.split(r"[;\s]+", str(spec).strip()):
            if not part:
                continue
            key, eq, value = part.partition("=")
            if not eq:
                raise ValueError(f"{name}: expected KEY=VALUES, got {part!r}")
            key = key.strip().lower()
            if key in items:                    # the last one had won, silently
                raise ValueError(f"{name}: {key} is given twice in {spec!r}; give each field "
                                 "once (its values comma-separated)")
            items[key] = value
        if not items:                           # '' had meant the whole default family
            raise ValueError(f"{name}: an empty specification; expected KEY=VALUES fields "
                             f"such as 'block=1,2 period=4,8' (any of {list(GENERATE_KEYS)})")
    bad = sorted(set(items) - set(GENERATE_KEYS))
    if bad:
        raise ValueError(f"{name}: unknown field(s) {bad}; expected some of "
                         f"{list(GENERATE_KEYS)}")
    out = {}
    for key, default in GENERATE_KEYS.items():
        v = items.get(key, default)
        if key == "density":
            out[key] = _density(v, name)
            continue
        vals = tuple(str(s).strip().lower() for s in (v.split(",") if isinstance(v, str)
                                                       else v))
        if not vals or not all(vals):           # 'block=1,,2': an entry left out
            raise ValueError(f"{name}: {key} has an empty entry in {v!r}")
        out[key] = tuple(_size(s, key, name) for s in vals) if key in ("block", "period") \
            else vals
    bad = [a for a in out["arrangement"] if a not in ("aligned", "staggered")]
    if bad:
        raise ValueError(f"{name}: arrangement {bad[0]!r}; expected aligned or staggered")
    for py, px in out["period"]:
        if py % 2 or px % 2 or py > MAX_PERIOD or px > MAX_PERIOD:
            raise ValueError(f"{name}: period {py}x{px}; expected whole Bayer periods (even "
                             f"numbers of sites) up to {MAX_PERIOD}")
    for bh, bw in out["block"]:
        if bh > 2 or bw > 2:
            raise ValueError(f"{name}: block {bh}x{bw}; expected 1, 2, 1x2 or 2x1")
    return out


def _size(text, key, name):
    m = re.fullmatch(r"(\d+)(?:x(\d+))?", str(text))
    if not m or int(m.group(1)) < 1 or (m.group(2) is not None and int(m.group(2)) < 1):
        raise ValueError(f"{name}: {key} {text!r}; expected N or NxM (rows x columns)")
    a = int(m.group(1))
    return a, int(m.group(2)) if m.group(2) is not None else a


def _density(v, name):
    if v is None:
        return None
    if isinstance(v, (tuple, list)):
        lo, hi = v
    else:
        try:
            lo, hi = (float(s) for s in str(v).split(":"))
        except ValueError:
            raise ValueError(f"{name}: density {v!r}; expected MIN:MAX, fractions of the "
                             "sites that are Z") from None
    if not 0 <= lo <= hi <= 1:
        raise ValueError(f"{name}: density {v!r}; expected 0 <= MIN <= MAX <= 1")
    return float(lo), float(hi)


def _tile_string(tile):
    return "/".join("".join(CHANNELS[c] for c in row) for row in tile)


def generate(spec, phase="GRBG", name="generate"):
    """The layouts of a family (:func:`parse_generate`), on the Bayer ``phase``: Z pixels of
    ``block`` sites, one per ``period`` (rows x columns of Bayer sites, even) in a square
    lattice (``aligned``) or with every other row of Z pixels moved half a period to the
    right (``staggered``, a period whose half is whole Bayer periods); their density (the
    share of sites that are Z) within ``density``. Each Z pixel covers the Bayer sites from
    the top-left green of a quad. Returns (candidates, notes on the combinations left out)."""
    spec = parse_generate(spec, name)
    bayer = Pattern("/".join([phase[:2], phase[2:]])).tile
    out, notes = [], []
    for bh, bw in spec["block"]:
        for py, px in spec["period"]:
            for arr in spec["arrangement"]:
                label = f"z{bh}x{bw}-p{py}x{px}-{arr[:4]}"
                if py < bh or px < bw:
                    notes.append(f"{label}: a period smaller than the Z pixel")
                    continue
                if arr == "staggered" and px % 4:
                    notes.append(f"{label}: staggered needs a period of 4k columns")
                    continue
                rows = py * (2 if arr == "staggered" else 1)
                tile = np.tile(bayer, (rows // 2, px // 2)).copy()
                tile[:bh, :bw] = Z
                if arr == "staggered":
                    tile[py:py + bh, px // 2:px // 2 + bw] = Z
                density = float(np.mean(tile == Z))
                lo, hi = spec["density"] or (0.0, 1.0)
                if not lo <= density <= hi:
                    continue
                try:
                    pattern = check_tile(_tile_string(tile), name)
                except ValueError as exc:
                    notes.append(f"{label}: {exc}")
                    continue
                pattern = Pattern(pattern.tile, name=label, bayer=phase)
                block, size, note = z_pixel(pattern)
                out.append(Candidate(label, pattern, "generated", block, size,
                                     canonical_key(pattern), note))
    if not out and spec["density"] is not None:
        # the family's layouts all fell outside the density range: said, not dropped unseen
        notes.append(f"{name}: no layout of the family has a density within "
                     f"{spec['density'][0]:g}:{spec['density'][1]:g}")
    return out, notes


def candidates(presets=("mask1", "mask2"), tiles=(), generate_spec=None, name="tiles"):
    """The layouts of a study, in the order given (presets, tiles, generated), each once:
    a layout equivalent to an earlier one (:func:`canonical_key`) is dropped and its name
    kept in the earlier one's ``same_as``. Returns (candidates, notes). Every tile is
    checked before anything runs (:func:`check_tile`, errors naming ``name``)."""
    found = []
    for p in presets:
        key = str(p).strip().lower()
        if key.split("_")[0] not in PRESETS:
            raise ValueError(f"presets: {p!r}; expected some of {', '.join(PRESETS)} "
                             "(optionally _rggb, _bggr, _gbrg)")
        pattern = check_tile(key, "presets")
        found.append(("preset", pattern))
    for i, t in enumerate(tiles):
        pattern = check_tile(t, name)
        if pattern.name == pattern.tile_string:
            pattern = Pattern(pattern.tile, name=f"tile{i + 1}", bayer=pattern.bayer_phase)
        found.append(("tile", pattern))
    out, notes = [], []
    for source, pattern in found:
        block, size, note = z_pixel(pattern)
        out.append(Candidate(pattern.name, pattern, source, block, size,
                             canonical_key(pattern), note))
    if generate_spec is not None:
        gen, notes = generate(generate_spec)
        out += gen
    kept, by_key = [], {}
    names = set()
    for c in out:
        if c.key in by_key:
            by_key[c.key].same_as.append(c.name)
            continue
        if c.name in names:
            raise ValueError(f"{name}: two layouts are named {c.name!r}")
        names.add(c.name)
        by_key[c.key] = c
        kept.append(c)
    return kept, notes
