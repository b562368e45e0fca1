"""The parser of every command, and :func:`main`: parse, run, report errors in one line."""

from __future__ import annotations

import argparse
import signal
import sys
import threading

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
    args.argv = argv
    previous = None
    if hasattr(signal, "SIGTERM") and threading.current_thread() is threading.main_thread():
        previous = signal.signal(signal.SIGTERM, _terminate)
    try:
        return int(args.run(args) or 0)
    except (_common.CliError, ValueError, TypeError, OSError, ImportError) as exc:
        text = _common.os_error_words(exc, args) if isinstance(exc, OSError) \
            and exc.filename is not None and str(exc).startswith("[Errno") \
            else _common.explain(exc, args.parser)
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
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)
