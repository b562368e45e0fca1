"""What every command of ``rgbz-fast`` shares.

The one error type (:class:`CliError`), the argument types, the option helpers
(each option's text is written here once and every command that takes the
option adds it through its helper), how a library error reads on the command
line (:func:`explain`), and the checks of output paths. A command module
declares its options with these helpers in ``add_parser(sub)`` and does its
work in ``run(args)``.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from pathlib import Path

from .._validate import parse_shape
from ..io import MAX_BYTES_ENV, MAX_PIXELS_ENV

__all__ = ["CliError", "Formatter", "EPILOG", "command_parser", "explain", "command_line",
           "output_folder", "check_outputs", "unique_outputs", "file_label"]

EPILOG = ("Every option's default is shown in parentheses. The user guide, the measured "
          "results and the API reference are in docs/ of the source distribution (the "
          "sdist, or a checkout): docs/guide/cli.md for the commands.")


class CliError(Exception):
    """A user error: printed as one line, exit status 2."""


class Formatter(argparse.RawDescriptionHelpFormatter):
    """Help with each option's default (unless the text gives it, or it has none)."""

    def _get_help_string(self, action):
        text = action.help or ""
        if "default" in text or not action.option_strings or any(
                action.default is v for v in (None, False, argparse.SUPPRESS)):
            return text
        return text + " (default: %(default)s)"


def command_parser(sub, name, help, description):
    """The parser of one command, with the help format and epilog every command shares."""
    return sub.add_parser(name, help=help, description=description, formatter_class=Formatter,
                          epilog=EPILOG)


# --------------------------------------------------------------------------- argument types
def csv(text):
    """A comma-separated list: 'a, b,,c' -> ('a', 'b', 'c'); an entry given twice, or no
    entry at all ('' or ','), is a usage error (it would be run twice; an empty list ran
    nothing and printed an empty table). :func:`csv_or_none` takes an empty list."""
    items = csv_or_none(text)
    if not items:
        raise argparse.ArgumentTypeError(f"expected at least one comma-separated entry, got "
                                          f"{text!r}")
    return items


def csv_or_none(text):
    """:func:`csv` where '' means none (pattern-study's --presets: custom tiles only)."""
    items = tuple(s.strip() for s in text.split(",") if s.strip())
    twice = next((s for i, s in enumerate(items) if s in items[:i]), None)
    if twice is not None:
        raise argparse.ArgumentTypeError(f"{twice!r} is given twice in {text!r}; name each "
                                          "entry once")
    return items


def number(convert, accept, what):
    """An argparse type: ``convert(text)`` when ``accept`` takes it, else a usage error."""
    def parse(text):
        try:
            v = convert(text)
        except ValueError:
            v = None
        if v is None or not accept(v):
            raise argparse.ArgumentTypeError(f"expected {what}, got {text!r}")
        return v
    return parse


positive_int = number(int, lambda v: v >= 1, "a positive integer")
non_negative_int = number(int, lambda v: v >= 0, "an integer >= 0")
positive_float = number(float, lambda v: 0 < v < float("inf"), "a positive number")
non_negative_float = number(float, lambda v: 0 <= v < float("inf"), "a number >= 0")


def thread_count(text):
    """Threads: a positive integer up to what check_workers accepts (MAX_WORKERS), so that
    no count reaches C as an integer too large for it."""
    from .._validate import MAX_WORKERS

    v = positive_int(text)
    if v > MAX_WORKERS:
        raise argparse.ArgumentTypeError(f"expected at most {MAX_WORKERS} threads, got {text!r}")
    return v


def off_or(parse):
    """An argparse type: ``off`` (None: the test is not made), else ``parse(text)``."""
    def parse_or_off(text):
        return None if text.strip().lower() == "off" else parse(text)
    return parse_or_off


def levels(text):
    """One level, or four (one per site of the 2x2 quad, row by row): '64' or '64,64,65,64'."""
    try:
        vals = [float(v) for v in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number or four comma-separated numbers, "
                                          f"got {text!r}") from None
    if len(vals) not in (1, 4):
        raise argparse.ArgumentTypeError(f"expected one value or four, got {len(vals)}")
    return vals[0] if len(vals) == 1 else vals


