"""The learned kernel of this checkout against another build's extension, in one process.

    python tools/learned_paired.py OTHER_EXTENSION.so speed [ROUNDS] [THREADS] [PATTERNS]
    python tools/learned_paired.py OTHER_EXTENSION.so kodak [DATASET]

OTHER_EXTENSION.so: a copy of another build's rgbz_fast/_kernels*.so (for example
build/cp311/src/rgbz_fast/_kernels.cpython-311-x86_64-linux-gnu.so of another worktree,
copied under any name); it is loaded beside this checkout's extension and
``rz.reconstruct(..., "learned")`` runs through either (the Python layer is this checkout's).

speed: the benchmark scene (astronaut tiled to 4000 x 3000) on Mask1 and Mask2, uint16
11-bit, precision float32; the two builds alternated call by call for ROUNDS rounds (default
15, the first call of each a warm-up), CPU time with 1 thread, wall time with more (THREADS,
default 1); prints the median and the IQR of the rounds' speed ratios (this build / the other,
> 1: this build is faster). PATTERNS: a comma-separated subset of mask1,mask2 (under
``perf record``, the two builds' functions are told apart by their files).

kodak: every image of DATASET (default ../shared/data/kodak) mosaicked on Mask1 and Mask2,
as uint16 11-bit and as float32 in [0, 1], precisions float32 and float64: the pixels whose
output differs between the builds, and the largest difference.
"""
import contextlib
import importlib.machinery
import importlib.util
import sys
import time
import types
from pathlib import Path

import numpy as np

import rgbz_fast as rz
from rgbz_fast.reconstruction import _reconstruct


def load_other(path):
    """The extension at ``path``, loaded as a module of its own."""
    sys.modules.setdefault("_other_build", types.ModuleType("_other_build"))
    loader = importlib.machinery.ExtensionFileLoader("_other_build._kernels", str(path))
    spec = importlib.util.spec_from_loader("_other_build._kernels", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


@contextlib.contextmanager
def kernels(mod):
    """rz.reconstruct's learned calls through ``mod`` (None: this checkout's extension)."""
    saved = _reconstruct._kernels
    if mod is not None:
        _reconstruct._kernels = mod
    try:
        yield
    finally:
        _reconstruct._kernels = saved


def alternate(call, other, rounds):
    """``rounds`` timings of ``call(None)`` (this build) and ``call(other)``, alternated with
    the order swapped every round: (median, q25, q75) of this / other speed, and the medians
    of the two builds' times in ms."""
    ratio, tn, to = [], [], []
    for i in range(rounds):
        if i % 2:
            t_new, _ = call(None)
            t_old, _ = call(other)
        else:
            t_old, _ = call(other)
            t_new, _ = call(None)
        ratio.append(t_old / t_new)
        tn.append(t_new)
        to.append(t_old)
    q = np.percentile(ratio, [25, 50, 75])
    return q[1], q[0], q[2], np.median(tn) * 1e3, np.median(to) * 1e3


def speed(other, rounds, threads, patterns=("mask1", "mask2")):
    from rgbz_fast._devtools.bench.cases import make_rgb
    clock = time.process_time if threads == 1 else time.perf_counter
    rgb = make_rgb((3000, 4000))
    for pat in patterns:
        frame = rz.mosaic(rgb, pat)

        def call(mod):
            with kernels(mod):
                t0 = clock()
                out = rz.reconstruct(frame, "learned", precision="float32", workers=threads)
                return clock() - t0, out
        _, a = call(None)
        _, b = call(other)
        same = int(np.count_nonzero(np.asarray(a) != np.asarray(b)))
        med, q25, q75, tn, to = alternate(call, other, rounds)
        print(f"{pat}: {threads} thread(s), {rounds} rounds: this / other speed {med:.3f} "
              f"[IQR {q25:.3f}-{q75:.3f}]; medians this {tn:.1f} ms, "
              f"other {to:.1f} ms; differing output pixels {same}")


def kodak(other, dataset):
    import skimage.io
    files = sorted(Path(dataset).glob("*.png"))
    if not files:
        raise SystemExit(f"{dataset}: no PNG images")
    for pat in ("mask1", "mask2"):
        for kind in ("uint16", "float32"):
            for prec in ("float32", "float64"):
                n_diff = n_px = 0
                worst = 0.0
                for p in files:
                    frame = rz.mosaic(skimage.io.imread(p)[..., :3], pat)
                    data = frame.data if kind == "uint16" else \
                        (frame.data / float((1 << frame.bit_depth) - 1)).astype(np.float32)
                    kw = dict(pattern=pat, precision=prec, workers=2)
                    if kind == "uint16":
                        kw["bit_depth"] = frame.bit_depth
                    outs = []
                    for mod in (None, other):
                        with kernels(mod):
                            outs.append(np.asarray(rz.reconstruct(data, "learned", **kw),
                                                   dtype=np.float64))
                    d = np.abs(outs[0] - outs[1])
                    n_diff += int(np.count_nonzero(d))
                    n_px += d.size
                    worst = max(worst, float(d.max()))
                print(f"{pat} {kind} {prec}: {len(files)} images, {n_diff} of {n_px} output "
                      f"pixels differ, largest difference {worst:g}")


def main(argv):
    if len(argv) < 2 or argv[1] not in ("speed", "kodak"):
        raise SystemExit(__doc__)
    other = load_other(argv[0])
    if argv[1] == "speed":
        speed(other, int(argv[2]) if len(argv) > 2 else 15, int(argv[3]) if len(argv) > 3 else 1,
              argv[4].split(",") if len(argv) > 4 else ("mask1", "mask2"))
    else:
        kodak(other, argv[2] if len(argv) > 2 else "../shared/data/kodak")


if __name__ == "__main__":
    main(sys.argv[1:])
