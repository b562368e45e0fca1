"""Search for the narrowest fixed-point configuration that meets the target, with a margin.

    python tools/hardware_default.py [--out docs/reports/figures/hardware_search.json]
    python tools/hardware_default.py --method learned \
        [--out docs/reports/figures/hardware_search_learned.json] [--check ../shared/data/kodak]
    python tools/hardware_default.py [--method learned] --recost   # the costs alone, again

The cost of a configuration is the sum, over the methods bi, edi_central,
edi_line, sg and the masks Mask1 and Mask2, of its table and datapath bits
(rgbz_fast.hardware.hardware_cost at 4000 pixels, 11 bits; the line buffers do
not depend on the configuration, and bilinear is exact at every configuration).
The calibration set is the five scikit-image samples that `rgbz-fast evaluate`
uses with no --dataset and every eighth image of CBSD68 (--extra), under both
protocols of `rgbz-fast hardware` (linear and 8-bit sRGB, 11-bit frames); Kodak
stays out of it, to check the result.
A configuration passes when, for every method, mask and protocol, at least
MARGIN["within_1lsb_pct"] % of the Z sites are within 1 LSB of float64 and the
mean CFA PSNR moves by at most MARGIN["dpsnr_db"] (every image by at most the
target's 0.05 dB): a margin over the target of 99.9 % and 0.05 dB.

The search is a coordinate descent, for each of the four combinations of table
modes (exp and recip: nearest entry or piecewise-linear): starting from a wide
configuration, each field in turn takes the smallest value that passes with the
others fixed (a bisection: the error grows as a field narrows), and the passes
repeat until no field moves. The cheapest of the four results is the default
of FixedPointConfig. Every evaluated configuration and its verdict is written
to --out (JSON), the path of the search to stdout.

``--method learned`` searches the learned filters' fields (tap_bits, hash_bits,
hash_const_bits, hash_norm_bits; the others do not reach its datapath) the same
way, from LEARNED_WIDE, over every Bayer phase of Mask1 and Mask2 the shipped
filters cover (the filters of the package, or --filters FILE ...), with the cost
the learned model's table (the filter ROM and the hash constants) and datapath
bits summed over Mask1 and Mask2. For the default it then measures the hash
buckets that flip: the share of Z sites whose bucket differs from the float64
hash of the filters' specification, and the error at those sites and at the
others (the fixed model's buckets from tests/_reference/fixed_learned.py, bit
exact with the C model), on the calibration set and, with --check, on a
held-out folder (Kodak).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

from rgbz_fast._devtools import hardware as H
from rgbz_fast.hardware import FixedPointConfig, hardware_cost

METHODS = ("sg", "edi_line", "edi_central", "bi")
MASKS = ("mask2", "mask1")
MARGIN = {"within_1lsb_pct": 99.99, "dpsnr_db": 0.02, "image_dpsnr_db": 0.05}
#: the fields, the order of the descent, and their lowest values (sigma_bits: 1 holds the
#: default sigma_rel 0.5 exactly)
FIELDS = {"exp_table_size": 2, "recip_table_size": 2, "exp_range_bits": 1, "sigma_bits": 1,
          "ratio_bits": 0, "alpha_bits": 2, "exp_bits": 2, "recip_bits": 2, "weight_bits": 2}
WIDE = dict(exp_bits=20, exp_table_size=1024, exp_range_bits=8, recip_bits=22,
            recip_table_size=1024, ratio_bits=18, sigma_bits=8, alpha_bits=16, weight_bits=22)


MODES = (("pwl", "pwl"), ("table", "pwl"), ("pwl", "table"), ("table", "table"))

#: the learned filters' search: the fields, the order of the descent, their lowest values;
#: the wide start (the widest whose registers fit 63 bits); every Bayer phase of both masks
LEARNED_FIELDS = {"tap_bits": 4, "hash_const_bits": 2, "hash_bits": 4, "hash_norm_bits": 1}
LEARNED_WIDE = dict(tap_bits=24, hash_bits=18, hash_const_bits=20, hash_norm_bits=20)
LEARNED_PATTERNS = tuple(f"{m}{ph}" for m in MASKS for ph in ("", "_rggb", "_bggr", "_gbrg"))


def _modes(text):
    out = tuple(tuple(m.split("/")) for m in text.split(","))
    if not all(len(m) == 2 and set(m) <= {"table", "pwl"} for m in out):
        raise argparse.ArgumentTypeError(f"expected EXP/RECIP pairs of table or pwl, got {text!r}")
    return out


def cost(cfg, methods=METHODS, params=None):
    """Table and datapath bits summed over the methods and masks."""
    total = 0
    for m in methods:
        for p in MASKS:
            c = hardware_cost(p, m, fixed_point=cfg, params=params)
            total += c.table_bits + c.datapath_bits
    return total


class Search:
    def __init__(self, images, methods=METHODS, patterns=MASKS, fields=None, params=None):
        self.methods, self.params = methods, params
        self.fields = FIELDS if fields is None else fields
        self.cases = {(m, p): H.prepare_cases(images, p, m, params=params)
                      for m in methods for p in patterns}
        self.seen = {}

    def cost(self, cfg):
        return cost(cfg, self.methods, self.params)

    def passes(self, cfg):
        key = tuple(sorted(cfg.as_dict().items()))
        if key in self.seen:
            return self.seen[key]["pass"]
        rec = {"config": cfg.as_dict(), "pass": True, "worst": None}
        try:
            c = self.cost(cfg)
        except ValueError as exc:
            rec.update({"pass": False, "refused": str(exc)})
            self.seen[key] = rec
            return False
        rec["cost_bits"] = c
        for (m, p), cases in self.cases.items():        # hardest first: stop at a failure
            err = H.measure_error(cases, m, cfg, self.params)
            for proto, e in err.items():
                bad = (e["within_1lsb_pct"] < MARGIN["within_1lsb_pct"]
                       or abs(e["dpsnr_mean"]) > MARGIN["dpsnr_db"]
                       or e["dpsnr_max_abs"] > MARGIN["image_dpsnr_db"])
                if rec["worst"] is None or e["within_1lsb_pct"] < rec["worst"][3]:
                    rec["worst"] = (m, p, proto, e["within_1lsb_pct"], e["dpsnr_mean"])
                if bad:
                    rec["pass"] = False
            if not rec["pass"]:
                break
        self.seen[key] = rec
        return rec["pass"]

    def descend(self, cfg, log):
        moved = True
        while moved:
            moved = False
            for field, lo in self.fields.items():
                cur = getattr(cfg, field)
                table = field.endswith("_table_size")
                vals = [2 ** k for k in range(int(np.log2(lo)), int(np.log2(cur)) + 1)] \
                    if table else list(range(lo, cur + 1))
                # bisection for the smallest passing value (cur passes)
                a, b = 0, len(vals) - 1
                while a < b:
                    mid = (a + b) // 2
                    if self.passes(cfg.replace(**{field: vals[mid]})):
                        b = mid
                    else:
                        a = mid + 1
                if vals[b] != cur:
                    cfg = cfg.replace(**{field: vals[b]})
                    moved = True
                    log(f"  {field}: {cur} -> {vals[b]}  (cost {self.cost(cfg)} bits)")
        return cfg


def bucket_flips(images, patterns, cfg, params=None, protocols=tuple(H.PROTOCOLS)):
    """The learned model's buckets against the float64 hash, per protocol: the share of Z
    sites whose bucket differs, and within 1 LSB / mean |fixed - float64| at those sites and
    at the others."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
    from _reference.fixed_learned import reference_fixed_learned

    from rgbz_fast.reconstruction import ReconstructParams, reconstruct
    from rgbz_fast.reconstruction._learned import resolve_filters
    from rgbz_fast.reconstruction._learned_hash import (gather_windows, hash_buckets,
                                                        hash_features)
    params = ReconstructParams.build(params)
    out = {}
    for proto in protocols:
        acc = {"sites": 0, "flipped": 0, "flip_within": 0, "flip_abs": 0, "rest_within": 0,
               "rest_abs": 0}
        for p in patterns:
            filters = resolve_filters(params.filters, p)
            P, Q = filters.pattern.period
            for _, frame, _, exact in ((n, f, r, e) for _, n, f, r, e in
                                       H.prepare_cases(images, p, "learned", (proto,), params)):
                data = frame.data
                fixed, bk = reference_fixed_learned(data, filters, cfg, frame.bit_depth,
                                                    return_buckets=True)
                fb = np.full(data.shape, -1, np.int64)
                thr = filters.thresholds(frame.bit_depth)
                for k, (X, (r, c, ny, nx)) in enumerate(gather_windows(
                        data, filters.pattern, filters.radius, filters.geometry)):
                    fb[r::P, c::Q][:ny, :nx] = hash_buckets(
                        hash_features(X, filters.geometry[k]),
                        *(t[k] for t in thr)).reshape(ny, nx)
                z = frame.z_mask
                d = np.abs(fixed[z] - exact[z].astype(np.int64))
                flip = fb[z] != bk[z]
                acc["sites"] += int(z.sum())
                acc["flipped"] += int(flip.sum())
                acc["flip_within"] += int((d[flip] <= 1).sum())
                acc["flip_abs"] += int(d[flip].sum())
                acc["rest_within"] += int((d[~flip] <= 1).sum())
                acc["rest_abs"] += int(d[~flip].sum())
        n, f = acc["sites"], acc["flipped"]
        out[proto] = {"sites": n, "flipped": f, "flipped_pct": 100.0 * f / max(n, 1),
                      "flipped_within_1lsb_pct": 100.0 * acc["flip_within"] / max(f, 1),
                      "flipped_mean_abs_lsb": acc["flip_abs"] / max(f, 1),
                      "other_within_1lsb_pct": 100.0 * acc["rest_within"] / max(n - f, 1),
                      "other_mean_abs_lsb": acc["rest_abs"] / max(n - f, 1),
                      "sites_beyond_1lsb_from_flips": f - acc["flip_within"],
                      "sites_beyond_1lsb_other": (n - f) - acc["rest_within"]}
    return out


