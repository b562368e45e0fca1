"""Operation counts of the counting build against numbers derived by hand from
csrc/recon_core.template.h, and the reading of the paper's Table 1."""

from __future__ import annotations

import json

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast import _kernels_count
from rgbz_fast.reconstruction._plans import build_plans
from rgbz_fast.reconstruction._reconstruct import _plans_for
from rgbz_fast._cli import main
from rgbz_fast._devtools.opcount import (CATEGORIES, TABLE1, count_operations, opcount_report,
                                         opcount_table)


def n_candidates(pattern, method="bilinear"):
    """{group: number of candidates} of the pattern's plans."""
    _, plans = build_plans(rz.get_pattern(pattern), method)
    out = {}
    for p in plans:
        out["green" if p["target"] == 1 else "red/blue"] = int(p["n_cand"])
    return out


def test_candidates_match_the_caption_of_table1():
    # Table 1's caption: 11 pixels for green, 8 for red/blue on Mask2; Mask1 has 4 greens
    assert n_candidates("mask1") == {"green": 4}
    assert n_candidates("mask2") == {"green": 11, "red/blue": 8}


@pytest.mark.parametrize("group", ["green", "red/blue"])
def test_table1_mask2_pairs_are_red_blue_then_green(group):
    # BI: 2 n^2 additions and n divisions, n the number of candidates. The first
    # number of each Mask2 cell (128, 8) fits n = 8, i.e. red/blue; the second green.
    n = n_candidates("mask2")[group]
    paper = TABLE1[("bi", "mask2", group)]
    assert paper["add"] == 2 * n * n
    assert paper["div"] == n
    assert TABLE1[("bi", "mask1", "green")]["add"] == 2 * 4 * 4


@pytest.mark.parametrize("precision", ["float32", "float64"])
@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_bilinear_counts_by_hand(pattern, precision):
    # rgbz_mean: c0 + sum_{k>=1} (c_k - c0) / n  ->  (n-1) subtractions, (n-2) additions,
    # 1 final addition, 1 division; nothing else. Mask1: 6 + 1; Mask2 green 20 + 1,
    # red/blue 14 + 1.
    res = count_operations("bilinear", pattern, precision=precision, shape=(32, 32))
    expect = {"mask1": {"green": 6}, "mask2": {"green": 20, "red/blue": 14}}[pattern]
    assert set(res) == set(expect)
    for g, adds in expect.items():
        n = n_candidates(pattern)[g]
        assert adds == 2 * n - 2
        for stat in ("mean", "min", "max"):
            c = res[g][stat]
            assert c["add"] == adds and c["div"] == 1
            assert all(c[k] == 0 for k in CATEGORIES if k not in ("add", "div"))


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_bi_counts_by_hand(pattern):
    # the plans of _plans.py: beta (eq. 4): n(n-1)/2 |c_k - c_m| (one sub + one abs
    # each), each added to both S_k and S_m (n(n-1) adds); weights alpha_k / S_k (n
    # divisions); den: n-1 adds; num: n-1 subs, n-1 muls, n-1 adds; result c0 + num/den:
    # 1 add, 1 div. BI never falls back (alpha/S > 0): the counts do not depend on the data.
    res = count_operations("bi", pattern, shape=(32, 32), seed=3, path="generic")
    auto = count_operations("bi", pattern, shape=(32, 32), seed=3)
    for g, r in res.items():
        n = n_candidates(pattern)[g]
        pairs = n * (n - 1) // 2
        expect = dict(add=3 * pairs + 3 * (n - 1) + 1, mul=n - 1, div=n + 1, exp=0, abs=pairs,
                      cmp=0, sqrt=0, atan2=0)
        assert r["min"] == expect and r["max"] == expect
        if pattern == "mask1":
            # the Mask1 fast path (recon_mask1.h) starts num from its first product
            expect["add"] -= 1
        assert auto[g]["min"] == expect and auto[g]["max"] == expect


