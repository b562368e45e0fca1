"""``rgbz-fast simulate``: scene file(s) -> raw RGB-Z frame files (NPZ or 16-bit TIFF)."""

from __future__ import annotations

import argparse
import warnings

from . import _common as c

NAME = "simulate"
DEFAULT_OUT = "rgbz_frames"


def add_parser(sub):
    p = c.command_parser(
        sub, NAME, "scene file(s) -> raw RGB-Z frame files",
        "Run the sensor models (colour and, when the scene has depth, i-ToF) and the RGB-Z "
        "build on each scene; write one frame file per scene, OUT/<scene>_<pattern>.npz (or "
        ".tif), with the reference Bayer CFA of the same exposure.")
    p.add_argument("scenes", nargs="+", type=c.path,
                   help="image files (PNG, TIFF, JPEG), RGB-D scene folders (rgb.png + "
                        "disp1.png + dmin.txt) or spectral .mat cubes")
    c.add_pattern(p, "mask1", "RGB-Z pattern: mask1, mask2, rows, bayer, or a tile such as "
                              "ZR/BG (rows separated by /)")
    p.add_argument("--noise", action=argparse.BooleanOptionalAction, default=True,
                   help="simulate the sensor noise (shot, dark, read, fixed pattern)")
    c.add_seed(p, 0, "noise seed: the same seed gives the same frame")
    p.add_argument("--format", choices=("npz", "tiff"), default="npz",
                   help="npz keeps everything (mosaic, reference CFA, ToF taps); tiff keeps the "
                        "16-bit mosaic and its metadata alone (no ToF taps, no reference)")
    c.add_grey(p)
    p.add_argument("--input-bits", type=c.positive_int, default=None, metavar="N",
                   help="bits the values of an image of 32-bit integer samples use (a TIFF of "
                        "int32 or uint32; 8- and 16-bit files say their range) (default: none)")
    c.add_run_options(p, DEFAULT_OUT, workers=False)
    return p


def run(args):
    from tqdm.auto import tqdm

    from .._patterns import get_pattern
    from ..simulation._loaders import folder_name

    pattern = get_pattern(args.pattern)
    if not args.noise and c.given(args, "seed"):
        raise c.CliError("--seed: draws the sensor noise, which --no-noise leaves out (the "
                         "frames would be the same for every seed)")
    c.must_exist(args.scenes, "scene ")
    out = c.output_folder(args.out)
    suffix = ".tif" if args.format == "tiff" else ".npz"
    # a folder by its name ('.' by the name of the folder it is, as the frame's meta has it)
    dests = [(s, f"{s.stem if not s.is_dir() else folder_name(s)}_{c.file_label(pattern)}{suffix}")
             for s in args.scenes]
    c.unique_outputs([(s, [n]) for s, n in dests], out)
    with c.batch(args, dests, out) as done:
        for s, name in tqdm(dests, desc="simulate", unit="scene", disable=not c.bars(args)):
            _simulate_one(args, s, name, out, pattern, suffix)
            done.append(s)
    return 0


def _simulate_one(args, s, name, out, pattern, suffix):
    """Simulate scene ``s`` and write its frame to ``out / name``."""
    from ..io import save_frame
    from ..simulation import load_scene, simulate

    try:
        scene = load_scene(s, grey=args.grey, input_bits=args.input_bits, **c.limits(args))
        frame = simulate(scene, pattern, seed=args.seed, noise=args.noise)
    except (ValueError, TypeError) as exc:
        # about a scene's content ("image: holds 1 NaN", "scene: too dark for
        # auto-exposure"): which of the scenes given
        msg = c.explain(exc, args.parser)
        what, _, rest = msg.partition(": ")
        if what == "scene":
            msg = f"scene {s}: {rest}"
        elif what in ("image", "depth", "depth_valid", "ir_reflectance", "wavelengths"):
            msg = f"scene {s}: {msg}"
        raise c.CliError(msg) from None
    with warnings.catch_warnings():          # the line below says what a TIFF keeps
        warnings.filterwarnings("ignore", r"path: .* does not keep the (reference CFA|ToF)",
                                UserWarning)
        save_frame(out / name, frame)        # the folder appears with its first file
    if not args.quiet:
        print(f"{s} -> {out / name} ({frame.shape[0]}x{frame.shape[1]}, "
              f"{_what_is_kept(frame, scene, pattern, suffix)})")


def _what_is_kept(frame, scene, pattern, suffix):
    """What the file written holds beside the mosaic: a TIFF keeps the mosaic alone, which the
    line had described as 'with ToF taps'."""
    if suffix == ".tif":
        lost = "the ToF taps and the reference CFA need" if frame.tof is not None \
            else "the reference CFA needs"
        return f"the mosaic only: {lost} --format npz"
    if frame.tof is not None:
        return "with ToF taps"
    if scene.depth is not None and not pattern.has_z:
        return f"no ToF: {pattern.name!r} has no Z pixel"
    return "no depth: no ToF"
