"""The learned method against every reconstruction that does not use the Z pixels.

    python tools/learned_targets.py [--heldout DIR] [--data DIR] [--sets a,b] [--out FILE]
                                    [--folder NAME=DIR[:K] ...]

For every set x mask x encoding: the mean CFA PSNR at the Z sites of ``learned`` and of every
method of the library that does not read the Z pixels (bilinear, BI, EDICentral, EDILine, SG,
each in the intensity and the colour-difference domain), the best of those and the margins
``learned - best`` and ``learned - SG``, against the targets of docs/guide/learned.md
(learned >= the best of them + 0.3 dB and >= SG + 1.5 dB).

Sets: Kodak (24), Kodak with the saturation doubled (the first 12 in name order: skimage
rgb2hsv on the 8-bit values, S x 2 clipped at 1, hsv2rgb, rounded to 8 bits), and the
held-out quarter of CBSD68, Manga109 (the 24 pages of train_extra) and Sun-Hays 80 (every
fourth image in name order, starting with the first).
Encodings:
* ``linear``: ``rgbz-fast evaluate``'s default protocol (sRGB EOTF, noise-free mosaic at 11
  bits, float64 arithmetic);
* ``srgb``: the 8-bit values mosaicked at 11 bits without linearisation,
  ``rz.mosaic(img8, pattern)`` then ``rz.reconstruct(frame, method)`` (float32);
* ``srgb8``: ``rgbz-fast evaluate --bit-depth 8 --no-linearise`` (8-bit frames, float64).
Filters: the shipped ones on Kodak (no Kodak image is in any fit); on the held-out parts, the
filters of ``python tools/learned_fit.py MASK OUT --heldout`` (without the held-out quarter of
any folder: the shipped ones are that fit), read from (or, when missing, fitted into)
``--heldout`` (about 15 minutes per mask on 2 busy cores).

``--folder NAME=DIR`` adds the images of DIR (every image file, in name order) as a set NAME
scored with the shipped filters, as Kodak is: for image sets no fit saw (McMaster, PolyU:
docs/reports/learned.md). ``NAME=DIR:K`` scores them with the saturation multiplied by K as
saturated Kodak's is (``--folder kodak_sat24=../shared/data/kodak:2``: all 24). With
``--folder``, ``--sets`` defaults to none.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

import rgbz_fast as rz
from rgbz_fast.evaluation import EvalConfig, image_frames
from rgbz_fast.io import folder_dataset
from rgbz_fast.metrics import cfa_psnr
from rgbz_fast.reconstruction import LearnedFilters

sys.path.insert(0, str(Path(__file__).resolve().parent))
from learned_fit import DATA, fit, heldout_split, saturate  # noqa: E402

# bilinear interpolates the intensities only (it refuses the colour-difference domain: H75)
NON_Z = [("bilinear", "intensity")] + [(m, d) for m in ("bi", "edi_central", "edi_line", "sg")
                                       for d in ("intensity", "colour_difference")]
LABEL = {"bilinear": "bilinear", "bi": "BI", "edi_central": "EDICentral",
         "edi_line": "EDILine", "sg": "SG"}
SETS = ("kodak", "kodak_sat", "cbsd68", "manga109", "sun_hays80")
ENCODINGS = ("linear", "srgb", "srgb8")
MASKS = ("mask1", "mask2")
TARGET_BEST, TARGET_SG = 0.3, 1.5


def boost_saturation(img8):
    """The issue's saturated Kodak: HSV saturation x 2 (clipped at 1), rounded to 8 bits."""
    return saturate(img8, 2.0)


def folder_images(spec):
    """(name, images) of a ``--folder NAME=DIR[:K]`` argument."""
    name, sep, rest = spec.partition("=")
    if not sep or not name or not rest:
        raise SystemExit(f"--folder: expected NAME=DIR or NAME=DIR:K, got {spec!r}")
    folder, k = rest, None
    head, colon, tail = rest.rpartition(":")
    if colon and head:
        try:
            folder, k = head, float(tail)
        except ValueError:
            folder = rest
    imgs = [s.load() for s in folder_dataset(Path(folder))]
    return name, [saturate(im, k) for im in imgs] if k else imgs


def images(name, data):
    if name == "kodak":
        return [s.load() for s in folder_dataset(data / "kodak")]
    if name == "kodak_sat":
        return [boost_saturation(s.load()) for s in folder_dataset(data / "kodak")[:12]]
    held, _ = heldout_split(name, data)
    return [s.load() for s in held]


