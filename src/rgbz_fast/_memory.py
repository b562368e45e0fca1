"""Large arrays on pages the process keeps: the pool of csrc/pool.h.

A call that writes a few hundred MB of results into fresh arrays pays the system for every
page it touches first (a page fault and a zeroed page), and glibc gives arrays that large
back to the system when they are freed, so a loop of calls pays it on every call: about
a tenth of the colour-guided ToF ISP's call on a 12 MP frame
(docs/reports/benchmarks.md). :func:`empty` takes such arrays from a pool that keeps the
memory of the ones freed, up to :func:`memory_pool`'s limit, and hands it to the next
request of the same size with its pages still mapped. Kept memory is marked ``MADV_FREE``
on Linux: under memory pressure the system takes those pages back (they fault again when
used), so what the pool keeps never stands between the system and memory it needs.

The values in an array from :func:`empty` are undefined, as ``numpy.empty``'s; the array is
an ordinary writable, C-contiguous ndarray whose ``base`` chain ends in the pool's block.
"""

from __future__ import annotations

import math
import numbers
import operator

import numpy as np

from . import _kernels

__all__ = ["empty", "empty_like", "memory_pool", "POOL_MIN_BYTES", "DEFAULT_LIMIT"]

#: arrays smaller than this come from ``numpy.empty``: glibc's heap recycles them well enough,
#: and the pool's ``MADV_FREE`` on every block given back cost a Kodak-size guided call 2-5 %
#: when its 2.4 MB arrays went through the pool (docs/reports/benchmarks.md)
POOL_MIN_BYTES = 4 << 20


#: bytes the pool keeps at most by default
DEFAULT_LIMIT = 1 << 30


def _default_limit():
    """:data:`DEFAULT_LIMIT`, or an eighth of the process's address-space limit (``ulimit -v``)
    when that is smaller: kept memory counts against it, and a NumPy array made elsewhere
    would not find the room the pool holds."""
    try:
        import resource
        soft = resource.getrlimit(resource.RLIMIT_AS)[0]
    except (ImportError, OSError, ValueError, AttributeError):
        return DEFAULT_LIMIT
    if soft == resource.RLIM_INFINITY or soft < 0:
        return DEFAULT_LIMIT
    return min(DEFAULT_LIMIT, soft // 8)


_kernels.pool_set_limit(_default_limit())


def empty(shape, dtype=np.float64):
    """``numpy.empty(shape, dtype)`` (C order), from the pool when it is at least
    :data:`POOL_MIN_BYTES` (4 MiB) and the pool's limit is not 0."""
    dtype = np.dtype(dtype)
    shape = tuple(map(operator.index, shape)) if np.iterable(shape) else \
        (operator.index(shape),)
    count = math.prod(shape)
    nbytes = count * dtype.itemsize
    if nbytes < POOL_MIN_BYTES or dtype.hasobject or _kernels.pool_stats()[0] == 0:
        return np.empty(shape, dtype)
    try:
        block = _kernels.PoolBlock(nbytes)
    except MemoryError:
        # no address space or memory for a new block (ulimit -v, a full machine): the kept
        # blocks go back to the system first, then NumPy allocates (and raises its own
        # error, which names the array's size, when that fails too)
        _kernels.pool_set_limit(_kernels.pool_set_limit(0))
        return np.empty(shape, dtype)
    return np.frombuffer(block, dtype, count).reshape(shape)


def empty_like(a):
    """:func:`empty` of the shape and dtype of the array ``a`` (C order)."""
    return empty(a.shape, a.dtype)


def memory_pool(limit=None):
    """The pool that keeps the memory of freed large result arrays for the next call.

    The colour-guided ToF ISP (``ToFISP().run(tof, guide=...)``),
    :func:`rgbz_fast.tof.upsample_depth` and the colour ISP's fused path
    (``ColourISP().run(frame)`` without ``return_stages``: its image and its defect-corrected
    CFA) take their arrays of 4 MiB or more from this pool. When such an array is freed, its memory is kept (up to ``limit`` bytes, the
    oldest given back first) and the next array of the same size takes it with its pages
    still mapped: a loop of calls on frames of one size then writes no fresh pages. On
    Linux the kept memory is marked ``MADV_FREE``: the system takes it back when it needs
    it, so the pool never holds memory the system is short of (it still counts in the
    process's resident size until then).

    Parameters
    ----------
    limit : int, optional
        Bytes to keep at most (default 1 GiB, or an eighth of the process's address-space
        limit, ``ulimit -v``, when that is smaller). ``0`` turns the pool off: the kept
        memory goes back to the system now, and new arrays come from ``numpy.empty``.
        When a new block does not fit in memory or the address space, the kept ones go
        back to the system and NumPy makes the array.

    Returns
    -------
    dict
        ``limit``, ``kept_bytes`` and ``kept_blocks`` (memory kept now), ``reused`` and
        ``mapped`` (blocks handed out from kept memory, and newly mapped, since the process
        started), after the limit is set.

    Examples
    --------
    >>> import rgbz_fast
    >>> before = rgbz_fast.memory_pool()["limit"]
    >>> rgbz_fast.memory_pool(0)["kept_bytes"]
    0
    >>> rgbz_fast.memory_pool(before)["limit"] == before
    True
    """
    if limit is not None:
        if isinstance(limit, bool) or not isinstance(limit, numbers.Integral):
            raise TypeError(f"limit: expected an int number of bytes (or None), got "
                            f"{type(limit).__name__}")
        if not 0 <= limit < 2**63:
            raise ValueError(f"limit: expected 0 <= limit < 2**63 bytes, got {limit}")
        _kernels.pool_set_limit(int(limit))
    lim, blocks, kept, reused, mapped = _kernels.pool_stats()
    return {"limit": int(lim), "kept_bytes": int(kept), "kept_blocks": int(blocks),
            "reused": int(reused), "mapped": int(mapped)}
