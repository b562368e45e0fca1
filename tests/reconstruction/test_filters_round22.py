"""Round 22 of the filters' checks: meta that round-trips, singular fits, filters of the other
kind, array fields of the wrong ndim, the z_guided loader's checks, meta the fit records, and
integral file fields."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast.reconstruction import LearnedFilters, ZGuidedFilters, train, train_z_guided
from rgbz_fast.reconstruction._learned import _DATA
from rgbz_fast.simulation import Scene, simulate

FAST = dict(n_strength=1, n_coherence=1, n_spread=1)


def _frame(img, pattern="mask1"):
    return dataclasses.replace(rz.mosaic(img, pattern), reference=rz.mosaic(img, "bayer").data)


def _scene(seed, shape=(32, 32)):
    rng = np.random.default_rng(seed)
    tex = rng.random(shape)
    return Scene(np.repeat(tex[..., None], 3, 2) * 0.8 + 0.1, depth=np.full(shape, 2.0),
                 ir_reflectance=tex * 0.8 + 0.1)


@pytest.fixture(scope="module")
def frame():
    return _frame(np.random.default_rng(0).random((32, 32, 3)))


@pytest.fixture(scope="module")
def zframes():
    return [simulate(_scene(s), "mask1", noise=False) for s in (1, 2)]


@pytest.fixture(scope="module")
def mine(frame, zframes):
    learned = train([frame], **FAST)
    return learned, train_z_guided(zframes, base=learned, select=None)


def _edited(tmp_path, src, name, **changes):
    d = dict(np.load(_DATA / src))
    d.update(changes)
    p = tmp_path / name
    np.savez(p, **d)
    return p


def test_d1_meta_round_trips_or_is_refused_at_construction(tmp_path, frame, mine):
    values = {"s": "text", "i": 3, "neg": -7, "f": 0.1, "big": 1e300, "tiny": 5e-324,
              "t": True, "np_f64": np.float64(0.5), "np_f32": np.float32(0.25),
              "np_i": np.int64(4), "np_b": np.bool_(False), "none": None, "path": tmp_path}
    f = train([frame], **FAST, meta=values)
    want = {"s": "text", "i": 3, "neg": -7, "f": 0.1, "big": 1e300, "tiny": 5e-324, "t": True,
            "np_f64": 0.5, "np_f32": 0.25, "np_i": 4, "np_b": False, "none": "None",
            "path": str(tmp_path)}
    for k, v in want.items():
        assert f.meta[k] == v and type(f.meta[k]) is type(v), k
    f.save(tmp_path / "l.npz")
    back = LearnedFilters.load(tmp_path / "l.npz")
    assert {k: (back.meta[k], type(back.meta[k])) for k in want} == \
        {k: (v, type(v)) for k, v in want.items()}
    zg = ZGuidedFilters(mine[1].base, mine[1].weights, mine[1].guide_weights,
                        mine[1].noise_thresholds, mine[1].lam, meta=values)
    zg.save(tmp_path / "z.npz")
    zback = ZGuidedFilters.load(tmp_path / "z.npz")
    assert {k: (zback.meta[k], type(zback.meta[k])) for k in want} == \
        {k: (v, type(v)) for k, v in want.items()}
    for bad in (math.nan, math.inf, -math.inf, np.float64("nan")):
        with pytest.raises(ValueError, match=r"^meta: 'score' is"):
            train([frame], **FAST, meta={"score": bad})
        with pytest.raises(ValueError, match=r"^meta: 'score' is"):
            LearnedFilters(f.pattern, f.bit_depth, f.weights, f.strength_thresholds,
                           f.coherence_thresholds, meta={"score": bad})
        with pytest.raises(ValueError, match=r"^meta: 'score' is"):
            train_z_guided([], meta={"score": bad}, select=None)
    with pytest.raises(ValueError, match=r"^meta: 'long' is .* characters long"):
        LearnedFilters(f.pattern, f.bit_depth, f.weights, f.strength_thresholds,
                       f.coherence_thresholds, meta={"long": "x" * 100_001})


def test_d2_singular_fits_fall_back_to_least_squares(frame, zframes):
    flat = _frame(np.full((32, 32, 3), 0.5))
    tiny = _frame(np.random.default_rng(1).random((2, 2, 3)))
    for f in (train([frame], ridge=0, prior=0), train([flat], ridge=0), train([tiny]),
              train_z_guided(zframes, ridge=0, prior=0, select=None)):
        assert np.all(np.isfinite(f.weights))
    # a flat image: every feature 0, the least-norm solution is the baseline itself
    out = rz.reconstruct(flat, "learned", filters=train([flat], ridge=0, **FAST))
    np.testing.assert_array_equal(out, rz.reconstruct(flat, "learned", filters=train(
        [flat], **FAST)))


def test_d3_filters_of_the_other_kind_are_refused(frame, zframes, mine):
    learned, zg = mine
    with pytest.raises(ValueError, match=r"^filters: the given filters hold z_guided filters; "
                                         r"method 'learned' takes its own kind"):
        rz.reconstruct(zframes[0], "learned", filters=zg)
    with pytest.raises(ValueError, match=r"^filters: the given filters hold learned filters; "
                                         r"method 'z_guided' takes its own kind"):
        rz.reconstruct(zframes[0], "z_guided", filters=learned)
    # both kinds in one value (an evaluation of both methods): each method takes its own
    both = (learned, zg)
    np.testing.assert_array_equal(rz.reconstruct(zframes[0], "learned", filters=both),
                                  rz.reconstruct(zframes[0], "learned", filters=learned))
    np.testing.assert_array_equal(rz.reconstruct(zframes[0], "z_guided", filters=both),
                                  rz.reconstruct(zframes[0], "z_guided", filters=zg))


def test_d4_array_fields_of_the_wrong_ndim_are_refused(tmp_path):
    src = np.load(_DATA / "learned_mask1.npz")
    for field in ("strength_thresholds", "coherence_thresholds", "spread_thresholds"):
        p = _edited(tmp_path, "learned_mask1.npz", f"{field}.npz", **{field: src[field][..., None]})
        with pytest.raises(ValueError, match=rf"^filters: {p}: {field} must be 2-D"):
            LearnedFilters.load(p)
    p = _edited(tmp_path, "learned_mask1.npz", "w.npz", weights=src["weights"][..., None])
    with pytest.raises(ValueError, match=rf"^filters: {p}: weights must be 3-D"):
        LearnedFilters.load(p)
    zsrc = np.load(_DATA / "z_guided_mask1_11bit.npz")
    p = _edited(tmp_path, "z_guided_mask1_11bit.npz", "zt.npz",
                noise_thresholds=zsrc["noise_thresholds"][:, None])
    with pytest.raises(ValueError, match=rf"^filters: {p}: noise thresholds must be a 1-D"):
        ZGuidedFilters.load(p)


def test_d5_z_guided_loader_checks_and_names_the_file(tmp_path):
    src = "z_guided_mask1_11bit.npz"
    z = np.load(_DATA / src)
    p = _edited(tmp_path, src, "keys.npz", meta_keys=np.array(list(z["meta_keys"]) + ["x"]))
    n = len(z["meta_keys"])
    with pytest.raises(ValueError, match=rf"^filters: {p} holds {n + 1} meta keys and {n} "
                                         r"values \(a damaged filters file\)"):
        ZGuidedFilters.load(p)
    gw = z["guide_weights"]
    for name, ch, msg in (("nan.npz", dict(guide_weights=gw * np.nan), "guide weights hold NaN"),
                          ("thr.npz", dict(noise_thresholds=np.array([0.5, 0.1])),
                           "noise thresholds must be increasing"),
                          ("shape.npz", dict(guide_weights=gw[:, :10]),
                           "expected guide weights of shape"),
                          ("lam.npz", dict(lam=np.array([0.01, 0.02])), "holds lam an array"),
                          ("ver.npz", dict(version=np.array(1.5)), "holds version 1.5, not an")):
        p = _edited(tmp_path, src, name, **ch)
        with pytest.raises(ValueError, match=rf"^filters: {p}:? {msg}"):
            ZGuidedFilters.load(p)
    p = _edited(tmp_path, src, "nokey.npz")
    assert ZGuidedFilters.load(p) == ZGuidedFilters.load(_DATA / src)     # shipped: still loads


def test_d6_the_fit_records_its_own_meta(frame, zframes):
    for key in ("ridge", "n_images", "prior", "library_version", "n_sites"):
        with pytest.raises(ValueError, match=rf"^meta: '{key}' is recorded by the fit itself"):
            train([frame], **FAST, meta={key: 99})
    for key in ("select", "cv_rmse", "lam", "colour_prior", "base_digest"):
        with pytest.raises(ValueError, match=rf"^meta: '{key}' is recorded by the fit itself"):
            train_z_guided(zframes, select=None, meta={key: "cv"})
    one = {"ridge": [1e-2], "prior": [20.0], "colour_prior": [8.0]}
    f = train_z_guided(zframes, cv_grid=one)
    assert f.meta["select"] == "cv" and (f.meta["ridge"], f.meta["prior"],
                                         f.meta["colour_prior"]) == (1e-2, 20.0, 8.0)
    g = train_z_guided(zframes[:1], cv_grid=one)              # one scene: nothing to score
    assert g.meta["select"] == "cv" and g.meta["ridge"] == 1e-2
    from rgbz_fast.evaluation import train_filters
    from rgbz_fast.io import sample_dataset
    for key in ("noise", "encoding", "training_set"):
        with pytest.raises(ValueError, match=rf"^meta: '{key}' is recorded by"):
            train_filters(sample_dataset()[:1], "mask1", meta={key: "x"}, **FAST)


def test_d7_integer_file_fields_must_be_integral(tmp_path):
    for field, value in (("version", 2.7), ("bit_depth", 11.9), ("radius", 3.5),
                         ("hash_radius", np.array([3, 3])), ("n_angles", 8.5)):
        p = _edited(tmp_path, "learned_mask1.npz", f"{field}.npz", **{field: np.array(value)})
        with pytest.raises(ValueError, match=rf"^filters: {p} holds {field} .*not an integer "
                                             r"\(a damaged filters file\)"):
            LearnedFilters.load(p)
    p = _edited(tmp_path, "learned_mask1.npz", "float11.npz", bit_depth=np.array(11.0))
    assert LearnedFilters.load(p).bit_depth == 11
