"""``rgbz-fast pattern-study`` from the user's side: the candidates and which of them count as
one layout, the tiles it refuses (naming ``tiles``) before any work, a small study through the
command line, resuming from the cache, and the Dask path giving the same numbers."""

from __future__ import annotations

import csv
import json

import imageio.v3 as iio
import numpy as np
import pytest

from rgbz_fast import Pattern, get_pattern
from rgbz_fast._cli import main
from rgbz_fast._devtools import pattern_candidates as pc
from rgbz_fast._devtools import pattern_study as ps

#: small and quick: a 48x48 wall, 96x96 scene crops
FAST = ps.StudySettings(methods=("bilinear", "sg"), wall_shape=(48, 48))


@pytest.fixture(scope="module")
def tiny(tmp_path_factory):
    """Two 64x64 colour images to evaluate, one to train on, one RGB-D scene."""
    import skimage.data

    root = tmp_path_factory.mktemp("study")
    for folder, images in (("ds", ("astronaut", "coffee")), ("train", ("chelsea",))):
        (root / folder).mkdir()
        for name in images:
            img = getattr(skimage.data, name)()
            iio.imwrite(root / folder / f"{name}.png", np.ascontiguousarray(img[100:164,
                                                                                 100:164]))
    scene = root / "rgbd" / "ramp"
    scene.mkdir(parents=True)
    img = np.ascontiguousarray(skimage.data.astronaut()[:96, :96])
    iio.imwrite(scene / "rgb.png", img)
    disp = np.tile(np.linspace(120, 200, 96).astype(np.uint8), (96, 1))
    iio.imwrite(scene / "disp1.png", disp)
    (scene / "dmin.txt").write_text("200\n")
    return root


def _flip_rows(tile):
    """The tile seen through y -> -y about site (0, 0): row r holds what row -r held."""
    t = get_pattern(tile).tile
    return "/".join("".join("RGBZ"[v] for v in t[(-r) % t.shape[0]])
                    for r in range(t.shape[0]))


def _roll(tile, dy, dx):
    t = np.roll(get_pattern(tile).tile, (dy, dx), (0, 1))
    return "/".join("".join("RGBZ"[v] for v in row) for row in t)


# --------------------------------------------------------------------------- candidates
def test_shifts_by_whole_bayer_periods_and_phase_keeping_flips_count_once():
    base = "ZRGR/BGBG/GRGR/BGBG"
    shifted = _roll(base, 2, 0)
    assert shifted == "GRGR/BGBG/ZRGR/BGBG"
    odd = "ZRGRGR/BGBGBG/GRGRGR/BGBGBG/GRGRGR/BGZGBG"     # Z on a different green
    flipped = _flip_rows(odd)
    assert flipped != odd
    kept, _ = pc.candidates((), (base, shifted, odd, flipped))
    assert [c.name for c in kept] == ["tile1", "tile3"]
    assert kept[0].same_as == ["tile2"] and kept[1].same_as == ["tile4"]
    assert pc.canonical_key(odd) == pc.canonical_key(flipped)


def test_a_shift_by_one_site_or_a_transpose_on_grbg_is_another_layout():
    base = "ZRGRGR/BGBGBG/GRGRGR/BGBGZG"
    transposed = "/".join("".join(r) for r in zip(*base.split("/")))
    assert get_pattern(transposed).bayer_phase == "GBRG"    # red and blue swap places
    assert pc.canonical_key(base) != pc.canonical_key(transposed)
    kept, _ = pc.candidates((), (base, transposed))
    assert len(kept) == 2
    # on RGGB the transpose keeps the phase: one layout
    rggb = "RZRGRG/GBGBGB/RGRGRG/GBGBGZ"
    rggb_t = "/".join("".join(r) for r in zip(*rggb.split("/")))
    assert get_pattern(rggb_t).bayer_phase == "RGGB"
    assert pc.canonical_key(rggb) == pc.canonical_key(rggb_t)