def main_learned(args, images):
    """The learned filters' search (see the module doc)."""
    t0 = time.perf_counter()
    params = {"filters": args.filters} if args.filters else None
    search = Search(images, ("learned",), LEARNED_PATTERNS, LEARNED_FIELDS, params)
    start = FixedPointConfig(**LEARNED_WIDE)
    print(f"learned: start {search.cost(start)} bits", flush=True)
    if not search.passes(start):
        print("  the wide start misses the margin", flush=True)
        return 1
    best = search.descend(start, lambda s: print(s, flush=True))
    c = search.cost(best)
    print(f"default: {', '.join(f'{f}={getattr(best, f)}' for f in LEARNED_FIELDS)}\n"
          f"cost {c} bits; {len(search.seen)} configurations evaluated in "
          f"{time.perf_counter() - t0:.0f} s", flush=True)
    flips = {"calibration": bucket_flips(images, LEARNED_PATTERNS, best, params),
             "calibration_wide_start": bucket_flips(images, LEARNED_PATTERNS, start, params)}
    print("bucket flips (calibration):", json.dumps(flips["calibration"], indent=1), flush=True)
    if args.check is not None:
        held = H.load_images(args.check)
        flips["check"] = bucket_flips(held, LEARNED_PATTERNS, best, params)
        flips["check_wide_start"] = bucket_flips(held, LEARNED_PATTERNS, start, params)
        print("bucket flips (--check):", json.dumps(flips["check"], indent=1), flush=True)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    tmp = args.out.with_suffix(".tmp")
    tmp.write_text(json.dumps({"margin": MARGIN, "methods": ["learned"],
                               "patterns": LEARNED_PATTERNS, "fields": list(LEARNED_FIELDS),
                               "start": LEARNED_WIDE, "images": [n for n, _ in images],
                               "default": {f: getattr(best, f) for f in LEARNED_FIELDS},
                               "cost_bits": c, "bucket_flips": flips,
                               "seconds": round(time.perf_counter() - t0),
                               "evaluated": list(search.seen.values())}, indent=1))
    tmp.replace(args.out)
    return 0


