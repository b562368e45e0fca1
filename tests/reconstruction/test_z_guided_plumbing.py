"""method="z_guided" through the library: the ISP, the datasets, evaluate, train, the CLI.

Each test checks that the frame's taps (or the registered NIR) reach the method
the way a direct ``reconstruct(frame, "z_guided")`` call gets them, and that a
guide estimated from the RGB is never reported as evidence.
"""

from __future__ import annotations

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast._cli import main
from rgbz_fast.evaluation import evaluate, train_filters
from rgbz_fast.io import folder_dataset
from rgbz_fast.isp import ColourISP, DefectCorrection, Reconstruction, fill_missing
from rgbz_fast.reconstruction import ZGuidedFilters, train, train_z_guided
from rgbz_fast.simulation import Scene, simulate


def _rgb_nir(seed, shape=(48, 64)):
    """An 8-bit RGB image and an 8-bit NIR image sharing a texture (a registered pair)."""
    rng = np.random.default_rng(seed)
    tex = np.kron(rng.random((shape[0] // 4, shape[1] // 4)), np.ones((4, 4)))
    hue = np.kron(rng.random((shape[0] // 8, shape[1] // 8, 3)), np.ones((8, 8, 1)))
    shade = 0.35 + 0.6 * tex
    rgb = np.round(255 * np.clip(shade[..., None] * (0.3 + 0.7 * hue), 0, 1)).astype(np.uint8)
    nir = np.round(255 * np.clip(0.1 + 0.8 * shade, 0, 1)).astype(np.uint8)
    return rgb, nir


def _frame(seed, pattern="mask1", noise=False):
    rgb, nir = _rgb_nir(seed)
    scene = Scene.from_rgb(rgb, depth=np.full(rgb.shape[:2], 2.0), ir_reflectance=nir / 255)
    return simulate(scene, pattern, seed=1, noise=noise)


@pytest.fixture(scope="module")
def zf():
    """z_guided filters for Mask1 at 11 bits, on the shipped learned filters."""
    return train_z_guided([_frame(s, noise=n) for s in (1, 2) for n in (False, True)])


@pytest.fixture()
def pairs(tmp_path):
    """A folder of two registered pairs (NNNN_rgb.png + NNNN_nir.png) and one RGB image alone."""
    import imageio.v3 as iio

    for i in (1, 2):
        rgb, nir = _rgb_nir(10 + i)
        iio.imwrite(tmp_path / f"000{i}_rgb.png", rgb)
        iio.imwrite(tmp_path / f"000{i}_nir.png", nir)
    iio.imwrite(tmp_path / "plain.png", _rgb_nir(13)[0])
    return tmp_path


def test_taps_of_a_plain_array_reach_the_method(zf):
    frame = _frame(5)
    direct = rz.reconstruct(frame, "z_guided", filters=zf)
    np.testing.assert_array_equal(
        rz.reconstruct(frame.data, "z_guided", pattern="mask1", tof=frame.tof, filters=zf),
        direct)
    np.testing.assert_array_equal(
        fill_missing(frame.data, "mask1", Reconstruction("z_guided", params={"filters": zf}),
                     tof=frame.tof), direct)
    with pytest.raises(TypeError, match="^frame.tof: expected ToFTaps"):
        rz.reconstruct(frame.data, "z_guided", pattern="mask1", tof=frame.data, filters=zf)


def test_colour_isp_passes_the_frames_taps(zf):
    frame = _frame(6)
    isp = ColourISP(defects=DefectCorrection(enabled=False),
                    reconstruction=Reconstruction("z_guided", params={"filters": zf}))
    out, st = isp.run(frame, return_stages=True)
    np.testing.assert_array_equal(st["reconstruction"],
                                  rz.reconstruct(frame, "z_guided", filters=zf))
    with pytest.raises(ValueError, match="^nir: method 'z_guided'"):
        isp.run(frame.data, pattern="mask1")
    nir = frame.tof.to_frame(frame.tof.amplitude()) * 7.0      # any scale
    _, st2 = isp.run(frame.data, pattern="mask1", nir=nir, return_stages=True)
    np.testing.assert_array_equal(
        st2["reconstruction"], rz.reconstruct(frame.data, "z_guided", pattern="mask1",
                                              nir=nir, filters=zf))
    assert out.shape == frame.shape + (3,)
    # the default (fused) path takes the same guide: it had dropped the taps and nir=
    np.testing.assert_array_equal(isp.run(frame), out)
    np.testing.assert_array_equal(isp.run(frame.data, pattern="mask1", nir=nir),
                                  isp.run(frame.data, pattern="mask1", nir=nir,
                                          return_stages=True)[0])


def test_folder_dataset_pairs_rgb_and_nir(pairs):
    ds = folder_dataset(pairs)
    assert [s.name for s in ds] == ["0001", "0002", "plain"]
    assert [s.nir is not None for s in ds] == [True, True, False]
    np.testing.assert_array_equal(ds[0].load_nir(), _rgb_nir(11)[1] / 255)
    assert ds[2].load_nir() is None
    assert ds[0].fingerprint() != folder_dataset(pairs)[1].fingerprint()


def test_evaluate_marks_rows_whose_guide_was_estimated(pairs, zf):
    res = evaluate(pairs, patterns="mask1", methods=("learned", "z_guided"),
                   metrics=("cfa_psnr",), params={"filters": zf}, processes=1, progress=False)
    z_rows = {r["image"]: r["ir_estimated"] for r in res.rows if r["method"] == "z_guided"}
    assert z_rows == {"0001": False, "0002": False, "plain": True}
    assert all("ir_estimated" not in r for r in res.rows if r["method"] == "learned")
    assert res.ir_estimated("mask1", "z_guided") == ["plain"]
    assert "NIR estimated from the RGB on 1 of 3 images" in res.summary_markdown()
    assert "NIR estimated from the RGB" in res.plain_table()
    assert res.to_csv().splitlines()[0].endswith(",ir_estimated")
    # every method of the run sees the sensor model's frame, the one z_guided is guided on
    rgb, nir = _rgb_nir(11)
    frame = simulate(Scene.from_rgb(rgb, depth=np.full(rgb.shape[:2], 2.0),
                                    ir_reflectance=nir / 255),
                     "mask1", rz.simulation.ColourSensor(black_level=0), seed=0, noise=False)
    want = rz.metrics.cfa_psnr(frame.reference, rz.reconstruct(frame, "z_guided", filters=zf,
                                                               precision="float64"),
                               frame.z_mask, bit_depth=11)
    got = [r["value"] for r in res.rows if r["image"] == "0001" and r["method"] == "z_guided"]
    assert got == [pytest.approx(want, abs=1e-9)]


def test_evaluate_refuses_what_z_guided_cannot_run(zf):
    with pytest.raises(ValueError, match="^linearise: methods \\['z_guided'\\]"):
        rz.evaluation.EvalConfig(methods=("z_guided",), linearise=False,
                                 params={"filters": zf}, patterns="mask1")
    with pytest.raises(ValueError, match="^filters: .*'rows'"):
        rz.evaluation.EvalConfig(methods=("z_guided",), patterns="rows")


def test_train_z_guided_routes(pairs):
    frames = [_frame(s, noise=n) for s in (1, 2) for n in (False, True)]
    a = train(frames, z_guided=True, lam=0.02, select=None)
    assert isinstance(a, ZGuidedFilters) and a == train_z_guided(frames, lam=0.02, select=None)
    with pytest.raises(ValueError, match="^radius: z_guided"):
        train(frames, z_guided=True, radius=2)
    with pytest.raises(TypeError, match=r"^lam: an option of train\(z_guided=True\) only"):
        train(frames, lam=0.02)
    # a name neither fit takes is unknown, with or without z_guided (round 25, API09: it
    # was called a z_guided option, and with z_guided=True a bare 'unexpected keyword')
    for z in (False, True):
        with pytest.raises(TypeError, match=r"^n_strenght: not an option of train\(\) \(its "
                                            r"options: radius, .*; with z_guided=True also "
                                            r"nir, base, .*\)$"):
            train(frames, z_guided=z, n_strenght=1)
    f = train_filters(folder_dataset(pairs)[:2], "mask1", z_guided=True, seed=1)
    assert isinstance(f, ZGuidedFilters) and f.meta["n_images"] == 4
    assert f.meta["cv_groups"] == 2                     # a pair's two frames: one group
    with pytest.raises(TypeError, match="^groups: not an option of train_filters"):
        train_filters(folder_dataset(pairs)[:2], "mask1", z_guided=True, groups=[0, 1, 2, 3])
    with pytest.raises(ValueError, match="^dataset: 'plain' has no registered NIR"):
        train_filters(pairs, "mask1", z_guided=True)
    with pytest.raises(ValueError, match="^noise: z_guided filters"):
        train_filters(pairs, "mask1", z_guided=True, noise=True)


def test_cli_train_z_guided(pairs, tmp_path, capsys):
    folder = tmp_path / "pairs"
    folder.mkdir()
    for p in pairs.glob("000*_*.png"):
        (folder / p.name).write_bytes(p.read_bytes())
    out = tmp_path / "z.npz"
    assert main(["train", "--z-guided", "--dataset", str(folder), "--pattern", "mask2",
                 "--out", str(out), "--quiet", "--select", "none"]) == 0
    f = ZGuidedFilters.load(out)
    assert f.pattern == rz.mask2() and f.meta["training_set"] == "pairs"
    assert "--z-guided" in f.meta["command"]
    frame = _frame(7, "mask2")
    assert rz.reconstruct(frame, "z_guided", filters=str(out)).shape == frame.shape


def test_train_z_guided_on_threads_fits_the_same_filters():
    """The frames' normal equations and the cross-validation's grid points run on threads:
    the same filters, weights and held-out errors bit for bit, on 1 to 3 threads (3 frames
    and a batch of 2 leave one frame to a batch of its own)."""
    frames = [_frame(s, noise=n) for s in (1, 2) for n in (False, True)][:3]
    grid = {"ridge": (1e-3, 1e-2), "prior": (10.0, 50.0), "colour_prior": (4.0,)}
    fits = [train_z_guided(frames, cv_folds=3, cv_grid=grid, workers=w) for w in (1, 2, 3)]
    for f in fits[1:]:
        assert f == fits[0]
        np.testing.assert_array_equal(f.weights, fits[0].weights)
        np.testing.assert_array_equal(f.guide_weights, fits[0].guide_weights)
        assert f.meta["cv_rmse"] == fits[0].meta["cv_rmse"]
    with pytest.raises(ValueError, match="^workers"):
        train_z_guided(frames, select=None, workers=0)
