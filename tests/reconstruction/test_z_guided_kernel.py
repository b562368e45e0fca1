"""method="z_guided": the C kernel (csrc/z_guided.c) against tests/_reference/z_guided.py.

Tolerances (stated here, asserted below):

* float64 precision: the kernel, the library's NumPy path (ZGuidedFilters.reconstruct)
  and the reference agree to 1e-9 DN (relative 1e-12) at every Z site; integer frames:
  C == floor(ref + 0.5) (+-1 at exact .5 ties);
* float32 precision: within 2e-3 DN of the float64 reference (times the frame's scale in
  DN: 2e-3 of 2047 is float32's rounding of a few terms) at all but MAX_F32_FLIPS of the
  Z sites: a float32 hash term on a bucket threshold lands in the neighbouring bucket;
* the guide from the taps (csrc/z_guided_guide.c) equals the NumPy reference's bit for bit
  (the same float64 operations in the same order, the exact median of the same sample of
  the sites), for any thread count and any order of the sites;
* the kernel with its guide's rows from the taps: in float64 the result of the grids bit for
  bit; in float32 (its rows demodulated in float) within the float32 tolerance above of the
  result of the grids (float64 demodulation, converted): the amplitudes differ by float
  roundings, which move an output by float32 rounding, or a level across a threshold.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

import rgbz_fast as rz
from _reference.z_guided import reference_guide_grid, reference_z_guided
from rgbz_fast.reconstruction import train, train_z_guided
from rgbz_fast.reconstruction._z_guided import guide_grid
from rgbz_fast._frame import ToFTaps
from rgbz_fast.simulation import Scene, simulate

MAX_F32_FLIPS = 1e-3


def _scene(shape, seed):
    """Random colour and NIR with some shared texture, a plane at 2 m."""
    rng = np.random.default_rng(seed)
    tex = np.kron(rng.random((shape[0] // 2 + 1, shape[1] // 2 + 1)),
                  np.ones((2, 2)))[:shape[0], :shape[1]]
    img = np.clip(0.5 * tex[..., None] + 0.5 * rng.random(shape + (3,)), 0, 1)
    return Scene(img, depth=np.full(shape, 2.0), ir_reflectance=0.1 + 0.8 * tex)


@pytest.fixture(scope="module")
def fitted():
    """Per mask: z_guided filters (on learned filters fitted here) with both noise levels."""
    out = {}
    for p in ("mask1", "mask2"):
        frames = [simulate(_scene((60, 72), s), p, seed=s, noise=n) for s in (1, 2)
                  for n in (False, True)]
        base = train(frames, n_strength=2, n_coherence=2)
        out[p] = train_z_guided(frames, base=base)
    return out


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
@pytest.mark.parametrize("shape", [(60, 76), (13, 17), (6, 6)])
@pytest.mark.parametrize("noise", [False, True])
def test_float64_matches_reference(fitted, pattern, shape, noise):
    f = fitted[pattern]
    frame = simulate(_scene(shape, 7), pattern, seed=3, noise=noise)
    data = frame.data.astype(np.float64)
    grids = guide_grid(data.shape, frame.pattern, tof=frame.tof)
    want = reference_z_guided(data, f, *grids)
    z = frame.z_mask
    for workers in (1, 2):
        got = rz.reconstruct(data, "z_guided", pattern=pattern, tof=frame.tof, filters=f,
                             precision="float64", workers=workers)
        np.testing.assert_allclose(got[z], want[z], rtol=1e-12, atol=1e-9)
        assert np.array_equal(got[~z], data[~z])
    np.testing.assert_allclose(np.clip(f.reconstruct(data, grids), 0, 2047)[z], want[z],
                               rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_nir_guide_and_integer_frames(fitted, pattern):
    f = fitted[pattern]
    frame = simulate(_scene((48, 60), 9), pattern, seed=4, noise=True)
    nir = np.random.default_rng(1).random(frame.shape) * 50
    grids = guide_grid(frame.shape, frame.pattern, nir=nir)
    want = np.floor(reference_z_guided(frame.data, f, *grids) + 0.5)
    got = rz.reconstruct(frame, "z_guided", filters=f, nir=nir, precision="float64")
    assert got.dtype == frame.data.dtype
    assert np.abs(got.astype(np.float64) - want).max() <= 1
    data = frame.data.astype(np.float32)
    out = rz.reconstruct(data, "z_guided", pattern=pattern, bit_depth=11, nir=nir, filters=f,
                         precision="float64")
    ref = reference_z_guided(data, f, *guide_grid(data.shape, frame.pattern, nir=nir))
    z = frame.z_mask
    assert out.dtype == np.float32        # the float64 result rounded to float32
    np.testing.assert_allclose(out[z], ref[z], rtol=2.0**-24, atol=1e-9)


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
@pytest.mark.parametrize("dtype", [np.float32, np.uint16])
def test_float32_within_tolerance(fitted, pattern, dtype):
    f = fitted[pattern]
    frame = simulate(_scene((96, 120), 11), pattern, seed=5, noise=True)
    data = frame.data.astype(dtype)
    got = rz.reconstruct(data, "z_guided", pattern=pattern, tof=frame.tof, filters=f,
                         precision="float32", workers=2)
    want = reference_z_guided(data, f, *guide_grid(data.shape, frame.pattern, tof=frame.tof))
    z = frame.z_mask
    diff = np.abs(got[z].astype(np.float64) - (np.floor(want[z] + 0.5) if dtype == np.uint16
                                               else want[z]))
    assert np.mean(diff > (1 if dtype == np.uint16 else 2e-3)) <= MAX_F32_FLIPS
    assert got.dtype == dtype


def test_threads_give_identical_results(fitted):
    f = fitted["mask2"]
    frame = simulate(_scene((120, 200), 5), "mask2", seed=6, noise=True)
    one = rz.reconstruct(frame, "z_guided", filters=f, workers=1, precision="float32")
    two = rz.reconstruct(frame, "z_guided", filters=f, workers=2, precision="float32")
    assert np.array_equal(one, two)


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
@pytest.mark.parametrize("precision", ["float32", "float64"])
def test_fast_path_agrees_with_the_generic_path(fitted, pattern, precision):
    # interior sites take the fast path (the learned kernel's: hash from box sums, colour
    # weights on the dense window); without the dense weights every site takes the generic
    # path (the taps' pairs and list): the same values up to the order of the sums
    from rgbz_fast import _kernels
    from rgbz_fast.reconstruction._z_guided_kernel import _PRECISION_CODES, kernel_arrays
    f = fitted[pattern]
    frame = simulate(_scene((70, 130), 12), pattern, seed=7, noise=True)
    data = frame.data.astype(np.float64)
    grid, var = guide_grid(data.shape, frame.pattern, tof=frame.tof)
    arrays = kernel_arrays(f)
    assert "wd_f32" in arrays            # the shipped window (radius 3) has the fast path
    generic = {k: v for k, v in arrays.items() if k not in ("wd_f32", "wd_f64")}
    P, Q = frame.pattern.period
    phase_map = np.full(P * Q, -1, np.int32)
    for k, ph in enumerate(f.base.geometry):
        phase_map[ph["rc"][0] * Q + ph["rc"][1]] = k
    got = {}
    for name, arr in (("fast", arrays), ("generic", generic)):
        out = np.empty_like(data)
        _kernels.z_guided(data, out, _PRECISION_CODES[precision], P, Q, phase_map, grid=grid,
                          var=var, maxval=2047.0, workers=2, **arr)
        got[name] = out
    z = frame.z_mask
    assert np.array_equal(got["fast"][~z], data[~z])
    if precision == "float64":
        np.testing.assert_allclose(got["fast"][z], got["generic"][z], rtol=1e-12, atol=1e-9)
    else:
        diff = np.abs(got["fast"][z] - got["generic"][z])
        assert np.mean(diff > 2e-3) <= MAX_F32_FLIPS


@pytest.mark.parametrize("pattern", ["mask1", "mask2", "mask2_rggb"])
@pytest.mark.parametrize("shape", [(60, 76), (45, 62), (6, 6)])
@pytest.mark.parametrize("noise", [False, True])
def test_guide_from_the_taps_equals_the_reference(pattern, shape, noise):
    pattern = rz.get_pattern(pattern)
    frame = simulate(_scene(shape, 3), pattern, seed=2, noise=noise)
    want = reference_guide_grid(frame.shape, pattern, frame.tof)
    for workers in (1, 2, 3):
        got = guide_grid(frame.shape, pattern, tof=frame.tof, workers=workers)
        for g, w in zip(got, want):
            np.testing.assert_array_equal(g, w)


@pytest.mark.parametrize("pattern,shape", [("mask1", (60, 76)), ("mask1", (45, 63)),
                                           ("mask2", (45, 62)), ("mask2", (13, 17))])
def test_guide_from_the_taps_inside_the_kernel(fitted, pattern, shape):
    # the kernel demodulates the guide's rows itself from the taps (guide_source): the result
    # of the grids of guide_grid, whatever the order of the sites and the threads (float64:
    # bit for bit; float32: its rows in float, within the float32 tolerance; float frames
    # show the difference that integer outputs round away)
    from rgbz_fast.reconstruction._z_guided_kernel import TapGuide, guide_source, run_z_guided
    f = fitted[pattern]
    frame = simulate(_scene(shape, 13), pattern, seed=8, noise=True)
    order = np.random.default_rng(2).permutation(frame.tof.n_sites)
    grids = guide_grid(frame.shape, frame.pattern, tof=frame.tof)
    for tof in (frame.tof, _with_taps(frame.tof, frame.tof.taps, order)):
        source = guide_source(frame.shape, frame.pattern, tof=tof, workers=2)
        assert isinstance(source, TapGuide)
        for data in (frame.data, frame.data.astype(np.float32)):
            for precision in ("float32", "float64"):
                for workers in (1, 2):
                    got, want = (run_z_guided(data, np.empty_like(data), frame.pattern, f, g,
                                              precision, 11, workers)
                                 for g in (source, grids))
                    if precision == "float64":
                        np.testing.assert_array_equal(got, want)
                        continue
                    assert np.array_equal(got[~frame.z_mask], data[~frame.z_mask])
                    diff = np.abs(got.astype(np.float64) - want)[frame.z_mask]
                    tol = 1 if data.dtype == np.uint16 else 2e-3
                    assert np.mean(diff > tol) <= MAX_F32_FLIPS


def _with_taps(tof, taps, order=None):
    """``tof`` with other taps and, given ``order``, its sites in that order."""
    order = np.arange(tof.n_sites) if order is None else order
    return ToFTaps(taps[:, :, order], tof.frequencies, tuple(a[order] for a in tof.sites),
                   tof.block, tof.bit_depth, tof.depth_true[order], tof.valid[order],
                   tof.saturated[order], tof.sensor, tof.shape, tof.meta)


def test_guide_from_taps_in_any_order_of_any_type():
    frame = simulate(_scene((40, 52), 4), "mask1", seed=5, noise=True)
    tof = frame.tof
    want = reference_guide_grid(frame.shape, frame.pattern, tof)
    shuffled = _with_taps(tof, tof.taps, np.random.default_rng(0).permutation(tof.n_sites))
    for t in (shuffled, _with_taps(tof, tof.taps.astype(np.float32)),
              _with_taps(tof, tof.taps.astype(np.int32))):
        for g, w in zip(guide_grid(frame.shape, frame.pattern, tof=t, workers=2), want):
            np.testing.assert_array_equal(g, w)


def test_guide_of_one_frequency_and_of_dark_pixels():
    frame = simulate(_scene((24, 28), 6), "mask2", seed=1, noise=True)
    tof = frame.tof
    one = ToFTaps(tof.taps[:1], tof.frequencies[:1], tof.sites, tof.block, tof.bit_depth,
                  tof.depth_true, tof.valid, tof.saturated,
                  replace(tof.sensor, frequencies=tuple(tof.frequencies[:1])), tof.shape,
                  tof.meta)
    grid, var = guide_grid(frame.shape, frame.pattern, tof=one, workers=2)
    np.testing.assert_array_equal(grid, reference_guide_grid(frame.shape, frame.pattern,
                                                             one)[0])
    assert not var.any()
    # every pixel dark (equal taps): amplitude 0, no lit site, ratios 1
    flat = _with_taps(tof, np.full_like(tof.taps, 7))
    grid, var = guide_grid(frame.shape, frame.pattern, tof=flat)
    assert not grid.any() and not var.any()
    # half of them dark: the median runs over the lit ones
    taps = tof.taps.copy()
    taps[:, :, ::2] = 7
    half = _with_taps(tof, taps)
    for g, w in zip(guide_grid(frame.shape, frame.pattern, tof=half, workers=2),
                    reference_guide_grid(frame.shape, frame.pattern, half)):
        np.testing.assert_array_equal(g, w)


def test_guide_median_runs_over_the_sample():
    # the medians r_f run over every (N // 16384 + 1)-th Z pixel in row-major order: here
    # every second one, all alike (ratios 1), while the others differ, so that the median over
    # every site would differ from the sample's
    frame = simulate(_scene((200, 400), 8), "mask1", seed=1, noise=False)
    tof = frame.tof
    n = tof.n_sites
    assert n // 16384 + 1 == 2
    amp = np.where(np.arange(n) % 2 == 0, 1.0, 1.0 + np.arange(3)[:, None] * 0.5) * 40.0
    amp = amp * (1 + 0.01 * np.random.default_rng(3).random(n))
    taps = np.full((3, 4, n), 100.0)
    taps[:, 0] += 2 * amp
    t = _with_taps(tof, np.round(taps).astype(np.uint16))
    want = reference_guide_grid(frame.shape, frame.pattern, t)
    for workers in (1, 2):
        for g, w in zip(guide_grid(frame.shape, frame.pattern, tof=t, workers=workers), want):
            np.testing.assert_array_equal(g, w)
    # the variance with the medians over every site: not the guide's
    a = t.amplitude("all")
    norm = a / np.median(a / a.mean(axis=0), axis=1)[:, None]
    every = ((norm - norm.mean(axis=0)) ** 2).sum(axis=0) / 6
    assert not np.allclose(want[1].reshape(-1), every, rtol=1e-3)


def test_guide_refuses_more_frequencies_than_it_reads():
    from rgbz_fast import _kernels
    frame = simulate(_scene((12, 16), 2), "mask1", seed=1, noise=True)
    tof = frame.tof
    F = _kernels.TOF_MAX_FREQS + 1
    freqs = 1e6 * np.arange(1, F + 1)
    many = ToFTaps(np.tile(tof.taps[:1], (F, 1, 1)), freqs, tof.sites,
                   tof.block, tof.bit_depth, tof.depth_true, tof.valid, tof.saturated,
                   replace(tof.sensor, frequencies=tuple(freqs)), tof.shape, tof.meta)
    with pytest.raises(ValueError, match="frame.tof: the guide reads at most"):
        guide_grid(frame.shape, frame.pattern, tof=many)