def frames(img, mask, encoding):
    """(frame, reference CFA, precision) of one image in one encoding."""
    if encoding == "srgb":
        pattern = rz.get_pattern(mask)
        return rz.mosaic(img, pattern), rz.mosaic(img, pattern.bayer_pattern()).data, "float32"
    cfg = EvalConfig() if encoding == "linear" else EvalConfig(bit_depth=8, linearise=False)
    fr, ref = image_frames(img, mask, cfg)
    return fr, ref, "float64"


def run_set(name, imgs, filters, masks=MASKS):
    """{(mask, encoding): {(method, domain): mean CFA PSNR}}."""
    out = {}
    for mask in masks:
        for enc in ENCODINGS:
            scores = {k: [] for k in [*NON_Z, ("learned", "")]}
            for img in imgs:
                fr, ref, prec = frames(img, mask, enc)
                for m, d in NON_Z:
                    cfa = rz.reconstruct(fr, m, domain=d, precision=prec)
                    scores[(m, d)].append(cfa_psnr(ref, cfa, fr.z_mask, bit_depth=fr.bit_depth))
                cfa = rz.reconstruct(fr, "learned", precision=prec, filters=filters)
                scores[("learned", "")].append(cfa_psnr(ref, cfa, fr.z_mask,
                                                        bit_depth=fr.bit_depth))
            out[(mask, enc)] = {k: float(np.mean(v)) for k, v in scores.items()}
    return out


def table(results, counts):
    lines = ["| set | mask | encoding | learned | best other (domain) | best | learned - best "
             "| SG | learned - SG | targets |", "|---|---|---|---|---|---|---|---|---|---|"]
    met = total = 0
    for name, res in results.items():
        for (mask, enc), sc in res.items():
            learned = sc[("learned", "")]
            (m, d), best = max(((k, v) for k, v in sc.items() if k[0] != "learned"),
                               key=lambda kv: kv[1])
            sg = sc[("sg", "intensity")]
            ok = learned - best >= TARGET_BEST and learned - sg >= TARGET_SG
            if enc != "srgb8":
                met += ok
                total += 1
            dom = "cd" if d == "colour_difference" else "int"
            mark = ("met" if ok else "**not met**") if enc != "srgb8" else (
                "(met)" if ok else "(not met)")
            lines.append(f"| {name} ({counts[name]}) | {mask} | {enc} | {learned:.2f} | "
                         f"{LABEL[m]} ({dom}) | {best:.2f} | {learned - best:+.2f} | {sg:.2f} | "
                         f"{learned - sg:+.2f} | {mark} |")
    lines.append("")
    lines.append(f"Targets (learned - best >= +{TARGET_BEST} dB and learned - SG >= "
                 f"+{TARGET_SG} dB) met in {met} of {total} rows of the linear and srgb "
                 "encodings (srgb8 rows in parentheses: outside the targets).")
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--heldout", type=Path, default=Path("learned_heldout"),
                    help="folder of the held-out fits (fitted there when missing)")
    ap.add_argument("--data", type=Path, default=DATA, help="the shared data folder")
    ap.add_argument("--sets", default=None, help="comma list of " + ",".join(SETS) +
                    " (default: all of them, none with --folder)")
    ap.add_argument("--folder", action="append", default=[], metavar="NAME=DIR[:K]",
                    help="a set of DIR's images scored with the shipped filters; :K "
                         "multiplies the saturation by K")
    ap.add_argument("--masks", default=",".join(MASKS))
    ap.add_argument("--out", type=Path, default=None, help="also write the table here")
    args = ap.parse_args(argv)
    results, counts = {}, {}
    sets = args.sets if args.sets is not None else "" if args.folder else ",".join(SETS)
    for name in filter(None, sets.split(",")):
        t = time.time()
        filters = None
        if name not in ("kodak", "kodak_sat"):
            filters = []
            for mask in args.masks.split(","):
                path = args.heldout / f"learned_{mask}_heldout.npz"
                if not path.exists():
                    args.heldout.mkdir(parents=True, exist_ok=True)
                    fit(mask, args.data, hold_out=True).save(path)
                filters.append(LearnedFilters.load(path))
        imgs = images(name, args.data)
        counts[name] = len(imgs)
        results[name] = run_set(name, imgs, filters, args.masks.split(","))
        print(f"{name}: {len(imgs)} images, {time.time() - t:.0f} s", file=sys.stderr)
    for spec in args.folder:
        t = time.time()
        name, imgs = folder_images(spec)
        counts[name] = len(imgs)
        results[name] = run_set(name, imgs, None, args.masks.split(","))
        print(f"{name}: {len(imgs)} images, {time.time() - t:.0f} s", file=sys.stderr)
    text = table(results, counts)
    print(text)
    if args.out:
        args.out.write_text(text + "\n")


if __name__ == "__main__":
    main()
