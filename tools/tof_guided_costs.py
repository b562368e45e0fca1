"""What the guided ToF ISP's two changes of 2026-11-27 (evening) cost in time: the range term
that knows the fixed pattern (col's fourth plane, ``tofg_denoise``) and Mask1's window of 31
cells. The section "The guided ISP's fixed-pattern range term and Mask1's window" of
docs/reports/benchmarks.md.

    python tools/tof_guided_costs.py [ROUNDS]     # about a minute

1. ``_kernels.tofg_denoise`` on a synthetic 1500 x 2000 grid (3 M measurements, F = 3,
   window 21, 2 threads) with col (3, N) and with col (4, N) (the fixed-pattern shares):
   the same call but the range term, alternated round by round; medians of wall and CPU.
2. ``ToFISP().run(tof, guide=image)`` on tools/tof_guided_speed.py's 12 MP Mask1 frame
   (art scaled to 3000 x 4000), the default window (31 on Mask1) against ``window=21``,
   alternated; medians, and the median of the rounds' CPU ratios.
"""

import statistics
import sys
import time
from pathlib import Path

import numpy as np

from rgbz_fast import _kernels
from rgbz_fast.tof import ToFISP

sys.path.insert(0, str(Path(__file__).resolve().parent))
from tof_guided_speed import frame_12mp  # noqa: E402


def _timed(fn):
    c, w = time.process_time(), time.perf_counter()
    fn()
    return time.perf_counter() - w, time.process_time() - c


def _table(name, cases, units, times):
    for k in cases:
        w = statistics.median(a for a, _ in times[k])
        c = statistics.median(b for _, b in times[k])
        print(f"| {name} | {k} | {w:.3f} s | {c / units * 1e9:.0f} ns |")


def main(rounds=7):
    print("| case | variant | wall, median | CPU per measurement, median |")
    print("|---|---|---|---|")
    R, C, F = 1500, 2000, 3
    N = R * C
    rng = np.random.default_rng(0)
    zr = (300 + rng.normal(0, 20, (F, N))).astype(np.float32)
    zi = (150 + rng.normal(0, 20, (F, N))).astype(np.float32)
    v = rng.uniform(300, 500, N).astype(np.float32)
    col3 = rng.normal(0, 0.7, (3, N)).astype(np.float32)
    col4 = np.ascontiguousarray(np.vstack([col3, rng.uniform(0, 0.8, (1, N))]), np.float32)
    use = np.ones(N, np.uint8)
    rows, cols = np.arange(R, dtype=np.int64) * 2, np.arange(C, dtype=np.int64) * 2
    out = (np.empty((F, N)), np.empty((F, N)), np.empty(N, np.float32), np.empty(N, np.float32))
    cases = {"col (3, N): independent frequencies": col3, "col (4, N): the fixed pattern": col4}
    times = {k: [] for k in cases}
    for _ in range(rounds):
        for k, col in cases.items():
            times[k].append(_timed(lambda: _kernels.tofg_denoise(
                zr, zi, v, col, use, rows, cols, 10, 10, 20, 0.125, 0.02, *out, 2)))
    _table("tofg_denoise, 3 M synthetic", cases, N, times)
    a, b = cases
    ratio = statistics.median(y[1] / x[1] for x, y in zip(times[a], times[b]))
    frame, guide = frame_12mp()
    tof = frame.tof
    isps = {"default (31 on Mask1)": ToFISP(), "window=21": ToFISP(window=21)}
    for isp in isps.values():
        isp.run(tof, guide=guide, workers=2)
    times = {k: [] for k in isps}
    for _ in range(rounds):
        for k, isp in isps.items():
            times[k].append(_timed(lambda: isp.run(tof, guide=guide, workers=2)))
    _table("ToFISP().run(tof, guide=image), 12 MP Mask1", isps, tof.n_sites, times)
    a2, b2 = isps
    ratio2 = statistics.median(x[1] / y[1] for x, y in zip(times[a2], times[b2]))
    print(f"\nCPU ratios (medians of the rounds): fixed-pattern term / without {ratio:.3f}; "
          f"window 31 / 21 {ratio2:.3f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
