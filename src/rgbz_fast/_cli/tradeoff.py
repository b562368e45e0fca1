"""``rgbz-fast tradeoff``: speed against accuracy of every method, Pareto plot."""

from __future__ import annotations

from pathlib import Path

from . import _common as c

NAME = "tradeoff"
DESCRIPTION = """\
Speed against accuracy of every method, precision, exponential and domain.

For every reconstruction method x pattern (Mask1, Mask2) x precision (float32,
float64) x exponential (the C library's exp, and the fast polynomial exp for
the methods that use one) -- plus the colour-difference domain of the weighted
methods (float64 with libm, float32 with the fast exp) and the learned filters
(no exponential) -- it measures

* the speed: frame Mpix/s of reconstruct on one frame (the benchmark scene of
  rgbz-fast bench, 1536x2048), all threads, the best of N runs interleaved
  across the variants (robust to bursts of load from other processes on a
  shared machine; the median and IQR are reported too);
* the accuracy on a set of images (Kodak with --dataset ../shared/data/kodak;
  by default scikit-image's sample images, so that it runs offline), with the
  frames and the colour chain of rgbz-fast evaluate: 8-bit sRGB linearised
  with the sRGB EOTF, noise-free mosaics at 11 bits, mean CFA PSNR on every
  reconstructed (Z) site (eqs. 20-21), and mean CPSNR of the 8-bit sRGB images
  (grey-world white balance estimated on the reference, Malvar 2004, sRGB
  gamma, 8-pixel border left out);
* what the approximations change: for float32 and/or the fast exp, the largest
  difference (DN) and the share of Z pixels that differ from the float64 +
  libm output of the same method.

It draws the Pareto plot and writes the table (Markdown) with a paragraph,
computed from the numbers, on what each approximation costs.

--quick is a smoke test (two 128x128 crops, a 192x256 speed frame, two runs):
its speeds are printed, labelled "quick run: numbers not comparable, no
verdict", but no speed ratio between variants is summarised and no Pareto
front is drawn from them."""

METHODS = "bilinear,bi,edi_central,edi_line,sg,learned"


def add_parser(sub):
    p = c.command_parser(sub, NAME, "speed vs accuracy, Pareto plot", DESCRIPTION)
    c.add_dataset(p, "folder of images (e.g. ../shared/data/kodak) (default: scikit-image "
                     "sample images)")
    c.add_limit(p)
    c.add_repeat(p, "timed runs (default 5, --quick 2)")
    c.add_methods(p, METHODS)
    c.add_patterns(p)
    c.add_report_options(p)
    return p


def run(args):
    from .._devtools import tradeoff
    from .._devtools._common import json_text
    from .._devtools.plots import tradeoff_plot
    from ..io import folder_dataset, sample_dataset

    out = c.output_folder(args.out)
    known = tradeoff.METHODS + tradeoff.OPTIONAL_METHODS
    bad = [m for m in args.methods if m not in known]
    if bad:
        from ..reconstruction import METHODS

        what = f"{', '.join(bad)} not measured by tradeoff" if all(m in METHODS for m in bad) \
            else f"unknown {', '.join(bad)}"
        raise c.CliError(f"--methods: {what}; expected some of {', '.join(known)}")
    if args.dataset:
        images = folder_dataset(args.dataset, args.limit)
        name = args.dataset.name
        c.check_report_outputs(out, ["tradeoff.png", "tradeoff.md", "tradeoff.json"],
                               args.dataset, reads=[Path(s.location) for s in images])
    else:
        images = sample_dataset()[:args.limit]
        name = "scikit-image samples"
    if args.quick:
        raw = [s.name for s in images[:2] if s.is_raw]
        if raw:       # a raw frame is not an image array to crop: an internal error had shown
            raise c.CliError(f"--quick: crops the dataset's first two images to 128 x 128, "
                             f"and {raw[0]} is a raw file, measured whole; run without "
                             "--quick, or on RGB images")
        images = [tradeoff.Crop(src, 128) for src in images[:2]]
    res = tradeoff.run_tradeoff(
        images, methods=args.methods, patterns=args.patterns,
        speed_shape=tradeoff.QUICK_SPEED_SHAPE if args.quick else tradeoff.SPEED_SHAPE,
        repeat=args.repeat or (2 if args.quick else 5), workers=args.workers,
        quiet=not c.bars(args), dataset_name=name, quick=args.quick)
    res["command"] = c.command_line(args)
    if out is not None:
        c.write_report(out, {
            "tradeoff.png": tradeoff_plot(res),
            "tradeoff.md": tradeoff.format_markdown(res, "tradeoff.png", res["command"]) + "\n",
            "tradeoff.json": json_text(res) + "\n"})
    print(json_text(res) if args.json else tradeoff.format_text(res))
    return 0
