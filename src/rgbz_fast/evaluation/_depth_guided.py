"""The colour-guided measurements of :func:`~rgbz_fast.evaluation.evaluate_depth`: the RGB-D
scenes run the way a user runs them, the full-resolution depth, and the real-NIR cross-check.

Every frame is ``simulate(scene, pattern, seed=seed)`` (colour and ToF taps of one
exposure) and its guide ``ColourISP().run(frame)`` at the defaults: the guide is what
the chip's colour pixels give, never the scene's RGB. The Middlebury scenes have no NIR
image: their NIR reflectance is estimated from the RGB
(:func:`~rgbz_fast.simulation.estimate_ir_reflectance`), which ties the amplitude to the
colour; the ``rgbnir`` section checks the guided ISP on real NIR reflectances
(``../shared/data/rgbnir``, EPFL RGB-NIR pairs) in front of a planar depth.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..io import read_image
from ..isp import ColourISP
from ..simulation import Scene, load_image, load_rgbd, simulate
from ..tof import ToFFlag, upsample_depth

__all__ = ["scene_folders", "scene_runs", "scene_row", "upsample_rows", "rgbnir_rows",
           "upsample_baselines", "UPSAMPLE_METHODS"]

UPSAMPLE_METHODS = ("nearest", "bilinear", "guided")
_FLAGS = {"saturated": ToFFlag.SATURATED, "low_signal": ToFFlag.LOW_SIGNAL,
          "inconsistent": ToFFlag.INCONSISTENT, "flying": ToFFlag.FLYING,
          "out_of_range": ToFFlag.OUT_OF_RANGE, "resolved": ToFFlag.RESOLVED}


def scene_folders(data):
    """The RGB-D scene folders of ``data`` (each holds rgb.png, disp1.png, dmin.txt), by name."""
    need = ("rgb.png", "disp1.png", "dmin.txt")
    return sorted(p.name for p in Path(data).iterdir()
                  if p.is_dir() and all((p / n).is_file() for n in need))


def scene_runs(data, patterns, isp, seed, limits):
    """Per scene and pattern: the frame, its guide and the ISP's result without and with it."""
    for name in scene_folders(data):
        scene = load_rgbd(Path(data) / name, **limits)
        for pattern in patterns:
            frame = simulate(scene, pattern, seed=seed)
            if not frame.tof.valid.any():
                raise ValueError(
                    f"data: scene {Path(data) / name}: none of its {frame.tof.n_sites} Z "
                    f"measurements ({pattern}) has a known depth within the "
                    f"{frame.tof.sensor.unambiguous_range:.4g} m unambiguous range; there is "
                    "nothing to score (move the scene out of the folder)")
            guide = ColourISP().run(frame)
            yield {"scene": name, "pattern": pattern, "depth": scene.depth,
                   "depth_valid": scene.depth_valid, "tof": frame.tof, "guide": guide,
                   "plain": isp.run(frame.tof), "guided": isp.run(frame.tof, guide=guide)}


def valid_errors(run, res):
    """|depth error| of the valid measurements of ``res`` whose truth is known: what a scene
    row's RMSE and median are of, and what the totals pool."""
    tof = run["tof"]
    return np.abs(res.depth - tof.depth_true)[res.valid & tof.valid]


def scene_row(run, res, tolerance):
    """One row of the scenes table: counts over the measurements whose truth is known."""
    tof = run["tof"]
    known = tof.valid
    err = res.depth - tof.depth_true
    wrong = (np.abs(err) > tolerance) & known
    ok = res.valid & known
    good = valid_errors(run, res)
    row = {"scene": run["scene"], "pattern": run["pattern"],
           "guide": "colour" if res is run["guided"] else "none", "known": int(known.sum()),
           "valid": int(ok.sum()), "wrong": int(wrong.sum()),
           "wrong_valid": int((wrong & res.valid).sum()),
           "depth_min": float(tof.depth_true[known].min()),
           "depth_max": float(tof.depth_true[known].max()),
           "rmse_valid": float(np.sqrt(np.mean(good ** 2))) if good.size else np.nan,
           "median_valid": float(np.median(good)) if good.size else np.nan}
    for key, bit in _FLAGS.items():
        row[key] = int(((res.flags & bit) > 0)[known].sum())
    return row


