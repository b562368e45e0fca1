"""The parser of every command, and :func:`main`: parse, run, report errors in one line."""

from __future__ import annotations

import argparse
import contextlib
import os
import signal
import sys
import threading
import warnings

from .._build_config import VERSION
from . import (_common, bench, calibrate, config, depth, evaluate, evaluate_depth, hardware,
               opcount, pattern_study, reconstruct, simulate, tradeoff, train)

__all__ = ["main", "build_parser", "COMMANDS", "Terminated"]

#: the commands, in the order of ``rgbz-fast --help``
COMMANDS = (simulate, reconstruct, depth, evaluate, train, calibrate, evaluate_depth, bench,
            opcount, tradeoff, pattern_study, hardware, config)


class Terminated(SystemExit):
    """SIGTERM (or SIGHUP, the terminal closed), raised in the main thread so that every
    ``finally`` and cleanup runs."""


def build_parser():
    """``rgbz-fast``'s parser: one subparser per module of :data:`COMMANDS`."""
    ap = argparse.ArgumentParser(
        prog="rgbz-fast",
        description="Simulate a monolithic RGB-Z CMOS imager and reconstruct its images "
                    "(missing colour at the Z sites, ISP, depth).",
        epilog=_common.EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--version", action="version", version=f"rgbz-fast {VERSION}")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    for command in COMMANDS:
        p = command.add_parser(sub)
        p.set_defaults(run=command.run, parser=p)
    return ap


class _ClosedPipeSafe:
    """Standard output or error that a reader closing early (``| head``, ``2>&1 | head -1``)
    does not stop: the first write that meets a closed pipe sends the rest to the null
    device, and the command finishes its batch (a closed pipe had ended a batch of frames at
    the first file, with '[Errno 32] Broken pipe'; on stderr, a warning or a 'skipped' line
    had been taken for the command's error, after the whole evaluation, and no report was
    written)."""

    def __init__(self, stream):
        self._stream = stream
        self._null = None

    def write(self, text):
        try:
            return self._stream.write(text)
        except BrokenPipeError:
            self._to_null()
            return len(text)

    def flush(self):
        try:
            self._stream.flush()
        except BrokenPipeError:
            self._to_null()

    def _to_null(self):
        try:                           # the interpreter's last flush must not meet it again
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, self._stream.fileno())
            os.close(null)
        except (OSError, ValueError, AttributeError):
            pass                       # not a file descriptor (a test's capture): drop only
        if self._null is None:
            self._null = open(os.devnull, "w")
        self._stream = self._null

    def close_null(self):
        """Close the null device the lines went to, if they did (after the command)."""
        if self._null is not None:
            self._null.close()

    def __getattr__(self, name):
        return getattr(self._stream, name)


def _writable(stream, undo):
    """``stream`` ready for the command's lines; what to put back after it goes on ``undo``.

    A closed descriptor (``>&-``, ``2>&-``; Python sets the stream to None) becomes the null
    device: every print had died with "'NoneType' object has no attribute 'write'", ending a
    batch at its first file. A stream that refuses the characters its encoding lacks (an
    ASCII or Latin-1 console, PYTHONIOENCODING=ascii) writes them as backslash escapes, as
    Python's own stderr does: the plus-minus sign of evaluate's table, opcount's beta, a
    scene's accented file name had stopped the command after its work ("'ascii' codec can't
    encode character"), exit 2. The encoding is kept."""
    if stream is None:
        sink = open(os.devnull, "w")
        undo.append(sink.close)
        return sink
    if getattr(stream, "errors", None) == "strict" and hasattr(stream, "reconfigure"):
        try:
            stream.reconfigure(errors="backslashreplace")
        except (OSError, ValueError, AttributeError):
            return stream                       # not a text stream that can change
        undo.append(lambda: stream.reconfigure(errors="strict"))
    return stream


@contextlib.contextmanager
def _command_streams():
    """sys.stdout and sys.stderr for the time of a command: a closed descriptor, a reader
    gone and a narrow encoding cost the lines they cannot take, never the run (see
    :class:`_ClosedPipeSafe`, :func:`_writable`); both put back as they were after it."""
    saved = sys.stdout, sys.stderr
    undo = []
    out, err = (_ClosedPipeSafe(_writable(s, undo)) for s in saved)
    sys.stdout, sys.stderr = out, err
    try:
        yield
    finally:
        for stream in (out, err):
            try:                       # what is still buffered meets a closed pipe here, not
                stream.flush()         # in the interpreter's last flush (exit status 120)
            except (OSError, ValueError):
                pass
            stream.close_null()
        sys.stdout, sys.stderr = saved
        for step in reversed(undo):
            try:
                step()
            except (OSError, ValueError):
                pass