def shape(text):
    """ROWSxCOLS, rows first."""
    try:
        return parse_shape(text, "shape")
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc).removeprefix("shape: ")) from None


#: the largest MAX of a depth range, in metres (a colour scale beyond it is no depth a ToF
#: pixel gives; 1e308 broke the plot's ticks after the TIFFs were written)
METRE_RANGE_MAX = 1e4


def path(text):
    """A file or folder argument: an empty one (an unset shell variable) is refused, where
    ``Path("")`` would have been the current folder (to write into, read or clean up)."""
    if not text.strip():
        raise argparse.ArgumentTypeError("an empty path (an unset shell variable?)")
    return Path(text)


def metre_range(text):
    """MIN:MAX in metres, 0 <= MIN < MAX <= 10 km, MAX - MIN >= 1 mm."""
    try:
        lo, hi = (float(v) for v in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected MIN:MAX in metres, got {text!r}") from None
    if not (0 <= lo < hi <= METRE_RANGE_MAX) or hi - lo < 1e-3:
        raise argparse.ArgumentTypeError(f"expected 0 <= MIN < MAX <= {METRE_RANGE_MAX:g} m and "
                                         f"MAX - MIN >= 0.001 m, got {text!r}")
    return lo, hi


def clip_level(text):
    """'auto', 'off' (None) or a positive number of DN."""
    t = text.strip().lower()
    if t == "auto":
        return "auto"
    if t in ("off", "none"):
        return None
    try:
        return positive_float(t)
    except argparse.ArgumentTypeError:
        raise argparse.ArgumentTypeError(
            f"expected auto, off or a positive number, got {text!r}") from None


# --------------------------------------------------------------------------- options
def add_workers(p, what="threads of each kernel call", default="all cores"):
    """``--workers N``: the one thread-count option; a count below 1 is a usage error.
    ``default`` says what the command does without it (evaluate's is its own)."""
    p.add_argument("--workers", type=thread_count, default=None, metavar="N",
                   help=f"{what} (default: {default})")


def add_limits(p):
    """``--max-pixels``, ``--max-bytes``: the read limits of every file the command reads."""
    p.add_argument("--max-pixels", type=positive_int, default=None, metavar="N",
                   help=f"refuse images larger than N pixels, as their headers declare them, "
                        f"before decoding (default: {MAX_PIXELS_ENV} when set, else 200000000)")
    p.add_argument("--max-bytes", type=positive_int, default=None, metavar="N",
                   help=f"refuse files, and arrays in them, larger than N bytes (default: "
                        f"{MAX_BYTES_ENV} when set, else 2147483648)")


def add_run_options(p, default_out, workers=True):
    """The options of the commands that run the chain on files: ``--workers`` (unless
    ``workers`` is False; a text: what the command does without it, where that is not all
    cores), ``--out DIR`` (``default_out``), ``--quiet`` and the read limits."""
    if isinstance(workers, str):
        add_workers(p, default=workers)
    elif workers:
        add_workers(p)
    add_output_folder(p, default_out)
    add_quiet(p)
    add_limits(p)


def add_report_options(p, workers=True):
    """The options of the measuring commands, which print a report: ``--quick``,
    ``--workers`` of the 'all threads' runs (unless ``workers`` is False), ``--json``,
    ``--out DIR`` to also write it, ``--quiet``."""
    add_quick(p)
    if workers:
        add_workers(p, "threads of the 'all threads' runs", "all cores")
    add_json(p, "print JSON instead of a table")
    add_output_folder(p, None, "also write the report (and JSON, plots) into DIR (default: "
                               "print only)")
    add_quiet(p, "no progress bar")


def add_output_folder(p, default, what="output folder, created when the first file is written"):
    """``--out DIR``; ``default`` None: the command prints only, unless given a folder."""
    p.add_argument("--out", type=path, default=None if default is None else Path(default),
                   metavar="DIR", help=what)


def add_output_file(p, what, default=None):
    """``--out FILE``: the one file a command writes (required when ``default`` is None)."""
    p.add_argument("--out", type=path, default=None if default is None else Path(default),
                   required=default is None, metavar="FILE",
                   help=what + (" (required)" if default is None else ""))


def _terminal():
    """Whether stderr is a terminal."""
    try:
        return bool(sys.stderr.isatty())
    except (AttributeError, ValueError):          # replaced or closed
        return False


def bars(args):
    """Whether the command draws progress bars: not with ``--quiet``, and not when stderr is
    no terminal (a log or a pipe, which the bars' carriage returns would fill)."""
    return not args.quiet and _terminal()


def add_quiet(p, what="no progress bar or per-file lines"):
    p.add_argument("--quiet", action="store_true", help=what)


def add_json(p, what):
    p.add_argument("--json", action="store_true", help=what)


def add_quick(p):
    p.add_argument("--quick", action="store_true",
                   help="small frames and few repeats (seconds)")


#: the most timed runs a --repeat asks for (100000000 ran without end)
REPEAT_MAX = 1000


def add_repeat(p, what):
    """``--repeat N``: timed runs; ``what`` names them and their defaults."""
    p.add_argument("--repeat", type=number(int, lambda v: 1 <= v <= REPEAT_MAX,
                                           f"an integer in [1, {REPEAT_MAX}]"),
                   default=None, metavar="N", help=f"{what} (at most {REPEAT_MAX})")


def add_seed(p, default, what):
    p.add_argument("--seed", type=non_negative_int, default=default, help=what)


def add_shape(p, default, what):
    """``--shape ROWSxCOLS``: a frame size, rows first."""
    p.add_argument("--shape", type=shape, default=None if default is None else shape(default),
                   metavar="ROWSxCOLS", help=what)


def made_shape(args, shape):
    """``shape``, the size of frames a command makes (not reads), within the pixel limit of
    reads (--max-pixels where the command has it, else RGBZ_FAST_MAX_PIXELS or 200
    megapixels): beyond it the arrays would not fit in memory. A CliError naming --shape."""
    from ..io import read_limits

    limit = read_limits(getattr(args, "max_pixels", None))[0]
    rows, cols = shape
    if rows * cols > limit:
        # raised with --max-pixels where the command has the option, else the variable only
        how = f"--max-pixels or {MAX_PIXELS_ENV}" if hasattr(args, "max_pixels") \
            else MAX_PIXELS_ENV
        raise CliError(f"--shape: {rows}x{cols} is {rows * cols / 1e6:.4g} megapixels, more "
                       f"than the limit of {limit / 1e6:.4g} megapixels ({how})")
    return tuple(shape)


def add_pattern(p, default, what):
    p.add_argument("--pattern", default=default, help=what)


def add_patterns(p, default="mask1,mask2", what="comma-separated patterns"):
    p.add_argument("--patterns", type=csv, default=default, help=what)


def z_patterns(names, flag="--patterns"):
    """``names`` (pattern names or tiles), each once and each with Z sites, else a CliError
    naming ``flag`` (a pattern without Z sites failed deep in a metric or a plan)."""
    from .._patterns import check_z_patterns

    try:
        return check_z_patterns(names, flag)
    except ValueError as exc:                   # get_pattern's own error names the pattern
        raise CliError(str(exc)) from None


def add_methods(p, default):
    p.add_argument("--methods", type=csv, default=default, help="comma-separated methods")


def add_dataset(p, what, required=False):
    p.add_argument("--dataset", type=path, default=None, required=required,
                   metavar="DIR" if required else None, help=what)


def add_limit(p, what="the first N images only (default: all)"):
    p.add_argument("--limit", type=positive_int, default=None, metavar="N", help=what)


def add_precision(p, default, what):
    p.add_argument("--precision", choices=("float32", "float64"), default=default, help=what)


def add_bit_depth(p, default, what):
    p.add_argument("--bit-depth", type=positive_int, default=default, help=what)


def add_grey(p):
    p.add_argument("--grey", action="store_true",
                   help="accept grey images, repeating them into R, G and B (default: refuse "
                        "them: a colour sensor needs colour)")


def add_linearise(p, instead):
    """``--linearise/--no-linearise``; ``instead``: what --no-linearise does with sRGB values."""
    p.add_argument("--linearise", action=argparse.BooleanOptionalAction, default=True,
                   help=f"linearise 8-bit sRGB images with the sRGB EOTF (default); "
                        f"--no-linearise {instead} the sRGB values (the 8-bit sRGB protocol)")


def add_reconstruction_options(p, precision, precision_help):
    """The options of the reconstruction itself: precision, domain, clip level, filters."""
    add_precision(p, precision, precision_help)
    p.add_argument("--domain", choices=("intensity", "colour_difference"), default="intensity",
                   help="interpolate intensities (the paper, eq. 13) or colour differences "
                        "(eq. 5)")
    p.add_argument("--clip-level", type=clip_level, default=None, metavar="off|auto|DN",
                   help="clipped (saturated) pixels: off takes every pixel as a real value; "
                        "auto uses the saturation level recorded when a raw file is read (none "
                        "for other frames); a number is the level in DN of the frame as it "
                        "is reconstructed (a raw file's after --bit-depth scales it; "
                        "--saturation-level is in the file's own DN). Differences between "
                        "two clipped pixels are then left out of the weights (default: off; a "
                        "pixel at the level is not always a clipped one)")
    p.add_argument("--filters", type=csv, default=None, metavar="FILE[,FILE]",
                   help="methods learned and z_guided: filters files from `rgbz-fast train` "
                        "(--z-guided for z_guided); the first that fits the frame's pattern, "
                        "or a mirror or shift of it, is used, and none fitting is an error "
                        "(default: the shipped ones, Mask1 and Mask2, every Bayer phase)")


def add_raw_options_file(p, note=""):
    """``--raw-options FILE``: how to read each raw file of the input, from a JSON file."""
    p.add_argument("--raw-options", type=path, default=None, metavar="FILE",
                   help="JSON file mapping raw file names (or \"*\", every file) to how to read "
                        "them: phase, black_level, white_level, clip_level, shape, "
                        f"bit_depth_in, downsample{note} (default: none; camera raw files "
                        "need none)")


# --------------------------------------------------------------------------- errors
#: how the command line gives the settings that library errors ask for, where it is not
#: the parameter's own flag (--black-level for black_level)
FLAG_WORDS = {"shape": "--shape ROWSxCOLS", "grey": "--grey",
              "reader": "give the file a camera raw extension",
              "filters": "--filters FILE", "train": "rgbz-fast train"}


def flag(setting):
    """The command line's words for a :class:`rgbz_fast.io.Setting`."""
    return FLAG_WORDS.get(setting.name, "--" + setting.name.replace("_", "-"))


def raw_option_words(setting):
    """The command line's words for a setting asked for in the ``--raw-options`` file: its
    JSON key ("phase"), and the file itself with an example entry."""
    if setting.name == "raw_options":
        name = setting.python.removeprefix("raw_options[").removesuffix("]")
        return f'--raw-options FILE, a JSON file {{{name}: {{"phase": ..., ...}}}}'
    if setting.name == "shape":
        return '"shape": "ROWSxCOLS"'
    return f'"{setting.name}"'


def _flag_of(parser):
    """:func:`flag` for the command of ``parser``: a setting the command has no flag for is
    named as the library's argument, with the command's lack of it (the message had told
    `rgbz-fast hardware` users to pass --grey or --filters, which it does not take)."""
    options = set(parser._option_string_actions)

    def spell(setting):
        words = flag(setting)
        if words.startswith("--") and words.split()[0] not in options:
            return (f"{setting.python} (a library argument: rgbz-fast {parser.prog.split()[-1]}"
                    f" has no {words.split()[0]})")
        return words
    return spell


def explain(exc, parser=None):
    """The message of an error in command-line words: the settings a library error asks for
    are given as flags (pass --phase, not phase=), or as keys of the --raw-options file when
    the error asks for them there; with the command's ``parser``, the ``name=value`` words
    of other library messages become the command's flags (:func:`flag_words`). ``exc`` may
    also be an evaluation's skip reason, which carries the error it came from."""
    from ..io import ParameterError

    error = getattr(exc, "error", None) or exc
    if isinstance(error, ParameterError):
        spell = raw_option_words if "raw_options" in error.settings else flag
        if parser is not None and spell is flag:
            spell = _flag_of(parser)
        text = " ".join(error.render(spell).split())
        return text if parser is None else _leading_flag(text, _options(parser))
    return str(exc) if parser is None else flag_words(str(exc), parser)


def os_error_words(exc, args):
    """A system error about a file ("[Errno 2] No such file or directory: '/proc/x'") as
    ``FLAG: path: reason``: ``--out`` when the file is the output folder or in it, else
    ``path``."""
    path = os.fsdecode(exc.filename)
    flag = "path"
    out = getattr(args, "out", None)
    if out is not None:
        where, target = os.path.abspath(out), os.path.abspath(path)
        if target == where or target.startswith(where.rstrip(os.sep) + os.sep):
            flag = "--out"
    return f"{flag}: {path}: {exc.strerror or exc}"


def _options(parser):
    """{dest: (its long option strings, its action)} of the options of ``parser``."""
    options = {}
    for action in parser._actions:
        longs = [o for o in action.option_strings if o.startswith("--")]
        if longs:
            options[action.dest] = (longs, action)
    return options


def _leading_flag(text, options):
    """The parameter ``text`` starts with written as the command's flag, when the command
    gives it by one ('width: ...' from the library is the command's '--width: ...')."""
    name = text.split(": ", 1)[0]
    return f"{options[name][0][0]}{text[len(name):]}" if name in options else text


def flag_words(text, parser):
    """``text`` with each ``name=value`` whose name is an option of ``parser`` written as
    that option: ``noise=True`` -> ``--noise``, ``linearise=False`` -> ``--no-linearise``,
    ``crop=300`` -> ``--crop 300``, ``filters=`` -> ``--filters``. Other words are left as
    they are (a library message that names a parameter the command does not have)."""
    options = _options(parser)

    def spell(m):
        name, value = m.group(1), m.group(2)
        longs, action = options[name]
        if isinstance(action, argparse.BooleanOptionalAction) and value in ("True", "False"):
            return longs[0] if value == "True" else longs[-1]
        if isinstance(action, argparse._StoreTrueAction) and value in ("True", "False"):
            return longs[0] if value == "True" else f"no {longs[0]}"
        if action.choices and value not in action.choices and value.lower() in action.choices:
            value = value.lower()                # select=None is the command's --select none
        if value == "None" and (action.metavar or "").split("|")[0] == "off":
            value = "off"                        # clip_level=None is --clip-level off
        return f"{longs[0]} {value}" if value else longs[0]

    if not options:
        return text
    names = "|".join(sorted(map(re.escape, options), key=len, reverse=True))
    return _leading_flag(re.sub(rf"(?<![\w.-])({names})=([^\s,;)]*)", spell, text), options)


# --------------------------------------------------------------------------- running
def options_given(parser, argv):
    """(spelling, action) of each option of ``argv`` (a command's arguments, up to ``--``),
    abbreviations resolved as argparse resolves them (a unique prefix)."""
    longs = {o: a for o, a in parser._option_string_actions.items() if o.startswith("--")}
    for token in argv:
        if token == "--":
            break
        if not token.startswith("--"):
            continue
        name = token.split("=", 1)[0]
        action = longs.get(name)
        if action is None:
            hits = {a for o, a in longs.items() if o.startswith(name)}
            action = hits.pop() if len(hits) == 1 else None
        if action is not None:
            yield name, action


def given(args, dest):
    """Whether the command line gave the option of ``dest`` (not: whether its value differs
    from the default, which an explicit default hides)."""
    return given_as(args, dest) is not None


def given_as(args, dest):
    """The option string the command line gave ``dest`` by, in full (``--no-linearise`` for
    ``--no-lin``), or None when it was not given."""
    argv = getattr(args, "command_argv", None)      # set by main()
    for spelling, action in options_given(args.parser, argv or ()):
        if action.dest == dest:
            return next((o for o in action.option_strings if o.startswith(spelling)), spelling)
    return None


def limits_need(args, reading, why):
    """A CliError when a read limit is given but the command reads no file (``reading``
    False): the limits had been accepted and applied to nothing. ``why``: what reads none."""
    for flag, value in (("--max-pixels", args.max_pixels), ("--max-bytes", args.max_bytes)):
        if value is not None and not reading:
            raise CliError(f"{flag}: limits the files the command reads; {why}")


def limits(args):
    """The read limits of the command (``--max-pixels``, ``--max-bytes``), as the keyword
    arguments of the library's readers."""
    return dict(max_pixels=args.max_pixels, max_bytes=args.max_bytes)


def learned_filters(args):
    """The ``--filters`` files, learned or z_guided, read with the command's limits (None:
    the shipped ones). z_guided files had been refused as 'not a rgbz-fast filters file';
    a method that takes no filters is refused with them (they had been ignored)."""
    from ..reconstruction._z_guided import check_any_filters

    if args.filters is None:
        return None
    methods = getattr(args, "methods", None) or [getattr(args, "method", None)]
    wanted = {"learned", "z_guided"} & set(methods)
    if not wanted:
        raise CliError(f"--filters: {', '.join(methods)} takes no filters; they are the "
                       "learned and z_guided methods' (--method learned or z_guided)")
    loaded = check_any_filters(tuple(args.filters), "filters", max_bytes=args.max_bytes)
    from ..reconstruction import LearnedFilters

    kinds = {"learned" if isinstance(f, LearnedFilters) else "z_guided" for f in loaded}
    if not kinds & wanted:                 # the method's shipped filters had run in their place
        raise CliError(f"--filters: {', '.join(map(str, args.filters))} hold "
                       f"{' and '.join(sorted(kinds))} filters; --method "
                       f"{' and '.join(sorted(wanted))} takes its own kind (rgbz-fast train"
                       f"{' --z-guided' if 'z_guided' in wanted else ''})")
    return loaded


def command_line(args):
    """The command as typed: ``rgbz-fast CMD ARGS...`` (recorded in the reports it writes)."""
    return " ".join(["rgbz-fast", *args.argv])


def output_folder(out):
    """``out`` when it can be an output folder (it may not exist yet), else a CliError: it is
    checked before the work, so that a run does not end on a --out it cannot write (a path
    under a file, a read-only or virtual file system) after minutes of measurements."""
    if out is None:
        return out
    if _exists(out, "--out") and not out.is_dir():
        raise CliError(f"--out: {str(out)!r} exists and is not a folder")
    _check_writable_folder(out)
    return out


def _check_writable_folder(out, given=None):
    """The nearest existing folder of ``out`` (``out`` itself, else an ancestor) takes a new
    entry: tried by making and removing a temporary folder there (nothing is left).
    ``given``: the --out the user gave, when ``out`` is the folder of that file."""
    import tempfile

    name = str(out if given is None else given)
    p = Path(out)                   # not normalised: 'link/..' is where the link leads
    while not _exists(p, "--out") and p != p.parent:
        p = p.parent
    if not p.is_dir():
        raise CliError(f"--out: {name!r}: {str(p)!r} is not a folder")
    try:
        os.rmdir(tempfile.mkdtemp(prefix=".rgbz-fast-", dir=p))
    except OSError as exc:
        raise CliError(f"--out: {name!r}: cannot write in {str(p)!r} "
                       f"({exc.strerror or exc})") from None


def output_file(out):
    """``out`` when it can be the one file a command writes, else a CliError: checked before
    the work, as :func:`output_folder` is (its folder, or the nearest that exists, made when
    the file is written, must take a new entry): a fit or a calibration had run to its end,
    then failed on the hidden temporary file of the atomic write ('path: .f.npz.<hex>.tmp')."""
    if _exists(out, "--out") and out.is_dir():
        raise CliError(f"--out: {str(out)!r} is a folder; give the name of the file to write")
    from ..io._files import _existing_kind

    kind = _existing_kind(out)
    if kind is not None:
        raise CliError(f"--out: {str(out)!r} is {kind}, not a regular file; give the name of "
                       "the file to write")
    _check_writable_folder(out.parent, out)
    return out


def _exists(path, flag):
    """``path.exists()``, or a CliError naming ``flag`` when the path cannot even be looked
    up (a name longer than the file system allows, a loop of links)."""
    try:
        return path.exists()
    except OSError as exc:
        raise CliError(f"{flag}: {str(path)[:80]!r}: {exc.strerror or exc}") from None


def _same_file_key(path):
    """What identifies the file at ``path``: its device and inode when it exists (a symbolic
    or hard link to an input is that input), else its absolute path with links resolved."""
    try:
        st = os.stat(path)
        return ("inode", st.st_dev, st.st_ino)
    except OSError:
        return ("path", os.path.realpath(path))


def check_outputs(writes, reads=(), read_dirs=(), flag="--out"):
    """The one input/output collision check of the command line, before anything is written.

    ``writes``: (source, path) of every file the command will write, ``source`` being what
    it comes from; ``reads``: every file it reads (frames, scenes, --filters, --raw-options,
    --calibration, the images of a dataset); ``read_dirs``: (folder, suffixes) of the
    folders whose files of those suffixes it reads (a dataset). A CliError naming ``flag``
    when two sources would write one file, when a file written is a file read (a link to it
    too: it would be overwritten, before it is read if it comes later), or when a file of
    a suffix read is written into a folder that is read (an evaluation would read its
    figures back as images on the next run), or when a file written exists as a device, a
    FIFO or a socket.
    """
    from ..io._files import _existing_kind

    seen = {}
    for src, path in writes:
        size = len(os.fsencode(Path(path).name))
        if size > 255:
            raise CliError(f"{flag}: the output name {Path(path).name[:40]}... (from {src}) is "
                           f"{size} bytes, more than the 255 a file name may have; rename "
                           "the input")
        if os.path.isdir(path):
            raise CliError(f"{flag}: {path} (from {src}) is a folder, where a file is to be "
                           f"written: remove it or choose another {flag}")
        kind = _existing_kind(path)
        if kind is not None:
            raise CliError(f"{flag}: {path} (from {src}) is {kind}, not a regular file; it "
                           f"would be replaced by one: remove it or choose another {flag}")
        key = _same_file_key(path)
        if key in seen and seen[key][0] != src:
            raise CliError(f"{flag}: {seen[key][0]} and {src} would both write {path}; give "
                           f"them different --out folders or rename one")
        seen[key] = (src, path)
    inputs = {_same_file_key(f): f for f in reads if f is not None}
    for src, path in writes:
        hit = inputs.get(_same_file_key(path))
        if hit is not None:
            raise CliError(f"{flag}: writing {path} (from {src}) would overwrite the input "
                           f"{hit}; choose another {flag}")
    for folder, suffixes in read_dirs:
        where = os.path.realpath(folder)
        for src, path in writes:
            if (os.path.realpath(Path(path).parent) == where
                    and Path(path).suffix.lower() in suffixes):
                raise CliError(f"{flag}: {Path(path).name} (from {src}) would be written "
                               f"into {folder}, a folder read as input, and read back from it; "
                               f"choose an {flag} outside it")


def check_report_outputs(out, names, dataset, what="the report", reads=()):
    """``check_outputs`` of the report files ``names`` a command writes into ``out`` (None:
    none) against the files ``reads`` (the images, option files) and the ``dataset`` folder
    (None, or a file: no folder; or a list of them, every folder the command reads images
    from): a figure written into the folder a dataset is read from is read back as an image
    by the next run."""
    if out is None:
        return
    from ..io import IMAGE_SUFFIXES, RAW_SUFFIXES

    datasets = dataset if isinstance(dataset, (list, tuple)) else [dataset]
    folders = [(d, IMAGE_SUFFIXES | RAW_SUFFIXES) for d in datasets
               if d is not None and Path(d).is_dir()]
    check_outputs([(what, Path(out) / n) for n in names], reads, folders)


def unique_outputs(pairs, out, reads=()):
    """``pairs``: (input, output names) in the folder ``out``; :func:`check_outputs` of them
    against each other and against the files ``reads`` (the inputs themselves included). An
    input given twice (a link to it too) is refused: it would be run and written twice."""
    given = {}
    for src, _ in pairs:
        key = _same_file_key(src)
        if key in given:
            same = "" if str(given[key]) == str(src) else f" (as {given[key]})"
            raise CliError(f"{src}: given twice{same}; give each input once")
        given[key] = src
    check_outputs([(src, out / name) for src, names in pairs for name in names],
                  [*(src for src, _ in pairs), *reads])


def file_label(name):
    """A pattern's or a method's name as one field of an output file name.

    Every command names its outputs ``<input>_<pattern>_<method>[_<product>].<ext>``:
    fields joined by ``_``, each lower-case with ``-`` inside it, so a field never splits
    (``bayer_grbg`` -> ``bayer-grbg``, the tile ``ZR/BG`` -> ``zr-bg``, ``SG`` -> ``sg``).
    ``name``: a string or anything with a ``name`` (a Pattern).
    A label longer than :data:`LABEL_MAX` characters (a large custom tile, 32x32 spelled out
    is over a thousand) is cut and ends in a digest of the whole name, so that different
    tiles keep different file names and a name stays within the file system's 255 bytes.
    """
    text = getattr(name, "name", name)
    label = re.sub(r"[^a-z0-9.-]", "-", str(text).strip().lower())
    if len(label) > LABEL_MAX:
        import hashlib

        digest = hashlib.sha1(str(text).encode("utf-8")).hexdigest()[:12]
        label = f"{label[:LABEL_MAX - 13]}-{digest}"
    return label


#: the longest field of an output file name (file_label)
LABEL_MAX = 48


def error_text(exc, args):
    """The message of an error a command stops on, in the command's words: an operating
    system's error on a file in :func:`os_error_words`, any other through :func:`explain`."""
    if isinstance(exc, OSError) and exc.filename is not None and str(exc).startswith("[Errno"):
        return os_error_words(exc, args)
    return explain(exc, args.parser)


def batch(args, inputs, out):
    """Run a command's inputs in turn, telling on a failure what was already written.

    ``with batch(args, inputs, out) as done:`` around the loop, ``done.append(path)`` after
    each input's outputs are written. An input that fails stops the run (its message as
    before), and when others were written before it the message says so: with ``a bad c``
    the outputs of ``a`` stayed in ``out`` and ``c`` never ran, without a word of either."""
    import contextlib

    @contextlib.contextmanager
    def run():
        done = []
        try:
            yield done
        except (CliError, ValueError, TypeError, OSError) as exc:
            if not done:
                raise
            text = error_text(exc, args)
            n, left = len(done), len(inputs) - len(done) - 1
            raise CliError(f"{text.splitlines()[0] if text else type(exc).__name__} ({n} "
                           f"input{'s' * (n > 1)} before it written to {out}, {left} after it "
                           "not run)") from None

    return run()


def must_exist(paths, prefix="path: "):
    """A CliError naming the first path of ``paths`` that does not exist."""
    for f in paths:
        if not _exists(f, prefix.rstrip(": ").rstrip() or "path"):
            raise CliError(f"{prefix}{f} does not exist")


#: zlib level of the PNGs the commands write: a 12 MP sRGB image in 1.3 s at 2, 6.2 s at 6
#: (Pillow's default) for 13 % more bytes (docs/reports/benchmarks.md)
PNG_LEVEL = 2


def png_bytes(image):
    """An image as PNG bytes (zlib level :data:`PNG_LEVEL`), for
    :func:`rgbz_fast.io.atomic_write`."""
    import imageio.v3 as iio

    return iio.imwrite("<bytes>", image, extension=".png", compress_level=PNG_LEVEL)


def tell_earlier_outputs(out, names, written, command):
    """One line on stderr naming the files of ``names`` (what the command may write into
    ``out`` for its inputs, with other options) that ``out`` holds and this run did not
    write (``written``): a rerun with other options had left the previous run's files
    beside the new ones, without a word. Nothing is removed."""
    seen = set(written)
    left = [n for n in dict.fromkeys(names) if n not in seen and os.path.lexists(out / n)]
    if left:
        them = "them" if len(left) > 1 else "it"
        print(f"rgbz-fast {command}: {out} holds {', '.join(left)} from an earlier run; this "
              f"run did not write {them}", file=sys.stderr)


def write_report(out, files):
    """Write ``files`` ({name: text or bytes}) into the folder ``out``, all or none (each to
    a temporary file, renamed when every one is written: a full disk leaves the folder's
    previous files as they were, not one new file beside an old one, H126); nothing when
    ``out`` is None."""
    from ..io._files import atomic_write_all

    if out is not None:
        atomic_write_all([(out / name, data) for name, data in files.items()])


def tool(name):
    """The measuring engine ``rgbz_fast._devtools.<name>``, or a CliError when this build
    lacks what it needs (the counting build of the kernels)."""
    import importlib

    try:
        return importlib.import_module(f"rgbz_fast._devtools.{name}")
    except ImportError as exc:
        raise CliError(f"not available in this build ({exc})") from None
