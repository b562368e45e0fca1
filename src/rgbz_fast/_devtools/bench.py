"""``rgbz-fast bench``: speed of every C kernel, beside OpenCV and the NumPy references.

Self-contained: the frame is scikit-image's astronaut (bundled with
scikit-image) mirrored and tiled up to 3000x4000 (rows x cols), mosaicked to 11-bit uint16 on
each pattern. For every kernel (each reconstruction method x pattern x
precision, the Malvar 2004 demosaic, ToF demodulation and unwrapping) it
reports the speed in **frame** megapixels per second (all pixels of the frame
over the wall time of one call), the median and the interquartile range of N
calls (after one warm-up call), with 1 thread and with all threads. Beside it:

* OpenCV's Bayer demosaic of the same-size Bayer frame in the same run,
  bilinear (``COLOR_BayerGR2RGB``) and edge-aware (``COLOR_BayerGR2RGB_EA``),
  with 1 thread and all threads (``cv2.setNumThreads``); "n/a" without cv2.
  Ratios are speed ratios, ours / theirs (> 1: we are faster), same thread
  setting, paired: each timed call of a case alternates with one call of each
  OpenCV demosaic, and the ratio is the median of the rounds' ratios, so that
  a change of the machine's load during the run hits both sides alike.
* With ``--numpy-reference FILE`` (``tests/_reference/reconstruction.py`` of a
  source checkout), the plain NumPy reference of each method, timed on a crop
  of the same frame and scaled to Mpix/s; the ratio is our 1-thread speed
  over it ("n/a" without the option).
  The Malvar demosaic is compared with colour-demosaicing's NumPy/SciPy
  implementation and the demodulation with a NumPy one-liner.
* ToF section: demodulation + unwrapping of the Z measurements of a Mask1
  frame of that size (3 million at 3000x4000; 3 frequencies x 4 taps,
  synthetic 11-bit taps of depths in [0.3, 7] m) in million measurements
  per second: the fused C kernel (``rgbz_fast.tof.demodulate_unwrap``) with 1
  thread and all threads beside the vectorised NumPy implementation of the
  same algorithm (``rgbz_fast._devtools._numpy_tof``: ``np.arctan2``, brute force over
  the same wrap candidates), timed in turn in the same loop, with the check
  that both agree. The issue's target is >= 5x NumPy with all threads.
* ``--chain``: the colour ISP (``isp.ColourISP``: defects -> SG float32
  reconstruction -> white balance -> C Malvar demosaic -> colour correction ->
  sRGB gamma -> 8-bit output) on the Mask1 frame, seconds per stage (medians).
* Peak memory of one ``reconstruct`` call on the full frame, measured in a
  fresh subprocess: the growth of the peak resident set size
  (``ru_maxrss``) across the call, and tracemalloc's peak of the Python-side
  (NumPy) allocations, against the input and output sizes. The issue's
  budget is input + output + 10 %, i.e. a growth of at most
  output + 0.1 (input + output).

Numbers from a shared machine are noisy: the load average before and after
the run is printed with them.

Honest by construction:

* every case is called once untimed (warm-up: the OpenMP thread team, caches,
  lazy plans), then timed ``--repeat`` times; the report says so;
* "all threads" is the thread count the library really uses on that frame:
  a kernel call takes at most one thread per 2**18 pixels
  (:data:`rgbz_fast._validate.MIN_PIXELS_PER_THREAD`), so on a small frame it
  is fewer than the cores, and the report shows the count;
* ``--quick`` is a smoke test: small frame, few runs, on a shared machine its
  numbers are not comparable with anything, so it prints no ratio (xNumPy,
  xCV, x NumPy of the ToF section) and no target verdict ("quick run: numbers
  not comparable, no verdict"). A full run gives the verdicts of the targets,
  which are defined on the 4000x3000 frame: another ``--shape`` gives the
  ratios but no verdict.
"""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from .._validate import kernel_threads, parse_shape
from ._common import (CliError, check_out_dir, check_workers_arg, common_parser,
                         machine_info, progress, run_main, tile_to, write_json)

__all__ = ["run_benchmarks", "format_table", "load_numpy_reference", "measure_memory",
           "tof_sites_benchmark", "colour_chain_benchmark", "format_tof", "format_chain", "main"]

FULL_SHAPE = (3000, 4000)     # rows, cols: a 4000x3000 (12 Mpix) frame
QUICK_SHAPE = (192, 256)
#: the paper's methods, then the library's learned filters (the shipped ones of each pattern;
#: no NumPy reference row: tests/_reference/learned.py is a test, not a benchmark)
RECON_METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "learned")
PATTERNS = ("mask1", "mask2")
PRECISIONS = ("float32", "float64")
TARGET_SG_MPIX = 150.0
TOF_FREQS = (80e6, 100e6, 120e6)


