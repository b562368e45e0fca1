"""Non-finite values in Results: the summaries say which means leave them out, and
results.json stays strict JSON (a non-finite value written as "inf", "-inf" or "nan")."""

import json
import math

import numpy as np
import pytest

from rgbz_fast.evaluation import EvalConfig, Results

INF = math.inf
CONFIG = EvalConfig(patterns=("mask1",), methods=("bilinear", "sg"), metrics=("cpsnr", "ssim"))
NOTE_HEAD = "Means leave out infinite values (a test image equal to its reference: PSNR +inf): "


def _results(sg_cpsnr_random=21.0):
    """A flat grey image (CPSNR +inf: the test image equals the reference) and a random one."""
    values = (("grey", "bilinear", "cpsnr", INF), ("grey", "sg", "cpsnr", INF),
              ("rand", "bilinear", "cpsnr", 20.0), ("rand", "sg", "cpsnr", sg_cpsnr_random),
              ("grey", "bilinear", "ssim", 1.0), ("grey", "sg", "ssim", 1.0),
              ("rand", "bilinear", "ssim", 0.5), ("rand", "sg", "ssim", 0.6))
    rows = [{"image": i, "pattern": "mask1", "method": m, "metric": k, "value": v}
            for i, m, k, v in values]
    return Results(rows, CONFIG)


def _fail(constant):
    raise AssertionError(f"not strict JSON: {constant}")


def test_partially_infinite_cells_are_noted():
    res = _results()
    note = NOTE_HEAD + "CPSNR of bilinear and SG on mask1 over 1 of 2 images."
    assert res.nonfinite_note() == note
    md = res.summary_markdown()
    assert md.startswith("Mean ± std over 2 image(s);")
    # one finite value: its mean and no spread (it printed "± 0.00")
    assert "| bilinear | 20.00 | 0.7500 ± 0.3536 |" in md
    assert md.count(note) == 1
    # under the means table, before the paired differences
    assert md.index("| SG |") < md.index(note) < md.index("Paired differences")
    assert ("Differences leave out the images on which either method is not finite (a PSNR "
            "is +inf where a test image equals its reference): Δ CPSNR of SG on mask1 over "
            "1 of 2 images.") in md
    text = res.plain_table()
    assert text.count(note) == 1
    assert "20.0000         " in text and "nan" not in text and "±0.000" not in text


def test_all_infinite_cell_shows_inf_and_is_noted():
    rows = [dict(r, value=INF) if r["metric"] == "cpsnr" and r["method"] == "sg" else r
            for r in _results().rows]
    res = Results(rows, CONFIG)
    note = (NOTE_HEAD + "CPSNR of bilinear on mask1 over 1 of 2 images; CPSNR of SG on mask1: "
            "all 2 images are +inf.")
    md = res.summary_markdown()
    assert "nan" not in md
    assert "| SG | **inf** | **0.8000 ± 0.2828** |" in md          # +inf everywhere: the best
    assert "| bilinear | 20.00 | 0.7500 ± 0.3536 |" in md
    assert md.count(note) == 1
    assert "Δ CPSNR of SG on mask1: none of 2 images." in md
    assert "| SG | — |" in md
    text = res.plain_table()
    assert "nan" not in text and text.count(note) == 1
    sg = next(line for line in text.splitlines() if line.startswith("SG"))
    assert sg.split()[1] == "inf"


def test_finite_results_have_no_note():
    rows = [dict(r, value=30.0) if r["value"] == INF else r for r in _results().rows]
    res = Results(rows, CONFIG)
    assert res.nonfinite_note() == "" and res.left_out() == {}
    assert "leave out" not in res.summary_markdown() and "leave out" not in res.plain_table()


def test_nonfinite_kinds_are_named():
    rows = _results().rows
    rows[3] = dict(rows[3], value=math.nan)                       # SG's rand CPSNR
    note = Results(rows, CONFIG).nonfinite_note()
    assert note.startswith("Means leave out non-finite values")
    assert "CPSNR of bilinear on mask1 over 1 of 2 images (+inf left out)" in note
    assert "CPSNR of SG on mask1: no finite value in 2 images (+inf, nan)" in note