def upsample_baselines(res):
    """Nearest-neighbour and bilinear upsampling of the valid measurements of ``res`` to its
    frame: (nearest, bilinear) float64 maps, NaN where a method gives nothing.

    Nearest: the value of the nearest valid measurement (centres of the Z pixels, Euclidean
    distance in pixels; ties as ``scipy.ndimage.distance_transform_edt`` breaks them),
    everywhere. Bilinear: the bilinear weights of the four measurements
    around the pixel over the valid ones among them; NaN where none of the four is valid.
    """
    from scipy import ndimage                  # noqa: PLC0415 (an evaluation dependency)

    r, c = (np.asarray(a) for a in res.sites)
    rows, cols = np.unique(r), np.unique(c)
    grid = np.full((rows.size, cols.size), np.nan)
    grid[np.searchsorted(rows, r), np.searchsorted(cols, c)] = np.where(res.valid, res.depth,
                                                                        np.nan)
    half = 0.5 * (res.block - 1)
    rc, cc = rows + half, cols + half
    H, W = res.shape
    fy = np.interp(np.arange(H), rc, np.arange(rows.size))
    fx = np.interp(np.arange(W), cc, np.arange(cols.size))
    valid = np.isfinite(grid)
    if not valid.any():
        nothing = np.full((H, W), np.nan)
        return nothing, nothing.copy()
    # the nearest valid measurement of every pixel, exactly: the Euclidean distance transform
    # of the valid centres on a grid fine enough to hold them (the centres of 2x2 Z pixels lie
    # between pixels: a grid of half pixels), read at the pixels (before, the 2 x 2 nodes around
    # a pixel and their own nearest valid nodes: another measurement at 37-1194 pixels a scene)
    s = 2 if res.block % 2 == 0 else 1
    cy = np.rint(s * (r[res.valid] + half)).astype(np.intp)
    cx = np.rint(s * (c[res.valid] + half)).astype(np.intp)
    fine = np.ones((s * (H - 1) + 1, s * (W - 1) + 1), bool)
    fine[cy, cx] = False
    value = np.full(fine.shape, np.nan)
    value[cy, cx] = res.depth[res.valid]
    _, (ii, jj) = ndimage.distance_transform_edt(fine, return_indices=True)
    nearest = value[ii[::s, ::s], jj[::s, ::s]]
    del ii, jj
    y0 = np.clip(np.floor(fy).astype(int), 0, rows.size - 1)
    x0 = np.clip(np.floor(fx).astype(int), 0, cols.size - 1)
    ty = (fy - y0)[:, None]
    tx = (fx - x0)[None, :]
    num = np.zeros((H, W))
    den = np.zeros((H, W))
    for yy, wy in ((y0, 1 - ty), (np.minimum(y0 + 1, rows.size - 1), ty)):
        for xx, wx in ((x0, 1 - tx), (np.minimum(x0 + 1, cols.size - 1), tx)):
            v = grid[yy][:, xx]
            w = wy * wx * np.isfinite(v)
            num += np.where(np.isfinite(v), v, 0.0) * w
            den += w
    bilinear = np.divide(num, den, out=np.full((H, W), np.nan), where=den > 0)
    return nearest, bilinear


def _scores(est, truth, known, weight, tolerance):
    cov = known & np.isfinite(est)
    e = np.abs(est - truth)[cov]
    w = weight[cov]
    # the sums too, so that the totals over scenes pool them (pooled_scores)
    return pooled_scores({"known": int(known.sum()), "covered": int(cov.sum()),
                          "wrong": int((e > tolerance).sum()), "sq_err": float((e * e).sum()),
                          "edge_weight": float(w.sum()), "edge_err": float((w * e).sum())})


def pooled_scores(row):
    """``row`` with its RMSE and edge-weighted MAE from its sums (``sq_err`` over ``covered``
    pixels, ``edge_err`` over ``edge_weight``): NaN where there is nothing to average."""
    row["rmse"] = float(np.sqrt(row["sq_err"] / row["covered"])) if row["covered"] else np.nan
    row["edge_mae"] = (row["edge_err"] / row["edge_weight"] if row["edge_weight"] > 0
                       else np.nan)
    return row


