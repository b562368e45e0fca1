"""Measuring the ToF chain: the numbers of docs/reports/isp.md, "Measured", in one reproducible run.

:func:`evaluate_depth` simulates what each measurement needs (the scenes'
taps know their truth, ``ToFTaps.depth_true`` and ``valid``; the ISP never
reads them) and runs the ToF ISP at its defaults. Sections:

* ``scenes`` -- the Middlebury RGB-D scenes of ``data`` (the six of
  ``../shared/data/rgbd``), Mask1 and Mask2, each frame ``simulate(scene,
  pattern, seed=seed)`` run without and with its guide ``ColourISP().run(frame)``:
  the share of known measurements that are valid, wrong (``|error| >
  tolerance``, 5 cm), wrong *and* valid, and the share of the wrong ones that
  are flagged ("caught");
* ``upsample`` -- the same frames at full resolution: nearest-neighbour and
  bilinear upsampling of the guided ISP's valid measurements against
  :func:`rgbz_fast.tof.upsample_depth` (coverage of the known pixels, share off,
  RMSE, the edge-weighted MAE);
* ``rgbnir`` -- the EPFL RGB-NIR pairs (``rgbnir`` beside ``data``): real NIR
  reflectances, a planar depth, without and with the guide;
* ``range`` -- depths beyond the unambiguous range: flat walls from 7.5 to
  15 m at NIR reflectance 0.2, 0.5 and 1 with the default source and a 10x
  stronger one, walls just below the range, and the Middlebury scenes moved 4x
  farther: the share of beyond-range measurements flagged;
* ``noise`` -- flat walls: the spread of the valid depths against the ISP's
  predicted ``sigma`` (the analytic noise through the denoise's weights),
  without and with the guide;
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

from .._patterns import check_z_patterns
from .._validate import check_entries, check_number, check_path, check_seed
from ..isp import ColourISP
from ..simulation import Scene, ToFSensor, load_rgbd, simulate, simulate_tof
from ..tof import FLAG_LOW_SIGNAL, FLAG_OUT_OF_RANGE, ToFISP, calibrate
from ._config import Z_WHY
from ._depth_guided import (pooled_scores, rgbnir_rows, scene_folders, scene_row, scene_runs,
                            total_rows, upsample_rows, valid_errors)
from ._depth_report import depth_report

__all__ = ["evaluate_depth", "depth_report", "DEPTH_SECTIONS", "RGBD_SCENES"]

DEPTH_SECTIONS = ("scenes", "upsample", "rgbnir", "range", "noise", "sunlight", "calibration")
#: the six Middlebury scenes of ../shared/data/rgbd (the sections run every scene folder
#: of ``data``)
RGBD_SCENES = ("aloe", "art", "baby1", "bowling1", "flowerpots", "rocks1")
_SCENE_KEYS = ("known", "valid", "wrong", "wrong_valid", "saturated", "low_signal",
               "inconsistent", "flying", "out_of_range", "resolved")


def _wall(depth, pattern, shape, sensor=None, *, seed=0, ir=0.5, noise=True):
    depth = np.broadcast_to(np.asarray(depth, np.float64), shape)
    scene = Scene(np.full(shape + (3,), 0.5), depth=depth, ir_reflectance=np.full(shape, ir))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # beyond-range walls warn by design
        return simulate_tof(scene, pattern, sensor, seed=seed, noise=noise)


def _scene_tables(data, patterns, isp, seed, tolerance, limits, want_upsample):
    """The scenes rows (without and with the guide, and their totals) and the upsample rows."""
    rows, up, errors = [], [], {}
    for run in scene_runs(data, patterns, isp, seed, limits):
        rows += [scene_row(run, run["plain"], tolerance), scene_row(run, run["guided"],
                                                                     tolerance)]
        for guide, res in (("none", run["plain"]), ("colour", run["guided"])):
            errors.setdefault((run["pattern"], guide), []).append(valid_errors(run, res))
        if want_upsample:
            up += upsample_rows(run, tolerance)
    totals = total_rows(rows, _SCENE_KEYS, ("pattern", "guide"))
    for t in totals:
        sel = [r for r in rows if (r["pattern"], r["guide"]) == (t["pattern"], t["guide"])]
        # over the valid measurements of every scene, pooled: a number when any scene has
        # one (the totals had been NaN always, which --json printed as NaN, not JSON)
        err = np.concatenate(errors[t["pattern"], t["guide"]])
        t.update(depth_min=min(r["depth_min"] for r in sel),
                 depth_max=max(r["depth_max"] for r in sel),
                 rmse_valid=float(np.sqrt(np.mean(err ** 2))) if err.size else np.nan,
                 median_valid=float(np.median(err)) if err.size else np.nan)
    keys = ("known", "covered", "wrong", "sq_err", "edge_weight", "edge_err")
    both = ("edge_weight_both", "edge_err_both", "edge_err_nearest_both")
    up_totals = []
    for pattern in patterns:
        for method in ("nearest", "bilinear", "guided"):
            sel = [r for r in up if (r["pattern"], r["method"]) == (pattern, method)]
            if sel:
                # RMSE and edge MAE pooled from the scenes' sums (they had been NaN, blank
                # cells in the report)
                t = pooled_scores({"scene": "all", "pattern": pattern, "method": method,
                                   **{k: sum(r[k] for r in sel) for k in keys}})
                if method == "guided":
                    t.update({k: sum(r[k] for r in sel) for k in both})
                up_totals.append(t)
    return rows + totals, up + up_totals


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
        for name in scene_folders(data):
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


#: frames per wall of the guided noise rows: its window holds 5x the measurements of the
#: unguided one (Mask2; 9x on Mask1 since its guided window is 31 cells), so a wall gives
#: that many times fewer independent depths to measure their spread
GUIDED_NOISE_FRAMES = 4


def _noise_rows(isp, seed):
    rows = []
    # (distance, seed offset): the near walls, where PRNU dominates, came last and keep the
    # other walls' seeds
    for pattern, shape, distances in (
            ("mask1", (256, 256), ((0.3, 4), (0.5, 0), (1.0, 1), (1.5, 2), (2.0, 3))),
            ("mask2", (384, 384), ((0.5, 4), (1.0, 0), (2.0, 1), (3.0, 2), (4.0, 3)))):
        for d, k in distances:
            for fpn in (True, False):
                sensor = ToFSensor() if fpn else ToFSensor(dsnu=0.0, prnu=0.0)
                scene = Scene(np.full(shape + (3,), 0.5), depth=np.full(shape, d),
                              ir_reflectance=np.full(shape, 0.5))
                for guide in ("none", "colour"):
                    errs, sig, valid = [], [], []
                    for j in range(1 if guide == "none" else GUIDED_NOISE_FRAMES):
                        frame = simulate(scene, pattern, tof_sensor=sensor,
                                         seed=seed + k + 1000 * j)
                        tof = frame.tof
                        res = isp.run(tof, guide=ColourISP().run(frame)
                                      if guide == "colour" else None)
                        r, c = tof.sites
                        margin = 6 * tof.block * 2
                        inner = ((r >= margin) & (r < shape[0] - margin) & (c >= margin)
                                 & (c < shape[1] - margin) & res.valid)
                        errs.append(res.depth[inner] - d)
                        sig.append(res.sigma[inner])
                        valid.append(res.valid)
                    err, sig = np.concatenate(errs), np.concatenate(sig)
                    rows.append({"pattern": pattern, "distance": d, "fpn": fpn, "guide": guide,
                                 "frames": len(errs), "n": int(err.size),
                                 "std": float(err.std()) if err.size > 1 else np.nan,
                                 "sigma": float(np.sqrt(np.mean(sig ** 2)))
                                 if sig.size else np.nan,
                                 "valid": float(np.concatenate(valid).mean())})
    return rows


#: the sensors of the sunlight section; the last two are docs/guide/sensor.md's "sunlight"
#: configurations (a suppression of 0.9 with the burst drains the weakest taps of the near walls
#: below the ADC's floor, which flags them: it had passed them, their depth biased)
SUNLIGHT_SENSORS = {"continuous wave (default)": {},
                    "suppression 0.9": {"ambient_suppression": 0.9},
                    "burst 0.1": {"duty_cycle": 0.1},
                    "burst 0.1 + suppression 0.5": {"duty_cycle": 0.1,
                                                    "ambient_suppression": 0.5}}


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


#: the sections whose rows count measurements "wrong" (an error above ``tolerance``)
WRONG_SECTIONS = ("scenes", "upsample", "rgbnir")
#: the sections that measure ``patterns`` (the others measure Mask1 and Mask2)
PATTERN_SECTIONS = ("scenes", "upsample", "rgbnir")
#: the patterns of the pattern sections when none are given
DEFAULT_PATTERNS = ("mask1", "mask2")


def reads_data(sections, rgbnir=None):
    """Whether a section of ``sections`` reads the RGB-D scenes' folder: scenes, upsample,
    range (its scenes 4x farther), or rgbnir without a folder of its own (the pairs
    beside it)."""
    return bool({"scenes", "upsample", "range"} & set(sections)
                or ("rgbnir" in sections and rgbnir is None))


def check_unread(sections, patterns=None, rgbnir=None, data=None):
    """A ValueError naming ``patterns``, ``rgbnir`` or ``data`` when it is given (not None)
    and no section of ``sections`` (checked names) reads it: it would be ignored. ``rgbz-fast
    evaluate-depth`` refuses its --patterns, --rgbnir and --data by it, in the command's
    words."""
    listed = ",".join(sections)
    if data is not None and not reads_data(sections, rgbnir):
        raise ValueError(f"data: the sections {listed} do not read the RGB-D scenes; data= "
                         "applies to scenes, upsample, range (its scenes 4x farther) and "
                         "rgbnir (the pairs beside it)")
    if patterns is not None and not set(PATTERN_SECTIONS) & set(sections):
        raise ValueError(f"patterns: the sections {listed} measure mask1 and mask2; "
                         "patterns= applies to scenes, upsample and rgbnir")
    if rgbnir is not None and "rgbnir" not in sections:
        raise ValueError(f"rgbnir: the sections {listed} do not read the RGB-NIR pairs; "
                         "rgbnir= applies to the rgbnir section")


def evaluate_depth(data=None, *, sections=DEPTH_SECTIONS, patterns=None, isp=None,
                   seed=1, tolerance=0.05, rgbnir=None, max_pixels=None,
                   max_bytes=None):
    """Run the depth measurements of docs/reports/isp.md; returns ``{section: [row dict, ...]}``.

    Parameters
    ----------
    data : str or Path, optional
        The folder of the Middlebury scenes (``../shared/data/rgbd``: every
        sub-folder with rgb.png, disp1.png and dmin.txt); None skips the
        sections that need it (``scenes``, ``upsample``, ``rgbnir`` and the
        scaled scenes of ``range``).
    sections : sequence of str
        Some of :data:`DEPTH_SECTIONS`.
    patterns : sequence of str, optional
        Patterns of the ``scenes``, ``upsample`` and ``rgbnir`` sections (None: Mask1 and
        Mask2); the other sections measure Mask1 and Mask2, and ``patterns`` given without
        any of those three sections is refused (ValueError), as it would be ignored.
    isp : ToFISP, optional
        The ISP (default ``ToFISP()``: the library's defaults).
    seed : int
        Noise seed of the simulations.
    rgbnir : str or Path, optional
        The folder of the RGB-NIR pairs of the ``rgbnir`` section (default:
        ``rgbnir`` beside ``data``); the section is skipped where it does not
        exist. Given without the ``rgbnir`` section, it is refused (ValueError).
    tolerance : float
        An error above it (m) is "wrong" (0.05); the rows of the sections that count
        wrong measurements keep it (``"tolerance"``).
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
    bad = [s for s in sections if s not in DEPTH_SECTIONS]
    if bad:
        raise ValueError(f"sections: unknown {bad}; expected some of {list(DEPTH_SECTIONS)}")
    # given for sections that do not read them, they had been ignored without a word
    check_unread(sections, patterns, rgbnir, data)
    patterns = check_z_patterns(DEFAULT_PATTERNS if patterns is None else patterns,
                                "patterns", Z_WHY)
    if data is not None and not check_path(data, "data").is_dir():
        raise FileNotFoundError(f"data: {data} is not a folder")
    if rgbnir is not None and not check_path(rgbnir, "rgbnir").is_dir():
        raise FileNotFoundError(f"rgbnir: {rgbnir} is not a folder")
    out = {}
    limits = dict(max_pixels=max_pixels, max_bytes=max_bytes)
    if data is not None and ("scenes" in sections or "upsample" in sections):
        if not scene_folders(data):
            raise ValueError(f"data: no RGB-D scene in {data} (a scene is a folder holding "
                             "rgb.png, disp1.png and dmin.txt)")
        rows, up = _scene_tables(data, patterns, isp, seed, tolerance, limits,
                                 "upsample" in sections)
        if "scenes" in sections:
            out["scenes"] = rows
        if "upsample" in sections:
            out["upsample"] = up
    for s in sections:
        if s in ("scenes", "upsample"):
            continue
        if s == "rgbnir":
            folder = Path(rgbnir) if rgbnir is not None else (
                Path(data).parent / "rgbnir" if data is not None else None)
            if folder is not None and folder.is_dir():
                out[s] = rgbnir_rows(folder, patterns, isp, seed, tolerance, limits)
        elif s == "range":
            out[s] = _range_rows(data, isp, seed, limits)
        elif s == "noise":
            out[s] = _noise_rows(isp, seed)
        elif s == "sunlight":
            out[s] = _sunlight_rows(isp, seed)
        else:
            out[s] = _calibration_rows(isp, seed)
    # the rows that count "wrong" say at what error, so that depth_report labels them right
    # (it had printed a 10 cm run under "wrong: |error| > 5 cm")
    for s in WRONG_SECTIONS:
        for r in out.get(s, ()):
            r["tolerance"] = tolerance
    return out