# ---------------------------------------------------------------------------------------------
# frames and references

def make_rgb(shape):
    """The benchmark scene: skimage.data.astronaut mirrored and tiled to ``shape``."""
    import skimage.data

    return tile_to(skimage.data.astronaut(), shape)


def load_numpy_reference(path):
    """The slow NumPy reference of the reconstruction, from the file ``path``.

    The reference (``tests/_reference/reconstruction.py`` of a source checkout)
    belongs to the tests, not to the installed package: ``rgbz-fast bench``
    compares with it only when asked (``--numpy-reference FILE``), and never
    looks for it on its own.

    Raises
    ------
    CliError
        The file does not exist or defines no ``reference_reconstruct``.
    """
    path = Path(path)
    if not path.is_file():
        raise CliError(f"--numpy-reference: {path} is not a file")
    spec = importlib.util.spec_from_file_location("_rgbz_numpy_reference", path)
    mod = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(mod)
    except Exception as exc:  # noqa: BLE001 - the user's file: report why it failed
        raise CliError(f"--numpy-reference: cannot load {path} ({exc})") from None
    if not hasattr(mod, "reference_reconstruct"):
        raise CliError(f"--numpy-reference: {path} defines no reference_reconstruct")
    return mod


def _tof_taps(n, seed=0):
    """Synthetic 11-bit taps (F, 4, n) of depths uniform in [0.3, 7] m (tap convention of
    docs/guide/sensor.md: A_k = black + K (O + a cos(phi + k pi / 2)))."""
    rng = np.random.default_rng(seed)
    depth = rng.uniform(0.3, 7.0, n)
    c = 299_792_458.0
    taps = np.empty((len(TOF_FREQS), 4, n), np.uint16)
    for i, f in enumerate(TOF_FREQS):
        phi = 4 * np.pi * f * depth / c
        for k in range(4):
            taps[i, k] = np.round(64 + 900 + 700 * np.cos(phi + k * np.pi / 2))
    return taps


# ---------------------------------------------------------------------------------------------
# timing

#: untimed calls of each case before the timed ones
WARMUP_CALLS = 1
QUICK_NOTE = "quick run: numbers not comparable, no verdict"


def _time(fn, repeat):
    for _ in range(WARMUP_CALLS):            # warm-up: thread pool, caches, lazy plans
        fn()
    out = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t0)
    return np.asarray(out)


def _stats(times, npix):
    q1, med, q3 = np.percentile(times, [25, 50, 75])
    mp = npix / 1e6
    return {"median_s": float(med), "q1_s": float(q1), "q3_s": float(q3),
            "min_s": float(times.min()), "max_s": float(times.max()), "n": int(times.size),
            "mpix_s": mp / med, "mpix_s_lo": mp / q3, "mpix_s_hi": mp / q1}


def _ratio(a, b):
    if a is None or b is None or not b:
        return None
    return a / b


class _OpenCVThreads:
    def __init__(self, cv2, n):
        self.cv2, self.n = cv2, n

    def __enter__(self):
        if self.cv2 is not None:
            self.old = self.cv2.getNumThreads()
            self.cv2.setNumThreads(self.n)

    def __exit__(self, *exc):
        if self.cv2 is not None:
            self.cv2.setNumThreads(self.old)


# ---------------------------------------------------------------------------------------------
# the cases

