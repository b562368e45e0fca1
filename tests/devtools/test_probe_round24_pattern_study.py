"""Probe round 24 (K-11, K-04): ``rgbz-fast pattern-study``'s own cache and its colour means.

K-11: the study's cache entries (``cache/cost``, ``cache/wall``, ``cache/rgbd``) were read
with a bare ``json.loads(f.read_text())``: a FIFO under an entry's name blocked the study
forever, and an edited entry was served as it was (ops/px 0.25 for 10.25). They are now
evaluate's entries: read through the guarded reader, checksummed, a bad one recomputed
with a warning naming the file.

K-04: the colour columns took ``Results.summary()``'s means, which leave a +inf PSNR (an
image every method reconstructs exactly: a flat one) out of the PSNR means and not out of
the zipper's, without a word; with a flat image alone the CPSNR was NaN, printed in bold as
the best. The means now cover the same images in every column and layout, a note names the
images left out, a cell of +inf only is inf, and the JSON stays strict."""

from __future__ import annotations

import json
import os

import imageio.v3 as iio
import numpy as np
import pytest

from rgbz_fast._cli import main
from rgbz_fast._devtools import pattern_report as report
from rgbz_fast._devtools import pattern_study as ps
from rgbz_fast._devtools._common import json_text
from _support import run_past_a_fifo

#: small and quick: two methods, a 48x48 wall
FAST = ps.StudySettings(methods=("bilinear", "bi"), wall_shape=(48, 48))


def _strict(text):
    """JSON as a strict reader takes it: NaN and Infinity refused."""
    def refuse(name):
        raise ValueError(f"{name} in strict JSON")
    return json.loads(text, parse_constant=refuse)


@pytest.fixture(scope="module")
def sets(tmp_path_factory):
    """Folders of 48x48 images: ``tex`` two textured ones, ``mix`` the same and a flat one,
    ``flat`` the flat one alone."""
    root = tmp_path_factory.mktemp("k04")
    y, x = np.mgrid[0:48, 0:48]
    tex = np.stack([(x * 7 + y) % 256, (y * 5) % 256, ((x + 3 * y) * 2) % 256],
                   -1).astype(np.uint8)
    flat = np.full((48, 48, 3), 120, np.uint8)
    for folder, images in (("tex", {"a": tex, "b": tex[::-1]}),
                           ("mix", {"0flat": flat, "a": tex, "b": tex[::-1]}),
                           ("flat", {"0flat": flat})):
        (root / folder).mkdir()
        for name, img in images.items():
            iio.imwrite(root / folder / f"{name}.png", np.ascontiguousarray(img))
    return root


# --------------------------------------------------------------------------- K-11: the cache
def _compute(calls, value):
    def compute():
        calls.append(1)
        return value
    return compute


def test_cache_entries_are_checksummed_and_a_bad_one_recomputed(tmp_path):
    """Probe round 24 (K-11): an edited entry ({"bi": 1.0} for 41 operations) was served as it
    was; any entry that is not the one the study wrote -- edited values, text, not JSON, an
    entry moved under another key, a file too large, a link to a device, a folder -- is now
    computed again with a warning naming the file, and written again."""
    calls = []
    compute = _compute(calls, {"bi": 41.0})
    assert ps._cached(tmp_path, "cost", "k1", compute) == {"bi": 41.0}
    assert ps._cached(tmp_path, "cost", "k1", compute) == {"bi": 41.0} and len(calls) == 1
    entry = tmp_path / "cost" / "k1.json"
    good = entry.read_text()
    ps._cached(tmp_path, "cost", "k2", _compute([], {"bi": 1.0}))
    other = (tmp_path / "cost" / "k2.json").read_text()
    for bad in ('{"bi": 1.0}', good.replace("41.0", "1.0"), other, "[1", "\xff", "NaN",
                '{"check": 1, "values": 2}', " " * 70_000):
        entry.write_text(bad)
        with pytest.warns(RuntimeWarning, match=f"^cache_dir: {entry}"):
            assert ps._cached(tmp_path, "cost", "k1", compute) == {"bi": 41.0}, bad
        assert entry.read_text() == good, bad
    entry.unlink()
    os.symlink(os.devnull, entry)                        # a link to a device: replaced
    with pytest.warns(RuntimeWarning, match="is a character device, not a regular file"):
        assert ps._cached(tmp_path, "cost", "k1", compute) == {"bi": 41.0}
    assert not entry.is_symlink() and entry.read_text() == good
    entry.unlink()
    entry.mkdir()                                        # a folder: the result, two warnings
    with pytest.warns(RuntimeWarning, match="is a folder"):
        assert ps._cached(tmp_path, "cost", "k1", compute) == {"bi": 41.0}
    assert len(calls) == 11


def test_a_fifo_in_the_cache_does_not_block(tmp_path):
    """Probe round 24 (K-11): a FIFO under an entry's name blocked pattern-study forever; it is
    now refused by the guarded reader (a warning), the value computed and written in its
    place."""
    entry = tmp_path / "wall" / "k.json"
    entry.parent.mkdir()
    os.mkfifo(entry)
    def run():
        with pytest.warns(RuntimeWarning, match="is a FIFO"):
            return ps._cached(tmp_path, "wall", "k", lambda: {"wall_n": 3})

    done = run_past_a_fifo(run, entry, 20, "a FIFO in pattern-study's cache blocked it")
    assert done == [{"wall_n": 3}] and entry.is_file()
    assert json.loads(entry.read_text())["values"] == {"wall_n": 3}


