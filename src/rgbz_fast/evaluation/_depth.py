"""Measuring the ToF chain: the numbers of docs/reports/isp.md, "Measured", in one reproducible run.

:func:`evaluate_depth` simulates what each measurement needs (the scenes'
taps know their truth, ``ToFTaps.depth_true`` and ``valid``; the ISP never
reads them) and runs the ToF ISP at its defaults. Sections:

* ``scenes`` -- the six Middlebury RGB-D scenes (``../shared/data/rgbd``),
  Mask1 and Mask2: the share of known measurements that are valid, wrong
  (``|error| > tolerance``, 5 cm), wrong *and* valid, and the share of the
  wrong ones that are flagged ("caught");
* ``range`` -- depths beyond the unambiguous range: flat walls from 7.5 to
  15 m at NIR reflectance 0.2, 0.5 and 1 with the default source and a 10x
  stronger one, walls just below the range, and the Middlebury scenes moved 4x
  farther: the share of beyond-range measurements flagged;
* ``noise`` -- flat walls: the spread of the valid depths against the ISP's
  predicted ``sigma`` (the analytic noise through the denoise's weights);
* ``sunlight`` -- Mask2 walls at 15 W/m^2 in-band ambient light, reflectance
  0.5: the valid share by distance without and with ambient suppression or
  burst illumination;
* ``calibration`` -- a sensor with harmonics, tap-contrast mismatch and
  per-pixel delays: the cyclic error before and after :func:`rgbz_fast.tof.calibrate`,
  measured on a sweep the fit did not see.

``rgbz-fast evaluate-depth`` runs it and prints the tables.
"""

from __future__ import annotations

import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np

from .._patterns import get_pattern
from .._validate import check_entries, check_number, check_path, check_seed
from ..simulation import Scene, ToFSensor, load_rgbd, simulate_tof
from ..tof import (FLAG_FLYING, FLAG_INCONSISTENT, FLAG_LOW_SIGNAL, FLAG_OUT_OF_RANGE,
                   FLAG_SATURATED, ToFISP, calibrate)

__all__ = ["evaluate_depth", "depth_report", "DEPTH_SECTIONS", "RGBD_SCENES"]

DEPTH_SECTIONS = ("scenes", "range", "noise", "sunlight", "calibration")
#: the six Middlebury scenes of ../shared/data/rgbd
RGBD_SCENES = ("art", "aloe", "baby1", "bowling1", "flowerpots", "rocks1")
_FLAGS = {"saturated": FLAG_SATURATED, "low_signal": FLAG_LOW_SIGNAL,
          "inconsistent": FLAG_INCONSISTENT, "flying": FLAG_FLYING,
          "out_of_range": FLAG_OUT_OF_RANGE}


def _wall(depth, pattern, shape, sensor=None, *, seed=0, ir=0.5, noise=True):
    depth = np.broadcast_to(np.asarray(depth, np.float64), shape)
    scene = Scene(np.full(shape + (3,), 0.5), depth=depth, ir_reflectance=np.full(shape, ir))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # beyond-range walls warn by design
        return simulate_tof(scene, pattern, sensor, seed=seed, noise=noise)


def _scene_rows(data, patterns, isp, seed, tolerance, limits):
    rows = []
    for name in RGBD_SCENES:
        scene = load_rgbd(Path(data) / name, **limits)
        for pattern in patterns:
            tof = simulate_tof(scene, pattern, seed=seed)
            res = isp.run(tof)
            known = tof.valid
            err = res.depth - tof.depth_true
            wrong = (np.abs(err) > tolerance) & known
            ok = res.valid & known
            row = {"scene": name, "pattern": pattern, "known": int(known.sum()),
                   "valid": int(ok.sum()), "wrong": int(wrong.sum()),
                   "wrong_valid": int((wrong & res.valid).sum()),
                   "depth_min": float(tof.depth_true[known].min()),
                   "depth_max": float(tof.depth_true[known].max()),
                   "rmse_valid": float(np.sqrt(np.mean(err[ok] ** 2))) if ok.any() else np.nan,
                   "median_valid": float(np.median(np.abs(err[ok]))) if ok.any() else np.nan}
            for key, bit in _FLAGS.items():
                row[key] = int(((res.flags & bit) > 0)[known].sum())
            rows.append(row)
    for pattern in patterns:
        sel = [r for r in rows if r["pattern"] == pattern]
        total = {"scene": "all", "pattern": pattern}
        for key in ("known", "valid", "wrong", "wrong_valid") + tuple(_FLAGS):
            total[key] = sum(r[key] for r in sel)
        total.update(depth_min=min(r["depth_min"] for r in sel),
                     depth_max=max(r["depth_max"] for r in sel), rmse_valid=np.nan,
                     median_valid=np.nan)
        rows.append(total)
    return rows


