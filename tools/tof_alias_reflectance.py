"""Valid measurements more than 5 cm off on flat walls, with and without ToFISP's upper bound
on the implied reflectance (``max_reflectance``), for frequency sets whose aliases lie close in
phase (docs/guide/isp.md, the out-of-range flag): Mask2, walls of reflectance 0.5 at 0.8-2.5 m,
64 x 64 pixels, seeds 2 and 7.

    python tools/tof_alias_reflectance.py      # about half a minute
"""
import warnings

import numpy as np

from rgbz_fast import ToFSensor
from rgbz_fast.simulation import Scene, simulate_tof
from rgbz_fast.tof import ToFISP

SETS = ((80e6, 100e6, 120.1e6), (80.5e6, 100e6, 120e6), (100e6, 100.5e6), (80e6, 100e6, 120e6))
DEPTHS = (0.8, 1.0, 1.5, 2.0, 2.5)


def main():
    print("| frequencies (MHz) | wall (m) | off & valid / valid, default | without the bound | "
          "farthest off & valid depth without it (m) |")
    print("|---|---|---|---|---|")
    for fr in SETS:
        sensor = ToFSensor(frequencies=fr)
        tot = {}
        for d in DEPTHS:
            row = [0, 0, 0, 0]
            far = 0.0
            for seed in (2, 7):
                scene = Scene(np.full((64, 64, 3), 0.5), depth=np.full((64, 64), d),
                              ir_reflectance=np.full((64, 64), 0.5))
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    taps = simulate_tof(scene, "mask2", sensor, seed=seed)
                for k, isp in enumerate((ToFISP(), ToFISP(max_reflectance=None))):
                    r = isp.run(taps)
                    bad = r.valid & (np.abs(r.depth - d) > 0.05)
                    row[2 * k] += int(bad.sum())
                    row[2 * k + 1] += int(r.valid.sum())
                    if k == 1 and bad.any():
                        far = max(far, float(r.depth[bad].max()))
            for i, v in enumerate(row):
                tot[i] = tot.get(i, 0) + v
            print(f"| {'/'.join(f'{f / 1e6:g}' for f in fr)} | {d} | {row[0]} / {row[1]} | "
                  f"{row[2]} / {row[3]} | {far:.2f} |")
        print(f"| {'/'.join(f'{f / 1e6:g}' for f in fr)} | all | {tot[0]} / {tot[1]} | "
              f"{tot[2]} / {tot[3]} | |")


if __name__ == "__main__":
    main()
