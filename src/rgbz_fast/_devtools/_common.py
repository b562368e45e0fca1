"""Helpers shared by ``rgbz-fast bench``, ``opcount`` and ``tradeoff``: machine facts, the
benchmark frame, command-line plumbing. Not a public API.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
from pathlib import Path

import numpy as np

__all__ = ["machine_info", "tile_to", "CliError", "common_parser", "run_main", "write_json",
           "progress"]


class CliError(Exception):
    """Bad command-line input: printed as one line, exit status 2."""


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


class _Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (and exit status 2)."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see --help)\n")


def common_parser(prog, description):
    """An ArgumentParser with the options every benchmark command shares."""
    p = _Parser(prog=prog, description=description,
                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")
    p.add_argument("--quick", action="store_true", help="small frames and few repeats (seconds)")
    p.add_argument("--workers", type=int, default=None,
                   help="threads of the 'all threads' runs (default: all cores)")
    p.add_argument("--out", metavar="DIR", default=None,
                   help="also write the report (and JSON, plots) into DIR (default: print "
                        "only)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    return p


def check_out_dir(out):
    if out is None:
        return None
    p = Path(out)
    if p.exists() and not p.is_dir():
        raise CliError(f"--out: {out!r} exists and is not a folder")
    p.mkdir(parents=True, exist_ok=True)
    return p


def check_workers_arg(workers):
    if workers is None:
        return None
    if workers < 1:
        raise CliError(f"--workers: expected a positive integer, got {workers}")
    return workers


def write_json(obj, path=None):
    text = json.dumps(obj, indent=2, sort_keys=False, default=_json_default)
    if path is None:
        return text
    Path(path).write_text(text + "\n", encoding="utf-8")
    return text


def _json_default(o):
    if isinstance(o, np.integer):
        return int(o)
    if isinstance(o, np.floating):
        return None if not np.isfinite(o) else float(o)
    if isinstance(o, np.ndarray):
        return o.tolist()
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


def run_main(parser, body, argv):
    """Parse ``argv``, run ``body(args)``; bad input -> one line on stderr and exit status 2."""
    args = parser.parse_args(argv)
    try:
        return int(body(args) or 0)
    except CliError as exc:
        print(f"{parser.prog}: error: {exc}", file=sys.stderr)
        return 2
    except (ValueError, TypeError) as exc:
        print(f"{parser.prog}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # pragma: no cover
        print(f"{parser.prog}: interrupted", file=sys.stderr)
        return 130