def _range_rows(data, isp, seed, limits):
    rows = []
    u = ToFSensor().unambiguous_range
    for power in (0.5, 5.0):
        sensor = ToFSensor(optical_power_w=power)
        for pattern, shape in (("mask1", (48, 64)), ("mask2", (96, 128))):
            for rho in (0.2, 0.5, 1.0):
                for d in (7.5, 8.0, 9.0, 10.0, 12.0, 15.0):
                    tof = _wall(d, pattern, shape, sensor, seed=seed, ir=rho)
                    res = isp.run(tof)
                    rows.append({"case": "wall", "pattern": pattern, "power_w": power,
                                 "reflectance": rho, "distance": d, "n": tof.n_sites,
                                 "flagged": int((~res.valid).sum()),
                                 "out_of_range": int(((res.flags & FLAG_OUT_OF_RANGE) > 0).sum()),
                                 "low_signal": int(((res.flags & FLAG_LOW_SIGNAL) > 0).sum())})
    # just below the range: noise may wrap the unwrapping to ~0 m
    for power in (0.5, 5.0):
        for pattern, shape in (("mask1", (48, 64)), ("mask2", (96, 128))):
            for d in (7.3, 7.45):
                tof = _wall(d, pattern, shape, ToFSensor(optical_power_w=power), seed=seed,
                            ir=1.0)
                res = isp.run(tof)
                near = res.depth < u / 2
                rows.append({"case": "below", "pattern": pattern, "power_w": power,
                             "reflectance": 1.0, "distance": d, "n": tof.n_sites,
                             "read_near": int(near.sum()),
                             "read_near_flagged": int((near & ~res.valid).sum()),
                             "flagged": int((~res.valid).sum())})
    # the Middlebury scenes 4x farther (4.6-9.4 m): part of every scene is beyond the range
    if data is not None:
        for name in RGBD_SCENES:
            scene = load_rgbd(Path(data) / name, **limits)
            far = Scene(scene.image, depth=scene.depth * 4.0, depth_valid=scene.depth_valid,
                        name=name)
            for pattern in ("mask1", "mask2"):
                for power in (0.5, 5.0):
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        tof = simulate_tof(far, pattern, ToFSensor(optical_power_w=power),
                                           seed=seed)
                    res = isp.run(tof)
                    # every cell of the Z pixel beyond the range (the surface is), or only
                    # some (a mixture whose in-range part may dominate and read right)
                    r, c = tof.sites
                    b = tof.block
                    cells = np.stack([far.depth[r + i, c + j] for i in range(b)
                                      for j in range(b)])
                    known = np.stack([far.depth_valid[r + i, c + j] for i in range(b)
                                      for j in range(b)]).all(axis=0)
                    beyond = known & np.all(cells >= u, axis=0)
                    partly = known & np.any(cells >= u, axis=0) & ~beyond
                    inside = tof.valid
                    rows.append({"case": "scene x4", "scene": name, "pattern": pattern,
                                 "power_w": power, "n": int(beyond.sum()),
                                 "flagged": int((beyond & ~res.valid).sum()),
                                 "partly": int(partly.sum()),
                                 "partly_flagged": int((partly & ~res.valid).sum()),
                                 "inside": int(inside.sum()),
                                 "inside_valid": int((inside & res.valid).sum())})
    return rows


def _noise_rows(isp, seed):
    rows = []
    for pattern, shape, distances in (("mask1", (256, 256), (0.5, 1.0, 1.5, 2.0)),
                                      ("mask2", (384, 384), (1.0, 2.0, 3.0, 4.0))):
        for k, d in enumerate(distances):
            for fpn in (True, False):
                sensor = ToFSensor() if fpn else ToFSensor(dsnu=0.0, prnu=0.0)
                tof = _wall(d, pattern, shape, sensor, seed=seed + k)
                res = isp.run(tof)
                r, c = tof.sites
                margin = 6 * tof.block * 2
                inner = ((r >= margin) & (r < shape[0] - margin) & (c >= margin)
                         & (c < shape[1] - margin) & res.valid)
                err = res.depth[inner] - d
                rows.append({"pattern": pattern, "distance": d, "fpn": fpn,
                             "n": int(inner.sum()),
                             "std": float(err.std()) if inner.sum() > 1 else np.nan,
                             "sigma": float(np.sqrt(np.mean(res.sigma[inner] ** 2)))
                             if inner.any() else np.nan,
                             "valid": float(res.valid.mean())})
    return rows