def test_an_edited_cost_entry_does_not_change_the_study(sets, tmp_path, monkeypatch):
    """Probe round 24 (K-11), as the user met it: the cost entry edited to {"bi": 1.0} made the
    table print bi's ops/px 0.25 instead of 10.25. The study's numbers are now those of a
    clean run, and a warning names the entry."""
    # the keys hold the package's digest: fixed here, so that a file edited meanwhile in the
    # working tree cannot move them between the two runs
    monkeypatch.setattr(ps, "results_version", lambda: "k11")
    kw = dict(presets=("mask1",), settings=FAST, cache_dir=tmp_path / "cache",
              progress=False, workers=1)
    first = ps.pattern_study(sets / "tex", **kw)
    (entry,) = (tmp_path / "cache" / "cost").glob("*.json")
    entry.write_text('{"bi": 1.0, "bilinear": 1.0}')
    with pytest.warns(RuntimeWarning, match=f"^cache_dir: {entry}"):
        again = ps.pattern_study(sets / "tex", **kw)
    assert again["rows"] == first["rows"]
    bi = next(r for r in again["rows"] if r["method"] == "bi")
    assert bi["ops_per_pixel"] == pytest.approx(10.25)


# --------------------------------------------------------------------------- K-04: the means
def test_common_means_cover_the_same_images_in_every_column():
    """Probe round 24 (K-04): a flat image's +inf was left out of the CPSNR mean and kept in the
    zipper's; every column and layout now averages the images on which all are finite."""
    inf = float("inf")

    def cell(cfa, cps, zip_):
        names = ("flat", "a", "b")
        return {"per_image": {"cfa_psnr": dict(zip(names, cfa)),
                              "cpsnr": dict(zip(names, cps)),
                              "zipper": dict(zip(names, zip_)), }}

    colours = [{"bi": cell((inf, 40.0, 42.0), (inf, 30.0, 32.0), (0.0, 3.0, 5.0)),
                "sg": {"note": "does not apply: ..."}},
               {"bi": cell((50.0, 41.0, 43.0), (60.0, 31.0, 33.0), (0.0, 4.0, 6.0))}]
    note, left = ps._common_means(colours, ["flat", "a", "b"])
    assert left == ["flat"] and "left out: flat" in note and "+inf" in note
    assert colours[0]["bi"]["cpsnr"] == 31.0 and colours[0]["bi"]["zipper"] == 4.0
    assert colours[1]["bi"]["cpsnr"] == 32.0 and colours[1]["bi"]["zipper"] == 5.0
    assert "cpsnr" not in colours[0]["sg"]
    # no image left: +inf on every image is inf, anything else no mean; never NaN
    colours = [{"bi": cell((inf,), (inf,), (0.0,))}]
    note, left = ps._common_means(colours, ["flat"])
    assert left == ["flat"] and "no image" in note
    assert colours[0]["bi"]["cpsnr"] == inf and colours[0]["bi"]["zipper"] is None
    assert ps._common_means([{"bi": cell((1.0,), (2.0,), (3.0,))}], ["flat"]) == ("", [])


def test_a_flat_image_is_left_out_of_every_mean_and_said(sets):
    """Probe round 24 (K-04), as the user met it: on two textured images and a flat one, the
    CPSNR averaged the 2 textured ones and the zipper all 3, without a word. Every colour
    mean is now that of the textured images alone, and the rows (CSV, Markdown) and the
    JSON name the image left out."""
    kw = dict(presets=("mask1",), settings=FAST, progress=False, workers=1)
    tex = ps.pattern_study(sets / "tex", **kw)
    mix = ps.pattern_study(sets / "mix", **kw)
    for a, b in zip(tex["rows"], mix["rows"]):
        for k in ps.COLOUR_METRICS:
            assert b[k] == pytest.approx(a[k]), (b["method"], k)
        assert "left out: 0flat" in b["note"] and "+inf" in b["note"]
        assert "left out" not in a["note"]
    assert mix["left_out"] == ["0flat"] and tex["left_out"] == []
    assert "left out: 0flat" in report.to_markdown(mix)
    assert _strict(json_text(mix))["left_out"] == ["0flat"]


def test_a_flat_image_alone_prints_inf_never_a_bold_nan(sets, tmp_path, capsys):
    """Probe round 24 (K-04): with only a flat image, pattern-study printed CPSNR ``nan``, in
    bold as the best, where evaluate prints inf. Every method's CPSNR is now inf (exact on
    every image), no NaN is printed or ranked, and --json stays strict (inf as null)."""
    res = ps.pattern_study(sets / "flat", presets=("mask1",), settings=FAST, progress=False,
                           workers=1)
    assert [r["cpsnr"] for r in res["rows"]] == [float("inf")] * 2
    assert res["left_out"] == ["0flat"]
    assert "nan" not in report.to_markdown(res).lower().split()
    assert "nan" not in report.to_text(res).lower()
    assert "**nan**" not in report.to_markdown(res).lower()
    code = main(["pattern-study", "--dataset", str(sets / "flat"), "--presets", "mask1",
                 "--methods", "bilinear,bi", "--no-cache", "--no-plots", "--quiet", "--json",
                 "--out", str(tmp_path / "out")])
    out = capsys.readouterr().out
    assert code == 0
    doc = _strict(out)
    assert [r["cpsnr"] for r in doc["rows"]] == [None, None] and doc["left_out"] == ["0flat"]
    _strict((tmp_path / "out" / "pattern_study.json").read_text())
    assert "nan" not in (tmp_path / "out" / "pattern_study.md").read_text().lower().split()
