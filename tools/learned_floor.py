"""Learned against OpenCV EA with and without its hash, in one process, call by call.

    python tools/learned_floor.py FLOOR_EXTENSION.so [ROUNDS] [THREADS]

FLOOR_EXTENSION.so: a copy of the extension built with tools/learned_floor.patch applied
(the patch's header gives the commands): its learned kernel replays the buckets it recorded
on a frame's first call, so that on the calls that follow the column stage, the row stage
and the buckets cost nothing and the output is the library's, bit for bit. On the benchmark's
frame (astronaut tiled to 4000 x 3000, uint16 11-bit, precision float32), Mask1 and Mask2,
three calls alternate for ROUNDS rounds (default 15, after one warm-up call each; the order
rotates every round): this checkout's learned, the floor build's, and
``cv2.cvtColor(cfa, COLOR_BayerGR2RGB_EA)`` on the benchmark's Bayer frame, with THREADS
threads (default 2; OpenCV's likewise; GOMP_SPINCOUNT=30000 unless set, as the rgbz-fast
command runs). Prints the medians and each one's speed against
OpenCV's, the median of the rounds' ratios (> 1: faster than OpenCV), and checks that both
builds give the same output.
"""
import os
import sys
import time

# libgomp's idle threads otherwise spin about 3 ms after each of our calls and slow the
# OpenCV call that follows (docs/reports/benchmarks.md); as the rgbz-fast command does
os.environ.setdefault("GOMP_SPINCOUNT", "30000")

import numpy as np  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from rgbz_fast._devtools.bench.cases import make_rgb  # noqa: E402

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from learned_paired import kernels, load_other  # noqa: E402


def main(argv):
    import cv2
    if not argv:
        print(__doc__)
        return 2
    floor = load_other(argv[0])
    rounds = int(argv[1]) if len(argv) > 1 else 15
    threads = int(argv[2]) if len(argv) > 2 else 2
    clock = time.process_time if threads == 1 else time.perf_counter
    cv2.setNumThreads(threads)
    rgb = make_rgb((3000, 4000))
    cfa = np.asarray(rz.mosaic(rgb, "bayer").data)
    for pat in ("mask1", "mask2"):
        frame = rz.mosaic(rgb, pat)

        def lib(mod):
            def call():
                with kernels(mod):
                    return rz.reconstruct(frame, "learned", precision="float32",
                                          workers=threads)
            return call
        calls = {"learned": lib(None), "learned, no hash": lib(floor),
                 "OpenCV EA": lambda: cv2.cvtColor(cfa, cv2.COLOR_BayerGR2RGB_EA)}
        outs = {k: np.asarray(c()) for k, c in calls.items() if k != "OpenCV EA"}
        outs["again"] = np.asarray(calls["learned, no hash"]())   # a replayed call
        calls["OpenCV EA"]()                                      # OpenCV's warm-up call
        same = int(np.count_nonzero(outs["learned"] != outs["again"]))
        names = list(calls)
        times = {k: [] for k in names}
        for r in range(rounds):
            order = names[r % 3:] + names[:r % 3]
            for k in order:
                t0 = clock()
                calls[k]()
                times[k].append(clock() - t0)
        cv = np.asarray(times["OpenCV EA"])
        print(f"{pat}: {threads} thread(s), {rounds} rounds; pixels differing between the "
              f"builds' outputs (a replayed call): {same}")
        for k in names:
            t = np.asarray(times[k])
            ratio = np.median(cv / t)
            print(f"  {k:17s} {1e3 * np.median(t):6.2f} ms  {12e6 / np.median(t) / 1e6:6.0f} "
                  f"Mpix/s  x OpenCV EA {ratio:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
