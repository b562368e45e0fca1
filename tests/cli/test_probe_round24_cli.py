"""Probe round 24: command-line findings (evaluate-depth's rgbnir section)."""

from __future__ import annotations

import json

import pytest

from rgbz_fast._cli import main
from _support import SHARED_DATA


def test_evaluate_depth_rgbnir_without_its_folder_is_refused(tmp_path, capsys):
    """J-04: ``--sections rgbnir`` with no rgbnir folder beside --data printed nothing (or
    {}) and exited 0; ``--rgbnir DIR`` names the folder; the default sections skip a
    missing one with a line on stderr."""
    data = tmp_path / "rgbd"
    data.mkdir()
    assert main(["evaluate-depth", "--data", str(data), "--sections", "rgbnir"]) == 2
    err = capsys.readouterr().err
    assert (f"error: --sections: rgbnir needs the RGB-NIR pairs: {tmp_path / 'rgbnir'} is "
            "not a folder; pass --rgbnir DIR") in err
    assert main(["evaluate-depth", "--sections", "rgbnir", "--rgbnir",
                 str(tmp_path / "none")]) == 2
    assert f"error: --rgbnir: {tmp_path / 'none'} is not a folder" in capsys.readouterr().err
    assert main(["evaluate-depth", "--sections", "noise", "--json"]) == 0
    assert "noise" in json.loads(capsys.readouterr().out)
    # --data for sections that do not read it is refused, as --patterns and --rgbnir are
    # (round 25, CLAIMS 02: it had been accepted and ignored)
    assert main(["evaluate-depth", "--data", str(data), "--sections", "noise", "--json"]) == 2
    assert ("error: --data: the sections noise do not read the RGB-D scenes; --data applies "
            "to scenes, upsample, range") in capsys.readouterr().err


@pytest.mark.skipif(not (SHARED_DATA / "rgbnir").is_dir(),
                    reason="../shared/data/rgbnir is absent (a user's checkout)")
def test_evaluate_depth_reads_the_rgbnir_folder_it_is_given(tmp_path, capsys):
    pairs = tmp_path / "pairs"
    pairs.mkdir()
    for name in ("0003_rgb.png", "0003_nir.png"):
        (pairs / name).symlink_to(SHARED_DATA / "rgbnir" / name)
    assert main(["evaluate-depth", "--sections", "rgbnir", "--rgbnir", str(pairs),
                 "--patterns", "mask2", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["rgbnir"]
    assert {r["pair"] for r in rows} == {"0003"} and {r["pattern"] for r in rows} == {"mask2"}


def test_evaluate_depth_refuses_patterns_no_section_measures(capsys):
    """I-04: ``--sections noise --patterns TILE`` measured Mask1 and Mask2 and exited 0."""
    assert main(["evaluate-depth", "--sections", "noise,range", "--patterns",
                 "ZRGR/BGBG/GRZR/BGBG"]) == 2
    assert ("error: --patterns: the sections noise,range measure mask1 and mask2; --patterns "
            "applies to scenes, upsample and rgbnir") in capsys.readouterr().err


def test_train_names_its_pattern_option(tmp_path, capsys):
    """I-06: a pattern without Z sites was refused naming "patterns" and "the evaluation"."""
    assert main(["train", "--dataset", str(tmp_path), "--pattern", "bayer", "--out",
                 str(tmp_path / "f.npz")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["rgbz-fast train: error: --pattern: 'bayer' has no Z site; give an RGB-Z "
                   "pattern such as 'mask1'"]


def test_evaluate_depth_refuses_an_rgbnir_folder_without_pairs_or_unread(tmp_path, capsys):
    """Review of round 24: an rgbnir folder without pairs printed {"rgbnir": []} and exited
    0; --rgbnir with no rgbnir section was accepted and ignored."""
    empty = tmp_path / "pairs"
    empty.mkdir()
    (empty / "0001_rgb.png").write_bytes(b"")            # no NIR beside it: no pair
    assert main(["evaluate-depth", "--sections", "rgbnir", "--rgbnir", str(empty)]) == 2
    assert f"error: --sections: rgbnir found no pair NNNN_rgb.png + NNNN_nir.png in {empty}" \
        in capsys.readouterr().err
    # the default sections with that folder given: refused as well (it had printed an empty
    # section and exited 0)
    assert main(["evaluate-depth", "--rgbnir", str(empty)]) == 2
    assert f"error: --rgbnir: rgbnir found no pair NNNN_rgb.png + NNNN_nir.png in {empty}" \
        in capsys.readouterr().err
    assert main(["evaluate-depth", "--sections", "noise", "--rgbnir", str(empty)]) == 2
    assert ("error: --rgbnir: the sections noise do not read the RGB-NIR pairs; --rgbnir "
            "applies to the rgbnir section") in capsys.readouterr().err


def test_evaluate_depth_names_with_a_pipe_stay_in_their_cell():
    """Probe round 24 (TB-04): a scene folder named 'al|oe' split its cell, and every column
    after it moved one to the right."""
    from rgbz_fast.evaluation import depth_report

    row = dict(scene="al|oe", pattern="mask1", guide="none", depth_min=1.2, depth_max=1.9,
               valid=9, known=10, wrong=1, wrong_valid=0, low_signal=1, flying=0,
               rmse_valid=0.01)
    table = [l for l in depth_report({"scenes": [row]}).splitlines() if l.startswith("| al")]
    assert table[0].startswith("| al\\|oe | mask1 |")
    assert len(table[0].replace("\\|", "").split("|")) == 14          # 12 cells


def test_evaluate_depth_takes_quiet(capsys):
    """Probe round 24 (TB-02): the command, half a minute or more, took no --quiet."""
    assert main(["evaluate-depth", "--sections", "noise", "--quiet", "--json"]) == 0
    assert "noise" in json.loads(capsys.readouterr().out)


def test_evaluate_seed_is_evalconfigs(tmp_path, capsys):
    """Round 25 (PARITY): EvalConfig(seed=) had no flag, so the command reproduced seed 0
    only; --seed with --noise gives the API's numbers for that seed."""
    import imageio.v3 as iio
    import numpy as np

    from rgbz_fast.evaluation import EvalConfig, evaluate
    from rgbz_fast.io import folder_dataset

    (tmp_path / "ds").mkdir()
    rng = np.random.default_rng(0)
    iio.imwrite(tmp_path / "ds" / "a.png", (rng.random((64, 64, 3)) * 255).astype(np.uint8))
    opts = ["--patterns", "mask1", "--methods", "sg", "--metrics", "cfa_psnr"]
    assert main(["evaluate", "--dataset", str(tmp_path / "ds"), *opts, "--noise", "--seed",
                 "3", "--no-plots", "--no-cache", "--quiet", "--json",
                 "--out", str(tmp_path / "o")]) == 0
    got = json.loads(capsys.readouterr().out)["mask1/sg/cfa_psnr"]["mean"]
    cfg = EvalConfig(patterns=("mask1",), methods=("sg",), metrics=("cfa_psnr",), noise=True)
    for seed, equal in ((3, True), (0, False)):
        res = evaluate(folder_dataset(tmp_path / "ds"), EvalConfig(**{
            **{k: getattr(cfg, k) for k in ("patterns", "methods", "metrics", "noise")},
            "seed": seed}), progress=False)
        assert (res.summary()[("mask1", "sg", "cfa_psnr")][0] == got) is equal
