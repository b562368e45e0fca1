"""What the guided ToF ISP lets through on scenes it was not tuned on: every valid measurement
more than 5 cm off, with the single measurement's depth and sigma beside the guided one's, and
the caught share under the settings that trade it. The section "Measured: two scenes no
default was chosen on" of docs/reports/isp.md.

    python tools/tof_heldout_misses.py HELD [SEEDS] [PATTERNS]   # HELD: tools/heldout_rgbd.py's OUT

SEEDS (default 1,2,3) and PATTERNS (default mask2) are comma lists. Each frame is
``simulate(scene, pattern, seed=seed)`` and its guide ``ColourISP().run(frame)``, as
``rgbz-fast evaluate-depth --sections scenes`` makes them; "single" is ``ToFISP(denoise="none")``
on the same taps. The second table pools HELD and ../shared/data/rgbd (the six scenes the
defaults were chosen on) separately.
"""

import sys
from pathlib import Path

import numpy as np

from rgbz_fast.evaluation._depth_guided import scene_folders
from rgbz_fast.isp import ColourISP
from rgbz_fast.simulation import load_rgbd, simulate
from rgbz_fast.tof import ToFISP

SIX = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "rgbd"
SETTINGS = (("default", {}), ("range_scale 1.8", {"range_scale": 1.8}),
            ("flying_step 0.04", {"flying_step": 0.04}),
            ("flying_step 0.03", {"flying_step": 0.03}))


def frames(data, patterns, seeds):
    for name in scene_folders(data):
        scene = load_rgbd(Path(data) / name)
        for pattern in patterns:
            for seed in seeds:
                frame = simulate(scene, pattern, seed=seed)
                yield name, pattern, seed, frame.tof, ColourISP().run(frame)


def misses(held, patterns, seeds):
    print("| scene | pattern | seed | site (row, col) | true m | guided error cm | guided sigma "
          "cm | single error cm | single sigma cm |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, pattern, seed, tof, guide in frames(held, patterns, seeds):
        res, single = ToFISP().run(tof, guide=guide), ToFISP(denoise="none").run(tof)
        err = res.depth - tof.depth_true
        r, c = (np.asarray(a) for a in tof.sites)
        for i in np.flatnonzero((np.abs(err) > 0.05) & tof.valid & res.valid):
            print(f"| {name} | {pattern} | {seed} | ({r[i]}, {c[i]}) | {tof.depth_true[i]:.3f} | "
                  f"{100 * err[i]:+.1f} | {100 * res.sigma[i]:.2f} | "
                  f"{100 * (single.depth[i] - tof.depth_true[i]):+.1f} | "
                  f"{100 * single.sigma[i]:.2f} |")


def settings(held, patterns, seeds):
    runs = {label: list(frames(data, patterns, seeds))
            for label, data in (("held-out", held), ("six", SIX))}
    print("\n| setting | pattern | scenes | valid % | valid & > 5 cm % | caught % (missed / "
          "wrong) |")
    print("|---|---|---|---|---|---|")
    for label, fields in SETTINGS:
        isp = ToFISP(**fields)
        for pattern in patterns:
            for which, items in runs.items():
                known = valid = wrong = missed = 0
                for _, p, _, tof, guide in items:
                    if p != pattern:
                        continue
                    res = isp.run(tof, guide=guide)
                    bad = (np.abs(res.depth - tof.depth_true) > 0.05) & tof.valid
                    known += int(tof.valid.sum())
                    valid += int((res.valid & tof.valid).sum())
                    wrong += int(bad.sum())
                    missed += int((bad & res.valid).sum())
                print(f"| {label} | {pattern} | {which} | {100 * valid / known:.2f} | "
                      f"{100 * missed / known:.4f} | {100 * (wrong - missed) / wrong:.2f} "
                      f"({missed} / {wrong}) |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    seeds = [int(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "1,2,3").split(",")]
    patterns = (sys.argv[3] if len(sys.argv) > 3 else "mask2").split(",")
    misses(sys.argv[1], patterns, seeds)
    settings(sys.argv[1], patterns, seeds)
