"""Build and runtime configuration report."""

from __future__ import annotations

import os
import platform
import sys

from . import _build_config as bc
from . import _kernels
from ._memory import memory_pool

__all__ = ["show_config", "config"]

#: how long OpenMP's idle threads spin after a call: the environment as the kernels loaded
#: (libgomp reads it once, when it loads, as the import above did)
_OMP_IDLE = {k: os.environ.get(k) for k in ("GOMP_SPINCOUNT", "OMP_WAIT_POLICY")}


def config():
    """dict: version, compiler, flags, OpenMP and thread counts of the compiled kernels.

    ``default_workers`` is the number of threads a call with ``workers=None`` runs (every
    core); ``max_threads`` is OpenMP's own default (``omp_get_max_threads()``, which
    ``OMP_NUM_THREADS`` sets), which the kernels do not use: every call passes its count.
    ``memory_pool`` is :func:`rgbz_fast.memory_pool`'s report: the memory of freed large
    result arrays kept for the next call, and its limit. ``omp_idle``: the environment's
    ``GOMP_SPINCOUNT`` and ``OMP_WAIT_POLICY`` as the kernels loaded (None where unset), which
    decide how long the kernels' idle threads spin after a call (the ``rgbz-fast`` command sets
    ``GOMP_SPINCOUNT=30000`` when neither is set; docs/guide/performance.md)."""
    return {
        "version": bc.VERSION,
        "python": sys.version.split()[0],
        "platform": platform.platform(),
        "compiler": f"{bc.CC_ID} {bc.CC_VERSION}",
        "buildtype": bc.BUILDTYPE,
        "optimization": f"-O{bc.OPTIMIZATION}",
        "kernel_c_args": bc.KERNEL_C_ARGS,
        "openmp": bool(_kernels.have_openmp()),
        "openmp_version": bc.OPENMP_VERSION or None,
        "max_threads": int(_kernels.max_threads()),
        "default_workers": os.cpu_count() or 1,        # what workers=None runs (unchecked:
                                                       # config reports, it does not refuse)
        "cpu_count": os.cpu_count(),
        "memory_pool": memory_pool(),
        # the rgbz-fast command sets GOMP_SPINCOUNT=30000 when neither is set
        "omp_idle": dict(_OMP_IDLE),
    }


def show_config(file=None):
    """Print how the C kernels were built: version, compiler flags, OpenMP on/off, threads.

    Parameters
    ----------
    file : text stream, optional
        Where to print: anything with a ``write()`` method (default: ``sys.stdout``).

    Examples
    --------
    >>> import rgbz_fast
    >>> rgbz_fast.show_config()  # doctest: +SKIP
    rgbz-fast 0.1.0
    ...
    """
    if file is not None and not callable(getattr(file, "write", None)):
        raise TypeError(f"file: expected a text stream with a write() method (or None for "
                        f"stdout), got {type(file).__name__}")
    c = config()
    lines = [
        f"rgbz-fast {c['version']}",
        f"  python        : {c['python']} ({c['platform']})",
        f"  compiler      : {c['compiler']}",
        f"  build         : {c['buildtype']} ({c['optimization']})",
        f"  kernel flags  : {c['kernel_c_args'] or '(none)'}",
        f"  OpenMP        : {'on' if c['openmp'] else 'off'}"
        + (f" (version {c['openmp_version']})" if c['openmp'] and c['openmp_version'] else ""),
        f"  threads       : {c['default_workers']} per call by default (workers=None: every "
        f"core; cores: {c['cpu_count']})",
        f"  memory pool   : keeps up to {c['memory_pool']['limit'] / 2**20:.0f} MiB of freed "
        f"result arrays ({c['memory_pool']['kept_bytes'] / 2**20:.0f} MiB kept now; "
        "rgbz_fast.memory_pool)",
    ]
    if c["openmp"]:
        idle = ", ".join(f"{k}={v}" for k, v in c["omp_idle"].items() if v is not None)
        lines.append("  idle threads  : " + (
            idle + " (from the environment when the kernels loaded)" if idle else
            "libgomp's default spin after each call (300000 rounds, about 3 ms, a core taken "
            "from the next threaded call of another library; GOMP_SPINCOUNT=30000 in the "
            "environment before the import shortens it, as the rgbz-fast command does)"))
    omp = os.environ.get("OMP_NUM_THREADS")
    if omp is not None and c["openmp"]:
        lines.append(f"  OMP_NUM_THREADS={omp} is not used: pass workers= (or --workers) to "
                     "limit a call's threads")
    print("\n".join(lines), file=sys.stdout if file is None else file)
