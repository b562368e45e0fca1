"""The metric kernels beside their NumPy references: agreement on a dataset, speed side by side.

    python tools/metrics_vs_reference.py --dataset ../shared/data/kodak [--limit N]
        [--repeat 7] [--json FILE]

Needs a source checkout (the references are tests/_reference/metrics.py, the former
NumPy/SciPy/colour-science code of rgbz_fast.metrics) and colour-science.

Agreement: for every image and every (pattern, method) of the default
evaluation (Mask1 and Mask2; bilinear, BI, EDICentral, EDILine, SG), the
reference and RGB-Z 8-bit sRGB images of ``rgbz-fast evaluate``'s colour chain
are scored by the library (C kernels) and by the references, with evaluate's
8-pixel crop: the largest relative difference of CFA PSNR, CPSNR, SSIM and
MS-SSIM, whether every zipper percentage is identical (and, where one is not,
the pixels whose |psi| > delta decision differs), and the largest |L*a*b*|
difference of the CIELAB conversion against colour-science.

Speed: on the first image's Mask1 SG pair, every metric timed in turn (C with
1 thread, C with all threads, reference) by the tools' one timing loop
(``rgbz_fast._devtools.timing.interleaved``: one warm-up call each, then
``--repeat`` rounds), the median of the rounds; the speedup is reference / C,
same run.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import sys
from pathlib import Path

import numpy as np

import rgbz_fast as rz
from rgbz_fast import metrics
from rgbz_fast._devtools.timing import WARMUP_CALLS, interleaved
from rgbz_fast.evaluation import EvalConfig, image_frames
from rgbz_fast.io import atomic_write, folder_dataset

REPO = Path(__file__).resolve().parents[1]
CROP = 8


def load_reference():
    path = REPO / "tests" / "_reference" / "metrics.py"
    spec = importlib.util.spec_from_file_location("_rgbz_metrics_reference", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def pairs(source, config):
    """Yield (pattern, method, ref CFA, test CFA, Z mask, ref sRGB, test sRGB) of one image."""
    img = source.load()
    chain = config.colour_isp()
    for pattern in config.patterns:
        frame, ref_cfa = image_frames(img, pattern, config)
        phase, bd = frame.pattern.bayer_phase, frame.bit_depth
        ref8, st = chain.render(ref_cfa, phase, bit_depth=bd, return_stages=True)
        for method in config.methods:
            out = rz.reconstruct(frame, method, params=config.params)
            test8 = chain.render(out, phase, bit_depth=bd, gains=st["gains"])
            yield pattern, method, ref_cfa, out, frame.z_mask, ref8, test8


def _rel(a, b):
    return abs(a - b) / abs(b) if b else abs(a - b)


def agreement(sources, ref, config):
    worst = {k: 0.0 for k in ("cfa_psnr", "cpsnr", "ssim", "ms_ssim")}
    zipper_pairs = zipper_equal = 0
    lab_max = 0.0
    differing = []
    for source in sources:
        for pattern, method, rcfa, tcfa, z, r8, t8 in pairs(source, config):
            bd = config.bit_depth
            peak = float(2 ** bd - 1)
            want = {"cfa_psnr": 10 * np.log10(peak ** 2 / ref.mse(rcfa, tcfa, z)),
                    "cpsnr": 10 * np.log10(255.0 ** 2 / ref.mse(r8[CROP:-CROP, CROP:-CROP],
                                                                t8[CROP:-CROP, CROP:-CROP])),
                    "ssim": ref.ssim(r8, t8, crop=CROP), "ms_ssim": ref.ms_ssim(r8, t8, crop=CROP)}
            got = {"cfa_psnr": metrics.cfa_psnr(rcfa, tcfa, z, bit_depth=bd),
                   "cpsnr": metrics.cpsnr(r8, t8, crop=CROP),
                   "ssim": metrics.ssim(r8, t8, crop=CROP),
                   "ms_ssim": metrics.ms_ssim(r8, t8, crop=CROP)}
            for k in worst:
                worst[k] = max(worst[k], _rel(got[k], want[k]))
            rc, tc = r8[CROP:-CROP, CROP:-CROP], t8[CROP:-CROP, CROP:-CROP]
            lab_r, lab_t = ref.to_lab(rc, 255.0), ref.to_lab(tc, 255.0)
            lab_max = max(lab_max, float(np.abs(metrics._zipper._to_lab(rc, "srgb8", 0)
                                                - lab_r).max()),
                          float(np.abs(metrics._zipper._to_lab(tc, "srgb8", 0) - lab_t).max()))
            z_ref = ref.zipper_lab(lab_r, lab_t, 2.3)
            z_c = metrics.zipper(r8, t8, crop=CROP)
            zipper_pairs += 1
            if z_c == z_ref:
                zipper_equal += 1
            else:
                # the pixels where the kernel's Lab (fed to the reference search) decides
                # otherwise than colour's
                flags_ref = ref.zipper_map(lab_r, lab_t, 2.3)[0]
                flags_c = ref.zipper_map(metrics._zipper._to_lab(rc, "srgb8", 0),
                                         metrics._zipper._to_lab(tc, "srgb8", 0), 2.3)[0]
                differing.append(dict(image=source.name, pattern=pattern, method=method,
                                      zipper_c=z_c, zipper_reference=z_ref,
                                      pixels=np.argwhere(flags_ref != flags_c).tolist()))
            print(f"  {source.name} {pattern} {method}: zipper {z_c:.4f} "
                  f"{'=' if z_c == z_ref else '!='} {z_ref:.4f}", file=sys.stderr, flush=True)
    return dict(max_relative_difference=worst, zipper_pairs=zipper_pairs,
                zipper_identical=zipper_equal, zipper_differing=differing,
                lab_max_abs_difference=lab_max)


def speed(source, ref, config, repeat):
    _, _, rcfa, tcfa, z, r8, t8 = next(p for p in pairs(source, config)
                                       if p[0] == "mask1" and p[1] == "sg")
    bd = config.bit_depth
    cases = {
        "cfa_psnr": (lambda w: metrics.cfa_psnr(rcfa, tcfa, z, bit_depth=bd, workers=w),
                     lambda: ref.mse(rcfa, tcfa, z)),
        "cpsnr": (lambda w: metrics.cpsnr(r8, t8, crop=CROP, workers=w),
                  lambda: ref.mse(r8[CROP:-CROP, CROP:-CROP], t8[CROP:-CROP, CROP:-CROP])),
        "ssim": (lambda w: metrics.ssim(r8, t8, crop=CROP, workers=w),
                 lambda: ref.ssim(r8, t8, crop=CROP)),
        "ms_ssim": (lambda w: metrics.ms_ssim(r8, t8, crop=CROP, workers=w),
                    lambda: ref.ms_ssim(r8, t8, crop=CROP)),
        "zipper": (lambda w: metrics.zipper(r8, t8, crop=CROP, workers=w),
                   lambda: ref.zipper(r8, t8, crop=CROP)),
        "all_metrics (SSIM shared with MS-SSIM)": (
            lambda w: metrics.all_metrics(r8, t8, crop=CROP, workers=w),
            lambda: (ref.mse(r8, t8), ref.ssim(r8, t8, crop=CROP),
                     ref.ms_ssim(r8, t8, crop=CROP), ref.zipper(r8, t8, crop=CROP))),
    }
    allw = os.cpu_count() or 1
    out = {}
    for name, (c, r) in cases.items():
        times = interleaved({"c_1": lambda: c(1), "c_all": lambda: c(allw), "reference": r},
                            repeat)
        med = {k: float(np.median(v)) for k, v in times.items()}
        out[name] = dict(median_s=med, x_reference_1=med["reference"] / med["c_1"],
                         x_reference_all=med["reference"] / med["c_all"])
    return dict(image=source.name, pair="mask1 sg", shape=list(r8.shape), repeat=repeat,
                warmup_calls=WARMUP_CALLS, threads_all=allw,
                metrics_isa=rz._kernels.metrics_isa(), cases=out)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--dataset", default=str(REPO.parent / "shared" / "data" / "kodak"))
    p.add_argument("--limit", type=int, default=None)
    p.add_argument("--repeat", type=int, default=7)
    p.add_argument("--json", default=None, help="also write the results to this file")
    p.add_argument("--no-agreement", action="store_true")
    args = p.parse_args(argv)
    ref = load_reference()
    sources = folder_dataset(args.dataset, args.limit)
    config = EvalConfig()
    load0 = os.getloadavg()
    res = {"command": "python tools/metrics_vs_reference.py "
                      + " ".join(sys.argv[1:] if argv is None else argv),
           "images": len(sources), "loadavg_before": load0}
    res["speed"] = speed(sources[0], ref, config, args.repeat)
    if not args.no_agreement:
        res["agreement"] = agreement(sources, ref, config)
    res["loadavg_after"] = os.getloadavg()
    s = res["speed"]
    print(f"speed on {s['image']} ({s['pair']}, {s['shape'][1]}x{s['shape'][0]}), median of "
          f"{s['repeat']} rounds after {s['warmup_calls']} warm-up, kernels on "
          f"{s['metrics_isa']}; load {load0[0]:.1f} -> {res['loadavg_after'][0]:.1f}")
    print(f"{'metric':42s} {'reference':>10s} {'C 1 thr':>9s} {'C all':>9s} {'x1':>7s} "
          f"{'xall':>7s}")
    for name, c in s["cases"].items():
        m = c["median_s"]
        print(f"{name:42s} {m['reference'] * 1e3:8.1f}ms {m['c_1'] * 1e3:7.2f}ms "
              f"{m['c_all'] * 1e3:7.2f}ms {c['x_reference_1']:7.1f} {c['x_reference_all']:7.1f}")
    if "agreement" in res:
        a = res["agreement"]
        print(f"agreement over {a['zipper_pairs']} image pairs: max relative difference "
              + ", ".join(f"{k} {v:.1e}" for k, v in a["max_relative_difference"].items())
              + f"; zipper identical in {a['zipper_identical']}/{a['zipper_pairs']}; "
              f"max |Lab difference| {a['lab_max_abs_difference']:.1e}")
        for d in a["zipper_differing"]:
            print(f"  zipper differs: {d['image']} {d['pattern']} {d['method']}: "
                  f"{d['zipper_c']} vs {d['zipper_reference']}, pixels {d['pixels'][:10]}")
    if args.json:
        atomic_write(args.json, json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
