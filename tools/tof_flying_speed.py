"""The flying-pixel test's C kernel against the NumPy code it replaced, in the unguided ToF ISP.

    python tools/tof_flying_speed.py [ROUNDS] [WORKERS]      # a minute or two

The 12 MP frame of tools/tof_guided_speed.py (art scaled to 3000x4000, Mask1, 3 M
measurements). ``ToFISP(denoise=...).run(tof)`` for "none", "box" and "bilateral" (the
default), and ``flying_pixels`` alone on that result, each run with the library's
``flying_pixels`` (csrc/tof_guided.c, rgbz_tofg_flying_candidates) and with the whole-grid NumPy
code it replaced (tests/_reference/tof.py, which the tests hold it to flag for flag),
alternated round by round: medians of the wall times and their ratio (> 1: the C kernel
is faster). The flags are compared too.
"""
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
sys.path.insert(0, str(HERE))

from _reference import tof as ref  # noqa: E402
from tof_guided_speed import frame_12mp  # noqa: E402

import rgbz_fast.tof._validity as V  # noqa: E402
from rgbz_fast.tof import ToFISP  # noqa: E402
from rgbz_fast.tof._filters import SiteGrid  # noqa: E402

C_KERNEL = V.flying_pixels


def numpy_code(*args, workers=None, **kw):
    return ref.flying_pixels(*args, **kw)


def paired(run, rounds, module=V, name="flying_pixels", c_code=C_KERNEL, numpy=numpy_code):
    """run() with module.name set to c_code ("C") and to numpy ("NumPy") in turn, the order
    swapped every round, one warm-up round: the medians of both and the last outputs."""
    t = {"C": [], "NumPy": []}
    out = {}
    for i in range(rounds + 1):
        for variant in (("C", "NumPy") if i % 2 else ("NumPy", "C")):
            setattr(module, name, c_code if variant == "C" else numpy)
            try:
                a = time.perf_counter()
                out[variant] = run()
                s = time.perf_counter() - a
            finally:
                setattr(module, name, c_code)
            if i:
                t[variant].append(s)
    return np.median(t["C"]), np.median(t["NumPy"]), out


def denoise_rows(tof, rounds, workers, fields, label, **stage):
    """One line per denoise: ``ToFISP(denoise=...).run(tof)`` with the C and the NumPy
    ``stage`` (paired's module, name, c_code, numpy) and whether ``fields`` are equal."""
    for denoise in ("none", "box", "bilateral"):
        isp = ToFISP(denoise=denoise)
        c, n, out = paired(lambda: isp.run(tof, workers=workers), rounds, **stage)
        same = all(np.array_equal(np.asarray(getattr(out["C"], k)).view(np.uint8),
                                  np.asarray(getattr(out["NumPy"], k)).view(np.uint8))
                   for k in fields)
        print(f"ToFISP(denoise={denoise!r}).run(tof): C {c:.3f} s, NumPy {n:.3f} s, "
              f"{n / c:.3f}x; {label} equal: {same}", flush=True)


def main(rounds=7, workers=2):
    frame, _ = frame_12mp()
    tof = frame.tof
    print(f"{tof.n_sites} measurements, {workers} thread(s), {rounds} rounds")
    denoise_rows(tof, rounds, workers, ("flags",), "flags")
    res = ToFISP().run(tof, workers=workers)
    grid = SiteGrid(tof.sites, tof.block)
    usable = (res.flags & 3) == 0
    c, n, out = paired(lambda: V.flying_pixels(res.depth, res.sigma, grid, block=tof.block,
                                               usable=usable, workers=workers), rounds)
    print(f"flying_pixels alone: C {1e3 * c:.1f} ms, NumPy {1e3 * n:.1f} ms, {n / c:.2f}x; "
          f"equal: {np.array_equal(out['C'], out['NumPy'])}")


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:3]))
