"""The unguided ToF ISP's validity stage in C against the NumPy code it replaced.

    python tools/tof_validity_speed.py [ROUNDS] [WORKERS]      # a minute or two

The 12 MP frame of tools/tof_guided_speed.py (art scaled to 3000x4000, Mask1, 3 M
measurements). ``ToFISP(denoise=...).run(tof)`` for "none", "box" and "bilateral" (the
default), each with the library's validity stage (csrc/tof_filter.c, rgbz_tof_validity, and
the flying-pixel test in C) and with the NumPy code they replaced (tests/_reference/tof.py:
``unguided_validity``, its flying-pixel test NumPy too), alternated round by round: medians
of the wall times and their ratio (> 1: C is faster). Every field of the results is compared.
"""
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
sys.path.insert(0, str(HERE))

from _reference import tof as ref  # noqa: E402
from tof_flying_speed import denoise_rows  # noqa: E402
from tof_guided_speed import frame_12mp  # noqa: E402

import rgbz_fast.tof._chain as chain  # noqa: E402

C_STAGE = chain.validity


def numpy_stage(depth, residual, amp, var, saturated, sensor, block, f, grid, *, workers=None,
                **kw):
    return ref.unguided_validity(depth, residual, amp, var, saturated, sensor, block, f,
                                 grid() if callable(grid) else grid, **kw)


def main(rounds=7, workers=2):
    frame, _ = frame_12mp()
    tof = frame.tof
    print(f"{tof.n_sites} measurements, {workers} thread(s), {rounds} rounds")
    denoise_rows(tof, rounds, workers,
                 ("snr", "sigma", "reflectance", "flags", "depth", "valid"), "every field",
                 module=chain, name="validity", c_code=C_STAGE, numpy=numpy_stage)


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:3]))
