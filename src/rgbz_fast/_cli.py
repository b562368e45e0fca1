"""``rgbz-fast``: the whole chain from the command line.

    rgbz-fast simulate   scene file(s) -> raw RGB-Z frame files (NPZ or 16-bit TIFF)
    rgbz-fast reconstruct raw frame(s) -> Bayer CFA or sRGB image
    rgbz-fast evaluate   dataset -> metrics tables, CSV/JSON, bar charts, crops
    rgbz-fast bench      kernel speed (Mpix/s) beside OpenCV and NumPy
    rgbz-fast opcount    operations per missing pixel beside the paper's Table 1
    rgbz-fast tradeoff   speed against accuracy, Pareto plot
    rgbz-fast calibrate  flat-wall sweep -> ToF phase calibration file (cyclic error, offsets)
    rgbz-fast evaluate-depth  the ToF chain measured: RGB-D scenes, range, noise, sunlight
    rgbz-fast config     how the C kernels were built (OpenMP, flags, threads)

Every subcommand has ``--help``. Bad input exits with status 2 and a one-line
reason on stderr.
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from pathlib import Path

import numpy as np

from ._build_config import VERSION
from ._config import show_config
from ._patterns import get_pattern
from .evaluation import EvalConfig, evaluate, write_reports
from .io import atomic_write, folder_dataset, load_frame, sample_dataset, save_frame
from .isp import ColourISP
from .reconstruction import ReconstructParams, reconstruct
from .simulation import Optics, load_scene, simulate

__all__ = ["main"]

EPILOG = ("Docs: docs/guide/ (user guide), docs/reports/ (measured results, each with the "
          "command that regenerates it), docs/reference/api.md.")


class CliError(Exception):
    """A user error: printed as one line, exit status 2."""


def _csv(text):
    return tuple(s.strip() for s in text.split(",") if s.strip())


def _clip_arg(text):
    """--clip-level: 'auto', 'off' or a positive number of DN."""
    t = text.strip().lower()
    if t == "auto":
        return "auto"
    if t in ("off", "none"):
        return None
    try:
        v = float(t)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected auto, off or a positive number, got {text!r}")
    if not (v > 0 and v != float("inf")):
        raise argparse.ArgumentTypeError(f"expected auto, off or a positive number, got {text!r}")
    return v


CLIP_HELP = ("clipped (saturated) pixels: off (default) takes every pixel as a real value; "
             "auto uses the clip level recorded for frames read from raw files "
             "(rgbz_fast.io.read_raw) and none for other frames; a number is the level in DN. See "
             "docs/guide/raw.md, 'Near clipping' (why off is the default)")


def _add_common(p, out_default=None):
    p.add_argument("--workers", type=int, default=None,
                   help="threads of each C kernel call; default: all cores (evaluate: 1 per "
                        "process when it runs several)")
    p.add_argument("--out", type=Path, default=out_default, help="output folder")
    p.add_argument("--quiet", action="store_true", help="no progress bars or chatter")


def _parser():
    ap = argparse.ArgumentParser(
        prog="rgbz-fast",
        description="Simulate a monolithic RGB-Z CMOS imager and reconstruct its images "
                    "(missing colour at the Z sites, ISP, depth).",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--version", action="version", version=f"rgbz-fast {VERSION}")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")

    s = sub.add_parser("simulate", help="scene file(s) -> raw RGB-Z frame files",
                       description="Run the sensor models (colour and, when the scene has depth, "
                                   "i-ToF) and the RGB-Z build on each scene; write one frame file "
                                   "per scene with the reference Bayer CFA of the same exposure.")
    s.add_argument("scenes", nargs="+", type=Path,
                   help="image files, RGB-D scene folders (rgb.png + disp1.png + dmin.txt) or "
                        "spectral .mat cubes")
    s.add_argument("--pattern", default="mask1", help="mask1, mask2, rows, bayer or a tile "
                                                      "such as ZR/BG (default mask1)")
    s.add_argument("--noise", action=argparse.BooleanOptionalAction, default=True,
                   help="simulate sensor noise (default on)")
    s.add_argument("--seed", type=int, default=0)
    s.add_argument("--format", choices=("npz", "tiff"), default="npz")
    _add_common(s, Path("rgbz_frames"))

    r = sub.add_parser("reconstruct", help="raw frame(s) -> Bayer CFA or sRGB image",
                       description="Fill in the colour missing at the Z sites; optionally run the "
                                   "colour ISP to an sRGB image.")
    r.add_argument("frames", nargs="+", type=Path, help=".npz/.tif frames from `simulate`, or "
                                                         "camera raw / Bayer files")
    r.add_argument("--method", default="sg",
                   help="bilinear, bi, edi_central, edi_line, sg, edi_rows (default sg)")
    r.add_argument("--pattern", default=None, help="pattern of files that carry none")
    r.add_argument("--bit-depth", type=int, default=None)
    r.add_argument("--precision", choices=("float32", "float64"), default="float32")
    r.add_argument("--output", choices=("cfa", "srgb"), default="cfa",
                   help="cfa: 16-bit TIFF Bayer CFA; srgb: 8-bit PNG through the colour ISP")
    r.add_argument("--clip-level", type=_clip_arg, default=None, metavar="off|auto|DN",
                   help=CLIP_HELP)
    _add_common(r, Path("rgbz_out"))

    e = sub.add_parser("evaluate", help="dataset -> metrics, tables and plots",
                       description="Run the paper's Fig. 19 chain (reference Bayer path and RGB-Z "
                                   "path through the same ISP) on every image x pattern x method "
                                   "and report CFA PSNR, CPSNR, SSIM, MS-SSIM and the zipper "
                                   "metric. With no --dataset it runs on five colour images "
                                   "shipped with scikit-image (offline).")
    e.add_argument("--dataset", type=Path, default=None,
                   help="folder of RGB images (Kodak, McMaster, your own)")
    e.add_argument("--patterns", type=_csv, default=("mask1", "mask2"))
    e.add_argument("--methods", type=_csv, default=("bilinear", "bi", "edi_central",
                                                    "edi_line", "sg"))
    e.add_argument("--metrics", type=_csv, default=None,
                   help="comma list from cfa_psnr,cpsnr,ssim,ms_ssim,zipper (default all)")
    e.add_argument("--noise", action="store_true", help="use the sensor noise model")
    e.add_argument("--demosaic", default="malvar2004", choices=("malvar2004", "menon2007"))
    e.add_argument("--crop", type=int, default=8, help="border crop of the image metrics")
    e.add_argument("--precision", choices=("float32", "float64"), default="float64")
    e.add_argument("--domain", choices=("intensity", "colour_difference"), default="intensity",
                   help="interpolate intensities (the paper, eq. 13) or colour differences (eq. 5)")
    e.add_argument("--raw-options", type=Path, default=None,
                   help="JSON file mapping raw file names (or \"*\") to rgbz_fast.io.read_raw "
                        "arguments: phase, black_level, white_level, shape, bit_depth_in, "
                        "downsample ... (for bare Bayer files that carry none)")
    e.add_argument("--clip-level", type=_clip_arg, default=None, metavar="off|auto|DN",
                   help=CLIP_HELP)
    e.add_argument("--optics", action="store_true",
                   help="blur the images through the lens model before sampling them "
                        "(rgbz_fast.simulation.Optics; default off: the pixels are the "
                        "image's)")
    e.add_argument("--f-number", type=float, default=2.8,
                   help="f-number of the lens with --optics (default 2.8)")
    e.add_argument("--olpf", type=float, default=0.0,
                   help="OLPF spot separation in pixel pitches with --optics (default 0: none; "
                        "1: zeros at Nyquist)")
    e.add_argument("--defocus-um", type=float, default=0.0,
                   help="blur-disk diameter in um with --optics (default 0: in focus)")
    e.add_argument("--limit", type=int, default=None, help="first N images only")
    e.add_argument("--table-image", default=None,
                   help="image of the per-image table (default kodim09 when present)")
    e.add_argument("--processes", type=int, default=None,
                   help="worker processes, one image each (default: all cores)")
    e.add_argument("--scheduler", default=None, help="Dask scheduler address (tcp://host:port)")
    e.add_argument("--cache", type=Path, default=None,
                   help="cache folder (default OUT/cache); runs resume from it")
    e.add_argument("--no-cache", action="store_true")
    e.add_argument("--no-plots", action="store_true")
    e.add_argument("--json", action="store_true", help="print the summary as JSON")
    _add_common(e, Path("rgbz_results"))

    for name, mod, text in (("bench", "bench", "kernel speed beside OpenCV and NumPy"),
                            ("opcount", "opcount", "operations per missing pixel vs Table 1"),
                            ("tradeoff", "tradeoff", "speed vs accuracy, Pareto plot")):
        b = sub.add_parser(name, help=text, add_help=False)
        b.set_defaults(delegate=mod)
    c = sub.add_parser(
        "calibrate", help="flat-wall sweep -> ToF phase calibration file",
        description="Fit the cyclic error of every modulation frequency and the phase offset "
                    "of every Z measurement (rgbz_fast.tof.calibrate) from frames of a flat "
                    "wall at known distances, and write them to an NPZ file that "
                    "tof_depth(calibration=ToFCalibration.load(...)) applies. Either give "
                    "frame files (from `simulate` or a real sensor, with ToF taps) and their "
                    "distances, or --simulate a sweep of a sensor model.")
    c.add_argument("frames", nargs="*", type=Path,
                   help=".npz frame files holding ToF taps, one per wall position")
    c.add_argument("--distances", default=None,
                   help="the wall distance (m) of every frame, comma-separated, in order")
    c.add_argument("--dark", nargs="*", type=Path, default=(),
                   help=".npz frames taken with the lens capped (tap dark offsets)")
    c.add_argument("--simulate", action="store_true",
                   help="simulate the sweep instead: --pattern, --shape, --near, --far, "
                        "--positions, --frames-per-position, --sensor")
    c.add_argument("--pattern", default="mask2", help="pattern of a simulated sweep (mask2)")
    c.add_argument("--shape", default="64x96", help="rows x cols of a simulated sweep (64x96)")
    c.add_argument("--near", type=float, default=0.6, help="nearest wall, m (0.6)")
    c.add_argument("--far", type=float, default=2.6,
                   help="farthest wall, m (2.6: more than the 1.874 m wrap range of 80 MHz)")
    c.add_argument("--positions", type=int, default=48, help="wall positions (48)")
    c.add_argument("--frames-per-position", type=int, default=3,
                   help="frames at each position (3)")
    c.add_argument("--reflectance", type=float, default=0.8, help="NIR reflectance (0.8)")
    c.add_argument("--sensor", default=None,
                   help="ToFSensor arguments as JSON, e.g. '{\"harmonics\": [[3, 0.04, 0.3]], "
                        "\"delay_fpn_ps\": 20}' (default: ToFSensor())")
    c.add_argument("--orders", type=int, default=8, help="harmonics of the cyclic error (8)")
    c.add_argument("--seed", type=int, default=0)
    c.add_argument("--out", type=Path, default=Path("tof_calibration.npz"),
                   help="the calibration file (default tof_calibration.npz)")
    c.add_argument("--quiet", action="store_true")

    d = sub.add_parser(
        "evaluate-depth", help="the ToF chain measured: scenes, range, noise, sunlight",
        description="Simulate and measure the ToF chain at the library's defaults "
                    "(rgbz_fast.evaluation.evaluate_depth): the six Middlebury RGB-D scenes "
                    "(wrong, wrong-and-valid, caught), depths beyond the unambiguous range "
                    "(flagged), depth noise against the predicted sigma, sunlight, and the "
                    "calibration's residual cyclic error. Prints Markdown tables "
                    "(docs/isp.md, 'Measured').")
    d.add_argument("--data", type=Path, default=None,
                   help="folder of the Middlebury scenes (default ../shared/data/rgbd when it "
                        "exists; without it the scene sections are skipped)")
    d.add_argument("--sections", type=_csv, default=None,
                   help="comma list from scenes,range,noise,sunlight,calibration (default all)")
    d.add_argument("--seed", type=int, default=1)
    d.add_argument("--json", action="store_true", help="print the rows as JSON")

    sub.add_parser("config", help="how the C kernels were built")
    return ap


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    ap = _parser()
    # bench/opcount/tradeoff own their argument parsing
    if argv and argv[0] in ("bench", "opcount", "tradeoff"):
        return _delegate(argv[0], argv[1:])
    args = ap.parse_args(argv)
    if args.command is None:
        ap.print_help()
        return 0
    try:
        return {"simulate": _simulate, "reconstruct": _reconstruct, "evaluate": _evaluate,
                "calibrate": _calibrate, "evaluate-depth": _evaluate_depth,
                "config": _config}[args.command](args)
    except (CliError, ValueError, TypeError, OSError, ImportError) as exc:
        print(f"rgbz-fast {args.command}: error: {exc}".splitlines()[0], file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"rgbz-fast {args.command}: interrupted", file=sys.stderr)
        return 130


def _delegate(name, argv):
    try:
        mod = importlib.import_module(f"rgbz_fast._devtools.{name}")
    except ImportError as exc:
        print(f"rgbz-fast {name}: error: not available in this build ({exc})", file=sys.stderr)
        return 2
    return mod.main(argv)


def _shape_arg(text):
    try:
        rows, cols = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise CliError(f"--shape: expected ROWSxCOLS, got {text!r}") from None
    return rows, cols


def _calibrate(args):
    import warnings

    from .simulation import Scene, ToFSensor, simulate_tof
    from .tof import calibrate

    if args.simulate:
        if args.frames:
            raise CliError("give frame files or --simulate, not both")
        try:
            kw = json.loads(args.sensor) if args.sensor else {}
        except ValueError as exc:
            raise CliError(f"--sensor: not JSON ({exc})") from None
        if not isinstance(kw, dict):
            raise CliError("--sensor: expected a JSON object of ToFSensor arguments")
        try:
            sensor = ToFSensor(**kw)
        except TypeError as exc:
            raise CliError(f"--sensor: {exc}".replace("ToFSensor.__init__() ", "")) from None
        shape = _shape_arg(args.shape)
        if not (0 < args.near < args.far):
            raise CliError(f"--near, --far: expected 0 < near < far, got {args.near}, "
                           f"{args.far}")
        if args.positions < 2 or args.frames_per_position < 1:
            raise CliError("--positions: at least 2; --frames-per-position: at least 1")
        distances = np.repeat(np.linspace(args.near, args.far, args.positions),
                              args.frames_per_position)

        def wall(d, s, seed):
            scene = Scene(np.full(shape + (3,), 0.5), depth=np.full(shape, d),
                          ir_reflectance=np.full(shape, args.reflectance))
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return simulate_tof(scene, args.pattern, s, seed=seed)

        sweep = [wall(d, sensor, args.seed * 100_000 + k) for k, d in enumerate(distances)]
        from dataclasses import replace
        capped = replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0)
        dark = [wall(1.0, capped, args.seed * 100_000 + 90_000 + k) for k in range(8)]
    else:
        if not args.frames:
            raise CliError("no frames: give .npz frame files with their --distances, or "
                           "--simulate")
        if args.distances is None:
            raise CliError("--distances: one distance per frame is needed")
        try:
            distances = [float(v) for v in args.distances.split(",") if v.strip()]
        except ValueError:
            raise CliError(f"--distances: expected comma-separated metres, got "
                           f"{args.distances!r}") from None
        sweep = [load_frame(f) for f in args.frames]
        dark = [load_frame(f) for f in args.dark] or None
    cal = calibrate(sweep, distances, orders=args.orders, dark=dark)
    cal.save(args.out)
    if not args.quiet:
        rms = ", ".join(f"{1e3 * v:.2f}" for v in cal.meta["fit_rms_m"])
        print(f"{len(sweep)} frames -> {args.out}: {cal!r}; fit residual per frequency "
              f"{rms} mm RMS")
    return 0


def _evaluate_depth(args):
    from .evaluation import depth_report, evaluate_depth

    data = args.data
    if data is None:
        guess = Path("..") / "shared" / "data" / "rgbd"
        data = guess if guess.is_dir() else None
    sections = args.sections or ("scenes", "range", "noise", "sunlight", "calibration")
    result = evaluate_depth(data, sections=sections, seed=args.seed)
    if args.json:
        print(json.dumps(result, indent=1, default=float))
    else:
        if data is None:
            print("(no RGB-D scenes: pass --data; the scene sections are skipped)")
        print(depth_report(result))
    return 0


def _config(args):
    show_config()
    return 0


def _simulate(args):

    pattern = get_pattern(args.pattern)
    for s in args.scenes:
        if not s.exists():
            raise CliError(f"scene {s} does not exist")
    args.out.mkdir(parents=True, exist_ok=True)
    from tqdm.auto import tqdm
    for s in tqdm(args.scenes, desc="simulate", unit="scene", disable=args.quiet):
        scene = load_scene(s)
        frame = simulate(scene, pattern, seed=args.seed, noise=args.noise)
        dest = args.out / f"{s.stem if s.is_file() else s.name}_{pattern.name}.{args.format}"
        save_frame(dest.with_suffix(".tif" if args.format == "tiff" else ".npz"), frame)
        if not args.quiet:
            tof = "with ToF taps" if frame.tof is not None else "no depth: no ToF"
            print(f"{s} -> {dest} ({frame.shape[0]}x{frame.shape[1]}, {tof})")
    return 0


def _reconstruct(args):


    params = ReconstructParams(precision=args.precision, clip_level=args.clip_level)
    for f in args.frames:
        frame = load_frame(f, pattern=args.pattern, bit_depth=args.bit_depth)
        cfa = reconstruct(frame, args.method, params=params, workers=args.workers)
        # created only once there is something to write: a failed run leaves no empty folder
        args.out.mkdir(parents=True, exist_ok=True)
        if args.output == "cfa":
            dest = args.out / f"{f.stem}_{args.method}_cfa.tif"
            import io
            import tifffile
            buf = io.BytesIO()
            data = cfa if cfa.dtype in (np.uint8, np.uint16) else \
                np.floor(np.clip(cfa, 0, frame.white_level) + 0.5).astype(np.uint16)
            tifffile.imwrite(buf, data, description=json.dumps(
                {"bayer": frame.pattern.bayer_phase, "bit_depth": frame.bit_depth,
                 "method": args.method}))
            atomic_write(dest, buf.getvalue())
        else:
            # the colour chain of the evaluation (grey world on the reconstructed CFA)
            srgb = ColourISP(precision="float64", black_level=0.0).render(
                cfa, frame.pattern.bayer_phase, bit_depth=frame.bit_depth, workers=args.workers)
            dest = args.out / f"{f.stem}_{args.method}.png"
            import imageio.v3 as iio
            atomic_write(dest, iio.imwrite("<bytes>", srgb, extension=".png"))
        if not args.quiet:
            print(f"{f} -> {dest}")
    return 0


def _evaluate(args):

    params = ReconstructParams(precision=args.precision, domain=args.domain,
                               clip_level=args.clip_level)
    kw = dict(patterns=args.patterns, methods=args.methods, noise=args.noise,
              demosaic=args.demosaic, crop=args.crop, params=params)
    if args.optics:
        kw["optics"] = Optics(f_number=args.f_number, olpf=args.olpf,
                              defocus_um=args.defocus_um)
    elif (args.f_number, args.olpf, args.defocus_um) != (2.8, 0.0, 0.0):
        raise CliError("--f-number, --olpf and --defocus-um need --optics")
    if args.metrics:
        kw["metrics"] = args.metrics
    config = EvalConfig(**kw)
    raw_options = None
    if args.raw_options is not None:
        try:
            raw_options = json.loads(Path(args.raw_options).read_text())
        except (OSError, ValueError) as exc:
            raise CliError(f"--raw-options: cannot read {args.raw_options}: {exc}") from None
    dataset = folder_dataset(args.dataset, args.limit, raw_options) if args.dataset else \
        sample_dataset()[:args.limit]
    cache = None if args.no_cache else (args.cache or args.out / "cache")
    res = evaluate(dataset, config, cache_dir=cache, processes=args.processes,
                   workers=args.workers, scheduler=args.scheduler, progress=not args.quiet)
    crop_src = None
    if not args.no_plots and config.image_metrics:
        crop_src = next((s for s in dataset if s.name == (args.table_image or "kodim09")),
                        dataset[0])
    files = write_reports(res, args.out, table_image=args.table_image, crop_source=crop_src,
                          plots=not args.no_plots)
    if args.json:
        print(json.dumps({f"{p}/{m}/{k}": {"mean": v[0], "std": v[1], "n": v[2]}
                          for (p, m, k), v in res.summary().items()}, indent=1))
    else:
        print(res.plain_table())
        if not args.quiet:
            print(f"reports: {', '.join(str(f) for f in files)}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
