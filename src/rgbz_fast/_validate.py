"""Argument checks shared by every public function (Python validates, C computes).

Every check raises ``TypeError`` (wrong kind of value) or ``ValueError`` (a
value out of range) whose message starts with the name of the parameter, says
what it got and what it expects. There is one check per kind of value:
:func:`check_number` for every real parameter (bounds open or closed, None or
infinity allowed on request), :func:`check_int` for every integer one,
:func:`check_flag`, :func:`check_choice`, :func:`check_dtype`,
:func:`check_bit_depth`, :func:`check_entries` (a sequence of names, each once),
:func:`integer_bits` (the one rule for the range of integer
images), :func:`check_seed`, :func:`check_workers` (threads of
a C kernel, and the stacks OpenMP gives them) and :func:`check_processes` (worker processes), and
:func:`check_image` for arrays. :func:`merge_params` is the one rule of every stage
that takes parameters: a frozen dataclass (``params=``) plus keyword overrides of its
fields, checked once by the dataclass.
"""

from __future__ import annotations

import dataclasses
import math
import numbers
from collections.abc import Mapping

import numpy as np

from ._threads import (MAX_WORKERS, MIN_PIXELS_PER_THREAD, check_processes,
                       check_thread_stacks, check_workers, kernel_threads, thread_limit)

__all__ = ["check_image", "check_finite", "finite_range", "check_number", "check_int", "check_flag",
           "check_choice", "check_dtype", "check_bit_depth", "check_seed", "check_workers",
           "check_processes", "check_thread_stacks", "thread_limit", "parse_shape",
           "merge_params", "integer_bits", "check_entries", "check_path", "check_meta",
           "as_array", "as_list", "check_frequencies", "check_sites", "check_block",
           "check_fill", "FRAME_DTYPES", "FLOAT_DTYPES",
           "MAX_WORKERS", "TYPE_RANGE_BITS"]

#: dtypes a raw frame may hold; kernels read and write them directly.
FRAME_DTYPES = (np.dtype(np.uint8), np.dtype(np.uint16), np.dtype(np.float32),
                np.dtype(np.float64))
#: dtypes of the stages that take linear or encoded light as floats in [0, 1]: an integer
#: image there has no [0, 1] scale (200 would be clipped to 1), so it is refused
FLOAT_DTYPES = (np.dtype(np.float16), np.dtype(np.float32), np.dtype(np.float64))


def check_image(arr, name, ndim=None, dtypes=None, *, finite=True, values=None):
    """Return ``np.asarray(arr)`` after checking ndim, dtype kind, size and (``finite``)
    finiteness; a caller passing ``finite=False`` checks it itself. ``values``: what the
    array holds ("image values", "distances in metres"): a bool array, a mask, is then
    refused (True would be read as the value 1)."""
    if arr is None:
        raise TypeError(f"{name}: expected an array, got None")
    a = as_array(arr, name)
    if a.dtype == object or np.issubdtype(a.dtype, np.complexfloating):
        raise TypeError(f"{name}: expected a real numeric array, got dtype {a.dtype}")
    if not a.dtype.isnative:
        # a big-endian file's array: the same values in this machine's byte order (the
        # kernels' dtype lists named '>u2' unsupported, as if uint16 were not)
        a = a.astype(a.dtype.newbyteorder("="))
    if values is not None and a.dtype == np.bool_:
        raise TypeError(f"{name}: dtype bool is not supported; expected {values} (an integer "
                        "or float array), not a mask")
    if not (np.issubdtype(a.dtype, np.number) or a.dtype == np.bool_):
        raise TypeError(f"{name}: expected a numeric array, got dtype {a.dtype}")
    if ndim is not None:
        allowed = (ndim,) if isinstance(ndim, int) else tuple(ndim)
        if a.ndim not in allowed:
            raise ValueError(f"{name}: expected a {' or '.join(f'{n}-D' for n in allowed)} "
                             f"array, got shape {a.shape}")
    if a.size == 0:
        raise ValueError(f"{name}: the array is empty (shape {a.shape})")
    if dtypes is not None and a.dtype not in dtypes:
        raise TypeError(f"{name}: dtype {a.dtype} is not supported; expected one of "
                        f"{', '.join(str(d) for d in dtypes)}")
    if finite:
        check_finite(a, name)
    return a


