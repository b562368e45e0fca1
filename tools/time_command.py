"""Time a whole command from outside: wall, CPU (user + system) and peak memory, medians.

    python tools/time_command.py [-n RUNS] [--warmup W] [--vs "COMMAND_B"] -- COMMAND [ARG ...]

COMMAND runs RUNS times (default 5) after W uncounted warm-up runs (default 1); each run's
user and system seconds and peak resident memory are the operating system's accounting of
the finished child (``os.wait4``), the wall seconds a monotonic clock around it. With
``--vs`` a second command B runs in turn with A (A B A B ...) and the ratios A / B are taken
pair by pair, so that a drift of the machine's speed during the call moves both sides.
Printed: min, median and max of every figure; quote the median. The commands' output is
discarded. The peak cannot read below this script's own resident size (the child
is forked from it before it runs the command). Nothing here is specific to rgbz-fast.
"""

import argparse
import os
import shlex
import statistics
import subprocess
import sys
import time


def run_once(cmd):
    """(wall s, cpu s, peak MiB, exit status) of one run of ``cmd`` (a list of words)."""
    t0 = time.monotonic()
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(proc.pid, 0)
    wall = time.monotonic() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    return wall, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0, proc.returncode


def spread(values, fmt):
    return " / ".join(fmt.format(v) for v in (min(values), statistics.median(values), max(values)))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-n", "--runs", type=int, default=5)
    parser.add_argument("--warmup", type=int, default=1)
    parser.add_argument("--vs", default=None, help="a second command, one string split as a shell does")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args(argv)
    cmd = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not cmd:
        parser.error("command: give the command to time after --")
    if args.runs < 1 or args.warmup < 0:
        parser.error(f"--runs must be >= 1 and --warmup >= 0, got {args.runs} and {args.warmup}")
    cmds = {"A": cmd}
    if args.vs:
        cmds["B"] = shlex.split(args.vs)
    for _ in range(args.warmup):
        for c in cmds.values():
            run_once(c)
    runs = {k: [] for k in cmds}
    for _ in range(args.runs):
        for k, c in cmds.items():
            runs[k].append(run_once(c))
    print(f"{os.cpu_count()} cores, {args.runs} runs each after {args.warmup} warm-up; "
          "min / median / max")
    for k, rs in runs.items():
        codes = sorted({r[3] for r in rs})
        print(f"{k}: wall {spread([r[0] for r in rs], '{:.2f}')} s, "
              f"cpu {spread([r[1] for r in rs], '{:.2f}')} s, "
              f"peak {spread([r[2] for r in rs], '{:.1f}')} MiB, exit {codes}")
    if "B" in runs:
        for i, name in ((0, "wall"), (1, "cpu")):
            ratios = [a[i] / b[i] for a, b in zip(runs["A"], runs["B"]) if b[i] > 0]
            print(f"A/B {name}: {spread(ratios, '{:.3f}')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
