"""What the measuring engines share: the facts of the machine, the benchmark frame, JSON of
results, a progress bar. Not a public API."""

from __future__ import annotations

import json
import os
import platform
import sys
from pathlib import Path

import numpy as np

from .._validate import nonfinite_as

__all__ = ["machine_info", "tile_to", "json_text", "progress"]


def machine_info():
    """Cores, CPU model, OS, Python/NumPy versions and the build of the kernels."""
    model = platform.processor() or ""
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            for line in fh:
                if line.lower().startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    info = {
        "cpu_model": model or "unknown",
        "logical_cores": os.cpu_count(),
        "usable_cores": len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity")
        else os.cpu_count(),
        "platform": platform.platform(),
        "python": platform.python_version(),
        "numpy": np.__version__,
    }
    try:
        from .. import _build_config, _kernels
        info.update(rgbz_fast=_build_config.VERSION, openmp=bool(_kernels.have_openmp()),
                    omp_max_threads=int(_kernels.max_threads()),
                    compiler=f"{_build_config.CC_ID} {_build_config.CC_VERSION}",
                    kernel_c_args=_build_config.KERNEL_C_ARGS,
                    buildtype=_build_config.BUILDTYPE)
    except (ImportError, AttributeError):  # pragma: no cover
        pass
    return info


def tile_to(img, shape):
    """Tile an image (mirrored, so that the seams are smooth) up to ``shape`` (rows, cols)."""
    rows, cols = shape
    ny = -(-rows // img.shape[0])
    nx = -(-cols // img.shape[1])
    row = [img if j % 2 == 0 else img[:, ::-1] for j in range(nx)]
    band = np.concatenate(row, axis=1)
    full = np.concatenate([band if i % 2 == 0 else band[::-1] for i in range(ny)], axis=0)
    return np.ascontiguousarray(full[:rows, :cols])


def common_means(cells, images):
    """Means of ``cells`` ({key: {image: value}}) over the same images: those of ``images`` on
    which every cell is finite. A PSNR is +inf where a reconstruction is exact (a flat image):
    averaged apart, each cell had covered other images (one flat image made every tradeoff
    mean +inf; pattern-study left it out of CPSNR and not of the zipper's). With no such
    image, a cell that is +inf on every image is inf (exact, as evaluate prints it), any
    other None: never NaN, which neither ranks nor goes into strict JSON.

    Returns ``({key: mean}, kept, left)``: the images averaged and those left out (of the
    ones some cell holds), in the order of ``images``.
    """
    seen = [n for n in images if any(n in c for c in cells.values())]
    kept = [n for n in seen if all(np.isfinite(c.get(n, np.nan)) for c in cells.values())]
    means = {}
    for key, c in cells.items():
        if kept:
            means[key] = float(np.mean([c[n] for n in kept]))
        else:
            means[key] = float("inf") if c and all(v == float("inf") for v in c.values()) \
                else None
    return means, kept, [n for n in seen if n not in kept]


def json_text(obj):
    """``obj`` as indented, strict JSON (NumPy numbers as numbers, non-finite floats as
    null: Python's own floats too, which json would write as NaN or Infinity)."""
    return json.dumps(_finite(obj), indent=2, sort_keys=False, default=_json_default,
                      allow_nan=False)


def _finite(o):
    """``o`` with every non-finite Python float (in dicts, lists and tuples) as None."""
    return nonfinite_as(o, lambda x: None)


def _json_default(o):
    if isinstance(o, np.integer):
        return int(o)
    if isinstance(o, np.floating):
        return None if not np.isfinite(o) else float(o)
    if isinstance(o, np.ndarray):
        return _finite(o.tolist())
    if isinstance(o, Path):
        return str(o)
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


def progress(iterable, total=None, desc=None, quiet=False):
    """tqdm over ``iterable`` on stderr, or the iterable itself when quiet or tqdm is absent."""
    if quiet:
        return iterable
    try:
        from tqdm.auto import tqdm
    except ImportError:  # pragma: no cover
        return iterable
    return tqdm(iterable, total=total, desc=desc, file=sys.stderr, leave=False)
