"""How the command line reads raw files: the raw options of ``reconstruct`` and the
``--raw-options`` JSON file of ``reconstruct`` and ``evaluate``."""

from __future__ import annotations

import json

from . import _common as c

__all__ = ["add_raw_group", "raw_options_file", "raw_kwargs", "RAW_FLAGS"]

#: (argument, read_raw parameter) of the raw options the user gives one by one
RAW_FLAGS = (("phase", "phase"), ("black_level", "black_level"),
             ("white_level", "white_level"), ("saturation_level", "clip_level"),
             ("shape", "shape"), ("bit_depth_in", "bit_depth_in"))


def add_raw_group(p):
    """The options that say how to read a camera raw, a Bayer PNG/TIFF or a headerless file."""
    raw = p.add_argument_group("raw files", "How to read a camera raw, a 16-bit Bayer PNG/TIFF "
                                            "or a headerless file (camera raw files record "
                                            "phase and levels; the options override them)")
    raw.add_argument("--phase", choices=("RGGB", "BGGR", "GRBG", "GBRG"), type=str.upper,
                     default=None, help="CFA phase at pixel (0, 0) (default: from the file)")
    raw.add_argument("--black-level", type=c.levels, default=None, metavar="DN[,DN,DN,DN]",
                     help="black level: one value, or four for the 2x2 quad row by row "
                          "(default: from the file)")
    raw.add_argument("--white-level", type=c.levels, default=None, metavar="DN[,DN,DN,DN]",
                     help="the raw value of full scale (default: from the file, else "
                          "2**bit-depth-in - 1)")
    raw.add_argument("--saturation-level", type=c.levels, default=None, metavar="DN[,DN,DN,DN]",
                     help="raw values at or above it are clipped (default: the white level)")
    c.add_shape(raw, None, "size of a headerless file, rows first, e.g. 1080x1920 (default: "
                           "none, required for headerless files)")
    raw.add_argument("--bit-depth-in", type=c.positive_int, default=None,
                     help="bits of the stored samples (default: from the file)")
    raw.add_argument("--byteorder", choices=("little", "big"), default="little",
                     help="byte order of a headerless file")
    raw.add_argument("--downsample", type=c.positive_int, default=1, metavar="K",
                     help="bin each colour plane KxK (the paper bins its HDR+ raws 2x2)")
    c.add_raw_options_file(raw, "; the options above override it")


class _DuplicateKey(Exception):
    pass


def _unique_keys(pairs):
    """json's object hook that refuses a key given twice in one object."""
    out = {}
    for k, v in pairs:
        if k in out:
            raise _DuplicateKey(k)
        out[k] = v
    return out


def raw_options_file(path):
    """The JSON file of ``--raw-options``: {file name or "*": {read_raw option: value}}."""
    from ..io import read_file
    from ..io._raw import check_raw_options

    if path is None:
        return {}
    try:
        text = read_file(path, "--raw-options", max_bytes=1 << 20).decode("utf-8")
        opts = json.loads(text, object_pairs_hook=_unique_keys)
    except _DuplicateKey as exc:            # json keeps the last of two, silently
        raise c.CliError(f"--raw-options: {path} gives {exc.args[0]!r} twice") from None
    except UnicodeDecodeError:
        raise c.CliError(f"--raw-options: {path} is not a UTF-8 text file; expected JSON") \
            from None
    except RecursionError:
        raise c.CliError(f"--raw-options: {path} nests its JSON too deeply; expected an "
                         "object of file names and their options") from None
    except (OSError, ValueError) as exc:
        why = " ".join(c.explain(exc).split()).removeprefix("--raw-options: ")
        if why.startswith("no such file"):              # the path is the message's already
            raise c.CliError(f"--raw-options: no such file: {path}") from None
        raise c.CliError(f"--raw-options: cannot read {path}: {why}") from None
    if not isinstance(opts, dict) or not all(isinstance(v, dict) for v in opts.values()):
        raise c.CliError(f"--raw-options: {path} should map file names (or \"*\") to objects of "
                         "options")
    try:
        return check_raw_options(opts, f"--raw-options: {path}")
    except ValueError as exc:
        raise c.CliError(str(exc)) from None


def raw_kwargs(args, path, from_file):
    """The read_raw options of one file: the JSON file's ("*", then its name), then the flags.

    Returns (every option, the ones the flags gave).
    """
    kw = {**from_file.get("*", {}), **from_file.get(path.name, {})}
    explicit = {}
    for flag, key in RAW_FLAGS:
        v = getattr(args, flag)
        if v is not None:
            explicit[key] = v
    if args.byteorder != "little":
        explicit["byteorder"] = ">"
    if args.downsample != 1:
        explicit["downsample"] = args.downsample
    kw.update(explicit)
    return kw, explicit
