"""Argument checks shared by every public function (Python validates, C computes).

Every check raises ``TypeError`` (wrong kind of value) or ``ValueError`` (a
value out of range) whose message starts with the name of the parameter, says
what it got and what it expects. There is one check per kind of value:
:func:`check_number` for every real parameter (bounds open or closed, None or
infinity allowed on request), :func:`check_int` for every integer one,
:func:`check_flag`, :func:`check_choice`, :func:`check_dtype`,
:func:`check_bit_depth`, :func:`check_seed`, :func:`check_workers` (threads of
a C kernel) and :func:`check_processes` (worker processes), and
:func:`check_image` for arrays. :func:`merge_params` is the one rule of every stage
that takes parameters: a frozen dataclass (``params=``) plus keyword overrides of its
fields, checked once by the dataclass.
"""

from __future__ import annotations

import dataclasses
import numbers
import os
from collections.abc import Mapping

import numpy as np

__all__ = ["check_image", "check_finite", "check_number", "check_int", "check_flag",
           "check_choice", "check_dtype", "check_bit_depth", "check_seed", "check_workers",
           "check_processes", "thread_limit", "parse_shape", "merge_params", "FRAME_DTYPES",
           "MAX_WORKERS"]

#: largest ``workers`` (threads of one kernel call); the result never depends on it.
#: OpenMP aborts the process (libgomp: "Thread creation failed") when it cannot start the
#: threads it is asked for, so a request above what this machine allows is refused before
#: any kernel runs (:func:`thread_limit`).
MAX_WORKERS = 1024

#: address space kept free for the buffers of the call itself when the thread limit is
#: derived from ``ulimit -v``
_THREAD_HEADROOM = 512 * 2**20

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


def check_finite(a, name):
    """ValueError naming ``name`` if a float array holds NaN or infinity."""
    if np.issubdtype(a.dtype, np.floating) and not np.all(np.isfinite(a)):
        bad = int(np.size(a) - np.count_nonzero(np.isfinite(a)))
        raise ValueError(f"{name}: holds {bad} NaN or infinite value(s); expected finite data")


#: pixels (or other work units) per thread below which a kernel call takes fewer threads:
#: a call on fewer pixels lasts well under a millisecond on one core, while each extra thread
#: costs a wake-up and a barrier (tens of microseconds on an idle machine, up to a scheduler
#: time slice, ~20 ms measured, when other processes hold the cores: docs/reports/benchmarks.md)
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


def _check_count(value, name, unit, minus_one):
    """None (or -1 when ``minus_one``) -> every core; else 1..MAX_WORKERS, as ``int``."""
    integral = not isinstance(value, (bool, np.bool_)) and isinstance(value, numbers.Integral)
    if value is None or (minus_one and integral and value == -1):
        return os.cpu_count() or 1
    if not integral or value < 1:
        accepted = "None, -1" if minus_one else "None"
        raise ValueError(f"{name}: expected {accepted} or a positive number of {unit}, "
                         f"got {value!r}")
    if value > MAX_WORKERS:
        raise ValueError(f"{name}: expected at most {MAX_WORKERS} {unit}, got {value!r}")
    if value > (os.cpu_count() or 1):            # the usual counts never pay for the probe
        limit, reason = thread_limit()
        if value > limit:
            raise ValueError(f"{name}: {value} {unit} cannot be started here ({reason}); "
                             f"pass at most {limit}")
    return int(value)


def _stack_bytes():
    """The stack of each OpenMP thread: OMP_STACKSIZE / GOMP_STACKSIZE, else the pthread
    default, which glibc takes from ``ulimit -s``; when that is unlimited glibc uses its
    architecture default (2 MiB on x86-64, measured; more elsewhere), taken as 8 MiB."""
    import resource

    for var in ("OMP_STACKSIZE", "GOMP_STACKSIZE"):
        text = os.environ.get(var, "").strip().upper()
        if text:
            unit = {"B": 1, "K": 2**10, "M": 2**20, "G": 2**30}.get(text[-1])
            try:
                return int(text[:-1] if unit else text) * (unit or 2**10)   # bare: KiB
            except ValueError:
                break
    soft = resource.getrlimit(resource.RLIMIT_STACK)[0]
    return 8 * 2**20 if soft == resource.RLIM_INFINITY else max(int(soft), 2**16)