def recost(args):
    """--recost: the search's JSON with every cost recomputed (see main's --recost)."""
    data = json.loads(args.out.read_text())
    learned = args.method == "learned"
    methods = ("learned",) if learned else METHODS
    params = {"filters": args.filters} if learned and args.filters else None

    def bits(config):
        return cost(FixedPointConfig(**config), methods, params)

    for rec in data["evaluated"]:
        if "cost_bits" in rec:
            rec["cost_bits"] = bits(rec["config"])
    if learned:
        default = FixedPointConfig(**data["default"])
        data["cost_bits"] = cost(default, methods, params)
        print(f"learned default: {data['cost_bits']} bits")
    else:
        for r in data["results"]:
            r["cost_bits"] = bits(r["config"])
        data["results"].sort(key=lambda r: r["cost_bits"])
        cheapest = data["results"][0]["config"]
        print("results:", ", ".join(f"{r['config']['exp']}/{r['config']['recip']} "
                                    f"{r['cost_bits']} bits" for r in data["results"]))
        if cheapest != data["default"]:
            print("the default is no longer the cheapest result: rerun the search")
            return 1
    tmp = args.out.with_suffix(".tmp")
    tmp.write_text(json.dumps(data, indent=1))
    tmp.replace(args.out)
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, default=None,
                    help="the JSON of the search (default: docs/reports/figures/"
                         "hardware_search.json, with --method learned "
                         "hardware_search_learned.json)")
    ap.add_argument("--method", choices=("plans", "learned"), default="plans",
                    help="plans: bi, edi_central, edi_line, sg; learned: the learned filters")
    ap.add_argument("--filters", nargs="+", default=None, metavar="FILE",
                    help="--method learned: filters files to search for (default: the shipped)")
    ap.add_argument("--check", type=Path, default=None, metavar="DIR",
                    help="--method learned: also measure the bucket flips on this folder")
    ap.add_argument("--extra", type=Path,
                    default=Path(__file__).resolve().parents[2] / "shared" / "data" / "cbsd68")
    ap.add_argument("--modes", type=_modes, default=MODES,
                    help="exp/recip table modes to search, e.g. pwl/pwl,table/pwl (default: "
                         "all four, the piecewise-linear ones first)")
    ap.add_argument("--recost", action="store_true",
                    help="recompute the cost of every configuration of an existing --out with "
                         "today's hardware_cost (the verdicts do not depend on it, nor does "
                         "the descent: it narrows each field to the smallest passing value) "
                         "and say whether the default is still the cheapest result")
    args = ap.parse_args(argv)
    if args.out is None:
        args.out = Path("docs/reports/figures/hardware_search_learned.json"
                        if args.method == "learned"
                        else "docs/reports/figures/hardware_search.json")
    if args.recost:
        return recost(args)
    t0 = time.perf_counter()
    images = H.load_images()
    if args.extra.exists():
        images += H.load_images(args.extra)[::8]
    if args.method == "learned":
        return main_learned(args, images)
    search = Search(images)
    results = []
    for e_mode, r_mode in args.modes:
        start = FixedPointConfig(exp=e_mode, recip=r_mode, **WIDE)
        print(f"modes exp={e_mode}, recip={r_mode}: start {cost(start)} bits", flush=True)
        if not search.passes(start):
            print("  the wide start misses the margin", flush=True)
            continue
        best = search.descend(start, lambda s: print(s, flush=True))
        results.append((cost(best), best))
        print(f"  -> {best} ({cost(best)} bits)", flush=True)
    results.sort(key=lambda r: r[0])
    best = results[0][1]
    print(f"default: {best}\ncost {results[0][0]} bits; {len(search.seen)} configurations "
          f"evaluated in {time.perf_counter() - t0:.0f} s", flush=True)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    tmp = args.out.with_suffix(".tmp")
    tmp.write_text(json.dumps({"margin": MARGIN, "methods": METHODS, "masks": MASKS,
                               "images": [n for n, _ in images],
                               "results": [{"cost_bits": c, "config": b.as_dict()}
                                           for c, b in results],
                               "default": best.as_dict(),
                               "seconds": round(time.perf_counter() - t0),
                               "evaluated": list(search.seen.values())}, indent=1))
    tmp.replace(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
