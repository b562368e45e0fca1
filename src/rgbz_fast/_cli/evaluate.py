"""``rgbz-fast evaluate``: dataset -> metrics tables, CSV/JSON, figures."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from . import _common as c
from ._raw import raw_options_file

#: rgbz_fast.isp.DEMOSAIC_METHODS, written out so that building the parser imports no kernel
#: (tests/cli holds the two equal)
DEMOSAICS = ("malvar2004", "menon2007", "bilinear")

NAME = "evaluate"
DEFAULT_OUT = "rgbz_results"


def add_parser(sub):
    p = c.command_parser(
        sub, NAME, "dataset -> metrics, tables and plots",
        "Run the paper's Fig. 19 chain (reference Bayer path and RGB-Z path through the same "
        "ISP) on every image x pattern x method and report CFA PSNR, CPSNR, SSIM, MS-SSIM and "
        "the zipper metric. With no --dataset it runs on five colour images shipped with "
        "scikit-image (offline).")
    c.add_dataset(p, "folder of RGB images (Kodak, McMaster, your own) or of raw files, or one "
                     "file (default: the scikit-image samples)")
    c.add_patterns(p)
    c.add_methods(p, "bilinear,bi,edi_central,edi_line,sg")
    p.add_argument("--metrics", type=c.csv, default="cfa_psnr,cpsnr,ssim,ms_ssim,zipper",
                   help="comma-separated metrics")
    p.add_argument("--noise", action=argparse.BooleanOptionalAction, default=False,
                   help="use the sensor noise model (default: noise-free mosaics)")
    c.add_seed(p, None, "with --noise: the noise seed of every image's frames, EvalConfig's "
                        "seed (default: 0)")
    p.add_argument("--demosaic", default="malvar2004", choices=DEMOSAICS,
                   help="Bayer demosaic of both paths")
    p.add_argument("--crop", type=c.non_negative_int, default=8,
                   help="border (pixels) left out of the image metrics")
    c.add_reconstruction_options(p, "float64", "arithmetic of the reconstruction")
    c.add_bit_depth(p, 11, "bits of the simulated frames")
    c.add_linearise(p, "mosaics")
    c.add_raw_options_file(p)
    c.add_limit(p)
    c.add_grey(p)
    p.add_argument("--skip-bad", action="store_true",
                   help="skip the images that cannot be evaluated, and list them (default: the "
                        "first one stops the run)")
    p.add_argument("--optics", action="store_true",
                   help="blur the images through the lens model before sampling them "
                        "(default: off, the pixels are the image's)")
    p.add_argument("--f-number", type=c.positive_float, default=2.8,
                   help="f-number of the lens, with --optics")
    p.add_argument("--olpf", type=c.non_negative_float, default=0.0,
                   help="optical low-pass filter spot separation in pixel pitches, with --optics "
                        "(0: none; 1: zeros at Nyquist)")
    p.add_argument("--defocus-um", type=c.non_negative_float, default=0.0,
                   help="blur-disk diameter in micrometres, with --optics (0: in focus)")
    p.add_argument("--zoom", type=zoom, default=None, metavar="ROW,COL[,SIZE]",
                   help="the region the crop figure enlarges: its top-left pixel and its size "
                        "(default: chosen where the methods' errors show, on structure, never "
                        "a dark or flat area; size 64)")
    p.add_argument("--table-image", default=None,
                   help="image of the per-image table (default: kodim09 when present, else the "
                        "first)")
    p.add_argument("--processes", type=c.positive_int, default=None, metavar="N",
                   help="spawned worker processes, one image each (default: none; threads "
                        "of this process take one image each, as many as cores; 1: one "
                        "image at a time)")
    p.add_argument("--scheduler", default=None,
                   help="Dask scheduler address, tcp://host:port (default: the local pool)")
    p.add_argument("--cache", type=c.path, default=None, metavar="DIR",
                   help="cache folder, from which an interrupted run resumes (default: OUT/cache)")
    p.add_argument("--no-cache", action="store_true", help="neither read nor write the cache")
    p.add_argument("--no-plots", action="store_true", help="tables only, no figures")
    c.add_json(p, "print the summary as JSON")
    # its own default: the images run side by side, one thread each, unless one at a time
    c.add_run_options(p, DEFAULT_OUT,
                      workers="1 while images run side by side, as by default and with "
                              "--processes N or --scheduler; all cores one image at a time: "
                              "--processes 1, or one image")
    return p


def _check_reports(args, config, dataset, out):
    """The files the reports may write, checked against the inputs before anything is run:
    no report over an image, --filters or --raw-options file, no figure in the dataset's
    folder, where the next run would evaluate it as an image, and no reports.txt of the
    user's in --out (its lines had been taken as reports to delete, and it was replaced)."""
    from ..evaluation._cache import _safe
    from ..evaluation._reports import MANIFEST, check_reports_folder

    if out is not None:
        try:
            check_reports_folder(out, "--out")
        except ValueError as exc:
            raise c.CliError(str(exc)) from None
    names = [MANIFEST, "results.csv", "results.json", "summary.md"]
    names += [f"{kind}_{k}.png" for k in config.metrics for kind in ("bars", "paired")]
    names += [f"{kind}_{_safe(s.name)}{ext}" for s in dataset
              for kind, ext in (("table", ".md"), ("crops", ".png"))]
    reads = [Path(s.location) for s in dataset if not s.location.startswith("skimage:")]
    reads += [*(args.filters or ()), args.raw_options]
    c.check_report_outputs(out, names, args.dataset, "the reports", reads)


