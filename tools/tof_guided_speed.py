"""Speed of the colour-guided ToF ISP and of upsample_depth beside the unguided ISP and the fused
kernel: the table "Speed of the guided ISP" of docs/reports/isp.md.

    python tools/tof_guided_speed.py [ROUNDS] [--kernels SO | --package DIR]   # a minute

A 12 MP Mask1 frame (art from ../shared/data/rgbd scaled to 3000x4000, 3 M measurements,
``simulate(scene, "mask1", seed=1)``) and its guide ``ColourISP().run(frame)``; 2 threads;
the cases alternate round by round; medians (and the best) of the wall time, and the
median CPU time (all threads) per measurement or pixel, which a busy machine inflates far
less than the wall time, and its user part (the system part is mostly the kernel zeroing
the fresh pages of the arrays a call returns, which swings with the machine's load).

``--kernels SO`` runs the extension module SO (another build's ``_kernels*.so``) in place of
the installed one: the same tool, alternated with it in turn, pairs two builds.
``--package DIR`` runs the package ``DIR/rgbz_fast`` (another checkout's ``src/rgbz_fast``
with its build's extension modules and ``_build_config.py`` copied in) in place of the
installed one: it pairs two builds whose Python calls the kernels differently.
"""

import importlib.util
import os
import resource
import statistics
import sys
import time
from pathlib import Path


def _kernels_from(path):
    """Load rgbz_fast._kernels from the extension module `path` before the package imports
    its own."""
    spec = importlib.util.spec_from_file_location("rgbz_fast._kernels", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules["rgbz_fast._kernels"] = module
    spec.loader.exec_module(module)


def _package_from(path):
    """Import rgbz_fast from the directory `path` instead of the editable install."""
    sys.meta_path[:] = [f for f in sys.meta_path if type(f).__name__ != "MesonpyMetaFinder"]
    sys.path.insert(0, str(Path(path).resolve()))


if "--kernels" in sys.argv:
    _i = sys.argv.index("--kernels")
    _kernels_from(sys.argv[_i + 1])
    del sys.argv[_i:_i + 2]
if "--package" in sys.argv:
    _i = sys.argv.index("--package")
    _package_from(sys.argv[_i + 1])
    del sys.argv[_i:_i + 2]

import numpy as np  # noqa: E402

import rgbz_fast  # noqa: E402

from rgbz_fast.isp import ColourISP  # noqa: E402
from rgbz_fast.simulation import Scene, load_rgbd, simulate  # noqa: E402
from rgbz_fast.tof import ToFISP, demodulate_unwrap, upsample_depth  # noqa: E402

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
    user = {k: [] for k in cases}
    for _ in range(rounds):
        for name, (run, _) in cases.items():
            r0 = resource.getrusage(resource.RUSAGE_SELF)
            c, t = time.process_time(), time.perf_counter()
            run()
            wall[name].append(time.perf_counter() - t)
            cpu[name].append(time.process_time() - c)
            user[name].append(resource.getrusage(resource.RUSAGE_SELF).ru_utime - r0.ru_utime)
    print("| case | wall, median (best) | CPU per measurement or pixel | of which user |")
    print("|---|---|---|---|")
    for name, (_, units) in cases.items():
        print(f"| `{name}` | {statistics.median(wall[name]):.2f} s ({min(wall[name]):.2f} s) | "
              f"{statistics.median(cpu[name]) / units * 1e9:.0f} ns | "
              f"{statistics.median(user[name]) / units * 1e9:.0f} ns |")
    print(f"load average {os.getloadavg()[0]:.1f}, {tof.n_sites} measurements, "
          f"package {Path(rgbz_fast.__file__).parent}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5)
