"""Markdown tables of an :func:`~rgbz_fast.evaluation.evaluate_depth` result
(docs/reports/isp.md)."""

from __future__ import annotations

import numpy as np

__all__ = ["depth_report"]


def _name(v):
    """A name in a table cell: a '|' in a scene's folder or a pair's name escaped (it had
    split the cell, and every column after it moved one to the right)."""
    return str(v).replace("|", "\\|")


def _pct(a, b):
    return f"{100.0 * a / b:.3f}" if b else "-"


def _cm(v):
    """A length in cm, '-' where there is none (NaN: nothing to average; the cells had been
    blank)."""
    return "-" if v is None or np.isnan(v) else f"{100 * v:.2f}"


def depth_report(result, tolerance=None):
    """Markdown tables of an :func:`evaluate_depth` result.

    ``tolerance`` (m), the error above which its tables call a measurement wrong, is the
    one the result was counted at (its rows keep it); given, it must agree with them (a
    result of an earlier version, whose rows do not say, is labelled with it, or 5 cm)."""
    from .._validate import check_number
    from ._depth import DEPTH_SECTIONS, WRONG_SECTIONS

    if not isinstance(result, dict) or not set(result) <= set(DEPTH_SECTIONS):
        raise TypeError(f"result: expected the dict of sections evaluate_depth returns, got "
                        f"{result!r:.60}")
    counted = {r["tolerance"] for s in WRONG_SECTIONS for r in result.get(s, ())
               if isinstance(r, dict) and "tolerance" in r}
    if len(counted) > 1:
        raise ValueError(f"result: its rows were counted at different tolerances "
                         f"{sorted(counted)}")
    if tolerance is not None:
        tolerance = check_number(tolerance, "tolerance", lo=0, lo_open=True)
        if counted and counted != {tolerance}:
            raise ValueError(f"tolerance: {tolerance:g} m, but the result counted wrong "
                             f"measurements at {counted.pop():g} m")
    tolerance = counted.pop() if counted else (0.05 if tolerance is None else tolerance)
    lines = []
    cm = f"{100 * tolerance:g} cm"
    if "scenes" in result:
        lines += [f"### Middlebury scenes (wrong: |error| > {cm})", "",
                  "| scene | pattern | guide | depth m | valid % | wrong % | wrong & valid % | "
                  "caught % | low signal % | flying % | resolved % | RMSE valid cm |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in result["scenes"]:
            rmse = _cm(r["rmse_valid"])
            caught = _pct(r["wrong"] - r["wrong_valid"], r["wrong"])
            lines.append(f"| {_name(r['scene'])} | {r['pattern']} | {r.get('guide', 'none')} | "
                         f"{r['depth_min']:.2f}-{r['depth_max']:.2f} | "
                         f"{_pct(r['valid'], r['known'])} | {_pct(r['wrong'], r['known'])} | "
                         f"{_pct(r['wrong_valid'], r['known'])} | {caught} | "
                         f"{_pct(r['low_signal'], r['known'])} | {_pct(r['flying'], r['known'])} | "
                         f"{_pct(r.get('resolved', 0), r['known'])} | {rmse} |")
        lines.append("")
    if "upsample" in result:
        lines += [f"### Full resolution (wrong: |error| > {cm}; edge MAE: weights |grad depth|)",
                  "", "| scene | pattern | method | covered % | wrong % | RMSE cm | "
                  "edge MAE cm | guided / nearest, same pixels |", "|---|---|---|---|---|---|---|---|"]
        for r in result["upsample"]:
            # the ratio is the guided rows' (the other methods' cells '-')
            ratio = (f"{r['edge_err_both'] / r['edge_err_nearest_both']:.3f}"
                     if r.get("edge_err_nearest_both") else "-")
            lines.append(f"| {_name(r['scene'])} | {r['pattern']} | {r['method']} | "
                         f"{_pct(r['covered'], r['known'])} | {_pct(r['wrong'], r['covered'])} | "
                         f"{_cm(r['rmse'])} | {_cm(r['edge_mae'])} | {ratio} |")
        lines += ["", "Last column: the guided rows' edge MAE over nearest's on the pixels "
                  "both cover.", ""]
    if "rgbnir" in result:
        lines += [f"### Real NIR reflectance (RGB-NIR pairs, planar depth; wrong: > {cm})", "",
                  "| pair | pattern | guide | valid % | wrong % | wrong & valid % | "
                  "full resolution: covered % | wrong % | RMSE cm |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for r in result["rgbnir"]:
            up = ("| " + " | ".join([_pct(r["covered"], r["pixels"]),
                                     _pct(r["up_wrong"], r["covered"]), _cm(r["up_rmse"])])
                  + " |" if "covered" in r else "| - | - | - |")
            lines.append(f"| {_name(r['pair'])} | {r['pattern']} | {r['guide']} | "
                         f"{_pct(r['valid'], r['known'])} | {_pct(r['wrong'], r['known'])} | "
                         f"{_pct(r['wrong_valid'], r['known'])} {up}")
        lines += ["", "Full resolution: `upsample_depth` of the colour-guided measurements "
                  "(`-` without the guide, which it needs).", ""]
    if "range" in result:
        walls = [r for r in result["range"] if r["case"] == "wall"]
        lines += ["### Beyond the unambiguous range: flat walls (flagged % of the measurements)",
                  "", "| pattern | source W | reflectance | " +
                  " | ".join(f"{d:g} m" for d in sorted({r['distance'] for r in walls})) + " |",
                  "|---|---|---|" + "---|" * len({r['distance'] for r in walls})]
        keys = sorted({(r["pattern"], r["power_w"], r["reflectance"]) for r in walls})
        for p, w, rho in keys:
            cells = [r for r in walls if (r["pattern"], r["power_w"], r["reflectance"]) ==
                     (p, w, rho)]
            cells.sort(key=lambda r: r["distance"])
            lines.append(f"| {p} | {w:g} | {rho:g} | " +
                         " | ".join(_pct(r["flagged"], r["n"]) for r in cells) + " |")
        lines.append("")
        below = [r for r in result["range"] if r["case"] == "below"]
        if below:
            lines += ["| pattern | source W | wall m (reflectance 1, in range) | read < U/2 % | "
                      "of those flagged % | flagged % |", "|---|---|---|---|---|---|"]
            for r in below:
                lines.append(f"| {r['pattern']} | {r['power_w']:g} | {r['distance']:g} | "
                             f"{_pct(r['read_near'], r['n'])} | "
                             f"{_pct(r['read_near_flagged'], r['read_near'])} | "
                             f"{_pct(r['flagged'], r['n'])} |")
            lines.append("")
        scaled = [r for r in result["range"] if r["case"] == "scene x4"]
        if scaled:
            lines += ["| scene x4 | pattern | source W | Z pixels beyond the range | flagged % | "
                      "partly beyond | flagged % | in range: valid % |",
                      "|---|---|---|---|---|---|---|---|"]
            for r in scaled:
                lines.append(f"| {r['scene']} | {r['pattern']} | {r['power_w']:g} | {r['n']} | "
                             f"{_pct(r['flagged'], r['n'])} | {r['partly']} | "
                             f"{_pct(r['partly_flagged'], r['partly'])} | "
                             f"{_pct(r['inside_valid'], r['inside'])} |")
            lines.append("")
    if "noise" in result:
        lines += ["### Depth noise on flat walls (reflectance 0.5)", "",
                  "| pattern | distance m | DSNU, PRNU | guide | valid % | std of valid depths mm "
                  "| predicted sigma mm | ratio |", "|---|---|---|---|---|---|---|---|"]
        for r in result["noise"]:
            ratio = r["std"] / r["sigma"] if r["n"] > 1 else np.nan
            lines.append(f"| {r['pattern']} | {r['distance']:g} | {'on' if r['fpn'] else 'off'} "
                         f"| {r.get('guide', 'none')} | {100 * r['valid']:.1f} | "
                         f"{1e3 * r['std']:.2f} | {1e3 * r['sigma']:.2f} | {ratio:.3f} |")
        lines.append("")
    if "sunlight" in result:
        rows = result["sunlight"]
        ds = sorted({r["distance"] for r in rows})
        lines += ["### Sunlight: Mask2, 15 W/m^2 in band, reflectance 0.5 (valid %)", "",
                  "| sensor | " + " | ".join(f"{d:g} m" for d in ds) + " |",
                  "|---|" + "---|" * len(ds)]
        for label in dict.fromkeys(r["config"] for r in rows):
            cells = sorted((r for r in rows if r["config"] == label), key=lambda r: r["distance"])
            lines.append(f"| {label} | " + " | ".join(f"{100 * r['valid']:.1f}" for r in cells)
                         + " |")
        lines.append("")
    if "calibration" in result:
        lines += ["### Calibration (Mask2, harmonics 3 and 5, tap mismatch, delays)", "",
                  "| ISP | positions | cyclic error RMS mm | peak mm | mean offset mm | "
                  "mean error RMS mm | RMS of all errors mm |",
                  "|---|---|---|---|---|---|---|"]
        for r in result["calibration"]:
            if r["isp"] == "fit":
                continue
            lines.append(f"| {r['isp']} | {r['positions']} | {1e3 * r['cyclic_rms']:.3f} | "
                         f"{1e3 * r['cyclic_peak']:.3f} | {1e3 * r['offset']:.3f} | "
                         f"{1e3 * r['bias_rms']:.3f} | {1e3 * r['error_rms']:.3f} |")
        lines.append("")
    return "\n".join(lines)
