"""How upsample_depth's defaults were chosen: its full-resolution scores at several
``ambiguity``, ``colour_scale`` and ``max_sigma`` settings on four Middlebury scenes, and on the
two held out.

    python tools/tof_upsample_tuning.py    # a minute or two; a table of docs/reports/isp.md

The frames are those of ``rgbz-fast evaluate-depth --sections upsample``:
``simulate(scene, pattern, seed=1)``, the guide ``ColourISP().run(frame)``, the default guided
``ToFISP()``. The settings were compared on the four (aloe, baby1, bowling1, flowerpots);
art (the one full-size Middlebury 2005 scene, the closest to scenes the library has not seen)
and rocks1 only check the choice. Scores pool the pixels of the scenes of a split whose depth
is known: covered %, the covered share more than 5 cm off, and the edge-weighted MAE over that
of the nearest valid measurement on the pixels both cover (``w = |numpy.gradient(depth)|``).
"""

import sys
from pathlib import Path

import numpy as np

from rgbz_fast.evaluation._depth_guided import scene_runs, upsample_baselines
from rgbz_fast.tof import ToFISP, upsample_depth
from rgbz_fast.tof._guided import UPSAMPLE_AMBIGUITY, UPSAMPLE_COLOUR_SCALE, UPSAMPLE_MAX_SIGMA

DATA = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "rgbd"
TRAIN = ("aloe", "baby1", "bowling1", "flowerpots")
HELD_OUT = ("art", "rocks1")
#: (ambiguity, colour_scale, max_sigma); ambiguity 1: never abstain (a pixel whose heaviest node
#: is a low-signal measurement no neighbour agrees with still gets none); max_sigma None: no
#: low-signal measurement takes part (each only vetoes)
_MS = UPSAMPLE_MAX_SIGMA
SETTINGS = ((1.0, 5.0, _MS), (1.0, 20.0, _MS), (0.1, 5.0, _MS), (0.15, 5.0, _MS),
            (0.1, 10.0, _MS), (0.15, 10.0, _MS), (0.1, 20.0, _MS), (0.15, 20.0, _MS),
            (0.2, 20.0, _MS), (0.15, 40.0, _MS),
            (0.15, 20.0, None), (0.15, 20.0, 0.0175), (0.15, 20.0, 0.025), (0.15, 20.0, 0.03))
_DEFAULT = (UPSAMPLE_AMBIGUITY, UPSAMPLE_COLOUR_SCALE, UPSAMPLE_MAX_SIGMA)


def main(data=DATA):
    sums = {}
    for run in scene_runs(data, ("mask1", "mask2"), ToFISP(), 1, {}):
        split = "the four" if run["scene"] in TRAIN else "art, rocks1" \
            if run["scene"] in HELD_OUT else None
        if split is None:
            continue
        res, truth, known = run["guided"], run["depth"], run["depth_valid"]
        weight = np.hypot(*np.gradient(truth))
        nearest, _ = upsample_baselines(res)
        for setting in SETTINGS:
            est, _ = upsample_depth(res, run["guide"], ambiguity=setting[0],
                                    colour_scale=setting[1], max_sigma=setting[2])
            cov = known & np.isfinite(est)
            err = np.abs(est.astype(np.float64) - truth)
            both = cov & np.isfinite(nearest)
            s = sums.setdefault((split, run["pattern"], setting), np.zeros(5))
            s += (known.sum(), cov.sum(), (err[cov] > 0.05).sum(), (weight * err)[both].sum(),
                  (weight * np.abs(nearest - truth))[both].sum())
    print("| scenes | pattern | ambiguity | colour_scale | max_sigma m | covered % | wrong % | "
          "edge MAE / nearest |")
    print("|---|---|---|---|---|---|---|---|")
    for (split, pattern, (amb, cs, ms)), s in sums.items():
        mark = " (default)" if (amb, cs, ms) == _DEFAULT else ""
        print(f"| {split} | {pattern} | {amb:g}{mark} | {cs:g} | "
              f"{'none' if ms is None else f'{ms:g}'} | {100 * s[1] / s[0]:.2f} | "
              f"{100 * s[2] / s[1]:.3f} | {s[3] / s[4]:.3f} |")


if __name__ == "__main__":
    main(*sys.argv[1:2])