#: the widest integer type whose width says the range of an image's values: uint8 holds 8-bit
#: values, uint16 16-bit ones (int8 7, int16 15, bool 1). NumPy makes int64 of any list of
#: Python ints and int32/uint32 are what wide readers give, whatever the data's range, so a
#: wider type says nothing about it (200 in an int64 is not 200 / (2**63 - 1) of full scale).
TYPE_RANGE_BITS = 16


def integer_bits(a, name, input_bits=None, *, what=None,
                 instead="; or pass a uint8 or uint16 array"):
    """The bits of the values of an integer image (None for a float one): the one rule.

    Every entry that reads an integer image against a range it takes from the
    image (``mosaic``, ``Scene``, the scene loaders, the evaluation) asks this
    function. The range is ``input_bits`` when the caller states it (1 up to
    the type's width), else the type's width when it is at most
    :data:`TYPE_RANGE_BITS` (bool 1, uint8 8, int8 7, uint16 16, int16 15);
    a wider type without ``input_bits`` is a TypeError, never the width of
    the type. The values must lie in ``[0, 2**bits - 1]``.

    Parameters
    ----------
    a : ndarray
        The image (already checked by :func:`check_image`).
    name : str
        The parameter named in the errors about the values.
    input_bits : int, optional
        The bits the caller states; not for float images.
    what : str, optional
        How the error names the image (default ``"an int64 image (a list of
        Python ints becomes int64)"``, with its dtype).
    instead : str
        The other way out the error gives, after ``input_bits``.

    Examples
    --------
    >>> integer_bits(np.zeros(3, np.uint8), "rgb"), integer_bits(np.zeros(3), "rgb")
    (8, None)
    >>> integer_bits(np.array([200]), "rgb", input_bits=8)
    8
    >>> integer_bits(np.array([200]), "rgb")
    Traceback (most recent call last):
    ...
    TypeError: rgb: an int64 image (a list of Python ints becomes int64) says nothing about the range of its values; pass input_bits= (the bits of the values, e.g. 8 or 12); or pass a uint8 or uint16 array
    """
    if input_bits is not None and (isinstance(input_bits, (bool, np.bool_))
                                   or not isinstance(input_bits, numbers.Integral)):
        raise TypeError(f"input_bits: expected an integer number of bits, got {input_bits!r}")
    if a.dtype.kind not in "biu":
        if input_bits is not None:
            raise ValueError(f"input_bits: applies to integer input only; {a.dtype} input is "
                             f"read as it is, got input_bits={input_bits}")
        return None
    width = 1 if a.dtype.kind == "b" else 8 * a.dtype.itemsize - (a.dtype.kind == "i")
    lo, hi = (a.min(), a.max()) if a.dtype.kind != "b" and a.size else (0, 0)
    if lo < 0:
        raise ValueError(f"{name}: integer values span [{lo}, {hi}]; expected values >= 0")
    if input_bits is None:
        if width > TYPE_RANGE_BITS:
            what = what or (f"{'an' if a.dtype.kind == 'i' else 'a'} {a.dtype} image"
                            + (" (a list of Python ints becomes int64)"
                               if a.dtype == np.int64 else ""))
            raise TypeError(f"{name}: {what} says nothing about the range of its values; pass "
                            f"input_bits= (the bits of the values, e.g. 8 or 12){instead}")
        bits = width
    else:
        bits = int(input_bits)
        if not 1 <= bits <= width:
            raise ValueError(f"input_bits: expected 1..{width} bits for {a.dtype} input, "
                             f"got {input_bits}")
    if int(hi) > (1 << bits) - 1:
        raise ValueError(f"{name}: integer values span [{lo}, {hi}], beyond the {bits}-bit "
                         f"input range [0, {(1 << bits) - 1}]")
    return bits


