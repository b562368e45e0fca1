"""The parser of every command, and :func:`main`: parse, run, report errors in one line."""

from __future__ import annotations

import argparse
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
    """SIGTERM, raised in the main thread so that every ``finally`` and cleanup runs."""


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
    """Standard output that a reader closing early (``| head``) does not stop: the first
    write that meets a closed pipe sends the rest to the null device, and the command
    finishes its batch (a closed pipe had ended a batch of frames at the first file, with
    '[Errno 32] Broken pipe')."""

    def __init__(self, stream):
        self._stream = stream

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
        self._stream = open(os.devnull, "w")

    def __getattr__(self, name):
        return getattr(self._stream, name)


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
    signal.signal(signal.SIGTERM, signal.SIG_IGN)      # cleaning up: do not interrupt it
    raise Terminated(128 + signum)


def main(argv=None):
    """Run ``rgbz-fast`` with ``argv`` (default: the process's arguments); the exit status."""
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
    previous = None
    if hasattr(signal, "SIGTERM") and threading.current_thread() is threading.main_thread():
        previous = signal.signal(signal.SIGTERM, _terminate)
    stdout = sys.stdout
    sys.stdout = _ClosedPipeSafe(stdout)
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
        print(f"rgbz-fast {args.command}: terminated", file=sys.stderr)
        return exc.code
    finally:
        sys.stdout = stdout
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)
