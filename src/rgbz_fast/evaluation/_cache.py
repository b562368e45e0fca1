"""The evaluation's cache: one folder per image, one checksummed JSON entry per (pattern,
method), read through the guarded reader and validated, written atomically."""

from __future__ import annotations

import hashlib
import json
import re
import threading

import numpy as np

from .._validate import check_path
from ..io import atomic_write, read_file
from ..io._files import _existing_kind


def _safe(name):
    return "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in name)


_REVISION = []


def results_version():
    """The version the cached results of this installation carry: the package's version and a
    digest of what computes them, its Python modules, its shipped filters and its compiled
    extension modules (about 11 MB, read once a process: 20 ms). The version alone (0.1.0 on
    every commit) had served the numbers of the shipped filters before a refit, and would have
    served the guided ISP's before a change of its kernel; any change of the code now starts
    a fresh cache (a rebuild that changes nothing but the extension's bytes does too)."""
    if not _REVISION:
        from pathlib import Path

        from .. import _kernels
        from .._build_config import VERSION

        root = Path(__file__).resolve().parents[1]
        files = sorted([*root.rglob("*.py"), *root.rglob("*.npz")])
        here = Path(_kernels.__file__).resolve().parent
        files += sorted([*here.glob("*.so"), *here.glob("*.pyd")])
        h = hashlib.sha1()
        for f in files:
            h.update(f.name.encode())
            h.update(hashlib.sha1(f.read_bytes()).digest())
        _REVISION.append(f"{VERSION}+{h.hexdigest()[:12]}")
    return _REVISION[0]


def check_cache_dir(cache_dir, name="cache_dir"):
    """``cache_dir`` as a Path (None stays None), a ValueError naming ``name`` when it exists
    and is not a folder (the first entry's write failed deep in the run, naming a sub-path)."""
    if cache_dir is None:
        return None
    cache_dir = check_path(cache_dir, name)
    if cache_dir.exists() and not cache_dir.is_dir():
        raise ValueError(f"{name}: {cache_dir} exists and is not a folder")
    return cache_dir


def check_scheduler(scheduler):
    """``scheduler`` when it is None, a Dask client (has ``submit``) or an address such as
    ``tcp://host:8786``; else a ValueError naming it (Dask's own message named no option)."""
    if scheduler is not None and not hasattr(scheduler, "submit") and not (
            isinstance(scheduler, str) and re.fullmatch(r"\w+://[^/\s]+:\d+", scheduler)):
        raise ValueError(f"scheduler: expected a Dask scheduler address such as "
                         f"tcp://host:8786, or a distributed.Client, got {scheduler!r:.60}")
    return scheduler


def distributed():
    """Dask's ``distributed`` module, or an ImportError that says how to install it (the bare
    "No module named 'distributed'" said nothing of the option that needs it)."""
    try:
        import distributed as mod
    except ImportError:
        raise ImportError("scheduler: a Dask scheduler needs the distributed package: pip "
                          "install \"dask[distributed]\"  (or pip install rgbz-fast[dask])") \
            from None
    return mod


def cache_folder(name):
    """The cache folder of an image name: readable, and distinct for distinct names.

    The name's characters outside ``[A-Za-z0-9._-]`` become ``_``, and a hash
    of the exact name is appended, so ``"a b"`` and ``"a_b"`` get two folders.
    A file name that is not UTF-8 (``b"caf\\xe9.png"``, which Python names
    ``"caf\\udce9"``) gets one too: its lone surrogate is ``_`` in the readable part
    (no surrogate is alphanumeric) and hashed as "surrogatepass" encodes it (one-to-one
    over every str, and the same bytes as UTF-8 for every other name, so no
    existing folder moves); strict UTF-8 had stopped every evaluation of such a
    dataset with "surrogates not allowed", naming nothing.
    """
    raw = name.encode("utf-8", "surrogatepass")
    return f"{_safe(name)[:60]}-{hashlib.sha1(raw).hexdigest()[:10]}"


