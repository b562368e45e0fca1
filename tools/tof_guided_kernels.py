"""The guided ISP's two heaviest stages alone, this build against another build's extension
module, alternated round by round, their outputs compared bit for bit: the denoise
(``tofg_denoise``: the four passes and the unwrapping) and the colour stage (``tofg_colour``:
the guide at the measurements and its Laplacian), on the arguments the guided ISP passes them
for the 12 MP Mask1 frame of tools/tof_guided_speed.py.

    python tools/tof_guided_kernels.py SO [ROUNDS] [WORKERS]   # about a minute

SO: the other build's ``_kernels*.so`` (e.g. a copy of main's build). Prints the CPU time
(all threads) per measurement of each round and the ratio this / other per round; "outputs
bit-identical" or the outputs that differ. Since 2026-11-28 the denoise also makes the prepare
stage and the validity (its keyword arguments ``taps``, ``sat``, ``offset``, ``flags``, ...):
the other build must take them, a build of that day or later.
"""

import importlib.util
import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import tof_guided_speed  # noqa: E402

import rgbz_fast._kernels as this  # noqa: E402
import rgbz_fast.tof._guided as guided  # noqa: E402
from rgbz_fast.tof import ToFISP  # noqa: E402


def _other(path):
    spec = importlib.util.spec_from_file_location("other._kernels", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _arguments():
    """The positional arguments the guided ISP passes tofg_denoise and tofg_colour (the
    colour stage without the in-kernel scaling, which an older build may not have)."""
    frame, guide = tof_guided_speed.frame_12mp()
    seen = {}
    kernels = guided._kernels

    class Spy:
        def __getattr__(self, name):
            fn = getattr(kernels, name)
            if name not in ("tofg_denoise", "tofg_colour"):
                return fn

            def call(*a, **k):
                seen[name] = (a, k)
                return fn(*a, **k)
            return call
    guided._kernels = Spy()
    try:
        ToFISP().run(frame.tof, guide=guide, workers=1)
    finally:
        guided._kernels = kernels
    return frame.tof.n_sites, seen


def main(so, rounds=5, workers=1):
    other = _other(so)
    n, seen = _arguments()
    da, dk = seen["tofg_denoise"]
    da = list(da)
    da[16] = workers
    ca = list(seen["tofg_colour"][0])[:9]
    ca[8] = workers
    outs_d, outs_c = [14, 20, 21, 22, 23, 24], [5, 6, 7]
    # the outputs among the keywords (sat: |= the taps at full scale, the same each call)
    outs_k = [k for k in ("count", "snr", "sigma", "refl", "flags", "offset", "usable")
              if dk.get(k) is not None]

    def denoise(mod):
        a, k = list(da), dict(dk)
        for i in outs_d:
            a[i] = np.full_like(da[i], 7)
        for key in outs_k:
            k[key] = np.full_like(dk[key], 7)
        mod.tofg_denoise(*a, **k)
        return [a[i] for i in outs_d] + [k[key] for key in outs_k]

    def colour(mod):
        a = list(ca)
        for i in outs_c:
            a[i] = None if ca[i] is None else np.full_like(ca[i], 7)
        mod.tofg_colour(*a)
        return [a[i] for i in outs_c if a[i] is not None]

    for name, run in (("tofg_denoise", denoise), ("tofg_colour", colour)):
        cpu = {"this": [], "other": []}
        got = {}
        for _ in range(rounds):
            for who, mod in (("this", this), ("other", other)):
                c = time.process_time()
                got[who] = run(mod)
                cpu[who].append((time.process_time() - c) / n * 1e9)
        same = all(np.array_equal(x, y, equal_nan=True)
                   for x, y in zip(got["this"], got["other"]))
        print(f"{name}, {workers} thread(s), CPU ns per measurement: this "
              f"{[round(x, 1) for x in cpu['this']]} median {statistics.median(cpu['this']):.1f}; "
              f"other {[round(x, 1) for x in cpu['other']]} median "
              f"{statistics.median(cpu['other']):.1f}")
        ratios = [round(x / y, 3) for x, y in zip(cpu["this"], cpu["other"])]
        print(f"  this / other per round {ratios}; "
              f"outputs {'bit-identical' if same else 'DIFFER'}")
    print(f"load average {os.getloadavg()[0]:.1f}, {n} measurements")


if __name__ == "__main__":
    main(sys.argv[1], *(int(a) for a in sys.argv[2:4]))
