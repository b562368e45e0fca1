"""``rgbz-fast``: the whole chain from the command line.

    rgbz-fast simulate    scene file(s) -> raw RGB-Z frame files (NPZ or 16-bit TIFF)
    rgbz-fast reconstruct RGB-Z frames, or camera raw / Bayer files given a Z pattern
                          -> Bayer CFA or sRGB image (and the reference it is compared with)
    rgbz-fast depth       frames with ToF taps -> depth map (float TIFF), flags, preview
    rgbz-fast evaluate    dataset -> metrics tables, CSV/JSON, figures
    rgbz-fast train       dataset -> filters of the "learned" reconstruction (.npz)
    rgbz-fast bench       kernel speed (Mpix/s) beside OpenCV and NumPy
    rgbz-fast opcount     operations per missing pixel beside the paper's Table 1
    rgbz-fast tradeoff    speed against accuracy, Pareto plot
    rgbz-fast hardware    the fixed-point model: silicon cost, error against float64, sweep
    rgbz-fast calibrate   flat-wall sweep -> ToF phase calibration file (cyclic error, offsets)
    rgbz-fast evaluate-depth  the ToF chain measured: RGB-D scenes, range, noise, sunlight
    rgbz-fast config      how the C kernels were built (OpenMP, flags, threads)

Every subcommand has ``--help``, and every option's help gives its default.
Bad input exits with status 2 and a one-line reason on stderr. Ctrl-C exits
130 and SIGTERM 143; either way no temporary file and no worker process is
left behind.
"""

from __future__ import annotations

import argparse
import importlib
import io
import json
import os
import re
import signal
import sys
from pathlib import Path

import numpy as np

from ._build_config import VERSION
from ._config import show_config
from ._patterns import get_pattern
from ._validate import parse_shape
from .evaluation import EvalConfig, evaluate, train_filters, write_reports
from .io import (MAX_BYTES_ENV, MAX_PIXELS_ENV, atomic_write, folder_dataset, load_frame,
                 read_file, sample_dataset, save_frame, to_rgbz)
from .isp import ColourISP
from .metrics import cfa_psnr
from .reconstruction import METHODS, ReconstructParams, reconstruct
from .simulation import Optics, load_scene, simulate

__all__ = ["main"]

EPILOG = ("Every option's default is shown in brackets. The user guide, the measured "
          "results and the API reference are in the project's documentation.")
DEFAULT_OUT = {"simulate": "rgbz_frames", "reconstruct": "rgbz_out", "depth": "rgbz_depth",
               "evaluate": "rgbz_results"}


class CliError(Exception):
    """A user error: printed as one line, exit status 2."""


class Terminated(SystemExit):
    """SIGTERM, raised in the main thread so that every ``finally`` and cleanup runs."""


class _Formatter(argparse.RawDescriptionHelpFormatter):
    """Help with each option's default (unless the text gives it, or it has none)."""

    def _get_help_string(self, action):
        text = action.help or ""
        if "default" in text or not action.option_strings or any(
                action.default is v for v in (None, False, argparse.SUPPRESS)):
            return text
        return text + " (default: %(default)s)"


# --------------------------------------------------------------------------- argument types
def _csv(text):
    return tuple(s.strip() for s in text.split(",") if s.strip())


def _number(convert, accept, what):
    """An argparse type: ``convert(text)`` when ``accept`` takes it, else a usage error."""
    def parse(text):
        try:
            v = convert(text)
        except ValueError:
            v = None
        if v is None or not accept(v):
            raise argparse.ArgumentTypeError(f"expected {what}, got {text!r}")
        return v
    return parse


_positive_int = _number(int, lambda v: v >= 1, "a positive integer")
_non_negative_int = _number(int, lambda v: v >= 0, "an integer >= 0")
_positive_float = _number(float, lambda v: 0 < v < float("inf"), "a positive number")


def _off_or(parse):
    """An argparse type: ``off`` (None: the test is not made), else ``parse(text)``."""
    def parse_or_off(text):
        return None if text.strip().lower() == "off" else parse(text)
    return parse_or_off


def _levels(text):
    """One level, or four (one per site of the 2x2 quad, row by row): '64' or '64,64,65,64'."""
    try:
        vals = [float(v) for v in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number or four comma-separated numbers, "
                                          f"got {text!r}") from None
    if len(vals) not in (1, 4):
        raise argparse.ArgumentTypeError(f"expected one value or four, got {len(vals)}")
    return vals[0] if len(vals) == 1 else vals


def _shape(text):
    try:
        return parse_shape(text, "shape")
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc).removeprefix("shape: ")) from None


def _fixed_fields(text):
    """--fixed-point: 'field=value,...' -> {field: int or str} (FixedPointConfig checks them)."""
    out = {}
    for item in _csv(text):
        key, sep, value = item.partition("=")
        if not sep or not key.strip() or not value.strip():
            raise argparse.ArgumentTypeError(f"expected FIELD=VALUE pairs, got {item!r}")
        value = value.strip()
        out[key.strip()] = int(value) if value.lstrip("-").isdigit() else value
    return out