#: the sensors of the sunlight section; the last is docs/guide/sensor.md's "sunlight" configuration
SUNLIGHT_SENSORS = {"continuous wave (default)": {},
                    "suppression 0.9": {"ambient_suppression": 0.9},
                    "burst 0.1": {"duty_cycle": 0.1},
                    "burst 0.1 + suppression 0.9": {"duty_cycle": 0.1,
                                                    "ambient_suppression": 0.9}}


def _sunlight_rows(isp, seed):
    rows = []
    for label, kw in SUNLIGHT_SENSORS.items():
        sensor = ToFSensor(ambient_irradiance=15.0, **kw)
        for d in (0.3, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0):
            tof = _wall(d, "mask2", (96, 128), sensor, seed=seed)
            res = isp.run(tof)
            rows.append({"config": label, "distance": d, "valid": float(res.valid.mean()),
                         "saturated": float(np.mean(tof.saturated))})
    return rows


#: the non-ideal sensor of the calibration section
CALIBRATION_SENSOR = dict(harmonics=((3, 0.04, 0.3), (5, 0.015, -0.5)),
                          tap_contrast=(1.0, 0.97, 1.02, 0.99), delay_ps=300.0,
                          delay_fpn_ps=20.0)


def _cyclic_stats(frames, distances, isp):
    """Per-distance mean error over the valid measurements of every frame at that distance,
    and every error."""
    per_d, every = {}, []
    for tof, d in zip(frames, distances):
        res = isp.run(tof)
        e = res.depth[res.valid] - d
        per_d.setdefault(d, []).append(e)
        every.append(e)
    means = np.array([np.concatenate(v).mean() for v in per_d.values()])
    return means, np.concatenate(every)


def _calibration_rows(isp, seed):
    """Fit on 48 positions x 3 frames from 0.6 to 2.6 m (a little more than the 1.874 m wrap
    range of 80 MHz), check on 25 other positions x 4 frames; 8 dark frames."""
    sensor = ToFSensor(**CALIBRATION_SENSOR)
    fit_d = np.repeat(np.linspace(0.6, 2.6, 48), 3)
    check_d = np.repeat(np.linspace(0.62, 2.58, 25), 4)
    fit = [_wall(d, "mask2", (64, 96), sensor, seed=seed + 1000 + k, ir=0.8)
           for k, d in enumerate(fit_d)]
    # dark frames: the lens capped (no laser, no ambient light): DSNU and dark current
    capped = replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0)
    dark = [_wall(1.0, "mask2", (64, 96), capped, seed=seed + 3000 + k) for k in range(8)]
    cal = calibrate(fit, fit_d, dark=dark)
    check = [_wall(d, "mask2", (64, 96), sensor, seed=seed + 5000 + k, ir=0.8)
             for k, d in enumerate(check_d)]
    rows = []
    for label, chain in (("uncalibrated", isp), ("calibrated", replace(isp, calibration=cal))):
        means, every = _cyclic_stats(check, check_d, chain)
        cyclic = means - means.mean()
        rows.append({"isp": label, "positions": int(means.size),
                     "cyclic_rms": float(np.sqrt(np.mean(cyclic ** 2))),
                     "cyclic_peak": float(np.abs(cyclic).max()),
                     "offset": float(means.mean()),
                     "bias_rms": float(np.sqrt(np.mean(means ** 2))),
                     "error_rms": float(np.sqrt(np.mean(every ** 2)))})
    rows.append({"isp": "fit", "positions": len(np.unique(fit_d)), "frames": len(fit_d),
                 "fit_rms_m": cal.meta["fit_rms_m"]})
    return rows