@pytest.mark.parametrize("method,pattern,n_exp", [
    ("edi_central", "mask1", 4), ("edi_central", "mask2", 4),
    ("edi_line", "mask1", 4), ("edi_line", "mask2", 4),
    ("sg", "mask1", 8), ("sg", "mask2", 12),
])
def test_exponentials_as_table1(method, pattern, n_exp):
    res = count_operations(method, pattern, shape=(32, 32), path="generic")
    for g, r in res.items():
        assert r["min"]["exp"] == r["max"]["exp"] == n_exp
        assert TABLE1[(method, pattern, g)]["exp"] == n_exp
    # the Mask1 fast path of the EDI methods evaluates only the two diagonal gammas:
    # every Mask1 candidate is diagonal, the axis gradients only set sigma
    fast = count_operations(method, pattern, shape=(32, 32))
    expect = 2 if (pattern == "mask1" and method != "sg") else n_exp
    for g, r in fast.items():
        assert r["min"]["exp"] == r["max"]["exp"] == expect
        # every exponential argument needs sigma: one reciprocal per gamma family
        assert r["min"]["div"] >= (2 if (method == "sg" and pattern == "mask2") else 1)


@pytest.mark.parametrize("method", ["edi_central", "edi_line", "sg"])
def test_min_mean_max_ordered_and_fallback_only_adds(method):
    res = count_operations(method, "mask1", shape=(48, 48), seed=1)
    r = res["green"]
    for k in CATEGORIES:
        assert r["min"][k] <= r["mean"][k] <= r["max"][k]
    # the only data-dependent branch is the fallback to the plain mean: it changes
    # the additions and nothing else
    for k in CATEGORIES:
        if k != "add":
            assert r["min"][k] == r["max"][k]


