"""The unguided ToF ISP's bilateral denoise (csrc/tof_filter.c), this build against another
build's extension: the same means, and the speed.

    python tools/tof_bilateral_paired.py OTHER.so [ROUNDS] [WORKERS]   # about a minute

OTHER.so: a copy of src/rgbz_fast/_kernels*.so of the build to compare with. On the 12 MP
Mask1 frame of tools/tof_guided_speed.py (3 M measurements, 3 frequencies),
``denoise_phasors_bilateral`` (two passes, the ISP's default window 9) with the phasors and
variances ``ToFISP().run`` gives it, the extensions alternated call by call after a warm-up:
medians and the median of the rounds' speed ratios (> 1: this build is faster), and
whether every output is the same bit for bit; then ``ToFISP().run(tof)`` the same way.
"""
import os
import statistics
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import tof_guided_speed  # noqa: E402
from learned_paired import load_other  # noqa: E402
from tof_unguided_paired import alternate  # noqa: E402

import rgbz_fast.tof._filters as filters  # noqa: E402
from rgbz_fast.tof import ToFISP  # noqa: E402
from rgbz_fast.tof._stages import _check_taps, _phasors_offset  # noqa: E402
from rgbz_fast.tof._noise import tap_variance  # noqa: E402


def with_kernels(kernels, fn):
    saved = filters._kernels
    filters._kernels = kernels
    try:
        return fn()
    finally:
        filters._kernels = saved


def paired(this, other, fn, rounds):
    """(this's seconds, other's seconds, same outputs) of fn alternated between the two."""
    a, b = with_kernels(this, fn), with_kernels(other, fn)
    same = all(np.array_equal(x, y, equal_nan=True) for x, y in zip(_arrays(a), _arrays(b)))
    t, _ = alternate({"this": lambda: with_kernels(this, fn),
                      "other": lambda: with_kernels(other, fn)}, rounds)
    return t["this"], t["other"], same


def _arrays(out):
    if isinstance(out, tuple):
        return out
    return [getattr(out, f) for f in ("depth", "sigma", "snr", "count", "flags")]


def main(other_path, rounds=7, workers=2):
    frame, _ = tof_guided_speed.frame_12mp()
    tof = frame.tof
    this, other = filters._kernels, load_other(other_path)
    i, q, offset = _phasors_offset(_check_taps(tof.taps))
    var = 2.0 * tap_variance(offset, tof.sensor)
    cases = {
        "denoise_phasors_bilateral (2 passes)":
            lambda: filters.denoise_phasors_bilateral(i, q, var, tof.sites, block=tof.block,
                                                      workers=workers),
        "ToFISP().run(tof)": lambda: ToFISP().run(tof, workers=workers),
    }
    print(f"| call (12 MP, {workers} threads) | this, ms | other, ms | speed ratio | same |")
    print("|---|---|---|---|---|")
    for name, fn in cases.items():
        a, b, same = paired(this, other, fn, rounds)
        ratio = statistics.median(y / x for x, y in zip(a, b))
        print(f"| `{name}` | {statistics.median(a) * 1e3:.0f} | {statistics.median(b) * 1e3:.0f} "
              f"| {ratio:.3f}x | {same} |", flush=True)
    print(f"load average {os.getloadavg()[0]:.1f}, {os.cpu_count()} cores, {rounds} rounds")


if __name__ == "__main__":
    main(sys.argv[1], *(int(a) for a in sys.argv[2:4]))
