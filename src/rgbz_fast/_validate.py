"""Argument checks shared by the public functions (Python validates, C computes)."""

from __future__ import annotations

import os

import numpy as np

__all__ = ["supported_float_type", "check_image", "check_bit_depth", "check_workers",
           "check_choice", "check_finite", "check_number", "FRAME_DTYPES"]

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
