"""``rgbz-fast opcount``: operations per missing pixel beside the paper's Table 1."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from . import _common as c

NAME = "opcount"


def add_parser(sub):
    p = c.command_parser(
        sub, NAME, "operations per missing pixel vs Table 1",
        "Arithmetic operations per reconstructed pixel, beside the paper's Table 1.\n\n"
        "Counts come from the counting build of the C kernels (-DRGBZ_COUNT_OPS).")
    c.add_methods(p, "bilinear,bi,edi_central,edi_line,sg,learned")
    c.add_patterns(p)
    c.add_precision(p, "float64", "arithmetic of the counted kernels")
    c.add_shape(p, "64x64", "random frame size ROWSxCOLS (default 64x64)")
    c.add_seed(p, 0, "seed of the random frame")
    p.add_argument("--image", default="astronaut",
                   help="also count on a 128x128 crop of this image: a scikit-image sample "
                        "name, an image file, or 'none'")
    p.add_argument("--text", action="store_true", help="plain-text table instead of Markdown")
    c.add_report_options(p, workers=False)
    return p


def run(args):
    from .._devtools._common import json_text
    from .._patterns import get_pattern

    opcount = c.tool("opcount")
    if args.quick and c.given(args, "shape"):
        raise c.CliError("--shape: --quick counts on a 32x32 frame; give one of them")
    shape = (32, 32) if args.quick else c.made_shape(args, args.shape)
    out = c.output_folder(args.out)
    methods = [m.lower() for m in args.methods]        # as reconstruct() takes them
    for i, m in enumerate(methods):
        if m in methods[:i]:
            raise c.CliError(f"--methods: {args.methods[i]!r} is given twice (as {m!r})")
    image, image_name = _image(args.image)
    names = c.z_patterns(args.patterns)
    pats = [get_pattern(n) for n in names]
    if image is not None:
        for name, p in zip(names, pats):
            need = _image_need(p)
            if any(min(s, 128) // per * per < n for s, per, n in
                   zip(image.shape[:2], p.period, need)):
                raise c.CliError(f"--image: {image_name} is {image.shape[0]}x"
                                 f"{image.shape[1]}; pattern {name!r} needs a crop of at least "
                                 f"{need[0]}x{need[1]} whole periods")
    rows = opcount.opcount_table(methods, args.patterns, precision=args.precision,
                                 shape=shape, seed=args.seed, image=image, image_name=image_name)
    tof = opcount.count_tof_operations()
    legend = opcount.opcount_legend(shape, args.seed, args.precision, image_name, tof,
                                    None if image is None else image.shape,
                                    [p.period for p in pats])
    doc = json_text({"rows": rows, "tof_demodulate": tof, "legend": legend})
    if args.json:                # printed before the files: a failed write keeps it
        print(doc)
    else:
        print(opcount.opcount_report(rows, "text" if args.text else "markdown"))
        print()
        print(legend)
    c.write_report(out, {"opcount.md": opcount.opcount_report(rows, "markdown") + "\n\n"
                         + legend + "\n", "opcount.json": doc + "\n"})
    return 0


def _image_need(pattern):
    """The smallest crop (rows, cols) of whole periods whose interior (2 pixels from each
    border, the 5x5 window) holds a Z site of ``pattern`` wherever the crop starts."""
    P, Q = pattern.period
    return (-(-(P + 4) // P) * P, -(-(Q + 4) // Q) * Q)


def _image(spec):
    """(8-bit RGB image, its name) of ``--image``: a file, a scikit-image sample, or none."""
    if spec is None or str(spec).lower() == "none":
        return None, None
    if Path(spec).is_file():
        from ..io import read_image

        img = read_image(spec, "--image")
        if img.ndim != 3 or img.shape[2] < 3 or img.dtype != np.uint8:
            raise c.CliError(f"--image: expected an 8-bit RGB image, got {img.dtype} "
                             f"{img.shape}")
        return np.ascontiguousarray(img[..., :3]), Path(spec).name
    import skimage.data

    # only the shipped RGB samples: any other attribute of skimage.data was called
    # (data_dir, __spec__, download_all, which would fetch every sample)
    if str(spec) not in SKIMAGE_RGB:
        raise c.CliError(f"--image: {spec!r} is neither a file nor one of scikit-image's RGB "
                         f"sample images ({', '.join(SKIMAGE_RGB)})")
    try:
        img = np.asarray(getattr(skimage.data, str(spec))())
    except Exception as exc:  # noqa: BLE001 - a sample scikit-image may have to download
        raise c.CliError(f"--image: cannot load scikit-image's {spec!r} ({exc})") from None
    if img.ndim != 3 or img.shape[2] < 3 or img.dtype != np.uint8:
        raise c.CliError(f"--image: {spec!r} is not an 8-bit RGB image")
    return np.ascontiguousarray(img[..., :3]), f"skimage.data.{spec}"


#: scikit-image's 8-bit RGB sample images that ship with it (no download)
SKIMAGE_RGB = ("astronaut", "chelsea", "coffee", "colorwheel", "hubble_deep_field",
               "immunohistochemistry", "retina", "rocket")
