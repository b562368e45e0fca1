"""Clip handling's speed, this build against another build's extension, alternated call by call.

    cd tools && python clip_speed.py OTHER.so matrix [--workers 1]
    cd tools && python clip_speed.py OTHER.so openisp [--rounds 7]
    cd tools && python clip_speed.py OTHER.so check [--calls 300] [--seed 10]

OTHER.so: a copy of src/rgbz_fast/_kernels*.so of the build to compare with. The other build
runs its clipped calls on the plans of _plans.py (``plans_only``): builds before 2026-11-26
17:40 UTC refuse the Mask1 fast path with a clip level.

``matrix``: the 12 MP bench frame (``make_rgb((3000, 4000))`` mosaicked, uint16 11-bit),
Mask1 and Mask2, clip levels None, 1800, 2047 and 5000 DN, bilinear, bi, edi_line and sg in
float32: a Markdown row per pattern and level, Mpix/s this / other (medians of 5 rounds).
``openisp``: ``../../shared/data/raw/openisp_test.RAW`` read as docs/reports/clipping.md
reads it, ``clip_level="auto"``, bi, edi_line, sg, 1 thread: Mpix/s of both builds, the
median [IQR] of the rounds' speed ratios, and the speed of the ``clip_level=None`` call.
``check``: random clipped calls (Mask1 and Mask2 at several Bayer phases; bilinear, bi,
edi_line, edi_central, sg; four element types; both precisions, exponentials and domains;
levels at 80, 95 and 99 % of white; 1-2 threads): every pixel where this build differs from
the other must equal this build's ``clip_level=None`` call (a site without a clipped tap);
exits 1 otherwise.
"""
import argparse
import sys
import time

import numpy as np

import rgbz_fast as rz
from rgbz_fast._devtools.bench import make_rgb
from rgbz_fast.io import read_raw, to_rgbz
from recon_against_build import R, load_other, run_with


def timed(k, frame, method, plans, **kw):
    a = time.perf_counter()
    run_with(k, frame, method, plans=plans, **kw)
    return time.perf_counter() - a


def matrix(other, workers):
    cur = R._kernels
    img = make_rgb((3000, 4000))
    print("| pattern | clip_level | clipped | bilinear | bi | edi_line | sg |")
    print("|---|---|---|---|---|---|---|")
    for pat in ("mask1", "mask2"):
        fr = rz.mosaic(img, pat)
        for c in (None, 1800.0, 2047.0, 5000.0):
            share = 0.0 if c is None else float((fr.data[~fr.z_mask] >= c).mean())
            cells = []
            for meth in ("bilinear", "bi", "edi_line", "sg"):
                t = {"this": [], "other": []}
                for i in range(6):
                    order = (("this", cur), ("other", other)) if i % 2 else (("other", other),
                                                                             ("this", cur))
                    for name, k in order:
                        s = timed(k, fr, meth, k is other and c is not None, workers=workers,
                                  clip_level=c)
                        if i:
                            t[name].append(s)
                mp = fr.data.size / 1e6
                cells.append(f"{mp / np.median(t['this']):.0f} / {mp / np.median(t['other']):.0f}")
            print(f"| {pat} | {c} | {100 * share:.2f} % | " + " | ".join(cells) + " |", flush=True)


def openisp(other, rounds):
    cur = R._kernels
    f = read_raw("../../shared/data/raw/openisp_test.RAW", shape=(1080, 1920), phase="RGGB",
                 black_level=0, bit_depth_in=10, clip_level=1020)
    for pname in ("mask1", "mask2"):
        fr, _ = to_rgbz(f, pname)
        share = float((fr.data[~fr.z_mask] >= rz.io.frame_clip_level(fr)).mean())
        print(f"{pname}: {100 * share:.1f} % of the colour pixels at the clip level")
        mp = fr.data.size / 1e6
        for meth in ("bi", "edi_line", "sg"):
            rat, tn, to, tnone = [], [], [], []
            for i in range(rounds + 1):
                t = {}
                order = (("this", cur), ("other", other)) if i % 2 else (("other", other),
                                                                         ("this", cur))
                for name, k in order:
                    t[name] = timed(k, fr, meth, k is other, workers=1, clip_level="auto")
                none = timed(cur, fr, meth, False, workers=1)
                if i:
                    rat.append(t["other"] / t["this"])
                    tn.append(t["this"])
                    to.append(t["other"])
                    tnone.append(none)
            q = np.percentile(rat, [25, 50, 75])
            print(f"  {meth:9s} this {mp / np.median(tn):6.1f} Mpix/s, other "
                  f"{mp / np.median(to):6.1f}, speed this / other {q[1]:.2f} [{q[0]:.2f}-"
                  f"{q[2]:.2f}]; clip_level=None {mp / np.median(tnone):6.1f}", flush=True)


def check(other, calls, seed):
    cur = R._kernels
    rng = np.random.default_rng(seed)
    pats = ["mask1", "mask2", rz.mask1("RGGB"), rz.mask2("BGGR"), rz.mask1("GBRG")]
    bad = differ = 0
    for i in range(calls):
        pat = pats[i % len(pats)]
        rows, cols = int(rng.integers(8, 70)), int(rng.integers(8, 300))
        x = rng.random((rows, cols)) * 2047
        if i % 3 == 0:
            x = np.cumsum(np.cumsum(x, 0), 1)
            x = x / x.max() * 2047
        dt = [np.uint16, np.float64, np.float32, np.uint8][rng.integers(4)]
        bd = 8 if dt == np.uint8 else 11
        if dt == np.uint8:
            x = x / 8
        d = (np.round(x) if dt in (np.uint16, np.uint8) else x).astype(dt)
        level = float([0.8, 0.95, 0.99][i % 3] * ((1 << bd) - 1))
        meth = ["sg", "edi_central", "edi_line", "bi", "bilinear"][rng.integers(5)]
        kw = dict(pattern=pat, precision=["float32", "float64"][rng.integers(2)],
                  exp=["libm", "fast"][rng.integers(2)], bit_depth=bd,
                  domain=(["intensity", "colour_difference"][rng.integers(2)]
                          if meth != "bilinear" else "intensity"),
                  workers=int(rng.integers(1, 3)))
        a = run_with(cur, d, meth, clip_level=level, **kw)
        b = run_with(other, d, meth, plans=True, clip_level=level, **kw)
        c = run_with(cur, d, meth, **kw)
        m = a != b
        if a.dtype.kind == "f":
            m &= ~(np.isnan(a) & np.isnan(b))
        differ += int(m.sum())
        if not np.array_equal(a[m], c[m]):
            bad += 1
            print("differs from both:", i, getattr(pat, "name", pat), meth, dt.__name__, kw)
    print(f"{calls} calls, {bad} bad; {differ} pixels differ from the other build, each equal "
          "to this build's clip_level=None call")
    return 1 if bad else 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("other", help="the other build's _kernels extension file")
    ap.add_argument("what", choices=("matrix", "openisp", "check"))
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--calls", type=int, default=300)
    ap.add_argument("--seed", type=int, default=10)
    a = ap.parse_args(argv)
    other = load_other(a.other)
    if a.what == "check":
        return check(other, a.calls, a.seed)
    if a.what == "matrix":
        matrix(other, a.workers)
    else:
        openisp(other, a.rounds)
    return 0


if __name__ == "__main__":
    sys.exit(main())
