"""The engine of ``rgbz-fast bench``: the speed of every C kernel beside OpenCV and NumPy.

:func:`run_benchmarks` times the cases of :mod:`.cases` (each reconstruction
method x pattern x precision, the Malvar 2004 demosaic, ToF demodulation and
unwrapping) on the benchmark frame with 1 thread and all threads, each timed
call alternated with OpenCV's Bayer demosaics (:mod:`rgbz_fast._devtools.timing`),
plus the ToF section, the colour chain and the peak memory when asked; the
result is a JSON-able dict that :func:`format_table` (:mod:`.report`) prints.

Invariants of the numbers:

* every case is called once untimed before its timed calls, and the result
  records the count (``warmup_calls``);
* "all threads" is the thread count the library really uses on that frame
  (a pixel kernel takes at most one thread per 2**18 pixels);
* a quick run gives speeds only: no ratio and no target verdict; verdicts
  also need the target frame (:data:`FULL_SHAPE`).
"""

from __future__ import annotations

import os

import numpy as np

from ..._validate import kernel_threads
from .._common import machine_info, progress
from ..timing import WARMUP_CALLS, interleaved, rate_stats, ratio, timed
from .cases import (FULL_SHAPE, TOF_TARGET_X_NUMPY, OpenCVThreads, build_cases, case_label,
                    colour_chain_benchmark, load_numpy_reference, make_rgb, opencv_calls,
                    opencv_speeds, simulate_benchmark, tof_isp_benchmark, tof_sites_benchmark)
from .memory import measure_memory
from .report import (QUICK_NOTE, format_chain, format_simulate, format_table, format_tof,
                     format_tof_isp)

__all__ = ["run_benchmarks", "NoCase", "check_shape", "format_table", "format_tof", "format_chain",
           "format_simulate", "format_tof_isp", "load_numpy_reference", "make_rgb", "measure_memory",
           "tof_sites_benchmark", "colour_chain_benchmark", "simulate_benchmark",
           "tof_isp_benchmark",
           "FULL_SHAPE", "QUICK_SHAPE", "TARGET_SG_MPIX",
           "QUICK_NOTE"]

QUICK_SHAPE = (192, 256)
#: the target of SG on Mask1, float32, all threads, on the target frame
TARGET_SG_MPIX = 150.0


def check_shape(shape, name="shape"):
    """``shape`` (rows, cols) when every pattern tiles it, else a ValueError naming ``name``."""
    h, w = shape
    if w < 24 or h < 24 or w % 4 or h % 12:
        raise ValueError(f"{name}: rows must be a multiple of 12 and columns of 4 (the pattern "
                         f"periods), both >= 24; got {h}x{w}")
    return (h, w)


class NoCase(ValueError):
    """``kernels`` matches no case of :func:`run_benchmarks` (raised before anything runs)."""

    def __init__(self, kernels):
        super().__init__(f"kernels: no case matches {','.join(kernels)!r}")


