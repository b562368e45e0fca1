"""Where the guided ToF ISP's time goes, and what a 20 M measurements/s call would leave to
everything but the denoise: the paragraph "What 20 M measurements/s would take" of
docs/reports/isp.md (issue 25).

    python tools/tof_guided_floor.py [ROUNDS]        # about a minute

On the 12 MP Mask1 frame of tools/tof_guided_speed.py (3 M measurements, 2 threads), medians
of ROUNDS (default 7) rounds, the cases alternated round by round:

- the whole call ``ToFISP().run(tof, guide=image)`` after the other cases (whose arrays
  leave the allocator's heap in another state), the same call right after another one (its
  freed arrays' pages reused), and each C kernel's share of it (the kernels wrapped in
  timers, calls as the ISP makes them);
- the denoise (``tofg_denoise``, which since 2026-11-28 also makes the prepare stage row by
  row as it reads the taps, and the validity with the fixed pattern's correction as it
  unwraps each row) on the call's own arguments, with its output arrays made once and
  written again (warm pages), and with fresh ones as the ISP makes them;
- the arrays of the returned ToFDepth (their shapes and types): written once with 2 threads
  into fresh arrays, and into the same arrays again -- what the result costs in page faults
  alone, whatever computes it.

Since 2026-11-28 the call takes its large arrays from the memory pool
(``rgbz_fast.memory_pool``), which keeps the memory of the last call's freed results; the
"fresh" cases here allocate with ``numpy.empty_like``, outside the pool, so they find the
memory the pool does not hold (on a VM that reports free memory to its host, memory the host
must fill again: slower than without the pool, docs/reports/benchmarks.md).
"""

import os
import statistics
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tof_guided_speed import frame_12mp  # noqa: E402

from rgbz_fast import _kernels  # noqa: E402
from rgbz_fast.tof import ToFISP  # noqa: E402

RESULT_FIELDS = ("depth", "residual", "wraps", "phase", "amplitude", "offset", "snr", "sigma",
                 "reflectance", "count", "valid", "flags", "measured")


def _timed(fn):
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def main(rounds=7):
    frame, guide = frame_12mp()
    tof, isp = frame.tof, ToFISP()
    stage = {}
    calls = {}
    originals = {n: getattr(_kernels, n) for n in dir(_kernels)
                 if n.startswith(("tofg_", "tof_fixed"))}

    def wrap(name, fn):
        def timed(*a, **k):
            calls[name] = (a, k)
            t0 = time.perf_counter()
            try:
                return fn(*a, **k)
            finally:
                stage[name] = stage.get(name, 0.0) + time.perf_counter() - t0
        return timed

    for n, fn in originals.items():
        setattr(_kernels, n, wrap(n, fn))
    result = isp.run(tof, guide=guide, workers=2)
    for n, fn in originals.items():
        setattr(_kernels, n, fn)
    denoise = originals["tofg_denoise"]
    d_args, d_kw = calls["tofg_denoise"]
    out_idx = [i for i, x in enumerate(d_args)
               if i >= 12 and isinstance(x, np.ndarray) and x.flags.writeable]

    def denoise_fresh():
        a = [np.empty_like(x) if i in out_idx else x for i, x in enumerate(d_args)]
        fresh = {k: np.empty_like(d_kw[k]) for k in
                 ("count", "snr", "sigma", "refl", "flags", "offset") if k in d_kw}
        denoise(*a, **{**d_kw, **fresh})

    arrays = [np.asarray(getattr(result, f)) for f in RESULT_FIELDS]
    nbytes = sum(a.nbytes for a in arrays)
    pool = ThreadPoolExecutor(2)

    def write(targets):
        def half(i):
            for t in targets:
                b = t.reshape(-1).view(np.uint8)
                m = b.size // 2
                b[i * m:b.size if i else m] = 1
        list(pool.map(half, (0, 1)))

    warm = [np.empty_like(a) for a in arrays]
    write(warm)
    def twice():
        isp.run(tof, guide=guide, workers=2)
        return _timed(lambda: isp.run(tof, guide=guide, workers=2))

    cases = {
        "the whole call": lambda: isp.run(tof, guide=guide, workers=2),
        "the whole call, right after another": twice,
        "denoise, its outputs warm": lambda: denoise(*d_args, **d_kw),
        "denoise, its outputs fresh": denoise_fresh,
        f"the result's {nbytes / 1e6:.0f} MB written, fresh arrays":
            lambda: write([np.empty_like(a) for a in arrays]),
        f"the result's {nbytes / 1e6:.0f} MB written, the same arrays again":
            lambda: write(warm),
    }
    times = {k: [] for k in cases}
    per_stage = {}
    for _ in range(rounds):
        for k, fn in cases.items():
            t0 = time.perf_counter()
            got = fn()                           # twice() gives its own second call's time
            took = time.perf_counter() - t0
            times[k].append(got if isinstance(got, float) else took)
        for n, fn in originals.items():
            setattr(_kernels, n, wrap(n, fn))
        stage.clear()
        isp.run(tof, guide=guide, workers=2)
        for n, fn in originals.items():
            setattr(_kernels, n, fn)
        for n, v in stage.items():
            per_stage.setdefault(n, []).append(v)
    n_meas = int(np.asarray(result.depth).size)
    print(f"| case | wall, median of {rounds} | |")
    print("|---|---|---|")
    for k, v in times.items():
        med = statistics.median(v)
        extra = f"{n_meas / med / 1e6:.1f} M measurements/s" if k == "the whole call" else ""
        print(f"| {k} | {med * 1e3:.1f} ms | {extra} |")
    for n, v in sorted(per_stage.items(), key=lambda kv: -statistics.median(kv[1])):
        print(f"| `{n}` in the call | {statistics.median(v) * 1e3:.1f} ms | |")
    print(f"load average {os.getloadavg()[0]:.1f}, {n_meas} measurements")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
