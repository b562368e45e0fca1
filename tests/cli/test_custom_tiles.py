"""A tile of the user's own works in every command, from the user's side: simulate, reconstruct
(an RGB-Z frame, and a real Bayer raw with the tile placed on the raw's own phase), depth,
evaluate-depth --patterns, train, tradeoff; and a method that does not apply to one layout
is a note of an evaluate run, never its end. Tiny inputs made here."""

from __future__ import annotations

import json

import numpy as np
import pytest

import rgbz_fast as rz  # noqa: E402
from rgbz_fast._cli import main  # noqa: E402
from _support import rgbd_folder  # noqa: E402

TILE = "ZRGR/BGBG/GRZR/BGBG"          # two 1x1 Z pixels on a diagonal of a 4x4 Bayer tile
LABEL = "zrgr-bgbg-grzr-bgbg"         # the tile as a field of an output file name


def images(path, n=2, shape=(48, 64)):
    import imageio.v3 as iio

    path.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(5)
    for i in range(n):
        iio.imwrite(path / f"img{i}.png", rng.integers(30, 230, shape + (3,), dtype=np.uint8))
    return path


def test_simulate_writes_a_frame_of_the_tile(tmp_path, capsys):
    assert main(["simulate", str(images(tmp_path / "ds", 1) / "img0.png"), "--pattern", TILE,
                 "--out", str(tmp_path / "f"), "--quiet"]) == 0
    frame = rz.io.load_frame(tmp_path / "f" / f"img0_{LABEL}.npz")
    assert frame.pattern.tile_string == TILE and frame.z_mask.mean() == 0.125
    assert frame.reference is not None


def test_reconstruct_a_frame_of_the_tile(tmp_path, capsys):
    src = images(tmp_path / "ds", 1) / "img0.png"
    assert main(["simulate", str(src), "--pattern", TILE, "--out", str(tmp_path / "f"),
                 "--no-noise", "--quiet"]) == 0
    capsys.readouterr()
    assert main(["reconstruct", str(tmp_path / "f" / f"img0_{LABEL}.npz"), "--method", "sg",
                 "--out", str(tmp_path / "o")]) == 0
    out = capsys.readouterr().out
    assert f"({TILE}, 48x64" in out and "CFA PSNR at the Z sites" in out
    assert (tmp_path / "o" / f"img0_{LABEL}_sg_cfa.tif").is_file()


@pytest.mark.parametrize("phase", ["GRBG", "RGGB", "BGGR", "GBRG"])
def test_reconstruct_places_the_tile_on_the_raws_own_phase(tmp_path, capsys, phase):
    """--rgbz-pattern with a tile on a Bayer raw: the tile is shifted onto the raw's phase,
    so every Z site stands in for the colour the raw has there, and only the Z sites
    change."""
    import imageio.v3 as iio
    import tifffile

    rng = np.random.default_rng(1)
    raw = rng.integers(0, 1024, (32, 40), dtype=np.uint16)
    iio.imwrite(tmp_path / "bayer.png", raw)
    assert main(["reconstruct", str(tmp_path / "bayer.png"), "--rgbz-pattern", TILE,
                 "--phase", phase, "--black-level", "0", "--bit-depth-in", "10",
                 "--method", "bilinear", "--out", str(tmp_path / "o")]) == 0
    out = capsys.readouterr().out
    placed = rz.io._bayer.place_on_phase(TILE, phase)
    assert placed.bayer_phase == phase and placed.z_fraction == 0.125
    assert f"({placed.tile_string}, 32x40" in out
    cfa = tifffile.imread(tmp_path / "o" / f"bayer_{LABEL}_bilinear_cfa.tif")
    ref = tifffile.imread(tmp_path / "o" / f"bayer_{LABEL}_reference_cfa.tif")
    np.testing.assert_array_equal(ref, raw)
    z = placed.z_mask(raw.shape)
    np.testing.assert_array_equal(cfa[~z], raw[~z])
    # the colour each Z site stands in for is the raw's colour there
    np.testing.assert_array_equal(placed.bayer_map(raw.shape), rz.bayer(phase).channel_map(
        raw.shape))


def test_reconstruct_refuses_a_tile_without_z_or_bayer_phase(tmp_path, capsys):
    import imageio.v3 as iio

    iio.imwrite(tmp_path / "bayer.png", np.zeros((8, 8), np.uint16))
    for bad in ("GR/BG", "ZR/RG"):
        with pytest.raises(SystemExit) as e:
            main(["reconstruct", str(tmp_path / "bayer.png"), "--rgbz-pattern", bad])
        assert e.value.code == 2
        assert "argument --rgbz-pattern" in capsys.readouterr().err


def test_depth_of_a_frame_of_the_tile(tmp_path, capsys):
    scene = rgbd_folder(tmp_path / "scene")
    assert main(["simulate", str(scene), "--pattern", TILE, "--out", str(tmp_path / "f"),
                 "--quiet"]) == 0
    assert main(["depth", str(tmp_path / "f" / f"scene_{LABEL}.npz"), "--out",
                 str(tmp_path / "d")]) == 0
    out = capsys.readouterr().out
    assert "measurements" in out and "valid" in out
    import tifffile

    depth = tifffile.imread(tmp_path / "d" / f"scene_{LABEL}_depth.tif")
    z = rz.get_pattern(TILE).z_mask(depth.shape)
    assert np.isnan(depth[~z]).all() and np.isfinite(depth[z]).any()


