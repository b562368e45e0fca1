"""``rgbz-fast calibrate``: flat-wall sweep -> ToF phase calibration file (cyclic error,
offsets)."""

from __future__ import annotations

import json

import numpy as np

from . import _common as c

NAME = "calibrate"


def add_parser(sub):
    p = c.command_parser(
        sub, NAME, "flat-wall sweep -> ToF phase calibration file",
        "Fit the cyclic error of every modulation frequency and the phase offset of every Z "
        "measurement from frames of a flat wall at known distances, and write them to an NPZ "
        "file that tof_depth(calibration=ToFCalibration.load(...)) applies. Either give frame "
        "files (from `simulate` or a real sensor, with ToF taps) and their distances, or "
        "--simulate a sweep of a sensor model.")
    p.add_argument("frames", nargs="*", type=c.path,
                   help=".npz frame files holding ToF taps, one per wall position (default: "
                        "none; --simulate makes them)")
    p.add_argument("--distances", default=None, metavar="M[,M...]",
                   help="the wall distance (m) of every frame, comma-separated, in order "
                        "(default: none; required with frame files)")
    p.add_argument("--dark", nargs="*", type=c.path, default=(),
                   help=".npz frames taken with the lens capped, for the tap dark offsets "
                        "(default: none)")
    p.add_argument("--simulate", action="store_true",
                   help="simulate the sweep instead: --pattern, --shape, --near, --far, "
                        "--positions, --frames-per-position, --sensor")
    c.add_pattern(p, "mask2", "pattern of a simulated sweep")
    c.add_shape(p, "64x96", "size of a simulated sweep's frames (default: 64x96)")
    wall = c.number(float, lambda v: 0 < v <= 1000, "a distance in (0, 1000] m")
    p.add_argument("--near", type=wall, default=0.6, metavar="M",
                   help="nearest wall of a simulated sweep, in metres")
    p.add_argument("--far", type=wall, default=2.6, metavar="M",
                   help="farthest wall of a simulated sweep, in metres (more than the 1.874 m "
                        "wrap range of 80 MHz)")
    p.add_argument("--positions", type=c.number(int, lambda v: 2 <= v <= 4096,
                                                "an integer in [2, 4096]"),
                   default=48, help="wall positions of a simulated sweep (2 to 4096)")
    p.add_argument("--frames-per-position", type=c.number(int, lambda v: 1 <= v <= 256,
                                                          "an integer in [1, 256]"),
                   default=3, help="frames at each position of a simulated sweep (1 to 256)")
    p.add_argument("--reflectance", type=c.number(float, lambda v: 0 < v <= 1,
                                                  "a number in (0, 1]"), default=0.8,
                   help="NIR reflectance of the simulated wall")
    p.add_argument("--sensor", default=None, metavar="JSON",
                   help="ToF sensor model arguments as JSON, e.g. '{\"harmonics\": [[3, 0.04, "
                        "0.3]], \"delay_fpn_ps\": 20}' (default: the library's sensor)")
    p.add_argument("--orders", type=c.number(int, lambda v: 1 <= v <= 32,
                                             "an integer in [1, 32]"), default=8,
                   help="harmonics of the fitted cyclic error (1 to 32; the sweep needs "
                        "2 * orders + 1 wall positions)")
    c.add_seed(p, 0, "seed of a simulated sweep's noise")
    c.add_output_file(p, "the calibration file to write", default="tof_calibration.npz")
    c.add_quiet(p, "no summary line")
    c.add_limits(p)
    return p


