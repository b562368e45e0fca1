"""``rgbz-fast reconstruct``: RGB-Z frames, or camera raw / Bayer files given a Z pattern ->
Bayer CFA or sRGB image (and the reference it is compared with)."""

from __future__ import annotations

import io
import warnings

import numpy as np

from . import _common as c
from ._raw import RAW_FLAGS, add_raw_group, raw_kwargs, raw_options_file

NAME = "reconstruct"
DEFAULT_OUT = "rgbz_out"


def add_parser(sub):
    from ..reconstruction import METHODS

    p = c.command_parser(
        sub, NAME, "raw frame(s) -> Bayer CFA or sRGB image",
        "Fill in the colour missing at the Z sites. Frames from `rgbz-fast simulate` carry "
        "their pattern. A real Bayer raw (camera raw, 16-bit Bayer PNG/TIFF, headerless .raw) "
        "has no Z sites: --rgbz-pattern places one on its CFA (the Z sites are dropped, then "
        "reconstructed, and the real CFA is the reference). Writes "
        "OUT/<name>_<method>_cfa.tif (<name>_<pattern>_<method>_cfa.tif for a file read with "
        "--pattern or --rgbz-pattern; .png with --output srgb) and, when there is one, the "
        "reference, and prints the CFA PSNR at the Z sites.")
    p.add_argument("frames", nargs="+", type=c.path,
                   help=".npz/.tif frames from `rgbz-fast simulate`, or camera raw / Bayer files")
    p.add_argument("--method", default="sg",
                   help=f"reconstruction method: {', '.join(METHODS)}")
    p.add_argument("--rgbz-pattern", default=None, type=rgbz_pattern,
                   metavar="mask1|mask2|rows|TILE",
                   help="place this Z pattern on the CFA of a plain Bayer raw, on its own Bayer "
                        "phase: a preset is built on it, a tile such as ZRGR/BGBG/GRZR/BGBG is "
                        "shifted onto it by a row and/or a column (default: none; a raw "
                        "without Z sites needs one)")
    c.add_pattern(p, None, "the RGB-Z pattern of a plain 16-bit TIFF/PNG mosaic that holds Z "
                           "sites but no rgbz-fast header, with --bit-depth (default: none; "
                           "frames from simulate carry theirs)")
    c.add_bit_depth(p, None, "bits of a plain TIFF/PNG mosaic given with --pattern; for a raw "
                             "file, the working bit depth it is scaled to (default: the file's "
                             "own: --bit-depth-in, or the bits of its white level: 14 for a "
                             "14-bit DNG, 12 with --white-level 4000)")
    c.add_reconstruction_options(p, "float32", "arithmetic of the kernel")
    p.add_argument("--output", choices=("cfa", "srgb"), default="cfa",
                   help="cfa: 16-bit TIFF Bayer CFA; srgb: 8-bit PNG through the colour ISP")
    colour = p.add_argument_group("colour of --output srgb")
    colour.add_argument("--white-balance", type=white_balance, default="auto",
                        metavar="auto|grey-world|R,G,B",
                        help="auto: the gains the file records (a camera raw's as-shot white "
                             "balance, a simulated spectral sensor's white), else grey world "
                             "on the reference; or three gains (default: auto)")
    colour.add_argument("--colour-matrix", type=colour_matrix, default="auto",
                        metavar="auto|none|M11,...,M33",
                        help="white-balanced camera RGB -> linear sRGB: auto: the matrix the "
                             "file records (a camera raw's, a simulated spectral sensor's), "
                             "else none; none: the identity; or nine numbers, row by row "
                             "(default: auto)")
    add_raw_group(p)
    c.add_run_options(p, DEFAULT_OUT)
    return p