def evaluate_depth(data=None, *, sections=DEPTH_SECTIONS, patterns=("mask1", "mask2"), isp=None,
                   seed=1, tolerance=0.05, max_pixels=None, max_bytes=None):
    """Run the depth measurements of docs/reports/isp.md; returns ``{section: [row dict, ...]}``.

    Parameters
    ----------
    data : str or Path, optional
        The folder of the six Middlebury scenes (``../shared/data/rgbd``);
        None skips the sections that need it (``scenes`` and the scaled scenes
        of ``range``).
    sections : sequence of str
        Some of :data:`DEPTH_SECTIONS`.
    patterns : sequence of str
        Patterns of the ``scenes`` section.
    isp : ToFISP, optional
        The ISP (default ``ToFISP()``: the library's defaults).
    seed : int
        Noise seed of the simulations.
    tolerance : float
        An error above it (m) is "wrong" (0.05).
    max_pixels, max_bytes : int, optional
        The read limits of the scenes' images (:func:`rgbz_fast.io.read_limits`).

    Returns
    -------
    dict
        One list of rows per section (see :func:`depth_report` for the columns).
    """
    isp = ToFISP() if isp is None else isp
    if not isinstance(isp, ToFISP):
        raise TypeError(f"isp: expected a ToFISP, got {type(isp).__name__}")
    seed = check_seed(seed, "seed")
    tolerance = check_number(tolerance, "tolerance", lo=0, lo_open=True)
    sections = check_entries(sections, "sections")
    patterns = check_entries(patterns, "patterns", key=get_pattern, strings=False)
    bad = [s for s in sections if s not in DEPTH_SECTIONS]
    if bad:
        raise ValueError(f"sections: unknown {bad}; expected some of {list(DEPTH_SECTIONS)}")
    if data is not None and not check_path(data, "data").is_dir():
        raise FileNotFoundError(f"data: {data} is not a folder")
    out = {}
    limits = dict(max_pixels=max_pixels, max_bytes=max_bytes)
    for s in sections:
        if s == "scenes":
            if data is not None:
                out[s] = _scene_rows(data, patterns, isp, seed, tolerance, limits)
        elif s == "range":
            out[s] = _range_rows(data, isp, seed, limits)
        elif s == "noise":
            out[s] = _noise_rows(isp, seed)
        elif s == "sunlight":
            out[s] = _sunlight_rows(isp, seed)
        else:
            out[s] = _calibration_rows(isp, seed)
    return out


def _pct(a, b):
    return f"{100.0 * a / b:.3f}" if b else "-"


def depth_report(result, tolerance=0.05):
    """Markdown tables of an :func:`evaluate_depth` result."""
    if not isinstance(result, dict) or not set(result) <= set(DEPTH_SECTIONS):
        raise TypeError(f"result: expected the dict of sections evaluate_depth returns, got "
                        f"{result!r:.60}")
    tolerance = check_number(tolerance, "tolerance", lo=0, lo_open=True)
    lines = []
    cm = f"{100 * tolerance:g} cm"
    if "scenes" in result:
        lines += [f"### Middlebury scenes (wrong: |error| > {cm})", "",
                  "| scene | pattern | depth m | valid % | wrong % | wrong & valid % | "
                  "caught % | flying % | RMSE valid cm |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for r in result["scenes"]:
            rmse = "" if np.isnan(r["rmse_valid"]) else f"{100 * r['rmse_valid']:.2f}"
            caught = _pct(r["wrong"] - r["wrong_valid"], r["wrong"])
            lines.append(f"| {r['scene']} | {r['pattern']} | {r['depth_min']:.2f}-"
                         f"{r['depth_max']:.2f} | {_pct(r['valid'], r['known'])} | "
                         f"{_pct(r['wrong'], r['known'])} | {_pct(r['wrong_valid'], r['known'])} | "
                         f"{caught} | {_pct(r['flying'], r['known'])} | {rmse} |")
        lines.append("")
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
                  "| pattern | distance m | DSNU, PRNU | valid % | std of valid depths mm | "
                  "predicted sigma mm | ratio |", "|---|---|---|---|---|---|---|"]
        for r in result["noise"]:
            ratio = r["std"] / r["sigma"] if r["n"] > 1 else np.nan
            lines.append(f"| {r['pattern']} | {r['distance']:g} | {'on' if r['fpn'] else 'off'} "
                         f"| {100 * r['valid']:.1f} | {1e3 * r['std']:.2f} | "
                         f"{1e3 * r['sigma']:.2f} | {ratio:.3f} |")
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
