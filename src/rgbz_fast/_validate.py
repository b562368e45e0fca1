"""Argument checks shared by every public function (Python validates, C computes).

Every check raises ``TypeError`` (wrong kind of value) or ``ValueError`` (a
value out of range) whose message starts with the name of the parameter, says
what it got and what it expects. There is one check per kind of value:
:func:`check_number` for every real parameter (bounds open or closed, None or
infinity allowed on request), :func:`check_int` for every integer one,
:func:`check_flag`, :func:`check_choice`, :func:`check_dtype`,
:func:`check_bit_depth`, :func:`check_seed`, :func:`check_workers` (threads of
a C kernel) and :func:`check_processes` (worker processes), and
:func:`check_image` for arrays.
"""

from __future__ import annotations

import numbers
import os

import numpy as np

__all__ = ["check_image", "check_finite", "check_number", "check_int", "check_flag",
           "check_choice", "check_dtype", "check_bit_depth", "check_seed", "check_workers",
           "check_processes", "FRAME_DTYPES", "MAX_WORKERS"]

#: largest ``workers`` (threads of one kernel call); the result never depends on it.
#: OpenMP aborts the process (libgomp) when it cannot start the threads it is asked for.
MAX_WORKERS = 1024

#: dtypes a raw frame may hold; kernels read and write them directly.
FRAME_DTYPES = (np.dtype(np.uint8), np.dtype(np.uint16), np.dtype(np.float32),
                np.dtype(np.float64))


def check_image(arr, name, ndim=None, dtypes=None):
    """Return ``np.asarray(arr)`` after checking ndim, dtype kind, size and finiteness."""
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
    """ValueError naming ``name`` if a float array holds NaN or infinity."""
    if np.issubdtype(a.dtype, np.floating) and not np.all(np.isfinite(a)):
        bad = int(np.size(a) - np.count_nonzero(np.isfinite(a)))
        raise ValueError(f"{name}: holds {bad} NaN or infinite value(s); expected finite data")


#: pixels (or other work units) per thread below which a kernel call takes fewer threads:
#: a call on fewer pixels lasts well under a millisecond on one core, while each extra thread
#: costs a wake-up and a barrier (tens of microseconds on an idle machine, up to a scheduler
#: time slice, ~20 ms measured, when other processes hold the cores: docs/benchmarks.md)
MIN_PIXELS_PER_THREAD = 1 << 18


def kernel_threads(threads, pixels, min_pixels=MIN_PIXELS_PER_THREAD):
    """Threads for one kernel call on ``pixels``: at most ``threads`` (a checked count),
    one per ``min_pixels``, at least 1. Results never depend on the thread count.

    Examples
    --------
    >>> kernel_threads(8, 256 * 192), kernel_threads(8, 1008 * 756), kernel_threads(2, 4000 * 3000)
    (1, 2, 2)
    """
    return max(1, min(int(threads), int(pixels) // int(min_pixels)))


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
    parts = []
    if lo is not None:
        parts.append(f"{'>' if lo_open else '>='} {lo:g}")
    if hi is not None:
        parts.append(f"{'<' if hi_open else '<='} {hi:g}")
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
    v = float(v)
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


def check_workers(workers, name="workers"):
    """Threads of one C kernel call: None or -1 -> every core; else 1..MAX_WORKERS.

    ``workers`` means threads everywhere in the library; the worker *processes*
    of a dataset evaluation are ``processes`` (:func:`check_processes`).
    """
    if workers is None or (not isinstance(workers, (bool, np.bool_))
                           and isinstance(workers, numbers.Integral) and workers == -1):
        return os.cpu_count() or 1
    if isinstance(workers, (bool, np.bool_)) or not isinstance(workers, numbers.Integral) \
            or workers < 1:
        raise ValueError(f"{name}: expected None, -1 or a positive number of threads, "
                         f"got {workers!r}")
    if workers > MAX_WORKERS:
        raise ValueError(f"{name}: expected at most {MAX_WORKERS} threads, got {workers!r}")
    return int(workers)


def check_processes(processes, name="processes"):
    """Worker processes of a dataset run: None -> every core; else a positive integer."""
    if processes is None:
        return os.cpu_count() or 1
    if isinstance(processes, (bool, np.bool_)) or not isinstance(processes, numbers.Integral) \
            or processes < 1:
        raise ValueError(f"{name}: expected None or a positive number of processes, "
                         f"got {processes!r}")
    if processes > MAX_WORKERS:
        raise ValueError(f"{name}: expected at most {MAX_WORKERS} processes, got {processes!r}")
    return int(processes)
