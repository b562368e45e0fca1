"""The guided ToF ISP's trade on photon-limited scenes: its Mask1 targets (valid >= 85 %, valid
and more than 5 cm off <= 0.05 %, >= 97 % of those more than 5 cm off caught) at wider windows
and narrower range scales, on the six Middlebury scenes, on art alone (the one Middlebury 2005
scene, photon-limited on Mask1 like the 2005 scenes the library has not seen) and on the five
2006 ones; and the valid share the same settings keep on a textured slanted wall. The table
"The guided ISP on photon-limited scenes" of docs/reports/isp.md.

    python tools/tof_guided_trade.py [DATA]     # about a minute; DATA: ../shared/data/rgbd

Each frame is ``simulate(scene, "mask1", seed=1)`` and its guide ``ColourISP().run(frame)``, as
``rgbz-fast evaluate-depth --sections scenes`` makes them. "low-signal only" is
``ToFISP(low_signal_window=41)``: the ISP runs twice, the default window then the wider one, and
takes the wider one's result for the measurements the default flagged low-signal alone where the
two depths agree within the default's sigma.
"""

import sys
from pathlib import Path

import numpy as np

from rgbz_fast.evaluation._depth_guided import scene_folders
from rgbz_fast.isp import ColourISP
from rgbz_fast.simulation import load_rgbd, simulate
from rgbz_fast.tof import ToFISP

DATA = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "rgbd"
#: (label, ToFISP fields, low-signal only)
SETTINGS = (("default (window 31, range scale 2)", {}, False),
            ("window 21 (the default before 2026-11-27)", {"window": 21}, False),
            ("window 41", {"window": 41}, False),
            ("window 41, range scale 1.8", {"window": 41, "range_scale": 1.8}, False),
            ("window 41, low-signal only", {"window": 41}, True))


def _run(frame, guide, fields, low_only):
    res = ToFISP(**({"low_signal_window": fields["window"]} if low_only else fields)).run(
        frame.tof, guide=guide)
    return res.depth, res.valid


def _slope_frame():
    """tests/tof/test_guided.py's two boxes in front of a textured wall on a slanted floor
    (its ``_frame``), at 192 x 256 pixels: the frame and its guide."""
    tests = Path(__file__).resolve().parents[1] / "tests"
    sys.path[:0] = [str(tests), str(tests / "tof")]
    from test_guided import _frame

    frame, guide, _ = _frame("mask1", shape=(192, 256), seed=2)
    return frame, guide


def main(data=DATA):
    frames = []
    for name in scene_folders(data):
        frame = simulate(load_rgbd(Path(data) / name), "mask1", seed=1)
        frames.append((name, frame, ColourISP().run(frame)))
    slope, slope_guide = _slope_frame()
    print("| Mask1, guided | six scenes: valid % / valid & > 5 cm % / caught % | art | "
          "the five 2006 scenes | textured slanted wall: valid % |")
    print("|---|---|---|---|---|")
    for label, fields, low_only in SETTINGS:
        sums = {"six": np.zeros(4), "art": np.zeros(4), "2006": np.zeros(4)}
        for name, frame, guide in frames:
            depth, valid = _run(frame, guide, fields, low_only)
            known = frame.tof.valid
            wrong = (np.abs(depth - frame.tof.depth_true) > 0.05) & known
            v = np.array([known.sum(), (valid & known).sum(), wrong.sum(),
                          (wrong & valid).sum()], float)
            sums["six"] += v
            sums["art" if name == "art" else "2006"] += v
        _, sv = _run(slope, slope_guide, fields, low_only)
        cells = [f"{100 * s[1] / s[0]:.2f} / {100 * s[3] / s[0]:.4f} / "
                 f"{100 * (1 - s[3] / s[2]):.2f}" for s in sums.values()]
        print(f"| {label} | " + " | ".join(cells)
              + f" | {100 * sv[slope.tof.valid].mean():.1f} |")


if __name__ == "__main__":
    main(*sys.argv[1:2])
