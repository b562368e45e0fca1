"""The table of ``rgbz-fast pattern-study``: its columns, CSV, Markdown, the Pareto front.

:data:`COLUMNS` is the one list of the table's columns (key, header, format,
meaning); CSV, Markdown and the column legend are all written from it. A
new measurement is one more entry here and one more field in the rows of
:func:`rgbz_fast._devtools.pattern_study.pattern_study`.
"""

from __future__ import annotations

import csv
import io

__all__ = ["COLUMNS", "LAYOUT_COLUMNS", "to_csv", "to_markdown", "to_text", "pareto_layouts",
           "best_rows"]


def _num(fmt):
    def f(v):
        return "-" if v is None else format(v, fmt)
    return f


def _text(v):
    return "" if v is None else str(v)


#: (key, header, format of a Markdown cell, meaning)
COLUMNS = (
    ("layout", "layout", _text, "name: a preset, tileN for a tile given, or the generated "
                                "family's z<block>-p<period>-<arrangement>"),
    ("tile", "tile", lambda v: f"`{v}`", "the repeated tile, rows top to bottom"),
    ("bayer", "Bayer", _text, "underlying Bayer phase"),
    ("z_pixel", "Z pixel", _text, "sites of one depth measurement (rows x columns)"),
    ("z_fill", "Z fill", lambda v: f"{100 * v:.2f} %", "share of the sites that are Z"),
    ("meas_per_mp", "meas/MP", _num(",.0f"), "depth measurements per megapixel"),
    ("method", "method", _text, "colour reconstruction at the Z sites"),
    ("cfa_psnr", "CFA PSNR", _num(".2f"), "dB on the reconstructed sites (eqs. 20-21), mean "
                                          "over the images"),
    ("cpsnr", "CPSNR", _num(".2f"), "dB, 8-bit sRGB against the Bayer path, mean"),
    ("zipper", "zipper", _num(".2f"), "% of the pixels (Lu & Tan), mean"),
    ("ops_per_z", "ops/Z", _num(".1f"), "arithmetic per reconstructed pixel (counting "
                                        "build, every category summed)"),
    ("ops_per_pixel", "ops/px", _num(".2f"), "the same per frame pixel (ops/Z x Z fill)"),
    ("line_buffers", "line buf", _num("d"), "line buffers of the fixed-point streaming model "
                                           "(rgbz_fast.hardware.hardware_cost, its default "
                                           "widths; methods and periods up to 8 it models)"),
    ("multipliers", "mults", _num("d"), "variable multipliers of that model's datapath (one "
                                        "site per clock)"),
    ("tof_ops_per_pixel", "ToF ops/px", _num(".2f"), "four-tap demodulation per frame pixel "
                                                     "(every frequency)"),
    ("wall_sigma_mm", "σ wall (mm)", _num(".1f"), "depth noise the guided ToF ISP predicts "
                                                  "on the flat wall (RMS, valid or not)"),
    ("wall_std_mm", "spread (mm)", _num(".1f"), "measured std of the valid wall depths"),
    ("wall_valid", "wall valid", lambda v: "-" if v is None else f"{100 * v:.1f} %",
     "valid share on the wall"),
    ("rgbd_valid", "RGB-D valid", lambda v: "-" if v is None else f"{100 * v:.1f} %",
     "valid share of the known measurements, all scenes"),
    ("rgbd_wrong", "wrong", lambda v: "-" if v is None else f"{100 * v:.2f} %",
     "share of the valid measurements off by more than 5 cm"),
    ("rgbd_rmse_mm", "RMSE (mm)", _num(".0f"), "RMSE of the valid measurements"),
    ("note", "note", _text, "what did not run, and why"),
)
#: the columns of a row that say something about the layout, not the method
LAYOUT_COLUMNS = ("layout", "tile", "bayer", "z_pixel", "z_fill", "meas_per_mp",
                  "tof_ops_per_pixel", "wall_sigma_mm", "wall_std_mm", "wall_valid",
                  "rgbd_valid", "rgbd_wrong", "rgbd_rmse_mm")


def _present(rows):
    """The columns some row has (a study without RGB-D scenes has no scene columns)."""
    return [c for c in COLUMNS if any(r.get(c[0]) is not None for r in rows)
            or c[0] in ("layout", "method", "note")]


def to_csv(rows):
    """The table as CSV: every column, plain numbers, empty where nothing was measured."""
    keys = [c[0] for c in COLUMNS] + ["source", "period", "best", "same_as"]
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=keys, extrasaction="ignore", lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: "" if r.get(k) is None else r[k] for k in keys})
    return buf.getvalue()


def best_rows(rows):
    """One row per layout: its best method's (highest CPSNR), or its first when none ran."""
    out = {}
    for r in rows:
        if r["layout"] not in out or r.get("best"):
            out[r["layout"]] = r
    return list(out.values())


