"""The one timing loop and the one summary of its times, for every speed the tools report.

:func:`interleaved` times several functions in turn, one call each per round,
after untimed warm-up calls: a change of the machine's load during the run
(other jobs on a shared machine) then slows all of them alike, so their ratio
stays fair. :func:`rate_stats` turns the times of one function into the
median, the interquartile range and the best rate. Not a public API.
"""

from __future__ import annotations

import time

import numpy as np

__all__ = ["WARMUP_CALLS", "interleaved", "timed", "rate_stats", "ratio"]

#: untimed calls of each function before the timed ones (the OpenMP thread team, caches,
#: lazily built plans)
WARMUP_CALLS = 1


def interleaved(fns, repeat, *, warmup=WARMUP_CALLS, rounds=None):
    """Seconds of each function of ``fns`` (name -> callable), ``repeat`` calls each.

    Every function is called ``warmup`` times untimed, then each round calls
    every function once, in order. ``rounds``: wraps the iterable of the
    rounds (a progress bar). Returns ``{name: ndarray of repeat seconds}``.
    """
    for fn in fns.values():
        for _ in range(warmup):
            fn()
    times = {k: [] for k in fns}
    steps = range(repeat) if rounds is None else rounds(range(repeat))
    for _ in steps:
        for k, fn in fns.items():
            t0 = time.perf_counter()
            fn()
            times[k].append(time.perf_counter() - t0)
    return {k: np.asarray(v) for k, v in times.items()}


def timed(fn, repeat, *, warmup=WARMUP_CALLS):
    """Seconds of ``repeat`` calls of ``fn`` (after ``warmup`` untimed ones), an ndarray."""
    return interleaved({"fn": fn}, repeat, warmup=warmup)["fn"]


def rate_stats(times, count, unit="mpix"):
    """The times of one function (s) and its rate in million ``count`` per second.

    ``count``: what one call processes (pixels, measurements). Returns
    ``median_s``, ``q1_s``, ``q3_s``, ``min_s``, ``max_s``, ``n`` and, with
    ``unit`` "mpix" (or "msites"), ``mpix_s`` (the median's rate),
    ``mpix_s_lo``/``mpix_s_hi`` (the rates of the third and first quartiles)
    and ``mpix_s_best`` (the fastest call's).
    """
    times = np.asarray(times, np.float64)
    q1, med, q3 = np.percentile(times, [25, 50, 75])
    m = count / 1e6
    return {"median_s": float(med), "q1_s": float(q1), "q3_s": float(q3),
            "min_s": float(times.min()), "max_s": float(times.max()), "n": int(times.size),
            f"{unit}_s": m / med, f"{unit}_s_lo": m / q3, f"{unit}_s_hi": m / q1,
            f"{unit}_s_best": m / times.min()}


def ratio(a, b):
    """a / b, or None when either is missing or b is 0."""
    if a is None or b is None or not b:
        return None
    return a / b