#: the largest cache entry read (one small JSON object of at most five numbers)
_CACHE_MAX_BYTES = 1 << 16
#: the values each metric can take: PSNRs are finite or +inf (equal images), the others
#: lie in their ranges; anything else in a cache entry was not written by the evaluation
_METRIC_RANGES = {"cfa_psnr": (-np.inf, np.inf), "cpsnr": (-np.inf, np.inf),
                  "ssim": (-1.0, 1.0), "ms_ssim": (0.0, 1.0), "zipper": (0.0, 100.0)}


def _json_number(text):
    """A JSON number of a cache entry: a literal too large for a double (1e999) is no value
    the evaluation wrote (it writes inf as Infinity)."""
    v = float(text)
    if not np.isfinite(v):
        raise ValueError(f"the number {text} is beyond the doubles")
    return v


def _json_constant(name):
    if name != "Infinity":                    # NaN and -Infinity are no metric's value
        raise ValueError(f"{name} is no metric value")
    return float("inf")


def _cache_check(key, body):
    """The checksum that binds an entry's values to its key: an entry edited by hand, or
    moved under another key, fails it and is computed again."""
    return hashlib.sha256(f"{key}\n{body}".encode()).hexdigest()


def _cache_read(cdir, key):
    """The cached values of one (pattern, method), or None to compute them again.

    Read through the guarded reader (a regular file of at most 64 kB, so that a FIFO or a
    device in the cache never blocks) and validated: ``{"values": ..., "check": ...}`` whose
    checksum matches (:func:`_cache_check`), the values a JSON object of known metrics, each
    a number in its range (a PSNR may be +inf). A damaged or tampered entry (NaN, 1e999,
    text, a value out of range, values edited without their checksum) is a miss, recomputed
    and written again.
    """
    try:
        data = read_file(cdir / f"{key}.json", "cache", max_bytes=_CACHE_MAX_BYTES)
        entry = json.loads(data.decode("utf-8"), parse_float=_json_number,
                           parse_int=_json_number, parse_constant=_json_constant)
        values = entry["values"]
        body = json.dumps(values, sort_keys=True)
        if entry.get("check") != _cache_check(key, body) or len(entry) != 2:
            return None
    except (OSError, ValueError, RecursionError, TypeError, KeyError, AttributeError):
        return None                                      # UnicodeDecodeError: a ValueError
    if not isinstance(values, dict):
        return None
    for k, v in values.items():
        lo, hi = _METRIC_RANGES.get(k, (None, None))
        if lo is None or not isinstance(v, float) or not lo <= v <= hi \
                or (v == np.inf and k not in ("cfa_psnr", "cpsnr")):
            return None
    return values


#: the causes (errno, cache folder) of failed cache writes warned of since the evaluation
#: began: a cache folder of no write permission (or a full disk) failed every entry, each
#: with a warning of its own (10 lines an image, 240 on Kodak)
_write_failures = set()
_write_failures_lock = threading.Lock()


def forget_write_failures():
    """An evaluation that begins warns again of a cache it cannot write."""
    with _write_failures_lock:
        _write_failures.clear()


def _cache_write(cdir, key, values):
    """Write an entry; a cache that cannot take it (a folder or a file of no write
    permission under its name) costs a warning, never the result: one warning for each
    cause (the error, in this cache) until :func:`forget_write_failures`."""
    body = json.dumps(values, sort_keys=True)
    entry = cdir / f"{key}.json"
    try:
        cdir.mkdir(parents=True, exist_ok=True)
        if _existing_kind(entry) is not None:
            # a FIFO or a device under the cache's own name (atomic_write refuses to replace
            # one): the cache's, so it goes; a folder stays and costs the warning below
            entry.unlink()
        atomic_write(cdir / f"{key}.json", json.dumps(
            {"check": _cache_check(key, body), "values": values}, sort_keys=True))
    except (OSError, ValueError) as exc:
        import warnings

        # the error within this cache: a folder of no permission, a full disk
        cause = (exc.errno, str(cdir.parent)) if isinstance(exc, OSError) else None
        with _write_failures_lock:
            first = cause not in _write_failures
            if cause is not None:
                _write_failures.add(cause)
        if first:
            more = "" if cause is None else \
                "; other entries that fail so are kept and not named either"
            warnings.warn(f"cache_dir: could not write {cdir / key}.json ({exc}); the result "
                          f"is kept, not cached{more}", RuntimeWarning, stacklevel=2)
