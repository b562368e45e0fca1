"""The data a sensor delivers: raw frames, time-of-flight taps, and sampling an image on a pattern.

:class:`RawFrame` is a mosaic of digital numbers plus the pattern that produced
it (and, from a simulation, the reference Bayer CFA and the ToF taps);
:class:`ToFTaps` holds the four taps of every Z measurement at every
modulation frequency. Both are produced by the sensor models and by the file
readers and consumed by the ISPs, so they live below all of them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ._patterns import Pattern, Z, get_pattern
from ._sensors import ToFSensor
from ._validate import (FRAME_DTYPES, as_array, as_list, check_bit_depth, check_dtype,
                        check_block, check_fill, check_finite, check_frequencies, check_image, check_int,
                        check_meta, check_sites, finite_range, integer_bits,
                        read_only_state)
from ._validate import _check_range, _in_range_fast

__all__ = ["RawFrame", "ToFTaps", "mosaic", "validate_frame", "frame_inputs", "raw_clip_level"]


@dataclass(frozen=True, eq=False)
class RawFrame:
    """A raw sensor frame: digital numbers on a colour-depth filter array.

    Parameters
    ----------
    data : ndarray, shape (rows, cols)
        Digital numbers in [0, 2**bit_depth - 1]; uint8, uint16, float32 or
        float64. Z sites hold no colour (their value is ignored).
    pattern : Pattern or str
        The pattern of the frame.
    bit_depth : int
        Bits of the ADC (default 11, as in the paper).
    reference : ndarray, optional
        The plain Bayer CFA of the same exposure (the paper's green path),
        when the frame comes from a simulation.
    tof : object, optional
        Time-of-flight taps at the Z sites (see :mod:`rgbz_fast.simulation`), or None
        when no depth was simulated.
    meta : dict
        Free-form metadata (source file, sensor parameters, ...).

    Attributes
    ----------
    z_mask : ndarray of bool, shape (rows, cols)
        True at the Z sites.
    white_level : int
        ``2**bit_depth - 1``.

    Notes
    -----
    The frame owns its arrays: ``data`` and ``reference`` are copied (C order)
    when the frame is made, then checked and made read-only, so that a later
    write to the caller's array cannot put NaN or out-of-range values past the
    checks. For a 12-megapixel uint16 frame the copy adds 6 to 14 ms to the
    6 ms of the checks (an SG reconstruction of it takes 110 to 170 ms on 2
    threads; medians measured side by side on a busy 2-core machine); a
    reconstruction of a plain array (``reconstruct(array, pattern=...)``)
    makes no copy.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast import RawFrame
    >>> a = np.zeros((4, 4), np.uint16)
    >>> frame = RawFrame(a, "mask1")
    >>> a[0, 1] = 60000                  # the caller's array, not the frame's
    >>> int(frame.data[0, 1]), frame.data.flags.writeable
    (0, False)
    """

    data: np.ndarray
    pattern: Pattern
    bit_depth: int = 11
    reference: np.ndarray | None = None
    tof: Any = None
    meta: dict = field(default_factory=dict)

    if TYPE_CHECKING:
        # the __init__ type checkers see (py.typed is shipped): ``pattern`` also takes a
        # preset name or a tile, which __post_init__ makes the Pattern the field holds
        def __init__(self, data: np.ndarray, pattern: Pattern | str, bit_depth: int = 11,
                     reference: np.ndarray | None = None, tof: Any = None,
                     meta: dict = ...) -> None: ...

    def __setstate__(self, state):          # a pickled or deep-copied frame stays read-only
        read_only_state(self, state)

    def __post_init__(self):
        pattern = get_pattern(self.pattern)
        object.__setattr__(self, "pattern", pattern)
        bd = check_bit_depth(self.bit_depth)
        object.__setattr__(self, "bit_depth", bd)
        # copied before the checks: what is checked is what the frame keeps
        data = validate_frame(_owned(self.data, "data"), pattern, bd, "data")
        object.__setattr__(self, "data", _read_only(data))
        if self.reference is not None:
            ref = check_image(_owned(self.reference, "reference"), "reference", ndim=2,
                              dtypes=FRAME_DTYPES)
            if ref.shape != self.data.shape:
                raise ValueError(f"reference: shape {ref.shape} differs from data "
                                 f"{self.data.shape}")
            _check_range(ref, bd, "reference")
            object.__setattr__(self, "reference", _read_only(ref))
        # checked here, not where they are used: a list as meta or a number as tof failed
        # later with an AttributeError deep inside the ISP or a writer
        if self.tof is not None and not isinstance(self.tof, ToFTaps):
            raise TypeError(f"tof: expected ToFTaps or None, got {type(self.tof).__name__}")
        if isinstance(self.tof, ToFTaps) and self.tof.shape != self.data.shape:
            raise ValueError(f"tof: taps of a {self.tof.shape[0]}x{self.tof.shape[1]} frame, "
                             f"the data is {self.data.shape[0]}x{self.data.shape[1]}")
        if isinstance(self.tof, ToFTaps):
            _check_z_sites(self.tof, pattern)
        object.__setattr__(self, "meta", check_meta(self.meta, "meta"))

    @property
    def shape(self):
        return self.data.shape

    @property
    def white_level(self):
        return (1 << self.bit_depth) - 1

    @property
    def z_mask(self):
        return self.pattern.z_mask(self.data.shape)

    @property
    def missing_colour(self):
        return self.pattern.missing_colour(self.data.shape)

    def __repr__(self):
        extra = ", with reference" if self.reference is not None else ""
        extra += ", with ToF taps" if self.tof is not None else ""
        return (f"RawFrame({self.data.shape[0]}x{self.data.shape[1]} {self.data.dtype}, "
                f"pattern={self.pattern.name!r}, bit_depth={self.bit_depth}{extra})")


def _check_z_sites(tof, pattern):
    """Every cell of every measurement's block is a Z site of ``pattern``: a measurement at
    a colour pixel would be reported as depth there."""
    from . import _kernels

    rows, cols = tof.sites
    tile_z = np.ascontiguousarray(pattern.tile == Z, np.uint8)
    i = _kernels.sites_off_z(np.ascontiguousarray(rows), np.ascontiguousarray(cols),
                             tof.block, tile_z)
    if i >= 0:
        raise ValueError(f"tof: the measurement at ({rows[i]}, {cols[i]}) (a {tof.block}x"
                         f"{tof.block} block) covers a colour pixel of pattern "
                         f"{pattern.name!r}; ToF measurements sit on its Z sites")


class _Adopt:
    """An array the library has just made and hands to a RawFrame, which keeps it as its own
    without copying it (the public constructor copies what a caller may still hold)."""

    __slots__ = ("array",)

    def __init__(self, array):
        self.array = array


def _owned(a, name="data"):
    """A C-ordered copy of an array-like (None stays None): the frame's own memory. An
    :class:`_Adopt` array is kept as it is when it is already C-ordered."""
    if a is None:
        return None
    if isinstance(a, _Adopt):
        return np.ascontiguousarray(a.array)
    if isinstance(a, np.ma.MaskedArray):
        a = a.data
    return np.array(as_array(a, name), copy=True, order="C")


def _read_only(a):
    a.setflags(write=False)
    return a


def validate_frame(data, pattern, bit_depth, name):
    """Check a raw frame array against its pattern and bit depth; returns ``np.asarray(data)``.

    Errors name ``name``: 2-D, a supported dtype, finite, at least one
    period, values (colour sites only) within [0, 2**bit_depth - 1], and a
    dtype wide enough for the bit depth.
    """
    data = check_image(data, name, ndim=2, dtypes=FRAME_DTYPES, finite=False)
    # a frame whose extremes are in range is finite too (NaN makes them NaN, infinity is out
    # of range): one reduction pass each, no frame-sized temporary; any other frame gets the
    # checks one by one, so that its errors come in the same order
    in_range = _in_range_fast(data, (1 << bit_depth) - 1)
    if not in_range:
        check_finite(data, name)
    if data.dtype == np.uint8 and bit_depth > 8:
        raise ValueError(f"{name}: a uint8 frame cannot hold {bit_depth}-bit data; "
                         "pass uint16 or a float dtype, or bit_depth <= 8")
    pattern.check_shape(data.shape, name)
    if not in_range:
        _check_range(data, bit_depth, name, pattern)
    return data


def frame_inputs(frame, pattern=None, bit_depth=None, name="frame"):
    """``(data, pattern, bit_depth)`` of a frame argument: a RawFrame, or an array plus pattern.

    What every function taking ``frame, *, pattern=None, bit_depth=None``
    does first. A :class:`RawFrame` gives its own data, pattern and bit depth
    (already checked when it was made); a ``pattern`` or ``bit_depth`` passed
    with it must agree with them. A plain array needs ``pattern``, takes
    ``bit_depth`` 11 by default, and is checked by :func:`validate_frame`
    under ``name``, without a copy.

    Raises
    ------
    TypeError
        A plain array without ``pattern``; a bad pattern or bit depth type.
    ValueError
        A ``pattern`` or ``bit_depth`` that differs from the frame's; an array
        :func:`validate_frame` refuses.
    """
    if isinstance(frame, RawFrame):
        if pattern is not None and get_pattern(pattern) != frame.pattern:
            raise ValueError(f"pattern: {get_pattern(pattern).name!r} differs from the "
                             f"frame's pattern {frame.pattern.name!r}")
        if bit_depth is not None and check_bit_depth(bit_depth) != frame.bit_depth:
            raise ValueError(f"bit_depth: {bit_depth} differs from the frame's {frame.bit_depth}")
        return frame.data, frame.pattern, frame.bit_depth
    if pattern is None:
        raise TypeError(f"pattern: required when {name} is a plain array "
                        "(pass a RawFrame, or pattern='mask1', ...)")
    pattern = get_pattern(pattern)
    bd = check_bit_depth(11 if bit_depth is None else bit_depth)
    return validate_frame(frame, pattern, bd, name), pattern, bd


def mosaic(rgb, pattern="mask1", bit_depth=11, *, dtype=np.uint16, input_bits=None):
    """Sample an RGB image on a pattern: the raw frame a noise-free sensor would give.

    Parameters
    ----------
    rgb : ndarray, shape (rows, cols, 3)
        The image. Integer input of k bits is scaled to the full range of the
        bit depth, ``round(v / (2**k - 1) * (2**bit_depth - 1))``; float input
        is taken as [0, 1]. An integer type wider than 16 bits (int32, int64:
        a list of Python ints) needs ``input_bits`` (see
        :func:`rgbz_fast._validate.integer_bits`).
    pattern : Pattern or str
        The pattern; ``bayer(...)`` gives the reference CFA of the same image.
    bit_depth : int
        Bits of the output (default 11).
    dtype : {uint16, uint8, float32, float64}
        Output dtype. Integer outputs are rounded; float outputs keep the
        exact scaled values.
    input_bits : int, optional
        Bits of integer input, 1 up to the dtype's width (default: the width
        for types of at most 16 bits, 8 for uint8 and 16 for uint16; required
        for wider ones, int32 or int64). Not for float input.

    Returns
    -------
    RawFrame
        ``data`` holds the colour of the underlying Bayer at every colour site
        and 0 at the Z sites.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast import mosaic, mask1
    >>> img = np.full((4, 4, 3), 255, np.uint8)
    >>> mosaic(img, mask1()).data
    array([[   0, 2047,    0, 2047],
           [2047, 2047, 2047, 2047],
           [   0, 2047,    0, 2047],
           [2047, 2047, 2047, 2047]], dtype=uint16)
    """
    pattern = get_pattern(pattern)
    bd = check_bit_depth(bit_depth)
    img = check_image(rgb, "rgb", ndim=3)
    if img.shape[2] != 3:
        raise ValueError(f"rgb: expected 3 channels in the last axis, got shape {img.shape}")
    k = integer_bits(img, "rgb", input_bits)
    out_dtype = check_dtype(dtype, FRAME_DTYPES)
    if out_dtype == np.uint8 and bd > 8:
        raise ValueError(f"dtype: uint8 cannot hold {bd}-bit data")
    top = (1 << bd) - 1
    shape = pattern.check_shape(img.shape[:2], "rgb")
    colour = pattern.bayer_map(shape)
    rr, cc = np.indices(shape, sparse=True)
    sampled = img[rr, cc, colour]
    if k is not None:
        scaled = sampled.astype(np.float64) * (top / ((1 << k) - 1))
    else:
        if sampled.min() < 0 or sampled.max() > 1:
            raise ValueError(f"rgb: float values span [{sampled.min()}, {sampled.max()}]; "
                             "float input is taken as [0, 1]")
        scaled = sampled.astype(np.float64) * top
    if np.issubdtype(out_dtype, np.integer):
        data = np.floor(scaled + 0.5).astype(out_dtype)
    else:
        data = scaled.astype(out_dtype)
    data[pattern.channel_map(shape) == Z] = 0
    return RawFrame(_Adopt(data), pattern, bd)


@dataclass(frozen=True, eq=False)
class ToFTaps:
    """The four taps of every Z measurement at every frequency, as the chip reads them.

    Attributes
    ----------
    taps : ndarray, shape (F, 4, n_sites)
        Digital numbers (uint16; float64 when the sensor does not quantise):
        ``taps[i, k, n]`` is tap k (at ``-k * 90`` degrees, see the module
        docstring for the convention) of measurement n at frequency i.
    frequencies : ndarray, shape (F,)
        Modulation frequencies in Hz.
    sites : (rows, cols) tuple of int64 arrays, shape (n_sites,)
        Top-left pixel of each Z measurement in the frame, row-major order.
    block : int
        Z pixel size in colour pixels (1: Mask1; 2: Mask2, one measurement
        per 2x2 Z pixel).
    bit_depth : int
        ADC bits of the taps.
    depth_true : ndarray of float64, shape (n_sites,)
        Ground-truth distance in metres (mean over the block's cells).
    valid : ndarray of bool, shape (n_sites,)
        False where the scene's depth is unknown (e.g. invalid disparity) or
        beyond :attr:`unambiguous_range`.
    saturated : ndarray of bool, shape (n_sites,)
        True where a tap at some frequency reached full well or full scale.
    sensor : ToFSensor
        The parameters used (with ``pixel_pitch_um`` resolved).
    shape : tuple (rows, cols)
        Frame shape.
    meta : dict
        From a simulation: ``noise``, ``seed``, ``system_gain``... and
        ``ir_estimated``: True when the scene had no NIR reflectance and the
        simulation estimated it from the RGB (the amplitude then carries the
        colour: no evidence for a method guided by it), False when it was
        given, None when unknown (a file saved before it was recorded).
    """

    taps: np.ndarray
    frequencies: np.ndarray
    sites: tuple
    block: int
    bit_depth: int
    depth_true: np.ndarray
    valid: np.ndarray
    saturated: np.ndarray
    sensor: ToFSensor
    shape: tuple
    meta: dict = field(default_factory=dict)

    def __setstate__(self, state):          # a pickled or deep-copied frame stays read-only
        read_only_state(self, state)

    def __post_init__(self):
        # own copies, read-only (as RawFrame): the caller's arrays stay the caller's; every
        # field checked here, where a file or a caller gives it (complex or text taps, float
        # or repeated sites, 0 or 99 bits failed later or gave silent results)
        if self.taps is None:
            raise TypeError("taps: expected an array of shape (F, 4, n_sites), got None")
        taps = _owned(self.taps, "taps")
        if taps.ndim != 3 or taps.shape[1] != 4:
            raise ValueError(f"taps: expected shape (F, 4, n_sites), got {taps.shape}")
        if taps.dtype.kind not in "iuf":
            raise TypeError(f"taps: expected real numbers, got dtype {taps.dtype}")
        check_finite(taps, "taps")
        F, _, n = taps.shape
        freqs = check_frequencies(self.frequencies, "frequencies", unique=True)
        if freqs.shape != (F,):
            raise ValueError(f"frequencies: expected {F} values, got shape {freqs.shape}")
        adopted = isinstance(self.sites, _Adopt)
        rows, cols, span = check_sites(self.sites.array if adopted else self.sites, "sites",
                                       copy=not adopted, span=True)
        per_site = {k: _owned(getattr(self, k), k) for k in ("depth_true", "valid",
                                                             "saturated")}
        for name, a in (("sites", rows), ("sites", cols), *per_site.items()):
            if np.shape(a) != (n,):
                raise ValueError(f"{name}: expected shape ({n},), got {np.shape(a)}")
        if n and per_site["depth_true"].dtype.kind not in "iuf":
            raise TypeError(f"depth_true: expected metres, got dtype "
                            f"{per_site['depth_true'].dtype}")
        if n:
            # the ground truth every depth error is measured against: NaN or infinity gave
            # "median nan mm", a negative depth an error of metres
            lo, _ = finite_range(per_site["depth_true"], "depth_true")
            if lo < 0:
                raise ValueError(f"depth_true: holds negative depths (min {lo:g} m); expected "
                                 "metres >= 0")
        for k in ("valid", "saturated"):
            if n and per_site[k].dtype != np.bool_:
                raise TypeError(f"{k}: expected a bool array, got dtype {per_site[k].dtype}")
        block = check_block(self.block, "block")
        object.__setattr__(self, "block", block)
        object.__setattr__(self, "bit_depth", check_bit_depth(self.bit_depth, "bit_depth"))
        top = (1 << self.bit_depth) - 1             # the ADC's codes: none can lie beyond
        if taps.size and (taps.min() < 0 or taps.max() > top):
            raise ValueError(f"taps: values span [{taps.min():g}, {taps.max():g}], beyond the "
                             f"{self.bit_depth}-bit range [0, {top}]")
        if not isinstance(self.sensor, ToFSensor):
            raise TypeError(f"sensor: expected a ToFSensor, got {type(self.sensor).__name__}")
        sf = np.asarray(self.sensor.frequencies, np.float64)
        if sf.shape != (F,) or not np.allclose(sf, freqs, rtol=1e-9, atol=0):
            # the ISP takes the noise model from the sensor and the phases from the taps: a
            # file whose two disagree failed deep in the validity stage (another count), or
            # was read at the taps' frequencies without a word (other values)
            raise ValueError(f"sensor: {len(self.sensor.frequencies)} frequencies "
                             f"{list(self.sensor.frequencies)}, the taps {F} "
                             f"{freqs.tolist()}; give the sensor the taps' frequencies")
        if self.sensor.bit_depth != self.bit_depth:
            raise ValueError(f"sensor: a {self.sensor.bit_depth}-bit ADC, the taps "
                             f"{self.bit_depth}-bit codes; give the sensor the taps' bit depth")
        shape = as_list(self.shape, "shape", "a (rows, cols) frame shape")
        if len(shape) != 2 or not all(isinstance(v, (int, np.integer)) and
                                      not isinstance(v, bool) for v in shape) \
                or min(shape) < block:
            raise ValueError(f"shape: expected a (rows, cols) frame shape, got {self.shape!r}")
        shape = tuple(int(v) for v in shape)
        object.__setattr__(self, "meta", check_meta(self.meta, "meta"))
        # every site's block inside the frame (a file could say anything)
        for name, lo, hi, size in (("rows", *span[:2], shape[0]), ("cols", *span[2:], shape[1])
                                   ) if n else ():
            if lo < 0 or hi > size - block:
                raise ValueError(f"sites: {name} span [{lo}, {hi}], outside the "
                                 f"{shape[0]}x{shape[1]} frame")
        for a in (taps, freqs, rows, cols, *per_site.values()):
            a.setflags(write=False)
        object.__setattr__(self, "taps", taps)
        object.__setattr__(self, "frequencies", freqs)
        object.__setattr__(self, "sites", (rows, cols))
        for k, a in per_site.items():
            object.__setattr__(self, k, a)
        object.__setattr__(self, "shape", shape)

    @property
    def n_sites(self):
        return int(self.taps.shape[2])

    @property
    def black_level(self):
        return self.sensor.black_level

    @property
    def white_level(self):
        return (1 << self.bit_depth) - 1

    @property
    def unambiguous_range(self):
        return self.sensor.unambiguous_range

    def amplitude(self, frequency=None, *, workers=None):
        """The demodulated amplitude of every Z measurement: what the Z pixels see of the scene.

        ``|I + iQ| / 2`` in DN (``I = A0 - A2``, ``Q = A3 - A1``; the black
        level and the ambient light cancel), by the C kernel of
        :func:`rgbz_fast.tof.demodulate`. At one distance it is proportional
        to the NIR reflectance at the laser wavelength, which is what
        ``reconstruct(frame, "z_guided")`` uses as its guide; it falls as
        ``1 / d^2`` with the distance ``d``, and noise biases it upwards
        where it is small.

        Parameters
        ----------
        frequency : int, "all" or None
            Index into :attr:`frequencies`; ``"all"``: every frequency; None
            (default): the mean over the frequencies (less noisy).
        workers : int, optional
            Threads (None or -1: all cores); the result does not depend on it.

        Returns
        -------
        ndarray of float64, shape (n_sites,) or, for ``"all"``, (F, n_sites)
            One value per measurement (paint it with :meth:`to_frame`).

        Examples
        --------
        >>> import numpy as np
        >>> from rgbz_fast.simulation import Scene, simulate
        >>> ir = np.tile([0.2, 0.2, 0.8, 0.8], (8, 2))          # a dark and a bright half
        >>> scene = Scene(np.full((8, 8, 3), 0.5), depth=np.full((8, 8), 1.0), ir_reflectance=ir)
        >>> amp = simulate(scene, "mask1", noise=False).tof.amplitude()
        >>> amp.shape, bool(amp[1] > 3 * amp[0])
        ((16,), True)
        """
        from . import _kernels
        from ._validate import check_workers

        F = self.taps.shape[0]
        every = isinstance(frequency, str) and frequency == "all"
        index = isinstance(frequency, (int, np.integer)) and not isinstance(frequency, bool)
        if not (frequency is None or every or (index and -F <= frequency < F)):
            raise ValueError(f"frequency: expected an index into the {F} frequencies, 'all' or "
                             f"None, got {frequency!r}")
        taps = self.taps if self.taps.dtype in (np.uint16, np.float32, np.float64) else \
            self.taps.astype(np.float64)
        taps = np.ascontiguousarray(taps)
        phase, amp, off = (np.empty((F, self.n_sites)) for _ in range(3))
        _kernels.tof_demodulate(taps, phase, amp, off, check_workers(workers))
        if every:
            return amp
        return amp.mean(axis=0) if frequency is None else amp[frequency]

    def to_frame(self, values, fill=0.0):
        """Paint per-measurement values onto the frame (every cell of its block).

        Parameters
        ----------
        values : array_like, shape (n_sites,) or (F, n_sites)
            One value per measurement, or one per frequency and measurement (as
            :meth:`amplitude` gives them with ``frequency="all"``).
        fill : scalar
            Value of the pixels that are no Z measurement (a bool array stays bool with a
            fill of 0, 1 or a bool; with another fill it comes as float32 at least).

        Returns
        -------
        ndarray, shape ``self.shape`` or (F,) + ``self.shape``
        """
        return paint_sites(as_array(values, "values"), self.shape, self.sites, self.block,
                           check_fill(fill))

    def __repr__(self):
        mhz = ", ".join(f"{f / 1e6:g}" for f in self.frequencies)
        return (f"ToFTaps({self.n_sites} sites, block {self.block}, {mhz} MHz, "
                f"{self.bit_depth}-bit, {int(self.valid.sum())} valid)")


def paint_sites(v, shape, sites, block, fill):
    """``v`` (n,) or (F, n), one value per measurement at ``sites`` (top-left cells of
    ``block`` x ``block`` Z pixels), painted on every cell of its Z pixel of a frame of
    ``shape``; ``fill`` elsewhere (:meth:`ToFTaps.to_frame` and
    :meth:`~rgbz_fast.tof.ToFDepth.to_frame`). The type is the values' with the fill's: a
    bool map stays bool with a fill of 0, 1 or a bool (it had come back uint8, whose ``~``
    is 254 or 255: never false); a float of less than 4 bytes is float32 (a NaN fill of a
    bool or uint8 field, float16 before)."""
    r, c = sites
    n = r.size
    if v.shape[-1:] != (n,) or v.ndim > 2:
        raise ValueError(f"values: expected shape ({n},) or (F, {n}), got {v.shape}")
    if v.dtype == bool and not isinstance(fill, (float, np.floating)) and fill in (0, 1):
        dtype = np.dtype(bool)
    else:
        dtype = np.result_type(v.dtype, np.min_scalar_type(fill))
        if dtype.kind == "f" and dtype.itemsize < 4:
            dtype = np.dtype(np.float32)
    out = np.full(v.shape[:-1] + tuple(shape), fill, dtype=dtype)
    for dr in range(block):
        for dc in range(block):
            out[..., r + dr, c + dc] = v
    return out


def raw_clip_level(frame):
    """The clip level of a frame read from a raw file, in the frame's digital numbers.

    This is what ``reconstruct(frame, ..., clip_level="auto")`` uses. The level
    comes from the ``clip_level``, ``black_level`` and ``white_level`` that
    :func:`rgbz_fast.io.read_raw` records in ``meta`` (in the file's units, per
    quad site), scaled like the data: ``(clip - black) / (white - black) *
    (2**bit_depth - 1)``, rounded half up for integer frames, as the data are,
    so that a raw value at the clip level lands exactly on it. With four
    different levels the smallest is taken, so that no clipped pixel escapes (a
    few pixels just below the clip of the other quad sites are then flagged too).

    Parameters
    ----------
    frame : RawFrame
        A frame from :func:`rgbz_fast.io.read_raw` or :func:`rgbz_fast.io.to_rgbz`
        (or saved from one with :func:`rgbz_fast.io.save_frame`, which keeps the
        levels).

    Returns
    -------
    float or None
        None when ``meta`` records no levels (a simulated or RGB-derived frame).

    Notes
    -----
    A binned pixel (``downsample=k``) is clipped by this level only if all its
    k x k pixels were; one that averages clipped and unclipped pixels is below the
    level although ``meta["clipped"]`` flags it.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast import RawFrame, bayer
    >>> from rgbz_fast.io import frame_clip_level
    >>> meta = {"black_level": (0,) * 4, "white_level": (1023,) * 4, "clip_level": (1020,) * 4}
    >>> frame_clip_level(RawFrame(np.zeros((2, 2), np.uint16), bayer("RGGB"), meta=meta))
    2041.0
    """
    if not isinstance(frame, RawFrame):
        raise TypeError(f"frame: expected a RawFrame, got {type(frame).__name__}")
    meta = frame.meta or {}
    try:
        clip, black, white = (np.asarray(meta[k], dtype=np.float64).reshape(-1)
                              for k in ("clip_level", "black_level", "white_level"))
    except (KeyError, TypeError, ValueError):
        return None
    if not (clip.size == black.size == white.size == 4) or np.any(white <= black):
        return None
    top = float(frame.white_level)
    # the expression read_raw applies to a pixel at the clip level
    scaled = float(np.min((clip - black) / (white - black) * top))
    if scaled > top:               # beyond every code: read_raw flagged no pixel, neither does
        return None                # "auto" (clamped to full scale, it had flagged white ones)
    level = max(scaled, 0.0)
    if np.issubdtype(frame.data.dtype, np.integer):
        level = float(np.floor(level + 0.5))
    else:
        level = float(np.asarray(level, dtype=frame.data.dtype))
    if not level > 0:
        # the level is the saturation level the frame was read with (read_raw's clip_level,
        # the command line's --saturation-level), not a clip_level of the caller: named as
        # the frame's, in plain numbers (it had read "clip_level: (np.float64(20.0), ...)",
        # which the command line took for its --clip-level)
        where = "at or below" if np.any(clip <= black) else \
            f"within half a code (of the frame's {frame.bit_depth} bits) of"
        raise ValueError(f"frame: its saturation level (meta clip_level, the clip_level it "
                         f"was read with) {_levels_text(clip)} is {where} its black level "
                         f"{_levels_text(black)}: every pixel would be clipped")
    return level


def _levels_text(levels):
    """Quad levels as text: one number when they are equal, else the four ('20', '(20, 30,
    30, 30)')."""
    vals = [float(v) for v in np.ravel(levels)]
    return f"{vals[0]:g}" if len(set(vals)) == 1 else "(" + ", ".join(f"{v:g}" for v in vals) + ")"
