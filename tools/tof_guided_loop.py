"""The colour-guided ToF ISP called in a loop, as a user's program calls it: the paragraph
"The result's pages" of docs/reports/isp.md (issue 25).

    python tools/tof_guided_loop.py [CALLS] [--pool-limit BYTES] [--package DIR]  # 20 s

On the 12 MP Mask1 frame of tools/tof_guided_speed.py (3 M measurements, 2 threads), CALLS
(default 15) calls of ``ToFISP().run(tof, guide=image)`` in a row, twice: ``r = isp.run(...)``
(the previous result alive while the next call runs, as in ``for frame in frames``) and
with each result dropped before the next call. Prints the median and best wall time of the
calls after the first two, measurements per second, and the memory pool's report
(``rgbz_fast.memory_pool()``). ``--pool-limit 0`` runs with the pool off (every array
from ``numpy.empty``); ``--package DIR`` runs another build (tools/tof_guided_speed.py).
"""

import os
import statistics
import sys
import time
from pathlib import Path

limit = None
if "--pool-limit" in sys.argv:
    _i = sys.argv.index("--pool-limit")
    limit = int(sys.argv[_i + 1])
    del sys.argv[_i:_i + 2]

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tof_guided_speed import frame_12mp  # noqa: E402  (takes --package)

import rgbz_fast  # noqa: E402
from rgbz_fast.tof import ToFISP  # noqa: E402


def main(calls=15):
    pool = getattr(rgbz_fast, "memory_pool", None)
    if limit is not None and pool is not None:
        pool(limit)
    frame, guide = frame_12mp()
    tof, isp = frame.tof, ToFISP()
    n = tof.n_sites
    for keep in (True, False):
        times = []
        r = None
        for _ in range(calls):
            if not keep:
                r = None
            t = time.perf_counter()
            r = isp.run(tof, guide=guide, workers=2)
            times.append(time.perf_counter() - t)
        del r
        tail = times[2:]
        med = statistics.median(tail)
        print(f"{'r = isp.run(...)' if keep else 'result dropped first'}: median "
              f"{med * 1e3:.1f} ms ({n / med / 1e6:.1f} M measurements/s), best "
              f"{min(tail) * 1e3:.1f} ms, calls {calls}")
    print(f"pool {pool() if pool is not None else 'none (this build has no pool)'}; load "
          f"average {os.getloadavg()[0]:.1f}; package {Path(rgbz_fast.__file__).parent}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 15)
