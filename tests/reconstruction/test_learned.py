"""method="learned": the C kernel against tests/_reference/learned.py, the filters, the fit.

Tolerances (stated here, asserted below):

* float64 precision: the C kernel and the reference agree to 1e-9 DN (relative 1e-12)
  at every Z site; integer frames: C == floor(ref + 0.5) (+-1 at exact .5 ties);
* float32 precision: within 2e-3 DN of the float64 reference at all but
  MAX_F32_FLIPS of the Z sites: float32 hash terms that sit on a bucket threshold can
  land in the neighbouring bucket (another filter), a few DN away.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import rgbz_fast as rz
from _reference.learned import reference_learned
from rgbz_fast.reconstruction import LearnedFilters, default_filters, train

MAX_F32_FLIPS = 1e-3

PATTERNS = {"mask1": rz.mask1, "mask2": rz.mask2, "mask1_rggb": lambda: rz.mask1("RGGB"),
            "rows": rz.rows, "custom_ZRZR/BGBG": lambda: rz.Pattern("ZRZR/BGBG/GRGR/BGBG")}


def _image(shape, seed=0):
    """A smooth random colour image with edges, in [0, 1]."""
    rng = np.random.default_rng(seed)
    small = rng.random((shape[0] // 4 + 2, shape[1] // 4 + 2, 3))
    img = np.kron(small, np.ones((4, 4, 1)))[:shape[0], :shape[1]]
    img = 0.7 * img + 0.3 * np.cumsum(rng.random(shape + (3,)), axis=1) / shape[1]
    return np.clip(img, 0, 1)


def _frame(pattern, shape, seed=0, bit_depth=11, dtype=np.uint16):
    img = _image(shape, seed)
    frame = rz.mosaic(img, pattern, bit_depth, dtype=dtype)
    ref = rz.mosaic(img, pattern.bayer_pattern(), bit_depth, dtype=dtype).data
    return dataclasses.replace(frame, reference=ref)


@pytest.fixture(scope="module")
def fitted():
    """Filters fitted on small synthetic frames, one per pattern (the shipped ones are
    tested apart: these cover patterns none ships for)."""
    out = {}
    for name, make in PATTERNS.items():
        p = make()
        frames = [_frame(p, (60, 72), seed=s) for s in range(3)]
        out[name] = train(frames, meta={"training_set": "synthetic"})
    return out


@pytest.mark.parametrize("name", list(PATTERNS))
@pytest.mark.parametrize("shape", [(60, 72), (13, 17), (6, 6)])
def test_float64_matches_reference(fitted, name, shape):
    f = fitted[name]
    p = f.pattern
    if shape[0] < p.period[0] or shape[1] < p.period[1]:
        pytest.skip("frame smaller than one period")
    frame = _frame(p, shape, seed=7, dtype=np.float64)
    got = rz.reconstruct(frame, "learned", filters=f, precision="float64")
    want = reference_learned(frame.data, f)
    z = frame.z_mask
    np.testing.assert_allclose(got[z], want[z], rtol=1e-12, atol=1e-9)
    assert np.array_equal(got[~z], frame.data[~z])


@pytest.mark.parametrize("name", ["mask1", "mask2", "rows"])
def test_integer_frames_round_half_up(fitted, name):
    f = fitted[name]
    frame = _frame(f.pattern, (48, 60), seed=3)
    got = rz.reconstruct(frame, "learned", filters=f, precision="float64")
    want = np.floor(reference_learned(frame.data, f) + 0.5)
    assert got.dtype == np.uint16
    assert np.abs(got.astype(np.float64) - want).max() <= 1


@pytest.mark.parametrize("name", ["mask1", "mask2"])
@pytest.mark.parametrize("dtype", [np.float32, np.uint16])
def test_float32_within_tolerance(fitted, name, dtype):
    f = fitted[name]
    frame = _frame(f.pattern, (96, 120), seed=11, dtype=dtype)
    data = frame.data
    got = rz.reconstruct(data, "learned", pattern=f.pattern, filters=f, precision="float32")
    want = reference_learned(data, f)
    z = frame.z_mask
    diff = np.abs(got[z].astype(np.float64) - (np.floor(want[z] + 0.5) if dtype == np.uint16
                                               else want[z]))
    tol = 1 if dtype == np.uint16 else 2e-3
    assert np.mean(diff > tol) <= MAX_F32_FLIPS
    assert got.dtype == dtype


@pytest.mark.parametrize("name", ["mask1", "mask2"])
def test_frames_wider_than_a_strip_match_reference(fitted, name):
    # the kernel's fast path runs in strips of 1024 columns (csrc/learned.template.h,
    # LRN_STRIP), each with its own rings of rows: 2600 columns make three strips; float32
    # data in float64 arithmetic goes through the ring of converted rows, exactly (the output
    # is float32: the float64 result rounded, to half a unit in the last place)
    f = fitted[name]
    frame = _frame(f.pattern, (20, 2600), seed=13, dtype=np.float32)
    want = reference_learned(frame.data, f)
    z = frame.z_mask
    for workers in (1, 2):
        got = rz.reconstruct(frame, "learned", filters=f, precision="float64", workers=workers)
        np.testing.assert_allclose(got[z], want[z], rtol=2.0**-24, atol=1e-9)
        assert np.array_equal(got[~z], frame.data[~z])


def test_threads_give_identical_results(fitted):
    f = fitted["mask2"]
    frame = _frame(f.pattern, (120, 200), seed=5, dtype=np.float32)
    one = rz.reconstruct(frame, "learned", filters=f, workers=1)
    two = rz.reconstruct(frame, "learned", filters=f, workers=2)
    assert np.array_equal(one, two)


def test_flat_colour_is_reproduced_exactly():
    """Every fitted filter sums to 1 over the target colour and to 0 over the others, so a
    flat colour field comes back unchanged (up to float rounding)."""
    for pname in ("mask1", "mask2"):
        img = np.empty((32, 32, 3))
        img[...] = (0.2, 0.5, 0.9)
        frame = rz.mosaic(img, pname, dtype=np.float64)
        ref = rz.mosaic(img, rz.get_pattern(pname).bayer_pattern(), dtype=np.float64).data
        got = rz.reconstruct(frame, "learned", precision="float64",
                             filters=default_filters(pname, 11))
        np.testing.assert_allclose(got, ref, atol=1e-6)


def test_shipped_filters_record_their_training():
    for pname in ("mask1", "mask2"):
        for bits, enc in ((11, "linear"), (8, "srgb")):
            f = default_filters(pname, bits)
            assert f.pattern == rz.get_pattern(pname) and f.bit_depth == bits
            assert f.meta["training_set"] == "cbsd68" and f.meta["encoding"] == enc
            assert f.meta["n_images"] == 68 and f.meta["noise"] is False
            assert f.n_buckets == 72 and f.radius == 3


def test_default_filters_are_used_when_none_given():
    frame = _frame(rz.mask1(), (40, 40), seed=2)
    a = rz.reconstruct(frame, "learned")
    b = rz.reconstruct(frame, "learned", filters=default_filters("mask1", 11))
    assert np.array_equal(a, b)


def test_save_load_round_trip(fitted, tmp_path):
    f = fitted["mask2"]
    path = tmp_path / "f.npz"
    f.save(path)
    g = LearnedFilters.load(path)
    assert g == f and g.digest == f.digest and g.meta == f.meta
    assert g.pattern == f.pattern and g.bit_depth == f.bit_depth
    frame = _frame(f.pattern, (40, 48), seed=1)
    assert np.array_equal(rz.reconstruct(frame, "learned", filters=str(path)),
                          rz.reconstruct(frame, "learned", filters=f))


def test_numpy_path_of_the_fit_matches_the_kernel(fitted):
    f = fitted["mask1"]
    frame = _frame(f.pattern, (40, 48), seed=9, dtype=np.float64)
    got = rz.reconstruct(frame, "learned", filters=f, precision="float64")
    z = frame.z_mask
    np.testing.assert_allclose(got[z], np.clip(f.reconstruct(frame.data), 0, 2047)[z],
                               rtol=1e-12, atol=1e-9)


def test_fit_beats_the_baseline_on_its_own_kind_of_image(fitted):
    """On held-out frames of the synthetic kind the fit must beat the bilinear mean."""
    f = fitted["mask2"]
    frame = _frame(f.pattern, (60, 72), seed=42)
    z = frame.z_mask
    ref = frame.reference.astype(np.float64)

    def err(m, **kw):
        return np.mean((rz.reconstruct(frame, m, **kw)[z] - ref[z]) ** 2)

    assert err("learned", filters=f) < err("bilinear")


def test_several_filters_pick_the_frame_s_pattern(fitted):
    both = (fitted["mask1"], fitted["mask2"])
    frame = _frame(rz.mask2(), (40, 40), seed=4)
    assert np.array_equal(rz.reconstruct(frame, "learned", filters=both),
                          rz.reconstruct(frame, "learned", filters=fitted["mask2"]))


# -- bad input --------------------------------------------------------------------------

def test_filters_of_another_pattern_or_bit_depth_are_refused(fitted):
    frame = _frame(rz.mask2(), (40, 40))
    with pytest.raises(ValueError, match=r"^filters: fitted for pattern 'mask1'"):
        rz.reconstruct(frame, "learned", filters=fitted["mask1"])
    frame8 = _frame(rz.mask1(), (40, 40), bit_depth=8, dtype=np.uint8)
    with pytest.raises(ValueError, match=r"^filters: fitted for 11-bit frames, the frame has 8"):
        rz.reconstruct(frame8, "learned", filters=fitted["mask1"])
    with pytest.raises(ValueError, match=r"^filters: none fits pattern 'mask2' at 11 bits"):
        rz.reconstruct(frame, "learned", filters=(fitted["mask1"], fitted["rows"]))


def test_no_shipped_filters_for_a_pattern_is_a_clear_error():
    frame = _frame(rz.rows(), (36, 36))
    with pytest.raises(ValueError, match=r"^filters: no filters ship for pattern 'rows'"):
        rz.reconstruct(frame, "learned")


def test_bad_filters_values(tmp_path):
    with pytest.raises(TypeError, match=r"^filters: expected a LearnedFilters"):
        rz.ReconstructParams(filters=3)
    with pytest.raises(FileNotFoundError, match=r"^filters: no such file"):
        rz.ReconstructParams(filters=tmp_path / "missing.npz")
    bad = tmp_path / "bad.npz"
    np.savez(bad, x=np.zeros(3))
    with pytest.raises(ValueError, match=r"^filters: .* is not a rgbz-fast filters file"):
        rz.ReconstructParams(filters=bad)
    with pytest.raises(ValueError, match=r"^filters: empty sequence"):
        rz.ReconstructParams(filters=())


def test_clipped_frames_are_refused():
    frame = _frame(rz.mask1(), (32, 32))
    with pytest.raises(ValueError, match=r"^clip_level: method 'learned'"):
        rz.reconstruct(frame, "learned", clip_level=100)


def test_train_rejects_bad_frames(fitted):
    f1 = _frame(rz.mask1(), (24, 24))
    with pytest.raises(ValueError, match=r"^frames: no frames"):
        train([])
    with pytest.raises(ValueError, match=r"^frames: frame 0 has no reference"):
        train([rz.mosaic(_image((24, 24)), "mask1")])
    with pytest.raises(ValueError, match=r"^frames: frame 1 is 'mask2'"):
        train([f1, _frame(rz.mask2(), (24, 24))])
    with pytest.raises(TypeError, match=r"^frames: expected RawFrame"):
        train([np.zeros((8, 8))])
    with pytest.raises(ValueError, match=r"^radius: "):
        train([f1], radius=9)
    with pytest.raises(ValueError, match=r"^frames: pattern 'bayer.*' has no Z site"):
        train([dataclasses.replace(rz.mosaic(_image((8, 8)), "bayer"),
                                   reference=rz.mosaic(_image((8, 8)), "bayer").data)])


def test_filters_arrays_are_checked(fitted):
    f = fitted["mask1"]
    with pytest.raises(ValueError, match=r"^filters: expected weights of shape"):
        LearnedFilters(f.pattern, 11, f.weights[:, :5], f.strength_thresholds,
                       f.coherence_thresholds)
    w = f.weights.copy()
    w[0, 0, 0] = np.nan
    with pytest.raises(ValueError, match=r"^filters: weights holds NaN"):
        LearnedFilters(f.pattern, 11, w, f.strength_thresholds, f.coherence_thresholds)
    with pytest.raises(ValueError, match=r"^filters: hash thresholds must be increasing"):
        LearnedFilters(f.pattern, 11, f.weights, f.strength_thresholds[:, ::-1],
                       f.coherence_thresholds)