def check_path(value, name="path"):
    """A file or folder path (a non-empty str or os.PathLike) as a :class:`pathlib.Path`;
    a TypeError or ValueError naming ``name`` otherwise (NumPy scalars, bytes and None had
    os.fspath's message, which names no parameter)."""
    import os
    from pathlib import Path

    if not isinstance(value, (str, os.PathLike)):
        raise TypeError(f"{name}: expected a path (str or pathlib.Path), got "
                        f"{type(value).__name__} {value!r:.40}")
    text = os.fspath(value)
    if not isinstance(text, str):
        raise TypeError(f"{name}: expected a path (str or pathlib.Path), got a bytes path")
    if not text or "\0" in text:
        raise ValueError(f"{name}: expected a file name, got {text!r}")
    longest = max((len(os.fsencode(part)) for part in Path(text).parts), default=0)
    if longest > 255:
        raise ValueError(f"{name}: a name in {text[:60]!r}{'...' * (len(text) > 60)} is "
                         f"{longest} bytes, more than the 255 a file name may have")
    return Path(text)


def check_meta(meta, name="meta", allow_none=False):
    """Free-form metadata: a mapping with string keys, as a dict of its own (None: an empty
    one, when ``allow_none``); a TypeError naming ``name`` otherwise."""
    if meta is None and allow_none:
        return {}
    if not isinstance(meta, Mapping):
        raise TypeError(f"{name}: expected a dict, got {type(meta).__name__}")
    bad = next((k for k in meta if not isinstance(k, str)), None)
    if bad is not None:
        raise TypeError(f"{name}: expected string keys, got {bad!r}")
    return dict(meta)


def as_array(value, name, **kwargs):
    """``np.asarray(value, **kwargs)``, or a TypeError naming ``name`` when NumPy cannot make
    an array of it (a ragged list, an object it refuses): NumPy's message names no parameter.
    With a real ``dtype``, complex numbers, text and dates are refused too: the conversion
    would drop the imaginary part or read numbers out of text."""
    if value is None:                              # np.asarray(None, float) is NaN
        raise TypeError(f"{name}: expected an array of numbers, got None")
    try:
        a = np.asarray(value)
        if kwargs.get("dtype") is not None and np.dtype(kwargs["dtype"]).kind in "biuf" \
                and a.dtype.kind in "cUSMm":
            raise TypeError(f"{name}: expected real numbers, got dtype {a.dtype}")
        return np.asarray(a, **kwargs)
    except OverflowError:                      # an int beyond any float or the dtype
        raise ValueError(f"{name}: holds a number too large for "
                         f"{np.dtype(kwargs.get('dtype') or np.float64).name}") from None
    except (ValueError, TypeError) as exc:
        if str(exc).startswith(f"{name}: "):
            raise
        raise TypeError(f"{name}: expected an array of numbers, got a {type(value).__name__} "
                        f"NumPy cannot make one of ({' '.join(str(exc).split())[:80]})") \
            from None


def outside_stacklevel():
    """The ``stacklevel`` that makes a warning raised by the caller of this function name the
    first frame outside the package (the user's line, however deep the library's calls)."""
    import os
    import sys

    root = os.path.dirname(os.path.abspath(__file__))
    frame, level = sys._getframe(1), 1
    while frame is not None and os.path.abspath(frame.f_code.co_filename).startswith(root):
        frame, level = frame.f_back, level + 1
    return level


