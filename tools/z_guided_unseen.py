"""The targets of method z_guided, scored with the shipped filters on RGB-NIR pairs no fit saw.

    python tools/z_guided_unseen.py FOLDER [--seeds 1,2,3] [--phase GRBG]

FOLDER holds NNNN_rgb.png + NNNN_nir.png pairs that are not among ../shared/data/rgbnir's
twenty (the shipped z_guided filters are fitted on all of those): the section "Pairs no fit
saw" of docs/reports/z_guided.md scores the eight pairs of ``data/Test_RGB_NIR`` of
pingfansong/CDLSR, whose ``Train_RGB_NIR`` the shipped twenty come from. The protocol of
tools/z_guided_targets.py (``Scene.from_rgb(rgb8, depth=2 m, ir_reflectance=nir8 / 255)``,
``simulate(scene, pattern, seed=s, noise=...)``, ``reconstruct(frame, method)`` at the
default precision, CFA PSNR at the Z sites against ``frame.reference``, mean over the pairs)
with the shipped ``learned`` and ``z_guided`` filters; ``--phase`` moves both masks onto
another Bayer phase (``mask1_rggb``, ...). Printed per pattern and noise setting: the means,
the mean paired gain with its 95 % t-interval and the per-pair gains; a noisy setting once
per seed. Exit status 1 when a mean gain misses its target.
"""

import argparse
import sys
from pathlib import Path

import numpy as np
from scipy import stats

from rgbz_fast import reconstruct
from rgbz_fast.io import read_image
from rgbz_fast.metrics import cfa_psnr
from rgbz_fast.simulation import Scene, simulate

sys.path.insert(0, str(Path(__file__).resolve().parent))
from z_guided_targets import pairs  # noqa: E402

#: (pattern, noisy) -> the issue's target of z_guided - learned, dB
TARGETS = {("mask1", False): 1.0, ("mask2", False): 0.7, ("mask1", True): 0.5,
           ("mask2", True): 0.4}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("folder", type=Path)
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--phase", default="GRBG", choices=("GRBG", "RGGB", "BGGR", "GBRG"))
    args = ap.parse_args(argv)
    seeds = [int(s) for s in args.seeds.split(",")]
    scores = {}                       # (pattern, noisy, seed) -> [(name, learned, z_guided)]
    for name in pairs(args.folder):
        rgb8 = read_image(args.folder / f"{name}_rgb.png", "rgb")
        nir8 = read_image(args.folder / f"{name}_nir.png", "nir")
        scene = Scene.from_rgb(rgb8, depth=np.full(rgb8.shape[:2], 2.0),
                               ir_reflectance=nir8 / 255)
        for mask in ("mask1", "mask2"):
            pattern = mask if args.phase == "GRBG" else f"{mask}_{args.phase.lower()}"
            for noisy in (False, True):
                for seed in seeds if noisy else seeds[:1]:
                    frame = simulate(scene, pattern, seed=seed, noise=noisy)
                    ps = [cfa_psnr(frame.reference, reconstruct(frame, m), frame.z_mask,
                                   bit_depth=frame.bit_depth) for m in ("learned", "z_guided")]
                    scores.setdefault((mask, noisy, seed), []).append((name, *ps))
    missed = False
    print(f"{args.folder}: {len(pairs(args.folder))} pairs, phase {args.phase}")
    for (mask, noisy, seed), rows in scores.items():
        target = TARGETS[(mask, noisy)]
        d = np.array([z - lrn for _, lrn, z in rows])
        half = (stats.t.ppf(0.975, d.size - 1) * d.std(ddof=1) / np.sqrt(d.size)
                if d.size > 1 else np.nan)
        ok = d.mean() >= target
        missed |= not ok
        label = f"noisy, seed {seed}" if noisy else "noise-free"
        print(f"{mask} {label}: learned {np.mean([r[1] for r in rows]):.2f}, z_guided "
              f"{np.mean([r[2] for r in rows]):.2f} dB, gain {d.mean():+.2f} "
              f"[{d.mean() - half:+.2f}, {d.mean() + half:+.2f}] (target {target:+.1f}: "
              f"{'met' if ok else 'NOT met'}), better on {int((d > 0).sum())} of {d.size}")
        print("    " + ", ".join(f"{n} {z - lrn:+.2f}" for n, lrn, z in rows))
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main())
