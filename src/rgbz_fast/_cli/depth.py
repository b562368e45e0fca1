"""``rgbz-fast depth``: frames with ToF taps -> depth map (float TIFF), flags, preview."""

from __future__ import annotations

import io
import json

import numpy as np

from . import _common as c

NAME = "depth"
DEFAULT_OUT = "rgbz_depth"
#: the flags map's value at the pixels that hold no Z measurement (colour sites)
NO_MEASUREMENT = 255


def add_parser(sub):
    p = c.command_parser(
        sub, NAME, "frame(s) with ToF taps -> depth map, flags, preview",
        "Run the ToF ISP (four-tap demodulation, edge-aware denoise, three-frequency "
        "unwrapping, validity) on the taps of frames simulated from scenes with depth. Writes, "
        "per frame, OUT/<name>_depth.tif (float32 metres on the frame grid, NaN where there is "
        "no valid measurement: the colour sites and the flagged Z pixels), "
        "OUT/<name>_depth.png (a colour-mapped preview with its scale), "
        "OUT/<name>_depth-flags.png (why each measurement is flagged: a map with a legend) "
        "and OUT/<name>_depth-flags.tif (uint8 on the frame grid: 0 valid, bits 1 saturated, "
        "2 low signal, 4 inconsistent frequencies, 8 flying pixel, 16 out of range, 32 resolved "
        "by the colour guide; 255 colour site). Prints how much is valid, why the rest is flagged and, for simulated frames, "
        "the error against the ground truth and how much of it is unknown.")
    p.add_argument("frames", nargs="+", type=c.path,
                   help=".npz frames from `rgbz-fast simulate` of scenes with depth")
    p.add_argument("--denoise", choices=("bilateral", "box", "none"), default="bilateral",
                   help="phasor denoise: edge-aware over the 5x5 nearest Z pixels, the paper's "
                        "plain 5x5 average (Fig. 17), or none")
    p.add_argument("--calibration", type=c.path, default=None, metavar="FILE",
                   help="phase calibration from `rgbz-fast calibrate` (default: none)")
    p.add_argument("--min-snr", type=c.non_negative_float, default=4.0,
                   help="flag measurements whose signal-to-noise ratio is below this (0: no "
                        "test)")
    p.add_argument("--max-range", type=c.positive_float, default=None, metavar="METRES",
                   help="unwrapping range (default: the unambiguous range of the frequencies)")
    p.add_argument("--max-sigma", type=c.off_or(c.positive_float), default=0.015,
                   metavar="METRES|off",
                   help="flag measurements whose predicted depth noise is above this")
    p.add_argument("--flying-step", type=c.off_or(c.positive_float), default=0.05,
                   metavar="METRES|off",
                   help="flag flying pixels: a depth step to a neighbour above this (and 2 "
                        "sigma); off keeps them")
    p.add_argument("--min-reflectance", type=c.number(float, lambda v: 0 <= v <= 1,
                                                      "a number in [0, 1]"), default=0.05,
                   help="flag measurements whose implied reflectance is below this (a surface "
                        "beyond the unambiguous range, aliased nearer)")
    p.add_argument("--max-reflectance", type=c.off_or(c.number(float, lambda v: 1 <= v < float(
                       "inf"), "a number >= 1")), default=4.0, metavar="R|off",
                   help="flag measurements whose implied reflectance is above this (a depth "
                        "unwrapped to a wrong, farther alias); off keeps retroreflectors")
    p.add_argument("--range", type=c.metre_range, default=None, metavar="MIN:MAX",
                   help="colour scale of the preview in metres (default: the 1st to 99th "
                        "percentile of the valid depth)")
    p.add_argument("--full-resolution", action="store_true",
                   help="also run the colour ISP, guide the ToF ISP with its image and write "
                        "a depth at every pixel: OUT/<name>_depth-full.tif (float32 metres, "
                        "NaN where none can be given), OUT/<name>_depth-full.png (preview) and "
                        "OUT/<name>_depth-full-confidence.tif (float32 in [0, 1]: low in holes "
                        "and at colour edges); "
                        "the map also takes the measurements flagged low-signal alone whose "
                        "sigma is at most 2 cm and that a usable neighbour confirms, whatever "
                        "--max-sigma")
    c.add_run_options(p, DEFAULT_OUT)
    return p


