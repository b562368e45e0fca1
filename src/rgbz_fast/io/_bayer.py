"""Real Bayer frames as RGB-Z frames, and where they clip.

:func:`to_rgbz` turns a plain Bayer frame (from :func:`rgbz_fast.io.read_raw`)
into an RGB-Z frame of the same phase (Z sites zeroed) plus the full CFA as
the reference, which is how real raw data is evaluated (the paper's HDR+
burst dataset, section 5.2.2 [1]_). :func:`clipped_mask` and
:func:`frame_clip_level` say where such a frame saturates.

References
----------
.. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", section 5.2.2 (HDR+ burst, real Bayer data, 2x binned) (docs/references.bib: rebiere_rgbz)
"""

from __future__ import annotations

import numpy as np

from .._frame import RawFrame, _Adopt, raw_clip_level
from .._patterns import BAYER_PHASES, Pattern, Z, get_pattern, mask1, mask2, rows
from .._validate import as_array, check_number

__all__ = ["to_rgbz", "clipped_mask", "frame_clip_level"]

_RGBZ_PRESETS = {"mask1": mask1, "mask2": mask2, "rows": rows}


def to_rgbz(frame, pattern):
    """Make an RGB-Z frame and its reference from a real Bayer frame.

    Parameters
    ----------
    frame : RawFrame
        A plain Bayer frame (no Z sites), e.g. from :func:`~rgbz_fast.io.read_raw`.
    pattern : {"mask1", "mask2", "rows"}, str or Pattern
        The RGB-Z preset or a tile string (``"ZRGR/BGBG/GRZR/BGBG"``). A
        preset is built on the frame's Bayer phase (``mask1(phase)``); a
        tile is shifted by a row and/or a column onto it
        (:func:`place_on_phase`); a phase suffix (``"mask1_rggb"``) or a
        :class:`~rgbz_fast.Pattern` must agree with it.

    Returns
    -------
    rgbz : RawFrame
        The RGB-Z frame: the CFA with the Z sites set to 0, its ``reference``
        the full CFA, ``meta`` copied from ``frame`` (with ``"clipped"``
        cropped alike and ``"rgbz_pattern"`` added).
    reference : ndarray, shape (rows, cols)
        The full raw CFA (the ground truth of the reconstruction).

    Notes
    -----
    Both are cropped at the bottom and right to the largest multiple of the
    pattern period (2x2 for Mask1, 4x4 for Mask2, 6x2 for rows), so that
    every tile is whole and the phase at (0, 0) is kept.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast import RawFrame, bayer
    >>> from rgbz_fast.io import to_rgbz
    >>> cfa = RawFrame(np.arange(1, 21, dtype=np.uint16).reshape(4, 5), bayer("RGGB"))
    >>> rgbz, ref = to_rgbz(cfa, "mask1")
    >>> rgbz.pattern.tile_string, rgbz.data
    ('RZ/GB', array([[ 1,  0,  3,  0],
           [ 6,  7,  8,  9],
           [11,  0, 13,  0],
           [16, 17, 18, 19]], dtype=uint16))
    """
    if not isinstance(frame, RawFrame):
        raise TypeError(f"frame: expected a RawFrame, got {type(frame).__name__}")
    if frame.pattern.has_z:
        raise ValueError(f"frame: pattern {frame.pattern.name!r} already has Z sites; "
                         "expected a plain Bayer frame")
    phase = frame.pattern.bayer_phase
    if phase is None:
        raise ValueError(f"frame: pattern {frame.pattern.name!r} is not a Bayer CFA")
    target = place_on_phase(pattern, phase) if isinstance(pattern, str) else \
        _rgbz_pattern(pattern, phase)
    P, Q = target.period
    r = frame.shape[0] - frame.shape[0] % P
    c = frame.shape[1] - frame.shape[1] % Q
    if r == 0 or c == 0:
        raise ValueError(f"frame: {frame.shape[0]}x{frame.shape[1]} is smaller than one "
                         f"period ({P}x{Q}) of pattern {target.name!r}")
    reference = np.ascontiguousarray(frame.data[:r, :c])
    data = reference.copy()
    data[target.channel_map((r, c)) == Z] = 0
    meta = dict(frame.meta)
    if isinstance(meta.get("clipped"), np.ndarray) and meta["clipped"].shape == frame.shape:
        cm = np.ascontiguousarray(meta["clipped"][:r, :c])
        cm.setflags(write=False)
        meta["clipped"] = cm
    meta["rgbz_pattern"] = target.name
    meta["crop_rgbz"] = (int(r), int(c))
    rgbz = RawFrame(_Adopt(data), target, frame.bit_depth, reference=reference, meta=meta)
    return rgbz, reference


