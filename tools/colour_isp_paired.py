"""The fused colour ISP, this build against another build's extension: same images, speed.

    cd tools && python colour_isp_paired.py OTHER.so [--bits 16] [--matrix]

OTHER.so: a copy of src/rgbz_fast/_kernels*.so of the build to compare with. The chain is
``ColourISP(output_bits=BITS)`` (8 by default), with ``--matrix`` a colour matrix other than
the identity (the one of tests/isp/test_fused.py). The 24 Kodak images (linearised, Mask1,
11-bit) rendered in float32 and float64 with both extensions, compared bit for bit; then the
12 MP bench frame (``make_rgb((3000, 4000))``, Mask1), 1 and 2 threads, the extensions
alternated call by call (7 rounds after a warm-up): medians and the median of the rounds'
speed ratios (> 1: this build is faster).
"""
import argparse
import glob
import sys
import time

import numpy as np
from skimage.io import imread

import rgbz_fast as rz
import rgbz_fast.isp._fused as fused
from rgbz_fast import isp
from rgbz_fast._devtools.bench import make_rgb
from learned_paired import load_other

MATRIX = ((1.6, -0.4, -0.2), (-0.3, 1.5, -0.2), (0.0, -0.5, 1.5))


def run_with(kernels, chain, frame, **kw):
    saved = fused._kernels
    fused._kernels = kernels
    try:
        return chain.run(frame, **kw)
    finally:
        fused._kernels = saved


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("other")
    ap.add_argument("--bits", type=int, default=8, choices=(8, 16))
    ap.add_argument("--matrix", action="store_true")
    args = ap.parse_args(argv)
    other, cur = load_other(args.other), fused._kernels
    extra = {"colour_correction": {"matrix": MATRIX}} if args.matrix else {}
    label = f"output_bits={args.bits}" + (", a colour matrix" if args.matrix else "")
    bad = n = 0
    for path in sorted(glob.glob("../../shared/data/kodak/*.png")):
        lin = rz.simulation.srgb_to_linear(imread(path) / 255.0)
        frame = rz.mosaic(lin, "mask1", 11)
        for prec in ("float32", "float64"):
            chain = isp.ColourISP(output_bits=args.bits, precision=prec, **extra)
            n += 1
            bad += not np.array_equal(run_with(cur, chain, frame), run_with(other, chain, frame))
    print(f"{n} Kodak renders ({label}, float32 and float64): {bad} differ")
    frame = rz.mosaic(make_rgb((3000, 4000)), "mask1")
    for prec in ("float32", "float64"):
        chain = isp.ColourISP(output_bits=args.bits, precision=prec, **extra)
        for workers in (1, 2):
            t = {"this": [], "other": []}
            for i in range(8):
                order = (("this", cur), ("other", other)) if i % 2 else (("other", other),
                                                                         ("this", cur))
                for name, k in order:
                    a = time.perf_counter()
                    run_with(k, chain, frame, workers=workers)
                    if i:
                        t[name].append(time.perf_counter() - a)
            ratio = np.median(np.array(t["other"]) / np.array(t["this"]))
            print(f"ColourISP({label}, precision={prec!r}).run, 12 MP Mask1, {workers} "
                  f"thread(s): {1e3 * np.median(t['this']):.0f} ms against "
                  f"{1e3 * np.median(t['other']):.0f} ms, speed ratio {ratio:.3f}", flush=True)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