def _check_dataset_options(args, dataset):
    """Options that would not apply are refused before anything runs (they had been ignored
    and still written into the report's header): the raw options without a raw file, the
    simulation's options on a dataset of raw files, --zoom without the crop figure (with
    --no-plots, or with no image metric); and a
    --table-image given by its file name is the image of that name."""
    from ..evaluation import IMAGE_METRICS

    raw = [s for s in dataset if s.is_raw]
    if args.raw_options is not None and not raw:
        raise c.CliError("--raw-options: the dataset holds no raw file; the options apply to "
                         "raw files")
    if raw and len(raw) == len(dataset):
        given = [flag for flag, on in (("--noise", args.noise), ("--optics", args.optics),
                                       ("--bit-depth", args.bit_depth != 11),
                                       ("--no-linearise", not args.linearise),
                                       ("--grey", args.grey)) if on]
        if given:
            raise c.CliError(f"{given[0]}: applies to the RGB images the evaluation mosaics; "
                             "the dataset's raw files are measured as they are (their own "
                             "bit depth, noise and lens)")
    if args.zoom is not None and args.no_plots:
        raise c.CliError("--zoom: places the crop figure, which --no-plots leaves out")
    if args.zoom is not None and not set(args.metrics) & set(IMAGE_METRICS):
        raise c.CliError(f"--zoom: places the crop figure, which is made for the image "
                         f"metrics ({', '.join(IMAGE_METRICS)}); --metrics "
                         f"{','.join(args.metrics)} leaves it out")
    if args.table_image is not None:
        names = [s.name for s in dataset]
        if args.table_image not in names and Path(args.table_image).stem in names:
            args.table_image = Path(args.table_image).stem
        if args.table_image not in names:
            raise c.CliError(f"--table-image: {args.table_image!r} is not an image of the "
                             f"dataset ({', '.join(names[:8])}{', ...' if len(names) > 8 else ''})")


def zoom(text):
    """ROW,COL[,SIZE]: the crop figure's region (SIZE 64 when not given)."""
    import argparse

    try:
        vals = [int(v) for v in text.split(",")]
    except ValueError:
        vals = []
    if len(vals) not in (2, 3) or min(vals) < 0 or (len(vals) == 3 and vals[2] < 1):
        raise argparse.ArgumentTypeError(f"expected ROW,COL or ROW,COL,SIZE (integers >= 0, "
                                         f"SIZE >= 1), got {text!r}")
    return (*vals, 64)[:3]


def _keep_freed_memory():
    """glibc's malloc keeps the memory this process frees for its next arrays instead of
    handing it back to the system and faulting it in again, zeroed, at the next allocation
    (every image allocates and frees the same frame-size arrays: 5 % of the command's CPU
    went to those page faults). A process setting, made by the command that owns the
    process; elsewhere than glibc nothing changes."""
    import ctypes

    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError, TypeError):   # pragma: no cover - not glibc
        return
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    m_trim_threshold, m_mmap_threshold = -1, -3
    mallopt(m_mmap_threshold, 32 << 20)        # glibc's largest: arrays up to 32 MiB reused
    mallopt(m_trim_threshold, 1 << 30)