def test_evaluate_depth_measures_the_tile_given_by_patterns(tmp_path, capsys):
    rgbd_folder(tmp_path / "rgbd" / "scene")
    assert main(["evaluate-depth", "--data", str(tmp_path / "rgbd"), "--sections", "scenes",
                 "--patterns", f"{TILE},mask2", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["scenes"]
    assert {r["pattern"] for r in rows} == {TILE, "mask2"}
    assert all(r["known"] > 0 for r in rows if r["scene"] == "scene")


def test_train_fits_filters_for_the_tile_that_evaluate_then_uses(tmp_path, capsys):
    ds = images(tmp_path / "ds", 2)
    f = tmp_path / "tile.npz"
    assert main(["train", "--dataset", str(ds), "--pattern", TILE, "--out", str(f),
                 "--strength", "1", "--coherence", "1", "--spread", "1", "--quiet"]) == 0
    assert rz.reconstruction.LearnedFilters.load(f).pattern.tile_string == TILE
    assert main(["evaluate", "--dataset", str(ds), "--patterns", TILE, "--methods",
                 "bilinear,learned", "--metrics", "cfa_psnr", "--filters", str(f),
                 "--no-cache", "--no-plots", "--quiet", "--processes", "1",
                 "--out", str(tmp_path / "r")]) == 0
    out = capsys.readouterr().out
    assert "learned" in out and "n/a" not in out


def test_tradeoff_runs_the_tile_and_notes_learned(tmp_path, capsys):
    ds = images(tmp_path / "ds", 1)
    assert main(["tradeoff", "--dataset", str(ds), "--quick", "--repeat", "1", "--patterns",
                 f"{TILE},mask1", "--methods", "bilinear,learned", "--quiet", "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    ran = {(r["pattern"], r["method"]) for r in res["rows"]}
    assert ran == {(TILE, "bilinear"), ("mask1", "bilinear"), ("mask1", "learned")}
    assert [n[:2] for n in res["not_applicable"]] == [[TILE, "learned"]]
    assert res["not_applicable"][0][2].startswith("filters: none fits pattern")


def test_a_method_that_does_not_apply_is_a_note_of_the_evaluate_run(tmp_path, capsys):
    """edi_rows off row patterns and learned without filters for the tile do not apply: the
    other pairs run, the summary says n/a with the reason, the JSON lists them."""
    ds = images(tmp_path / "ds", 2)
    out = tmp_path / "r"
    assert main(["evaluate", "--dataset", str(ds), "--patterns", f"{TILE},mask1,rows",
                 "--methods", "bilinear,edi_rows,learned", "--metrics", "cfa_psnr,cpsnr",
                 "--no-cache", "--quiet", "--processes", "1", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "n/a: EDI rows (Shi) on mask1: method: 'edi_rows' needs" in text
    assert f"n/a: learned on {TILE}: filters: none fits pattern" in text
    res = json.loads((out / "results.json").read_text())
    assert {(p, m) for p, m, _ in res["not_applicable"]} == {
        (TILE, "edi_rows"), (TILE, "learned"), ("mask1", "edi_rows"), ("rows", "learned")}
    ran = {(r["pattern"], r["method"]) for r in res["rows"]}
    assert ran == {(TILE, "bilinear"), ("mask1", "bilinear"), ("mask1", "learned"),
                   ("rows", "bilinear"), ("rows", "edi_rows")}
    summary = (out / "summary.md").read_text()
    assert "| learned | n/a | n/a |" in summary
    # no pair that applies: the run fails with the reason, before any image
    assert main(["evaluate", "--dataset", str(ds), "--patterns", TILE, "--methods",
                 "edi_rows", "--metrics", "cfa_psnr", "--no-cache", "--quiet",
                 "--out", str(tmp_path / "r2")]) == 2
    assert "error: method: 'edi_rows' needs" in capsys.readouterr().err


def test_a_large_tile_gets_a_short_file_name(tmp_path, capsys):
    """A 32x32 tile spelled out is over a thousand characters, more than a file name may
    hold: its label is cut and ends in a digest, so two large tiles keep two names."""
    from rgbz_fast._cli._common import LABEL_MAX, file_label

    rows = []
    for r in range(32):
        row = ("RG" if r % 2 == 0 else "GB") * 16
        rows.append("Z" + row[1:] if r % 8 == 0 or r == 2 else row)
    big = "/".join(rows)            # 32x32 at its smallest period (row 2's Z breaks the 8)
    assert rz.get_pattern(big).period == (32, 32)
    other = big.replace("Z", "R", 1).replace("GBGBGBGB", "ZBGBGBGB", 1)
    assert len(file_label(big)) == LABEL_MAX and file_label(big) != file_label(other)
    src = images(tmp_path / "ds", 1) / "img0.png"
    assert main(["simulate", str(src), "--pattern", big, "--out", str(tmp_path / "f"),
                 "--no-noise", "--quiet"]) == 0
    (written,) = (tmp_path / "f").iterdir()
    assert written.name == f"img0_{file_label(big)}.npz"
    assert rz.io.load_frame(written).pattern.tile_string == big