def test_generated_family_meets_the_presets_and_is_deduplicated():
    kept, notes = pc.candidates(("mask1", "mask2"), (),
                                "block=1,2 period=2,4 arrangement=aligned,staggered")
    names = [c.name for c in kept]
    mask1 = next(c for c in kept if c.name == "mask1")
    mask2 = next(c for c in kept if c.name == "mask2")
    assert mask1.same_as == ["z1x1-p2x2-alig"] and mask2.same_as == ["z2x2-p4x4-alig"]
    assert "z1x1-p4x4-stag" in names and "z2x2-p4x4-stag" in names
    assert any("staggered needs a period of 4k columns" in n for n in notes)
    stag = next(c for c in kept if c.name == "z2x2-p4x4-stag")
    assert stag.block == 2 and stag.pattern.period == (8, 4)
    assert len({c.key for c in kept}) == len(kept)


def test_rectangular_z_pixels_are_not_supported_for_depth():
    kept, _ = pc.candidates((), (), "block=2x1 period=4 arrangement=aligned")
    (c,) = kept
    assert c.block is None and c.z_size == (2, 1)
    assert "not supported: 2x1 Z pixels" in c.note
    assert pc.z_pixel(get_pattern("rows"))[0] == 2       # rows of Z tile into 2x2 pixels


@pytest.mark.parametrize("tile,match", [
    ("ZR/RG", "fit no Bayer phase"),
    ("ZZ/ZZ", "only Z"),
    ("GR/BG", "has no Z site"),
    ("GR" * 17 + "/" + "BG" * 17, "more than the largest tile"),
    ("ZZGR/ZGBG/GRGR/BGBG", "not a rectangle"),
    ("ZQ/BG", "unknown channel letter"),
])
def test_bad_tiles_name_tiles(tile, match):
    with pytest.raises(ValueError, match=f"^tiles: .*{match}"):
        pc.check_tile(tile)


@pytest.mark.parametrize("spec,match", [
    ("block=3", "block 3x3"), ("period=3", "whole Bayer periods"), ("shape=4", "unknown"),
    ("arrangement=diagonal", "arrangement"), ("density=0.5", "MIN:MAX"), ("block", "KEY="),
    ("block=1 block=2", "block is given twice"), ("period=4;period=8", "period is given twice"),
    ("", "an empty specification"), ("block=1,,2", "block has an empty entry")])
def test_bad_generate_names_generate(spec, match):
    with pytest.raises(ValueError, match=f"^generate: .*{match}"):
        pc.parse_generate(spec)


def test_a_density_range_no_layout_meets_is_said():
    """density=0.9:1 made no layout and said nothing."""
    cands, notes = pc.generate("block=1 period=4 density=0.9:1")
    assert cands == [] and notes == ["generate: no layout of the family has a density within "
                                     "0.9:1"]


def test_bad_tile_fails_before_any_work(tmp_path, capsys, monkeypatch):
    def no_work(*a, **k):
        raise AssertionError("work started")

    monkeypatch.setattr(ps, "_run", no_work)
    code = main(["pattern-study", "--tiles", "ZRGR/BGBG,ZR/RG", "--out", str(tmp_path / "o"),
                 "--quiet"])
    err = capsys.readouterr().err
    assert code == 2 and "pattern-study: error: --tiles: the colour sites of 'ZR/RG'" in err
    assert not (tmp_path / "o").exists()