def nonfinite_as(obj, spell):
    """``obj`` with every non-finite Python float replaced by ``spell(value)`` (dicts, lists
    and tuples walked; tuples become lists), for ``json.dumps(..., allow_nan=False)``: JSON has
    no such numbers."""
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else spell(obj)
    if isinstance(obj, dict):
        return {k: nonfinite_as(v, spell) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [nonfinite_as(v, spell) for v in obj]
    return obj


class ReadOnlyDict(dict):
    """A dict that refuses changes (``_what`` says why), and pickles and copies as one (a
    MappingProxyType does not pickle); ``dict(d)`` is a copy to edit."""

    _what = "this mapping is read-only"

    def _refuse(self, *args, **kwargs):
        raise TypeError(self._what)

    __setitem__ = __delitem__ = update = pop = popitem = clear = setdefault = _refuse
    __ior__ = _refuse

    def __reduce__(self):
        return type(self), (dict(self),)


def read_only_state(obj, state):
    """``obj.__setstate__`` of a class whose arrays are read-only: the ``state`` of a pickle or
    a deep copy restored with its arrays (and those in its tuples and dicts) read-only again. NumPy
    unpickles arrays writeable and a deep copy copies them writeable, which let a copy's
    values be changed past the checks its constructor made."""
    def freeze(v):
        if isinstance(v, np.ndarray):
            v.setflags(write=False)
        elif isinstance(v, tuple):
            for x in v:
                freeze(x)
        elif isinstance(v, dict):          # a frame's meta (read_raw's clipped mask)
            for x in v.values():
                freeze(x)

    for v in state.values():
        freeze(v)
    obj.__dict__.update(state)


def real_array(value, name):
    """An own float64 copy of an array of real numbers; booleans, text, complex numbers and
    objects are a TypeError naming ``name`` (NumPy would read True as 1, parse text and drop
    an imaginary part)."""
    a = as_array(value, name)
    if a.dtype.kind not in "iuf":
        raise TypeError(f"{name}: expected real numbers, got dtype {a.dtype}")
    return np.array(a, np.float64)


def as_list(value, name, what="a sequence"):
    """``list(value)`` of a sequence (not a string, bytes, a mapping or a 0-d array), or a
    TypeError naming ``name``."""
    if isinstance(value, (str, bytes, Mapping)) or (isinstance(value, np.ndarray)
                                                    and value.ndim == 0):
        raise TypeError(f"{name}: expected {what}, got {type(value).__name__} {value!r:.40}")
    try:
        return list(value)
    except TypeError:
        raise TypeError(f"{name}: expected {what}, got {type(value).__name__} "
                        f"{value!r:.40}") from None


def check_frequencies(values, name="frequencies", *, unique=False):
    """Modulation frequencies: a non-empty 1-D sequence of real numbers >= 1 Hz, as float64
    (finite; ``unique``: none twice). A complex or text value was converted or dropped,
    an empty list or 0 Hz gave an infinite unambiguous range, a negative one a number."""
    f = as_array(values, name)
    if f.dtype.kind not in "iuf" or f.dtype == np.bool_:
        raise TypeError(f"{name}: expected real numbers in Hz, got dtype {f.dtype}")
    f = f.astype(np.float64).reshape(-1) if f.ndim <= 1 else f
    if f.ndim != 1 or f.size == 0:
        raise ValueError(f"{name}: expected one or more frequencies in Hz, got shape "
                         f"{np.shape(values)}")
    if not np.all(np.isfinite(f)) or f.min() < 1 or f.max() > 1e18:
        raise ValueError(f"{name}: expected frequencies in [1 Hz, 1e18 Hz], got "
                         f"{f.tolist()!r:.80}")
    if unique and np.unique(f).size != f.size:
        raise ValueError(f"{name}: a frequency is given twice in {f.tolist()}; each "
                         "frequency is one measurement")
    return f


def check_block(block, name="block"):
    """The size of a Z pixel in colour pixels: 1 (Mask1) or 2 (Mask2), as ``int``."""
    if isinstance(block, (bool, np.bool_)) or not isinstance(block, numbers.Integral) \
            or block not in (1, 2):
        raise ValueError(f"{name}: expected 1 or 2, got {block!r:.40}")
    return int(block)


def check_sites(sites, name="sites", copy=True, *, span=False):
    """Measurement sites: a pair (rows, cols) of 1-D integer arrays of one length, >= 0,
    no site twice; as two int64 arrays (copies, or with ``copy`` False the arrays themselves
    when they are int64). Float indices were truncated, a repeated site made two
    measurements of one pixel. With ``span``: also ``(row min, row max, col min, col max)``
    (None when there is no site).

    int64 sites (those the library makes and files hold) are checked in one C pass
    (csrc/scan.c: the span and the row-major order); a pair out of order is searched for a
    repeat by sorting."""
    pair = as_list(sites, name, "(rows, cols) arrays of pixel indices")
    if len(pair) != 2:
        raise TypeError(f"{name}: expected (rows, cols), got {len(pair)} arrays")
    arrs = []
    for label, a in zip(("rows", "cols"), pair):
        arr = as_array(a, name)
        if arr.ndim != 1:
            raise ValueError(f"{name}: expected two arrays of the same shape (n,), got "
                             f"{label} of shape {arr.shape}")
        if arr.size and (arr.dtype.kind not in "iu"):
            raise TypeError(f"{name}: expected integer pixel indices, got {label} of dtype "
                            f"{arr.dtype}")
        arrs.append(arr)
    if arrs[0].shape != arrs[1].shape:
        raise ValueError(f"{name}: expected two arrays of the same shape (n,), got "
                         f"{arrs[0].shape} and {arrs[1].shape}")
    rows, cols = (a.astype(np.int64, copy=copy) for a in arrs)
    lo_hi, ordered = None, True
    if rows.size:
        if rows.flags.c_contiguous and cols.flags.c_contiguous:
            from . import _kernels                  # _validate is imported before it
            lo_hi, ordered = _kernels.sites_range(rows, cols)
        else:
            lo_hi = (rows.min(), rows.max(), cols.min(), cols.max())
            ordered = None
        for label, a, lo, hi in (("rows", arrs[0], *lo_hi[:2]), ("cols", arrs[1], *lo_hi[2:])):
            if lo < 0 or hi >= 1 << 31:                 # the given values, not the int64 ones
                raise ValueError(f"{name}: {label} span [{a.min()}, {a.max()}]; expected "
                                 "pixel indices >= 0")
        lo_hi = tuple(int(v) for v in lo_hi)
    if rows.size > 1 and not ordered:
        key = rows * (lo_hi[3] + 1) + cols
        if ordered is None and np.all(key[1:] > key[:-1]):     # row-major: no repeat, O(n)
            return (rows, cols, lo_hi) if span else (rows, cols)
        order = np.argsort(key, kind="stable")
        same = np.flatnonzero(key[order][1:] == key[order][:-1])
        if same.size:
            i = order[same[0]]
            raise ValueError(f"{name}: the site ({rows[i]}, {cols[i]}) is given twice; "
                             "each measurement has a site of its own")
    return (rows, cols, lo_hi) if span else (rows, cols)


def merge_params(cls, params=None, overrides=None, *, name="params", caller=None, what=None):
    """The parameters of one call: ``params`` with keyword ``overrides`` of its fields.

    The one parameter rule of the library: a stage takes ``params=`` (an
    instance of the frozen dataclass ``cls``) and keyword overrides of its
    fields. The result is made by ``cls`` itself, so its ``__post_init__`` is
    the one place the fields are checked; the caller never checks them again.

    Parameters
    ----------
    cls : type
        A frozen dataclass whose ``__post_init__`` checks (and may normalise)
        every field.
    params : cls, mapping or None
        The base: an instance (returned as it is when there is nothing to
        override), a mapping of field names to values, or None (the defaults).
    overrides : mapping, optional
        Field values that replace those of ``params`` (a function's
        ``**kwargs``).
    name : str
        The parameter ``params`` is passed as, named in the errors about it.
    caller : str, optional
        What takes ``overrides``, named in the error about an unknown one
        (``"reconstruct()"``); default ``name``.
    what : str, optional
        How the error lists the accepted names (default ``"fields of CLS"``).

    Returns
    -------
    cls

    Raises
    ------
    TypeError
        ``params`` that is neither a ``cls``, a mapping nor None; a name that
        is no field of ``cls`` (the message Python gives for an unexpected
        keyword argument, plus the accepted names).
    ValueError, TypeError
        A bad field value, from ``cls`` (the message names the field).

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> @dataclass(frozen=True)
    ... class Blur:
    ...     sigma: float = 1.0
    ...     def __post_init__(self):
    ...         object.__setattr__(self, "sigma", check_number(self.sigma, "sigma", lo=0))
    >>> merge_params(Blur, None, {"sigma": 2})
    Blur(sigma=2.0)
    >>> merge_params(Blur, Blur(3.0), {"size": 5}, caller="blur()")
    Traceback (most recent call last):
    ...
    TypeError: blur() got an unexpected keyword argument 'size' (fields of Blur: sigma)
    """
    names = tuple(f.name for f in dataclasses.fields(cls))
    what = what or f"fields of {cls.__name__}"

    def known(mapping, label):
        unknown = [k for k in mapping if k not in names]
        if unknown:
            raise TypeError(f"{label} got an unexpected keyword argument {unknown[0]!r} "
                            f"({what}: {', '.join(names)})")
        return mapping

    overrides = known(dict(overrides or {}), caller or name)
    if isinstance(params, cls):
        return dataclasses.replace(params, **overrides) if overrides else params
    if params is None:
        base = {}
    elif isinstance(params, Mapping):
        base = known(dict(params), name)
    else:
        article = "an" if cls.__name__[:1] in "AEIOU" else "a"
        raise TypeError(f"{name}: expected {article} {cls.__name__}, a dict of its fields or "
                        f"None, got {type(params).__name__}")
    return cls(**{**base, **overrides})


def _scan(a):
    """(smallest, largest) of a float32/float64 array in one C pass (csrc/scan.c; not both
    finite if a value is NaN or infinite), or None for other types and layouts."""
    if a.dtype not in (np.float32, np.float64) or a.size == 0 or not (
            a.flags.c_contiguous or a.flags.f_contiguous):
        return None
    from . import _kernels                      # _validate is imported before the extension
    return _kernels.float_range(a.ravel(order="K"))


def _not_finite(a, name):
    bad = int(np.size(a) - np.count_nonzero(np.isfinite(a)))
    return ValueError(f"{name}: holds {bad} NaN or infinite value(s); expected finite data")


def check_finite(a, name):
    """ValueError naming ``name`` if a float array holds NaN or infinity."""
    if not np.issubdtype(a.dtype, np.floating):
        return
    scan = _scan(a)
    if scan is None:
        if not np.all(np.isfinite(a)):
            raise _not_finite(a, name)
    elif not (np.isfinite(scan[0]) and np.isfinite(scan[1])):
        raise _not_finite(a, name)


def finite_range(a, name):
    """``(min, max)`` of a non-empty real array as floats, after a ValueError naming
    ``name`` if it holds NaN or infinity: one pass for float32/float64 (csrc/scan.c)."""
    scan = _scan(a) if np.issubdtype(a.dtype, np.floating) else None
    if scan is None:
        check_finite(a, name)
        return float(a.min()), float(a.max())
    if not (np.isfinite(scan[0]) and np.isfinite(scan[1])):
        raise _not_finite(a, name)
    return float(scan[0]), float(scan[1])


def _real(value):
    """``value`` as a Python number if it is a real number (bool excluded), else None."""
    if isinstance(value, (bool, np.bool_)):
        return None
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf":
        value = value.item()
    if isinstance(value, numbers.Real):
        return value
    return None


def _bounds(lo, hi, lo_open, hi_open):
    def num(v):                 # an integer bound in full (2**40, not 1.09951e+12)
        return f"{v:d}" if isinstance(v, (int, np.integer)) and not isinstance(v, bool) \
            else f"{v:g}"

    parts = []
    if lo is not None:
        parts.append(f"{'>' if lo_open else '>='} {num(lo)}")
    if hi is not None:
        parts.append(f"{'<' if hi_open else '<='} {num(hi)}")
    return (" " + " and ".join(parts)) if parts else ""


def check_number(value, name, *, lo=None, hi=None, lo_open=False, hi_open=False,
                 allow_none=False, allow_inf=False):
    """A real number within the bounds, as ``float``.

    Parameters
    ----------
    value : object
        The value to check: an int, float or NumPy scalar (bool, strings and
        other objects are a TypeError).
    name : str
        The parameter named in the message.
    lo, hi : float, optional
        Bounds, closed unless ``lo_open`` / ``hi_open``.
    allow_none : bool
        None passes (and is returned).
    allow_inf : bool
        +inf passes when within the bounds (NaN never does).

    Examples
    --------
    >>> check_number(2, "gain", lo=0, lo_open=True)
    2.0
    >>> check_number(0, "gain", lo=0, lo_open=True)
    Traceback (most recent call last):
    ...
    ValueError: gain: expected a finite number > 0, got 0
    """
    if value is None and allow_none:
        return None
    v = _real(value)
    if v is None:
        raise TypeError(f"{name}: expected a number, got {value!r}")
    try:
        v = float(v)
    except OverflowError:                   # an int beyond any float (10**400)
        kind = "number" if allow_inf else "finite number"
        raise ValueError(f"{name}: expected a {kind}{_bounds(lo, hi, lo_open, hi_open)}, "
                         f"got an integer of {len(str(abs(value)))} digits") from None
    bad = np.isnan(v) or (np.isinf(v) and not allow_inf)
    if not bad and lo is not None:
        bad = v <= lo if lo_open else v < lo
    if not bad and hi is not None:
        bad = v >= hi if hi_open else v > hi
    if bad:
        kind = "number" if allow_inf else "finite number"
        raise ValueError(f"{name}: expected a {kind}{_bounds(lo, hi, lo_open, hi_open)}, "
                         f"got {value!r}")
    return v


def check_fill(value, name="fill"):
    """The value of the pixels that have none: a real number, NaN and inf included (they
    mark those pixels), or a bool (a map of flags); returned as it is. An array or text is
    a TypeError naming ``name``."""
    if not isinstance(value, (bool, np.bool_)) and _real(value) is None:
        raise TypeError(f"{name}: expected a number (NaN marks pixels without a value), got "
                        f"{value!r:.40}")
    return value


def check_int(value, name, *, lo=None, hi=None):
    """An integer (Python or NumPy; bool and floats rejected) within [lo, hi], as ``int``.

    Examples
    --------
    >>> check_int(3, "crop", lo=0)
    3
    >>> check_int(-1, "crop", lo=0)
    Traceback (most recent call last):
    ...
    ValueError: crop: expected an integer >= 0, got -1
    """
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Integral,)):
        raise TypeError(f"{name}: expected an integer, got {value!r}")
    v = int(value)
    if (lo is not None and v < lo) or (hi is not None and v > hi):
        raise ValueError(f"{name}: expected an integer{_bounds(lo, hi, False, False)}, "
                         f"got {value!r}")
    return v