@pytest.mark.parametrize("value", [INF, -INF, math.nan])
def test_json_is_strict_and_round_trips(value):
    res = _results()
    res.rows[3]["value"] = value
    text = res.to_json()
    data = json.loads(text, parse_constant=_fail)
    assert data["rows"][0]["value"] == "inf"
    assert data["rows"][3]["value"] == {INF: "inf", -INF: "-inf"}.get(value, "nan")
    back = Results.from_json(text)
    assert back.config == res.config
    got = [r["value"] for r in back.rows]
    want = [r["value"] for r in res.rows]
    assert all(g == w or (math.isnan(g) and math.isnan(w)) for g, w in zip(got, want))
    assert back.summary_markdown() == res.summary_markdown()


def test_from_json_reads_older_files():
    """Files written before: Infinity and NaN (json.dumps' default) are read too."""
    res = _results(sg_cpsnr_random=math.nan)
    old = json.dumps({"config": json.loads(res.to_json())["config"], "rows": res.rows,
                      "skipped": [], "not_applicable": []}, indent=1)
    assert "Infinity" in old and "NaN" in old
    back = Results.from_json(old)
    assert back.rows[0]["value"] == INF and math.isnan(back.rows[3]["value"])
    assert Results.from_json(old.encode()).rows[2]["value"] == 20.0


def test_from_json_keeps_skipped_and_optics():
    from rgbz_fast.simulation import Optics

    cfg = EvalConfig(patterns=("mask1",), methods=("bilinear",), metrics=("cpsnr",),
                     optics=Optics())
    res = Results([{"image": "a", "pattern": "mask1", "method": "bilinear", "metric": "cpsnr",
                    "value": INF}], cfg, skipped=[("b", "unreadable")])
    back = Results.from_json(res.to_json())
    assert back.config == cfg and back.skipped == [("b", "unreadable")]
    assert back.rows == res.rows


def test_from_json_refuses_other_text():
    with pytest.raises(ValueError, match="rows"):
        Results.from_json("[1, 2]")


def test_from_json_reads_a_run_with_given_filters(tmp_path):
    """to_json describes given filters (their repr), it does not store them: from_json had
    taken the description for a file name and failed; now the rows come back and the
    configuration without the filters, said in a warning."""
    import rgbz_fast as rz
    from rgbz_fast.reconstruction import default_filters

    default_filters(rz.mask1()).save(tmp_path / "f.npz")
    cfg = EvalConfig(patterns=("mask1",), methods=("bilinear", "learned"),
                     metrics=("cfa_psnr",), params={"filters": str(tmp_path / "f.npz")})
    rows = [{"image": "a", "pattern": "mask1", "method": m, "metric": "cfa_psnr", "value": v}
            for m, v in (("bilinear", 30.0), ("learned", 31.0))]
    text = Results(rows, cfg).to_json()
    with pytest.warns(UserWarning, match="filters are described, not stored"):
        back = Results.from_json(text)
    assert back.rows == rows and back.config.params.filters is None
    assert back.config.params.precision == "float64"


def test_a_mapping_of_params_keeps_the_evaluations_float64():
    assert EvalConfig(params=None).params.precision == "float64"
    assert EvalConfig(params={"sigma_rel": 0}).params.precision == "float64"
    assert EvalConfig(params={"sigma_rel": 0}).params.sigma_rel == 0


def test_one_image_shows_no_spread():
    """One image: the values without '± 0.00' (a spread of one value is not 0), the summary's
    std NaN, and 'image' in the singular."""
    res = Results([r for r in _results().rows if r["image"] == "rand"], CONFIG)
    assert all(math.isnan(std) and n == 1 for _, std, n in res.summary().values())
    md, text = res.summary_markdown(), res.plain_table()
    assert md.startswith("The values of 1 image (no spread to show);")
    assert "±" not in md.split("Paired")[0] and "±" not in text
    assert "(1 image;" in text


