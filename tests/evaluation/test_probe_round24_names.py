"""Probe round 24 (K-09): a dataset image whose file name is not UTF-8.

``b"caf\\xe9.png"`` (a Latin-1 name from an old camera card, or a zip made on Windows) is
what Python names ``"caf\\udce9.png"``: a lone surrogate stands for the byte 0xE9. simulate,
reconstruct, train, hardware and tradeoff read and print it; ``rgbz-fast evaluate`` stopped
with exit 2 and ``'utf-8' codec can't encode character '\\udce9' ... surrogates not
allowed``, naming nothing: with the cache at the first image (the cache folder's hash
encoded the name as strict UTF-8), with ``--no-cache`` after the whole evaluation (the
reports written as strict UTF-8), and with the figures in matplotlib (the crop figure's
title). The run now completes and the reports name the image with its byte escaped."""

from __future__ import annotations

import hashlib
import json
import os
import sys

import imageio.v3 as iio
import numpy as np
import pytest

from rgbz_fast.evaluation import EvalConfig, Results, evaluate, write_reports
from rgbz_fast.evaluation._cache import cache_folder
from rgbz_fast.io import atomic_write

#: the name Python gives the file b"caf\xe9.png" (its stem, the image's name)
NAME = "caf\udce9"

pytestmark = pytest.mark.skipif(sys.platform in ("darwin", "win32"),
                                reason="file names are bytes on Linux and the BSDs only")


def _image(rows, cols, seed):
    y, x = np.mgrid[0:rows, 0:cols]
    return np.stack([(x * 7 + y + seed) % 256, (y * 5) % 256, (x + 3 * y) % 256],
                    -1).astype(np.uint8)


@pytest.fixture
def latin1(tmp_path):
    """A folder of two 40x48 images, one named b"caf\\xe9.png" (not UTF-8), one "z.png"."""
    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "z.png", _image(40, 48, 0))
    try:
        iio.imwrite(os.fsdecode(os.fsencode(str(ds)) + b"/caf\xe9.png"), _image(40, 48, 9))
    except (OSError, UnicodeError):                      # a file system of UTF-8 names only
        pytest.skip("this file system refuses a name that is not UTF-8")
    return ds


CONFIG = EvalConfig(patterns=("mask1",), methods=("bilinear", "bi"),
                    metrics=("cfa_psnr", "cpsnr"))


def test_cache_folder_of_a_name_that_is_not_utf8():
    """Probe round 24 (K-09): ``cache_folder("caf\\udce9")`` raised UnicodeEncodeError for
    every image of such a name; it is a folder now, readable ("caf_"), distinct from the
    folders of "café" and "caf_", and every other name keeps its folder (its hash is the
    UTF-8 one: no existing cache moves)."""
    folder = cache_folder(NAME)
    assert folder.startswith("caf_-")
    assert len({folder, cache_folder("café"), cache_folder("caf_"),
                cache_folder("caf\udcc3\udca9")}) == 4
    for name in ("kodim09", "café", "a b"):
        assert cache_folder(name).endswith(hashlib.sha1(name.encode()).hexdigest()[:10])


def test_atomic_write_escapes_a_lone_surrogate(tmp_path):
    """Probe round 24 (K-09): text naming such an image was refused as a whole ("surrogates
    not allowed"); it is written as UTF-8 with the surrogate escaped, and JSON text (whose
    escapes are ASCII) is written as it is."""
    atomic_write(tmp_path / "t.md", f"| {NAME} | ±1 dB |\n")
    assert (tmp_path / "t.md").read_text(encoding="utf-8") == "| caf\\udce9 | ±1 dB |\n"
    atomic_write(tmp_path / "t.json", json.dumps({"image": NAME}))
    assert json.loads((tmp_path / "t.json").read_text(encoding="utf-8")) == {"image": NAME}


def test_evaluate_and_its_reports_take_a_name_that_is_not_utf8(latin1, tmp_path):
    """Probe round 24 (K-09): with the cache, evaluate stopped at the image; without it, the
    reports (results.csv first) failed after the whole evaluation; with the figures, the crop
    figure of that image failed in matplotlib. Every report is written: the tables name the
    image ``caf\\udce9`` (its byte 0xE9 escaped), the table's file name is ``table_caf_.md``,
    and results.json reads back to the same image names."""
    from rgbz_fast.evaluation._run import dataset_sources

    sources = dataset_sources(str(latin1), None)
    assert [s.name for s in sources] == [NAME, "z"]
    cached = evaluate(sources, CONFIG, processes=1, progress=False,
                      cache_dir=tmp_path / "cache")
    assert evaluate(sources, CONFIG, processes=1, progress=False,
                    cache_dir=tmp_path / "cache").rows == cached.rows        # read back
    out = tmp_path / "out"
    files = write_reports(cached, out, crop_source=sources[0], crop_box=(0, 0, 16, 16))
    names = {f.name for f in files}
    assert {"results.csv", "results.json", "summary.md", "table_caf_.md",
            "crops_caf_.png"} <= names
    assert "caf\\udce9,mask1,bilinear,cfa_psnr," in (out / "results.csv").read_text("utf-8")
    assert "caf\\udce9" in (out / "table_caf_.md").read_text("utf-8")
    back = Results.from_json((out / "results.json").read_text("utf-8"))
    assert back.images() == [NAME, "z"] and back.rows == cached.rows
    # a second run into the folder replaces the first (its manifest lists the safe names)
    assert {f.name for f in write_reports(cached, out, plots=False)} >= {"table_caf_.md"}


def test_cli_evaluate_of_a_dataset_with_a_name_that_is_not_utf8(latin1, tmp_path, capsys):
    """Probe round 24 (K-09): ``rgbz-fast evaluate`` exited 2 with "'utf-8' codec can't encode
    character '\\udce9' ... surrogates not allowed", with and without ``--no-cache``."""
    from rgbz_fast._cli import main

    for extra in ([], ["--no-cache"]):
        out = tmp_path / f"ev{len(extra)}"
        code = main(["evaluate", "--dataset", str(latin1), "--patterns", "mask1", "--methods",
                     "bi", "--metrics", "cfa_psnr", "--no-plots", "--processes", "1",
                     "--quiet", "--out", str(out), *extra])
        err = capsys.readouterr().err
        assert code == 0, err
        assert "caf\\udce9" in (out / "results.csv").read_text("utf-8")
