"""Argument checks shared by the public functions (Python validates, C computes).

Also the one reader of image files (:func:`read_image_file`), which turns a
file that does not decode into such an error, naming the parameter and the path.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

__all__ = ["supported_float_type", "check_image", "check_bit_depth", "check_workers",
           "check_choice", "check_finite", "check_number", "check_dtype", "check_seed",
           "check_flag", "read_image_file", "FRAME_DTYPES"]

#: largest ``workers`` (threads of one kernel call); the result never depends on it
MAX_WORKERS = 1024

#: dtypes a raw frame may hold; kernels read and write them directly.
FRAME_DTYPES = (np.dtype(np.uint8), np.dtype(np.uint16), np.dtype(np.float32),
                np.dtype(np.float64))


def supported_float_type(dtype):
    """float16 -> float32, float32/float64 kept, every integer -> float64 (skimage's rule)."""
    dtype = np.dtype(dtype)
    if dtype == np.float16:
        return np.dtype(np.float32)
    if dtype in (np.float32, np.float64):
        return dtype
    if np.issubdtype(dtype, np.integer) or dtype == np.bool_:
        return np.dtype(np.float64)
    raise TypeError(f"dtype {dtype} is not supported (complex and object arrays are rejected)")


def check_image(arr, name, ndim=None, dtypes=None):
    """Return ``np.asarray(arr)`` after checking ndim, dtype kind and finiteness."""
    if arr is None:
        raise TypeError(f"{name}: expected an array, got None")
    a = np.asarray(arr)
    if a.dtype == object or np.issubdtype(a.dtype, np.complexfloating):
        raise TypeError(f"{name}: expected a real numeric array, got dtype {a.dtype}")
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
    check_finite(a, name)
    return a


def check_finite(a, name):
    if np.issubdtype(a.dtype, np.floating) and not np.all(np.isfinite(a)):
        bad = int(np.size(a) - np.count_nonzero(np.isfinite(a)))
        raise ValueError(f"{name}: holds {bad} NaN or infinite value(s); expected finite data")


def check_bit_depth(bit_depth, name="bit_depth"):
    if isinstance(bit_depth, bool) or not isinstance(bit_depth, (int, np.integer)):
        raise TypeError(f"{name}: expected an integer number of bits, got {bit_depth!r}")
    if not 1 <= int(bit_depth) <= 16:
        raise ValueError(f"{name}: expected 1..16 bits, got {bit_depth}")
    return int(bit_depth)


def check_workers(workers, name="workers"):
    """None or -1 -> all cores; a positive integer otherwise."""
    if workers is None or (not isinstance(workers, bool) and workers == -1):
        return os.cpu_count() or 1
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise ValueError(f"{name}: expected None, -1 or a positive integer, got {workers!r}")
    if workers > MAX_WORKERS:      # OpenMP aborts or crashes when it cannot start the threads
        raise ValueError(f"{name}: expected at most {MAX_WORKERS} threads, got {workers!r}")
    return int(workers)


def check_choice(value, choices, name):
    if not isinstance(value, str) or value.lower() not in choices:
        raise ValueError(f"{name}: expected one of {', '.join(map(repr, choices))}, got {value!r}")
    return value.lower()


def check_number(value, name, *, lo=None, lo_open=False, hi=None, allow_none=False):
    """A finite real number within the bounds, as float (None passes when ``allow_none``)."""
    if value is None and allow_none:
        return None
    if isinstance(value, bool):
        raise TypeError(f"{name}: expected a number, got {value!r}")
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a number, got {value!r}") from None
    if not np.isfinite(v) or (lo is not None and (v <= lo if lo_open else v < lo)) or (
            hi is not None and v > hi):
        rng = []
        if lo is not None:
            rng.append(f"{'>' if lo_open else '>='} {lo:g}")
        if hi is not None:
            rng.append(f"<= {hi:g}")
        bound = (" " + " and ".join(rng)) if rng else ""
        raise ValueError(f"{name}: expected a finite number{bound}, got {value!r}")
    return v


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


def check_seed(value, name="seed"):
    """A random seed: an integer >= 0 (bool rejected), as int."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
        raise ValueError(f"{name}: expected an integer >= 0, got {value!r}")
    return int(value)


def check_flag(value, name):
    """True or False (NumPy's bool too), as bool; 0/1 and strings are rejected."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: expected True or False, got {value!r}")
    return bool(value)


def read_image_file(path, name="path", decode=None):
    """Decode an image file (PNG, TIFF, ...) read into memory first, as an ndarray.

    Parameters
    ----------
    path : str or os.PathLike
        The file; a missing file raises ``FileNotFoundError`` (callers check
        existence first when they promise another error).
    name : str
        The parameter named in the error message.
    decode : callable, optional
        ``decode(data: bytes) -> array_like``; default imageio's ``imread``
        with the file's extension as the format hint.

    Raises
    ------
    ValueError
        ``"{name}: cannot read {path} as an image (...)"`` when the bytes do
        not decode, or decode to no pixel.

    Notes
    -----
    imageio leaks the file handles it opens when a file fails to decode
    (``ResourceWarning``) and raises ``OSError``, ``ValueError`` and other
    types depending on the plugin; decoding bytes leaves nothing to leak and
    gives one exception type. The reason is kept on one line (the command
    line prints one line per error).
    """
    p = Path(path)
    data = p.read_bytes()
    try:
        if decode is None:
            import imageio.v3 as iio

            img = iio.imread(data, extension=p.suffix.lower() or None)
        else:
            img = decode(data)
        img = np.asarray(img)
    except Exception as exc:  # noqa: BLE001 - the decoders raise many types for bad data
        reason = " ".join(str(exc).split()) or type(exc).__name__
        raise ValueError(f"{name}: cannot read {p} as an image ({reason})") from None
    if img.size == 0:
        raise ValueError(f"{name}: cannot read {p} as an image (it decodes to no pixel, "
                         f"shape {img.shape})")
    return img
