"""``save_frame`` and ``load_frame`` of an NPZ frame, this checkout against another commit's
package loaded beside it (made by ``tools/tof_unguided_paired.py --make``), alternated call
by call: the time, the file's size, and whether each side reads the other's file back to the
same frame.

    python tools/frame_io_paired.py DIR [ROUNDS]   # a few minutes

The 12 MP Mask1 frame of tools/tof_guided_speed.py (art scaled to 3000x4000, its ToF taps
included), written to a temporary folder; medians and the median of the rounds' speed
ratios (> 1: this checkout is faster).
"""
import importlib
import os
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from simulate_paired import scene  # noqa: E402
from tof_unguided_paired import alternate  # noqa: E402


def frame(pkg):
    sim, sc = scene(pkg)
    return sim.simulate(sc, "mask1", seed=1)


def same(a, b):
    return (np.array_equal(a.data, b.data) and np.array_equal(a.reference, b.reference)
            and np.array_equal(a.tof.taps, b.tof.taps)
            and np.array_equal(a.tof.depth_true, b.tof.depth_true)
            and a.pattern.tile_string == b.pattern.tile_string)


def main(other_dir, rounds=5):
    importlib.import_module("rgbz_fast._kernels")            # this extension first
    sys.path.insert(0, str(Path(other_dir).resolve()))
    io = {"this": importlib.import_module("rgbz_fast.io"),
          "other": importlib.import_module("rgbz_old.io")}
    fr = {"this": frame("rgbz_fast"), "other": frame("rgbz_old")}
    with tempfile.TemporaryDirectory() as tmp:
        paths = {k: Path(tmp) / f"{k}.npz" for k in io}
        saves = {k: (lambda k=k: io[k].save_frame(paths[k], fr[k])) for k in io}
        loads = {k: (lambda k=k: io[k].load_frame(paths[k])) for k in io}
        for run in saves.values():
            run()
        back = {k: io[k].load_frame(paths[k]) for k in io}
        cross = {k: io[k].load_frame(paths["other" if k == "this" else "this"]) for k in io}
        t_save, r_save = alternate(saves, rounds)
        t_load, r_load = alternate(loads, rounds)
        size = {k: paths[k].stat().st_size / 2 ** 20 for k in io}
    print("| 12 MP Mask1 frame with ToF taps | this | other | speed ratio |")
    print("|---|---|---|---|")
    print(f"| `save_frame`, s | {statistics.median(t_save['this']):.2f} | "
          f"{statistics.median(t_save['other']):.2f} | {r_save:.2f}x |")
    print(f"| `load_frame`, s | {statistics.median(t_load['this']):.2f} | "
          f"{statistics.median(t_load['other']):.2f} | {r_load:.2f}x |")
    print(f"| file, MiB | {size['this']:.1f} | {size['other']:.1f} | |")
    print(f"each reads back its own frame: "
          f"{all(same(fr['this'], b) for b in back.values())}; the other's: "
          f"{all(same(fr['this'], b) for b in cross.values())}; load average "
          f"{os.getloadavg()[0]:.1f}, {os.cpu_count()} cores, {rounds} rounds")


if __name__ == "__main__":
    main(sys.argv[1], *(int(a) for a in sys.argv[2:3]))
