"""Saving and loading raw frames: NPZ (everything) or 16-bit TIFF (the mosaic plus metadata).

An NPZ file holds the frame data, the pattern tile, the bit depth, the
reference CFA when there is one, the ToF taps when there are any, and the
metadata as JSON. A TIFF holds the mosaic as uint16 with the pattern, bit
depth and metadata as JSON in the ImageDescription tag, so other tools can
open it. Files are written atomically. A tuple of the metadata is written as the JSON
object ``{"__tuple__": [...]}`` and loads as a tuple.
"""

from __future__ import annotations

import io
import json

import numpy as np

from .._frame import RawFrame, ToFTaps, _Adopt
from .._patterns import Pattern, get_pattern
from .._sensors import ToFSensor
from .._threads import map_in_order
from .._validate import as_list, check_bit_depth, check_path
from ._errors import ParameterError, named
from ._files import atomic_write, check_size, raise_it, read_file, read_image, read_limits
from ._npz import npz_bytes
from ._raw import read_raw
from ._suffixes import FRAME_SUFFIXES

__all__ = ["save_frame", "load_frame", "FRAME_SUFFIXES"]

_FORMAT_TAG = "rgbz-fast raw frame"


_NOT_JSON = object()


#: the JSON object a tuple of ``meta`` is saved as, so that it loads as a tuple (it had come
#: back a list, unequal to what was saved: ``(1, 2) != [1, 2]``)
_TUPLE_KEY = "__tuple__"


def _json_value(v):
    """``v`` as JSON (NumPy scalars as numbers, tuples as ``{"__tuple__": [...]}``, nested
    lists and objects), or _NOT_JSON."""
    if isinstance(v, (str, int, float, bool)) or v is None:
        return v
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, (list, tuple)):
        items = [_json_value(x) for x in v]
        if any(x is _NOT_JSON for x in items):
            return _NOT_JSON
        return {_TUPLE_KEY: items} if isinstance(v, tuple) else items
    if isinstance(v, dict) and all(isinstance(k, str) for k in v):
        if set(v) == {_TUPLE_KEY}:
            return _NOT_JSON          # the tuple marker itself: it would load as a tuple
        items = {k: _json_value(x) for k, x in v.items()}
        return _NOT_JSON if any(x is _NOT_JSON for x in items.values()) else items
    return _NOT_JSON


def _from_json(v):
    """A ``meta`` value read from JSON: the tuples :func:`_json_value` wrote, tuples again
    (files of earlier versions hold lists, which stay lists)."""
    if isinstance(v, list):
        return [_from_json(x) for x in v]
    if isinstance(v, dict):
        if set(v) == {_TUPLE_KEY} and isinstance(v[_TUPLE_KEY], list):
            return tuple(_from_json(x) for x in v[_TUPLE_KEY])
        return {k: _from_json(x) for k, x in v.items()}
    return v


def _jsonable(meta, arrays=None, dropped=None):
    """The JSON of a frame's ``meta``. Arrays go to ``arrays`` (the NPZ's ``meta__KEY``
    members) when it is given; what neither holds is listed in ``dropped``, except the
    sensor models (dataclass objects), which the header records otherwise."""
    import dataclasses

    out = {}
    for k, v in (meta or {}).items():
        j = _json_value(v)
        if j is not _NOT_JSON:
            out[k] = j
        elif isinstance(v, np.ndarray) and arrays is not None:
            arrays[f"meta__{k}"] = v
        elif dropped is not None and not dataclasses.is_dataclass(v):
            dropped.append(k)
    return out


def _warn_lost(path, what):
    """A UserWarning, at save_frame's caller, that ``path`` does not keep ``what``."""
    import warnings

    warnings.warn(f"path: {path.name} {what}", UserWarning, stacklevel=3)


def _warn_dropped(path, dropped, why):
    if dropped:
        _warn_lost(path, f"does not keep meta {', '.join(map(repr, dropped))} ({why})")


