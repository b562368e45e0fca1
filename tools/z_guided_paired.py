"""z_guided of this checkout against another build's extension, in one process.

    python tools/z_guided_paired.py OTHER_EXTENSION.so [ROUNDS] [THREADS] [PATTERNS]

OTHER_EXTENSION.so: a copy of another build's rgbz_fast/_kernels*.so (for example
build/cp311/src/rgbz_fast/_kernels.cpython-311-x86_64-linux-gnu.so of /work/main, copied under
any name), loaded beside this checkout's extension; ``rz.reconstruct(frame, "z_guided")`` runs
through either (the Python layer is this checkout's, so the two builds must share the
extension's interface). The frame: the benchmark scene (astronaut tiled to 4000 x 3000)
through the sensor model (a plane at 2 m, noisy), from its taps, the shipped filters,
precision float32. The two builds alternate call by call for ROUNDS rounds (default 15, after
one warm-up call each), CPU time with 1 thread, wall time with more (THREADS, default 2);
prints the median and the IQR of the rounds' speed ratios (this build / the other, > 1: this
build is faster), the medians of both, and the largest difference of the outputs at the Z
sites (DN). PATTERNS: a comma-separated subset of mask1,mask2 (default mask1).
"""
import contextlib
import sys
import time

import numpy as np

import rgbz_fast as rz
from rgbz_fast.reconstruction import _reconstruct, _z_guided, _z_guided_kernel, default_z_filters
from learned_paired import alternate, load_other

_MODULES = (_reconstruct, _z_guided, _z_guided_kernel)


@contextlib.contextmanager
def kernels(mod):
    """z_guided's calls through ``mod`` (None: this checkout's extension)."""
    saved = [m._kernels for m in _MODULES]
    if mod is not None:
        for m in _MODULES:
            m._kernels = mod
    try:
        yield
    finally:
        for m, k in zip(_MODULES, saved):
            m._kernels = k


def speed(other, rounds, threads, patterns):
    from rgbz_fast._devtools.bench.cases import make_rgb
    from rgbz_fast.simulation import Scene, simulate
    clock = time.process_time if threads == 1 else time.perf_counter
    shape = (3000, 4000)
    rgb = make_rgb(shape)
    for pat in patterns:
        f = default_z_filters(pat)
        frame = simulate(Scene.from_rgb(rgb, depth=np.full(shape, 2.0)), pat, seed=0, noise=True)

        def call(mod):
            with kernels(mod):
                t0 = clock()
                out = rz.reconstruct(frame, "z_guided", filters=f, precision="float32",
                                     workers=threads)
                return clock() - t0, out
        _, a = call(None)
        _, b = call(other)
        z = frame.z_mask
        worst = float(np.abs(a[z].astype(np.float64) - b[z]).max())
        med, q25, q75, tn, to = alternate(call, other, rounds)
        print(f"{pat}: {threads} thread(s), {rounds} rounds: this / other speed {med:.3f} "
              f"[IQR {q25:.3f}-{q75:.3f}]; medians this {tn:.1f} ms, "
              f"other {to:.1f} ms; largest output difference {worst:g} DN")


def main(argv):
    if not argv:
        raise SystemExit(__doc__)
    speed(load_other(argv[0]), int(argv[1]) if len(argv) > 1 else 15,
          int(argv[2]) if len(argv) > 2 else 2,
          argv[3].split(",") if len(argv) > 3 else ("mask1",))


if __name__ == "__main__":
    main(sys.argv[1:])