def clipped_mask(frame, clip_level=None, *, radius=0):
    """Where the raw data is clipped (saturated).

    Parameters
    ----------
    frame : RawFrame or ndarray, shape (rows, cols)
        A frame from :func:`~rgbz_fast.io.read_raw` or :func:`to_rgbz` (its
        ``meta["clipped"]`` is used), another RawFrame (pixels at its white
        level ``2**bit_depth - 1``; Z sites are never clipped), or a plain
        array (needs ``clip_level``).
    clip_level : float, optional
        Values at or above it are clipped. Overrides ``meta["clipped"]``
        and the white level.
    radius : int
        Grow the mask by this many pixels (Chebyshev distance, a square
        window). ``radius=2`` flags every pixel whose 5x5 reconstruction
        window touches a clipped pixel.

    Returns
    -------
    ndarray of bool, shape (rows, cols)

    Raises
    ------
    TypeError
        ``clip_level`` is not a number.
    ValueError
        ``clip_level`` is NaN or infinite (a NaN level would flag nothing),
        or missing for a plain array; ``radius`` is not an integer >= 0.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.io import clipped_mask
    >>> clipped_mask(np.array([[0, 1020], [5, 1023]]), 1020).astype(int)
    array([[0, 1],
           [0, 1]])
    """
    if clip_level is not None:
        clip_level = check_number(clip_level, "clip_level")
    if isinstance(radius, bool) or not isinstance(radius, (int, np.integer)) or radius < 0:
        raise ValueError(f"radius: expected a non-negative integer, got {radius!r}")
    if radius > 1 << 16:
        raise ValueError(f"radius: expected at most {1 << 16} pixels, got {radius!r}")
    if isinstance(frame, RawFrame):
        stored = frame.meta.get("clipped")
        if clip_level is None and isinstance(stored, np.ndarray) and stored.shape == frame.shape:
            mask = np.array(stored, dtype=bool)
        else:
            level = frame.white_level if clip_level is None else clip_level
            mask = frame.data >= level
            mask[frame.z_mask] = False
    else:
        if clip_level is None:
            raise ValueError("clip_level: a plain array needs clip_level= (the raw value at "
                             "which the sensor saturates)")
        data = as_array(frame, "frame")
        if data.ndim != 2:
            raise ValueError(f"frame: expected a 2-D array, got shape {data.shape}")
        mask = data >= clip_level
    if radius > 0:
        from scipy.ndimage import maximum_filter

        mask = maximum_filter(mask, size=2 * int(radius) + 1, mode="constant", cval=False)
    return mask


#: the clip level of a frame read from a raw file (:func:`rgbz_fast._frame.raw_clip_level`)
frame_clip_level = raw_clip_level


def place_on_phase(pattern, phase):
    """``pattern`` (a preset name, a tile string or a Pattern) on the Bayer phase ``phase``.

    A preset is built on the phase (``mask1(phase)``). Any other tile is shifted by one row
    and/or one column -- the shift that maps its Bayer phase onto ``phase`` -- which is what
    the presets' other phases are (``mask1("RGGB")`` is ``mask1()`` shifted by a column):
    the layout stays the same, the frame's colour sites keep their colours.

    Raises
    ------
    ValueError
        ``pattern`` has no Z sites, its colour sites fit no Bayer phase, or a preset
        name's phase suffix (``"mask1_rggb"``) differs from ``phase``.

    Examples
    --------
    >>> from rgbz_fast.io._bayer import place_on_phase
    >>> place_on_phase("ZRGR/BGBG/GRZR/BGBG", "RGGB").tile_string
    'RGRZ/GBGB/RZRG/GBGB'
    """
    if isinstance(pattern, str):
        base, _, suffix = pattern.strip().lower().partition("_")
        if base in _RGBZ_PRESETS and (not suffix or suffix.upper() in BAYER_PHASES):
            return _rgbz_pattern(pattern, phase)
        pattern = get_pattern(pattern)
    elif not isinstance(pattern, Pattern):
        raise TypeError(f"pattern: expected a preset name, a tile string or a Pattern, got "
                        f"{type(pattern).__name__}")
    if not pattern.has_z:
        raise ValueError(f"pattern: {pattern.name!r} has no Z sites; expected 'mask1', "
                         "'mask2', 'rows' or a tile with Z sites such as 'ZRGR/BGBG/GRZR/BGBG'")
    if pattern.bayer_phase is None:
        raise ValueError(f"pattern: the colour sites of {pattern.name!r} fit no Bayer phase")
    if pattern.bayer_phase == phase:
        return pattern
    for shift in ((0, 0), (0, 1), (1, 0), (1, 1)):
        moved = np.roll(pattern.tile, (-shift[0], -shift[1]), (0, 1))
        try:
            return Pattern(moved, bayer=phase)
        except ValueError:                # the colour sites of this shift fit another phase
            continue
    raise ValueError(f"pattern: {pattern.name!r} cannot be placed on Bayer phase {phase!r}")


def _rgbz_pattern(pattern, phase):
    """The RGB-Z preset on the Bayer phase of the frame."""
    if isinstance(pattern, Pattern):
        if not pattern.has_z:
            raise ValueError(f"pattern: {pattern.name!r} has no Z sites")
        if pattern.bayer_phase != phase:
            raise ValueError(f"pattern: {pattern.name!r} lies on Bayer phase "
                             f"{pattern.bayer_phase!r}, the frame on {phase!r}")
        return pattern
    if not isinstance(pattern, str):
        raise TypeError(f"pattern: expected a preset name or a Pattern, got "
                        f"{type(pattern).__name__}")
    base, _, suffix = pattern.strip().lower().partition("_")
    if base not in _RGBZ_PRESETS:
        raise ValueError(f"pattern: expected one of {', '.join(map(repr, _RGBZ_PRESETS))}, "
                         f"got {pattern!r}")
    if suffix and suffix.upper() != phase:
        raise ValueError(f"pattern: {pattern!r} asks for Bayer phase {suffix.upper()!r}, "
                         f"but the frame is {phase!r}; pass {base!r}")
    return _RGBZ_PRESETS[base](phase)
