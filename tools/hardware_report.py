"""Write docs/reports/hardware.md: the fixed-point model's cost and its error against float64.

    python tools/hardware_report.py [--kodak DIR] [--extra DIR] [--out docs/reports]

Sections: the default configuration and its search (from
docs/reports/figures/hardware_search.json, which tools/hardware_default.py writes,
and hardware_search_learned.json, which `tools/hardware_default.py --method learned`
writes: the learned filters' fields and their hash buckets that flip);
the targets on Kodak (every method and mask, learned on every Bayer phase of both
masks, both protocols of `rgbz-fast hardware`);
the same on an independent set (CBSD68) and on the default dataset the search used;
the cost of every method and mask at 4000 pixels; the full `rgbz-fast hardware` report
of SG and learned on both masks; the sweep of SG and learned on both masks
(`rgbz-fast hardware --sweep`: table and plot) with its time. The page and its figures
are written to temporary files and renamed.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

from rgbz_fast import FixedPointConfig, __version__
from rgbz_fast._devtools import hardware as H
from rgbz_fast._devtools.plots import hardware_sweep_plot
from rgbz_fast.hardware import hardware_cost
from rgbz_fast.io import atomic_write

REPO = Path(__file__).resolve().parents[1]
METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg")
MASKS = ("mask1", "mask2")
#: the learned filters on every Bayer phase of both masks they cover
LEARNED_PATTERNS = tuple(f"{m}{ph}" for m in MASKS for ph in ("", "_rggb", "_bggr", "_gbrg"))
LEARNED_FIELDS = ("tap_bits", "hash_const_bits", "hash_bits", "hash_norm_bits")


def _cpu():
    try:
        for line in open("/proc/cpuinfo", encoding="utf-8"):
            if line.lower().startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def target_table(images, label):
    """Rows method x mask x protocol of the default configuration against float64 (learned:
    every Bayer phase of both masks)."""
    out = [f"### {label}", "",
           "| method | mask | protocol | CFA PSNR float64 (dB) | fixed - float64 (dB, mean) | "
           "worst image (dB) | within 1 LSB | max abs diff (LSB) | target |",
           "|---|---|---|---|---|---|---|---|---|"]
    worst = {"dpsnr": 0.0, "within": 100.0}
    for m, p in [(m, p) for m in METHODS for p in MASKS] + \
            [("learned", p) for p in LEARNED_PATTERNS]:
        cases = H.prepare_cases(images, p, m)
        err = H.measure_error(cases, m, FixedPointConfig())
        for proto, e in err.items():
            ok = H.meets_target({proto: e})
            worst["dpsnr"] = max(worst["dpsnr"], abs(e["dpsnr_mean"]))
            worst["within"] = min(worst["within"], e["within_1lsb_pct"])
            out.append(f"| {m} | {p} | {proto} | {e['psnr_float']:.3f} | "
                       f"{e['dpsnr_mean']:+.4f} | {e['dpsnr_max_abs']:.4f} | "
                       f"{e['within_1lsb_pct']:.3f} % | {e['max_abs_lsb']} | "
                       f"{'met' if ok else 'MISSED'} |")
    out += ["", f"Worst over the table: |mean change| {worst['dpsnr']:.4f} dB, "
            f"{worst['within']:.3f} % of Z sites within 1 LSB.", ""]
    return out


def bit_depth_table(images):
    """SG on both masks under the linear protocol at other bit depths: the default configuration,
    and FixedPointConfig.for_bit_depth (every width one bit more per bit beyond 11, the tables
    twice the entries per three bits)."""
    from rgbz_fast import reconstruct
    from rgbz_fast.evaluation import EvalConfig
    from rgbz_fast.evaluation._run import image_frames

    out = ["| bits | mask | default: within 1 LSB | max abs diff | for_bit_depth: within 1 LSB "
           "| max abs diff | its table + datapath bits (default's) |",
           "|---|---|---|---|---|---|---|"]
    base = FixedPointConfig()
    for b in (8, 10, 12, 14, 16):
        wide = FixedPointConfig.for_bit_depth(b)
        for p in MASKS:
            ec = EvalConfig(bit_depth=b)
            res = []
            for cfg in (base, wide):
                n = within = worst = 0
                for _, img in images:
                    frame, _ = image_frames(img, p, ec)
                    exact = reconstruct(frame, "sg", precision="float64")
                    fixed = reconstruct(frame, "sg", precision="fixed", fixed_point=cfg)
                    d = np.abs(fixed[frame.z_mask].astype(np.int64) - exact[frame.z_mask])
                    n += d.size
                    within += int(np.count_nonzero(d <= 1))
                    worst = max(worst, int(d.max()))
                res.append((100.0 * within / n, worst))
            cw = hardware_cost(p, "sg", bit_depth=b, fixed_point=wide)
            cb = hardware_cost(p, "sg", bit_depth=b, fixed_point=base)
            out.append(f"| {b} | {p} | {res[0][0]:.3f} % | {res[0][1]} | {res[1][0]:.3f} % | "
                       f"{res[1][1]} | {cw.table_bits + cw.datapath_bits} "
                       f"({cb.table_bits + cb.datapath_bits}) |")
    return out


def vitis_table():
    """Our design at the 4K width of the Vitis figures, 11 and 16 bits."""
    out = ["| method | mask | bits | line buffers (BRAM_18K) | tables (bits; BRAM_18K if in block "
           "RAM) | variable multipliers | DSP48E2 (estimate) |", "|---|---|---|---|---|---|---|"]
    for m in ("bilinear", "sg", "learned"):
        for p in MASKS:
            for b in (11, 16):
                cfg = FixedPointConfig.for_bit_depth(b)
                c = hardware_cost(p, m, width=3840, bit_depth=b, fixed_point=cfg)
                tb = sum(t["bram18"] for t in c.tables.values())
                out.append(f"| {m} | {p} | {b} | {c.line_buffers} x 3840 "
                           f"({c.line_buffer_bram18}) | {c.table_bits} ({tb}) | "
                           f"{sum(c.multipliers().values())} | {c.dsp48()} |")
    return out


def cost_table():
    out = ["| method | mask | line buffers (BRAM_18K) | tables (bits) | datapath (bits) | "
           "total (bits) | multipliers | DSP48E2 | table reads per site (1/x, exp) | "
           "latency | longest path (operations) |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for m in (*METHODS, "learned"):
        for p in MASKS:
            c = hardware_cost(p, m, width=4000)
            reads = (c.tables.get("recip", {}).get("reads_per_site", 0),
                     c.tables.get("exp", {}).get("reads_per_site", 0))
            if m == "learned":
                reads = ("ROM", 1)
            out.append(f"| {m} | {p} | {c.line_buffers} x 4000 x 11 ({c.line_buffer_bram18}) | "
                       f"{c.table_bits} | {c.datapath_bits} | {c.total_bits} | "
                       f"{sum(c.multipliers().values())} | {c.dsp48()} | {reads[0]}, {reads[1]} | "
                       f"{c.latency_rows} rows + {c.latency_pixels} px | {c.depth} |")
    return out


def learned_search_section(search, held_out=None):
    """The learned filters' fields: the search and the hash buckets that flip (``held_out``:
    the flips at the default on Kodak, measured by this tool)."""
    m, d = search["margin"], search["default"]
    out = ["### The learned filters' fields", "",
           f"Found by `python tools/hardware_default.py --method learned` in "
           f"{search['seconds']} s ({len(search['evaluated'])} configurations evaluated): one "
           f"coordinate descent from {', '.join(f'{k}={v}' for k, v in search['start'].items())}"
           f" over {', '.join(search['fields'])} (in that order), each narrowed to the smallest "
           f"value that keeps, on every Bayer phase of both masks "
           f"({', '.join(search['patterns'])}) and both protocols of the calibration images, "
           f"at least {m['within_1lsb_pct']} % of the Z sites within 1 LSB of float64, the mean "
           f"CFA PSNR within {m['dpsnr_db']} dB and every image within {m['image_dpsnr_db']} dB; "
           f"the cost is the learned model's table (filter ROM and hash constants) and datapath "
           f"bits summed over Mask1 and Mask2. Result: "
           f"{', '.join(f'{k}={v}' for k, v in d.items())} ({search['cost_bits']} bits).", "",
           "Hash buckets that flip: a Z site whose bucket in the fixed model differs from the "
           "float64 hash of the filters' specification gets another filter. The share of such "
           "sites, and the error there and elsewhere (|fixed - float64| in LSB), at the default "
           "and at the wide start of the search (the calibration rows as the search measured "
           "them, on the filters it ran on; the Kodak default rows measured by this tool, on "
           "the shipped filters):", "",
           "| images | configuration | protocol | Z sites | flipped | within 1 LSB where "
           "flipped | mean abs diff where flipped | within 1 LSB elsewhere | sites > 1 LSB: "
           "flipped / elsewhere |", "|---|---|---|---|---|---|---|---|---|"]
    names = {"calibration": ("calibration", "default"),
             "calibration_wide_start": ("calibration", "wide start"),
             "check": ("Kodak (held out)", "default"),
             "check_wide_start": ("Kodak (held out)", "wide start")}
    flips = dict(search["bucket_flips"])
    if held_out is not None:
        flips["check"] = held_out
    for key, (imgs, cfg) in names.items():
        for proto, e in flips.get(key, {}).items():
            out.append(f"| {imgs} | {cfg} | {proto} | {e['sites']} | {e['flipped']} "
                       f"({e['flipped_pct']:.4f} %) | {e['flipped_within_1lsb_pct']:.1f} % | "
                       f"{e['flipped_mean_abs_lsb']:.2f} | {e['other_within_1lsb_pct']:.4f} % | "
                       f"{e['sites_beyond_1lsb_from_flips']} / "
                       f"{e['sites_beyond_1lsb_other']} |")
    return out + [""]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--kodak", type=Path, default=REPO.parent / "shared" / "data" / "kodak")
    ap.add_argument("--extra", type=Path, default=REPO.parent / "shared" / "data" / "cbsd68")
    ap.add_argument("--out", type=Path, default=REPO / "docs" / "reports")
    args = ap.parse_args(argv)
    t0 = time.perf_counter()
    load0 = os.getloadavg()[0]
    figs = args.out / "figures"
    figs.mkdir(parents=True, exist_ok=True)
    cfg = FixedPointConfig()
    search_path = figs / "hardware_search.json"
    search = json.loads(search_path.read_text()) if search_path.exists() else None

    lines = ["# The fixed-point model: cost and error against float64", "",
             "* **Command:** `python tools/hardware_report.py` (this page and "
             "`figures/hardware_sweep_*.png`; the default configuration's search: "
             "`python tools/hardware_default.py`, which writes `figures/hardware_search.json`)",
             f"* **Machine:** {_cpu()}, {os.cpu_count()} logical cores, {platform.system()} "
             f"{platform.release()}, Python {platform.python_version()}, NumPy {np.__version__}",
             f"* **Date:** {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, rgbz-fast "
             f"{__version__}; load average {load0:.2f} before the run", "",
             "What the model is and how to read this page: [From the paper to silicon]"
             "(../guide/hardware.md).", "",
             "## The default configuration", "", f"`{cfg!r}`", ""]
    if search:
        m = search["margin"]
        lines += [f"Found by `tools/hardware_default.py` in {search['seconds']} s "
                  f"({len(search['evaluated'])} configurations evaluated): a coordinate descent "
                  f"per combination of table modes, each field narrowed to the smallest value "
                  f"that keeps, on every method (bi, edi_central, edi_line, sg), mask and "
                  f"protocol of the calibration images ({', '.join(search['images'])}), at "
                  f"least {m['within_1lsb_pct']} % of the Z sites within 1 LSB of float64, the "
                  f"mean CFA PSNR within {m['dpsnr_db']} dB and every image within "
                  f"{m['image_dpsnr_db']} dB; the cost is the table and datapath bits summed "
                  f"over those methods and both masks (4000 pixels, 11 bits). The "
                  f"{len(search['results'])} descents ended at:", "",
                  "| exp | recip | cost (bits) | configuration |", "|---|---|---|---|"]
        for r in search["results"]:
            c = r["config"]
            rest = ", ".join(f"{k}={v}" for k, v in c.items() if k not in ("exp", "recip",
                                                                           "register_bits"))
            lines.append(f"| {c['exp']} | {c['recip']} | {r['cost_bits']} | {rest} |")
        lines.append("")
    learned_at = len(lines)     # the learned search's section, read when the page is done
    kodak = H.load_images(args.kodak) if args.kodak.exists() else None
    lines += ["## The targets", "",
              "Target: the default configuration within 0.05 dB of float64's mean CFA PSNR "
              "and within 1 LSB of it at >= 99.9 % of the Z sites, for every method and "
              "mask, under evaluate's default protocol (`linear`: sRGB linearised, noise-free "
              "11-bit mosaics) and on the 8-bit sRGB values mosaicked at 11 bits (`srgb`: "
              "`rz.mosaic(img8, pattern)`).", ""]
    if kodak:
        lines += target_table(kodak, f"Kodak ({len(kodak)} images; not used by the search)")
    if args.extra.exists():
        extra = H.load_images(args.extra)
        lines += target_table(extra, f"{args.extra.name} ({len(extra)} images; not used by "
                                     f"the search)")
    lines += target_table(H.load_images(), "The default dataset (the search's calibration set)")
    if kodak:
        lines += ["## Other bit depths (SG, linear protocol, the first 8 Kodak images)", "",
                  "The default configuration is searched at 11 bits (the paper's ADC). A "
                  "wider frame keeps the relative error of the weighted mean, so its error in "
                  "LSB grows with the range; `FixedPointConfig.for_bit_depth(b)` widens every "
                  "width by one bit per bit beyond 11 and doubles the tables per three bits.",
                  ""]
        lines += bit_depth_table(kodak[:8]) + [""]
    lines += ["## Cost of every method (4000 pixels, 11 bits, the default configuration)", ""]
    lines += cost_table() + [""]
    big = FixedPointConfig.for_bit_depth(16)
    entries = max(big.exp_table_size, big.recip_table_size) + 1
    lines += ["## Beside AMD Vitis `xf::cv::rgbir2bayer`", "",
              "AMD documents 37 BRAM_18K, 0 DSP, 4345 FF and 6243 LUT at 300 MHz, one pixel "
              "per clock, for a 4K 4x4 RGB-IR remosaic (5x5 colour and 3x3 IR filters) whose "
              "weights are fixed (shifts and adds: no multiplier). Our design at 3840 pixels "
              "per row (16-bit frames: `FixedPointConfig.for_bit_depth(16)`); tables this "
              f"small ({entries} entries or fewer) fit distributed RAM (LUTs) as well as block "
              "RAM, so the BRAM column is an upper bound; FF and LUT counts need a synthesis "
              "run, not given here:", ""]
    lines += vitis_table() + [""]
    for m, name in (("sg", "SG"), ("learned", "learned")):
        lines += [f"## `rgbz-fast hardware --method {m}` on both masks (Kodak)", ""]
        for p in MASKS:
            rep = H.hardware_report(m, p, width=4000, images=kodak or None)
            lines += [H.format_report(rep).replace("## ", "### ", 1), ""]
    for m, name in (("sg", "SG"), ("learned", "learned")):
        lines += [f"## The sweep: quality against cost ({name}, default dataset)", ""]
        for p in MASKS:
            ts = time.perf_counter()
            rows = H.run_sweep(m, p)
            secs = time.perf_counter() - ts
            fig = figs / f"hardware_sweep_{m}_{p}.png"
            atomic_write(fig, hardware_sweep_plot(rows, f"{name} on {p}: fixed vs float64, "
                                                        "default dataset"))
            lines += [f"### {p}: `rgbz-fast hardware --method {m} --pattern {p} --sweep` "
                      f"({len(rows)} configurations, {secs:.0f} s)", "",
                      f"![sweep](figures/{fig.name})", "", H.format_sweep(rows), ""]
    held_out = None
    if kodak:
        from hardware_default import LEARNED_PATTERNS as PHASES, bucket_flips
        held_out = bucket_flips(kodak, PHASES, FixedPointConfig())
    learned_path = figs / "hardware_search_learned.json"
    if learned_path.exists():
        lines[learned_at:learned_at] = learned_search_section(
            json.loads(learned_path.read_text()), held_out)
    lines += [f"Whole page: {time.perf_counter() - t0:.0f} s; load average "
              f"{os.getloadavg()[0]:.2f} after the run."]
    page = args.out / "hardware.md"
    atomic_write(page, "\n".join(lines) + "\n")
    print(page)
    return 0


if __name__ == "__main__":
    sys.exit(main())
