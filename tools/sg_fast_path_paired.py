"""SG float32: the compiled plans (Mask1: the constants of recon_mask1.h; Mask2: the
straight-line code of recon_mask2.h) against the same plans run by the plan interpreter
(``plans_only``), in one process, alternated call by call (the order swapped every round), on
the 12 MP bench frame; prints the median [IQR] of the rounds' speed ratios interpreter /
compiled (below 1: the compiled code is faster) and whether the two give the same bits.

    python tools/sg_fast_path_paired.py [ROUNDS] [PATTERN]   # PATTERN: mask1 (default), mask2, ...
"""
import sys
import time

import numpy as np

import rgbz_fast as rz
from rgbz_fast._devtools.bench import make_rgb
from rgbz_fast.reconstruction import _reconstruct as R


def one(frame, workers, interpreter):
    t0 = time.perf_counter()
    if interpreter:
        with R.plans_only():
            rz.reconstruct(frame, "sg", workers=workers)
    else:
        rz.reconstruct(frame, "sg", workers=workers)
    return time.perf_counter() - t0


def main(rounds=11, pattern="mask1"):
    frame = rz.mosaic(make_rgb((3000, 4000)), pattern)
    for workers in (1, 2):
        a = rz.reconstruct(frame, "sg", workers=workers)
        with R.plans_only():
            b = rz.reconstruct(frame, "sg", workers=workers)
        ratios = []
        for r in range(rounds):
            t = {}
            for interp in ((False, True) if r % 2 else (True, False)):
                t[interp] = one(frame, workers, interp)
            ratios.append(t[False] / t[True])
        q = np.percentile(ratios, [25, 50, 75])
        print(f"{pattern}, workers {workers}: speed interpreter / compiled {q[1]:.3f} "
              f"[{q[0]:.3f}-{q[2]:.3f}], {rounds} rounds; same bits: {np.array_equal(a, b)}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 11,
         sys.argv[2] if len(sys.argv) > 2 else "mask1")
