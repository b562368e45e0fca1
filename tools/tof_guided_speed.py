"""Speed of the colour-guided ToF ISP and of upsample_depth beside the unguided ISP and the fused
kernel: the table "Speed of the guided ISP" of docs/reports/isp.md.

    python tools/tof_guided_speed.py [ROUNDS]     # about a minute (plus the simulation)

A 12 MP Mask1 frame (art from ../shared/data/rgbd scaled to 3000x4000, 3 M measurements,
``simulate(scene, "mask1", seed=1)``) and its guide ``ColourISP().run(frame)``; 2 threads;
the cases alternate round by round; medians (and the best) of the wall time, and the
median CPU time (all threads) per measurement or pixel, which a busy machine inflates far
less than the wall time.
"""

import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from rgbz_fast.isp import ColourISP
from rgbz_fast.simulation import Scene, load_rgbd, simulate
from rgbz_fast.tof import ToFISP, demodulate_unwrap, upsample_depth

DATA = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "rgbd" / "art"


def frame_12mp():
    """art scaled (nearest) to 3000 x 4000: a real image with real depth edges."""
    scene = load_rgbd(DATA)
    H, W = 3000, 4000
    ri = np.arange(H) * scene.shape[0] // H
    ci = np.arange(W) * scene.shape[1] // W
    big = Scene(scene.image[ri][:, ci], depth=scene.depth[ri][:, ci],
                depth_valid=scene.depth_valid[ri][:, ci])
    frame = simulate(big, "mask1", seed=1)
    return frame, ColourISP().run(frame)


def main(rounds=5):
    frame, guide = frame_12mp()
    tof, isp = frame.tof, ToFISP()
    result = isp.run(tof, guide=guide, workers=2)
    cases = {"ToFISP().run(tof, guide=image)": (lambda: isp.run(tof, guide=guide, workers=2),
                                                tof.n_sites),
             "ToFISP().run(tof)": (lambda: isp.run(tof, workers=2), tof.n_sites),
             "demodulate_unwrap (the fused kernel alone)":
                 (lambda: demodulate_unwrap(tof.taps, tof.frequencies, workers=2), tof.n_sites),
             "upsample_depth(result, image) (12 MP)":
                 (lambda: upsample_depth(result, guide, workers=2), guide.shape[0] * guide.shape[1])}
    wall = {k: [] for k in cases}
    cpu = {k: [] for k in cases}
    for _ in range(rounds):
        for name, (run, _) in cases.items():
            c, t = time.process_time(), time.perf_counter()
            run()
            wall[name].append(time.perf_counter() - t)
            cpu[name].append(time.process_time() - c)
    print("| case | wall, median (best) | CPU per measurement or pixel |")
    print("|---|---|---|")
    for name, (_, units) in cases.items():
        print(f"| `{name}` | {statistics.median(wall[name]):.2f} s ({min(wall[name]):.2f} s) | "
              f"{statistics.median(cpu[name]) / units * 1e9:.0f} ns |")
    print(f"load average {os.getloadavg()[0]:.1f}, {tof.n_sites} measurements")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5)