def check_flag(value, name):
    """True or False (NumPy's bool too), as ``bool``; 0/1 and strings are rejected."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: expected True or False, got {value!r}")
    return bool(value)


def check_entries(value, name, key=None, strings=True):
    """A sequence of names (a tuple of strings, or one comma-separated string) as a tuple: at
    least one, each a string (unless ``strings`` is False: ``key`` checks them), none twice.
    ``key(entry)`` says when two spellings name the same thing (``"mask1"`` and
    ``"mask1_grbg"``): a repeated entry would be run and reported twice.

    Examples
    --------
    >>> check_entries("sg, bi", "methods")
    ('sg', 'bi')
    >>> check_entries(("sg", "sg"), "methods")
    Traceback (most recent call last):
    ...
    ValueError: methods: 'sg' is given twice; name each entry once
    """
    if isinstance(value, str):
        value = tuple(s.strip() for s in value.split(",") if s.strip())
    value = tuple(as_list(value, name, "a sequence of names or a comma-separated string"))
    if not value:
        raise ValueError(f"{name}: expected at least one entry, got none")
    seen = {}
    for v in value:
        if strings and not isinstance(v, str):
            raise TypeError(f"{name}: expected names (strings), got {v!r}")
        k = v if key is None else key(v)
        if k in seen:
            same = "" if seen[k] == v else f" (as {seen[k]!r})"
            raise ValueError(f"{name}: {v!r} is given twice{same}; name each entry once")
        seen[k] = v
    return value


def check_choice(value, choices, name):
    """One of ``choices`` (case-insensitive string), as the lower-case string."""
    if not isinstance(value, str) or value.lower() not in choices:
        raise ValueError(f"{name}: expected one of {', '.join(map(repr, choices))}, got {value!r}")
    return value.lower()


def check_dtype(dtype, allowed, name="dtype"):
    """``np.dtype(dtype)`` when it is one of ``allowed``, else TypeError naming ``name``.

    A string NumPy does not know (``"junk"``) gets the same message as a known
    dtype that is not allowed, instead of NumPy's "data type not understood".
    """
    allowed = tuple(np.dtype(d) for d in allowed)
    names = [str(d) for d in allowed]
    want = " or ".join(names) if len(names) == 2 else "one of " + ", ".join(names)
    try:
        dt = np.dtype(dtype)
    except TypeError:
        raise TypeError(f"{name}: expected {want}, got {dtype!r}") from None
    if dt not in allowed:
        raise TypeError(f"{name}: expected {want}, got {dt}")
    return dt


def check_bit_depth(bit_depth, name="bit_depth"):
    """Bits of a raw frame or an ADC: an integer in 1..16."""
    if isinstance(bit_depth, (bool, np.bool_)) or not isinstance(bit_depth, numbers.Integral):
        raise TypeError(f"{name}: expected an integer number of bits, got {bit_depth!r}")
    if not 1 <= int(bit_depth) <= 16:
        raise ValueError(f"{name}: expected 1..16 bits, got {bit_depth}")
    return int(bit_depth)


def check_seed(value, name="seed"):
    """A random seed: an integer >= 0 (bool rejected), as ``int``."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral) \
            or value < 0:
        raise ValueError(f"{name}: expected an integer >= 0, got {value!r}")
    return int(value)