def run(args):
    from ..evaluation import EvalConfig, evaluate, write_reports
    from ..io import folder_dataset, sample_dataset
    from ..reconstruction import ReconstructParams
    from ..simulation import Optics

    # options that would be ignored (pattern-study refuses the first pair as well)
    if args.no_cache and args.cache is not None:
        raise c.CliError("--cache: names the cache that --no-cache turns off; give one of them")
    if args.processes is not None and args.scheduler is not None:
        raise c.CliError("--processes: starts local worker processes, which --scheduler "
                         "replaces by the Dask scheduler's workers; give one of --processes "
                         "and --scheduler")
    params = ReconstructParams(precision=args.precision, domain=args.domain,
                               clip_level=args.clip_level, filters=c.learned_filters(args))
    optics = None
    if args.optics:
        try:
            optics = Optics(f_number=args.f_number, olpf=args.olpf, defocus_um=args.defocus_um)
        except ValueError as exc:       # 'Optics.f_number: ...' is the command's --f-number
            raise c.CliError(c.flag_words(str(exc).removeprefix("Optics."), args.parser)) \
                from None
    elif (args.f_number, args.olpf, args.defocus_um) != (2.8, 0.0, 0.0):
        raise c.CliError("--f-number, --olpf and --defocus-um need --optics")
    if args.seed is not None and not args.noise:
        # a noise-free run draws nothing (the API's EvalConfig(seed=) had no flag: the command
        # could reproduce seed 0 only)
        raise c.CliError("--seed: applies with --noise (a noise-free run draws nothing)")
    config = EvalConfig(patterns=args.patterns, methods=args.methods, metrics=args.metrics,
                        noise=args.noise, seed=0 if args.seed is None else args.seed,
                        bit_depth=args.bit_depth, linearise=args.linearise,
                        demosaic=args.demosaic, crop=args.crop, params=params, optics=optics)
    out = c.output_folder(args.out)
    raw_options = None
    if args.raw_options is not None:
        raw_options = raw_options_file(args.raw_options)
    if args.dataset:
        dataset = folder_dataset(args.dataset, args.limit, raw_options, grey=args.grey,
                                 **c.limits(args))
    else:
        dataset = sample_dataset()[:args.limit]
    _check_dataset_options(args, dataset)
    _check_reports(args, config, dataset, out)
    cache = None if args.no_cache else (args.cache or out / "cache")
    _keep_freed_memory()
    res = evaluate(dataset, config, cache_dir=cache, processes=args.processes,
                   workers=args.workers, scheduler=args.scheduler, progress=c.bars(args),
                   skip_bad=args.skip_bad)
    for name, why in res.skipped:
        print(f"rgbz-fast evaluate: skipped {name}: {c.explain(why, args.parser)}",
              file=sys.stderr)
    if not res.rows:
        raise c.CliError(f"dataset: none of the {len(dataset)} image(s) could be evaluated")
    crop_src = None
    if not args.no_plots and config.image_metrics:
        done = [s for s in dataset if s.name in res.images()]
        crop_src = next((s for s in done if s.name == (args.table_image or "kodim09")), done[0])
    box = None if args.zoom is None else (*args.zoom[:2], args.zoom[2], args.zoom[2])
    try:
        files = write_reports(res, out, table_image=args.table_image, crop_source=crop_src,
                              crop_box=box, plots=not args.no_plots)
    except ValueError as exc:
        if str(exc).startswith("crop_box: "):
            raise c.CliError(f"--zoom: {str(exc).removeprefix('crop_box: ')} of "
                             f"{crop_src.name}") from None
        raise
    if args.json:                  # valid JSON: a non-finite mean is the string "inf" or "nan"
        print(json.dumps(res.summary_dict(), indent=1, allow_nan=False))
    else:
        print(res.plain_table())
        if not args.quiet:             # status, as the progress: `> table.txt` keeps the table
            print(f"reports: {', '.join(str(f) for f in files)}", file=sys.stderr)
    return 0
