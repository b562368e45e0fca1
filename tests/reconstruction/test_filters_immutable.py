"""Probe round 24 (H): the learned and z_guided filters are immutable all through.

Their digest is their identity (equality, hash, the evaluation cache's key), computed once
in the constructor: an attribute assigned afterwards (NaN weights ran; the kernel's cached
arrays ignored new weights; the cache served the old weights' numbers), a write into the
learned geometry (shared through a cache with the shipped filters) or into the arrays
``kernel_arrays`` hands out had changed later results without a word. The derived state is
not pickled (a worker was sent 4x the filters' size after one use)."""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast.reconstruction import LearnedFilters, default_filters, default_z_filters


@pytest.fixture(scope="module")
def frame():
    rng = np.random.default_rng(0)
    scene = rz.Scene.from_rgb(rng.random((32, 32, 3)), depth=np.full((32, 32), 1.0))
    return rz.simulate(scene, "mask1", seed=1)


def _copy_of(f):
    return LearnedFilters(f.pattern, f.bit_depth, f.weights, f.strength_thresholds,
                          f.coherence_thresholds, f.spread_thresholds, meta=f.meta)


@pytest.mark.parametrize("kind", ["learned", "z_guided"])
def test_attributes_cannot_be_assigned_or_deleted(kind, frame):
    f = default_filters("mask1") if kind == "learned" else default_z_filters("mask1")
    before = rz.reconstruct(frame, kind)
    for name, value in (("weights", np.full(f.weights.shape, np.nan)), ("bit_depth", -3),
                        ("digest", "0"), ("anything_new", 1)):
        with pytest.raises(AttributeError, match=rf"^{type(f).__name__} is immutable: {name} "
                                                 r"cannot be set"):
            setattr(f, name, value)
    with pytest.raises(AttributeError, match="is immutable: weights cannot be deleted"):
        del f.weights
    for g in (copy.copy(f), copy.deepcopy(f), pickle.loads(pickle.dumps(f))):
        assert g == f
        with pytest.raises(AttributeError, match="is immutable"):
            g.weights = np.zeros(f.weights.shape)
    assert np.array_equal(rz.reconstruct(frame, kind), before)


def test_the_geometry_and_the_kernel_arrays_are_read_only(frame):
    shipped = default_filters("mask1")
    before = rz.reconstruct(frame, "learned")
    mine = _copy_of(shipped)
    assert mine.geometry is shipped.geometry              # shared: hence read-only
    ph = mine.geometry[0]
    with pytest.raises(ValueError, match="read-only"):
        ph["taps"][0, 0] = 3
    with pytest.raises(ValueError, match="read-only"):
        ph["pairs"][0][0, 0] = 0
    with pytest.raises(TypeError):
        ph["taps"] = np.zeros((1, 2), np.int32)
    for f in (shipped, default_z_filters("mask1")):
        arrays = f.kernel_arrays() if isinstance(f, LearnedFilters) else \
            __import__("rgbz_fast.reconstruction._z_guided_kernel",
                       fromlist=["kernel_arrays"]).kernel_arrays(f)
        for name, a in arrays.items():
            if isinstance(a, np.ndarray):
                assert not a.flags.writeable, name
    assert np.array_equal(rz.reconstruct(frame, "learned"), before)


@pytest.mark.parametrize("kind", ["learned", "z_guided"])
def test_a_pickle_leaves_the_derived_state_out(kind, frame):
    f = default_filters("mask1") if kind == "learned" else default_z_filters("mask1")
    fresh = _copy_of(f) if kind == "learned" else pickle.loads(pickle.dumps(f))
    size = len(pickle.dumps(fresh))
    out = rz.reconstruct(frame, kind, filters=fresh)          # fills the kernel cache
    assert len(pickle.dumps(fresh)) == size
    back = pickle.loads(pickle.dumps(fresh))
    assert back == fresh and np.array_equal(rz.reconstruct(frame, kind, filters=back), out)
    geometry = (back if kind == "learned" else back.base).geometry
    assert geometry is (f if kind == "learned" else f.base).geometry


def test_z_guided_names_the_layout_it_cannot_read():
    """Probe round 24 (I-05): on Mask2 shifted by a column (2x2 Z sites off the quads) z_guided
    asked for filters to be fitted, which no fit could give; the reason is the layout."""
    rng = np.random.default_rng(0)
    frame = rz.mosaic(rng.random((32, 32, 3)), rz.Pattern("ZGRZ/ZBGZ/RGRG/GBGB"))
    rz.reconstruct(frame, "learned")                   # the shipped Mask2 filters, shifted
    with pytest.raises(ValueError, match=r"^pattern: the 4 Z sites of .* are not one aligned "
                                         r"2x2 Z pixel, which 'z_guided' needs$"):
        rz.reconstruct(frame, "z_guided", nir=np.ones((32, 32)))


def test_a_pickle_of_an_earlier_version_is_immutable_and_the_geometry_pickles():
    """Review of round 24: a pickle made before ``_frozen`` existed (its state without it)
    came back mutable; the geometry's read-only phases (MappingProxyType at first) did not
    pickle or deep-copy."""
    f = default_filters("mask1")
    old_state = {k: v for k, v in f.__dict__.items()
                 if k not in ("_frozen", "_kernel", "geometry")}
    g = LearnedFilters.__new__(LearnedFilters)
    g.__setstate__(old_state)
    assert g == f and g.geometry is f.geometry
    with pytest.raises(AttributeError, match="is immutable"):
        g.weights = np.zeros(f.weights.shape)
    back = pickle.loads(pickle.dumps(f.geometry))
    assert [ph["rc"] for ph in back] == [ph["rc"] for ph in f.geometry]
    assert np.array_equal(copy.deepcopy(f.geometry)[0]["taps"], f.geometry[0]["taps"])
    with pytest.raises(TypeError, match="read-only"):
        back[0]["taps"] = None


@pytest.mark.parametrize("kind", ["learned", "z_guided"])
def test_the_meta_is_read_only(kind, tmp_path):
    """Round 25 (API01): ``meta`` was a plain dict of the one shipped object: an edit through
    one caller's filters changed every caller's repr and what ``save`` writes, the digest
    unchanged. It refuses changes now; ``dict(meta)`` is a copy to edit, and a copy, a pickle
    (also of an earlier version's plain dict) and a saved file keep it read-only."""
    f = default_filters("mask1") if kind == "learned" else default_z_filters("mask1")
    before = repr(f)
    for change in (lambda m: m.__setitem__("training_set", "mine"), lambda m: m.clear(),
                   lambda m: m.update(x=1), lambda m: m.pop("training_set")):
        with pytest.raises(TypeError, match="the filters' meta is read-only"):
            change(f.meta)
    assert repr(f) == before
    mine = dict(f.meta)
    mine["training_set"] = "mine"                           # a copy edits
    for g in (copy.deepcopy(f), pickle.loads(pickle.dumps(f))):
        with pytest.raises(TypeError, match="read-only"):
            g.meta["x"] = 1
    old_state = {**f.__getstate__(), "meta": dict(f.meta)}
    old_state.pop("_frozen", None)
    g = type(f).__new__(type(f))
    g.__setstate__(old_state)
    with pytest.raises(TypeError, match="read-only"):
        g.meta["x"] = 1
    if kind == "learned":
        f.save(tmp_path / "f.npz")
        with pytest.raises(TypeError, match="read-only"):
            LearnedFilters.load(tmp_path / "f.npz").meta["x"] = 1