def run(args):
    from .._progress import ticking
    from ..io import load_frame
    from ..tof import calibrate

    c.output_file(args.out)
    if isinstance(args.dark, list) and not args.dark:   # '--dark' alone: the default is ()
        raise c.CliError("--dark: expected the lens-capped frame files after it")
    if args.simulate:
        if args.frames:
            raise c.CliError("give frame files or --simulate, not both")
        c.limits_need(args, False, "--simulate reads none")
        for flag, given in (("--distances", args.distances is not None),
                            ("--dark", bool(args.dark))):
            if given:                          # the simulated sweep has its own
                raise c.CliError(f"{flag}: applies to frame files; --simulate makes the "
                                 "sweep from --near, --far and --positions")
        if args.positions < 2 * args.orders + 1:     # said before the sweep, not after it
            raise c.CliError(f"--positions: {args.positions} wall positions cannot fit "
                             f"--orders {args.orders} harmonics (2 * orders + 1 = "
                             f"{2 * args.orders + 1} are needed); add positions or lower "
                             "--orders")
        sweep, distances, dark = _simulated_sweep(args)
    else:
        if not args.frames:
            raise c.CliError("no frames: give .npz frame files with their --distances, or "
                             "--simulate")
        for dest in SIMULATE_ONLY:            # ignored with frame files, and said nowhere
            if getattr(args, dest) != args.parser.get_default(dest):
                raise c.CliError(f"--{dest.replace('_', '-')}: applies to --simulate; frame "
                                 "files bring their own sensor and walls")
        if args.distances is None:
            raise c.CliError("--distances: one distance per frame is needed")
        distances = _distances(args.distances)
        sweep = [load_frame(f, **c.limits(args)) for f in args.frames]
        dark = [load_frame(f, **c.limits(args)) for f in args.dark] or None
    c.check_outputs([("the calibration", args.out)], [*args.frames, *args.dark])
    with ticking(f"calibrate: fitting {len(sweep)} frames", c.bars(args)):
        try:
            cal = calibrate(sweep, distances, orders=args.orders, dark=dark)
        except ValueError as exc:
            if args.simulate and str(exc).startswith("distances: "):
                # the walls of a simulated sweep are --near, --far and --positions (the error
                # had named --distances, which --simulate refuses)
                raise c.CliError("--near/--far/--positions: "
                                 + str(exc).removeprefix("distances: ")) from None
            raise
    cal.save(args.out)
    if not args.quiet:
        rms = ", ".join(f"{1e3 * v:.2f}" for v in cal.meta["fit_rms_m"])
        print(f"{len(sweep)} frames -> {args.out}: {cal!r}; fit residual per frequency "
              f"{rms} mm RMS")
    return 0


#: the options of a simulated sweep alone
SIMULATE_ONLY = ("pattern", "shape", "near", "far", "positions", "frames_per_position",
                 "reflectance", "sensor", "seed")


def _distances(text):
    """--distances: comma-separated metres, each in (0, 1000] (1e308 had reached the fit's
    least squares, which printed LAPACK's complaint), no empty entry."""
    items = [v.strip() for v in text.split(",")]
    try:
        values = [float(v) for v in items]
    except ValueError:
        raise c.CliError(f"--distances: expected comma-separated metres, got {text!r:.80}"
                         ) from None
    bad = next((v for v in values if not 0 < v <= 1000), None)
    if bad is not None:
        raise c.CliError(f"--distances: {bad:g} is not a distance in (0, 1000] m")
    return values


def _simulated_sweep(args):
    """(wall frames, their distances, lens-capped frames) of a simulated sweep."""
    import warnings
    from dataclasses import replace

    from ..simulation import Scene, ToFSensor, simulate_tof

    try:
        kw = json.loads(args.sensor) if args.sensor else {}
    except (ValueError, RecursionError) as exc:
        raise c.CliError(f"--sensor: not JSON ({str(exc) or 'nested too deeply'})") from None
    if not isinstance(kw, dict):
        raise c.CliError("--sensor: expected a JSON object of ToFSensor arguments")
    try:
        sensor = ToFSensor(**kw)
    except TypeError as exc:
        raise c.CliError(f"--sensor: {exc}".replace("ToFSensor.__init__() ", "")) from None
    shape = c.made_shape(args, args.shape)
    if not (0 < args.near < args.far):
        raise c.CliError(f"--near, --far: expected 0 < near < far, got {args.near}, "
                         f"{args.far}")
    distances = np.repeat(np.linspace(args.near, args.far, args.positions),
                          args.frames_per_position)

    def wall(d, s, seed):
        scene = Scene(np.full(shape + (3,), 0.5), depth=np.full(shape, d),
                      ir_reflectance=np.full(shape, args.reflectance))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return simulate_tof(scene, args.pattern, s, seed=seed)

    from tqdm.auto import tqdm

    capped = replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0)
    jobs = [(d, sensor, args.seed * 100_000 + k) for k, d in enumerate(distances)]
    jobs += [(1.0, capped, args.seed * 100_000 + 90_000 + k) for k in range(8)]
    frames = [wall(*job) for job in tqdm(jobs, desc="calibrate: simulating the sweep",
                                         unit="frame", disable=not c.bars(args))]
    sweep, dark = frames[:len(distances)], frames[len(distances):]
    return sweep, distances, dark
