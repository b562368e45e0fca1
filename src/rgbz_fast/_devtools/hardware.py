"""``rgbz-fast hardware``: the fixed-point model's cost and its error against float64.

For one method and pattern: the silicon of :func:`rgbz_fast.hardware.hardware_cost`
(line buffers and BRAM_18K, window, latency, operators by width, tables,
register widths), the error of ``precision="fixed"`` against ``precision="float64"``
on a dataset (by default the images ``rgbz-fast evaluate`` uses with no
``--dataset``) under two protocols -- ``linear``, evaluate's default (sRGB
linearised, noise-free 11-bit mosaics) and ``srgb``, the 8-bit sRGB values
mosaicked at 11 bits as they are (``rz.mosaic(img8, pattern)``) --: the change
of the mean CFA PSNR and the histogram of the differences (LSB) at the Z
sites; and the fixed model's operations per site beside Table 1 and the float
core's counts. :func:`run_sweep` varies the widths and table sizes around a
configuration and gives quality against cost and its Pareto front.

No argparse here: the command line (``rgbz-fast hardware``) parses and calls.
"""

from __future__ import annotations

import threading
import time

import numpy as np

from .. import metrics
from .._patterns import get_pattern
from .._threads import check_workers, map_in_order
from ..evaluation import EvalConfig
from ..evaluation._run import image_frames
from ..hardware import FixedPointConfig, hardware_cost
from ..io import folder_dataset, sample_dataset
from ..reconstruction import ReconstructParams, reconstruct

__all__ = ["PROTOCOLS", "TARGET", "load_images", "prepare_cases", "measure_error",
           "meets_target", "hardware_report", "sweep_configs", "run_sweep", "pareto_front",
           "format_report", "format_sweep"]

#: the two protocols of the error: evaluate's default and the 8-bit sRGB values at 11 bits
PROTOCOLS = {"linear": EvalConfig(), "srgb": EvalConfig(linearise=False)}
#: what the default configuration meets against float64 on every method, mask and protocol
TARGET = {"dpsnr_db": 0.05, "within_1lsb_pct": 99.9}
#: the histogram's bins of fixed - float64 (DN): <= -4, -3 .. 3, >= 4
HIST_BINS = ("<=-4", "-3", "-2", "-1", "0", "1", "2", "3", ">=4")


def load_images(dataset=None, limit=None, *, max_pixels=None, max_bytes=None):
    """[(name, RGB array)] of a folder of images, or the scikit-image samples (None);
    ``max_pixels``, ``max_bytes``: the read limits of every file."""
    sources = sample_dataset() if dataset is None else folder_dataset(
        dataset, limit, max_pixels=max_pixels, max_bytes=max_bytes)
    if dataset is None and limit:
        sources = sources[:limit]
    return [(s.name, s.load()) for s in sources]


def prepare_cases(images, pattern, method, protocols=tuple(PROTOCOLS), params=None):
    """Per image and protocol: (protocol, name, frame, reference CFA, float64 CFA)."""
    params = ReconstructParams.build(params)
    cases = []
    for proto in protocols:
        ec = PROTOCOLS[proto]
        for name, img in images:
            frame, ref = image_frames(img, pattern, ec)
            exact = reconstruct(frame, method, params=params.replace(precision="float64"))
            cases.append((proto, name, frame, ref, exact))
    return cases