def save_frame(path, frame):
    """Write ``frame`` to ``path`` (.npz or .tif/.tiff), atomically; returns the path."""
    if not isinstance(frame, RawFrame):
        raise TypeError(f"frame: expected a RawFrame, got {type(frame).__name__}")
    path = check_path(path, "path")
    suffix = path.suffix.lower()
    meta_arrays, dropped = ({} if suffix == ".npz" else None), []
    header = {"format": _FORMAT_TAG, "pattern": frame.pattern.tile_string,
              "pattern_name": frame.pattern.name, "bayer": frame.pattern.bayer_phase,
              "bit_depth": frame.bit_depth,
              "meta": _jsonable(frame.meta, meta_arrays, dropped)}
    if suffix == ".npz":
        _warn_dropped(path, dropped, "not JSON")
        arrays = {"data": frame.data, "header": np.array(json.dumps(header)), **meta_arrays}
        if frame.reference is not None:
            arrays["reference"] = frame.reference
        tof = frame.tof
        if tof is not None:
            import dataclasses

            arrays.update(tof_taps=np.asarray(tof.taps),
                          tof_frequencies=np.asarray(tof.frequencies, dtype=np.float64),
                          tof_sites_rows=np.asarray(tof.sites[0]),
                          tof_sites_cols=np.asarray(tof.sites[1]),
                          tof_depth_true=np.asarray(tof.depth_true),
                          tof_valid=np.asarray(tof.valid), tof_saturated=np.asarray(tof.saturated))
            header["tof"] = {"block": int(tof.block), "bit_depth": int(tof.bit_depth),
                             "shape": [int(v) for v in tof.shape],
                             "sensor": dataclasses.asdict(tof.sensor),
                             "meta": _jsonable(tof.meta)}
            arrays["header"] = np.array(json.dumps(header, default=_json_default))
        atomic_write(path, npz_bytes(arrays))
    elif suffix in (".tif", ".tiff"):
        import tifffile

        data = frame.data
        _warn_dropped(path, dropped, "a TIFF holds the mosaic and JSON metadata; .npz keeps "
                                     "arrays")
        # the reference and the taps had been dropped without a word, and the simulator's
        # meta["tof"] still described the taps the file no longer held
        lost = [what for what, there in (("the reference CFA", frame.reference is not None),
                                         ("the ToF taps", frame.tof is not None)) if there]
        if lost:
            _warn_lost(path, f"does not keep {' and '.join(lost)} (a TIFF holds the mosaic; "
                             ".npz keeps them)")
        if frame.tof is not None and isinstance(header["meta"], dict):
            header["meta"].pop("tof", None)
        if data.dtype not in (np.uint8, np.uint16):
            _warn_lost(path, f"keeps the {data.dtype} mosaic as 16-bit codes (rounded); .npz "
                             "keeps it as it is")
            data = np.floor(np.clip(data, 0, frame.white_level) + 0.5).astype(np.uint16)
        buf = io.BytesIO()
        tifffile.imwrite(buf, data, description=json.dumps(header), metadata=None)
        atomic_write(path, buf.getvalue())
    else:
        raise ValueError(f"path: unsupported frame file type {suffix!r}; use .npz or .tif")
    return path


def load_frame(path, *, pattern=None, bit_depth=None, max_pixels=None, max_bytes=None,
               **raw_kwargs):
    """Read a frame written by :func:`save_frame`, or a camera raw file through :func:`rgbz_fast.io.read_raw`.

    ``pattern`` and ``bit_depth`` are needed for a TIFF or PNG that carries
    no rgbz-fast header; a file that has one records its own, and a different
    ``pattern`` or ``bit_depth`` is refused (it would be ignored). For a raw
    file (read by :func:`~rgbz_fast.io.read_raw` with ``raw_kwargs``),
    ``bit_depth`` is the working bit depth it is scaled to (``"input"``: the
    file's own).
    ``max_pixels`` and ``max_bytes`` bound what is read (see
    :func:`rgbz_fast.io.read_limits`): the file's size, and every array the
    file declares, checked from the headers before anything is allocated.

    Raises
    ------
    ValueError
        ``"path: ..."`` naming the file when it does not exist, is not a
        regular file (a folder, a FIFO, a device), is larger than the limits,
        or cannot be read: an NPZ that is truncated, not a zip archive, or
        lacks the frame's arrays or header keys (``pattern``, ``bit_depth``);
        a TIFF or PNG that does not decode; a header that is not JSON or
        describes no valid frame. The errors of :func:`rgbz_fast.io.read_raw`
        for other files. A raw option (``raw_kwargs``) given for an rgbz-fast
        frame file or a plain mosaic read with ``pattern``, which take none,
        is refused, naming the option.
    """
    path = check_path(path, "path")
    limits = read_limits(max_pixels, max_bytes)
    if not path.exists():
        raise ValueError(f"path: {path} does not exist")
    suffix = path.suffix.lower()
    if suffix == ".npz":
        _no_raw_options(raw_kwargs, path, _FRAME_FILE)
        return _as_recorded(_load_npz(path, limits), path, pattern, bit_depth)
    if suffix in (".tif", ".tiff"):
        from ._tiff import open_tiff

        desc = []

        def decode(blob):
            with open_tiff(blob) as tf:
                page = tf.pages[0]
                desc.append(page.description or "")
                return page.asarray()

        data = read_image(path, "path", decode, max_pixels=limits[0], max_bytes=limits[1])
        try:
            header = _parse_json(desc[0])
        except ValueError:
            header = None                                   # not ours: a plain mosaic
        if isinstance(header, dict) and header.get("format") == _FORMAT_TAG:
            _no_raw_options(raw_kwargs, path, _FRAME_FILE)
            return _as_recorded(_checked(path, lambda: _frame_from(_check_header(header), data)),
                                path, pattern, bit_depth)
    if pattern is not None and suffix in (".tif", ".tiff", ".png"):
        _no_raw_options(raw_kwargs, path, "read as a plain mosaic with pattern=, as it is")
        if bit_depth is None:
            raise ValueError("bit_depth: required for a plain TIFF/PNG mosaic with a pattern")
        data = read_image(path, "path", max_pixels=limits[0], max_bytes=limits[1])
        return RawFrame(_Adopt(data), get_pattern(pattern), bit_depth, meta={"source": str(path)})
    if bit_depth is not None:
        raw_kwargs["bit_depth"] = bit_depth           # the working bit depth of a raw file
    return read_raw(path, max_pixels=limits[0], max_bytes=limits[1], **raw_kwargs)