def test_bad_inputs_name_their_parameter(tiny):
    with pytest.raises(ValueError, match="^methods: unknown"):
        ps.pattern_study(tiny / "ds", settings=ps.StudySettings(methods=("nope",)),
                         progress=False)
    with pytest.raises(ValueError, match="^presets: 'mask7'"):
        ps.pattern_study(tiny / "ds", presets=("mask7",), progress=False)
    with pytest.raises(ValueError, match="^train: 1 image"):
        ps.pattern_study(tiny / "ds", train=tiny / "ds", train_limit=1, progress=False)
    with pytest.raises(ValueError, match="^rgbd: .* holds no RGB-D scene"):
        ps.pattern_study(tiny / "ds", rgbd=tiny / "ds", progress=False)
    with pytest.raises(ValueError, match="^train: .*missing"):
        ps.pattern_study(tiny / "ds", train=tiny / "missing", progress=False)
    with pytest.raises(ValueError, match="^dataset: .*missing"):
        ps.pattern_study(tiny / "missing", progress=False)
    with pytest.raises(ValueError, match="^tiles: no layout"):
        ps.pattern_study(tiny / "ds", presets=(), progress=False)


def test_methods_given_with_settings_are_measured_or_the_conflict_refused(tiny, monkeypatch):
    """``methods=`` had been ignored whenever ``settings=`` was given (the rows held every
    method of the settings); a ``settings.methods`` of its own that disagrees is refused."""
    res = ps.pattern_study(tiny / "ds", presets=("mask1",), methods=("bilinear",),
                           settings=ps.StudySettings(wall_shape=(48, 48)), progress=False)
    assert {r["method"] for r in res["rows"]} == {"bilinear"}
    assert res["methods"] == res["settings"]["methods"] == ["bilinear"]

    def no_work(*a, **k):
        raise AssertionError("the study ran")

    monkeypatch.setattr(ps, "_run", no_work)
    with pytest.raises(ValueError, match=r"^methods: \['bi'\] conflicts with settings.methods "
                                         r"\['bilinear', 'sg'\]"):
        ps.pattern_study(tiny / "ds", presets=("mask1",), methods=("bi",), settings=FAST,
                         progress=False)


@pytest.mark.parametrize("kw, match", [
    ({"train_limit": 1}, "^train_limit: applies with train="),
    ({"rgbd_limit": 1}, "^rgbd_limit: applies with rgbd="),
])
def test_a_limit_without_its_folder_is_refused(tiny, monkeypatch, kw, match):
    """As the command line refuses --train-limit without --train (--rgbd-limit without
    --rgbd): the limit had been accepted and ignored."""
    def no_work(*a, **k):
        raise AssertionError("the study ran")

    monkeypatch.setattr(ps, "_run", no_work)
    with pytest.raises(ValueError, match=match):
        ps.pattern_study(tiny / "ds", presets=("mask1",), settings=FAST, progress=False, **kw)


