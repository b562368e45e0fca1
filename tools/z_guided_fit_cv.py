"""The z_guided fit's ridge, prior and colour prior chosen by inner cross-validation, scored 5-fold.

    python tools/z_guided_fit_cv.py [RGBNIR_DIR] [--patterns mask1,mask2] [--folds 5] [--inner 4]

The protocol and the outer folds are those of tools/z_guided_targets.py (pair i in fold i mod
k). In each outer fold, (ridge, prior, colour_prior) of ``fit_stats`` is chosen on the training
pairs alone: ``--inner`` folds of those pairs, each held-out inner fold's squared error computed
from its normal equations (``sum (y - F w)^2 = y.y - 2 w.v + w' A w``; y.y does not depend on
the choice), summed, the grid point of least error kept. The fit with that choice then scores
the outer fold's pairs. Printed per pattern and noise setting: the mean gain over learned with
its 95 % t-interval for the shipped settings (ridge 1e-3, prior 50, colour prior 4) and for the
inner-CV choice; the choice per fold, and the choice the inner CV makes on all the pairs (what a
fit on all of them would use). A few minutes per pattern on 2 busy cores.
"""

import argparse
import itertools
import sys
from pathlib import Path

import numpy as np

from rgbz_fast import reconstruct
from rgbz_fast.metrics import cfa_psnr
from rgbz_fast.reconstruction import default_filters
from rgbz_fast.reconstruction._z_guided_fit import fit_stats, frame_stats

sys.path.insert(0, str(Path(__file__).resolve().parent))
from z_guided_targets import LAM, frames, pairs, t_interval  # noqa: E402

SHIPPED = (1e-3, 50.0, 4.0)
GRID = list(itertools.product([1e-4, 1e-3, 1e-2, 1e-1], [12.5, 50.0, 200.0, 800.0, 3200.0],
                              [1.0, 4.0, 16.0, 64.0, 256.0]))


def _sum(stats, names):
    total = None
    for n in names:
        for s in stats[n]:
            total = s if total is None else [[a + b for a, b in zip(x, y)]
                                             for x, y in zip(total, s)]
    return total


def _weights(A, v, counts, ridge, prior, mult):
    """The solutions of ``_z_guided_fit._fit_buckets`` (the same equations), all buckets at once."""
    p = A.shape[1]
    Ag, vg, n = A.sum(0), v.sum(0), max(int(counts.sum()), 1)
    scale = max(np.trace(Ag) / p, np.finfo(float).tiny)
    wg = np.linalg.solve(Ag + ridge * scale * np.eye(p), vg)
    lam = (prior * scale / n + ridge * np.trace(A, axis1=1, axis2=2)[:, None] / p) * mult
    lam = np.where(lam > 0, lam, ridge * scale + np.finfo(float).tiny)
    return np.linalg.solve(A + lam[:, :, None] * np.eye(p), (v + lam * wg)[..., None])[..., 0]


def _held_error(train, test, base, cfg):
    ridge, prior, cp = cfg
    err = 0.0
    for k, ph in enumerate(base.geometry):
        mult = np.ones(train[k][0].shape[1])
        mult[:len(ph["taps"])] = cp
        W = _weights(*train[k], ridge, prior, mult)
        A, v, _ = test[k]
        err += np.einsum("bi,bij,bj->", W, A, W) - 2 * np.einsum("bi,bi->", W, v)
    return err


def choose(stats, names, base, k):
    inner = [names[i::k] for i in range(k)]
    err = np.zeros(len(GRID))
    for held in inner:
        train = _sum(stats, [n for n in names if n not in held])
        test = _sum(stats, held)
        err += [_held_error(train, test, base, g) for g in GRID]
    return GRID[int(np.argmin(err))]


def run_pattern(folder, names, pattern, n_folds, n_inner):
    base = default_filters(pattern)
    fr = {n: frames(folder, n, pattern) for n in names}
    stats = {n: [frame_stats(f, base, LAM) for f in fr[n]] for n in names}
    score = {}
    for fi in range(n_folds):
        held = names[fi::n_folds]
        fit = [n for n in names if n not in held]
        chosen = choose(stats, fit, base, n_inner)
        print(f"  {pattern} fold {fi + 1}: ridge, prior, colour prior chosen {chosen}",
              file=sys.stderr, flush=True)
        total = _sum(stats, fit)
        for label, (r, p, cp) in (("shipped", SHIPPED), ("inner CV", chosen)):
            f = fit_stats(total, base, LAM, ridge=r, prior=p, colour_prior=cp)
            for n in held:
                for noise, frame in enumerate(fr[n]):
                    score[noise, label, n] = cfa_psnr(
                        frame.reference, reconstruct(frame, "z_guided", filters=f),
                        frame.z_mask, bit_depth=frame.bit_depth)
        for n in held:
            for noise, frame in enumerate(fr[n]):
                score[noise, "learned", n] = cfa_psnr(
                    frame.reference, reconstruct(frame, "learned"), frame.z_mask,
                    bit_depth=frame.bit_depth)
    print(f"\n### {pattern}: the inner CV on all {len(names)} pairs chooses ridge, prior, "
          f"colour prior = {choose(stats, names, base, n_inner)}\n")
    print("| noise | fit settings | mean CFA PSNR (dB) | gain over learned (dB), 95 % t-interval |")
    print("|---|---|---|---|")
    for noise in (0, 1):
        learned = np.array([score[noise, "learned", n] for n in names])
        for label in ("shipped", "inner CV"):
            v = np.array([score[noise, label, n] for n in names])
            g, lo, hi = t_interval(v - learned)
            print(f"| {'noisy' if noise else 'noise-free'} | {label} | {v.mean():.2f} | "
                  f"{g:+.2f} [{lo:+.2f}, {hi:+.2f}] |")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("folder", nargs="?",
                    default=str(Path(__file__).resolve().parents[1].parent / "shared" / "data"
                                / "rgbnir"))
    ap.add_argument("--patterns", default="mask1,mask2")
    ap.add_argument("--folds", type=int, default=5)
    ap.add_argument("--inner", type=int, default=4)
    a = ap.parse_args(argv)
    names = pairs(a.folder)
    if not 2 <= a.folds <= len(names) or not 2 <= a.inner <= len(names) - len(names) // a.folds:
        sys.exit(f"--folds, --inner: expected 2..{len(names)} outer and enough pairs per inner "
                 f"fold, got {a.folds}, {a.inner}")
    for pattern in a.patterns.split(","):
        run_pattern(a.folder, names, pattern, a.folds, a.inner)


if __name__ == "__main__":
    main()