def _cases(shape, ref_crop, ref=None):
    """[(name, meta, build)] where build() -> (fn(workers), reference fn or None, ref pixels)."""
    import rgbz_fast as rz

    rgb = make_rgb(shape)
    frames = {}

    def frame(pat):
        if pat not in frames:
            frames[pat] = rz.mosaic(rgb, pat)
        return frames[pat]

    cr = (ref_crop[0] // 12 * 12, ref_crop[1] // 4 * 4)   # fits every pattern period
    cases = []

    def recon_case(method, pat, prec, exp="auto"):
        def build():
            fr = frame(pat)
            ref_fn = None
            if ref is not None and exp == "auto" and method != "learned":
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

    def malvar_build(out_dtype):
        def build():
            cfa = frame("bayer").data
            from ..isp import demosaic as _dm

            def fn(w):
                _dm(cfa, "GRBG", "malvar2004", dtype=out_dtype, workers=w)
            ref_fn = None
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", DeprecationWarning)
                    from colour_demosaicing import demosaicing_CFA_Bayer_Malvar2004 as _cm
                crop = cfa[:cr[0], :cr[1]].astype(np.float64)

                def ref_fn():
                    with warnings.catch_warnings():      # scipy.ndimage.filters in colour
                        warnings.simplefilter("ignore", DeprecationWarning)
                        _cm(crop, "GRBG")
            except ImportError:
                pass
            return fn, ref_fn, cr[0] * cr[1]
        return build

    for dt in (np.float32, np.float64):
        cases.append(("demosaic malvar2004", dict(kernel="demosaic", method="malvar2004",
                                                  pattern="bayer", precision=np.dtype(dt).name,
                                                  exp=None), malvar_build(dt)))

    from .. import _kernels

    def tof_build(pat, stage):
        def build():
            fr = frame(pat)
            block = 2 if pat == "mask2" else 1
            n = int(fr.z_mask.sum()) // (block * block)
            taps = _tof_taps(n)
            F = taps.shape[0]
            phase, amp, off = (np.empty((F, n)) for _ in range(3))
            _kernels.tof_demodulate(taps, phase, amp, off, 1)
            freqs = np.asarray(TOF_FREQS)
            weights = freqs ** 2 / (freqs ** 2).sum()
            max_range = 299_792_458.0 / (2 * 20e6)
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
    return cases, rgb, frame, ref is not None


def _opencv_calls(frame_fn):
    """(cv2, {"bilinear": fn, "ea": fn}): OpenCV's Bayer demosaics of the benchmark's Bayer
    frame, to time beside each case; None without cv2."""
    try:
        import cv2
    except ImportError:
        return None
    cfa = frame_fn("bayer").data
    return cv2, {"bilinear": lambda: cv2.cvtColor(cfa, cv2.COLOR_BayerGR2RGB),
                 "ea": lambda: cv2.cvtColor(cfa, cv2.COLOR_BayerGR2RGB_EA)}


def _opencv(frame_fn, repeat, workers, npix):
    try:
        import cv2
    except ImportError:
        return None
    cfa = frame_fn("bayer").data
    out = {"version": cv2.__version__}
    for key, code in (("bilinear", cv2.COLOR_BayerGR2RGB), ("ea", cv2.COLOR_BayerGR2RGB_EA)):
        out[key] = {}
        for label, n in (("1", 1), ("all", workers)):
            with _OpenCVThreads(cv2, n):
                out[key][label] = _stats(_time(lambda: cv2.cvtColor(cfa, code), repeat), npix)
    return out


# ---------------------------------------------------------------------------------------------
# ToF measurements per second, C beside NumPy; the colour chain stage by stage

TOF_TARGET_X_NUMPY = 5.0


def _interleaved(fns, repeat):
    """Times of each function of ``fns`` (name -> fn), one call each per round after one
    warm-up call each: the rounds alternate the functions, so that a change of the
    machine's load during the run hits all of them alike."""
    for fn in fns.values():
        fn()
    times = {k: [] for k in fns}
    for _ in range(repeat):
        for k, fn in fns.items():
            t0 = time.perf_counter()
            fn()
            times[k].append(time.perf_counter() - t0)
    return {k: np.asarray(v) for k, v in times.items()}


def _site_stats(times, n):
    q1, med, q3 = np.percentile(times, [25, 50, 75])
    return {"median_s": float(med), "q1_s": float(q1), "q3_s": float(q3),
            "min_s": float(times.min()), "n": int(times.size), "msites_s": n / 1e6 / med,
            "msites_s_lo": n / 1e6 / q3, "msites_s_hi": n / 1e6 / q1}


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

    from .. import tof
    from ._numpy_tof import numpy_tof_depth

    workers = workers or (os.cpu_count() or 1)
    pat = rz.get_pattern(pattern)
    z = pat.z_mask(shape)
    n = int(z.sum())
    if pattern == "mask2":
        n //= 4
    taps = _tof_taps(n)
    f = np.asarray(TOF_FREQS)

    def stages():
        ph, _, _ = tof.demodulate(taps, workers=workers)
        tof.unwrap(ph, f, workers=workers)

    times = _interleaved({
        "c_1": lambda: tof.demodulate_unwrap(taps, f, workers=1),
        "c_all": lambda: tof.demodulate_unwrap(taps, f, workers=workers),
        "c_stages_all": stages,
        "numpy": lambda: numpy_tof_depth(taps, f),
    }, repeat)
    out = {k: _site_stats(v, n) for k, v in times.items()}
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
    """Seconds of every stage of ``isp.ColourISP().run`` (SG float32, C Malvar) on the
    benchmark frame mosaicked on ``pattern``: medians over ``repeat`` runs after a warm-up."""
    import rgbz_fast as rz

    from ..isp import STAGES, ColourISP

    workers = workers or (os.cpu_count() or 1)
    frame = rz.mosaic(make_rgb(shape), pattern)
    chain = ColourISP()
    chain.run(frame, workers=workers)
    totals, stages = [], {k: [] for k in STAGES}
    for _ in range(repeat):
        t0 = time.perf_counter()
        _, st = chain.run(frame, workers=workers, return_stages=True)
        totals.append(time.perf_counter() - t0)
        for k in STAGES:
            stages[k].append(st["seconds"][k])
    return dict(pattern=pattern, frame_shape=list(shape), workers=workers, repeat=repeat,
                reconstruction=chain.reconstruction.method, precision=chain.precision,
                demosaic=chain.demosaicing.method,
                total_s=float(np.median(totals)), total_min_s=float(np.min(totals)),
                stages_s={k: float(np.median(v)) for k, v in stages.items()})


# ---------------------------------------------------------------------------------------------
# memory

_MEM_SCRIPT = r"""
import gc, json, sys, tracemalloc
import numpy as np
import rgbz_fast as rz
path, pattern, method, precision, workers, mode = sys.argv[1:7]
data = np.load(path)
rz.reconstruct(data[:96, :96].copy(), method, pattern=pattern, precision=precision,
               workers=int(workers))                      # warm-up: threads, plans
def status(key):
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
def reset_hwm():
    try:
        with open("/proc/self/clear_refs", "w") as fh:   # "5": reset the peak RSS (Linux >= 4.0)
            fh.write("5")
        return True
    except OSError:
        return False
# one mode per process: freed pages may stay resident (malloc keeps them) and hide the next
frame = rz.RawFrame(data, pattern, 11) if mode == "rawframe" else data
kw = {} if mode == "rawframe" else {"pattern": pattern}
gc.collect()
exact = reset_hwm()
before = status("VmRSS") if exact else status("VmHWM")
tracemalloc.start()
out = rz.reconstruct(frame, method, precision=precision, workers=int(workers), **kw)
_, traced = tracemalloc.get_traced_memory()
tracemalloc.stop()
after = status("VmHWM")
print(json.dumps(dict(rss_before=before, hwm_after=after, traced_peak=traced, hwm_reset=exact,
                      in_bytes=data.nbytes, out_bytes=out.nbytes)))
"""


def measure_memory(data, pattern="mask1", method="sg", precision="float32", workers=None):
    """Peak-memory growth of one ``reconstruct`` call, in a fresh Python process.

    The frame is handed over as a .npy file (``np.load`` allocates nothing but
    the array). Before the call the peak RSS is reset (``/proc/self/clear_refs``,
    Linux >= 4.0), so the growth of the high-water mark (VmHWM, i.e.
    ``ru_maxrss``) over the resident size before the call is everything the call
    touched: the output pages, NumPy temporaries (argument validation), the C
    kernel's scratch and the thread stacks. tracemalloc gives the peak of the
    NumPy (Python allocator) part alone. Two inputs are measured: a plain
    array (``reconstruct`` checks its value range) and a :class:`RawFrame`
    (already validated at construction). Returns ``{"array": {...},
    "rawframe": {...}, ...}``, or None when /proc is not there.
    """
    import json

    if not Path("/proc/self/status").exists():
        return None
    workers = workers or (os.cpu_count() or 1)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "frame.npy"
        np.save(path, np.ascontiguousarray(data))
        out = {}
        for mode in ("array", "rawframe"):
            res = subprocess.run([sys.executable, "-c", _MEM_SCRIPT, str(path), str(pattern),
                                  method, precision, str(workers), mode], capture_output=True,
                                 text=True, timeout=600)
            if res.returncode != 0:
                err = res.stderr.strip().splitlines()
                return {"error": err[-1] if err else "failed"}
            m = json.loads(res.stdout.strip().splitlines()[-1])
            grow = m["hwm_after"] - m["rss_before"]
            budget = m["out_bytes"] + 0.1 * (m["in_bytes"] + m["out_bytes"])
            m.update(rss_growth=grow, rss_growth_over_output=grow / m["out_bytes"],
                     peak_over_in_plus_out=(m["in_bytes"] + grow) / (m["in_bytes"]
                                                                     + m["out_bytes"]),
                     budget_bytes=budget, within_budget=bool(grow <= budget))
            out[mode] = m
    return dict(pattern=str(pattern), method=method, precision=precision, workers=workers,
                shape=list(np.shape(data)), **out)


# ---------------------------------------------------------------------------------------------
# driver

def run_benchmarks(shape=FULL_SHAPE, repeat=5, workers=None, ref_crop=(240, 320), kernels=None,
                   reference=True, memory=True, quiet=True, tof_sites=True, chain=False,
                   numpy_reference=None, quick=False):
    """Run every benchmark; returns the JSON-able result dict (see ``--json``).

    ``quick``: a smoke test (``--quick``): the speeds are measured and reported,
    but no ratio (``vs_numpy``, ``vs_opencv_*``, the ToF ``x_numpy_*``) and no
    target verdict (``targets`` is empty). Verdicts also need the target frame
    (:data:`FULL_SHAPE`).

    ``numpy_reference``: the module of :func:`load_numpy_reference` (the tests' slow
    reconstruction reference), timed beside the C kernels; None: not timed.
    ``tof_sites``: the ToF section (C vs NumPy, M measurements/s); it runs unless
    ``kernels`` is given and none of its entries occurs in ``"tof sites"``. ``chain``:
    the colour ISP stage by stage.
    """
    workers = workers or (os.cpu_count() or 1)
    npix = shape[0] * shape[1]
    load0 = os.getloadavg() if hasattr(os, "getloadavg") else None
    cases, _, frame_fn, have_ref = _cases(shape, ref_crop, numpy_reference)
    if kernels:
        cases = [c for c in cases if any(k in _label(c[0], c[1]) for k in kernels)]
    results = []
    ratio = (lambda a, b: None) if quick else _ratio
    cv = _opencv_calls(frame_fn) if not quick else None
    for name, meta, build in progress(cases, desc="bench", quiet=quiet):
        fn, ref_fn, ref_pix = build()
        threads, paired = {}, {}
        for label, n in (("1", 1), ("all", workers)):
            if cv is None:
                threads[label] = _stats(_time(lambda: fn(n), repeat), npix)
                continue
            # our call and OpenCV's alternated round by round: a change of the machine's
            # load hits both, and the ratio is the median of the rounds' ratios
            with _OpenCVThreads(cv[0], n):
                t = _interleaved({"ours": lambda: fn(n), **cv[1]}, repeat)
            threads[label] = _stats(t["ours"], npix)
            for key in cv[1]:
                paired[f"vs_opencv_{key}_{label}"] = float(np.median(t[key] / t["ours"]))
        # the threads the call really runs: pixel kernels take one per 2**18 pixels at most
        threads["all"]["threads"] = (kernel_threads(workers, npix) if meta["kernel"] in
                                     ("reconstruct", "demosaic") else workers)
        threads["1"]["threads"] = 1
        ref_mpix = None
        if reference and ref_fn is not None:
            ref_mpix = _stats(_time(ref_fn, max(1, min(repeat, 3))), ref_pix)["mpix_s"]
        results.append(dict(name=name, **meta, threads=threads, numpy_ref_mpix_s=ref_mpix,
                            vs_numpy=ratio(threads["1"]["mpix_s"], ref_mpix), **paired))
    ocv = _opencv(frame_fn, repeat, workers, npix)
    for r in results:
        for key in ("bilinear", "ea"):
            for label in ("1", "all"):
                r.setdefault(f"vs_opencv_{key}_{label}", None)
    tof = None
    if tof_sites and (not kernels or any(k in "tof sites" for k in kernels)):
        tof = tof_sites_benchmark(shape, repeat, workers, verdict=not quick)
    colour = colour_chain_benchmark(shape, repeat, workers) if chain else None
    mem = None
    if memory:
        mem = measure_memory(frame_fn("mask1").data, "mask1", "sg", "float32", workers)
    sg = next((r for r in results if r["kernel"] == "reconstruct" and r["method"] == "sg"
               and r["pattern"] == "mask1" and r["precision"] == "float32"
               and r["exp"] == "auto"), None)
    targets = {}
    verdict = not quick and tuple(shape) == FULL_SHAPE
    if quick:
        pass                       # a smoke test: no ratio, no verdict
    elif sg is not None:
        v = sg["threads"]["all"]["mpix_s"]
        targets["sg_mask1_float32_all_threads_mpix_s"] = v
        targets["target_mpix_s"] = TARGET_SG_MPIX
        targets["target_met"] = bool(v >= TARGET_SG_MPIX) if verdict else None
        if ocv is not None and sg.get("vs_opencv_ea_all") is not None:
            targets["opencv_ea_all_threads_mpix_s"] = ocv["ea"]["all"]["mpix_s"]
            targets["fraction_of_opencv_ea"] = sg["vs_opencv_ea_all"]
    if tof is not None and not quick:
        targets["tof_x_numpy_all_threads"] = tof["x_numpy_all"]
        targets["tof_target_x_numpy"] = TOF_TARGET_X_NUMPY
        targets["tof_target_met"] = tof["target_met"] if verdict else None
    if mem and "array" in mem and not quick:
        targets["peak_memory_within_budget"] = {k: mem[k]["within_budget"]
                                                for k in ("array", "rawframe")}
    return {
        "machine": dict(machine_info(), loadavg_before=load0,
                        loadavg_after=os.getloadavg() if hasattr(os, "getloadavg") else None),
        "frame": {"shape": list(shape), "pixels": npix, "dtype": "uint16", "bit_depth": 11,
                  "source": "skimage.data.astronaut, mirrored and tiled"},
        "quick": bool(quick), "verdict": verdict, "target_frame": list(FULL_SHAPE),
        "repeat": repeat, "warmup_calls": WARMUP_CALLS, "workers_all": workers,
        "numpy_reference": {"available": have_ref and reference,
                            "crop": [ref_crop[0] // 12 * 12, ref_crop[1] // 4 * 4]},
        "results": results, "opencv": ocv, "tof_sites": tof, "colour_chain": colour,
        "memory": mem, "targets": targets,
    }


def _label(name, meta):
    """The label --kernels matches: 'reconstruct sg mask1 float32 exp=auto', 'tof unwrap mask2
    float64', 'demosaic malvar2004 bayer float32'."""
    base = name.split(" exp=")[0]
    return f"{base} {meta['pattern']} {meta['precision']}" + (
        f" exp={meta['exp']}" if meta.get("exp") else "")


def _f(v, nd=1):
    if v is None:
        return "n/a"
    if v >= 100:
        return f"{v:.0f}"
    return f"{v:.{nd}f}"


def format_table(res):
    """The human-readable report of :func:`run_benchmarks`'s result."""
    m = res["machine"]
    quick = res.get("quick", False)
    lines = ([QUICK_NOTE.upper()[:1] + QUICK_NOTE[1:] + " (a smoke test of a small frame)"]
             if quick else [])
    lines += [f"rgbz-fast {m.get('rgbz_fast', '?')} bench: frame {res['frame']['shape'][0]}x"
             f"{res['frame']['shape'][1]} (rows x cols, {res['frame']['pixels'] / 1e6:.1f} Mpix, "
             "uint16 11-bit),"
             f" median [IQR] of {res['repeat']} timed calls after "
             f"{res.get('warmup_calls', WARMUP_CALLS)} warm-up call per case, Mpix/s = frame "
             "pixels / s",
             f"machine: {m['cpu_model']}, {m['logical_cores']} logical cores "
             f"({m.get('usable_cores')} usable), OpenMP {m.get('openmp')}, "
             f"{m.get('compiler', '')}; all threads = {res['workers_all']}; load average "
             f"{_load(m['loadavg_before'])} -> {_load(m['loadavg_after'])}"]
    head = ["kernel", "pattern", "precision", "1 thread", "all threads", "threads", "xNumPy",
            "xCV bil", "xCV EA"]
    if quick:
        head = head[:-3]
    rows = []
    for r in res["results"]:
        t1, ta = r["threads"]["1"], r["threads"]["all"]
        row = [r["name"], r["pattern"], r["precision"],
               f"{_f(t1['mpix_s'])} [{_f(t1['mpix_s_lo'])}-{_f(t1['mpix_s_hi'])}]",
               f"{_f(ta['mpix_s'])} [{_f(ta['mpix_s_lo'])}-{_f(ta['mpix_s_hi'])}]",
               str(ta.get("threads", res["workers_all"]))]
        if not quick:
            row += [_f(r["vs_numpy"]), _f(r["vs_opencv_bilinear_all"], 2),
                    _f(r["vs_opencv_ea_all"], 2)]
        rows.append(row)
    ocv = res["opencv"]
    if ocv is not None:
        for key, label in (("bilinear", "OpenCV Bayer bilinear"), ("ea", "OpenCV Bayer EA")):
            t1, ta = ocv[key]["1"], ocv[key]["all"]
            rows.append([label, "bayer", "uint16",
                         f"{_f(t1['mpix_s'])} [{_f(t1['mpix_s_lo'])}-{_f(t1['mpix_s_hi'])}]",
                         f"{_f(ta['mpix_s'])} [{_f(ta['mpix_s_lo'])}-{_f(ta['mpix_s_hi'])}]",
                         str(res["workers_all"])] + ([] if quick else ["", "", ""]))
    w = [max(len(h), *(len(x[i]) for x in rows)) if rows else len(h) for i, h in enumerate(head)]
    lines.append("")
    lines.append("  ".join(h.ljust(n) for h, n in zip(head, w)))
    lines.append("  ".join("-" * n for n in w))
    lines += ["  ".join(c.ljust(n) for c, n in zip(x, w)) for x in rows]
    lines.append("")
    lines.append(f"threads: those of the 'all threads' column (at most {res['workers_all']}; "
                 "a reconstruction or demosaic call takes one per 2**18 pixels at most).")
    if quick:
        lines.append(f"{QUICK_NOTE}: no xNumPy, xCV or target columns; run without --quick "
                     "(the 4000x3000 frame) for them.")
    else:
        lines.append(
            "xNumPy: our 1-thread speed / the NumPy reference's (timed on a "
            f"{res['numpy_reference']['crop'][1]}x{res['numpy_reference']['crop'][0]} crop"
            + ("" if res["numpy_reference"]["available"] else "; reconstruction: n/a "
               "without --numpy-reference FILE") + "). xCV: our all-threads speed / OpenCV's "
            "on the same-size Bayer frame, the median of the per-round ratios of calls "
            "alternated with ours (so that a change of load hits both; the OpenCV rows "
            "above are timed on their own)" + ("" if ocv else " (cv2 not installed: n/a)")
            + ".")
    t = res["targets"]
    if "sg_mask1_float32_all_threads_mpix_s" in t:
        if t["target_met"] is None:
            verdict = (f"no verdict: the target is defined on the {res['target_frame'][1]}x"
                       f"{res['target_frame'][0]} frame")
        else:
            verdict = "met" if t["target_met"] else "NOT met"
        s = (f"target: SG Mask1 float32 all threads {t['sg_mask1_float32_all_threads_mpix_s']:.1f}"
             f" Mpix/s vs >= {t['target_mpix_s']:.0f}: {verdict}")
        if "opencv_ea_all_threads_mpix_s" in t:
            s += (f"; OpenCV EA {t['opencv_ea_all_threads_mpix_s']:.0f} Mpix/s on its own; "
                  f"alternated with it we run at {t['fraction_of_opencv_ea']:.3f} of its "
                  "speed (median of the rounds)")
        lines.append(s)
    tof = res.get("tof_sites")
    if tof:
        lines += ["", format_tof(tof, res.get("verdict", True))]
    if res.get("colour_chain"):
        lines += ["", format_chain(res["colour_chain"])]
    mem = res["memory"]
    if mem:
        if "error" in mem:
            lines.append(f"memory: n/a ({mem['error']})")
        else:
            for mode, label in (("array", "plain array (range check)"),
                                ("rawframe", "RawFrame (validated)")):
                m = mem[mode]
                lines.append(
                    f"memory: reconstruct {mem['method']} {mem['pattern']} {mem['precision']}, "
                    f"{label}: peak RSS +{m['rss_growth'] / 2**20:.1f} MiB = "
                    f"{m['rss_growth_over_output']:.2f} x output ({m['out_bytes'] / 2**20:.1f} "
                    f"MiB), tracemalloc peak {m['traced_peak'] / 2**20:.1f} MiB; input + growth ="
                    f" {m['peak_over_in_plus_out']:.3f} x (input + output) [budget 1.10: "
                    f"{'ok' if m['within_budget'] else 'OVER'}]")
    return "\n".join(lines)


def format_tof(tof, verdict=True):
    """The ToF section of the report (C vs NumPy, million measurements per second);
    ``verdict`` False: no target verdict (a frame other than the target's)."""
    lines = [f"ToF: demodulation + unwrapping of the {tof['n_sites']:,} Z measurements of a "
             f"{tof['frame_shape'][0]}x{tof['frame_shape'][1]} {tof['pattern']} frame "
             f"({len(tof['frequencies'])} frequencies x 4 taps, uint16), median [IQR] of "
             f"{tof['repeat']} timed runs after {tof.get('warmup_calls', WARMUP_CALLS)} warm-up, "
             "M measurements/s (timed in turn in one loop)"]
    rows = [("C fused, 1 thread", tof["c_1"]), (f"C fused, {tof['workers']} threads",
                                                 tof["c_all"]),
            (f"C demodulate + unwrap, {tof['workers']} threads", tof["c_stages_all"]),
            ("NumPy (np.arctan2 + vectorised brute force)", tof["numpy"])]
    w = max(len(r[0]) for r in rows)
    for label, t in rows:
        lines.append(f"  {label.ljust(w)}  {_f(t['msites_s'])} [{_f(t['msites_s_lo'])}-"
                     f"{_f(t['msites_s_hi'])}]  ({t['median_s']:.3f} s)")
    a = tof["agreement"]
    if tof["x_numpy_all"] is None:
        ratio = f"{QUICK_NOTE}; "
    else:
        ratio = (f"x NumPy: {tof['x_numpy_1']:.1f} (1 thread), {tof['x_numpy_all']:.1f} "
                 f"({tof['workers']} threads) vs >= {tof['target_x_numpy']:g}: "
                 + ((("met" if tof["target_met"] else "NOT met")) if verdict else
                    "no verdict (not the target frame)") + "; ")
    lines.append(f"  {ratio}C and NumPy agree: wrap counts "
                 f"{'identical' if a['wraps_equal'] else 'DIFFER'}, max |depth diff| "
                 f"{a['max_abs_depth_diff_m']:.1e} m, max |phase diff| "
                 f"{a['max_abs_phase_diff_rad']:.1e} rad")
    return "\n".join(lines)


def format_chain(ch):
    """The colour-chain section: seconds per stage."""
    lines = [f"colour chain: ColourISP on a {ch['frame_shape'][0]}x{ch['frame_shape'][1]} "
             f"{ch['pattern']} frame ({ch['reconstruction']} {ch['precision']}, "
             f"{ch['demosaic']}, {ch['workers']} threads), median of {ch['repeat']} runs: "
             f"{ch['total_s']:.3f} s in all"]
    for k, v in ch["stages_s"].items():
        lines.append(f"  {k:<18} {v:.3f} s  {100 * v / ch['total_s']:5.1f} %")
    return "\n".join(lines)


def _load(v):
    return "n/a" if v is None else "/".join(f"{x:.2f}" for x in v)


def _parse_shape(s):
    h, w = parse_shape(s)
    if w < 24 or h < 24 or w % 4 or h % 12:
        raise CliError(f"--shape: rows must be a multiple of 12 and columns of 4 (the pattern "
                       f"periods), both >= 24; got {s!r}")
    return (h, w)


def main(argv=None):
    """``rgbz-fast bench``."""
    p = common_parser("rgbz-fast bench", __doc__)
    p.add_argument("--repeat", type=int, default=None, help="timed runs per case (default 5, "
                   "--quick 3)")
    p.add_argument("--shape", default=None, help="frame size ROWSxCOLS (default 3000x4000, "
                   "with --quick 192x256)")
    p.add_argument("--kernels", default=None,
                   help="comma-separated substrings; run only the cases whose label "
                        "('reconstruct sg mask1 float32', 'demosaic', 'tof') contains one; "
                        "the ToF section runs when one is a substring of 'tof sites' "
                        "('tof sites' alone: that section only) (default: every case)")
    p.add_argument("--no-reference", action="store_true",
                   help="skip the NumPy and colour-demosaicing baselines")
    p.add_argument("--numpy-reference", default=None, metavar="FILE",
                   help="also time the slow NumPy reference of the reconstruction: a Python "
                        "file defining reference_reconstruct, such as the test suite's "
                        "(default: none)")
    p.add_argument("--no-memory", action="store_true", help="skip the peak-memory subprocess")
    p.add_argument("--no-tof-sites", action="store_true",
                   help="skip the ToF section (C vs NumPy in M measurements/s)")
    p.add_argument("--chain", action="store_true",
                   help="also time the colour ISP chain stage by stage")

    def body(args):
        shape = _parse_shape(args.shape) if args.shape else (QUICK_SHAPE if args.quick
                                                             else FULL_SHAPE)
        repeat = args.repeat if args.repeat is not None else (3 if args.quick else 5)
        if repeat < 1:
            raise CliError(f"--repeat: expected a positive integer, got {repeat}")
        workers = check_workers_arg(args.workers)
        out = check_out_dir(args.out)
        kernels = [k.strip() for k in args.kernels.split(",")] if args.kernels else None
        crop = (48, 64) if args.quick else (240, 320)
        crop = (min(crop[0], shape[0]), min(crop[1], shape[1]))
        numpy_ref = (load_numpy_reference(args.numpy_reference)
                     if args.numpy_reference and not args.no_reference else None)
        res = run_benchmarks(shape, repeat, workers, crop, kernels, not args.no_reference,
                             not args.no_memory, args.quiet, not args.no_tof_sites, args.chain,
                             numpy_reference=numpy_ref, quick=args.quick)
        if not res["results"] and res["tof_sites"] is None:
            raise CliError(f"--kernels: no case matches {args.kernels!r}")
        res["command"] = "rgbz-fast bench " + " ".join(sys.argv[1:] if argv is None else argv)
        table = format_table(res)
        if out is not None:
            write_json(res, out / "bench.json")
            (out / "bench.txt").write_text(table + "\n", encoding="utf-8")
        print(write_json(res) if args.json else table)
        return 0

    return run_main(p, body, argv)


if __name__ == "__main__":
    sys.exit(main())
