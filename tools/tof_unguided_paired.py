"""The unguided ToF ISP, this checkout against another commit's package, alternated call by
call in one process: the same results, and the speed of each denoise.

    python tools/tof_unguided_paired.py --make COMMIT SO DIR   # the other package, once
    python tools/tof_unguided_paired.py DIR [ROUNDS] [WORKERS] [--guided] [--mask2]

``--make`` copies COMMIT's src/rgbz_fast to DIR/rgbz_old with its imports renamed, the
extension module SO (that commit's build of ``_kernels``) and this build's
``_build_config.py`` beside it, so that both packages load side by side (this one's
extension first). The 12 MP Mask1 frame of tools/tof_guided_speed.py (art, 3 M
measurements), simulated by each package with the same seed (the same taps, checked);
``ToFISP(denoise=D).run(tof, workers=WORKERS)`` for the three denoises, and with
``--guided`` the guided ISP (``ToFISP().run(tof, guide=g)``) with the frame's colour image as
uint8 and as float64 in [0, 1]; ``--mask2``: the Mask2 frame (750 k 2x2 Z pixels) instead.
Medians, the median of the rounds' speed ratios (> 1: this checkout is faster) and whether
every field of the results is equal.
"""
import importlib
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
FIELDS = ("depth", "residual", "wraps", "phase", "amplitude", "offset", "snr", "sigma",
          "reflectance", "count", "flags")


def make(commit, so, dest):
    """DIR/rgbz_old: COMMIT's package under another name, with SO as its extension."""
    out = Path(dest) / "rgbz_old"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    files = subprocess.run(["git", "-C", str(HERE.parent), "ls-tree", "-r", "--name-only",
                            commit, "src/rgbz_fast"], check=True, capture_output=True,
                           text=True).stdout.split()
    for name in files:
        text = subprocess.run(["git", "-C", str(HERE.parent), "show", f"{commit}:{name}"],
                              check=True, capture_output=True).stdout
        target = out / Path(name).relative_to("src/rgbz_fast")
        target.parent.mkdir(parents=True, exist_ok=True)
        if name.endswith(".py"):
            text = text.decode().replace("rgbz_fast", "rgbz_old").encode()
        target.write_bytes(text)
    built = Path(importlib.import_module("rgbz_fast._kernels").__file__)
    shutil.copy(so, out / ("_kernels" + "".join(built.suffixes)))
    shutil.copy(built.parent / "_build_config.py", out / "_build_config.py")
    print(f"{out}: {commit} with {so}")


def alternate(runs, rounds):
    """({"this": [s], "other": [s]}, the median of other / this) of the two callables in
    `runs`, alternated call by call, the order swapped every round."""
    t = {"this": [], "other": []}
    for i in range(rounds):
        for name in (("this", "other") if i % 2 else ("other", "this")):
            s = time.perf_counter()
            runs[name]()
            t[name].append(time.perf_counter() - s)
    return t, statistics.median(o / n for n, o in zip(t["this"], t["other"]))


def frame(pkg, with_guide=False, pattern="mask1"):
    """The 12 MP frame of tools/tof_guided_speed.py (Mask1 unless `pattern`), made by the
    package `pkg` (its taps, or the taps and the guide ``ColourISP().run(frame)``)."""
    sim = importlib.import_module(f"{pkg}.simulation")
    scene = sim.load_rgbd(HERE.parent / ".." / "shared" / "data" / "rgbd" / "art")
    H, W = 3000, 4000
    ri = np.arange(H) * scene.shape[0] // H
    ci = np.arange(W) * scene.shape[1] // W
    big = sim.Scene(scene.image[ri][:, ci], depth=scene.depth[ri][:, ci],
                    depth_valid=scene.depth_valid[ri][:, ci])
    fr = sim.simulate(big, pattern, seed=1)
    if with_guide:
        return fr.tof, importlib.import_module(f"{pkg}.isp").ColourISP().run(fr)
    return fr.tof


def main(other_dir, rounds=7, workers=2, guided=False, pattern="mask1"):
    importlib.import_module("rgbz_fast._kernels")            # this extension first
    sys.path.insert(0, str(Path(other_dir).resolve()))
    (this_tof, guide), (other_tof, _) = (frame("rgbz_fast", True, pattern),
                                         frame("rgbz_old", True, pattern))
    assert np.array_equal(this_tof.taps, other_tof.taps)
    this = importlib.import_module("rgbz_fast.tof").ToFISP
    other = importlib.import_module("rgbz_old.tof").ToFISP
    cases = {f"denoise={d!r}": (d, None) for d in ("none", "box", "bilateral")}
    if guided:
        cases = {"guide uint8": ("bilateral", guide),
                 "guide float64": ("bilateral", guide / 255.0)}
    print(f"| `ToFISP(...).run(tof)`, 12 MP {pattern}, {workers} threads | this, ms | other, ms "
          "| speed ratio | same results |")
    print("|---|---|---|---|---|")
    for label, (denoise, g) in cases.items():
        runs = {"this": lambda: this(denoise=denoise).run(this_tof, guide=g, workers=workers),
                "other": lambda: other(denoise=denoise).run(other_tof, guide=g,
                                                            workers=workers)}
        a, b = runs["this"](), runs["other"]()
        same = all(np.array_equal(getattr(a, f), getattr(b, f), equal_nan=True)
                   for f in FIELDS)
        t, ratio = alternate(runs, rounds)
        print(f"| `{label}` | {statistics.median(t['this']) * 1e3:.0f} | "
              f"{statistics.median(t['other']) * 1e3:.0f} | {ratio:.3f}x | {same} |", flush=True)
    print(f"load average {os.getloadavg()[0]:.1f}, {os.cpu_count()} cores, {rounds} rounds")


if __name__ == "__main__":
    if sys.argv[1] == "--make":
        make(*sys.argv[2:5])
    else:
        args = [a for a in sys.argv[1:] if a not in ("--guided", "--mask2")]
        main(args[0], *(int(a) for a in args[1:3]), guided="--guided" in sys.argv,
             pattern="mask2" if "--mask2" in sys.argv else "mask1")
