"""Per-call CPU of the Kodak evaluation's kernels on one image pair, one thread.

Times, as the evaluation calls them, the kernels of one Kodak test image (kodim05, Mask1, SG,
its reference rendered as ``evaluate`` renders it, border crop 8): the SSIM sums at scale 0
from the reference's moments, the reference's moments, the zipper's test and reference passes,
the planar copy, and the render of the reference CFA. Run it with each build's interpreter in
turn to compare two builds (docs/reports/benchmarks.md):

    python tools/kodak_eval_kernels.py [ROUNDS]

Prints the median of ROUNDS (default 21) calls of each, in milliseconds of process CPU.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from rgbz_fast import _kernels
from rgbz_fast._patterns import get_pattern
from rgbz_fast.evaluation import EvalConfig
from rgbz_fast.evaluation._run import _frames, _reference_render
from rgbz_fast.io import folder_dataset
from rgbz_fast.metrics._ssim import _ssim_reference, _window
from rgbz_fast.reconstruction import reconstruct

KODAK = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "kodak"


def _pair():
    """(reference sRGB, test sRGB, reference CFA, gains, chain) of kodim05, Mask1, SG."""
    source = {s.name: s for s in folder_dataset(KODAK)}["kodim05"]
    config = EvalConfig()
    chain = config.colour_isp()
    frame, cfa = _frames(source.load(), get_pattern("mask1"), config, {})
    bayer, bits = frame.pattern.bayer_phase, frame.bit_depth
    ref, gains = _reference_render(chain, cfa, bayer, bits, 1, [])
    test = chain.render(reconstruct(frame, "sg", params=config.params, workers=1), bayer,
                        bit_depth=bits, gains=gains, workers=1)
    return ref, test, cfa, gains, chain


def main(rounds=21):
    ref, test, cfa, gains, chain = _pair()
    c = 8
    r = np.ascontiguousarray(ref[c:-c, c:-c])
    t = np.ascontiguousarray(test[c:-c, c:-c])
    x = np.ascontiguousarray(np.moveaxis(r, -1, 0))
    y = np.ascontiguousarray(np.moveaxis(t, -1, 0))
    w = _window(11, 1.5, True)
    moments = _ssim_reference(x, 1)
    c1, c2 = (0.01 * 255) ** 2, (0.03 * 255) ** 2
    ssim_sum, cs_sum = np.empty(3), np.empty(3)
    best = np.empty((r.shape[0] - 2, r.shape[1] - 2))
    nearest = np.empty(best.shape, np.uint8)
    _kernels.zipper_reference(r, 255.0, best, nearest, 1)
    planes = np.empty_like(y)
    cases = {
        "SSIM sums, scale 0, from the reference's moments":
            lambda: _kernels.ssim_sums(x, y, moments, w, c1, c2, ssim_sum, cs_sum, 1),
        "SSIM, the reference's moments at scale 0": lambda: _ssim_reference(x, 1),
        "zipper, test pass": lambda: _kernels.zipper_count_reference(t, 255.0, best, nearest,
                                                                    2.3, 1),
        "zipper, reference pass": lambda: _kernels.zipper_reference(r, 255.0, best, nearest, 1),
        "planar copy of the test image": lambda: (
            _kernels.planar(t, planes, 1) if hasattr(_kernels, "planar")
            else np.copyto(planes, np.moveaxis(t, -1, 0))),
        "render of the reference CFA": lambda: chain.render(cfa, "GRBG", bit_depth=11,
                                                            gains=gains, workers=1),
    }
    for name, call in cases.items():
        call()
        times = []
        for _ in range(rounds):
            t0 = time.process_time()
            call()
            times.append(time.process_time() - t0)
        print(f"{1000 * np.median(times):7.3f} ms  {name}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 21)