def _range(text):
    try:
        lo, hi = (float(v) for v in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected MIN:MAX in metres, got {text!r}") from None
    if not (0 <= lo < hi < float("inf")):
        raise argparse.ArgumentTypeError(f"expected 0 <= MIN < MAX, got {text!r}")
    return lo, hi


def _clip_arg(text):
    """--clip-level: 'auto', 'off' or a positive number of DN."""
    t = text.strip().lower()
    if t == "auto":
        return "auto"
    if t in ("off", "none"):
        return None
    try:
        return _positive_float(t)
    except argparse.ArgumentTypeError:
        raise argparse.ArgumentTypeError(
            f"expected auto, off or a positive number, got {text!r}") from None


CLIP_HELP = ("clipped (saturated) pixels: off takes every pixel as a real value; auto uses the "
             "saturation level recorded when a raw file is read (none for other frames); a "
             "number is the level in DN. Differences between two clipped pixels are then left "
             "out of the weights (default: off; a pixel at the level is not always a clipped "
             "one)")

FILTERS_HELP = ("method learned: filters files from `rgbz-fast train` (the one fitted for the "
                "frame's pattern and bit depth is used); default: the ones shipped for Mask1 "
                "and Mask2")


def _add_limits(p):
    p.add_argument("--max-pixels", type=_positive_int, default=None, metavar="N",
                   help=f"refuse images larger than N pixels, as their headers declare them, "
                        f"before decoding (default: {MAX_PIXELS_ENV} when set, else 200000000)")
    p.add_argument("--max-bytes", type=_positive_int, default=None, metavar="N",
                   help=f"refuse files, and arrays in them, larger than N bytes (default: "
                        f"{MAX_BYTES_ENV} when set, else 2147483648)")


def _add_common(p, command, workers=True):
    if workers:
        p.add_argument("--workers", type=_positive_int, default=None, metavar="N",
                       help="threads of each kernel call (default: all cores; evaluate: 1 per "
                            "process when it runs several)")
    p.add_argument("--out", type=Path, default=Path(DEFAULT_OUT[command]), metavar="DIR",
                   help="output folder, created when the first file is written")
    p.add_argument("--quiet", action="store_true", help="no progress bar or per-file lines")
    _add_limits(p)


def _parser():
    ap = argparse.ArgumentParser(
        prog="rgbz-fast",
        description="Simulate a monolithic RGB-Z CMOS imager and reconstruct its images "
                    "(missing colour at the Z sites, ISP, depth).",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--version", action="version", version=f"rgbz-fast {VERSION}")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    kw = dict(formatter_class=_Formatter, epilog=EPILOG)

    s = sub.add_parser("simulate", help="scene file(s) -> raw RGB-Z frame files",
                       description="Run the sensor models (colour and, when the scene has depth, "
                                   "i-ToF) and the RGB-Z build on each scene; write one frame file "
                                   "per scene, OUT/<scene>_<pattern>.npz (or .tif), with the "
                                   "reference Bayer CFA of the same exposure.", **kw)
    s.add_argument("scenes", nargs="+", type=Path,
                   help="image files (PNG, TIFF, JPEG), RGB-D scene folders (rgb.png + "
                        "disp1.png + dmin.txt) or spectral .mat cubes")
    s.add_argument("--pattern", default="mask1",
                   help="RGB-Z pattern: mask1, mask2, rows, bayer, or a tile such as ZR/BG "
                        "(rows separated by /)")
    s.add_argument("--noise", action=argparse.BooleanOptionalAction, default=True,
                   help="simulate the sensor noise (shot, dark, read, fixed pattern)")
    s.add_argument("--seed", type=_non_negative_int, default=0,
                   help="noise seed: the same seed gives the same frame")
    s.add_argument("--format", choices=("npz", "tiff"), default="npz",
                   help="npz keeps everything (mosaic, reference CFA, ToF taps); tiff keeps the "
                        "16-bit mosaic and its metadata")
    s.add_argument("--grey", action="store_true",
                   help="accept grey images, repeating them into R, G and B (default: refuse "
                        "them: a colour sensor needs colour)")
    _add_common(s, "simulate", workers=False)

    r = sub.add_parser("reconstruct", help="raw frame(s) -> Bayer CFA or sRGB image",
                       description="Fill in the colour missing at the Z sites. Frames from "
                                   "`rgbz-fast simulate` carry their pattern. A real Bayer raw "
                                   "(camera raw, 16-bit Bayer PNG/TIFF, headerless .raw) has no "
                                   "Z sites: --rgbz-pattern places one on its CFA (the Z sites "
                                   "are dropped, then reconstructed, and the real CFA is the "
                                   "reference). Writes OUT/<name>_<method>_cfa.tif (or .png with "
                                   "--output srgb) and, when there is one, the reference, and "
                                   "prints the CFA PSNR at the Z sites.", **kw)
    r.add_argument("frames", nargs="+", type=Path,
                   help=".npz/.tif frames from `rgbz-fast simulate`, or camera raw / Bayer files")
    r.add_argument("--method", default="sg",
                   help=f"reconstruction method: {', '.join(METHODS)}")
    r.add_argument("--rgbz-pattern", default=None, choices=("mask1", "mask2", "rows"),
                   help="place this Z pattern on the CFA of a plain Bayer raw, on its own Bayer "
                        "phase (default: none; a raw without Z sites needs one)")
    r.add_argument("--pattern", default=None,
                   help="the RGB-Z pattern of a plain 16-bit TIFF/PNG mosaic that holds Z sites "
                        "but no rgbz-fast header, with --bit-depth (default: none; frames from "
                        "simulate carry theirs)")
    r.add_argument("--bit-depth", type=_positive_int, default=None,
                   help="bits of a plain TIFF/PNG mosaic given with --pattern; for a raw file, "
                        "the working bit depth it is scaled to (default: 11)")
    r.add_argument("--precision", choices=("float32", "float64"), default="float32",
                   help="arithmetic of the kernel")
    r.add_argument("--domain", choices=("intensity", "colour_difference"),
                   default="intensity",
                   help="interpolate intensities (the paper, eq. 13) or colour differences")
    r.add_argument("--output", choices=("cfa", "srgb"), default="cfa",
                   help="cfa: 16-bit TIFF Bayer CFA; srgb: 8-bit PNG through the colour ISP")
    r.add_argument("--clip-level", type=_clip_arg, default=None, metavar="off|auto|DN",
                   help=CLIP_HELP)
    r.add_argument("--filters", type=_csv, default=None, metavar="FILE[,FILE]",
                   help=FILTERS_HELP)
    raw = r.add_argument_group("raw files", "How to read a camera raw, a 16-bit Bayer PNG/TIFF "
                                            "or a headerless file (camera raw files record "
                                            "phase and levels; the options override them)")
    raw.add_argument("--phase", choices=("RGGB", "BGGR", "GRBG", "GBRG"), type=str.upper,
                     default=None, help="CFA phase at pixel (0, 0) (default: from the file)")
    raw.add_argument("--black-level", type=_levels, default=None, metavar="DN[,DN,DN,DN]",
                     help="black level: one value, or four for the 2x2 quad row by row "
                          "(default: from the file)")
    raw.add_argument("--white-level", type=_levels, default=None, metavar="DN[,DN,DN,DN]",
                     help="the raw value of full scale (default: from the file, else "
                          "2**bit-depth-in - 1)")
    raw.add_argument("--saturation-level", type=_levels, default=None, metavar="DN[,DN,DN,DN]",
                     help="raw values at or above it are clipped (default: the white level)")
    raw.add_argument("--shape", type=_shape, default=None, metavar="ROWSxCOLS",
                     help="size of a headerless file, rows first, e.g. 1080x1920 (default: "
                          "none, required for headerless files)")
    raw.add_argument("--bit-depth-in", type=_positive_int, default=None,
                     help="bits of the stored samples (default: from the file)")
    raw.add_argument("--byteorder", choices=("little", "big"), default="little",
                     help="byte order of a headerless file")
    raw.add_argument("--downsample", type=_positive_int, default=1, metavar="K",
                     help="bin each colour plane KxK (the paper bins its HDR+ raws 2x2)")
    raw.add_argument("--raw-options", type=Path, default=None, metavar="FILE",
                     help="JSON file mapping raw file names (or \"*\", every file) to options "
                          "(phase, black_level, white_level, clip_level, shape, bit_depth_in, "
                          "downsample); the options above override it (default: none)")
    _add_common(r, "reconstruct")

    d = sub.add_parser("depth", help="frame(s) with ToF taps -> depth map, flags, preview",
                       description="Run the ToF ISP (four-tap demodulation, edge-aware "
                                   "denoise, three-frequency unwrapping, validity) on the taps "
                                   "of frames simulated from scenes with depth. Writes, per "
                                   "frame, OUT/<name>_depth.tif (float32 metres on the frame "
                                   "grid, NaN where there is no valid measurement: the colour "
                                   "sites and the flagged Z pixels), OUT/<name>_depth_flags.png "
                                   "(0 valid, bits 1 saturated, 2 low signal, 4 inconsistent "
                                   "frequencies, 8 flying pixel, 16 out of range; 255 colour "
                                   "site) and OUT/<name>_depth.png (a colour-mapped "
                                   "preview with its scale). Prints how much is valid and, for "
                                   "simulated frames, the error against the ground truth and "
                                   "how much of it is unknown.", **kw)
    d.add_argument("frames", nargs="+", type=Path,
                   help=".npz frames from `rgbz-fast simulate` of scenes with depth")
    d.add_argument("--denoise", choices=("bilateral", "box", "none"), default="bilateral",
                   help="phasor denoise: edge-aware over the 5x5 nearest Z pixels, the paper's "
                        "plain 5x5 average (Fig. 17), or none")
    d.add_argument("--calibration", type=Path, default=None, metavar="FILE",
                   help="phase calibration from `rgbz-fast calibrate` (default: none)")
    d.add_argument("--min-snr", type=_positive_float, default=4.0,
                   help="flag measurements whose signal-to-noise ratio is below this")
    d.add_argument("--max-range", type=_positive_float, default=None, metavar="METRES",
                   help="unwrapping range (default: the unambiguous range of the frequencies)")
    d.add_argument("--max-sigma", type=_off_or(_positive_float), default=0.015,
                   metavar="METRES|off",
                   help="flag measurements whose predicted depth noise is above this")
    d.add_argument("--flying-step", type=_off_or(_positive_float), default=0.05,
                   metavar="METRES|off",
                   help="flag flying pixels: a depth step to a neighbour above this (and 2 "
                        "sigma); off keeps them")
    d.add_argument("--min-reflectance", type=_number(float, lambda v: 0 <= v <= 1,
                                                     "a number in [0, 1]"), default=0.05,
                   help="flag measurements whose implied reflectance is below this (a surface "
                        "beyond the unambiguous range, aliased nearer)")
    d.add_argument("--range", type=_range, default=None, metavar="MIN:MAX",
                   help="colour scale of the preview in metres (default: the 1st to 99th "
                        "percentile of the valid depth)")
    _add_common(d, "depth")

    e = sub.add_parser("evaluate", help="dataset -> metrics, tables and plots",
                       description="Run the paper's Fig. 19 chain (reference Bayer path and RGB-Z "
                                   "path through the same ISP) on every image x pattern x method "
                                   "and report CFA PSNR, CPSNR, SSIM, MS-SSIM and the zipper "
                                   "metric. With no --dataset it runs on five colour images "
                                   "shipped with scikit-image (offline).", **kw)
    e.add_argument("--dataset", type=Path, default=None,
                   help="folder of RGB images (Kodak, McMaster, your own) or of raw files, or one "
                        "file (default: the scikit-image samples)")
    e.add_argument("--patterns", type=_csv, default="mask1,mask2", help="comma-separated patterns")
    e.add_argument("--methods", type=_csv, default="bilinear,bi,edi_central,edi_line,sg",
                   help="comma-separated methods")
    e.add_argument("--metrics", type=_csv, default="cfa_psnr,cpsnr,ssim,ms_ssim,zipper",
                   help="comma-separated metrics")
    e.add_argument("--noise", action="store_true", help="use the sensor noise model (default: "
                                                        "noise-free mosaics)")
    e.add_argument("--demosaic", default="malvar2004", choices=("malvar2004", "menon2007"),
                   help="Bayer demosaic of both paths")
    e.add_argument("--crop", type=_non_negative_int, default=8,
                   help="border (pixels) left out of the image metrics")
    e.add_argument("--precision", choices=("float32", "float64"), default="float64",
                   help="arithmetic of the reconstruction")
    e.add_argument("--bit-depth", type=_positive_int, default=11,
                   help="bits of the simulated frames")
    e.add_argument("--linearise", action=argparse.BooleanOptionalAction, default=True,
                   help="linearise 8-bit sRGB images with the sRGB EOTF (default); "
                        "--no-linearise mosaics the sRGB values (the 8-bit sRGB protocol)")
    e.add_argument("--filters", type=_csv, default=None, metavar="FILE[,FILE]",
                   help=FILTERS_HELP)
    e.add_argument("--domain", choices=("intensity", "colour_difference"), default="intensity",
                   help="interpolate intensities (the paper, eq. 13) or colour differences "
                        "(eq. 5)")
    e.add_argument("--raw-options", type=Path, default=None, metavar="FILE",
                   help="JSON file mapping raw file names (or \"*\") to how to read them: phase, "
                        "black_level, white_level, clip_level, shape, bit_depth_in, downsample "
                        "(default: none; camera raw files need none)")
    e.add_argument("--clip-level", type=_clip_arg, default=None, metavar="off|auto|DN",
                   help=CLIP_HELP)
    e.add_argument("--limit", type=_positive_int, default=None, metavar="N",
                   help="the first N images only (default: all)")
    e.add_argument("--grey", action="store_true",
                   help="accept grey images, repeating them into R, G and B (default: refuse "
                        "them)")
    e.add_argument("--skip-bad", action="store_true",
                   help="skip the images that cannot be evaluated, and list them (default: the "
                        "first one stops the run)")
    e.add_argument("--optics", action="store_true",
                   help="blur the images through the lens model before sampling them "
                        "(default: off, the pixels are the image's)")
    e.add_argument("--f-number", type=_positive_float, default=2.8,
                   help="f-number of the lens, with --optics")
    e.add_argument("--olpf", type=_number(float, lambda v: 0 <= v < float("inf"),
                                          "a number >= 0"), default=0.0,
                   help="optical low-pass filter spot separation in pixel pitches, with --optics "
                        "(0: none; 1: zeros at Nyquist)")
    e.add_argument("--defocus-um", type=_number(float, lambda v: 0 <= v < float("inf"),
                                                "a number >= 0"), default=0.0,
                   help="blur-disk diameter in micrometres, with --optics (0: in focus)")
    e.add_argument("--table-image", default=None,
                   help="image of the per-image table (default: kodim09 when present, else the "
                        "first)")
    e.add_argument("--processes", type=_positive_int, default=None, metavar="N",
                   help="worker processes, one image each (default: all cores)")
    e.add_argument("--scheduler", default=None,
                   help="Dask scheduler address, tcp://host:port (default: the local pool)")
    e.add_argument("--cache", type=Path, default=None, metavar="DIR",
                   help="cache folder, from which an interrupted run resumes (default: OUT/cache)")
    e.add_argument("--no-cache", action="store_true", help="neither read nor write the cache")
    e.add_argument("--no-plots", action="store_true", help="tables only, no figures")
    e.add_argument("--json", action="store_true", help="print the summary as JSON")
    _add_common(e, "evaluate")

    t = sub.add_parser("train", help="dataset -> filters of the learned reconstruction",
                       description="Fit the filters of method 'learned' (hashed 7x7 linear "
                                   "filters, see the user guide) to a folder of images, with "
                                   "the evaluation's protocol (sRGB EOTF, mosaic at --bit-depth), "
                                   "and write them to --out. Fit on images you do not evaluate "
                                   "on.", **kw)
    t.add_argument("--dataset", type=Path, required=True, metavar="DIR",
                   help="folder of RGB images to fit on (required; keep the images you "
                        "evaluate on out of it)")
    t.add_argument("--pattern", default="mask1",
                   help="RGB-Z pattern: mask1, mask2 or a tile such as ZR/BG (default: mask1)")
    t.add_argument("--out", type=Path, required=True, metavar="FILE",
                   help="the .npz file to write (required)")
    t.add_argument("--bit-depth", type=_positive_int, default=11,
                   help="bits of the frames the filters are for")
    t.add_argument("--noise", action="store_true",
                   help="fit on frames of the sensor noise model (default: noise-free mosaics)")
    t.add_argument("--linearise", action=argparse.BooleanOptionalAction, default=True,
                   help="linearise 8-bit sRGB images with the sRGB EOTF (default); "
                        "--no-linearise fits on the sRGB values (the 8-bit sRGB protocol)")
    t.add_argument("--name", default=None,
                   help="training set name kept in the file (default: the folder's name)")
    t.add_argument("--limit", type=_positive_int, default=None, metavar="N",
                   help="the first N images only (default: every image)")
    t.add_argument("--radius", type=_positive_int, default=3,
                   help="window radius of the filter taps (3: a 7x7 window)")
    t.add_argument("--hash-radius", type=_positive_int, default=3,
                   help="window radius of the gradients the hash is computed from")
    t.add_argument("--strength", type=_positive_int, default=3,
                   help="strength levels of the hash")
    t.add_argument("--coherence", type=_positive_int, default=3,
                   help="coherence levels of the hash")
    t.add_argument("--ridge", type=_positive_float, default=1e-3,
                   help="ridge regularisation, relative to the mean diagonal of the normal "
                        "matrix")
    t.add_argument("--prior", type=_number(float, lambda v: 0 <= v < float("inf"),
                                           "a number >= 0"), default=50.0,
                   help="weight, in training sites, of the common filter in each bucket's fit")
    t.add_argument("--quiet", action="store_true", help="no progress bar or summary line")
    _add_limits(t)

    c = sub.add_parser(
        "calibrate", help="flat-wall sweep -> ToF phase calibration file",
        description="Fit the cyclic error of every modulation frequency and the phase offset "
                    "of every Z measurement from frames of a flat "
                    "wall at known distances, and write them to an NPZ file that "
                    "tof_depth(calibration=ToFCalibration.load(...)) applies. Either give "
                    "frame files (from `simulate` or a real sensor, with ToF taps) and their "
                    "distances, or --simulate a sweep of a sensor model.", **kw)
    c.add_argument("frames", nargs="*", type=Path,
                   help=".npz frame files holding ToF taps, one per wall position (default: "
                        "none; --simulate makes them)")
    c.add_argument("--distances", default=None, metavar="M[,M...]",
                   help="the wall distance (m) of every frame, comma-separated, in order "
                        "(default: none; required with frame files)")
    c.add_argument("--dark", nargs="*", type=Path, default=(),
                   help=".npz frames taken with the lens capped, for the tap dark offsets "
                        "(default: none)")
    c.add_argument("--simulate", action="store_true",
                   help="simulate the sweep instead: --pattern, --shape, --near, --far, "
                        "--positions, --frames-per-position, --sensor")
    c.add_argument("--pattern", default="mask2", help="pattern of a simulated sweep")
    c.add_argument("--shape", type=_shape, default=(64, 96), metavar="ROWSxCOLS",
                   help="size of a simulated sweep's frames (default: 64x96)")
    c.add_argument("--near", type=_positive_float, default=0.6, metavar="M",
                   help="nearest wall of a simulated sweep, in metres")
    c.add_argument("--far", type=_positive_float, default=2.6, metavar="M",
                   help="farthest wall of a simulated sweep, in metres (more than the 1.874 m "
                        "wrap range of 80 MHz)")
    c.add_argument("--positions", type=_number(int, lambda v: v >= 2, "an integer >= 2"),
                   default=48, help="wall positions of a simulated sweep")
    c.add_argument("--frames-per-position", type=_positive_int, default=3,
                   help="frames at each position of a simulated sweep")
    c.add_argument("--reflectance", type=_number(float, lambda v: 0 < v <= 1,
                                                 "a number in (0, 1]"), default=0.8,
                   help="NIR reflectance of the simulated wall")
    c.add_argument("--sensor", default=None, metavar="JSON",
                   help="ToF sensor model arguments as JSON, e.g. '{\"harmonics\": [[3, 0.04, "
                        "0.3]], \"delay_fpn_ps\": 20}' (default: the library's sensor)")
    c.add_argument("--orders", type=_positive_int, default=8,
                   help="harmonics of the fitted cyclic error")
    c.add_argument("--seed", type=_non_negative_int, default=0,
                   help="seed of a simulated sweep's noise")
    c.add_argument("--out", type=Path, default=Path("tof_calibration.npz"), metavar="FILE",
                   help="the calibration file to write")
    c.add_argument("--quiet", action="store_true", help="no summary line")
    _add_limits(c)

    d = sub.add_parser(
        "evaluate-depth", help="the ToF chain measured: scenes, range, noise, sunlight",
        description="Simulate and measure the ToF chain at the library's defaults: the six "
                    "Middlebury RGB-D scenes (wrong, wrong-and-valid, caught), depths beyond "
                    "the unambiguous range (flagged), depth noise against the predicted sigma, "
                    "sunlight, and the calibration's residual cyclic error. Prints Markdown "
                    "tables.", **kw)
    d.add_argument("--data", type=Path, default=None, metavar="DIR",
                   help="folder of the Middlebury scenes (default: ../shared/data/rgbd when it "
                        "exists; without it the scene sections are skipped)")
    d.add_argument("--sections", type=_csv, default=None,
                   help="comma list from scenes,range,noise,sunlight,calibration (default: all)")
    d.add_argument("--seed", type=_non_negative_int, default=1, help="seed of the sensor noise")
    d.add_argument("--json", action="store_true", help="print the rows as JSON")
    _add_limits(d)

    h = sub.add_parser(
        "hardware", help="the fixed-point model: silicon cost and error against float64",
        description="The fixed-point streaming model of one method on one pattern "
                    "(precision='fixed'): line buffers and BRAM_18K, window, latency, "
                    "multipliers by width, adders, comparators, tables, register widths; its "
                    "error against float64 (CFA PSNR change, histogram of the LSB differences "
                    "at the Z sites) under evaluate's protocol and on 8-bit sRGB values at 11 "
                    "bits; its operations per pixel beside Table 1 and the float core's. "
                    "--sweep varies the widths and table sizes: quality against cost.", **kw)
    h.add_argument("--method", default="sg", choices=("bilinear", "bi", "edi_central",
                                                      "edi_line", "sg"),
                   help="reconstruction method")
    h.add_argument("--pattern", default="mask1",
                   help="RGB-Z pattern: mask1, mask2, rows, or a tile such as ZR/BG")
    h.add_argument("--width", type=_positive_int, default=4000, metavar="PIXELS",
                   help="pixels per row: the depth of a line buffer")
    h.add_argument("--dataset", type=Path, default=None, metavar="DIR",
                   help="folder of RGB images for the error (default: the five scikit-image "
                        "samples evaluate uses with no --dataset)")
    h.add_argument("--limit", type=_positive_int, default=None, metavar="N",
                   help="the first N images of the dataset only (default: every image)")
    h.add_argument("--sweep", action="store_true",
                   help="also vary every width and table size around the configuration: a "
                        "table and a plot of quality against cost (written to --out)")
    h.add_argument("--fixed-point", type=_fixed_fields, default=None, metavar="FIELD=VALUE,...",
                   help="the configuration to report, as fields of FixedPointConfig (default: "
                        "its defaults), e.g. exp_bits=12,recip=table")
    h.add_argument("--json", action="store_true", help="print JSON instead of Markdown")
    h.add_argument("--out", type=Path, default=Path("rgbz_hardware"), metavar="DIR",
                   help="folder of hardware.md, hardware.json and, with --sweep, "
                        "hardware_sweep.png")
    h.add_argument("--quiet", action="store_true", help="no progress bar")

    for name, mod, text in (("bench", "bench", "kernel speed beside OpenCV and NumPy"),
                            ("opcount", "opcount", "operations per missing pixel vs Table 1"),
                            ("tradeoff", "tradeoff", "speed vs accuracy, Pareto plot")):
        b = sub.add_parser(name, help=text, add_help=False)
        b.set_defaults(delegate=mod)
    sub.add_parser("config", help="how the C kernels were built")
    return ap


# --------------------------------------------------------------------------- main
#: the Python spelling of options in library messages, and the command line's
_CLI_WORDS = [("max_pixels=, --max-pixels", "--max-pixels"),
              ("max_bytes=, --max-bytes", "--max-bytes"),
              ("shape=(rows, cols)", "--shape ROWSxCOLS"), ("phase=", "--phase"),
              ("black_level=", "--black-level"), ("white_level=", "--white-level"),
              ("bit_depth_in=", "--bit-depth-in"), ("grey=True", "--grey"),
              ("pass reader=", "give the file a camera raw extension")]


def _for_the_command_line(message):
    """A library message with its advice in command-line terms (pass --phase, not phase=)."""
    for py, cli in _CLI_WORDS:
        message = message.replace(py, cli)
    return re.sub(r"\s*\(command line: [^)]*\)", "", message)


def _terminate(signum, frame):
    signal.signal(signal.SIGTERM, signal.SIG_IGN)      # cleaning up: do not interrupt it
    raise Terminated(128 + signum)


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
    previous = None
    if hasattr(signal, "SIGTERM") and _main_thread():
        previous = signal.signal(signal.SIGTERM, _terminate)
    saved_env = {k: os.environ.get(k) for k in (MAX_PIXELS_ENV, MAX_BYTES_ENV)}
    try:
        # the limits go through the environment, so the evaluation's processes inherit them
        for key, value in ((MAX_PIXELS_ENV, getattr(args, "max_pixels", None)),
                           (MAX_BYTES_ENV, getattr(args, "max_bytes", None))):
            if value is not None:
                os.environ[key] = str(value)
        return {"simulate": _simulate, "reconstruct": _reconstruct, "depth": _depth,
                "evaluate": _evaluate, "train": _train, "calibrate": _calibrate,
                "evaluate-depth": _evaluate_depth, "hardware": _hardware,
                "config": _config}[args.command](args)
    except (CliError, ValueError, TypeError, OSError, ImportError) as exc:
        text = _for_the_command_line(str(exc)).splitlines()[0] if str(exc) else \
            type(exc).__name__
        print(f"rgbz-fast {args.command}: error: {text}", file=sys.stderr)
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
        for key, value in saved_env.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value


def _main_thread():
    import threading
    return threading.current_thread() is threading.main_thread()


def _delegate(name, argv):
    try:
        mod = importlib.import_module(f"rgbz_fast._devtools.{name}")
    except ImportError as exc:
        print(f"rgbz-fast {name}: error: not available in this build ({exc})", file=sys.stderr)
        return 2
    return mod.main(argv)


def _hardware(args):
    from ._devtools import hardware as hw
    from ._devtools._common import progress, write_json
    from .hardware import FixedPointConfig

    try:
        config = FixedPointConfig.build(args.fixed_point)
    except (TypeError, ValueError) as exc:
        raise CliError(f"--fixed-point: {exc}") from None
    pattern = get_pattern(args.pattern)
    images = hw.load_images(args.dataset, args.limit)
    report = hw.hardware_report(args.method, pattern, width=args.width, images=images,
                                config=config)
    files = {"hardware.md": hw.format_report(report) + "\n"}
    if args.sweep:
        configs = hw.sweep_configs(config)
        bar = progress(range(len(configs)), total=len(configs), desc="sweep", quiet=args.quiet)
        it = iter(bar)
        rows = hw.run_sweep(args.method, pattern, width=args.width, images=images, base=config,
                            configs=configs, tick=lambda: next(it, None))
        report["sweep"] = rows
        files["hardware.md"] += "\n## Sweep\n\n" + hw.format_sweep(rows) + "\n"
        args.out.mkdir(parents=True, exist_ok=True)
        tmp = args.out / "hardware_sweep.tmp.png"
        hw.plot_sweep(rows, tmp, f"{args.method} on {pattern.name}")
        tmp.replace(args.out / "hardware_sweep.png")
    files["hardware.json"] = write_json(report) + "\n"
    args.out.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        atomic_write(args.out / name, text.encode())
    print(files["hardware.json"] if args.json else files["hardware.md"], end="")
    return 0


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
        shape = tuple(args.shape)
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


def _unique_outputs(pairs, out):
    """``pairs``: (input, output names); a CliError when two inputs would write one file."""
    seen = {}
    for src, names in pairs:
        for name in names:
            if name in seen and seen[name] != src:
                raise CliError(f"--out: {seen[name]} and {src} would both write "
                               f"{out / name}; give them different --out folders or rename one")
            seen[name] = src


def _label(pattern):
    """A pattern's name as a file-name part: ZR/BG -> ZR-BG (no folder separator)."""
    return re.sub(r"[^A-Za-z0-9_.-]", "-", pattern.name)


# --------------------------------------------------------------------------- simulate
def _simulate(args):
    pattern = get_pattern(args.pattern)
    for s in args.scenes:
        if not s.exists():
            raise CliError(f"scene {s} does not exist")
    suffix = ".tif" if args.format == "tiff" else ".npz"
    dests = [(s, f"{s.stem if not s.is_dir() else s.name}_{_label(pattern)}{suffix}")
             for s in args.scenes]
    _unique_outputs([(s, [n]) for s, n in dests], args.out)
    from tqdm.auto import tqdm
    for s, name in tqdm(dests, desc="simulate", unit="scene", disable=args.quiet):
        scene = load_scene(s, grey=args.grey)
        frame = simulate(scene, pattern, seed=args.seed, noise=args.noise)
        save_frame(args.out / name, frame)       # the folder appears with its first file
        if not args.quiet:
            tof = "with ToF taps" if frame.tof is not None else "no depth: no ToF"
            print(f"{s} -> {args.out / name} ({frame.shape[0]}x{frame.shape[1]}, {tof})")
    return 0


# --------------------------------------------------------------------------- reconstruct
_RAW_FLAGS = (("phase", "phase"), ("black_level", "black_level"),
              ("white_level", "white_level"), ("saturation_level", "clip_level"),
              ("shape", "shape"), ("bit_depth_in", "bit_depth_in"))


def _raw_options_file(path):
    if path is None:
        return {}
    try:
        opts = json.loads(read_file(path, "--raw-options", max_bytes=1 << 20))
    except (OSError, ValueError) as exc:
        raise CliError(f"--raw-options: cannot read {path}: {' '.join(str(exc).split())}") \
            from None
    if not isinstance(opts, dict) or not all(isinstance(v, dict) for v in opts.values()):
        raise CliError(f"--raw-options: {path} should map file names (or \"*\") to objects of "
                       "options")
    return opts


def _raw_kwargs(args, path, from_file):
    """The read_raw options of one file: the JSON file's ("*", then its name), then the flags."""
    kw = {**from_file.get("*", {}), **from_file.get(path.name, {})}
    explicit = {}
    for flag, key in _RAW_FLAGS:
        v = getattr(args, flag)
        if v is not None:
            explicit[key] = v
    if args.byteorder != "little":
        explicit["byteorder"] = ">"
    if args.downsample != 1:
        explicit["downsample"] = args.downsample
    kw.update(explicit)
    return kw, explicit


def _write_cfa(dest, cfa, frame, method):
    import tifffile

    buf = io.BytesIO()
    data = cfa if cfa.dtype in (np.uint8, np.uint16) else \
        np.floor(np.clip(cfa, 0, frame.white_level) + 0.5).astype(np.uint16)
    tifffile.imwrite(buf, data, description=json.dumps(
        {"bayer": frame.pattern.bayer_phase, "bit_depth": frame.bit_depth, "method": method}))
    atomic_write(dest, buf.getvalue())


def _write_png(dest, rgb):
    import imageio.v3 as iio

    atomic_write(dest, iio.imwrite("<bytes>", rgb, extension=".png"))


def _reconstruct(args):
    if args.pattern is not None and args.rgbz_pattern is not None:
        raise CliError("--pattern: names the pattern of a plain mosaic that already holds Z "
                       "sites; --rgbz-pattern places one on a Bayer raw; give one of them")
    if args.pattern is not None and any(getattr(args, f) is not None for f, _ in _RAW_FLAGS):
        raise CliError("--pattern: a plain RGB-Z mosaic is read as it is stored; the raw "
                       "options (--phase, --black-level, ...) apply to Bayer raw files, with "
                       "--rgbz-pattern")
    params = ReconstructParams(precision=args.precision, domain=args.domain,
                               clip_level=args.clip_level, filters=args.filters)
    from_file = _raw_options_file(args.raw_options)
    for f in args.frames:
        if not f.exists():
            raise CliError(f"path: {f} does not exist")
    label = args.rgbz_pattern and f"_{args.rgbz_pattern}"
    ext = "_cfa.tif" if args.output == "cfa" else ".png"
    names = [(f, f"{f.stem}{label or ''}") for f in args.frames]
    _unique_outputs([(f, [f"{n}_{args.method}{ext}", f"{n}_reference{ext}"]) for f, n in names],
                    args.out)
    for f, stem in names:
        kw, explicit = _raw_kwargs(args, f, from_file)
        frame = load_frame(f, pattern=args.pattern, bit_depth=args.bit_depth, **kw)
        if explicit and (frame.meta.get("reader") is None
                         or frame.meta.get("source") != str(f)):
            flag = "--" + next(iter(explicit)).replace("_", "-").replace("clip-level",
                                                                         "saturation-level")
            raise CliError(f"{flag}: {f} is an rgbz-fast frame file, which records its own "
                           "pattern and levels; the raw options apply to raw files")
        frame = _with_z_sites(frame, f, args.rgbz_pattern)
        cfa = reconstruct(frame, args.method, params=params, workers=args.workers)
        ref = frame.reference
        dest = args.out / f"{stem}_{args.method}{ext}"
        ref_dest = args.out / f"{stem}_reference{ext}" if ref is not None else None
        if args.output == "cfa":
            _write_cfa(dest, cfa, frame, args.method)
            if ref is not None:
                _write_cfa(ref_dest, ref, frame, "reference")
        else:
            # the colour chain of the evaluation: grey world on the reference when there is
            # one, and the same gains on the reconstruction (Fig. 19)
            chain = ColourISP(precision="float64", black_level=0.0)
            phase = frame.pattern.bayer_phase
            gains = None
            if ref is not None:
                ref_srgb, stages = chain.render(ref, phase, bit_depth=frame.bit_depth,
                                                workers=args.workers, return_stages=True)
                gains = stages["gains"]
                _write_png(ref_dest, ref_srgb)
            _write_png(dest, chain.render(cfa, phase, bit_depth=frame.bit_depth, gains=gains,
                                          workers=args.workers))
        if not args.quiet:
            extra = ""
            if ref is not None:
                psnr = cfa_psnr(ref, cfa, frame.z_mask, bit_depth=frame.bit_depth)
                extra = f", reference {ref_dest}; CFA PSNR at the Z sites {psnr:.2f} dB"
            print(f"{f} -> {dest} ({frame.pattern.name}, {frame.shape[0]}x{frame.shape[1]}"
                  f"{extra})")
    return 0


def _with_z_sites(frame, path, rgbz_pattern):
    """The frame to reconstruct: a plain Bayer frame gets the Z pattern asked for, or fails."""
    if frame.pattern.has_z:
        if rgbz_pattern is not None:
            raise CliError(f"--rgbz-pattern: {path} already has Z sites (pattern "
                           f"{frame.pattern.name}); it applies to plain Bayer raw files")
        return frame
    if rgbz_pattern is None:
        raise CliError(f"--rgbz-pattern: {path} is a plain Bayer frame ({frame.pattern.name}, "
                       "no Z sites), so there is nothing to reconstruct; pass --rgbz-pattern "
                       "mask1 (or mask2, rows) to place Z sites on its CFA and reconstruct them")
    rgbz, _ = to_rgbz(frame, rgbz_pattern)
    return rgbz


# --------------------------------------------------------------------------- depth
_NO_MEASUREMENT = 255


def _depth(args):
    from .tof import ToFCalibration, tof_depth

    for f in args.frames:
        if not f.exists():
            raise CliError(f"path: {f} does not exist")
    calibration = None
    if args.calibration is not None:
        try:
            calibration = ToFCalibration.load(args.calibration)
        except (OSError, ValueError, TypeError, KeyError) as exc:
            raise CliError(f"--calibration: {args.calibration}: {exc}") from None
    outs = [(f, [f"{f.stem}_depth.tif", f"{f.stem}_depth_flags.png", f"{f.stem}_depth.png"])
            for f in args.frames]
    _unique_outputs(outs, args.out)
    for f, (tif_name, flags_name, png_name) in outs:
        frame = load_frame(f)
        if frame.tof is None:
            raise CliError(f"path: {f} holds no ToF taps (simulate a scene with depth, such as "
                           "an RGB-D folder, and save it as .npz)")
        res = tof_depth(frame.tof, denoise=args.denoise, calibration=calibration,
                        min_snr=args.min_snr, max_sigma=args.max_sigma,
                        flying_step=args.flying_step, min_reflectance=args.min_reflectance,
                        max_range=args.max_range, workers=args.workers)
        depth = res.depth_map().astype(np.float32)         # NaN: colour site or flagged
        flags = res.to_frame(res.flags.astype(np.uint16), fill=_NO_MEASUREMENT).astype(np.uint8)
        summary = _depth_summary(frame.tof, res)
        import tifffile

        buf = io.BytesIO()
        tifffile.imwrite(buf, depth, description=json.dumps(
            {"unit": "m", "invalid": "NaN", "source": str(f), **summary}))
        atomic_write(args.out / tif_name, buf.getvalue())
        import imageio.v3 as iio

        atomic_write(args.out / flags_name, iio.imwrite("<bytes>", flags, extension=".png"))
        atomic_write(args.out / png_name, depth_preview(
            res, f.stem, summary, args.range,
            frame.tof.valid if "truth_unknown_fraction" in summary else None))
        if not args.quiet:
            print(f"{f} -> {args.out / tif_name}, {flags_name}, {png_name}: "
                  f"{summary['text']}")
    return 0


def _depth_summary(taps, res):
    """Validity and, for simulated taps, the error against the ground truth (a dict + a line)."""
    n = res.n_sites
    valid = res.valid
    out = {"measurements": n, "valid_fraction": float(valid.mean())}
    text = f"{n} measurements, {100 * valid.mean():.1f} % valid"
    truth = getattr(taps, "depth_true", None)
    known = getattr(taps, "valid", None)
    if truth is not None and known is not None and len(truth) == n:
        both = valid & known
        out["truth_unknown_fraction"] = float(1 - known.mean())
        text += (f"; ground truth unknown at {100 * (1 - known.mean()):.1f} % of them "
                 f"(no disparity, or beyond the range)")
        if both.any():
            err = np.abs(res.depth[both] - truth[both])
            out["median_abs_error_m"] = float(np.median(err))
            out["p95_abs_error_m"] = float(np.percentile(err, 95))
            text += (f"; where both are known, |error| median {1e3 * np.median(err):.1f} mm, "
                     f"95th percentile {1e3 * np.percentile(err, 95):.1f} mm")
    out["text"] = text
    return out


def depth_preview(res, name, summary, scale=None, truth_known=None):
    """An 8-bit colour-mapped PNG of a depth result, with its colour scale (PNG bytes).

    The Z measurements are painted on the frame; colour sites show the
    nearest measurement (the preview only: the TIFF holds NaN there), the
    measurements the ISP flags are grey, and, for a simulated frame
    (``truth_known``: the taps' ground-truth validity), the measurements
    whose ground truth is unknown are shaded red: the scene filled their
    depth in from the nearest known one.
    """
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch
    from scipy import ndimage

    depth = res.to_frame(res.depth)
    valid = res.to_frame(res.valid, fill=False).astype(bool)
    measured = res.to_frame(np.ones(res.n_sites, bool), fill=False).astype(bool)
    idx = ndimage.distance_transform_edt(~measured, return_distances=False,
                                         return_indices=True)
    depth = depth[idx[0], idx[1]]
    valid = valid[idx[0], idx[1]]
    unknown = None
    if truth_known is not None and not np.all(truth_known):
        unknown = res.to_frame(~np.asarray(truth_known, bool), fill=False).astype(bool)
        unknown = unknown[idx[0], idx[1]]
    good = depth[valid]
    if scale is None:
        scale = (float(np.percentile(good, 1)), float(np.percentile(good, 99))) if good.size \
            else (0.0, 1.0)
        if scale[1] <= scale[0]:
            scale = (scale[0], scale[0] + 1e-3)
    rows, cols = depth.shape
    width = 6.4
    fig, ax = plt.subplots(figsize=(width, width * rows / cols * 0.92 + 0.9))
    cmap = matplotlib.colormaps["viridis"].with_extremes(bad="0.6")
    im = ax.imshow(np.ma.masked_where(~valid, depth), cmap=cmap, vmin=scale[0], vmax=scale[1],
                   interpolation="nearest")
    handles = [Patch(color="0.6", label="no valid depth (flagged)")]
    if unknown is not None:
        overlay = np.zeros(depth.shape + (4,))
        overlay[unknown] = (0.85, 0.1, 0.1, 0.55)
        ax.imshow(overlay, interpolation="nearest")
        handles.append(Patch(color=(0.85, 0.1, 0.1, 0.55),
                             label=f"ground truth unknown "
                                   f"({100 * summary['truth_unknown_fraction']:.1f} %)"))
    ax.set_xticks([])
    ax.set_yticks([])
    bar = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.02, extend="both")
    bar.set_label("distance (m)")
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.0, -0.01), fontsize=8,
              frameon=False, ncol=2)
    ax.set_title(f"{name}: depth, {100 * summary['valid_fraction']:.1f} % of "
                 f"{summary['measurements']} measurements valid", fontsize=9)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