def measure_error(cases, method, config, params=None, workers=1):
    """The fixed model against float64 on prepared cases, per protocol; the cases on
    ``workers`` threads (None: every core; the result does not depend on it).

    Returns {protocol: {"images", "sites", "exact_images", "psnr_float", "psnr_fixed",
    "dpsnr_mean", "dpsnr_max_abs", "within_1lsb_pct", "max_abs_lsb", "hist"}}: PSNRs are
    means of the per-image CFA PSNR at the Z sites (as evaluate reports them) over the
    images where both are finite, dpsnr the fixed minus the float64 value (0 on the
    ``exact_images``, which both reconstruct exactly: PSNR +inf twice), the histogram
    counts Z sites by fixed - float64.
    """
    params = ReconstructParams.build(params).replace(precision="fixed", fixed_point=config)

    def one(case):
        proto, name, frame, ref, exact = case
        fixed = reconstruct(frame, method, params=params)
        z = frame.z_mask
        pf = metrics.cfa_psnr(ref, exact, z, bit_depth=frame.bit_depth, workers=1)
        px = metrics.cfa_psnr(ref, fixed, z, bit_depth=frame.bit_depth, workers=1)
        return proto, pf, px, fixed[z].astype(np.int64) - exact[z].astype(np.int64)

    acc = {}
    for proto, pf, px, d in map_in_order(one, cases, check_workers(workers)):
        a = acc.setdefault(proto, {"pf": [], "px": [], "n": 0, "within": 0, "max": 0,
                                   "hist": np.zeros(len(HIST_BINS), np.int64)})
        a["pf"].append(pf)
        a["px"].append(px)
        a["n"] += d.size
        a["within"] += int(np.count_nonzero(np.abs(d) <= 1))
        a["max"] = max(a["max"], int(np.abs(d).max()) if d.size else 0)
        a["hist"] += np.bincount(np.clip(d, -4, 4) + 4, minlength=len(HIST_BINS))
    out = {}
    for proto, a in acc.items():
        pf, px = np.array(a["pf"]), np.array(a["px"])
        # an image both reconstruct exactly at every Z site (a flat one: PSNR +inf twice) has
        # not changed; inf - inf had made every mean NaN and the verdict a miss
        exact = np.isposinf(pf) & np.isposinf(px)
        with np.errstate(invalid="ignore"):
            dp = np.where(exact, 0.0, px - pf)
        both = np.isfinite(pf) & np.isfinite(px)
        out[proto] = {
            "images": len(a["pf"]), "sites": a["n"], "exact_images": int(exact.sum()),
            "psnr_float": float(pf[both].mean()) if both.any() else float(pf.mean()),
            "psnr_fixed": float(px[both].mean()) if both.any() else float(px.mean()),
            "dpsnr_mean": float(dp.mean()), "dpsnr_max_abs": float(np.abs(dp).max()),
            "within_1lsb_pct": 100.0 * a["within"] / max(a["n"], 1),
            "max_abs_lsb": a["max"], "hist": dict(zip(HIST_BINS, a["hist"].tolist())),
        }
    return out


def meets_target(error, target=TARGET):
    """True if every protocol's mean PSNR change and share within 1 LSB meet ``target``."""
    return all(abs(e["dpsnr_mean"]) <= target["dpsnr_db"]
               and e["within_1lsb_pct"] >= target["within_1lsb_pct"] for e in error.values())


def _float_opcounts(pattern, method):
    """The float core's mean operations per site ({group: {category: mean}}) and Table 1's."""
    from . import opcount
    counts = opcount.count_operations(method, pattern, precision="float64", shape=(32, 32))
    # Table 1 knows the presets on any Bayer phase by their name (mask1_rggb is Mask1)
    table1 = {g: opcount.TABLE1.get((method, opcount._table1_name(get_pattern(pattern)), g))
              for g in counts}
    return ({g: {k: round(v["mean"][k], 2) for k in ("add", "mul", "div", "exp", "abs", "cmp")}
             for g, v in counts.items()}, table1)


def hardware_report(method="sg", pattern="mask1", *, width=4000, images=None, params=None,
                    config=None, protocols=tuple(PROTOCOLS), bit_depth=11, workers=None):
    """Cost, error and operation counts of one configuration: a dict (see the module doc);
    the frames on ``workers`` threads (None: every core)."""
    params = ReconstructParams.build(params)
    pattern = get_pattern(pattern)
    config = FixedPointConfig.build(config if config is not None else params.fixed_point)
    cost = hardware_cost(pattern, method, width=width, bit_depth=bit_depth, params=params,
                         fixed_point=config)
    t0 = time.perf_counter()
    images = load_images() if images is None else images
    cases = prepare_cases(images, pattern, method, protocols, params)
    error = measure_error(cases, method, config, params, workers)
    fl, t1 = _float_opcounts(pattern, method)
    return {"method": method, "pattern": pattern.name, "cost": cost.as_dict(),
            "error": error, "target": TARGET, "meets_target": meets_target(error),
            "images": [n for n, _ in images],
            "opcounts": {"fixed": cost.ops, "float64": fl, "table1": t1},
            "seconds": round(time.perf_counter() - t0, 1)}


