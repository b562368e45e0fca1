"""The targets of method z_guided on the RGB-NIR pairs, every number out of sample (k-fold).

    python tools/z_guided_targets.py [RGBNIR_DIR] [--patterns mask1,mask2] [--folds 5]
        [--inner 4] [--select cv|none] [--csv OUT]

The protocol of the targets: for every pair NNNN_rgb.png + NNNN_nir.png of the folder
(default ../shared/data/rgbnir), ``Scene.from_rgb(rgb8, depth=np.full(shape, 2.0),
ir_reflectance=nir8 / 255)`` (the NIR PNG as the reflectance, as it is), ``simulate(scene,
pattern, seed=1, noise=False)`` and ``noise=True`` (default sensors), ``reconstruct(frame,
method)`` at the default precision, CFA PSNR at the Z sites against ``frame.reference``, mean
over the images.

Pair i (names sorted) is in fold i mod k: 5 folds of 4 pairs for the 20 pairs. Each fold's
z_guided filters are fitted by the shipped procedure (``train_z_guided``: the shipped learned
filters as the base, the noise-free and the noisy frames of the other pairs, one fit for both
as the shipped one must; its ridge, prior and colour prior chosen with ``select="cv"`` by an
``--inner``-fold cross-validation over those other pairs alone, the two frames of a pair in
one inner fold: ``fit_folds`` on their equations, pair i of the fit in inner fold i mod 4) and
score the fold's own pairs, which no step of the fit saw. ``--select none``: the fixed settings
instead (ridge 1e-3, prior 50, colour prior 4). Printed, per pattern and noise setting:

* the mean CFA PSNR of learned and z_guided and the mean paired gain with its 95 % t-interval
  (of the per-image differences); the same for z_guided fitted without the guide (its colour
  correction alone: what refitting on these scenes gives without the Z pixels);
* the per-image gains, the images where z_guided loses to learned, and those where the guide
  itself hurts (z_guided below its own fit without the guide);
* where it hurts within the images: the gain over all held-out Z sites split by the strength
  level of the learned hash (flat, textured, strong structure), over learned and over the fit
  without the guide.

The settings each fold's inner cross-validation chose are printed too. The pairs are fitting
data for the shipped filters: the numbers here are the k-fold estimate. About 30 minutes on
2 busy cores.
"""

import argparse
import csv
import sys
from pathlib import Path

import numpy as np
from scipy import stats

from rgbz_fast import reconstruct
from rgbz_fast.io import read_image
from rgbz_fast.metrics import cfa_psnr
from rgbz_fast.reconstruction import default_filters
from rgbz_fast.reconstruction._learned_hash import gather_windows, hash_buckets, hash_features
from rgbz_fast.reconstruction._z_guided_fit import fit_folds, frame_stats, sum_stats
from rgbz_fast.simulation import Scene, simulate

LAM = 0.01
STRENGTH = ("flat", "textured", "strong")


def pairs(folder):
    names = sorted(p.name[:-len("_rgb.png")] for p in Path(folder).glob("*_rgb.png"))
    missing = [n for n in names if not (Path(folder) / f"{n}_nir.png").is_file()]
    if not names or missing:
        sys.exit(f"{folder}: expected NNNN_rgb.png + NNNN_nir.png pairs (missing NIR: {missing})")
    return names


def frames(folder, name, pattern):
    rgb8 = read_image(Path(folder) / f"{name}_rgb.png", "rgb")
    nir8 = read_image(Path(folder) / f"{name}_nir.png", "nir")
    shape = rgb8.shape[:2]
    scene = Scene.from_rgb(rgb8, depth=np.full(shape, 2.0), ir_reflectance=nir8 / 255)
    return [simulate(scene, pattern, seed=1, noise=noise) for noise in (False, True)]