# --------------------------------------------------------------------------- a study
def test_cli_study_of_three_layouts(tiny, tmp_path, capsys, terminal):
    out = tmp_path / "out"
    code = main(["pattern-study", "--dataset", str(tiny / "ds"), "--presets", "mask1",
                 "--tiles", "ZRGR/BGBG/GRZR/BGBG", "--generate",
                 "block=2x1 period=4 arrangement=aligned", "--methods", "bilinear,learned",
                 "--train", str(tiny / "train"), "--rgbd", str(tiny / "rgbd"),
                 "--rgbd-size", "96x96", "--out", str(out), "--workers", "1"])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    assert "pattern-study" in captured.err                  # progress on stderr
    assert {p.name for p in out.iterdir()} >= {"pattern_study.csv", "pattern_study.md",
                                                "pattern_study.json", "pattern_study.png",
                                                "cache"}
    rows = list(csv.DictReader((out / "pattern_study.csv").read_text().splitlines()))
    assert [(r["layout"], r["method"]) for r in rows] == [
        (n, m) for n in ("mask1", "tile1", "z2x1-p4x4-alig") for m in ("bilinear", "learned")]
    by = {(r["layout"], r["method"]): r for r in rows}
    for name in ("mask1", "tile1"):
        r = by[(name, "learned")]
        assert float(r["cpsnr"]) > 20 and float(r["ops_per_z"]) > 0
        assert "filters train" in r["note"]
        assert float(r["wall_sigma_mm"]) > 0 and 0 < float(r["rgbd_valid"]) <= 1
    # bilinear on Mask1: 6 additions and 1 division (opcount's count) at 1/4 of the sites
    assert float(by[("mask1", "bilinear")]["ops_per_z"]) == 7.0
    assert float(by[("mask1", "bilinear")]["ops_per_pixel"]) == 7.0 / 4
    assert float(by[("mask1", "bilinear")]["meas_per_mp"]) == pytest.approx(250000)
    assert float(by[("tile1", "bilinear")]["z_fill"]) == pytest.approx(2 / 16)
    rect = by[("z2x1-p4x4-alig", "bilinear")]
    assert rect["wall_sigma_mm"] == "" and "not supported: 2x1 Z pixels" in rect["note"]
    assert float(rect["cpsnr"]) > 20                 # its colour is still measured
    doc = json.loads((out / "pattern_study.json").read_text())
    assert doc["train"]["name"] == "train" and doc["rgbd"] == ["ramp"]
    md = (out / "pattern_study.md").read_text()
    assert "rgbz-fast pattern-study --dataset" in md and "![Pareto plot](pattern_study.png)" in md
    assert (out / "pattern_study.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_resume_from_the_cache_after_an_interrupt(tiny, tmp_path, monkeypatch):
    cache = tmp_path / "cache"
    kw = dict(presets=("mask1", "mask2"), settings=FAST, cache_dir=cache, progress=False,
              workers=1)
    calls = []
    real = ps._wall_task

    def wall_then_interrupt(cand, settings):
        calls.append(cand.name)
        if calls == ["mask1", "mask2"]:              # Ctrl-C during the second wall
            raise KeyboardInterrupt
        return real(cand, settings)

    monkeypatch.setattr(ps, "_wall_task", wall_then_interrupt)
    with pytest.raises(KeyboardInterrupt):
        ps.pattern_study(tiny / "ds", **kw)
    assert calls == ["mask1", "mask2"]
    calls.clear()
    first = ps.pattern_study(tiny / "ds", **kw)
    assert calls == ["mask2"]                            # mask1's wall came from the cache

    def no_work(*a, **k):
        raise AssertionError("recomputed")

    monkeypatch.setattr(ps, "_wall_task", no_work)
    monkeypatch.setattr("rgbz_fast.evaluation._run.reconstruct", no_work)
    monkeypatch.setattr(ps, "op_cost", no_work)
    again = ps.pattern_study(tiny / "ds", **kw)
    assert again["rows"] == first["rows"]


def test_dask_local_cluster_gives_the_same_numbers(tiny, tmp_path):
    distributed = pytest.importorskip("distributed")
    kw = dict(presets=("mask1",), tiles=("ZRGR/BGBG/GRZR/BGBG",), settings=FAST,
              progress=False, workers=1)
    local = ps.pattern_study(tiny / "ds", **kw)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        remote = ps.pattern_study(tiny / "ds", scheduler=cluster.scheduler_address, **kw)
    assert remote["rows"] == local["rows"]
    assert remote["scheduler"] == cluster.scheduler_address


def test_dask_workers_warnings_are_the_callers(tiny, tmp_path, capfd):
    """A Dask worker of another process printed a task's warnings itself (here: damaged cache
    entries, computed again), past the caller's filters; the caller issues them (H125)."""
    import warnings

    distributed = pytest.importorskip("distributed")
    kw = dict(presets=("mask1",), settings=FAST, progress=False, workers=1,
              cache_dir=tmp_path / "cache")
    first = ps.pattern_study(tiny / "ds", **kw)
    entries = sorted((tmp_path / "cache").rglob("*.json"))
    assert entries
    for e in entries:
        e.write_text("x")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        capfd.readouterr()
        with warnings.catch_warnings(record=True) as got:
            warnings.simplefilter("always")
            again = ps.pattern_study(tiny / "ds", scheduler=cluster.scheduler_address, **kw)
        assert "is not JSON" not in capfd.readouterr().err       # no worker printed one
    assert again["rows"] == first["rows"]
    msgs = [str(w.message) for w in got if "is not JSON" in str(w.message)]
    assert msgs and all(m.startswith("cache_dir: ") for m in msgs), [str(w.message) for w in got]


def test_method_that_does_not_apply_is_a_note(tiny):
    tile = "ZZ/ZZ/ZZ/ZZ/ZZ/ZZ/GR/BG"               # six rows of Z: none of its colour near
    assert "does not apply" in ps.method_note(Pattern(tile), "bilinear")
    assert ps.method_note(get_pattern("mask1"), "sg") == ""
    settings = ps.StudySettings(methods=("bilinear", "sg"), wall_shape=(96, 96))
    res = ps.pattern_study(tiny / "ds", presets=("mask1",), tiles=(tile,), settings=settings,
                           progress=False, workers=1)
    rows = [r for r in res["rows"] if r["layout"] == "tile1"]
    assert [r["cpsnr"] for r in rows] == [None, None]
    for r in rows:                                 # no colour, so no guide: depth unguided
        assert r["note"].startswith("does not apply: pattern: the Z site")
        assert "depth without the colour guide" in r["note"] and r["wall_sigma_mm"] > 0
    assert all(r["cpsnr"] > 20 for r in res["rows"] if r["layout"] == "mask1")


def test_line_buffers_and_multipliers_come_from_the_fixed_point_model():
    """The hardware columns are hardware_cost's line buffers and variable multipliers where
    the fixed-point model covers the method and the period, absent elsewhere."""
    from rgbz_fast.hardware import hardware_cost

    for tile, method in (("mask1", "sg"), ("ZRGR/BGBG/GRZR/BGBG", "bi"), ("mask2", "bilinear")):
        cost = hardware_cost(get_pattern(tile), method)
        assert ps._hardware(get_pattern(tile), method) == {
            "line_buffers": cost.line_buffers,
            "multipliers": sum(cost.multipliers().values())}
    assert ps._hardware(get_pattern("mask1"), "sg")["line_buffers"] == 4
    assert ps._hardware(get_pattern("mask1"), "bilinear")["multipliers"] == 0
    assert ps._hardware(get_pattern("mask1"), "learned") == {}
    assert ps._hardware(get_pattern("rows"), "edi_rows") == {}
    sixteen = "/".join(["ZRGRGRGRGRGRGRGR"] + ["BGBGBGBGBGBGBGBG", "GRGRGRGRGRGRGRGR"] * 7
                       + ["BGBGBGBGBGBGBGBG"])
    assert ps._hardware(Pattern(sixteen), "sg") == {}            # period 16: beyond the model
    from rgbz_fast._devtools.pattern_report import COLUMNS

    assert {"line_buffers", "multipliers"} <= {c[0] for c in COLUMNS}


def test_the_text_table_keeps_names_and_tiles_whole():
    """The terminal table is to copy from: an 8x8 tile (71 characters) and a long layout name
    are printed whole (they had been cut to 24 and 22 characters), in aligned columns."""
    from rgbz_fast._devtools.pattern_report import to_text

    tile = "/".join(["ZZGRGRGR", "ZZBGBGBG"] + ["GRGRGRGR", "BGBGBGBG"] * 3)
    rows = [{"layout": "generated-block2-staggered-0.0625", "tile": tile, "z_fill": 0.0625,
             "method": "sg", "cpsnr": 33.1, "ops_per_pixel": 2.5, "wall_sigma_mm": 4.2,
             "best": True},
            {"layout": "mask1", "tile": "ZR/BG", "z_fill": 0.25, "method": "sg", "cpsnr": 30.0,
             "ops_per_pixel": 9.0, "wall_sigma_mm": 3.0, "best": True}]
    lines = to_text({"rows": rows}).splitlines()
    assert tile in lines[2] and "generated-block2-staggered-0.0625" in lines[2]
    assert len({line.index("%") for line in lines[2:]}) == 1          # aligned