def run_benchmarks(shape=FULL_SHAPE, repeat=5, workers=None, ref_crop=(240, 320), kernels=None,
                   reference=True, memory=True, quiet=True, tof_sites=True, chain=False,
                   numpy_reference=None, quick=False):
    """Run every benchmark; returns the JSON-able result dict.

    ``kernels``: substrings; only the cases whose label (:func:`.cases.case_label`)
    holds one run. ``reference``: time the NumPy and colour-demosaicing baselines.
    ``numpy_reference``: the module of :func:`load_numpy_reference` (the tests'
    slow reconstruction reference), timed beside the C kernels; None: not timed.
    ``tof_sites``: the ToF section (C vs NumPy, M measurements/s); it runs unless
    ``kernels`` is given and none of its entries occurs in ``"tof sites"``.
    ``chain``: the colour ISP stage by stage, :func:`rgbz_fast.simulate` of the frame
    with a depth map (noise-free and noisy, Mask1 and Mask2), and the ToF ISP on the
    simulated Mask1 frame (guided, unguided, ``upsample_depth``). ``quick``: a smoke test, the speeds
    only: no ratio (``vs_numpy``, ``vs_opencv_*``, the ToF ``x_numpy_*``) and no
    target verdict (``targets`` is empty).
    """
    workers = workers or (os.cpu_count() or 1)
    npix = shape[0] * shape[1]
    load0 = os.getloadavg() if hasattr(os, "getloadavg") else None
    cases, frame = build_cases(shape, ref_crop, numpy_reference)
    tof_asked = tof_sites and (not kernels or any(k in "tof sites" for k in kernels))
    if kernels:
        labels = [case_label(c[0], c[1]) for c in cases]
        # every entry must match something: one that matches nothing beside one that does
        # had been dropped without a word (a typo such as 'edi_centrl')
        unmatched = [k for k in kernels
                     if not any(k in label for label in labels) and k not in "tof sites"]
        if unmatched:
            raise NoCase(unmatched)
        cases = [c for c, label in zip(cases, labels) if any(k in label for k in kernels)]
        if not cases and not tof_asked:
            raise NoCase(kernels)
    # 'tof sites' alone: that section only (not OpenCV's speeds nor the peak memory of SG)
    kernels_only = bool(kernels) and not cases
    results = []
    vs = (lambda a, b: None) if quick else ratio
    cv = opencv_calls(frame) if not quick else None
    for name, meta, build in progress(cases, desc="bench", quiet=quiet):
        fn, ref_fn, ref_pix = build()
        threads, paired = {}, {}
        for label, n in (("1", 1), ("all", workers)):
            # our call and OpenCV's alternated round by round: a change of the machine's
            # load hits both, and the ratio is the median of the rounds' ratios
            with OpenCVThreads(cv and cv[0], n):
                t = interleaved({"ours": lambda: fn(n), **(cv[1] if cv else {})}, repeat)
            ours = t.pop("ours")
            threads[label] = rate_stats(ours, npix)
            for key, theirs in t.items():
                rounds = theirs / ours
                paired[f"vs_opencv_{key}_{label}"] = float(np.median(rounds))
                # the spread of the rounds' ratios: how far one run's median can be trusted
                paired[f"vs_opencv_{key}_{label}_iqr"] = [
                    float(q) for q in np.percentile(rounds, [25, 75])]
        # the threads the call really runs: pixel kernels take one per 2**18 pixels at most
        threads["all"]["threads"] = (kernel_threads(workers, npix) if meta["kernel"] in
                                     ("reconstruct", "demosaic") else workers)
        threads["1"]["threads"] = 1
        ref_mpix = None
        if reference and ref_fn is not None:
            ref_mpix = rate_stats(timed(ref_fn, max(1, min(repeat, 3))), ref_pix)["mpix_s"]
        results.append(dict(name=name, **meta, threads=threads, numpy_ref_mpix_s=ref_mpix,
                            vs_numpy=vs(threads["1"]["mpix_s"], ref_mpix), **paired))
    ocv = None if kernels_only else opencv_speeds(frame, repeat, workers, npix)
    for r in results:
        for key in ("bilinear", "ea"):
            for label in ("1", "all"):
                r.setdefault(f"vs_opencv_{key}_{label}", None)
                r.setdefault(f"vs_opencv_{key}_{label}_iqr", None)
    tof = None
    if tof_asked:
        tof = tof_sites_benchmark(shape, repeat, workers, verdict=not quick)
    colour = colour_chain_benchmark(shape, repeat, workers) if chain else None
    sim = simulate_benchmark(shape, repeat, workers, verdict=not quick and tuple(shape) ==
                             FULL_SHAPE) if chain else None
    tof_isp = tof_isp_benchmark(shape, repeat, workers, verdict=not quick and tuple(shape) ==
                                FULL_SHAPE) if chain else None
    mem = measure_memory(frame("mask1").data, "mask1", "sg", "float32", workers) \
        if memory and not kernels_only else None
    verdict = not quick and tuple(shape) == FULL_SHAPE
    return {
        "machine": dict(machine_info(), loadavg_before=load0,
                        loadavg_after=os.getloadavg() if hasattr(os, "getloadavg") else None),
        "frame": {"shape": list(shape), "pixels": npix, "dtype": "uint16", "bit_depth": 11,
                  "source": "skimage.data.astronaut, mirrored and tiled"},
        "quick": bool(quick), "verdict": verdict, "target_frame": list(FULL_SHAPE),
        "repeat": repeat, "warmup_calls": WARMUP_CALLS, "workers_all": workers,
        "numpy_reference": {"available": numpy_reference is not None and reference,
                            "crop": [ref_crop[0] // 12 * 12, ref_crop[1] // 4 * 4]},
        "results": results, "opencv": ocv, "tof_sites": tof, "colour_chain": colour,
        "simulate": sim, "tof_isp": tof_isp,
        "memory": mem, "targets": {} if quick else _targets(results, ocv, tof, mem, verdict),
    }


def _targets(results, ocv, tof, mem, verdict):
    """The figures the targets are defined on, and whether they are met (None: no verdict)."""
    targets = {}
    sg = next((r for r in results if r["kernel"] == "reconstruct" and r["method"] == "sg"
               and r["pattern"] == "mask1" and r["precision"] == "float32"
               and r["exp"] == "auto"), None)
    if sg is not None:
        v = sg["threads"]["all"]["mpix_s"]
        targets["sg_mask1_float32_all_threads_mpix_s"] = v
        targets["target_mpix_s"] = TARGET_SG_MPIX
        targets["target_met"] = bool(v >= TARGET_SG_MPIX) if verdict else None
        if ocv is not None and sg.get("vs_opencv_ea_all") is not None:
            targets["opencv_ea_all_threads_mpix_s"] = ocv["ea"]["all"]["mpix_s"]
            targets["fraction_of_opencv_ea"] = sg["vs_opencv_ea_all"]
            targets["fraction_of_opencv_ea_iqr"] = sg["vs_opencv_ea_all_iqr"]
    if tof is not None:
        targets["tof_x_numpy_all_threads"] = tof["x_numpy_all"]
        targets["tof_target_x_numpy"] = TOF_TARGET_X_NUMPY
        targets["tof_target_met"] = tof["target_met"] if verdict else None
    if mem and "array" in mem:
        targets["peak_memory_within_budget"] = {k: mem[k]["within_budget"]
                                                for k in ("array", "rawframe")}
    return targets