# -- the sweep ---------------------------------------------------------------------------------

#: how each field moves in the sweep, one at a time around the base: bits added to a width,
#: factors of a table size
SWEEP = {
    "weight_bits": (-3, -1, 1, 3),
    "recip_bits": (-3, -1, 1, 3),
    "exp_bits": (-3, -1, 1, 3),
    "ratio_bits": (-3, -1, 1, 3),
    "alpha_bits": (-3, -1, 1, 3),
    "exp_range_bits": (-2, -1, 1),
    "sigma_bits": (-2, 4),
    "recip_table_size": (0.25, 0.5, 2, 4),
    "exp_table_size": (0.25, 0.5, 2, 4),
}
#: the same for the fields of the learned filters' model
SWEEP_LEARNED = {
    "tap_bits": (-4, -2, -1, 1, 2),
    "hash_bits": (-6, -3, -1, 2),
    "hash_const_bits": (-6, -3, -1, 2),
    "hash_norm_bits": (-6, -3, -1, 2),
}


def sweep_configs(base, method="sg"):
    """The base configuration, each field of SWEEP (``method="learned"``: SWEEP_LEARNED) moved
    alone (values a field cannot take are left out), the other table modes, and every width
    narrowed and widened by 2 bits together: [(label, config)]. Only the fields that reach
    the method's datapath (:data:`rgbz_fast.hardware.FIELDS_USED`) move: bilinear's sweep is
    its default alone."""
    from ..hardware import FIELDS_USED

    used = set(FIELDS_USED.get(method, FIELDS_USED["sg"]))
    out = [("default", base)]
    if method == "learned":
        for field, steps in SWEEP_LEARNED.items():
            for step in steps:
                try:
                    out.append((f"{field}={getattr(base, field) + step}",
                                base.replace(**{field: getattr(base, field) + step})))
                except ValueError:
                    continue
        for step in (-2, 2):
            try:
                out.append((f"every width {step:+d}", base.replace(
                    **{f: getattr(base, f) + step for f in SWEEP_LEARNED})))
            except ValueError:
                continue
        return out
    for field, steps in SWEEP.items():
        if field not in used:          # a field the method's datapath does not take
            continue
        for step in steps:
            cur = getattr(base, field)
            v = int(cur * step) if field.endswith("_table_size") else cur + step
            try:
                out.append((f"{field}={v}", base.replace(**{field: v})))
            except ValueError:
                continue
    for e in ("table", "pwl") if "exp" in used else (base.exp,):
        for r in ("table", "pwl") if "recip" in used else (base.recip,):
            if (e, r) != (base.exp, base.recip):
                out.append((f"exp={e}, recip={r}" if "exp" in used else f"recip={r}",
                            base.replace(exp=e, recip=r)))
    widths = [f for f in ("exp_bits", "recip_bits", "ratio_bits", "alpha_bits", "weight_bits")
              if f in used]
    if not widths:
        return out
    for step in (-2, 2):
        try:
            out.append((f"every width {step:+d}", base.replace(
                **{f: getattr(base, f) + step for f in widths})))
        except ValueError:
            continue
    return out