def test_per_site_counts_agree_with_per_plan_counts():
    # the per-site trick (one plan per site) against the kernel's own per-plan counters,
    # for a method whose counts do not depend on the data
    pattern = rz.mask2()
    rng = np.random.default_rng(0)
    data = rng.integers(0, 2048, (32, 32)).astype(np.uint16)
    data[pattern.z_mask(data.shape)] = 0
    phase_map, plans, n = _plans_for(pattern, "bi", "auto", "intensity")
    counts = np.zeros(n * _kernels_count.NOPS, np.uint64)
    _kernels_count.reconstruct(data, np.empty_like(data), 1, 4, 4, phase_map, plans, n, 1e-3, 0.0,
                               0.5, 2047.0, 0, 1, opcounts=counts)
    per_plan = counts.reshape(n, -1).astype(float) / (data.size // 16)
    res = count_operations("bi", pattern, frame=rz.RawFrame(data, pattern, 11))
    _, pl = build_plans(pattern, "bi")
    for i, t in enumerate(pl["target"]):
        g = "green" if t == 1 else "red/blue"
        assert [res[g]["mean"][k] for k in CATEGORIES] == per_plan[i].tolist()


@pytest.mark.parametrize("phase", ["GRBG", "RGGB", "BGGR", "GBRG"])
def test_mask1_fast_path_counted_on_every_phase(phase):
    # every interior site of every Mask1 phase takes the fast path: its counts are the
    # plan interpreter's minus the additions that start from 0 (BI: one)
    pat = rz.mask1(phase)
    auto = count_operations("bi", pat, shape=(20, 20))["green"]
    gen = count_operations("bi", pat, shape=(20, 20), path="generic")["green"]
    assert auto["min"]["add"] == auto["max"]["add"] == gen["max"]["add"] - 1


def test_counts_on_a_frame_and_kwargs():
    img = np.random.default_rng(2).integers(0, 256, (24, 24, 3), dtype=np.uint8)
    frame = rz.mosaic(img, rz.mask1())
    a = count_operations("sg", frame=frame, pattern=None, sigma_rel=0.0)
    assert a["green"]["n_sites"] == 10 * 10
    b = count_operations("sg", frame=frame, pattern=None, exp="fast", sigma_rel=0.5)
    # the relative floor of sigma: the sum of the 8 SGs (7 adds), rel * sum (1 mul),
    # / count (1 div), one more comparison
    a, b = a["green"]["min"], b["green"]["min"]
    assert (b["add"] - a["add"], b["mul"] - a["mul"], b["div"] - a["div"],
            b["cmp"] - a["cmp"]) == (7, 1, 1, 1)


def test_bad_arguments():
    with pytest.raises(ValueError, match="method"):
        count_operations("nope", "mask1")
    with pytest.raises(TypeError, match="unexpected keyword"):
        count_operations("bi", "mask1", sigma=2)
    with pytest.raises(ValueError, match="shape"):
        count_operations("bi", "mask2", shape=(6, 8))
    assert count_operations("bi", "rows", shape=(64, 64))["green"]["n_sites"] > 0
    with pytest.raises(ValueError, match="edi_rows"):
        count_operations("edi_rows", "mask1")


def test_edi_rows_counts():
    # five |differences| (5 subs, 5 abs), the vertical mean (1 add, 1 mul), four comparisons
    # for the smallest difference; a dominant edge adds 1 mul + 1 cmp and the median 3 cmps
    res = count_operations("edi_rows", "rows", shape=(48, 32))
    for r in res.values():
        assert r["min"]["add"] == r["max"]["add"] == 6 and r["min"]["abs"] == 5
        assert r["min"]["mul"] == 1 and r["max"]["mul"] <= 2
        assert 4 <= r["min"]["cmp"] <= r["max"]["cmp"] <= 4 + 1 + 3
        assert r["max"]["exp"] == r["max"]["div"] == 0


def test_tof_demodulation_counts_when_built():
    from rgbz_fast._devtools.opcount import count_tof_operations

    c = count_tof_operations(n_sites=16)
    if c is None:
        pytest.skip("this build does not count the ToF demodulation")
    # I = A0 - A2, Q = A3 - A1, one atan2, one sqrt (tof.c)
    assert c["atan2"] == 1 and c["sqrt"] == 1 and c["add"] >= 2 and c["exp"] == 0


def test_report_and_table():
    rows = opcount_table(("bilinear", "bi"), ("mask1", "mask2"), shape=(24, 24))
    assert [(r["method"], r["pattern"], r["target"]) for r in rows] == [
        ("bilinear", "mask1", "green"), ("bi", "mask1", "green"),
        ("bilinear", "mask2", "green"), ("bilinear", "mask2", "red/blue"),
        ("bi", "mask2", "green"), ("bi", "mask2", "red/blue")]
    bi1 = rows[1]
    assert bi1["paper"] == TABLE1[("bi", "mask1", "green")]
    assert bi1["path"] == "mask1 fast path" and bi1["generic_mean"]["add"] == 28
    assert bi1["ratio"]["add"] == pytest.approx(bi1["mean"]["add"] / 32)
    assert bi1["add_no_beta"] == bi1["mean"]["add"] - 18
    md = opcount_report(rows, "markdown")
    assert md.splitlines()[0].startswith("| method") and "106 / 128 ×0.83" in md
    assert "106 / 128" in opcount_report(rows, "text")


def test_cli(capsys, tmp_path):
    assert main(["opcount", "--quick", "--json", "--methods", "bilinear,sg", "--image", "none",
                 "--out", str(tmp_path)]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert {r["method"] for r in doc["rows"]} == {"bilinear", "sg"}
    assert (tmp_path / "opcount.md").read_text().startswith("| method")
    assert json.loads((tmp_path / "opcount.json").read_text()) == doc
    assert main(["opcount", "--quick", "--methods", "nope", "--image", "none"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("rgbz-fast opcount: error: method")
    with pytest.raises(SystemExit) as exc:
        main(["opcount", "--shape"])
    assert exc.value.code == 2