def test_the_repr_is_a_summary_not_every_row():
    """Probe round 24 (H-04): the dataclass's repr printed every row (3 MB for 500 images)."""
    from rgbz_fast.evaluation import EvalConfig, Results

    cfg = EvalConfig(patterns=("mask1", "mask2"), methods=("bi", "sg"), metrics=("cpsnr",))
    rows = [{"image": f"im{i:03d}", "pattern": p, "method": m, "metric": "cpsnr",
             "value": 30.0 + i % 7}
            for i in range(500) for p in cfg.patterns for m in cfg.methods]
    text = repr(Results(rows, cfg, skipped=[("bad", "unreadable")]))
    assert text == ("Results(2000 rows: 500 images x patterns ['mask1', 'mask2'] x methods "
                    "['bi', 'sg'] x metrics ['cpsnr'], 1 skipped)")


def _cell_rows(values):
    """Rows of one pattern and metric: values {method: [per image]}."""
    return [{"image": f"im{i}", "pattern": "mask2", "method": m, "metric": "cfa_psnr",
             "value": v} for m, vs in values.items() for i, v in enumerate(vs)]


def test_no_best_is_marked_where_the_means_cover_different_images():
    """Probe round 24 (J-02): SG exact on a ramp (+inf, left out of its mean) and best on the
    other image had its mean over one image, the others' over two (their 65-72 dB on the
    ramp): EDILine was marked best although worse on every image."""
    from rgbz_fast.evaluation import EvalConfig, Results

    cfg = EvalConfig(patterns=("mask2",), methods=("bilinear", "edi_line", "sg"),
                     metrics=("cfa_psnr",))
    res = Results(_cell_rows({"bilinear": [64.99, 29.38], "edi_line": [72.24, 33.24],
                              "sg": [math.inf, 33.32]}), cfg)
    md = res.summary_markdown()
    assert "**" not in md.split("Paired")[0].replace("**mask2**", "")
    assert "No best is marked for CFA PSNR (dB) where the means cover different images." in md
    # as many images each, but not the same ones: no best either (the first form of the rule
    # compared counts, and marked bilinear here)
    res2 = Results(_cell_rows({"bilinear": [25.0, math.inf], "edi_line": [24.0, math.inf],
                               "sg": [math.inf, 20.0]}), cfg)
    assert "**" not in res2.summary_markdown().split("Paired")[0].replace("**mask2**", "")
    # the same images everywhere: the best is marked
    res = Results(_cell_rows({"bilinear": [64.99, 29.38], "edi_line": [72.24, 33.24],
                              "sg": [73.0, 33.32]}), cfg)
    assert "| SG | **53.16 ± 28.06** |" in res.summary_markdown()


def test_the_json_summary_tells_a_perfect_cell_from_one_that_did_not_run():
    """Probe round 24 (J-03): a method exact on every image and one that does not apply both
    had {"mean": "nan", "n": 0} in evaluate --json, where the tables say inf and n/a."""
    from rgbz_fast.evaluation import EvalConfig, Results

    cfg = EvalConfig(patterns=("mask1", "mask2"), methods=("bilinear", "edi_rows"),
                     metrics=("cfa_psnr",))
    rows = [{"image": "flat", "pattern": p, "method": m, "metric": "cfa_psnr", "value": v}
            for p, m, v in (("mask1", "bilinear", math.inf), ("mask2", "bilinear", 40.0),
                            ("mask2", "edi_rows", math.inf))]
    d = Results(rows, cfg).summary_dict()
    assert d["mask2/edi_rows/cfa_psnr"] == {"mean": "inf", "std": "nan", "n": 0,
                                            "left_out": {"n": 1, "kinds": ["+inf"]}}
    assert d["mask1/edi_rows/cfa_psnr"] == {"mean": "nan", "std": "nan", "n": 0,
                                            "applies": False}
    assert d["mask2/bilinear/cfa_psnr"] == {"mean": 40.0, "std": "nan", "n": 1}
    json.dumps(d, allow_nan=False)


