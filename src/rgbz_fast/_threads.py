"""Threads and processes: how many a call may start, and whether the machine can start them.

:func:`check_workers` (threads of one C kernel call) and :func:`check_processes`
(worker processes of a dataset run) are the checks of those counts; above the core
count :func:`thread_limit` says how many threads this machine can start, and
:func:`check_thread_stacks` whether OpenMP can give its threads the stacks
``OMP_STACKSIZE`` asks for: libgomp aborts the whole process when it cannot create a
thread, so both are checked before a kernel runs. :func:`kernel_threads` is how many
of them one call on a given number of pixels uses. Re-exported by
:mod:`rgbz_fast._validate`, the module of every argument check.
"""

from __future__ import annotations

import numbers
import os

import numpy as np

__all__ = ["check_workers", "check_processes", "check_thread_stacks", "thread_limit",
           "kernel_threads", "map_in_order", "MAX_WORKERS", "MIN_PIXELS_PER_THREAD"]


#: largest ``workers`` (threads of one kernel call); the result never depends on it.
#: OpenMP aborts the process (libgomp: "Thread creation failed") when it cannot start the
#: threads it is asked for, so a request above what this machine allows is refused before
#: any kernel runs (:func:`thread_limit`).
MAX_WORKERS = 1024

#: address space kept free for the buffers of the call itself when the thread limit is
#: derived from ``ulimit -v``
_THREAD_HEADROOM = 512 * 2**20

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


def map_in_order(fn, items, threads):
    """``[fn(item) for item in items]``, on up to ``threads`` Python threads (a checked count;
    for work that releases the GIL: C kernels, zlib): the same list, in the same order, on
    any count; one thread or one item runs on the calling thread.

    Examples
    --------
    >>> map_in_order(abs, [-2, 3, -5], 2)
    [2, 3, 5]
    """
    items = list(items)
    n = min(int(threads), len(items))
    if n <= 1:
        return [fn(item) for item in items]
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(n) as ex:
        return list(ex.map(fn, items))


def _check_count(value, name, unit, minus_one):
    """None (or -1 when ``minus_one``) -> every core; else 1..MAX_WORKERS, as ``int``."""
    integral = not isinstance(value, (bool, np.bool_)) and isinstance(value, numbers.Integral)
    if value is None or (minus_one and integral and value == -1):
        return os.cpu_count() or 1
    if not integral or value < 1:
        accepted = "None, -1" if minus_one else "None"
        # a wrong type (text, a float, a bool) is a TypeError, as check_int's
        raise (ValueError if integral else TypeError)(
            f"{name}: expected {accepted} or a positive number of {unit}, got {value!r}")
    if value > MAX_WORKERS:
        raise ValueError(f"{name}: expected at most {MAX_WORKERS} {unit}, got {value!r}")
    if value > 1 and value > (os.cpu_count() or 1):    # the usual counts never pay for the probe
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
    of a dataset evaluation are ``processes`` (:func:`check_processes`). More
    than one thread also needs the thread stacks OpenMP will ask for
    (:func:`check_thread_stacks`).
    """
    count = _check_count(workers, name, "threads", minus_one=True)
    check_thread_stacks(count, name)
    return count


def _libgomp_stacksize(env):
    """``(variable, text, bytes)`` of the thread stack libgomp takes from ``env`` (a
    mapping), parsed as libgomp's env.c does -- digits, optional blanks, an optional B, K, M
    or G (default K) -- ``OMP_STACKSIZE`` first, then ``GOMP_STACKSIZE``; None when neither
    holds a valid size (libgomp then keeps the pthread default, with a warning)."""
    for var in ("OMP_STACKSIZE", "GOMP_STACKSIZE"):
        text = env.get(var)
        if text is None:
            continue
        t = text.strip()
        digits = len(t) - len(t.lstrip("0123456789"))
        if not digits:
            continue
        rest = t[digits:].strip().upper()
        shift = {"": 10, "B": 0, "K": 10, "M": 20, "G": 30}.get(rest)
        if shift is None:
            continue
        size = int(t[:digits]) << shift
        if size >= 1 << 64:                       # libgomp: overflow, an invalid value
            continue
        if size < _thread_stack_min():
            # libgomp: pthread_attr_setstacksize refuses it, libgomp warns "Stack size less
            # than minimum" and keeps the default stack (OMP_STACKSIZE=0 was refused here
            # with the advice to set a smaller size)
            return None
        return var, text, size
    return None


def _thread_stack_min():
    """The smallest thread stack pthreads accepts (PTHREAD_STACK_MIN), 16 KiB if unknown."""
    try:
        return max(int(os.sysconf("SC_THREAD_STACK_MIN")), 1)
    except (ValueError, OSError, AttributeError):
        return 16384


#: the thread stack libgomp uses, from the environment as the library was loaded (libgomp
#: reads it once, when it loads with the kernels)
_OMP_STACK = _libgomp_stacksize(os.environ)
#: (stack bytes, extra threads) -> None, or why such threads cannot be started
_STACK_PROBES: dict = {}


def check_thread_stacks(threads, name="workers"):
    """A ValueError naming ``OMP_STACKSIZE`` when ``threads`` OpenMP threads cannot get the
    stacks it asks for.

    libgomp gives every thread it starts the stack of ``OMP_STACKSIZE`` (or
    ``GOMP_STACKSIZE``), and aborts the whole process ("Thread creation failed") when the
    system refuses one: ``OMP_STACKSIZE=32G`` killed the interpreter inside
    ``reconstruct(workers=2)``. Before the first parallel region of a call, the
    ``threads - 1`` stacks it would start are mapped the way pthreads maps a stack (private
    anonymous memory, all at once) and released; a refusal is the error instead of the
    abort. The outcome is kept per (size, count). Nothing to check for one thread or for
    libgomp's default stack.
    """
    if _OMP_STACK is None or threads <= 1:
        return
    var, text, size = _OMP_STACK
    key = (size, threads - 1)
    if key not in _STACK_PROBES:
        _STACK_PROBES[key] = _probe_stacks(size, threads - 1)
    why = _STACK_PROBES[key]
    if why is not None:
        raise ValueError(f"{var}: {text.strip()!r} asks for a stack of {size / 2**30:g} GiB "
                         f"for each of the {threads - 1} thread(s) OpenMP starts for {name}="
                         f"{threads}, which this system refuses ({why}); set {var} to a "
                         f"smaller size such as 8M, or unset it, or pass {name}=1")


def _probe_stacks(size, count):
    """None when ``count`` stacks of ``size`` bytes can be mapped at once, else why not."""
    import mmap

    maps = []
    try:
        for _ in range(count):
            maps.append(mmap.mmap(-1, size, flags=mmap.MAP_PRIVATE))
    except (OSError, OverflowError, ValueError) as exc:
        return getattr(exc, "strerror", None) or str(exc)
    finally:
        for m in maps:
            m.close()
    return None


def check_processes(processes, name="processes"):
    """Worker processes of a dataset run: None -> every core; else a positive integer."""
    return _check_count(processes, name, "processes", minus_one=False)
