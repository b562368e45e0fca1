"""The choice of the z_guided fit's ridge, prior and colour prior by cross-validation.

``train_z_guided(select="cv")`` scores every point of a grid on held-out folds of the
training scenes from their normal equations; here the same errors are measured by brute
force (a fit per fold, the held-out frames reconstructed), and the targets tool is checked
to run the same procedure on each outer fold's training pairs alone.
"""

from __future__ import annotations

import ast
import importlib.util
import itertools
import sys
from pathlib import Path

import numpy as np
import pytest

from rgbz_fast._cli import main
from rgbz_fast.reconstruction import ZGuidedFilters, train, train_z_guided
from rgbz_fast.reconstruction._z_guided import guide_grid
from rgbz_fast.reconstruction._z_guided_fit import (CV_GRID, fit_folds, fit_stats, frame_stats,
                                                    sum_stats)
from rgbz_fast.simulation import Scene, simulate

GRID = {"ridge": (1e-4, 1e-1), "prior": (12.5, 3200.0), "colour_prior": (1.0, 256.0)}
LAM = 0.01


def _scene(seed, shape=(40, 48)):
    """Colour and NIR sharing a texture of 2x2 cells, flat depth."""
    rng = np.random.default_rng(seed)
    tex = np.kron(rng.random((shape[0] // 2, shape[1] // 2)), np.ones((2, 2)))
    hue = np.kron(rng.random((shape[0] // 8, shape[1] // 8, 3)), np.ones((8, 8, 1)))
    shade = 0.3 + 0.6 * tex
    return Scene(np.clip(shade[..., None] * (0.3 + 0.7 * hue), 0, 1),
                 depth=np.full(shape, 2.0), ir_reflectance=0.1 + 0.8 * shade ** 1.3)


@pytest.fixture(scope="module")
def data():
    """Four scenes, each noise-free and noisy (one group per scene), and learned filters."""
    frames = [simulate(_scene(s), "mask1", seed=s, noise=n) for s in range(4)
              for n in (False, True)]
    groups = [s for s in range(4) for _ in (False, True)]
    base = train(frames, n_strength=1, n_coherence=2, n_spread=1)
    return frames, groups, base


def _held_out_rmse(frames, groups, base, folds, setting, guide):
    """The held-out error of ``setting`` by brute force: per fold, filters fitted on the
    other folds' frames, the fold's frames reconstructed, squared errors at the Z sites."""
    stats = [frame_stats(f, base, LAM) for f in frames]
    sse = n = 0
    for j in range(folds):
        fit = sum_stats(s for s, g in zip(stats, groups) if g % folds != j)
        f = fit_stats(fit, base, LAM, guide=guide, **setting)
        for fr, g in zip(frames, groups):
            if g % folds == j:
                out = f.reconstruct(fr.data, guide_grid(fr.shape, fr.pattern, tof=fr.tof))
                d = (out - fr.reference)[fr.z_mask]
                sse, n = sse + d @ d, n + d.size
    return np.sqrt(sse / n)


@pytest.mark.parametrize("guide", [True, False])
def test_the_choice_is_the_optimum_of_the_held_out_error(data, guide):
    frames, groups, base = data
    f = train_z_guided(frames, base=base, groups=groups, cv_folds=2, cv_grid=GRID, guide=guide)
    names = list(GRID)
    points = [dict(zip(names, p)) for p in
              itertools.product(*(GRID[k] for k in names))]
    brute = np.array([_held_out_rmse(frames, groups, base, 2, p, guide) for p in points])
    got = np.array(ast.literal_eval(f.meta["cv_rmse"]))
    # the errors from the normal equations are the measured ones (weights kept in float32)
    np.testing.assert_allclose(got, brute, rtol=1e-4)
    assert np.ptp(brute) > 0.01 * brute.min()          # the grid's points differ
    best = points[int(np.argmin(brute))]
    assert {k: f.meta[k] for k in names} == best
    assert f.meta["select"] == "cv" and f.meta["cv_folds"] == 2 and f.meta["cv_groups"] == 4
    assert f.meta["cv_grid"] == "ridge [0.0001, 0.1]; prior [12.5, 3200.0]; colour_prior " \
                                "[1.0, 256.0]"
    stats = sum_stats(frame_stats(fr, base, LAM) for fr in frames)
    assert f == fit_stats(stats, base, LAM, guide=guide, **best)


def test_the_choice_is_deterministic_and_given_values_are_kept(data):
    frames, groups, base = data
    a = train_z_guided(frames, base=base, groups=groups, cv_grid=GRID)
    b = train_z_guided(frames, base=base, groups=[f"scene {g}" for g in groups], cv_grid=GRID)
    assert a == b and a.meta == b.meta
    assert a.meta["cv_folds"] == 4                       # 4 scenes, 4 folds: one per scene
    held = train_z_guided(frames, base=base, groups=groups, cv_grid=GRID, ridge=0.5)
    assert held.meta["ridge"] == 0.5 and held.meta["cv_grid"].startswith("ridge [0.5];")
    assert len(ast.literal_eval(held.meta["cv_rmse"])) == 4
    fixed = train_z_guided(frames, base=base, select=None)
    assert (fixed.meta["select"], fixed.meta["ridge"], fixed.meta["prior"],
            fixed.meta["colour_prior"]) == ("none", 1e-3, 50.0, 4.0)
    given = train_z_guided(frames[:2], base=base, ridge=1e-3, prior=50, colour_prior=4)
    assert given.meta["select"] == "given"       # nothing to choose: one scene is enough
    assert len(CV_GRID["ridge"]) * len(CV_GRID["prior"]) * len(CV_GRID["colour_prior"]) == 100


def test_a_scene_is_never_on_both_sides_of_a_fold(data):
    """With its frames' groups, the noise-free and noisy frames of a scene share a fold; the
    fit is the one of the folds' summed equations, group i in fold i mod k."""
    frames, groups, base = data
    f = train_z_guided(frames, base=base, groups=groups, cv_folds=2, cv_grid=GRID)
    stats = [frame_stats(fr, base, LAM) for fr in frames]
    folds = [sum_stats(s for s, g in zip(stats, groups) if g % 2 == j) for j in range(2)]
    assert f == fit_folds(folds, base, LAM, cv_grid=GRID)
    alone = train_z_guided(frames, base=base, cv_folds=2, cv_grid=GRID)    # a frame a group
    assert alone.meta["cv_groups"] == 8


def test_bad_selections_are_refused(data):
    frames, groups, base = data
    kw = {"base": base, "groups": groups}
    for grid, err, msg in (
            ({"ridge": []}, ValueError, "^cv_grid\\['ridge'\\]: expected at least one value"),
            ({"alpha": [1.0]}, ValueError, "^cv_grid: unknown parameter 'alpha'"),
            ({"colour_prior": [0.0]}, ValueError, "^cv_grid\\['colour_prior'\\]: expected a "
                                                  "finite number > 0"),
            ({"prior": [-1.0]}, ValueError, "^cv_grid\\['prior'\\]: expected a finite number"),
            ({"ridge": [float("nan")]}, ValueError, "^cv_grid\\['ridge'\\]"),
            ({"ridge": [1e-3, 1e-3]}, ValueError, "^cv_grid\\['ridge'\\]: expected distinct"),
            ({"ridge": "0.1"}, TypeError, "^cv_grid\\['ridge'\\]: expected a sequence"),
            ([1e-3], TypeError, "^cv_grid: expected a dict")):
        with pytest.raises(err, match=msg):
            train_z_guided(frames, cv_grid=grid, **kw)
    with pytest.raises(ValueError, match="^select: expected 'cv' or None, got 'loo'"):
        train_z_guided(frames, select="loo", **kw)
    with pytest.raises(ValueError, match="^cv_folds: expected an integer >= 2, got 1"):
        train_z_guided(frames, cv_folds=1, **kw)
    with pytest.raises(ValueError, match="^cv_grid: applies to select='cv' only"):
        train_z_guided(frames, select=None, cv_grid=GRID, **kw)
    with pytest.raises(ValueError, match="^groups: expected one label per frame \\(8\\), got 2"):
        train_z_guided(frames, base=base, groups=[0, 1])
    with pytest.raises(TypeError, match="^groups: expected hashable labels"):
        train_z_guided(frames, base=base, groups=[[g] for g in groups])
    with pytest.raises(ValueError, match="^select: cross-validation needs frames of at least 2"):
        train_z_guided(frames[:2], base=base, groups=[0, 0])
    with pytest.raises(ValueError, match="^colour_prior: expected a finite number > 0"):
        train_z_guided(frames, colour_prior=0, **kw)


def test_the_targets_tool_fits_each_fold_on_its_training_pairs_alone(data, monkeypatch):
    """tools/z_guided_targets.py: an outer fold's test pairs enter neither its inner
    cross-validation nor its fit (their equations poisoned with NaN change nothing), and the
    fit is train_z_guided's on the training pairs' frames."""
    frames, _, base = data
    path = Path(__file__).resolve().parents[2] / "tools" / "z_guided_targets.py"
    spec = importlib.util.spec_from_file_location("z_guided_targets", path)
    tool = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, "z_guided_targets", tool)
    spec.loader.exec_module(tool)
    names = ["p0", "p1", "p2", "p3"]
    pair = {n: frames[2 * i:2 * i + 2] for i, n in enumerate(names)}
    eq = {n: sum_stats(frame_stats(f, base, tool.LAM) for f in pair[n]) for n in names}
    held = ["p1"]
    fit_names = [n for n in names if n not in held]
    fits = tool.fold_fits(eq, fit_names, base, 2, "cv")
    poisoned = dict(eq)
    poisoned["p1"] = [[np.full_like(a, np.nan if a.dtype.kind == "f" else 10 ** 9) for a in s]
                      for s in eq["p1"]]
    assert tool.fold_fits(poisoned, fit_names, base, 2, "cv") == fits
    train_frames = [f for n in fit_names for f in pair[n]]
    groups = [n for n in fit_names for _ in pair[n]]
    for m, guide in (("z_guided", True), ("no_guide", False)):
        want = train_z_guided(train_frames, base=base, groups=groups, cv_folds=2,
                              lam=tool.LAM, guide=guide)
        assert fits[m] == want
        assert {k: fits[m].meta[k] for k in GRID} == {k: want.meta[k] for k in GRID}


def test_cli_train_z_guided_selects_or_takes_the_fixed_settings(tmp_path):
    """--select cv (the default) chooses what is not given, the two frames of a pair in one
    fold; --select none takes the fixed settings; the z_guided options need --z-guided."""
    folder = tmp_path / "pairs"
    folder.mkdir()
    import imageio.v3 as iio

    for i in range(3):
        scene = _scene(10 + i, (32, 32))
        iio.imwrite(folder / f"{i:04d}_rgb.png", np.round(255 * scene.image).astype(np.uint8))
        iio.imwrite(folder / f"{i:04d}_nir.png",
                    np.round(255 * scene.ir_reflectance).astype(np.uint8))
    out = tmp_path / "z.npz"
    base = ["train", "--z-guided", "--dataset", str(folder), "--pattern", "mask1", "--out",
            str(out), "--quiet"]
    assert main(base + ["--ridge", "0.01", "--prior", "200"]) == 0
    f = ZGuidedFilters.load(out)
    assert f.meta["select"] == "cv" and f.meta["cv_groups"] == 3 and f.meta["cv_folds"] == 3
    assert (f.meta["ridge"], f.meta["prior"]) == (0.01, 200.0)
    assert f.meta["colour_prior"] in CV_GRID["colour_prior"]
    assert len(ast.literal_eval(f.meta["cv_rmse"])) == len(CV_GRID["colour_prior"])
    assert main(base + ["--select", "none", "--colour-prior", "16"]) == 0
    f = ZGuidedFilters.load(out)
    assert (f.meta["select"], f.meta["ridge"], f.meta["prior"], f.meta["colour_prior"]) == \
        ("none", 1e-3, 50.0, 16.0)


@pytest.mark.parametrize("argv, msg", [
    (["--colour-prior", "4"], "--colour-prior: applies with --z-guided only"),
    (["--select", "none"], "--select: applies with --z-guided only"),
    (["--z-guided", "--cv-folds", "1"], "--cv-folds: expected an integer >= 2, got 1"),
    (["--z-guided", "--select", "none", "--cv-folds", "3"],
     "--cv-folds: applies to --select cv only"),
])
def test_cli_train_refuses_misplaced_selection_options(tmp_path, capsys, argv, msg):
    (tmp_path / "ds").mkdir()
    assert main(["train", "--dataset", str(tmp_path / "ds"), "--out",
                 str(tmp_path / "f.npz")] + argv) == 2
    assert msg in capsys.readouterr().err
    assert not (tmp_path / "f.npz").exists()

