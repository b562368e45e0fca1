"""What ``rgbz-fast bench`` times: the benchmark frame, one case per kernel, the baselines
(OpenCV, the NumPy references), the ToF section and the colour chain."""

from __future__ import annotations

import importlib.machinery
import importlib.util
import os
import warnings
from pathlib import Path

import numpy as np

from ...simulation import SPEED_OF_LIGHT
from .._common import tile_to
from ..timing import WARMUP_CALLS, interleaved, rate_stats, timed

__all__ = ["make_rgb", "load_numpy_reference", "tof_taps", "build_cases", "case_label",
           "opencv_calls", "opencv_speeds", "OpenCVThreads", "tof_sites_benchmark", "colour_chain_benchmark",
           "simulate_benchmark", "tof_isp_benchmark", "bench_depth", "SIMULATE_TARGETS_S",
           "TOF_ISP_TARGETS", "FULL_SHAPE", "RECON_METHODS", "PATTERNS", "PRECISIONS", "TOF_FREQS",
           "TOF_TARGET_X_NUMPY"]

FULL_SHAPE = (3000, 4000)     # rows, cols: a 3000x4000 (12 Mpix) frame
#: the paper's methods, then the library's learned filters (the shipped ones of each pattern;
#: no NumPy reference row: tests/_reference/learned.py is a test, not a benchmark)
RECON_METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "learned", "z_guided")
PATTERNS = ("mask1", "mask2")
PRECISIONS = ("float32", "float64")
TOF_FREQS = (80e6, 100e6, 120e6)
#: the ToF section's target: the fused C kernel, all threads, over the NumPy implementation
TOF_TARGET_X_NUMPY = 5.0
#: the simulate case's targets on the full frame, Mask1 with ToF: seconds, noise-free / noisy
SIMULATE_TARGETS_S = {"noise_free": 0.5, "noisy": 1.0}
#: the ToF ISP case's targets on the full frame, Mask1: the colour-guided ISP in million
#: measurements per second, upsample_depth in Mpix/s (issue 25)
TOF_ISP_TARGETS = {"guided": 20.0, "upsample": 50.0}


def make_rgb(shape):
    """The benchmark scene: skimage.data.astronaut mirrored and tiled to ``shape``."""
    import skimage.data

    return tile_to(skimage.data.astronaut(), shape)


def load_numpy_reference(path, name="path"):
    """The slow NumPy reference of the reconstruction, from the file ``path``.

    The reference (``tests/_reference/reconstruction.py`` of a source checkout)
    belongs to the tests, not to the installed package: it is timed only when
    a file is given, never looked for.

    Raises
    ------
    ValueError
        ``"{name}: ..."``: the file does not exist, does not load, or defines
        no ``reference_reconstruct``.
    """
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"{name}: {path} is not a file")
    # loaded as Python source whatever its name (a file without .py gave no loader)
    loader = importlib.machinery.SourceFileLoader("_rgbz_numpy_reference", str(path))
    spec = importlib.util.spec_from_loader("_rgbz_numpy_reference", loader)
    mod = importlib.util.module_from_spec(spec)
    try:
        loader.exec_module(mod)
    except (Exception, SystemExit) as exc:  # noqa: BLE001 - the user's file: say why it failed
        raise ValueError(f"{name}: cannot load {path} ({type(exc).__name__}: {exc})") from None
    if not hasattr(mod, "reference_reconstruct"):
        raise ValueError(f"{name}: {path} defines no reference_reconstruct")
    return mod


def tof_taps(n, seed=0):
    """Synthetic 11-bit taps (F, 4, n) of depths uniform in [0.3, 7] m (tap convention of
    docs/guide/sensor.md: A_k = black + K (O + a cos(phi + k pi / 2)))."""
    rng = np.random.default_rng(seed)
    depth = rng.uniform(0.3, 7.0, n)
    taps = np.empty((len(TOF_FREQS), 4, n), np.uint16)
    for i, f in enumerate(TOF_FREQS):
        phi = 4 * np.pi * f * depth / SPEED_OF_LIGHT
        for k in range(4):
            taps[i, k] = np.round(64 + 900 + 700 * np.cos(phi + k * np.pi / 2))
    return taps


