"""This build's reconstruction against another build's extension: bit for bit, or paired speed.

    python tools/recon_against_build.py same OTHER.so [--calls 100] [--seed 0] [--clip-share 0.2]
        [--old-other]
    python tools/recon_against_build.py speed OTHER.so [--pattern mask2] [--workers 2] [--rounds 9]
        [--method sg] [--precision float32] [--exp auto] [--clip-level DN] [--old-other]

OTHER.so: a copy of src/rgbz_fast/_kernels*.so of the build to compare with (copy it out of
build/ before changing the C code). Both extensions are loaded in one process; the Python
layer of this checkout calls one or the other.

``same``: random ``reconstruct`` calls (Mask1, Mask2 at three Bayer phases; sg, edi_line,
edi_central, bi, bilinear; the four element types; both precisions, exponentials, domains
and sigma_rel values; a clip level in one call of five (``--clip-share``); random, smooth and
partly flat frames of 8-69 x 8-299 pixels; 1 or 2 threads), each output compared bit for bit;
exits 1 if one differs. Both builds run every call on the library's own path. Builds before
2026-11-26 17:40 UTC refuse the fast path with a clip level: ``--old-other`` runs OTHER's calls
with a clip level on the plans of _plans.py (``plans_only``), which equal the Mask1 fast path
within rounding, not bit for bit (1-ulp differences at a few sites in about 4 calls of 1000
with a clip level, both builds the same), so with it a Mask1 call with a clip level may differ
by that much.

``speed``: SG (or ``--method``, in ``--precision``) on the 12 MP bench frame (``make_rgb((3000, 4000))`` mosaicked), the two
extensions alternated call by call (the order swapped every round, one warm-up round), and
the median [IQR] of the rounds' speed ratios this / OTHER (> 1: this build is faster).
"""
import argparse
import sys
import time

import numpy as np

import rgbz_fast as rz
from rgbz_fast._devtools.bench import make_rgb
from rgbz_fast.reconstruction import _reconstruct as R
from learned_paired import load_other


def run_with(kernels, *args, plans=False, **kw):
    saved = R._kernels
    R._kernels = kernels
    try:
        if plans:
            with R.plans_only():
                return rz.reconstruct(*args, **kw)
        return rz.reconstruct(*args, **kw)
    finally:
        R._kernels = saved


def same(other, calls, seed, clip_share=0.2, old_other=False):
    cur = R._kernels
    rng = np.random.default_rng(seed)
    pats = ["mask2", "mask2", "mask2", rz.mask2("RGGB"), rz.mask2("BGGR"), "mask1"]
    methods = ["sg", "sg", "sg", "edi_line", "edi_central", "bi", "bilinear"]
    bad = 0
    for i in range(calls):
        pat = pats[rng.integers(len(pats))]
        meth = methods[rng.integers(len(methods))]
        dt = [np.uint8, np.uint16, np.float32, np.float64][rng.integers(4)]
        rows, cols = int(rng.integers(8, 70)), int(rng.integers(8, 300))
        bd = 8 if dt == np.uint8 else 11
        kw = dict(precision=["float32", "float64"][rng.integers(2)],
                  exp=["libm", "fast"][rng.integers(2)],
                  domain=["intensity", "colour_difference"][rng.integers(2)],
                  sigma_rel=[0.0, 0.5][rng.integers(2)])
        if meth == "sg":
            kw["sg_mode"] = ["auto", "pure", "combined"][rng.integers(3)]
        if meth == "bilinear":      # no weights: neither a domain nor sigma_rel applies
            del kw["domain"], kw["sigma_rel"]
        if rng.random() < clip_share:
            kw["clip_level"] = float(0.8 * ((1 << bd) - 1))
        smooth = rng.random() < 0.5
        x = rng.random((rows, cols)) * ((1 << bd) - 1)
        if smooth:
            x = np.cumsum(np.cumsum(x, 0), 1)
            x = x / x.max() * ((1 << bd) - 1)
        if rng.random() < 0.2:
            x[:, : cols // 3] = 100.0
        frame = x.astype(dt) if dt in (np.float32, np.float64) else np.round(x).astype(dt)
        w = int(rng.integers(1, 3))
        a, b = (run_with(k, frame, meth, pattern=pat, bit_depth=bd, workers=w,
                         plans=old_other and k is other and "clip_level" in kw, **kw)
                for k in (cur, other))
        if not (a.dtype == b.dtype and np.array_equal(a.view(np.uint8), b.view(np.uint8))):
            bad += 1
            print("differs:", i, getattr(pat, "name", pat), meth, dt.__name__, rows, cols, w, kw)
    print(f"{calls} calls, {bad} differ")
    return 1 if bad else 0


def speed(other, pattern, workers, rounds, method="sg", precision="float32", exp="auto",
          clip_level=None, old_other=False):
    cur = R._kernels
    frame = rz.mosaic(make_rgb((3000, 4000)), pattern)
    ratios = []
    for i in range(rounds + 1):
        t = {}
        order = (("this", cur), ("other", other)) if i % 2 else (("other", other), ("this", cur))
        for name, k in order:
            t0 = time.perf_counter()
            run_with(k, frame, method, workers=workers, precision=precision, exp=exp,
                     clip_level=clip_level,
                     plans=old_other and k is other and clip_level is not None)
            t[name] = time.perf_counter() - t0
        if i:
            ratios.append(t["other"] / t["this"])
    q = np.percentile(ratios, [25, 50, 75])
    print(f"{method} {pattern} {precision} exp={exp} clip_level={clip_level}, {workers} thread(s): speed this / other {q[1]:.3f} "
          f"[{q[0]:.3f}-{q[2]:.3f}], {rounds} rounds")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=("same", "speed"))
    ap.add_argument("other", help="the other build's _kernels extension file")
    ap.add_argument("--calls", type=int, default=100)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--pattern", default="mask2")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--rounds", type=int, default=9)
    ap.add_argument("--method", default="sg")
    ap.add_argument("--precision", default="float32", choices=("float32", "float64"))
    ap.add_argument("--exp", default="auto", choices=("auto", "libm", "fast"))
    ap.add_argument("--clip-share", type=float, default=0.2)
    ap.add_argument("--clip-level", type=float, default=None)
    ap.add_argument("--old-other", action="store_true",
                    help="OTHER is a build before 2026-11-26 17:40 UTC: its calls with a clip "
                         "level on the plans of _plans.py")
    a = ap.parse_args(argv)
    other = load_other(a.other)
    if a.what == "same":
        return same(other, a.calls, a.seed, a.clip_share, a.old_other)
    return speed(other, a.pattern, a.workers, a.rounds, a.method, a.precision, a.exp,
                 a.clip_level, a.old_other)


if __name__ == "__main__":
    sys.exit(main())
