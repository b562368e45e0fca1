"""The two validity kernels (guided ``tofg_validity``, unguided ``tof_validity``) of this build
against another build's extension, in one process, alternated call by call (the order swapped
every round), on 3 M synthetic measurements of 3 frequencies, 2 threads: the median [IQR] of
the rounds' speed ratios this / other (> 1: this build is faster) and whether the flags agree
where the other build has no upper reflectance bound (this build's called with none).

    python tools/tof_validity_paired.py OTHER.so [ROUNDS]      # a few seconds
"""
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from learned_paired import load_other  # noqa: E402

from rgbz_fast import _kernels as this  # noqa: E402


def arrays(n=3_000_000, F=3, seed=4):
    rng = np.random.default_rng(seed)
    amp = rng.uniform(0, 80, (F, n))
    return dict(amp=amp, var=rng.uniform(50, 500, n), depth=rng.uniform(-0.5, 8, n),
                residual=rng.uniform(0, 0.3, n), sat=(rng.random(n) < 0.05).astype(np.uint8),
                scale=rng.uniform(1e-5, 1e-4, F), coef=rng.uniform(1e-3, 1e-2, F))


def guided(mod, a, out, bound):
    extra = () if bound is None else (None, bound)
    mod.tofg_validity(a["amp"], a["var"].astype(np.float32), a["depth"], a["residual"],
                      a["sat"], a["scale"], a["coef"], 4.0, 1.0, 0.015, 0.15, 0.05, 7.49,
                      *out, 2, *extra)


def unguided(mod, a, out, bound):
    var = np.repeat(a["var"][None], a["amp"].shape[0], 0)
    extra = () if bound is None else (None, bound)
    mod.tof_validity(a["amp"], var, a["depth"], a["residual"], a["sat"], a["scale"],
                     a["coef"], np.pi ** 2 / 3, 0.5, 0.4, 0.3, 1e4, 1.0, 4.0, 1.0, 0.015,
                     0.15, 0.05, 7.49, *out, 2, *extra)


def main(other_path, rounds=15):
    other = load_other(other_path)
    a = arrays()
    n = a["depth"].size
    for name, fn in (("tofg_validity (guided)", guided), ("tof_validity (unguided)", unguided)):
        mine = [np.empty(n), np.empty(n), np.empty(n), np.empty(n, np.uint8)]
        theirs = [np.empty(n), np.empty(n), np.empty(n), np.empty(n, np.uint8)]
        fn(this, a, mine, np.inf)
        fn(other, a, theirs, None)
        same = all(np.array_equal(x, y) for x, y in zip(mine, theirs))
        ratios = []
        for r in range(rounds):
            t = {}
            for who in ((0, 1) if r % 2 else (1, 0)):
                t0 = time.perf_counter()
                if who == 0:
                    fn(this, a, mine, 4.0)
                else:
                    fn(other, a, theirs, None)
                t[who] = time.perf_counter() - t0
            ratios.append(t[1] / t[0])
        q = np.percentile(ratios, [25, 50, 75])
        print(f"{name}: speed this (max_reflectance 4) / other {q[1]:.3f} "
              f"[{q[0]:.3f}-{q[2]:.3f}], {rounds} rounds; same outputs without the bound: "
              f"{same}")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 15)
