"""z_guided's CFA PSNR with the shipped filters on the RGB-NIR pairs: a quick check of a kernel change.

    python tools/z_guided_psnr.py [RGBNIR_DIR] [--csv OUT]

Issue 24's protocol (tools/z_guided_targets.py) without the k-fold fits: every pair
NNNN_rgb.png + NNNN_nir.png of the folder (default ../shared/data/rgbnir) through
``Scene.from_rgb(rgb8, depth=np.full(shape, 2.0), ir_reflectance=nir8 / 255)``,
``simulate(scene, pattern, seed=1, noise=False)`` and ``noise=True``, ``reconstruct(frame,
"z_guided")`` with the shipped filters at the default precision, CFA PSNR at the Z sites
against ``frame.reference``. Prints the mean per mask and noise setting (and writes the
per-image scores to ``--csv``): run it on two builds and compare. The pairs are the shipped
filters' fitting data: these are not out-of-sample numbers.
"""

import argparse
import csv
from pathlib import Path

import numpy as np

from rgbz_fast import reconstruct
from rgbz_fast.io import read_image
from rgbz_fast.metrics import cfa_psnr
from rgbz_fast.simulation import Scene, simulate


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder", nargs="?", default="../shared/data/rgbnir")
    ap.add_argument("--csv", help="per-image scores (name, pattern, noise, cfa_psnr)")
    args = ap.parse_args()
    folder = Path(args.folder)
    names = sorted(p.name[:-len("_rgb.png")] for p in folder.glob("*_rgb.png"))
    if not names:
        raise SystemExit(f"{folder}: no NNNN_rgb.png + NNNN_nir.png pairs")
    rows = []
    for name in names:
        rgb8 = read_image(folder / f"{name}_rgb.png", "rgb")
        nir8 = read_image(folder / f"{name}_nir.png", "nir")
        scene = Scene.from_rgb(rgb8, depth=np.full(rgb8.shape[:2], 2.0),
                               ir_reflectance=nir8 / 255)
        for pattern in ("mask1", "mask2"):
            for noise in (False, True):
                frame = simulate(scene, pattern, seed=1, noise=noise)
                out = reconstruct(frame, "z_guided")
                rows.append((name, pattern, int(noise),
                             cfa_psnr(frame.reference, out, frame.z_mask,
                                      bit_depth=frame.bit_depth)))
    if args.csv:
        with open(args.csv, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["name", "pattern", "noise", "cfa_psnr"])
            w.writerows((n, p, z, f"{v:.6f}") for n, p, z, v in rows)
    for pattern in ("mask1", "mask2"):
        for noise in (0, 1):
            v = [r[3] for r in rows if r[1] == pattern and r[2] == noise]
            print(f"{pattern} {'noisy' if noise else 'noise-free':10s} mean CFA PSNR "
                  f"{np.mean(v):.4f} dB over {len(v)} pairs")


if __name__ == "__main__":
    main()
