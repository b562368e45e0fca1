"""The serial Python of the colour-guided ToF ISP on the 12 MP frame of tof_guided_speed.py:
CPU and wall time of each piece a call runs outside the C kernels' threads (the benchmarks' section
"The guided ISP's serial Python").

    python tools/tof_guided_serial.py [ROUNDS]      # about half a minute (plus the simulation)

The pieces alternate round by round, 1 thread unless named; medians (and the best).
"""

import os
import statistics
import sys
import time

import numpy as np

from tof_guided_speed import frame_12mp

from rgbz_fast import _kernels  # noqa: E402
from rgbz_fast.tof import ToFISP, _guided  # noqa: E402


def main(rounds=15):
    frame, guide = frame_12mp()
    tof = frame.tof
    res = ToFISP().run(tof, guide=guide, workers=1)
    layout = _guided._layout_of(tof.sites, tof.block, tof.shape)
    g, scale = _guided.check_guide(guide, tof.shape)
    flags, depth, sigma = np.ascontiguousarray(res.flags), res.measured, res.sigma
    bad = _guided.FLAG_SATURATED | _guided.FLAG_LOW_SIGNAL
    neff = res.count.astype(np.float32)
    col = np.ones((3, layout.N), np.float32)
    inv = np.ones((3, 1), np.float32)

    def usable_numpy():
        u = ((flags & bad) == 0) & layout.present
        u &= np.isfinite(depth) & np.isfinite(sigma)
        return u

    def usable_kernel(workers):
        u = np.empty(layout.N, np.uint8)
        _kernels.tofg_usable(flags, depth, sigma, None, bad, u, workers)
        return u

    assert np.array_equal(usable_numpy(), usable_kernel(1).view(bool))

    cases = {"the layout proven a grid (_Layout)": lambda: _guided._Layout(tof.sites, tof.block,
                                                                            tof.shape),
             "the layout of the same ToFTaps again (_layout_of)":
                 lambda: _guided._layout_of(tof.sites, tof.block, tof.shape),
             "the flying test's usable mask in NumPy": usable_numpy,
             "the flying test's usable mask, tofg_usable, 1 thread": lambda: usable_kernel(1),
             "the flying test's usable mask, tofg_usable, 2 threads": lambda: usable_kernel(2),
             "count to float64": lambda: neff.astype(np.float64),
             "the guide's colours scaled by their noise (col *= inv)": lambda: col.__imul__(inv),
             "guide_colours (its kernel on 1 thread and the scaling)":
                 lambda: _guided.guide_colours(g, scale, layout, 1)}
    cpu = {k: [] for k in cases}
    wall = {k: [] for k in cases}
    for _ in range(rounds):
        for name, run in cases.items():
            c, t = time.process_time(), time.perf_counter()
            run()
            wall[name].append(time.perf_counter() - t)
            cpu[name].append(time.process_time() - c)
    print("| piece | CPU ms, median (best) | wall ms, median (best) |")
    print("|---|---|---|")
    for name in cases:
        print(f"| {name} | {statistics.median(cpu[name]) * 1e3:.2f} ({min(cpu[name]) * 1e3:.2f}) "
              f"| {statistics.median(wall[name]) * 1e3:.2f} ({min(wall[name]) * 1e3:.2f}) |")
    print(f"load average {os.getloadavg()[0]:.1f}, {tof.n_sites} measurements")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 15)
