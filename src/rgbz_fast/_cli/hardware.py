"""``rgbz-fast hardware``: the fixed-point model's silicon, its error against float64, the sweep."""

from __future__ import annotations

import argparse
from pathlib import Path

from . import _common as c

NAME = "hardware"
DESCRIPTION = """\
The fixed-point streaming model of one method on one pattern (precision='fixed').

It reports the silicon -- line buffers (count x width x bits, BRAM_18K at 18
Kbit a block), window registers, latency in rows and pixels, pixels per clock,
multipliers by width, adders, comparators, table bits, every register's
declared width -- and the error against float64 on a dataset: the change of
the mean CFA PSNR and the histogram of the differences (LSB) at the Z sites,
under evaluate's default protocol (sRGB linearised, noise-free 11-bit mosaics)
and on the 8-bit sRGB values mosaicked at 11 bits; and the fixed model's
operations per pixel beside the paper's Table 1 and the float core's.

--sweep varies every width and table size around the configuration and gives
quality against cost (a table, its Pareto front, and with --out a plot).
--workers threads run the frames of the error, and the sweep's configurations,
side by side (the model streams each frame on one thread); the report does
not depend on it."""

#: the methods the fixed-point model runs
METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "learned")


def fixed_fields(text):
    """--fixed-point: 'field=value,...' -> {field: int or str} (FixedPointConfig checks them)."""
    out = {}
    for item in c.csv(text):
        key, sep, value = item.partition("=")
        if not sep or not key.strip() or not value.strip():
            raise argparse.ArgumentTypeError(f"expected FIELD=VALUE pairs, got {item!r}")
        key, value = key.strip(), value.strip()
        if key in out:                          # the last one had won, silently
            raise argparse.ArgumentTypeError(f"{key!r} is given twice in {text!r}; give each "
                                              "field once")
        out[key] = int(value) if value.lstrip("-").isdigit() else value
    return out


def add_parser(sub):
    p = c.command_parser(sub, NAME, "the fixed-point model: silicon cost, error against float64",
                         DESCRIPTION)
    p.add_argument("--method", default="sg", choices=METHODS, help="reconstruction method")
    c.add_pattern(p, "mask1", "RGB-Z pattern: mask1, mask2, rows, or a tile such as ZR/BG")
    p.add_argument("--width", type=c.positive_int, default=4000, metavar="PIXELS",
                   help="pixels per row: the depth of a line buffer")
    c.add_dataset(p, "folder of RGB images for the error (default: the five scikit-image "
                     "samples evaluate uses with no --dataset)")
    c.add_limit(p)
    p.add_argument("--sweep", action="store_true",
                   help="also vary every width and table size around the configuration: a "
                        "table of quality against cost (and hardware_sweep.png with --out)")
    p.add_argument("--fixed-point", type=fixed_fields, default=None, metavar="FIELD=VALUE,...",
                   help="the configuration to report, as fields of FixedPointConfig (default: "
                        "its defaults), e.g. exp_bits=12,recip=table")
    c.add_json(p, "print JSON instead of Markdown")
    c.add_output_folder(p, None, "also write hardware.md, hardware.json and, with --sweep, "
                                 "hardware_sweep.png into DIR (default: print only)")
    c.add_quiet(p, "no progress bar")
    c.add_limits(p)
    c.add_workers(p, "threads running the frames and the sweep's configurations side by side",
                  "all cores")
    return p


def run(args):
    from .._devtools import hardware as hw
    from .._devtools._common import json_text, progress
    from .._patterns import get_pattern
    from ..hardware import FixedPointConfig
    from ..reconstruction._fixed_config import check_fields_used

    out = c.output_folder(args.out)
    c.check_report_outputs(out, ["hardware.md", "hardware.json"]
                           + (["hardware_sweep.png"] if args.sweep else []), args.dataset)
    try:
        config = FixedPointConfig.build(args.fixed_point)
    except (TypeError, ValueError) as exc:
        raise c.CliError(f"--fixed-point: {exc}") from None
    try:                         # it would be recorded in hardware.json and change nothing
        check_fields_used(args.method, args.fixed_point or {}, "--fixed-point")
    except ValueError as exc:
        raise c.CliError(str(exc)) from None
    if args.sweep and args.method == "bilinear":
        raise c.CliError("--sweep: bilinear is exact, with no width to move")
    c.limits_need(args, args.dataset is not None,
                  "without --dataset it reads none (scikit-image's samples)")
    c.z_patterns([args.pattern], "--pattern")
    pattern = get_pattern(args.pattern)
    images = hw.load_images(args.dataset, args.limit, **c.limits(args))
    report = hw.hardware_report(args.method, pattern, width=args.width, images=images,
                                config=config, workers=args.workers)
    text = hw.format_report(report) + "\n"
    files = {}
    if args.sweep:
        from .._devtools.plots import hardware_sweep_plot

        configs = hw.sweep_configs(config, args.method)
        ticks = iter(progress(range(len(configs)), total=len(configs), desc="sweep",
                              quiet=not c.bars(args)))
        rows = hw.run_sweep(args.method, pattern, width=args.width, images=images, base=config,
                            configs=configs, tick=lambda: next(ticks, None),
                            workers=args.workers)
        report["sweep"] = rows
        text += "\n## Sweep\n\n" + hw.format_sweep(rows) + "\n"
        if out is not None:
            files["hardware_sweep.png"] = hardware_sweep_plot(
                rows, f"{args.method} on {pattern.name}",
                dataset=Path(args.dataset).resolve().name if args.dataset is not None
                else "scikit-image's samples")
    report["command"] = c.command_line(args)
    doc = json_text(report) + "\n"
    files.update({"hardware.md": text, "hardware.json": doc})
    print(doc if args.json else text, end="")     # before the files: kept if a write fails
    c.write_report(out, files)
    if out is not None and not args.quiet:   # hardware_sweep.png of a run with --sweep
        c.tell_earlier_outputs(out, REPORTS, files, NAME)
    return 0


#: every file hardware may write into --out (hardware_sweep.png with --sweep)
REPORTS = ("hardware.md", "hardware.json", "hardware_sweep.png")