_FRAME_FILE = "an rgbz-fast frame file, which records its own pattern, bit depth and levels"


def _no_raw_options(raw_kwargs, path, what):
    """A ValueError naming the first raw option given for a file that does not take them
    (they had been accepted and ignored)."""
    if raw_kwargs:
        key = next(iter(raw_kwargs))
        raise ValueError(f"{key}: {path} is {what}; the raw options apply to camera raw "
                         "files (read_raw)")


def _as_recorded(frame, path, pattern, bit_depth):
    """``frame``, read from a file that records its pattern and bit depth, when ``pattern``
    and ``bit_depth`` (None, or ``"input"``: the file's own) agree with what it records; a
    ValueError naming the one that does not (it would be ignored)."""
    if pattern is not None and get_pattern(pattern) != frame.pattern:
        raise ValueError(f"pattern: {path} records its own pattern {frame.pattern.name!r}; "
                         f"pattern={pattern!r:.40} applies to a plain TIFF/PNG mosaic")
    if not (bit_depth is None or isinstance(bit_depth, str) and bit_depth == "input") \
            and check_bit_depth(bit_depth) != frame.bit_depth:
        raise ValueError(f"bit_depth: {path} records its own bit depth {frame.bit_depth}; "
                         f"bit_depth={bit_depth!r:.40} applies to a plain TIFF/PNG mosaic or "
                         "a raw file")
    return frame


#: the arrays of an NPZ frame (anything else in the archive is not read)
_NPZ_KEYS = ("header", "data", "reference", "tof_taps", "tof_frequencies", "tof_sites_rows",
             "tof_sites_cols", "tof_depth_true", "tof_valid", "tof_saturated")
#: the JSON types of the header's fields: (key, types, required, what)
_HEADER_FIELDS = (("pattern", (str,), True, "a tile string"),
                  ("pattern_name", (str, type(None)), False, "a string"),
                  ("bayer", (str, type(None)), False, "a Bayer phase"),
                  ("bit_depth", (int,), True, "an integer"),
                  ("meta", (dict,), False, "an object"))
_TOF_FIELDS = (("block", (int,), True, "an integer"), ("bit_depth", (int,), True, "an integer"),
               ("shape", (list,), True, "a list [rows, cols]"),
               ("sensor", (dict,), True, "an object"), ("meta", (dict,), False, "an object"))


def _parse_json(text):
    try:
        return json.loads(text)
    except RecursionError:
        raise ValueError("the header is nested too deeply") from None
    except ValueError as exc:
        raise ValueError(f"the header is not JSON: {exc}") from None


def _check_header(header):
    """The header of a frame file, its fields type-checked (a ValueError says which is wrong)."""
    _check_fields(header, _HEADER_FIELDS, "header")
    if "tof" in header:
        _check_fields(header["tof"], _TOF_FIELDS, "header's 'tof'")
        shape = header["tof"]["shape"]
        if len(shape) != 2 or not all(type(v) is int for v in shape):
            raise ValueError(f"the header's 'tof' shape is {shape!r}, expected [rows, cols]")
    return header