# --------------------------------------------------------------------------- evaluate
def _evaluate(args):
    params = ReconstructParams(precision=args.precision, domain=args.domain,
                               clip_level=args.clip_level, filters=args.filters)
    optics = None
    if args.optics:
        optics = Optics(f_number=args.f_number, olpf=args.olpf, defocus_um=args.defocus_um)
    elif (args.f_number, args.olpf, args.defocus_um) != (2.8, 0.0, 0.0):
        raise CliError("--f-number, --olpf and --defocus-um need --optics")
    config = EvalConfig(patterns=args.patterns, methods=args.methods, metrics=args.metrics,
                        noise=args.noise, bit_depth=args.bit_depth, linearise=args.linearise,
                        demosaic=args.demosaic, crop=args.crop, params=params, optics=optics)
    raw_options = None
    if args.raw_options is not None:
        raw_options = _raw_options_file(args.raw_options)
    if args.dataset:
        dataset = folder_dataset(args.dataset, args.limit, raw_options, grey=args.grey)
    else:
        dataset = sample_dataset()[:args.limit]
    cache = None if args.no_cache else (args.cache or args.out / "cache")
    res = evaluate(dataset, config, cache_dir=cache, processes=args.processes,
                   workers=args.workers, scheduler=args.scheduler, progress=not args.quiet,
                   skip_bad=args.skip_bad)
    for name, why in res.skipped:
        print(f"rgbz-fast evaluate: skipped {name}: {_for_the_command_line(why)}",
              file=sys.stderr)
    if not res.rows:
        raise CliError(f"dataset: none of the {len(dataset)} image(s) could be evaluated")
    crop_src = None
    if not args.no_plots and config.image_metrics:
        done = [s for s in dataset if s.name in res.images()]
        crop_src = next((s for s in done if s.name == (args.table_image or "kodim09")), done[0])
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


def _train(args):
    if not args.dataset.is_dir():
        raise CliError(f"--dataset: {args.dataset} is not a folder")
    command = " ".join(["rgbz-fast train", *sys.argv[2:]]) if sys.argv[1:2] == ["train"] else ""
    filters = train_filters(
        args.dataset, args.pattern, bit_depth=args.bit_depth, noise=args.noise,
        linearise=args.linearise, limit=args.limit, name=args.name, progress=not args.quiet,
        radius=args.radius, hash_radius=args.hash_radius, n_strength=args.strength,
        n_coherence=args.coherence, ridge=args.ridge, prior=args.prior,
        meta={"command": command} if command else {})
    filters.save(args.out)
    if not args.quiet:
        m = filters.meta
        print(f"{filters} -> {args.out} ({m['n_images']} images, {m['n_sites']} sites, "
              f"{m['empty_buckets']} empty buckets)")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