def _proc_fields(path, keys):
    out = {}
    try:
        with open(path) as fh:
            for line in fh:
                k, _, v = line.partition(":")
                if k in keys:
                    out[k] = v.split()
    except OSError:
        pass
    return out


def _user_threads(uid):
    """Threads of every process of ``uid`` (what RLIMIT_NPROC counts), from /proc."""
    n = 0
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            f = _proc_fields(f"/proc/{entry.name}/status", ("Uid", "Threads"))
            if f.get("Uid", [None])[0] == str(uid) and f.get("Threads"):
                n += int(f["Threads"][0])
    return n


def thread_limit():
    """How many threads one kernel call can start on this machine: ``(limit, reason)``.

    libgomp aborts the process when a thread cannot be created. On Linux that
    happens when the address space (``ulimit -v``) has no room for another
    thread stack (``ulimit -s`` or ``OMP_STACKSIZE``; measured: 450 threads
    of 8 MiB under ``ulimit -v 4000000`` started, 512 aborted), when the
    user's processes and threads reach ``ulimit -u`` (not for root), when the
    cgroup's ``pids.max`` is reached, or at the kernel's ``threads-max``. The
    limit is the smallest of these, with headroom, and at most
    :data:`MAX_WORKERS`; ``reason`` names the one that binds.
    """
    found = [(MAX_WORKERS, f"at most {MAX_WORKERS} threads")]
    try:
        import resource
    except ImportError:  # pragma: no cover - not POSIX
        return found[0]
    soft = resource.getrlimit(resource.RLIMIT_AS)[0]
    if soft != resource.RLIM_INFINITY:
        vm = _proc_fields("/proc/self/status", ("VmSize",)).get("VmSize")
        used = int(vm[0]) * 1024 if vm else 0
        stack = _stack_bytes()
        n = max((int(soft) - used - _THREAD_HEADROOM) // (stack + 2**16), 1)
        found.append((n, f"the address-space limit, ulimit -v {int(soft) // 1024} kB, leaves "
                         f"room for {n} thread stacks of {stack / 2**20:g} MiB"))
    if hasattr(resource, "RLIMIT_NPROC") and os.geteuid() != 0:
        nproc = resource.getrlimit(resource.RLIMIT_NPROC)[0]
        if nproc != resource.RLIM_INFINITY and os.path.isdir("/proc"):
            n = max(int(nproc) - _user_threads(os.geteuid()) - 16, 1)
            found.append((n, f"ulimit -u {nproc} processes and threads for this user"))
    for line in _proc_lines("/proc/self/cgroup"):
        parts = line.split(":", 2)
        if len(parts) == 3 and parts[0] == "0":                    # cgroup v2
            d = f"/sys/fs/cgroup{parts[2].strip()}"
            cap, cur = _first(f"{d}/pids.max"), _first(f"{d}/pids.current")
            if cap and cap.isdigit() and cur and cur.isdigit():
                n = max(int(cap) - int(cur) - 8, 1)
                found.append((n, f"the control group allows {cap} tasks, {cur} in use"))
    cap, load = _first("/proc/sys/kernel/threads-max"), _first("/proc/loadavg", 3)
    if cap and cap.isdigit() and load and "/" in load:
        n = max(int(cap) - int(load.split("/")[1]) - 64, 1)
        found.append((n, f"the kernel's threads-max {cap}"))
    return min(found, key=lambda t: t[0])


def _proc_lines(path):
    try:
        with open(path) as fh:
            return fh.read().splitlines()
    except OSError:
        return []


def _first(path, field=0):
    lines = _proc_lines(path)
    parts = lines[0].split() if lines else []
    return parts[field] if len(parts) > field else None


def check_workers(workers, name="workers"):
    """Threads of one C kernel call: None or -1 -> every core; else 1..MAX_WORKERS.

    ``workers`` means threads everywhere in the library; the worker *processes*
    of a dataset evaluation are ``processes`` (:func:`check_processes`).
    """
    return _check_count(workers, name, "threads", minus_one=True)


def check_processes(processes, name="processes"):
    """Worker processes of a dataset run: None -> every core; else a positive integer."""
    return _check_count(processes, name, "processes", minus_one=False)


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