def pareto_layouts(rows):
    """Names of the layouts on the front of colour (best CPSNR, higher is better) against
    depth noise (predicted wall sigma, lower is better): nothing else is at least as good
    in both and better in one."""
    pts = [(r["layout"], r["cpsnr"], r["wall_sigma_mm"]) for r in best_rows(rows)
           if r.get("cpsnr") is not None and r.get("wall_sigma_mm") is not None]
    front = []
    for name, c, s in pts:
        if not any((c2 >= c and s2 <= s) and (c2 > c or s2 < s) for _, c2, s2 in pts):
            front.append(name)
    return front


def _table(rows, cols, bold=None):
    lines = ["| " + " | ".join(c[1] for c in cols) + " |",
             "|" + "|".join("---" for _ in cols) + "|"]
    for r in rows:
        cells = []
        for key, _, fmt, _ in cols:
            v = fmt(r.get(key))
            if bold and bold(r) and key in ("method", "cpsnr"):
                v = f"**{v}**"
            cells.append(v.replace("|", "\\|"))
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def to_markdown(res, png_name=None, command=None):
    """The study as Markdown: what ran, the layouts at their best method (on the Pareto
    front or not), the whole table (one row per layout and method), the columns' meaning."""
    rows = res["rows"]
    front = set(pareto_layouts(rows))
    m = res["machine"]
    ds = res["dataset"]
    train = res["train"]
    s = res["settings"]
    lines = ["# Pattern study", "",
             "Generated by `rgbz-fast pattern-study`" + (f" (`{command}`)" if command else "")
             + f" in {res['wall_time_s']:.0f} s on {m['cpu_model']} "
             f"({m['logical_cores']} logical cores"
             + (f", Dask scheduler {res['scheduler']}" if res.get("scheduler") else "")
             + "). Re-running the command reads every finished task from its cache.", "",
             f"Colour: {len(ds['images'])} image(s) of {ds['name']} "
             f"({', '.join(ds['images'])}), noise-free {s['bit_depth']}-bit mosaics, the "
             "chain and metrics of `rgbz-fast evaluate`. learned: "
             + (f"fitted per layout on {train['name']} ({len(train['images'])} images)."
                if train else "not fitted (no training set given).")
             + f" Depth: the colour-guided ToF ISP at its defaults on a flat wall at "
             f"{s['wall_distance']:g} m (NIR reflectance {s['wall_reflectance']:g}, "
             f"{s['wall_shape'][0]}x{s['wall_shape'][1]} frame, seed {s['seed']})"
             + (f" and on {len(res['rgbd'])} RGB-D scene(s) ({', '.join(res['rgbd'])}; "
                + ("whole frames" if s["rgbd_size"] is None else
                   f"centre {s['rgbd_size'][0]}x{s['rgbd_size'][1]} crops") + ")"
                if res["rgbd"] else "") + ".", ""]
    if png_name:
        lines += [f"![Pareto plot]({png_name})", ""]
    best = best_rows(rows)
    lines += ["## Layouts at their best method", "",
              "The method with the highest CPSNR per layout; **bold**: on the Pareto front "
              "of CPSNR against the wall's predicted depth noise.", ""]
    cols = [c for c in _present(best) if c[0] not in ("note",)]
    lines += _table(best, cols, bold=lambda r: r["layout"] in front) + [""]
    same = [(lay["name"], lay["same_as"]) for lay in res["layouts"] if lay["same_as"]]
    if same:
        lines += ["Counted once (the same layout under whole-Bayer-period shifts and the "
                  "flips/transposes that keep the Bayer phase): "
                  + "; ".join(f"{n} = {', '.join(s)}" for n, s in same) + ".", ""]
    if res["notes"]:
        lines += ["Generated combinations left out: " + "; ".join(res["notes"]) + ".", ""]
    lines += ["## Every layout and method", ""]
    lines += _table(rows, _present(rows), bold=lambda r: r.get("best")) + [""]
    lines += ["## Columns", ""] + [f"* **{h}**: {d}" for k, h, _, d in _present(rows)] + [""]
    return "\n".join(lines)


def to_text(res):
    """A short plain-text table: each layout at its best method (names and tiles whole, to
    copy: a tile of 8x8 sites is 71 characters)."""
    best = best_rows(res["rows"])
    front = set(pareto_layouts(res["rows"]))
    wl = max([len("layout")] + [len(r["layout"]) for r in best])
    wt = max([len("tile")] + [len(r["tile"]) for r in best])
    head = (f"{'layout':{wl}} {'tile':{wt}} {'Z fill':>7} {'method':11} {'CPSNR':>6} "
            f"{'ops/px':>7} {'σ mm':>6}  front")
    out = [head, "-" * len(head)]
    for r in best:
        def f(k, fmt):
            v = r.get(k)
            return "-" if v is None else format(v, fmt)
        out.append(f"{r['layout']:{wl}} {r['tile']:{wt}} {100 * r['z_fill']:6.2f}% "
                   f"{r['method'] if r.get('cpsnr') is not None else '-':11} "
                   f"{f('cpsnr', '.2f'):>6} {f('ops_per_pixel', '.2f'):>7} "
                   f"{f('wall_sigma_mm', '.1f'):>6}  {'*' if r['layout'] in front else ''}")
    return "\n".join(out)