def run(args):
    import tifffile

    from .._devtools.plots import (depth_flags_figure, depth_preview, depth_scale,
                                   full_depth_preview, nearest_measurement)
    from ..io import load_frame
    from ..io._files import atomic_write_all
    from ..tof import ToFCalibration, tof_depth

    c.must_exist(args.frames)
    out = c.output_folder(args.out)
    calibration = None
    if args.calibration is not None:
        try:
            calibration = ToFCalibration.load(args.calibration, max_bytes=args.max_bytes)
        except (OSError, ValueError, TypeError, KeyError) as exc:
            raise c.CliError(f"--calibration: {args.calibration}: {c.explain(exc)}") from None
    full = FULL_PRODUCTS if args.full_resolution else ()
    outs = [(f, [f.stem + x for x in PRODUCTS + full]) for f in args.frames]
    c.unique_outputs(outs, out, reads=[args.calibration])
    with c.batch(args, outs, out) as done:
        for f, (tif_name, png_name, flags_name, bits_name, *full_names) in outs:
            frame = load_frame(f, **c.limits(args))
            if frame.tof is None:
                raise c.CliError(f"path: {f} holds no ToF taps (simulate a scene with depth, such "
                                 "as an RGB-D folder, and save it as .npz)")
            guide = None
            if full_names:                 # the frame's own colour image, as a chip would have it
                from ..isp import ColourISP
                guide = ColourISP().run(frame, workers=args.workers)
            res = tof_depth(frame.tof, denoise=args.denoise, calibration=calibration,
                            min_snr=args.min_snr, max_sigma=args.max_sigma,
                            flying_step=args.flying_step, min_reflectance=args.min_reflectance,
                            max_reflectance=args.max_reflectance,
                            max_range=args.max_range, guide=guide, workers=args.workers)
            depth = res.depth_map().astype(np.float32)         # NaN: colour site or flagged
            flags = res.to_frame(res.flags.astype(np.uint16), fill=NO_MEASUREMENT).astype(np.uint8)
            summary = depth_summary(frame.tof, res)
            # the frame's files all or none (each to a temporary file, renamed when every one
            # is written: a full disk leaves a previous run's set as it was, H126)
            made = []
            buf = io.BytesIO()
            tifffile.imwrite(buf, depth, description=json.dumps(
                {"unit": "m", "invalid": "NaN", "source": str(f), **summary}))
            made.append((out / tif_name, buf.getvalue()))
            bits = io.BytesIO()
            tifffile.imwrite(bits, flags, description=json.dumps(
                {"flags": FLAG_LEGEND, "colour site": NO_MEASUREMENT, "source": str(f)}))
            made.append((out / bits_name, bits.getvalue()))
            title = (f"{f.stem}: depth, {100 * summary['valid_fraction']:.1f} % of "
                     f"{summary['measurements']} measurements valid")
            nearest = nearest_measurement(res)                  # both figures' grid
            # one colour scale for both previews of the frame (each had taken its own 1st-99th
            # percentile: one colour was two depths in two figures written side by side)
            scale = args.range if args.range is not None else depth_scale(res, nearest)
            made.append((out / png_name, depth_preview(
                res, title, scale,
                frame.tof.valid if "truth_unknown_fraction" in summary else None, nearest)))
            made.append((out / flags_name, depth_flags_figure(
                res, f"{f.stem}: why measurements are flagged", nearest)))
            if full_names:
                from ..tof import upsample_depth
                up, conf = upsample_depth(res, guide, workers=args.workers)
                buf = io.BytesIO()
                tifffile.imwrite(buf, up, description=json.dumps(
                    {"unit": "m", "invalid": "NaN", "source": str(f),
                     "covered_fraction": float(np.isfinite(up).mean())}))
                made.append((out / full_names[0], buf.getvalue()))
                made.append((out / full_names[1], full_depth_preview(
                    up, f"{f.stem}: depth at every pixel", scale)))
                buf = io.BytesIO()                  # how much each depth is to be trusted
                tifffile.imwrite(buf, conf, description=json.dumps(
                    {"unit": "1", "range": [0, 1], "source": str(f),
                     "meaning": "summed weight of the measurements the depth comes from; 0 where "
                                "it is NaN"}))
                made.append((out / full_names[2], buf.getvalue()))
            atomic_write_all(made)
            if not args.quiet:
                extra = "".join(f", {n}" for n in full_names)
                print(f"{f} -> {out / tif_name}, {png_name}, {flags_name}, {bits_name}{extra}: "
                      f"{summary['text']}")
            done.append(f)
    if not args.quiet:
        left = [f.stem + x for f in args.frames for x in PRODUCTS + FULL_PRODUCTS]
        c.tell_earlier_outputs(out, left, [n for _, names in outs for n in names], NAME)
    return 0


#: what ``depth`` writes per frame, after the frame's stem; with --full-resolution also
#: FULL_PRODUCTS
PRODUCTS = ("_depth.tif", "_depth.png", "_depth-flags.png", "_depth-flags.tif")
FULL_PRODUCTS = ("_depth-full.tif", "_depth-full.png", "_depth-full-confidence.tif")


#: the flag bits of the flags TIFF, as its description gives them
FLAG_LEGEND = {"1": "saturated", "2": "low signal", "4": "inconsistent frequencies",
               "8": "flying pixel", "16": "out of range", "32": "resolved by the colour guide"}


def depth_summary(taps, res):
    """Validity, why the rest is flagged (the share of the measurements each flag marks; one
    may carry several) and, for simulated taps, the error against the ground truth (a dict
    + a line)."""
    from .._devtools.plots import flag_bits

    n = res.n_sites
    valid = res.valid
    out = {"measurements": n, "valid_fraction": float(valid.mean())}
    text = f"{n} measurements, {100 * valid.mean():.1f} % valid"
    flags = np.asarray(res.flags).astype(np.int64)
    flagged = {label: float(np.mean((flags & bit) != 0)) for label, bit in flag_bits().items()}
    out["flagged_fraction"] = flagged
    shares = sorted(((v, k) for k, v in flagged.items() if v > 0), reverse=True)
    if shares:
        text += "; flagged: " + ", ".join(
            (f"{100 * v:.1f} %" if v >= 5e-4 else "< 0.1 %") + f" {k}" for v, k in shares)
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