def parse_shape(text, name="shape"):
    """A frame shape written ``ROWSxCOLS`` (``"1080x1920"``: 1080 rows of 1920 pixels).

    The one shape convention of the command line, as of every array in the
    library: rows first (the height), then columns (the width).

    Examples
    --------
    >>> parse_shape("1080x1920")
    (1080, 1920)
    >>> parse_shape("1920*1080")
    Traceback (most recent call last):
    ...
    ValueError: shape: expected ROWSxCOLS such as 1080x1920 (rows first), got '1920*1080'
    """
    parts = str(text).lower().replace(" ", "").split("x")
    if len(parts) != 2 or not all(p.isdigit() and int(p) > 0 for p in parts):
        raise ValueError(f"{name}: expected ROWSxCOLS such as 1080x1920 (rows first), "
                         f"got {text!r}")
    return int(parts[0]), int(parts[1])


def _in_range_fast(data, top):
    """True if a C-contiguous ``data`` lies within [0, top], by one contiguous reduction per
    bound (SIMD, no buffering; an unsigned type needs no lower one). NaN makes NumPy's min
    and max NaN and infinity is out of range, so True also says the data are finite. False
    for a non-contiguous array, which the per-phase views of :func:`_check_range` read
    instead."""
    if not (data.size and data.flags.c_contiguous):
        return False
    return bool((data.dtype.kind == "u" or data.min() >= 0) and data.max() <= top)


def _check_range(data, bit_depth, name, pattern=None):
    """Values of the colour sites within [0, 2**bit_depth - 1], without frame-sized temporaries.

    With a pattern, each non-Z phase of the tile is reduced on a strided view,
    so a 50-megapixel frame costs no extra memory.
    """
    top = (1 << bit_depth) - 1
    # one contiguous pass first; only a frame whose extremes are out of range -- perhaps
    # only at Z sites -- needs the per-phase views below
    if _in_range_fast(data, top):
        return
    if pattern is None:
        views = [data]
    else:
        P, Q = pattern.period
        views = [data[r::P, c::Q] for r in range(P) for c in range(Q)
                 if pattern.tile[r, c] != 3 and r < data.shape[0] and c < data.shape[1]]
    views = [v for v in views if v.size]
    if not views:
        return
    lo = min(v.min() for v in views)
    hi = max(v.max() for v in views)
    if lo < 0 or hi > top:
        raise ValueError(f"{name}: values span [{lo}, {hi}], beyond the {bit_depth}-bit "
                         f"range [0, {top}]")