def test_pattern_objects_are_named_by_string_in_the_results(tmp_path):
    """Probe round 24 (I-01): EvalConfig took Pattern objects, the evaluation ran, and every
    table and report then failed with a bare TypeError (a Pattern in ', '.join)."""
    import imageio.v3 as iio

    import rgbz_fast as rz
    from rgbz_fast.evaluation import evaluate, write_reports

    cfg = EvalConfig(patterns=(rz.Pattern("ZRGR/BGBG/GRZR/BGBG", name="sparse"), rz.mask1()),
                     methods=("bilinear",), metrics=("cfa_psnr",))
    assert cfg.patterns == ("ZRGR/BGBG/GRZR/BGBG", "mask1")
    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "a.png", (np.random.default_rng(0).random((32, 32, 3)) * 255)
                .astype(np.uint8))
    res = evaluate(str(ds), cfg, progress=False)
    assert "ZRGR/BGBG/GRZR/BGBG" in res.plain_table()
    write_reports(res, tmp_path / "out", plots=False)
    # a Pattern whose Bayer phase its tile does not imply cannot be named by a string
    odd = rz.Pattern("GZ/ZG", bayer="GBRG")          # its tile alone reads as GRBG
    assert rz.get_pattern("GZ/ZG") != odd
    with pytest.raises(ValueError, match=r"^patterns: the Pattern 'GZ/ZG' with the Bayer "
                                         r"phase 'GBRG' is not the one its tile implies"):
        EvalConfig(patterns=(odd,), methods=("bilinear",), metrics=("cfa_psnr",))


def test_one_paired_image_has_no_interval_and_an_empty_paired_table_is_left_out():
    """Probe round 24 (TB-03, TB-06): a difference over one image printed the interval
    [d, d], which reads as exact; a pattern on which no method pairs with the baseline
    printed a table of no row."""
    cfg = EvalConfig(patterns=("mask1", "rows"), methods=("bilinear", "sg", "learned"),
                     metrics=("cfa_psnr",))
    rows = [{"image": i, "pattern": p, "method": m, "metric": "cfa_psnr", "value": v}
            for i, vals in (("a", (30.0, 31.71, 32.0)), ("flat", (math.inf,) * 3))
            for p in ("mask1", "rows") for m, v in zip(cfg.methods, vals)
            if cfg.applies(p, m)]
    md = Results(rows, cfg).summary_markdown()
    paired = md.split("Paired differences")[1]
    assert "| SG | +1.71 (1 image, no interval) |" in paired
    assert "[+1.71, +1.71]" not in paired
    # bilinear and learned alone: learned does not take rows, so nothing pairs there
    cfg2 = EvalConfig(patterns=("mask1", "rows"), methods=("bilinear", "learned"),
                      metrics=("cfa_psnr",))
    rows2 = [r for r in rows if r["method"] in cfg2.methods]
    paired2 = Results(rows2, cfg2).summary_markdown().split("Paired differences")[1]
    assert "**mask1**" in paired2 and "**rows**" not in paired2


def test_the_image_table_takes_the_summary_decimals():
    """Probe round 24 (TB-07): the per-image table's .4g mixed 35.6 with 38.78 in one row
    and printed a perfect SSIM as 1."""
    cfg = EvalConfig(patterns=("mask1",), methods=("bilinear", "sg"),
                     metrics=("cpsnr", "ssim"))
    rows = [{"image": "a", "pattern": "mask1", "method": m, "metric": k, "value": v}
            for m, k, v in (("bilinear", "cpsnr", 35.6), ("sg", "cpsnr", 38.78),
                            ("bilinear", "ssim", 1.0), ("sg", "ssim", 0.99681))]
    md = Results(rows, cfg).image_markdown("a")
    assert "| CPSNR (dB) | 35.60 | 38.78 |" in md and "| SSIM | 1.0000 | 0.9968 |" in md
