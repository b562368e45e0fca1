"""The bilinear demosaic in C against the path it replaced (colour-demosaicing's
``demosaicing_CFA_Bayer_bilinear`` through scipy.ndimage, and the colour ISP's NumPy stages
around it, which ``ColourISP(demosaicing={"method": "bilinear"})`` ran before it was fused).

    python tools/bilinear_speed.py [ROUNDS] [WORKERS]   # about a minute

The 12 MP bench frame (``make_rgb((3000, 4000))``, Mask1, 11-bit); the two paths alternated
call by call after a warm-up: the medians and the median of the rounds' speed ratios (> 1:
the C path is faster), and whether the two give the same output. The old path is this
build's stage chain with colour-demosaicing's function as the demosaic stage (its border
rule padded by whole periods for ``mode="period"``, as isp.demosaic did), so the pair
differs in the demosaic and the fusion only.
"""
import os
import statistics
import sys

import numpy as np

import rgbz_fast as rz
import rgbz_fast.isp._chain as chain_mod
from rgbz_fast import isp
from rgbz_fast._devtools.bench import make_rgb
from rgbz_fast._deps import import_colour_demosaicing as _colour_demosaicing
from tof_unguided_paired import alternate


def old_demosaic(cfa, phase, method="malvar2004", *, mode="reflect", dtype=None, workers=None):
    """isp.demosaic's bilinear as it was: colour-demosaicing on float64, cast."""
    assert method == "bilinear" and mode == "reflect"
    out = _colour_demosaicing().demosaicing_CFA_Bayer_bilinear(
        np.asarray(cfa, np.float64), phase)
    dt = np.float64 if dtype is None and cfa.dtype == np.float64 else (dtype or np.float32)
    return np.ascontiguousarray(out, dtype=dt)


def old_isp(chain, frame, workers):
    """ColourISP.run on the NumPy stages with colour-demosaicing's bilinear."""
    saved = chain_mod.demosaic
    chain_mod.demosaic = old_demosaic
    try:
        return chain.run(frame, workers=workers, return_stages=True)[0]
    finally:
        chain_mod.demosaic = saved


def main(rounds=7, workers=2):
    frame = rz.mosaic(make_rgb((3000, 4000)), "mask1", 11)
    chain = isp.ColourISP(demosaicing={"method": "bilinear"})
    cfa = chain.run(frame, workers=workers, return_stages=True)[1]["white_balance"]
    same_isp = np.array_equal(chain.run(frame, workers=workers), old_isp(chain, frame, workers))
    same_dm = np.array_equal(isp.demosaic(cfa, "GRBG", "bilinear", workers=workers),
                             old_demosaic(cfa, "GRBG", "bilinear"))
    pairs = {"isp.demosaic(method='bilinear')":
             (lambda: isp.demosaic(cfa, "GRBG", "bilinear", workers=workers),
              lambda: old_demosaic(cfa, "GRBG", "bilinear"), same_dm),
             "ColourISP(demosaicing={'method': 'bilinear'}).run":
             (lambda: chain.run(frame, workers=workers),
              lambda: old_isp(chain, frame, workers), same_isp)}
    print(f"| call ({workers} threads, 12 MP) | C, ms | before, ms | speed ratio | same output |")
    print("|---|---|---|---|---|")
    for name, (new, old, same) in pairs.items():
        t, ratio = alternate({"this": new, "other": old}, rounds)
        print(f"| `{name}` | {statistics.median(t['this']) * 1e3:.1f} | "
              f"{statistics.median(t['other']) * 1e3:.1f} | {ratio:.2f}x | {same} |")
    print(f"load average {os.getloadavg()[0]:.1f}, {os.cpu_count()} cores, {rounds} rounds")


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:3]))