def strength(frame, base):
    """The strength level of the learned hash at every Z site (row-major per phase, as reconstruct
    writes them), and the Z sites' values of an image in the same order."""
    P, Q = frame.pattern.period
    levels, where = [], []
    for k, (X, (r, c, ny, nx)) in enumerate(
            gather_windows(frame.data, frame.pattern, base.radius, base.geometry)):
        bk = hash_buckets(hash_features(X, base.geometry[k]), *(t[k] for t in base.thresholds()))
        levels.append((bk // (base.n_coherence * base.n_spread)) % base.n_strength)
        where.append((r, c, ny, nx))

    def sites(img):
        return np.concatenate([np.asarray(img, np.float64)[r::P, c::Q][:ny, :nx].reshape(-1)
                               for r, c, ny, nx in where])
    return np.concatenate(levels), sites


def t_interval(d):
    d = np.asarray(d, np.float64)
    h = stats.t.ppf(0.975, len(d) - 1) * d.std(ddof=1) / np.sqrt(len(d))
    return d.mean(), d.mean() - h, d.mean() + h


def fold_fits(equations, fit_names, base, n_inner, select):
    """The z_guided fit of one outer fold and the same without the guide, from the equations
    of its training pairs ``fit_names`` alone (``equations``: per pair, its two frames'
    summed): train_z_guided's procedure, pair i of the fit in inner fold i mod ``n_inner``."""
    inner = [sum_stats(equations[n] for n in fit_names[i::n_inner]) for i in range(n_inner)]
    return {"z_guided": fit_folds(inner, base, LAM, select=select),
            "no_guide": fit_folds(inner, base, LAM, select=select, guide=False)}


def run_pattern(folder, names, pattern, n_folds, n_inner, select, rows, chosen):
    base = default_filters(pattern)
    all_frames = {}
    equations = {}                  # per pair: the sum of its two frames' (one group)
    for n in names:
        all_frames[n] = frames(folder, n, pattern)
        equations[n] = sum_stats(frame_stats(f, base, LAM) for f in all_frames[n])
        print(f"  {pattern} {n}: equations", file=sys.stderr, flush=True)
    folds = [names[i::n_folds] for i in range(n_folds)]
    score = {}                      # (noise, method, image) -> dB
    err = {}                        # (noise, method) -> [squared errors], strength levels
    for fi, held in enumerate(folds):
        fit_names = [n for n in names if n not in held]
        fits = fold_fits(equations, fit_names, base, n_inner, select)
        for m, f in fits.items():
            chosen.append((pattern, fi, m, f.meta["ridge"], f.meta["prior"],
                           f.meta["colour_prior"]))
            print(f"  {pattern} fold {fi + 1} {m}: ridge {f.meta['ridge']:g}, prior "
                  f"{f.meta['prior']:g}, colour prior {f.meta['colour_prior']:g}",
                  file=sys.stderr, flush=True)
        for n in held:
            for noise, frame in enumerate(all_frames[n]):
                outs = {"learned": reconstruct(frame, "learned")}
                for m, f in fits.items():
                    outs[m] = reconstruct(frame, "z_guided", filters=f)
                level, sites = strength(frame, base)
                ref = sites(frame.reference)
                for m, out in outs.items():
                    score[noise, m, n] = cfa_psnr(frame.reference, out, frame.z_mask,
                                                  bit_depth=frame.bit_depth)
                    e = err.setdefault((noise, m), ([], []))
                    e[0].append((sites(out) - ref) ** 2)
                    e[1].append(level)
                    rows.append({"pattern": pattern, "noise": noise, "image": n, "fold": fi,
                                 "method": m, "cfa_psnr": f"{score[noise, m, n]:.4f}"})
        print(f"  {pattern}: fold {fi + 1}/{n_folds} scored", file=sys.stderr, flush=True)
    return score, err


def report(pattern, names, score, err):
    for noise in (0, 1):
        label = "noisy (sensor model)" if noise else "noise-free"
        print(f"\n### {pattern}, {label}\n")
        learned = np.array([score[noise, "learned", n] for n in names])
        print("| method | mean CFA PSNR (dB) | gain over learned (dB), 95 % t-interval | "
              "images better |")
        print("|---|---|---|---|")
        print(f"| learned (shipped) | {learned.mean():.2f} | | |")
        for m, lab in (("z_guided", "z_guided"), ("no_guide", "z_guided without the guide")):
            v = np.array([score[noise, m, n] for n in names])
            g, lo, hi = t_interval(v - learned)
            print(f"| {lab} | {v.mean():.2f} | {g:+.2f} [{lo:+.2f}, {hi:+.2f}] | "
                  f"{int((v > learned).sum())}/{len(names)} |")
        gains = {n: score[noise, "z_guided", n] - score[noise, "learned", n] for n in names}
        print("\nPer image (z_guided - learned, dB): " +
              ", ".join(f"{n} {g:+.2f}" for n, g in gains.items()))
        own = {n: score[noise, "z_guided", n] - score[noise, "no_guide", n] for n in names}
        g, lo, hi = t_interval(list(own.values()))
        print(f"\nThe guide alone (z_guided - z_guided without the guide): {g:+.2f} "
              f"[{lo:+.2f}, {hi:+.2f}] dB; per image: " +
              ", ".join(f"{n} {d:+.2f}" for n, d in own.items()))
        for what, d in (("z_guided loses to learned", gains), ("the guide hurts", own)):
            hurt = [n for n, v in d.items() if v < 0]
            print(f"\nWhere {what}: {', '.join(hurt) if hurt else 'no image'}.")
        lv = np.concatenate(err[noise, "learned"][1])
        z_e = np.concatenate(err[noise, "z_guided"][0])
        for other in ("learned", "no_guide"):
            o_e = np.concatenate(err[noise, other][0])
            cells = []
            for s, name in enumerate(STRENGTH):
                m = lv == s
                if m.any():
                    cells.append(f"{name} {10 * np.log10(o_e[m].mean() / z_e[m].mean()):+.2f} "
                                 f"dB ({m.mean():.0%} of the sites)")
            print(f"Gain over {other} by the strength of the learned hash, all held-out "
                  "sites: " + ", ".join(cells) + ".")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("folder", nargs="?",
                    default=str(Path(__file__).resolve().parents[1].parent / "shared" / "data"
                                / "rgbnir"))
    ap.add_argument("--patterns", default="mask1,mask2")
    ap.add_argument("--folds", type=int, default=5)
    ap.add_argument("--inner", type=int, default=4,
                    help="folds of the inner cross-validation of --select cv (default 4)")
    ap.add_argument("--select", choices=("cv", "none"), default="cv",
                    help="the fit's ridge, prior and colour prior: by inner cross-validation "
                         "(the shipped procedure) or the fixed settings (default cv)")
    ap.add_argument("--csv", help="write the per-image scores to this CSV file")
    a = ap.parse_args(argv)
    names = pairs(a.folder)
    if not 2 <= a.folds <= len(names):
        sys.exit(f"--folds: expected 2..{len(names)}, got {a.folds}")
    if not 2 <= a.inner <= len(names) - -(-len(names) // a.folds):
        sys.exit(f"--inner: expected 2..{len(names) - -(-len(names) // a.folds)}, got {a.inner}")
    select = None if a.select == "none" else "cv"
    rows, chosen = [], []
    print(f"z_guided against learned, {len(names)} RGB-NIR pairs of {a.folder}, "
          f"{a.folds}-fold (every score out of sample), fit settings "
          + (f"by {a.inner}-fold inner cross-validation on each fold's training pairs"
             if select else "fixed (ridge 1e-3, prior 50, colour prior 4)"))
    for pattern in a.patterns.split(","):
        score, err = run_pattern(a.folder, names, pattern, a.folds, a.inner, select, rows,
                                 chosen)
        report(pattern, names, score, err)
    if select:
        print("\n### The settings each fold's inner cross-validation chose\n")
        print("| pattern | fold | fit | ridge | prior | colour prior |")
        print("|---|---|---|---|---|---|")
        for pattern, fi, m, r, p, cp in chosen:
            lab = "z_guided" if m == "z_guided" else "without the guide"
            print(f"| {pattern} | {fi + 1} | {lab} | {r:g} | {p:g} | {cp:g} |")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
