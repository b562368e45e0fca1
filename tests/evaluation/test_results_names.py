"""Round 25 (API08): the Results accessors take the names EvalConfig takes -- a Pattern
object as its preset name or tile -- and refuse a name not in the results everywhere,
``ir_estimated`` included (it had returned [], which read as "no estimated guide")."""

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast.evaluation import EvalConfig, Results

TILE = "ZRGRGRGR/BGBGBGBG/GRGRZRGR/BGBGBGBG"


def _results():
    cfg = EvalConfig(patterns=[rz.mask1(), rz.Pattern(TILE)], methods=("bilinear", "sg"),
                     metrics=("cpsnr",))
    rows = [{"image": i, "pattern": p, "method": m, "metric": "cpsnr", "value": v + d}
            for p in cfg.patterns for i, v in (("a", 30.0), ("b", 20.0))
            for m, d in (("bilinear", 0.0), ("sg", 1.5))]
    return Results(rows, cfg)


def test_a_pattern_object_selects_its_cells():
    res = _results()
    assert res.config.patterns == ("mask1", TILE)
    for p, name in ((rz.mask1(), "mask1"), (rz.Pattern(TILE), TILE)):
        np.testing.assert_array_equal(res.values(p, "sg", "cpsnr"),
                                      res.values(name, "sg", "cpsnr"))
        assert res.paired(p, "sg", "cpsnr")[1] == pytest.approx(1.5)
        assert res.ir_estimated(p, "sg") == []
    # a Pattern equal to the config's, written otherwise (the review of round 25)
    np.testing.assert_array_equal(res.values(rz.get_pattern("ZR/BG"), "sg", "cpsnr"),
                                  res.values("mask1", "sg", "cpsnr"))


def test_names_not_in_the_results_are_refused_everywhere():
    res = _results()
    for call in (lambda: res.values(rz.mask2(), "sg", "cpsnr"),
                 lambda: res.ir_estimated(rz.mask2(), "sg"),
                 lambda: res.ir_estimated("mask2", "sg")):
        with pytest.raises(ValueError, match=r"^pattern: .* is not in the results \(expected "
                                             r"one of mask1, ZRGR"):
            call()
    with pytest.raises(ValueError, match=r"^method: 'z_guidd' is not in the results"):
        res.ir_estimated("mask1", "z_guidd")
    # a pattern not in the results is named by its tile; a long name is cut with '...'
    with pytest.raises(ValueError, match=r"^pattern: 'ZRGRGRGRGRGR/BGBG.*' is not in"):
        res.values(rz.Pattern("ZRGRGRGRGRGR/BGBGBGBGBGBG/GRGRGRZRGRGR/BGBGBGBGBGBG"), "sg",
                   "cpsnr")
    with pytest.raises(ValueError, match=r"^method: 'x{56}\.\.\. is not in the results"):
        res.values("mask1", "x" * 100, "cpsnr")
