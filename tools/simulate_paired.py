"""``simulate``, this checkout against another commit's package loaded beside it (made by
``tools/tof_unguided_paired.py --make``), alternated call by call: the same frame, and the
speed.

    python tools/simulate_paired.py DIR [ROUNDS] [WORKERS] [--optics] [--bench] [--noise-free]
    python tools/simulate_paired.py DIR [ROUNDS] --scene

The 12 MP art scene of tools/tof_guided_speed.py (depth included; its arrays come from
fancy indexing, so they are not in C order, as a user's transposed or indexed arrays), Mask1,
seed 1, with ``optics=Optics()`` when asked, or with ``--bench`` the scene of ``rgbz-fast bench
--chain`` (its 8-bit image and depth plane, C-ordered), noise-free with ``--noise-free``;
with ``--scene`` the building of a Scene from the bench's 8-bit image (its sRGB decoding): medians, the median of the rounds' speed ratios
(> 1: this checkout is faster), and whether the colour data and the taps are equal.
"""
import importlib
import os
import statistics
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from tof_unguided_paired import HERE, alternate  # noqa: E402


def scene(pkg):
    sim = importlib.import_module(f"{pkg}.simulation")
    s = sim.load_rgbd(HERE.parent / ".." / "shared" / "data" / "rgbd" / "art")
    ri = np.arange(3000) * s.shape[0] // 3000
    ci = np.arange(4000) * s.shape[1] // 4000
    return sim, sim.Scene(s.image[ri][:, ci], depth=s.depth[ri][:, ci],
                          depth_valid=s.depth_valid[ri][:, ci])


def bench_scene(pkg):
    sim = importlib.import_module(f"{pkg}.simulation")
    cases = importlib.import_module(f"{pkg}._devtools.bench.cases")
    return sim, sim.Scene(cases.make_rgb(cases.FULL_SHAPE),
                          depth=cases.bench_depth(cases.FULL_SHAPE))


def scene_build(other_dir, rounds):
    """The Scene of the bench's 8-bit 12 MP image, both builds alternated."""
    importlib.import_module("rgbz_fast._kernels")
    sys.path.insert(0, str(Path(other_dir).resolve()))
    runs = {}
    for name, pkg in (("this", "rgbz_fast"), ("other", "rgbz_old")):
        sim = importlib.import_module(f"{pkg}.simulation")
        cases = importlib.import_module(f"{pkg}._devtools.bench.cases")
        runs[name] = (lambda sim=sim, rgb=cases.make_rgb(cases.FULL_SHAPE): sim.Scene(rgb))
    same = np.array_equal(runs["this"]().image, runs["other"]().image)
    t, ratio = alternate(runs, rounds)
    print(f"Scene(8-bit 12 MP image): {statistics.median(t['this']):.3f} s against "
          f"{statistics.median(t['other']):.3f} s, speed ratio {ratio:.3f}, same image: {same}; "
          f"load average {os.getloadavg()[0]:.1f}, {os.cpu_count()} cores, {rounds} rounds")


def main(other_dir, rounds=3, workers=2, optics=False, bench=False, noise_free=False):
    importlib.import_module("rgbz_fast._kernels")            # this extension first
    sys.path.insert(0, str(Path(other_dir).resolve()))
    runs = {}
    for name, pkg in (("this", "rgbz_fast"), ("other", "rgbz_old")):
        sim, sc = (bench_scene if bench else scene)(pkg)
        kw = dict(noise=False) if noise_free else dict(seed=1)
        runs[name] = (lambda sim=sim, sc=sc, kw=kw: sim.simulate(
            sc, "mask1", optics=sim.Optics() if optics else None, workers=workers, **kw))
    a, b = runs["this"](), runs["other"]()
    same = np.array_equal(a.data, b.data) and np.array_equal(a.tof.taps, b.tof.taps)
    t, ratio = alternate(runs, rounds)
    label = "Optics()" if optics else "None"
    print(f"simulate({'bench' if bench else 'art'} 12 MP, 'mask1', noise={not noise_free}, optics={label}, workers={workers}): "
          f"{statistics.median(t['this']):.2f} s against {statistics.median(t['other']):.2f} s, "
          f"speed ratio {ratio:.3f}, same frame: {same}; load average "
          f"{os.getloadavg()[0]:.1f}, {os.cpu_count()} cores, {rounds} rounds")


if __name__ == "__main__":
    flags = ("--optics", "--bench", "--noise-free", "--scene")
    args = [a for a in sys.argv[1:] if a not in flags]
    if "--scene" in sys.argv:
        scene_build(args[0], *(int(a) for a in args[1:2]))
        sys.exit()
    main(args[0], *(int(a) for a in args[1:3]), optics="--optics" in sys.argv,
         bench="--bench" in sys.argv, noise_free="--noise-free" in sys.argv)