def upsample_rows(run, tolerance):
    """The upsample table's rows of one scene and pattern: nearest, bilinear and guided
    upsampling of the guided ISP's measurements, each scored on the pixels it covers; the
    guided row also holds both edge-weighted MAEs on the pixels the nearest covers too."""
    res, truth, known = run["guided"], run["depth"], run["depth_valid"]
    gy, gx = np.gradient(truth)
    weight = np.hypot(gy, gx)
    nearest, bilinear = upsample_baselines(res)
    guided, _ = upsample_depth(res, run["guide"])
    guided = guided.astype(np.float64)
    rows = []
    for method, est in zip(UPSAMPLE_METHODS, (nearest, bilinear, guided)):
        row = {"scene": run["scene"], "pattern": run["pattern"], "method": method}
        row.update(_scores(est, truth, known, weight, tolerance))
        rows.append(row)
    both = known & np.isfinite(guided) & np.isfinite(nearest)
    w = weight[both]
    # the sums, so that totals over scenes pool them
    rows[-1].update(edge_weight_both=float(w.sum()),
                    edge_err_both=float((w * np.abs(guided - truth)[both]).sum()),
                    edge_err_nearest_both=float((w * np.abs(nearest - truth)[both]).sum()))
    return rows


def total_rows(rows, keys, by):
    """Sums of ``keys`` over the rows of each value of ``by`` (tuple of fields)."""
    out = []
    for group in dict.fromkeys(tuple(r[k] for k in by) for r in rows):
        sel = [r for r in rows if tuple(r[k] for k in by) == group]
        total = dict(zip(by, group), scene="all")
        for k in keys:
            total[k] = sum(r[k] for r in sel)
        out.append(total)
    return out


#: the planar depth of the rgbnir section: a plane tilted from 1.2 m (top) to 2.0 m (bottom)
RGBNIR_DEPTH = (1.2, 2.0)


def rgbnir_pairs(folder):
    """The RGB images of the RGB-NIR pairs of ``folder`` (``NNNN_rgb.png`` beside
    ``NNNN_nir.png``), sorted."""
    return sorted(p for p in Path(folder).glob("*_rgb.png")
                  if (p.parent / p.name.replace("_rgb", "_nir")).is_file())


def rgbnir_rows(folder, patterns, isp, seed, tolerance, limits):
    """The guided ISP on the real NIR reflectances of the RGB-NIR pairs of ``folder`` in front
    of a tilted plane: valid, wrong, wrong and valid (without and with the guide), and the
    guided upsampling's coverage, share off and RMSE."""
    rows = []
    for rgb in rgbnir_pairs(folder):
        nir = read_image(rgb.parent / rgb.name.replace("_rgb", "_nir"), "rgbnir", **limits)
        if nir.ndim == 3:
            nir = nir[..., 0]
        nir = nir.astype(np.float64) / np.iinfo(nir.dtype).max if nir.dtype.kind == "u" \
            else nir.astype(np.float64)
        H, W = nir.shape
        near, far = RGBNIR_DEPTH
        plane = np.broadcast_to(np.linspace(near, far, H)[:, None], (H, W))
        base = load_image(rgb, **limits)
        scene = Scene(base.image, depth=plane, ir_reflectance=nir,
                      name=rgb.stem.replace("_rgb", ""))
        for pattern in patterns:
            frame = simulate(scene, pattern, seed=seed)
            guide = ColourISP().run(frame)
            tof = frame.tof
            known = tof.valid
            for label, res in (("none", isp.run(tof)), ("colour", isp.run(tof, guide=guide))):
                err = np.abs(res.depth - tof.depth_true)
                wrong = (err > tolerance) & known
                row = {"pair": scene.name, "pattern": pattern, "guide": label,
                       "known": int(known.sum()), "valid": int((res.valid & known).sum()),
                       "wrong": int(wrong.sum()), "wrong_valid": int((wrong & res.valid).sum())}
                if label == "colour":
                    up, _ = upsample_depth(res, guide)
                    s = _scores(up.astype(np.float64), plane, np.ones((H, W), bool),
                                np.ones((H, W)), tolerance)
                    row.update(pixels=s["known"], covered=s["covered"], up_wrong=s["wrong"],
                               up_rmse=s["rmse"])
                rows.append(row)
    return rows