def _check_fields(obj, fields, where):
    if not isinstance(obj, dict):
        raise ValueError(f"the {where} is a JSON {type(obj).__name__}, not an object")
    for key, types, required, what in fields:
        if key not in obj:
            if required:
                raise KeyError(key)
            continue
        v = obj[key]
        if not isinstance(v, types) or isinstance(v, bool):
            raise ValueError(f"the {where} field {key!r} is {v!r:.40}, expected {what}")


def _frame_from(header, data, reference=None, tof=None):
    return RawFrame(_Adopt(data), _pattern(header), header["bit_depth"],
                    reference=None if reference is None else _Adopt(reference), tof=tof,
                    meta=_from_json(header.get("meta", {})))


def _checked(path, build):
    """``build()``, reporting what is wrong with the file's content as a ValueError naming it.

    The content of a frame file is the value of ``path``: a missing header
    key or archive member, a header that is not JSON, an array or a pattern
    RawFrame rejects all mean the file is not a readable frame.
    """
    try:
        return build()
    except KeyError as exc:
        raise ValueError(f"path: {path} is not a readable rgbz-fast frame (missing key "
                         f"{exc})") from None
    except ParameterError as exc:
        if exc.param == "path":                            # a size limit: already named
            raise exc from None
        raise named(exc, "path", f"{path} is not a readable rgbz-fast frame (", ")") from None
    except (ValueError, TypeError, OverflowError, RecursionError) as exc:
        raise ValueError(f"path: {path} is not a readable rgbz-fast frame ({exc})") from None


def read_npz(path, name="path", *, keys=None, required=(), max_pixels=None, max_bytes=None):
    """The arrays of an NPZ archive, read without trusting it.

    The archive is read into memory (at most ``max_bytes``, from a regular
    file only) and each member's ``.npy`` header is read before its array: a
    member that declares more than the limits (:func:`rgbz_fast.io.read_limits`),
    or more than its own uncompressed size in the zip directory (a zip bomb),
    or Python objects, is refused before anything is allocated.

    Parameters
    ----------
    path : str or Path
    name : str
        The parameter named in errors.
    keys : iterable of str, optional
        The members to read (others are ignored); default: every member.
    required : iterable of str
        Members that must be present.
    max_pixels, max_bytes : int, optional
        The read limits (:func:`rgbz_fast.io.read_limits`): the elements of one
        member and the bytes of the file.

    Returns
    -------
    dict of str to ndarray

    Raises
    ------
    FileNotFoundError
        ``"<name>: no such file: ..."`` when the file is missing.
    ValueError
        ``"<name>: ..."`` when it is not a regular file, too large, not an
        NPZ archive, damaged, or lacks a required member.

    Examples
    --------
    >>> import io, tempfile, pathlib, numpy as np
    >>> from rgbz_fast.io import read_npz
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = pathlib.Path(d) / "a.npz"
    ...     np.savez(p, x=np.arange(3))
    ...     read_npz(p)["x"]
    array([0, 1, 2])
    """
    path = check_path(path, name)
    required = () if required is None else required
    for label, names in (("keys", keys), ("required", required)):
        if names is not None and not all(
                isinstance(k, str) for k in as_list(names, label, "member names")):
            raise TypeError(f"{label}: expected member names (strings), got {names!r:.40}")
    try:
        return _npz_members(path, name, keys, required, read_limits(max_pixels, max_bytes))
    except ValueError as exc:
        if isinstance(exc, ParameterError) and exc.param == name:
            raise exc from None                            # about the file itself: named
        raise named(exc, name, f"{path} is not a readable NPZ archive (", ")") from None


def _npz_members(path, name, keys, required, limits):
    """:func:`read_npz`: errors of the file itself (missing, too large) name ``name``; the
    others (what is wrong with the content) are bare, for the caller to name."""
    import zipfile
    import zlib

    broken = (zipfile.BadZipFile, zlib.error, EOFError, OSError, NotImplementedError)
    blob = read_file(path, name, max_bytes=limits[1])
    if blob[:2] != b"PK":          # else np.load tries an .npy array, then a pickle
        raise ValueError("not an NPZ archive: no zip signature")
    try:
        zf = zipfile.ZipFile(io.BytesIO(blob))
    except broken + (ValueError,) as exc:
        raise ValueError(f"not an NPZ archive: {type(exc).__name__}: {exc}") from None
    with zf:
        members = {n[:-4]: zf.getinfo(n) for n in zf.namelist() if n.endswith(".npy")}
        missing = [k for k in required if k not in members]
        if missing:
            raise ValueError(f"no member(s) {', '.join(missing)}")
        wanted = [k for k in (members if keys is None else keys) if k in members]
        wanted += [k for k in members if keys is not None and k.startswith("meta__")]
        declared = sum(members[k].file_size for k in wanted)
        if declared > limits[1]:
            raise ParameterError(None, f"its arrays declare {declared} bytes uncompressed, "
                                       f"more than the limit of {limits[1]} bytes",
                                 *raise_it("max_bytes"))
        try:
            return dict(zip(wanted, _read_members(zf, [members[k] for k in wanted], path,
                                                  limits, name, declared)))
        except broken as exc:
            raise ValueError(f"a damaged archive member: {type(exc).__name__}: "
                             f"{exc}") from None