def run_sweep(method="sg", pattern="mask1", *, width=4000, images=None, params=None,
              base=None, protocols=tuple(PROTOCOLS), bit_depth=11, configs=None, tick=None,
              workers=None):
    """Quality against cost of :func:`sweep_configs`: rows of label, config, bits and error;
    the configurations on ``workers`` threads (None: every core; the rows do not depend on
    it), ``tick()`` after each."""
    params = ReconstructParams.build(params)
    base = FixedPointConfig.build(base if base is not None else params.fixed_point)
    images = load_images() if images is None else images
    cases = prepare_cases(images, pattern, method, protocols, params)
    lock = threading.Lock()

    def row(item):
        out = _row(*item)
        if tick:
            with lock:
                tick()
        return out

    def _row(label, cfg):
        try:
            cost = hardware_cost(pattern, method, width=width, bit_depth=bit_depth,
                                 params=params, fixed_point=cfg)
        except ValueError as exc:          # a width no register of this plan can hold
            return {"label": label, "config": cfg.as_dict(), "refused": str(exc)}
        err = measure_error(cases, method, cfg, params)
        return {
            "label": label, "config": cfg.as_dict(),
            "bits": {"tables": cost.table_bits, "datapath": cost.datapath_bits,
                     "line_buffers": cost.line_buffer_bits, "total": cost.total_bits},
            "dsp48": cost.dsp48(),
            "within_1lsb_pct": min(e["within_1lsb_pct"] for e in err.values()),
            "dpsnr_max_abs": max(abs(e["dpsnr_mean"]) for e in err.values()),
            "max_abs_lsb": max(e["max_abs_lsb"] for e in err.values()),
            "meets_target": meets_target(err), "error": err}

    rows = map_in_order(row, configs or sweep_configs(base, method), check_workers(workers))
    front = pareto_front(rows)
    for r in rows:
        r["pareto"] = r.get("label") in front
    return rows


def pareto_front(rows):
    """Labels of the rows no other row beats in both cost (table + datapath bits) and the share
    of Z sites within 1 LSB."""
    ok = [r for r in rows if "bits" in r]
    front, seen = [], set()
    for r in ok:
        c, q = r["bits"]["tables"] + r["bits"]["datapath"], r["within_1lsb_pct"]
        if (c, q) in seen:               # the same point again (a field this method ignores)
            continue
        if not any((o["bits"]["tables"] + o["bits"]["datapath"] <= c and o["within_1lsb_pct"] >= q)
                   and (o["bits"]["tables"] + o["bits"]["datapath"] < c
                        or o["within_1lsb_pct"] > q) for o in ok):
            front.append(r["label"])
            seen.add((c, q))
    return front


# -- text -------------------------------------------------------------------------------------

def _mults(d):
    return ", ".join(f"{n} x ({k})" for k, n in d.items()) or "none"