def rgbz_pattern(text):
    """A preset name or a tile with Z sites whose colour sites fit a Bayer phase."""
    import argparse

    from .._patterns import get_pattern

    try:
        pattern = get_pattern(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(" ".join(str(exc).split())) from None
    if not pattern.has_z or pattern.bayer_phase is None:
        raise argparse.ArgumentTypeError(
            f"expected a pattern with Z sites whose colour sites fit a Bayer phase (mask1, "
            f"mask2, rows or a tile such as ZRGR/BGBG/GRZR/BGBG), got {text!r}")
    return text.strip()


def _numbers(text, n, what):
    import argparse

    try:
        vals = tuple(float(v) for v in text.split(","))
    except ValueError:
        vals = ()
    if len(vals) != n or not all(abs(v) < float("inf") for v in vals):
        raise argparse.ArgumentTypeError(f"expected {what}, got {text!r}")
    return vals


def white_balance(text):
    """auto, grey-world or three positive gains R,G,B."""
    t = text.strip().lower()
    if t in ("auto", "grey-world"):
        return t
    gains = _numbers(t, 3, "auto, grey-world or three gains R,G,B")
    if min(gains) <= 0:
        import argparse

        raise argparse.ArgumentTypeError(f"expected positive gains, got {text!r}")
    return gains


def colour_matrix(text):
    """auto, none or nine numbers, row by row."""
    t = text.strip().lower()
    if t in ("auto", "none"):
        return t
    m = _numbers(t, 9, "auto, none or nine comma-separated numbers (the 3x3 matrix row by row)")
    from ..isp._stages import MATRIX_MAX

    if max(abs(v) for v in m) > MATRIX_MAX:
        import argparse

        raise argparse.ArgumentTypeError(f"expected entries within +-{MATRIX_MAX:g} (a "
                                         f"camera's lie within about 10), got {text!r}")
    return (m[0:3], m[3:6], m[6:9])


def run(args):
    from ..io import load_frame
    from ..metrics import cfa_psnr
    from ..reconstruction import NEEDS_TOF, ReconstructParams, reconstruct

    if args.pattern is not None and args.rgbz_pattern is not None:
        raise c.CliError("--pattern: names the pattern of a plain mosaic that already holds Z "
                         "sites; --rgbz-pattern places one on a Bayer raw; give one of them")
    if args.pattern is not None and any(getattr(args, f) is not None for f, _ in RAW_FLAGS):
        raise c.CliError("--pattern: a plain RGB-Z mosaic is read as it is stored; the raw "
                         "options (--phase, --black-level, ...) apply to Bayer raw files, with "
                         "--rgbz-pattern")
    if args.saturation_level is not None and args.clip_level != "auto":
        # the level a raw file is read with reaches the reconstruction through auto alone
        raise c.CliError("--saturation-level: takes effect with --clip-level auto (off takes "
                         "every pixel as a real value, a number is its own level)")
    if args.output == "cfa":
        for flag, value in (("--white-balance", args.white_balance),
                            ("--colour-matrix", args.colour_matrix)):
            if value != "auto":                  # the CFA output has neither applied
                raise c.CliError(f"{flag}: applies to --output srgb; the CFA output is the "
                                 "raw values")
    params = ReconstructParams(precision=args.precision, domain=args.domain,
                               clip_level=args.clip_level, filters=c.learned_filters(args))
    from_file = raw_options_file(args.raw_options)
    c.must_exist(args.frames)
    out = c.output_folder(args.out)
    # the pattern a file is read with is in its outputs' names (a plain mosaic read with two
    # patterns in turn had written both to one name, the second over the first)
    given = args.rgbz_pattern or args.pattern
    label = given and f"_{c.file_label(given)}"
    method = c.file_label(args.method)
    ext = "_cfa.tif" if args.output == "cfa" else ".png"
    names = [(f, f"{f.stem}{label or ''}") for f in args.frames]
    c.unique_outputs([(f, [f"{n}_{method}{ext}", f"{n}_reference{ext}"]) for f, n in names], out,
                     reads=[*(args.filters or ()), args.raw_options])
    with c.batch(args, names, out) as done:
        for f, stem in names:
            kw, explicit = raw_kwargs(args, f, from_file)
            # a raw file keeps its own bit depth unless --bit-depth says otherwise
            bit_depth = args.bit_depth if args.bit_depth is not None or args.pattern is not None \
                else "input"
            try:
                with warnings.catch_warnings(record=True) as said:
                    warnings.simplefilter("always")
                    frame = load_frame(f, pattern=args.pattern, bit_depth=bit_depth,
                                       **c.limits(args), **kw)
            except ValueError as exc:
                # load_frame refuses raw options for a frame file (they had been ignored when they
                # came from --raw-options); the flags are named by the error mechanism
                key, _, rest = str(exc).partition(": ")
                if key in kw and key not in explicit:
                    raise c.CliError(f"--raw-options: {key} for {f.name}: {rest}") from None
                flags = {k: "--" + dest.replace("_", "-") for dest, k in RAW_FLAGS}
                if key in explicit and key in flags:       # --saturation-level gives clip_level
                    raise c.CliError(f"{flags[key]}: {rest}") from None
                raise
            for w in said:            # "white_level: ..." of the reader is this --white-level
                warnings.warn(c.flag_words(str(w.message), args.parser), w.category,
                              stacklevel=1)
            frame = _with_z_sites(frame, f, args.rgbz_pattern)
            if args.method.strip().lower() in NEEDS_TOF and frame.tof is None:
                # the library's advice (pass nir=) has no flag here: say what a user of the
                # command does
                raise c.CliError(f"--method {args.method.strip()}: {f} carries no ToF taps, and "
                                 "the method is guided by the NIR amplitude the Z pixels measure; "
                                 "give a frame simulated from a scene with depth (rgbz-fast "
                                 "simulate SCENE_FOLDER holding rgb.png, disp1.png, dmin.txt) or "
                                 "another --method")
            try:
                cfa = reconstruct(frame, args.method, params=params, workers=args.workers)
            except ValueError as exc:
                # about the frame read ("frame: its saturation level ..." of a frame file
                # saved with one at its black level): which file
                what, _, rest = str(exc).partition(": ")
                if what != "frame":
                    raise
                raise c.CliError(f"{f}: {rest}") from None
            ref = frame.reference
            dest = out / f"{stem}_{method}{ext}"
            ref_dest = out / f"{stem}_reference{ext}" if ref is not None else None
            if args.output == "cfa":
                _write_cfa(dest, cfa, frame, args.method.strip().lower())
                if ref is not None:
                    _write_cfa(ref_dest, ref, frame, "reference")
            else:
                _write_srgb(dest, ref_dest, cfa, frame, args)
            if not args.quiet:
                extra = ""
                if ref is not None:
                    psnr = cfa_psnr(ref, cfa, frame.z_mask, bit_depth=frame.bit_depth)
                    extra = f", reference {ref_dest}; CFA PSNR at the Z sites {psnr:.2f} dB"
                print(f"{f} -> {dest} ({frame.pattern.name}, {frame.shape[0]}x{frame.shape[1]}"
                      f"{extra})")
            done.append(f)
    return 0


def _with_z_sites(frame, path, rgbz_pattern):
    """The frame to reconstruct: a plain Bayer frame gets the Z pattern asked for, or fails."""
    from ..io import to_rgbz

    if frame.pattern.has_z:
        if rgbz_pattern is not None:
            raise c.CliError(f"--rgbz-pattern: {path} already has Z sites (pattern "
                             f"{frame.pattern.name}); it applies to plain Bayer raw files")
        return frame
    if rgbz_pattern is None:
        raise c.CliError(f"--rgbz-pattern: {path} is a plain Bayer frame ({frame.pattern.name}, "
                         "no Z sites), so there is nothing to reconstruct; pass --rgbz-pattern "
                         "mask1 (or mask2, rows, a tile) to place Z sites on its CFA and "
                         "reconstruct them")
    rgbz, _ = to_rgbz(frame, rgbz_pattern)
    return rgbz


def _write_cfa(dest, cfa, frame, method):
    """The CFA as a 16-bit TIFF that describes itself: its Bayer phase, the black level that
    stays in its data (a simulated sensor's; 0 for a raw file's, subtracted when read), its
    white level, bit depth and method, under the key by which the raw reader knows the file
    as rgbz-fast's (``reconstruct OUT/x_cfa.tif --rgbz-pattern ...`` reads it back; it had
    asked for --phase, --black-level and --white-level)."""
    import tifffile

    from ..io import atomic_write
    from ..io._raw import cfa_tiff_description
    from ..isp import recorded_rendering

    buf = io.BytesIO()
    data = cfa if cfa.dtype in (np.uint8, np.uint16) else \
        np.floor(np.clip(cfa, 0, frame.white_level) + 0.5).astype(np.uint16)
    black = recorded_rendering(frame)["black_level"] or 0.0
    tifffile.imwrite(buf, data, description=cfa_tiff_description(
        frame.pattern.bayer_phase, black, frame.white_level, frame.bit_depth, method=method))
    atomic_write(dest, buf.getvalue())


def _write_srgb(dest, ref_dest, cfa, frame, args):
    """8-bit sRGB PNGs through the evaluation's colour chain, with the black level, white
    balance and colour matrix the frame records unless the options say otherwise: the gains
    found on the reference when there is one are used on the reconstruction (Fig. 19)."""
    from ..io import atomic_write
    from ..isp import ColourISP, recorded_rendering

    recorded = recorded_rendering(frame)
    chain = ColourISP(precision="float64", black_level=recorded["black_level"] or 0.0)
    gains = recorded["white_gains"] if args.white_balance == "auto" else \
        None if args.white_balance == "grey-world" else args.white_balance
    matrix = recorded["colour_matrix"] if args.colour_matrix == "auto" else \
        None if args.colour_matrix == "none" else args.colour_matrix
    kw = dict(bit_depth=frame.bit_depth, white_level=recorded["white_level"],
              colour_matrix=matrix, workers=args.workers)
    phase = frame.pattern.bayer_phase
    if frame.reference is None:
        atomic_write(dest, c.png_bytes(chain.render(cfa, phase, gains=gains, **kw)))
        return
    if gains is None:                       # the reference's own, as render finds them
        gains = chain.white_balance_gains(frame.reference, phase, bit_depth=frame.bit_depth,
                                          white_level=recorded["white_level"])
    ref_srgb = chain.render(frame.reference, phase, gains=gains, **kw)
    # the reference's PNG is deflated on a thread (Pillow releases the GIL) while the
    # reconstruction renders and deflates its own
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(1) as ex:
        pending = ex.submit(lambda: atomic_write(ref_dest, c.png_bytes(ref_srgb)))
        atomic_write(dest, c.png_bytes(chain.render(cfa, phase, gains=gains, **kw)))
        pending.result()