def _load_npz(path, limits):
    """An NPZ frame; every way the file can be broken is a ValueError naming it
    (:func:`read_npz` reads the archive without trusting it)."""

    def build():
        z = _npz_members(path, "path", _NPZ_KEYS, (), limits)
        if "header" not in z or "data" not in z:
            raise ValueError("no header/data")
        h = z["header"]
        if h.dtype.kind not in "US" or h.ndim != 0:
            raise ValueError(f"the header is a {h.dtype} array of shape {h.shape}, not a "
                             "JSON string")
        header = _check_header(_parse_json(str(h)))
        tof = None
        if "tof_taps" in z:
            if "tof" not in header:
                raise KeyError("tof")
            tof = _load_tof(z, header["tof"])
        meta_arrays = {k[len("meta__"):]: v for k, v in z.items() if k.startswith("meta__")}
        if meta_arrays:                          # e.g. read_raw's clipped mask
            header = {**header, "meta": {**header.get("meta", {}), **meta_arrays}}
        return _frame_from(header, z["data"], z.get("reference"), tof)

    return _checked(path, build)


def _read_members(zf, infos, path, limits, name, declared):
    """:func:`_npz_array` of each member, in order; on threads (each inflating its own
    member: zipfile reads the archive under a lock, zlib inflates without the GIL) when they
    declare 4 MiB or more."""
    import os

    # Python threads: no OpenMP stacks to check
    threads = (os.cpu_count() or 1) if declared >= (4 << 20) else 1
    return map_in_order(lambda info: _npz_array(zf, info, path, limits, name), infos, threads)


def _npz_array(zf, info, path, limits, name="path"):
    """One ``.npy`` member of an archive, its declared size checked before it is read."""
    with zf.open(info) as fh:
        try:
            version = np.lib.format.read_magic(fh)
            if version == (1, 0):
                shape, fortran, dtype = np.lib.format.read_array_header_1_0(fh)
            elif version == (2, 0):
                shape, fortran, dtype = np.lib.format.read_array_header_2_0(fh)
            else:
                raise ValueError(f"unsupported .npy version {version}")
        except (ValueError, SyntaxError, TypeError) as exc:
            raise ValueError(f"member {info.filename}: {exc}") from None
        if dtype.hasobject:
            raise ValueError(f"member {info.filename} holds Python objects")
        nbytes = int(np.prod(shape, dtype=object)) * dtype.itemsize
        if nbytes > info.file_size:
            raise ValueError(f"member {info.filename} declares {nbytes} bytes of data in "
                             f"{info.file_size} bytes")
        check_size(shape, dtype.itemsize, path, name, limits=limits)
        raw = fh.read(nbytes)
    if len(raw) != nbytes:
        raise ValueError(f"member {info.filename} is truncated")
    arr = np.frombuffer(raw, dtype=dtype)
    return arr.reshape(shape[::-1]).T if fortran else arr.reshape(shape)


def _pattern(header):
    return Pattern(header["pattern"], name=header.get("pattern_name"), bayer=header.get("bayer"))


def _json_default(v):
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, np.ndarray):
        return v.tolist()
    return str(v)


def _load_tof(z, h):
    sensor = ToFSensor(**{k: tuple(v) if isinstance(v, list) else v
                          for k, v in h["sensor"].items()})
    # a file that does not say whether the scene's NIR was estimated: unknown (None), not False
    return ToFTaps(taps=z["tof_taps"], frequencies=z["tof_frequencies"],
                   sites=(z["tof_sites_rows"], z["tof_sites_cols"]), block=h["block"],
                   bit_depth=h["bit_depth"], depth_true=z["tof_depth_true"],
                   valid=z["tof_valid"], saturated=z["tof_saturated"], sensor=sensor,
                   shape=tuple(h["shape"]),
                   meta={"ir_estimated": None, **_from_json(h.get("meta", {}))})