def build_cases(shape, ref_crop, ref=None):
    """The cases and the frames they run on: ``(cases, frame)``.

    ``cases``: [(name, meta, build)], where ``build()`` -> (fn(workers), the
    reference's fn or None, the pixels the reference runs on); ``frame(pattern)``
    mosaics the benchmark scene on a pattern (once). ``ref``: the module of
    :func:`load_numpy_reference`, or None.
    """
    import rgbz_fast as rz

    rgb = make_rgb(shape)
    frames = {}

    def frame(pat):
        if pat not in frames:
            frames[pat] = rz.mosaic(rgb, pat)
        return frames[pat]

    def tof_frame(pat):
        """The scene through the sensor model (a plane at 2 m): a frame with ToF taps, for the
        methods of NEEDS_TOF (the speed of z_guided includes demodulating the amplitude)."""
        if ("tof", pat) not in frames:
            from ...simulation import Scene, simulate
            frames["tof", pat] = simulate(Scene.from_rgb(rgb, depth=np.full(shape, 2.0)), pat,
                                          seed=0, noise=True)
        return frames["tof", pat]

    cr = (ref_crop[0] // 12 * 12, ref_crop[1] // 4 * 4)   # fits every pattern period
    cases = []

    def recon_case(method, pat, prec, exp="auto"):
        def build():
            fr = tof_frame(pat) if method in rz.NEEDS_TOF else frame(pat)
            ref_fn = None
            if ref is not None and exp == "auto" and method not in ("learned", "z_guided"):
                crop = np.ascontiguousarray(fr.data[:cr[0], :cr[1]])
                pattern = fr.pattern

                def ref_fn():
                    ref.reference_reconstruct(crop, pattern, method, bit_depth=fr.bit_depth)
            return (lambda w: rz.reconstruct(fr, method, precision=prec, workers=w, exp=exp),
                    ref_fn, cr[0] * cr[1])
        name = f"reconstruct {method}" + ("" if exp == "auto" else f" exp={exp}")
        cases.append((name, dict(kernel="reconstruct", method=method, pattern=pat,
                                 precision=prec, exp=exp), build))

    for pat in PATTERNS:
        for method in RECON_METHODS:
            for prec in PRECISIONS:
                recon_case(method, pat, prec)
        recon_case("sg", pat, "float32", "libm")   # the default is exp="auto": fast in float32
    for prec in PRECISIONS:
        recon_case("edi_rows", "rows", prec)

    # colour-demosaicing's function of each demosaic: the NumPy reference of the bench
    reference_names = {"malvar2004": "demosaicing_CFA_Bayer_Malvar2004",
                       "menon2007": "demosaicing_CFA_Bayer_Menon2007"}

    def demosaic_build(method, out_dtype):
        def build():
            cfa = frame("bayer").data
            from ...isp import demosaic as _dm

            def fn(w):
                _dm(cfa, "GRBG", method, dtype=out_dtype, workers=w)
            ref_fn = None
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", DeprecationWarning)
                    import colour_demosaicing
                _cm = getattr(colour_demosaicing, reference_names[method])
                crop = cfa[:cr[0], :cr[1]].astype(np.float64)

                def ref_fn():
                    with warnings.catch_warnings():      # scipy.ndimage.filters in colour
                        warnings.simplefilter("ignore", DeprecationWarning)
                        _cm(crop, "GRBG")
            except ImportError:
                pass
            return fn, ref_fn, cr[0] * cr[1]
        return build

    for method in ("malvar2004", "menon2007"):
        for dt in (np.float32, np.float64):
            cases.append((f"demosaic {method}", dict(kernel="demosaic", method=method,
                                                     pattern="bayer",
                                                     precision=np.dtype(dt).name, exp=None),
                          demosaic_build(method, dt)))

    from ... import _kernels

    def tof_build(pat, stage):
        def build():
            fr = frame(pat)
            block = 2 if pat == "mask2" else 1
            n = int(fr.z_mask.sum()) // (block * block)
            taps = tof_taps(n)
            F = taps.shape[0]
            phase, amp, off = (np.empty((F, n)) for _ in range(3))
            _kernels.tof_demodulate(taps, phase, amp, off, 1)
            freqs = np.asarray(TOF_FREQS)
            weights = freqs ** 2 / (freqs ** 2).sum()
            max_range = SPEED_OF_LIGHT / (2 * 20e6)
            depth, resid = np.empty(n), np.empty(n)
            wraps = np.empty(n, np.int32)
            if stage == "demodulate":
                def fn(w):
                    _kernels.tof_demodulate(taps, phase, amp, off, w)
                tc = taps[:, :, : max(1, n * cr[0] * cr[1] // fr.data.size)].astype(np.float64)

                def ref_fn():
                    i = tc[:, 0] - tc[:, 2]
                    q = tc[:, 3] - tc[:, 1]
                    np.mod(np.arctan2(q, i), 2 * np.pi)
                    0.5 * np.hypot(i, q)
                    tc.mean(axis=1)
                return fn, ref_fn, cr[0] * cr[1]

            def fn(w):
                _kernels.tof_unwrap(phase, freqs, weights, max_range, depth, resid, wraps, w)
            return fn, None, 0
        return build

    for pat in PATTERNS:
        for stage in ("demodulate", "unwrap"):
            cases.append((f"tof {stage}", dict(kernel=f"tof_{stage}", method=stage, pattern=pat,
                                               precision="float64", exp=None),
                          tof_build(pat, stage)))
    return cases, frame


def case_label(name, meta):
    """The label ``--kernels`` matches: 'reconstruct sg mask1 float32 exp=auto', 'tof unwrap
    mask2 float64', 'demosaic malvar2004 bayer float32'."""
    base = name.split(" exp=")[0]
    return f"{base} {meta['pattern']} {meta['precision']}" + (
        f" exp={meta['exp']}" if meta.get("exp") else "")


def opencv_calls(frame):
    """(cv2, {"bilinear": fn, "ea": fn}): OpenCV's Bayer demosaics of the benchmark's Bayer
    frame (``frame("bayer")``), to time beside each case; None without cv2."""
    try:
        import cv2
    except ImportError:
        return None
    cfa = frame("bayer").data
    return cv2, {"bilinear": lambda: cv2.cvtColor(cfa, cv2.COLOR_BayerGR2RGB),
                 "ea": lambda: cv2.cvtColor(cfa, cv2.COLOR_BayerGR2RGB_EA)}


def opencv_speeds(frame, repeat, workers, npix):
    """OpenCV's Bayer demosaics of the Bayer frame timed on their own, 1 thread and
    ``workers`` threads: {"version", "bilinear": {"1", "all"}, "ea": ...}; None without cv2."""
    calls = opencv_calls(frame)
    if calls is None:
        return None
    cv2, fns = calls
    out = {"version": cv2.__version__}
    for key, fn in fns.items():
        out[key] = {}
        for label, n in (("1", 1), ("all", workers)):
            with OpenCVThreads(cv2, n):
                out[key][label] = rate_stats(timed(fn, repeat), npix)
    return out


class OpenCVThreads:
    """OpenCV's thread count set to ``n`` inside the block (nothing without cv2)."""

    def __init__(self, cv2, n):
        self.cv2, self.n = cv2, n

    def __enter__(self):
        if self.cv2 is not None:
            self.old = self.cv2.getNumThreads()
            self.cv2.setNumThreads(self.n)

    def __exit__(self, *exc):
        if self.cv2 is not None:
            self.cv2.setNumThreads(self.old)


def tof_sites_benchmark(shape=FULL_SHAPE, repeat=5, workers=None, pattern="mask1",
                        verdict=True):
    """Demodulation + unwrapping of the Z measurements of a ``shape`` frame: C vs NumPy.

    ``verdict`` False (a quick run): the speeds only; the ratios over NumPy and
    the target verdict are None.

    Returns a dict with the measurement count, ``c_1`` / ``c_all`` (fused C kernel, 1 and
    ``workers`` threads), ``c_stages_all`` (``demodulate`` then ``unwrap``, two C passes),
    ``numpy`` (:mod:`rgbz_fast._devtools._numpy_tof`), each with ``msites_s`` (median, million
    measurements per second), the speed ratios over NumPy and their agreement.
    """
    import rgbz_fast as rz

    from ... import tof
    from .._numpy_tof import numpy_tof_depth

    workers = workers or (os.cpu_count() or 1)
    pat = rz.get_pattern(pattern)
    z = pat.z_mask(shape)
    n = int(z.sum())
    if pattern == "mask2":
        n //= 4
    taps = tof_taps(n)
    f = np.asarray(TOF_FREQS)

    def stages():
        ph, _, _ = tof.demodulate(taps, workers=workers)
        tof.unwrap(ph, f, workers=workers)

    times = interleaved({
        "c_1": lambda: tof.demodulate_unwrap(taps, f, workers=1),
        "c_all": lambda: tof.demodulate_unwrap(taps, f, workers=workers),
        "c_stages_all": stages,
        "numpy": lambda: numpy_tof_depth(taps, f),
    }, repeat)
    out = {k: rate_stats(v, n, "msites") for k, v in times.items()}
    c = tof.demodulate_unwrap(taps, f, workers=workers)
    ref = numpy_tof_depth(taps, f)
    agree = {"wraps_equal": bool(np.array_equal(c[2], ref[2])),
             "max_abs_depth_diff_m": float(np.max(np.abs(c[0] - ref[0]))) if n else 0.0,
             "max_abs_phase_diff_rad": float(np.max(np.abs(c[3] - ref[3]))) if n else 0.0}
    npy = out["numpy"]["median_s"]
    x_1 = npy / out["c_1"]["median_s"] if verdict else None
    x_all = npy / out["c_all"]["median_s"] if verdict else None
    return dict(pattern=pattern, frame_shape=list(shape), n_sites=n, frequencies=list(TOF_FREQS),
                workers=workers, repeat=repeat, warmup_calls=WARMUP_CALLS, **out,
                x_numpy_1=x_1, x_numpy_all=x_all, target_x_numpy=TOF_TARGET_X_NUMPY,
                target_met=None if x_all is None else bool(x_all >= TOF_TARGET_X_NUMPY),
                agreement=agree)


def colour_chain_benchmark(shape=FULL_SHAPE, repeat=3, workers=None, pattern="mask1"):
    """``isp.ColourISP().run`` (SG float32, Malvar) on the benchmark frame mosaicked on
    ``pattern``: the fused path (``run(frame)``, the C passes) and the reference (``run(frame,
    return_stages=True)``, the NumPy stages) timed in turn in the same rounds with OpenCV's
    edge-aware demosaic of the Bayer frame (``workers`` threads): their medians, the
    reference's seconds per stage, and the speed ratios of the rounds (OpenCV EA's seconds
    over ours, > 1: we are faster), median over the rounds; whether the two paths give the
    same image."""
    import rgbz_fast as rz

    from ...isp import STAGES, ColourISP

    workers = workers or (os.cpu_count() or 1)
    rgb = make_rgb(shape)
    frame = rz.mosaic(rgb, pattern)
    chain = ColourISP()
    seconds = []                     # the stages' seconds of every call, warm-up first

    def stages():
        seconds.append(chain.run(frame, workers=workers, return_stages=True)[1]["seconds"])

    fns = {"fused": lambda: chain.run(frame, workers=workers), "stages": stages}
    calls = opencv_calls(lambda _: rz.mosaic(rgb, "bayer"))
    cv2 = None
    if calls is not None:
        cv2, ocv = calls
        fns["opencv_ea"] = ocv["ea"]
    with OpenCVThreads(cv2, workers):
        times = interleaved(fns, repeat)
    runs = seconds[-repeat:]
    same = bool(np.array_equal(chain.run(frame, workers=workers),
                               chain.run(frame, workers=workers, return_stages=True)[0]))
    out = dict(pattern=pattern, frame_shape=list(shape), workers=workers, repeat=repeat,
               reconstruction=chain.reconstruction.method, precision=chain.precision,
               demosaic=chain.demosaicing.method,
               fused_s=float(np.median(times["fused"])),
               fused_min_s=float(np.min(times["fused"])),
               total_s=float(np.median(times["stages"])),
               total_min_s=float(np.min(times["stages"])),
               stages_s={k: float(np.median([s[k] for s in runs])) for k in STAGES},
               identical=same, opencv_ea_s=None, vs_opencv_ea_fused=None,
               vs_opencv_ea_stages=None)
    if "opencv_ea" in times:
        ea = times["opencv_ea"]
        out.update(opencv_ea_s=float(np.median(ea)),
                   vs_opencv_ea_fused=float(np.median(ea / times["fused"])),
                   vs_opencv_ea_stages=float(np.median(ea / times["stages"])))
    return out


def bench_depth(shape):
    """The simulate case's depth map: a plane sloping from 1 m to 3.5 m, within the range of
    the default ToF frequencies (7.5 m)."""
    rows, cols = shape
    yy, xx = np.mgrid[:rows, :cols]
    return 1.0 + 2.0 * xx / cols + 0.5 * yy / rows


def simulate_benchmark(shape=FULL_SHAPE, repeat=3, workers=None, patterns=("mask1", "mask2"),
                       verdict=True):
    """Seconds of :func:`rgbz_fast.simulate` of the benchmark scene with a depth map (the
    8-bit image of :func:`make_rgb`, no optics, the default 3 ToF frequencies), noise-free
    and noisy, per pattern: medians over ``repeat`` runs after a warm-up, the two runs of a
    pattern alternated; and the seconds of building the :class:`~rgbz_fast.simulation.Scene`
    (the sRGB decoding of the image). The targets are Mask1's on the full frame."""
    import time

    from ...simulation import Scene, simulate

    workers = workers or (os.cpu_count() or 1)
    rgb, depth = make_rgb(shape), bench_depth(shape)
    t0 = time.perf_counter()
    scene = Scene(rgb, depth=depth)
    scene_s = time.perf_counter() - t0
    out = {}
    for pattern in patterns:
        times = interleaved({
            "noise_free": lambda p=pattern: simulate(scene, p, noise=False, workers=workers),
            "noisy": lambda p=pattern: simulate(scene, p, seed=1, workers=workers)}, repeat)
        out[pattern] = {k: {"median_s": float(np.median(v)), "min_s": float(np.min(v))}
                        for k, v in times.items()}
    targets = {}
    if "mask1" in out:
        for k, limit in SIMULATE_TARGETS_S.items():
            got = out["mask1"][k]["median_s"]
            targets[k] = {"seconds": got, "target_s": limit,
                          "met": bool(got <= limit) if verdict else None}
    return dict(frame_shape=list(shape), workers=workers, repeat=repeat, scene_s=scene_s,
                frequencies=3, optics=None, patterns=out, targets=targets)


def tof_isp_benchmark(shape=FULL_SHAPE, repeat=3, workers=None, pattern="mask1", verdict=True):
    """The ToF ISP on the simulate case's frame (the benchmark image with its depth plane,
    noisy, seed 1, ``pattern``), as a loop over frames runs it: each round
    ``ToFISP().run(tof, guide=image)`` with the frame's own colour image
    (``ColourISP().run(frame)``), then ``upsample_depth`` of that result, both timed, the
    results dropped before the next round (their arrays land on the memory pool's kept
    pages, :func:`rgbz_fast.memory_pool`); then ``ToFISP().run(tof)`` (the default bilateral
    denoise) on its own, ``repeat`` calls (its 0.9 GiB of fresh arrays a call, between the
    guided calls, would be a loop no program runs). Medians, in million measurements (the
    ISP) or pixels (the upsampling) per second, and the targets of :data:`TOF_ISP_TARGETS`
    (Mask1, the full frame; None without a verdict)."""
    import time

    from ..._memory import memory_pool
    from ...isp import ColourISP
    from ...simulation import Scene, simulate
    from ...tof import ToFISP, upsample_depth

    workers = workers or (os.cpu_count() or 1)
    frame = simulate(Scene(make_rgb(shape), depth=bench_depth(shape)), pattern, seed=1,
                     workers=workers)
    guide = ColourISP().run(frame, workers=workers)
    tof, isp = frame.tof, ToFISP()
    chain = {"guided": [], "upsample": []}
    valid = []

    def depth_chain():
        t0 = time.perf_counter()
        result = isp.run(tof, guide=guide, workers=workers)
        t1 = time.perf_counter()
        upsample_depth(result, guide, workers=workers)
        chain["guided"].append(t1 - t0)
        chain["upsample"].append(time.perf_counter() - t1)
        valid.append(float(result.valid.mean()) if result.valid.size else 0.0)

    interleaved({"chain": depth_chain}, repeat)
    times = {k: v[-repeat:] for k, v in chain.items()}
    times.update(interleaved({"unguided": lambda: isp.run(tof, workers=workers)}, repeat))
    n, npix = tof.n_sites, shape[0] * shape[1]
    out = {k: rate_stats(v, npix if k == "upsample" else n, "mpix" if k == "upsample"
                         else "msites") for k, v in times.items()}
    targets = {}
    if pattern == "mask1":
        for k, limit in TOF_ISP_TARGETS.items():
            got = out[k]["mpix_s" if k == "upsample" else "msites_s"]
            targets[k] = {"rate": got, "target": limit,
                          "met": bool(got >= limit) if verdict else None}
    return dict(pattern=pattern, frame_shape=list(shape), n_sites=n, workers=workers,
                repeat=repeat, valid_share=valid[-1],
                memory_pool_limit=memory_pool()["limit"], **out, targets=targets)
