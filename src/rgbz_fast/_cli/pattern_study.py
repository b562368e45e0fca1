"""``rgbz-fast pattern-study``: RGB-Z layouts ranked by colour loss, depth noise and cost."""

from __future__ import annotations

from . import _common as c

NAME = "pattern-study"
DEFAULT_OUT = "pattern_study"
DESCRIPTION = """\
Rank candidate RGB-Z layouts by colour loss, depth quality and cost, in one table.

Candidates: presets (--presets), tiles (--tiles "ZRGR/BGBG/GRZR/BGBG,..."), and
generated families (--generate "block=1,2 period=4,8 arrangement=aligned,staggered
density=0.02:0.3"). Layouts that are the same under shifts by whole Bayer periods
and the flips/transposes that keep the Bayer phase are run once (the table names
the others). Every tile is checked before any work starts.

Per layout: CFA PSNR, CPSNR and zipper of every method that applies (rgbz-fast
evaluate's chain on --dataset; 'learned' fitted for the layout on --train and
cached), operations per pixel from the counting build, the Z fill factor and
measurements per megapixel, the colour-guided ToF ISP's depth noise on a flat wall,
and with --rgbd the valid share and error on the RGB-D scenes.

Writes pattern_study.csv/.md/.json and the Pareto plot pattern_study.png into --out;
progress on stderr; every finished task is cached (--cache), so a re-run or an
interrupted run resumes. The default run (two presets, the scikit-image samples,
no training set, no RGB-D scenes) takes seconds."""


#: the smallest side of an RGB-D crop of the study
RGBD_MIN = 32


def _size_or_full(text):
    if text.strip().lower() == "full":
        return None
    return c.shape(text)


def add_parser(sub):
    p = c.command_parser(sub, NAME, "rank RGB-Z layouts: colour, depth, cost", DESCRIPTION)
    c.add_dataset(p, "colour images (e.g. ../shared/data/kodak) (default: scikit-image "
                     "sample images, offline)")
    c.add_limit(p)
    p.add_argument("--presets", type=c.csv_or_none, default="mask1,mask2",
                   help="comma-separated presets: mask1, mask2, rows (none: '')")
    p.add_argument("--tiles", type=c.csv_or_none, default=(),
                   help="comma-separated tiles, rows separated by / (default: none)")
    p.add_argument("--generate", default=None, metavar="SPEC",
                   help="generated family: block=1,2 period=4,8 (or RxC) "
                        "arrangement=aligned,staggered density=MIN:MAX (default: none)")
    c.add_methods(p, "bilinear,bi,edi_central,edi_line,sg,learned")
    p.add_argument("--train", type=c.path, default=None, metavar="DIR",
                   help="images 'learned' is fitted on, per layout, held out of --dataset "
                        "(default: none; learned is then a note)")
    p.add_argument("--train-limit", type=c.positive_int, default=None, metavar="N",
                   help="the first N training images only (default: all)")
    p.add_argument("--rgbd", type=c.path, default=None, metavar="DIR",
                   help="folder of RGB-D scenes (e.g. ../shared/data/rgbd) (default: none)")
    p.add_argument("--rgbd-limit", type=c.positive_int, default=None, metavar="N",
                   help="the first N scenes only (default: all)")
    p.add_argument("--rgbd-size", type=_size_or_full, default=(384, 384),
                   metavar="ROWSxCOLS|full", help="centre crop of each scene (default: 384x384)")
    p.add_argument("--wall-distance", type=c.number(float, lambda v: 0.01 <= v <= 1000,
                                                     "a distance in [0.01, 1000] m"),
                   default=2.0, metavar="M",
                   help="distance of the flat wall of the depth noise, metres")
    c.add_seed(p, 1, "seed of the depth simulations")
    p.add_argument("--scheduler", default=None,
                   help="Dask scheduler address, tcp://host:port (default: this process)")
    p.add_argument("--cache", type=c.path, default=None, metavar="DIR",
                   help="cache folder, from which an interrupted run resumes (default: "
                        "OUT/cache)")
    p.add_argument("--no-cache", action="store_true", help="neither read nor write the cache")
    p.add_argument("--no-plots", action="store_true", help="tables only, no figure")
    c.add_json(p, "print the result as JSON")
    c.add_workers(p)
    c.add_output_folder(p, DEFAULT_OUT)
    c.add_quiet(p, "no progress bar")
    return p


def run(args):
    from .._devtools._common import json_text

    study = c.tool("pattern_study")
    from .._devtools import pattern_report as report

    for flag, dest, needs in (("--rgbd-size", "rgbd_size", "rgbd"),
                              ("--rgbd-limit", "rgbd_limit", "rgbd"),
                              ("--train-limit", "train_limit", "train")):
        if getattr(args, needs) is None and c.given(args, dest):
            raise c.CliError(f"{flag}: applies with --{needs}")     # it had been ignored
    if args.no_cache and args.cache is not None:
        raise c.CliError("--cache: names the cache that --no-cache turns off; give one of them")
    if args.rgbd_size is not None and min(args.rgbd_size) < RGBD_MIN:
        raise c.CliError(f"--rgbd-size: {args.rgbd_size[0]}x{args.rgbd_size[1]} is smaller "
                         f"than {RGBD_MIN}x{RGBD_MIN}, too small for the ToF ISP's windows")
    from ..simulation import ToFSensor

    reach = ToFSensor().unambiguous_range
    if args.wall_distance >= reach:
        raise c.CliError(f"--wall-distance: {args.wall_distance:g} m lies beyond the ToF "
                         f"sensor's unambiguous range ({reach:.4g} m); every measurement of "
                         "the wall would be flagged")
    out = c.output_folder(args.out)
    c.check_report_outputs(out, ["pattern_study.csv", "pattern_study.json", "pattern_study.md"]
                           + ([] if args.no_plots else ["pattern_study.png"]),
                           [args.dataset, args.train])   # the plot had been fitted on
    settings = study.StudySettings(methods=tuple(args.methods), seed=args.seed,
                                   rgbd_size=args.rgbd_size,
                                   wall_distance=args.wall_distance)
    res = study.pattern_study(
        args.dataset, presets=args.presets, tiles=args.tiles, generate=args.generate,
        train=args.train, train_limit=args.train_limit, rgbd=args.rgbd,
        rgbd_limit=args.rgbd_limit, limit=args.limit, settings=settings,
        cache_dir=None if args.no_cache else (args.cache or out / "cache"),
        scheduler=args.scheduler, workers=args.workers, progress=c.bars(args))
    res["command"] = c.command_line(args)
    files = {"pattern_study.csv": report.to_csv(res["rows"]),
             "pattern_study.json": json_text(res) + "\n",
             "pattern_study.md": report.to_markdown(
                 res, None if args.no_plots else "pattern_study.png", res["command"])}
    if not args.no_plots:
        from .._devtools.plots import pattern_study_plot

        files["pattern_study.png"] = pattern_study_plot(res)
    c.write_report(out, files)
    print(json_text(res) if args.json else report.to_text(res))
    return 0