def _one_line_warnings(command):
    """``warnings.showwarning`` for the command line: ``rgbz-fast CMD: warning: ...``, one
    line, without the source file and line Python prints (they name the library's code,
    not what the user gave)."""
    def show(message, category, filename, lineno, file=None, line=None):
        text = " ".join(str(message).split())
        print(f"rgbz-fast {command}: warning: {text}", file=sys.stderr if file is None else file)
    return show


def _given_twice(parser, argv):
    """The first option of ``argv`` (a command's arguments) given twice where only the last
    would apply (argparse lets it win, silently; ``--noise`` and ``--no-noise`` are one
    option), with the spellings used, or None. A flag that takes no value repeated as it is
    (``--quiet --quiet``) means the same twice and passes; appending options pass."""
    seen = {}
    for name, action in _common.options_given(parser, argv):
        if isinstance(action, (argparse._AppendAction, argparse._HelpAction,
                               argparse._CountAction)):
            continue
        if action in seen:
            if seen[action] == name and action.nargs == 0:
                continue
            return seen[action] if seen[action] == name else f"{seen[action]}, {name}"
        seen[action] = name
    return None


def _terminate(signum, frame):
    for sig in _stop_signals():                        # cleaning up: do not interrupt it
        signal.signal(sig, signal.SIG_IGN)
    raise Terminated(128 + signum)


def _stop_signals():
    """SIGTERM, and SIGHUP (a closed terminal had ended a run without its cleanup: its
    temporary files left) unless the command was started with it ignored (``nohup``)."""
    sigs = [signal.SIGTERM] if hasattr(signal, "SIGTERM") else []
    if hasattr(signal, "SIGHUP") and signal.getsignal(signal.SIGHUP) in (signal.SIG_DFL,
                                                                         _terminate):
        sigs.append(signal.SIGHUP)
    return sigs


def main(argv=None):
    """Run ``rgbz-fast`` with ``argv`` (default: the process's arguments); the exit status."""
    with _command_streams():           # the usage and help lines too
        return _main(argv)


def _main(argv):
    argv = list(sys.argv[1:] if argv is None else argv)
    ap = build_parser()
    args, extra = ap.parse_known_args(argv)
    if args.command is None:
        if extra:
            ap.error(f"unrecognized arguments: {' '.join(extra)}")
        ap.print_help()
        return 0
    if extra:                      # the command's own usage, and its name on the error line
        args.parser.error(f"unrecognized arguments: {' '.join(extra)}")
    args.command_argv = argv[argv.index(args.command) + 1:]
    twice = _given_twice(args.parser, args.command_argv)
    if twice:
        args.parser.error(f"{twice}: given twice (only the last would apply)")
    args.argv = argv
    previous = {}
    if threading.current_thread() is threading.main_thread():
        previous = {sig: signal.signal(sig, _terminate) for sig in _stop_signals()}
    try:
        with warnings.catch_warnings():
            warnings.showwarning = _one_line_warnings(args.command)
            return int(args.run(args) or 0)
    except (_common.CliError, ValueError, TypeError, OSError, ImportError) as exc:
        text = _common.error_text(exc, args)
        print(f"rgbz-fast {args.command}: error: "
              f"{text.splitlines()[0] if text else type(exc).__name__}", file=sys.stderr)
        return 2
    except MemoryError as exc:              # a size no check foresaw: one line, not a traceback
        print(f"rgbz-fast {args.command}: error: out of memory ({exc or 'no detail'}); try a "
              "smaller input or --max-pixels", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"rgbz-fast {args.command}: interrupted", file=sys.stderr)
        return 130
    except Terminated as exc:
        hangup = hasattr(signal, "SIGHUP") and exc.code == 128 + signal.SIGHUP
        print(f"rgbz-fast {args.command}: terminated{' (hangup)' if hangup else ''}",
              file=sys.stderr)
        return exc.code
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
