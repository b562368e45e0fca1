"""z_guided speed on a 12 MP Mask1 frame from its taps, float32, 2 threads; learned beside it.

    python tools/z_guided_speed.py

The benchmark scene (astronaut tiled to 4000 x 3000) through the sensor model (a plane at
2 m, noisy), the shipped filters. Per call, 5 rounds alternating the calls (so that the load
of other processes hits them alike), median and best: reconstruct(frame, "z_guided") whole,
reconstruct(frame, "learned"), and the parts of z_guided: the taps' amplitude, the guide grid
(amplitude, noise variance), the cell terms (C) and the per-site kernel alone.
"""
import time
import numpy as np, rgbz_fast as rz
from rgbz_fast.reconstruction import default_z_filters
from rgbz_fast.reconstruction._z_guided import guide_grid
from rgbz_fast.reconstruction._z_guided_kernel import cell_arrays
from rgbz_fast.simulation import Scene, simulate
from rgbz_fast._devtools.bench.cases import make_rgb
shape = (3000, 4000)
f = default_z_filters("mask1")
rgb = make_rgb(shape)
frame = simulate(Scene.from_rgb(rgb, depth=np.full(shape, 2.0)), "mask1", seed=0, noise=True)
calls = {
  "z_guided": lambda: rz.reconstruct(frame, "z_guided", filters=f, precision="float32", workers=2),
  "learned": lambda: rz.reconstruct(frame, "learned", precision="float32", workers=2),
  "guide_grid": lambda: guide_grid(frame.shape, frame.pattern, tof=frame.tof),
}
g = guide_grid(frame.shape, frame.pattern, tof=frame.tof)
calls["cell_arrays"] = lambda: cell_arrays(f, frame.data, g, 2)
calls["amplitude"] = lambda: frame.tof.amplitude("all")
for fn in calls.values(): fn()
t = {k: [] for k in calls}
for _ in range(5):
    for k, fn in calls.items():
        t0 = time.perf_counter(); fn(); t[k].append(time.perf_counter() - t0)
for k, v in t.items():
    m = float(np.median(v))
    print(f"{k:12s} median {m*1e3:8.1f} ms  best {min(v)*1e3:8.1f} ms  -> {shape[0]*shape[1]/m/1e6:7.1f} Mpix/s (median)")
# the per-site kernel alone
from rgbz_fast import _kernels
from rgbz_fast.reconstruction._z_guided_kernel import kernel_arrays
cell, level = cell_arrays(f, frame.data, g, 2)
P, Q = frame.pattern.period
pm = np.full(P * Q, -1, np.int32)
for k, ph in enumerate(f.base.geometry):
    r, c = ph["rc"]; pm[r * Q + c] = k
out = np.empty_like(frame.data)
ka = kernel_arrays(f)
ts = []
for _ in range(5):
    t0 = time.perf_counter()
    _kernels.z_guided(frame.data, out, 0, P, Q, pm, cell=cell, level=level, maxval=2047.0, workers=2, **ka)
    ts.append(time.perf_counter() - t0)
m = float(np.median(ts))
print(f"kernel only  median {m*1e3:8.1f} ms -> {shape[0]*shape[1]/m/1e6:7.1f} Mpix/s")
