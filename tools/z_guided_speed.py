"""z_guided speed on a 12 MP Mask1 frame from its taps, float32, 2 threads; learned beside it.

    python tools/z_guided_speed.py

The benchmark scene (astronaut tiled to 4000 x 3000) through the sensor model (a plane at
2 m, noisy), the shipped filters. Per call, 5 rounds alternating the calls (so that the load
of other processes hits them alike), median and best: reconstruct(frame, "z_guided") whole,
reconstruct(frame, "learned"), and the parts of z_guided: the guide's medians from a sample of
the taps (guide_source: the sites checked, csrc/z_guided_guide.c) and the kernel (the guide's
rows from the taps, the cell terms and every Z site, csrc/z_guided.c) alone; the guide grid
as a separate pass over the taps (guide_grid: what nir=-free fits read) and
ToFTaps.amplitude (the data model's demodulation, phase included) for scale.
"""
import time
import numpy as np, rgbz_fast as rz
from rgbz_fast.reconstruction import default_z_filters
from rgbz_fast.reconstruction._z_guided import guide_grid
from rgbz_fast.reconstruction._z_guided_kernel import guide_source, run_z_guided
from rgbz_fast.simulation import Scene, simulate
from rgbz_fast._devtools.bench.cases import make_rgb
shape = (3000, 4000)
f = default_z_filters("mask1")
rgb = make_rgb(shape)
frame = simulate(Scene.from_rgb(rgb, depth=np.full(shape, 2.0)), "mask1", seed=0, noise=True)
g = guide_source(frame.shape, frame.pattern, tof=frame.tof, workers=2)
out = np.empty_like(frame.data)
calls = {
  "z_guided": lambda: rz.reconstruct(frame, "z_guided", filters=f, precision="float32", workers=2),
  "learned": lambda: rz.reconstruct(frame, "learned", precision="float32", workers=2),
  "medians": lambda: guide_source(frame.shape, frame.pattern, tof=frame.tof, workers=2),
  "kernel": lambda: run_z_guided(frame.data, out, frame.pattern, f, g, "float32", 11, 2),
  "guide_grid": lambda: guide_grid(frame.shape, frame.pattern, tof=frame.tof, workers=2),
  "amplitude": lambda: frame.tof.amplitude("all", workers=2),
}
for fn in calls.values(): fn()
t = {k: [] for k in calls}
for _ in range(5):
    for k, fn in calls.items():
        t0 = time.perf_counter(); fn(); t[k].append(time.perf_counter() - t0)
for k, v in t.items():
    m = float(np.median(v))
    print(f"{k:12s} median {m*1e3:8.1f} ms  best {min(v)*1e3:8.1f} ms  -> "
          f"{shape[0]*shape[1]/m/1e6:7.1f} Mpix/s (median)")
