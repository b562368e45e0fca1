"""method="z_guided": the amplitude of the taps, the guide, what it reads, the fit, the files.

The NumPy path of reconstruction/_z_guided.py is the method's definition here; the
guide is read at the Z sites only, at any positive scale.
"""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast.io import load_frame, save_frame
from rgbz_fast._patterns import get_pattern
from rgbz_fast.reconstruction import (NEEDS_TOF, ZGuidedFilters, default_z_filters, train,
                                      train_z_guided)
from rgbz_fast.reconstruction._z_guided import guide_grid, resolve_z_filters, z_layout
from rgbz_fast.simulation import Scene, simulate


def _scene(shape=(48, 64), seed=0, ir=True):
    """Colour and NIR sharing a texture of 2x2 cells (the NIR a distorted copy), flat depth."""
    rng = np.random.default_rng(seed)
    small = rng.random((shape[0] // 4 + 2, shape[1] // 4 + 2))
    tex = np.kron(small, np.ones((4, 4)))[:shape[0], :shape[1]]
    fine = np.kron(rng.random((shape[0] // 2 + 1, shape[1] // 2 + 1)),
                   np.ones((2, 2)))[:shape[0], :shape[1]]       # as fine as a Mask2 Z pixel
    shade = 0.35 + 0.4 * tex + 0.25 * fine
    hue = rng.random((shape[0] // 8 + 2, shape[1] // 8 + 2, 3))
    hue = np.kron(hue, np.ones((8, 8, 1)))[:shape[0], :shape[1]]
    img = np.clip(shade[..., None] * (0.4 + 0.6 * hue), 0, 1)
    nir = np.clip(0.1 + 0.8 * shade ** 1.2, 0, 1) if ir else None
    return Scene(img, depth=np.full(shape, 1.5), ir_reflectance=nir), nir


@pytest.fixture(scope="module")
def fitted():
    """z_guided and learned filters fitted on three noise-free frames per mask (the fixed
    settings: test_z_guided_select.py tests their choice)."""
    out = {}
    for p in ("mask1", "mask2"):
        frames = [simulate(_scene(seed=s)[0], p, noise=False) for s in (1, 2, 3)]
        base = train(frames, n_strength=2, n_coherence=2)
        out[p] = (base, train_z_guided(frames, base=base, select=None,
                                       meta={"training_set": "test"}))
    return out


# ---------------------------------------------------------------- the data model
def test_amplitude_is_the_demodulated_modulus_and_scales_with_the_reflectance():
    scene, nir = _scene()
    tof = simulate(scene, "mask1", noise=False).tof
    t = tof.taps.astype(np.float64)
    amp = np.hypot(t[:, 0] - t[:, 2], t[:, 3] - t[:, 1]) / 2
    np.testing.assert_allclose(tof.amplitude(), amp.mean(axis=0), rtol=1e-12)
    np.testing.assert_allclose(tof.amplitude(1), amp[1], rtol=1e-12)
    np.testing.assert_allclose(tof.amplitude(-1), amp[-1], rtol=1e-12)
    np.testing.assert_allclose(tof.amplitude("all"), amp, rtol=1e-12)
    r, c = tof.sites
    assert np.corrcoef(tof.amplitude(), nir[r, c])[0, 1] > 0.99
    for bad in (3, -4, 1.0, True, "0", "each"):
        with pytest.raises(ValueError, match="frequency"):
            tof.amplitude(bad)


def test_simulate_records_whether_the_nir_was_estimated(tmp_path):
    given, _ = _scene()
    estimated = dataclasses.replace(given, ir_reflectance=None)
    assert simulate(given, "mask1", noise=False).tof.meta["ir_estimated"] is False
    frame = simulate(estimated, "mask2", noise=False)
    assert frame.tof.meta["ir_estimated"] is True
    path = save_frame(tmp_path / "f.npz", frame)
    assert load_frame(path).tof.meta["ir_estimated"] is True


def test_a_file_from_before_the_record_reads_as_unknown(tmp_path):
    frame = simulate(_scene()[0], "mask1", noise=False)
    path = save_frame(tmp_path / "f.npz", frame)
    with np.load(path) as z:
        arrays = {k: z[k] for k in z.files}
    header = json.loads(str(arrays["header"]))
    del header["tof"]["meta"]["ir_estimated"]
    arrays["header"] = np.array(json.dumps(header))
    np.savez(tmp_path / "old.npz", **arrays)
    assert load_frame(tmp_path / "old.npz").tof.meta["ir_estimated"] is None


# ---------------------------------------------------------------- the guide
@pytest.mark.parametrize("pattern", ["mask1", "mask2", "mask2_rggb", "mask1_bggr"])
def test_the_guide_from_the_taps_is_the_guide_from_their_painted_amplitude(pattern):
    pattern = rz.get_pattern(pattern)
    frame = simulate(_scene((45, 62))[0], pattern, noise=True, seed=3)   # cut Z pixels
    from_taps, var = guide_grid(frame.shape, pattern, tof=frame.tof)
    painted = frame.tof.to_frame(frame.tof.amplitude(), fill=np.nan)
    grid, zero = guide_grid(frame.shape, pattern, nir=painted)
    np.testing.assert_allclose(grid, from_taps, rtol=1e-12)
    assert not zero.any() and var.shape == grid.shape and (var > 0).all()
    # the values at the colour sites are never read
    painted[~frame.z_mask] = -1.0
    np.testing.assert_allclose(guide_grid(frame.shape, pattern, nir=painted)[0], from_taps,
                               rtol=1e-12)


def test_the_noise_of_the_amplitude_comes_from_the_disagreement_of_the_frequencies():
    scene = _scene()[0]
    clean, noisy = (guide_grid((48, 64), "mask1", tof=simulate(scene, "mask1", noise=n).tof)
                    for n in (False, True))
    amp, var = noisy
    F = 3
    tof = simulate(scene, "mask1", noise=True).tof
    a = tof.amplitude("all")
    ratio = np.median(a / a.mean(axis=0), axis=1)
    expect = (a / ratio[:, None]).var(axis=0) * F / (F * (F - 1))
    np.testing.assert_allclose(var.reshape(-1), expect, rtol=1e-9)
    # quantisation alone against the sensor model's noise: the relative noise of the guide
    rel = [np.median(v / np.maximum(g, 1e-9) ** 2) for g, v in (clean, noisy)]
    assert rel[0] < 0.2 * rel[1], rel


def test_a_mask2_z_pixel_reads_the_mean_of_its_four_sites():
    nir = np.zeros((8, 8))
    nir[0:2, 0:2] = [[1.0, 2.0], [3.0, 6.0]]
    grid, _ = guide_grid(nir.shape, "mask2", nir=nir)
    assert grid.shape == (2, 2) and grid[0, 0] == 3.0 and grid[1, 1] == 0.0


def test_the_guide_refuses_what_cannot_be_a_nir_image():
    shape = (16, 16)
    z = rz.mask1().z_mask(shape)
    with pytest.raises(ValueError, match="^nir: .*shape"):
        guide_grid(shape, "mask1", nir=np.ones((16, 15)))
    bad = np.ones(shape)
    bad[z.nonzero()[0][0], z.nonzero()[1][0]] = -1
    with pytest.raises(ValueError, match="^nir: .*negative"):
        guide_grid(shape, "mask1", nir=bad)
    bad[z] = np.nan
    with pytest.raises(ValueError, match="^nir: .*NaN"):
        guide_grid(shape, "mask1", nir=bad)
    with pytest.raises(TypeError, match="^nir: "):
        guide_grid(shape, "mask1", nir=np.full(shape, "a"))
    with pytest.raises(ValueError, match="^pattern: .*one\\s+Z pixel per tile"):
        z_layout(rz.Pattern("ZRGR/BGBG/GRZR/BGBG"))             # two Z pixels per tile
    with pytest.raises(ValueError, match="^pattern: "):
        z_layout("bayer")


def test_taps_of_another_pattern_are_refused():
    frame = simulate(_scene()[0], "mask1", noise=False)
    with pytest.raises(ValueError, match="^frame.tof: .*2x2"):
        guide_grid(frame.shape, "mask2", tof=frame.tof)
    with pytest.raises(ValueError, match="^frame.tof: .*not the Z pixels"):
        guide_grid(frame.shape, rz.mask1("RGGB"), tof=frame.tof)


# ---------------------------------------------------------------- reconstruct
def test_a_frame_without_taps_or_nir_gets_an_error_naming_nir(fitted):
    base, zf = fitted["mask1"]
    frame = simulate(_scene()[0], "mask1", noise=False)
    with pytest.raises(ValueError, match="^nir: .*no ToF taps"):
        rz.reconstruct(frame.data, "z_guided", pattern="mask1", filters=zf)
    with pytest.raises(ValueError, match="^nir: "):
        rz.reconstruct(dataclasses.replace(frame, tof=None), "z_guided", filters=zf)


def test_every_method_outside_needs_tof_runs_on_a_plain_array():
    assert NEEDS_TOF == rz.NEEDS_TOF and NEEDS_TOF <= set(rz.METHODS)
    data = rz.mosaic(np.full((16, 16, 3), 100, np.uint8), "mask1").data
    for m in rz.METHODS:
        if m not in NEEDS_TOF and m != "edi_rows":          # edi_rows: row patterns only
            rz.reconstruct(data, m, pattern="mask1")


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_z_guided_reads_the_guide_at_the_z_sites_only_at_any_scale(fitted, pattern):
    _, zf = fitted[pattern]
    scene, nir = _scene(seed=7)
    frame = simulate(scene, pattern, noise=False)
    data = frame.data.astype(np.float64)
    kw = dict(pattern=pattern, filters=zf, precision="float64")
    out = rz.reconstruct(data, "z_guided", nir=nir, **kw)
    np.testing.assert_array_equal(out[~frame.z_mask], data[~frame.z_mask])
    np.testing.assert_allclose(rz.reconstruct(data, "z_guided", nir=nir * 37.5, **kw), out,
                               rtol=1e-9, atol=1e-9)
    other = nir.copy()
    other[~frame.z_mask] = np.nan
    np.testing.assert_array_equal(rz.reconstruct(data, "z_guided", nir=other, **kw), out)
    # the frame's own taps: their amplitude and its noise (nir= is taken as exact)
    ref = zf.reconstruct(frame.data, guide_grid(frame.shape, pattern, tof=frame.tof))
    want = np.floor(np.clip(ref, 0, 2047) + 0.5)
    np.testing.assert_array_equal(rz.reconstruct(frame, "z_guided", filters=zf,
                                                 precision="float64"), want)
    # float32 arithmetic may round a value within 1e-4 of a half the other way
    got = rz.reconstruct(frame, "z_guided", filters=zf).astype(np.float64)
    assert np.abs(got - want).max() <= 1
    assert np.all((got == want) | (np.abs(ref - np.floor(ref) - 0.5) < 1e-3))



@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
@pytest.mark.parametrize("precision", ["float32", "float64"])
def test_a_nir_in_any_unit_stays_in_the_kernels_range(fitted, pattern, precision):
    """H82: the kernel reads each amplitude against its 3x3 mean in its precision; a nir
    of 1e-39 or 1e39 (float32's range left) had made nearly every Z site 0 without a word.
    A power-of-two unit gives the same bits; any other the same values to rounding."""
    _, zf = fitted[pattern]
    scene, nir = _scene(seed=7)
    data = simulate(scene, pattern, noise=False).data.astype(np.float64)
    kw = dict(pattern=pattern, filters=zf, precision=precision)
    out = rz.reconstruct(data, "z_guided", nir=nir, **kw)
    for unit in (2.0 ** -1000, 2.0 ** 200):
        np.testing.assert_array_equal(rz.reconstruct(data, "z_guided", nir=nir * unit, **kw),
                                      out)
    tol = 1e-2 if precision == "float32" else 1e-8
    for unit in (1e-300, 1e-39, 1e39, 1e300):
        np.testing.assert_allclose(rz.reconstruct(data, "z_guided", nir=nir * unit, **kw),
                                   out, rtol=0, atol=tol)
    # a value 2^-100 below the brightest and less is unlit, as 0 is
    dark = nir.copy()
    dark[:, : nir.shape[1] // 2] = 0.0
    tiny = nir.copy()
    tiny[:, : nir.shape[1] // 2] *= 2.0 ** -110
    np.testing.assert_array_equal(rz.reconstruct(data, "z_guided", nir=tiny, **kw),
                                  rz.reconstruct(data, "z_guided", nir=dark, **kw))

@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_the_guide_improves_on_learned_where_colour_and_nir_share_their_detail(fitted,
                                                                               pattern):
    base, zf = fitted[pattern]
    frame = simulate(_scene(seed=11)[0], pattern, noise=False)
    score = {m: rz.metrics.cfa_psnr(frame.reference, rz.reconstruct(frame, m, filters=f),
                                    frame.z_mask, bit_depth=11)
             for m, f in (("learned", base), ("z_guided", zf))}
    assert score["z_guided"] > score["learned"] + 1.0, score


# ---------------------------------------------------------------- filters
def test_filters_round_trip_and_each_method_picks_its_kind(fitted, tmp_path):
    base, zf = fitted["mask2"]
    zf.save(tmp_path / "z.npz")
    base.save(tmp_path / "l.npz")
    back = ZGuidedFilters.load(tmp_path / "z.npz")
    assert back == zf and back.meta["training_set"] == "test" and back.lam == zf.lam
    frame = simulate(_scene(seed=9)[0], "mask2", noise=False)
    both = [tmp_path / "l.npz", tmp_path / "z.npz"]
    np.testing.assert_array_equal(rz.reconstruct(frame, "z_guided", filters=both),
                                  rz.reconstruct(frame, "z_guided", filters=zf))
    np.testing.assert_array_equal(rz.reconstruct(frame, "learned", filters=both),
                                  rz.reconstruct(frame, "learned", filters=base))
    # given only the other kind, a method refuses them (its shipped filters had run, the
    # given ones unused: D3 of the 2026-11-27 probes); an evaluation of both methods gives
    # each method its own kind and the other its shipped filters
    with pytest.raises(ValueError, match="^filters: the given filters hold z_guided filters"):
        rz.reconstruct(frame, "learned", filters=zf)
    with pytest.raises(ValueError, match="^filters: the given filters hold learned filters"):
        rz.reconstruct(frame, "z_guided", filters=base)
    from rgbz_fast.evaluation import EvalConfig

    cfg = EvalConfig(patterns=["mask2"], methods=["learned", "z_guided"], metrics=["cfa_psnr"],
                     params={"filters": zf})
    np.testing.assert_array_equal(rz.reconstruct(frame, "learned",
                                                 params=cfg.params_for("learned")),
                                  rz.reconstruct(frame, "learned"))
    assert cfg.applies("mask2", "learned") and cfg.applies("mask2", "z_guided")
    with pytest.raises(ValueError, match="^filters: the given filters hold z_guided filters"):
        EvalConfig(patterns=["mask2"], methods=["learned"], metrics=["cfa_psnr"],
                   params={"filters": zf})                # no method of the run takes them
    with pytest.raises(ValueError, match="^filters: .*none ship for pattern 'rows"):
        resolve_z_filters(None, get_pattern("rows"), 11)
    with pytest.raises(ValueError, match="^filters: fitted for pattern 'mask2'"):
        rz.reconstruct(simulate(_scene()[0], "mask1", noise=False), "z_guided", filters=zf)
    with pytest.raises(ValueError, match="^filters: .*not a rgbz-fast"):
        ZGuidedFilters.load(tmp_path / "l.npz")


def test_the_fit_refuses_frames_it_cannot_learn_from():
    frame = simulate(_scene()[0], "mask1", noise=False)
    with pytest.raises(ValueError, match="^frames: no frames"):
        train_z_guided([])
    with pytest.raises(ValueError, match="^frames: frame 0 has no reference"):
        train_z_guided([dataclasses.replace(frame, reference=None)])
    with pytest.raises(ValueError, match="^nir\\[0\\]: "):
        train_z_guided([dataclasses.replace(frame, tof=None)])
    with pytest.raises(ValueError, match="^nir: expected one entry per frame"):
        train_z_guided([frame], nir=[None, None])
    with pytest.raises(ValueError, match="^lam: "):
        train_z_guided([frame], lam=0)


def test_the_fit_is_the_solution_of_the_summed_equations():
    from rgbz_fast.reconstruction._z_guided_fit import fit_stats, frame_stats

    frames = [simulate(_scene(seed=s)[0], "mask2", noise=bool(s % 2)) for s in (4, 5)]
    base = train(frames, n_strength=1, n_coherence=2)
    fit = train_z_guided(frames, base=base, lam=0.02, select=None)
    s0, s1 = (frame_stats(f, base, 0.02) for f in frames)
    total = [[a + b for a, b in zip(x, y)] for x, y in zip(s0, s1)]
    assert fit_stats(total, base, 0.02) == fit
    alone = train_z_guided(frames, base=base, lam=0.02, guide=False, select=None)
    assert not alone.guide_weights.any() and alone.meta["guide"] == 0
    assert alone.weights.shape == (4, 2 * base.n_buckets, base.weights.shape[2])
    assert not np.array_equal(alone.weights[:, :base.n_buckets], base.weights)


def test_shipped_filters_build_on_the_shipped_learned_ones():
    """The shipped z_guided filters: Mask1 and Mask2 at 11 bits, fitted by rgbz-fast train
    --z-guided on the RGB-NIR pairs, on the learned filters the package ships (a refit of
    those fails here until z_guided is refitted on them: the command is in meta)."""
    from rgbz_fast.reconstruction import default_filters
    for p in ("mask1", "mask2"):
        f = default_z_filters(p)
        assert f is not None and f.pattern == get_pattern(p) and f.bit_depth == 11
        assert "train --z-guided" in f.meta["command"] and f.meta["training_set"] == "rgbnir"
        assert f.meta["n_images"] == 40                     # 20 pairs, noise-free and noisy
        assert f.meta["base_digest"] == default_filters(p).digest, f.meta["command"]
        # its settings chosen by the 4-fold cross-validation over the 20 pairs
        assert (f.meta["select"], f.meta["cv_folds"], f.meta["cv_groups"]) == ("cv", 4, 20)
    # the other Bayer phases: the same filters mirrored or shifted, on the same base
    for p in ("mask1_rggb", "mask2_bggr"):
        f = default_z_filters(p)
        assert f.pattern == get_pattern(p) and f.base == default_filters(p)
        assert f.meta["derived_from"].startswith(p.split("_")[0] + ", digest ")
    assert default_z_filters("rows") is None


@pytest.mark.parametrize("src", ["mask1", "mask2"])
@pytest.mark.parametrize("phase", ["rggb", "bggr", "gbrg"])
def test_filters_of_every_bayer_phase_are_the_fit_moved_with_the_frame(src, phase):
    """On a frame that is a Mask frame flipped and shifted onto another Bayer phase (with its
    guide), the derived filters give the Mask frame's values moved the same way, to float64
    rounding, away from the borders."""
    from rgbz_fast.reconstruction._learned import pattern_transform
    dst = f"{src}_{phase}"
    fy, fx, oy, ox = pattern_transform(get_pattern(src), get_pattern(dst))
    rng = np.random.default_rng(5)
    H, W = 48, 64
    img = rng.random((H, W, 3)) * 0.6 + 0.2
    nir = rng.random((H, W)) * 0.5 + img.mean(2) * 0.5
    P, Q = get_pattern(src).period
    y0 = oy if fy == 1 else H - 1 - (H - 1 - oy) % P
    x0 = ox if fx == 1 else W - 1 - (W - 1 - ox) % Q
    at = np.ix_(y0 + fy * np.arange(H - P), x0 + fx * np.arange(W - Q))
    a = rz.mosaic(img, src, dtype=np.float64).data
    want = rz.reconstruct(a, "z_guided", pattern=src, nir=nir, precision="float64")[at]
    got = rz.reconstruct(a[at], "z_guided", pattern=dst, nir=nir[at], precision="float64")
    assert not np.allclose(got, a[at])          # the Z sites were filled
    np.testing.assert_allclose(got[8:-8, 8:-8], want[8:-8, 8:-8], rtol=0, atol=1e-9)
