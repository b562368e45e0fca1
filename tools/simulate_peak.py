"""Peak memory and time of building a scene and of ``simulate`` through optics, this checkout
against another commit's package (made by ``tools/tof_unguided_paired.py --make``), each case
in a fresh process of its own, the two packages alternated.

    python tools/simulate_peak.py DIR [ROUNDS]   # a few minutes

Cases, 12 MP (art from ../shared/data/rgbd scaled to 3000x4000 by nearest neighbour):
``Scene(image)`` of its uint8 sRGB image, and ``simulate(scene, "mask1", seed=1,
optics=Optics(), workers=2)`` with its depth. Prints per package the median wall time of the
call and the median of the peak of the memory allocated during the call (``tracemalloc``,
which NumPy reports its arrays to; the C kernels' own scratch buffers are not counted), and
whether the two results are equal. The wall time includes tracemalloc's bookkeeping.
"""
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent

CHILD = r"""
import hashlib, importlib, json, sys, time, tracemalloc
pkg, case, other = sys.argv[1], sys.argv[2], sys.argv[3]
import rgbz_fast._kernels                                  # this extension first
if pkg == "rgbz_old":
    sys.path.insert(0, other)
import numpy as np
sim = importlib.import_module(pkg + ".simulation")
s = sim.load_rgbd(sys.argv[4])                             # 1.4 MP
ri = np.arange(3000) * s.shape[0] // 3000
ci = np.arange(4000) * s.shape[1] // 4000
# scaled up as uint8 codes, C order: no temporary above what the call itself holds
small = np.asarray(np.round(s.image ** (1 / 2.2) * 255), np.uint8)
rgb = np.ascontiguousarray(small[ri][:, ci])
depth = np.ascontiguousarray(s.depth[ri][:, ci])
valid = np.ascontiguousarray(s.depth_valid[ri][:, ci])
del s, small
scene = sim.Scene(rgb, depth=depth, depth_valid=valid) if case == "simulate" else None
tracemalloc.start()
t = time.perf_counter()
if case == "scene":
    out = sim.Scene(rgb)
else:
    out = sim.simulate(scene, "mask1", seed=1, optics=sim.Optics(), workers=2)
wall = time.perf_counter() - t
peak = tracemalloc.get_traced_memory()[1] / 2 ** 20
tracemalloc.stop()
arrays = (out.image,) if case == "scene" else (out.data, out.tof.taps)
digest = hashlib.sha1(b"".join(a.tobytes() for a in arrays)).hexdigest()
print(json.dumps({"wall": wall, "peak": peak, "digest": digest}))
"""


def run(pkg, case, other):
    art = HERE.parent / ".." / "shared" / "data" / "rgbd" / "art"
    out = subprocess.run([sys.executable, "-c", CHILD, pkg, case, str(other), str(art)],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main(other_dir, rounds=3):
    other = Path(other_dir).resolve()
    print("| case, 12 MP | this: wall, peak allocated | other: wall, peak | same result |")
    print("|---|---|---|---|")
    for case, label in (("scene", "`Scene(uint8 sRGB image)`"),
                        ("simulate", "`simulate(..., optics=Optics())`, Mask1 with ToF")):
        res = {"this": [], "other": []}
        for i in range(rounds):
            for name in (("this", "other") if i % 2 else ("other", "this")):
                res[name].append(run("rgbz_fast" if name == "this" else "rgbz_old", case,
                                     other))
        med = {k: (statistics.median(r["wall"] for r in v),
                   statistics.median(r["peak"] for r in v)) for k, v in res.items()}
        same = len({r["digest"] for v in res.values() for r in v}) == 1
        print(f"| {label} | {med['this'][0]:.2f} s, {med['this'][1]:.0f} MiB | "
              f"{med['other'][0]:.2f} s, {med['other'][1]:.0f} MiB | {same} |", flush=True)
    print(f"load average {os.getloadavg()[0]:.1f}, {os.cpu_count()} cores, {rounds} processes "
          "per package and case")


if __name__ == "__main__":
    main(sys.argv[1], *(int(a) for a in sys.argv[2:3]))
