"""Menon 2007 on the 12 MP bench frame: the kernel against colour-demosaicing, and Malvar's
kernel beside it; the colour ISP with Menon against another build's.

    python tools/menon_speed.py [ROUNDS]
    python tools/menon_speed.py isp DIR [ROUNDS]

``rgbz_fast.isp.demosaic(cfa, "GRBG", method, dtype=float64, workers=w)`` for Menon 2007
and Malvar 2004 on 1 and 2 threads (medians of ROUNDS calls, default 7), then
``colour_demosaicing.demosaicing_CFA_Bayer_Menon2007(cfa.astype(float64), "GRBG")`` (the
median of 3), and whether the two Menon images are equal bit for bit. The frame is the
bench's (``rgbz-fast bench``: skimage's astronaut tiled to 3000x4000, uint16 11-bit).

``isp DIR``: ``ColourISP(demosaicing={"method": "menon2007"}).run(cfa, pattern="bayer")`` of this checkout
and of DIR/rgbz_old (another commit's package, made by ``tools/tof_unguided_paired.py
--make``), alternated call by call, at 768x512 and 3000x4000 (the bench frame and its
top-left corner), with Malvar's ``ColourISP().run(cfa)`` of this checkout beside them:
medians, and whether the two Menon images are equal.
"""

import statistics
import sys
import time
import warnings

import numpy as np

import rgbz_fast as rz
from rgbz_fast._devtools.bench.cases import make_rgb
from rgbz_fast.isp import demosaic


def _median(fn, n):
    times, out = [], None
    for _ in range(n):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def main(rounds=7):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        import colour_demosaicing
    cfa = rz.mosaic(make_rgb((3000, 4000)), "bayer").data
    ours = None
    for w in (1, 2):
        t_menon, ours = _median(lambda: demosaic(cfa, "GRBG", "menon2007", dtype=np.float64,
                                                 workers=w), rounds)
        t_malvar, _ = _median(lambda: demosaic(cfa, "GRBG", "malvar2004", dtype=np.float64,
                                               workers=w), rounds)
        print(f"{w} thread(s): Menon 2007 {t_menon * 1e3:.0f} ms, Malvar 2004 "
              f"{t_malvar * 1e3:.0f} ms")
    t_ref, ref = _median(lambda: colour_demosaicing.demosaicing_CFA_Bayer_Menon2007(
        cfa.astype(np.float64), "GRBG"), 3)
    print(f"colour-demosaicing Menon 2007 {t_ref:.2f} s; the same image: "
          f"{np.array_equal(ref, ours)}")


def isp(other, rounds=7):
    sys.path.insert(0, other)
    import rgbz_old
    from rgbz_fast import ColourISP

    cfa = rz.mosaic(make_rgb((3000, 4000)), "bayer").data
    menon = {"method": "menon2007"}
    for shape in ((512, 768), (3000, 4000)):
        c = np.ascontiguousarray(cfa[:shape[0], :shape[1]])
        runs = {"this": ColourISP(demosaicing=menon).run,
                "other": rgbz_old.ColourISP(demosaicing=menon).run,
                "malvar": ColourISP().run}
        times = {k: [] for k in runs}
        images = {k: f(c, pattern="bayer") for k, f in runs.items()}    # warm-up
        for _ in range(rounds):
            for k, f in runs.items():
                t = time.perf_counter()
                f(c, pattern="bayer")
                times[k].append(time.perf_counter() - t)
        med = {k: statistics.median(v) * 1e3 for k, v in times.items()}
        print(f"{shape[0]}x{shape[1]}: Menon this {med['this']:.1f} ms, other "
              f"{med['other']:.1f} ms; Malvar (this) {med['malvar']:.1f} ms; the same "
              f"image: {np.array_equal(images['this'], images['other'])}")


if __name__ == "__main__":
    if sys.argv[1:2] == ["isp"]:
        isp(sys.argv[2], *(int(a) for a in sys.argv[3:4]))
    else:
        main(*(int(a) for a in sys.argv[1:2]))