def format_report(rep):
    """Markdown of :func:`hardware_report`."""
    c = rep["cost"]
    lb, lat = c["line_buffers"], c["latency"]
    lines = [f"## {rep['method']} on {rep['pattern']}: {c['width']} pixels wide, "
             f"{c['bit_depth']} bits", "",
             "| resource | value |", "|---|---|",
             f"| line buffers | {lb['count']} x {lb['width']} x {lb['bits_per_pixel']} bits = "
             f"{lb['bits']} bits, {lb['bram18']} BRAM_18K |",
             f"| window registers | {c['window']['rows']} x {c['window']['columns']} x "
             f"{c['bit_depth']} bits |",
             f"| latency | {lat['rows']} rows + {lat['pixels']} pixels + the pipeline "
             f"({lat['datapath_depth']} operations on the longest path) |",
             f"| pixels per clock | {c['pixels_per_clock']} |",
             f"| multipliers (a x b bits) | {_mults(c['multipliers'])}; about {c['dsp48']} "
             f"DSP48E2 |",
             f"| constant multipliers | {_mults(c['constant_multipliers'])} |",
             f"| adders (width: count) | {c['adders']} |",
             f"| subtractors | {c['subtractors']} |",
             f"| comparators | {c['comparators']} |"]
    for name, t in c["tables"].items():
        lines.append(f"| {name} table ({t['mode']}) | {t['entries']} x {t['bits']} bits x "
                     f"{t['copies']} copies ({t['reads_per_site']} reads per site) = "
                     f"{t['total_bits']} bits |")
    b = c["bits"]
    lines += [f"| bits | line buffers {b['line_buffers']}, tables {b['tables']}, datapath "
              f"{b['datapath']}, total {b['total']} |", "",
              "Register widths (worst case, bits): " + ", ".join(
                  f"{k} {v}" for k, v in c["registers"].items()), ""]
    lines += ["| protocol | images | CFA PSNR float64 | fixed | difference (dB) | "
              "within 1 LSB | max abs(diff) | histogram fixed - float64 (" +
              " ".join(HIST_BINS) + ") |", "|---|---|---|---|---|---|---|---|"]
    for proto, e in rep["error"].items():
        lines.append(f"| {proto} | {e['images']} | {e['psnr_float']:.3f} | "
                     f"{e['psnr_fixed']:.3f} | {e['dpsnr_mean']:+.4f} | "
                     f"{e['within_1lsb_pct']:.3f} % | {e['max_abs_lsb']} | "
                     + " ".join(str(v) for v in e["hist"].values()) + " |")
    lines += ["", "| operations per site | " + " | ".join(
        ("add/sub", "mul", "div", "exp", "cmp", "abs", "table reads (1/x, exp; ROM)")) + " |",
        "|---" * 8 + "|"]
    ops = rep["opcounts"]
    for g, f in ops["fixed"].items():
        fl, t1 = ops["float64"].get(g, {}), ops["table1"].get(g)
        adds = f.get("add", 0) + f.get("sub", 0)
        lines.append(f"| fixed, {g} | {adds} | {f.get('mul', 0)} (+{f.get('cmul', 0)} "
                     f"constant) | 0 | 0 | {f.get('cmp', 0)} | {f.get('abs', 0)} | "
                     f"{f.get('recip_lookup', 0)}, {f.get('exp_lookup', 0)}"
                     + (f"; {f['rom_read']}" if f.get("rom_read") else "") + " |")
        if fl:
            lines.append(f"| float64, {g} | {fl['add']:g} | {fl['mul']:g} | {fl['div']:g} | "
                         f"{fl['exp']:g} | {fl['cmp']:g} | {fl['abs']:g} | - |")
        if t1:
            lines.append(f"| Table 1, {g} | {t1['add']} | {t1['mul']} | {t1['div']} | "
                         f"{t1['exp']} | - | - | - |")
    exact = {p: e.get("exact_images", 0) for p, e in rep["error"].items()}
    if any(exact.values()):
        lines += ["", "The CFA PSNR means leave out the images that both reconstruct exactly "
                  "at every Z site (PSNR +inf; their change counts as 0 dB): " + ", ".join(
                      f"{n} of {rep['error'][p]['images']} ({p})" for p, n in exact.items())
                  + "."]
    verdict = "meets" if rep["meets_target"] else "MISSES"
    lines += ["", f"Target (|mean CFA PSNR change| <= {TARGET['dpsnr_db']} dB and >= "
              f"{TARGET['within_1lsb_pct']} % of Z sites within 1 LSB, every protocol): "
              f"{verdict}. Images: {', '.join(rep['images'])} ({rep['seconds']} s)."]
    for n in c["notes"]:
        lines.append(f"Note: {n}.")
    return "\n".join(lines)


def format_sweep(rows):
    """Markdown table of :func:`run_sweep` (Pareto rows marked)."""
    out = ["| configuration | table bits | datapath bits | DSP48 | within 1 LSB (worst "
           "protocol) | max abs(dPSNR) dB | max diff | target | front |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if "bits" not in r:
            out.append(f"| {r['label']} | refused: {r['refused']} | | | | | | | |")
            continue
        out.append(f"| {r['label']} | {r['bits']['tables']} | {r['bits']['datapath']} | "
                   f"{r['dsp48']} | {r['within_1lsb_pct']:.3f} % | {r['dpsnr_max_abs']:.4f} | "
                   f"{r['max_abs_lsb']} | {'yes' if r['meets_target'] else 'no'} | "
                   f"{'*' if r['pareto'] else ''} |")
    return "\n".join(out)
