"""The engine of ``rgbz-fast hardware`` (rgbz_fast._devtools.hardware): error against float64,
the report, the sweep and its Pareto front, on small images."""

from __future__ import annotations

import json

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast._devtools import hardware as H
from rgbz_fast._devtools.plots import hardware_sweep_plot
from rgbz_fast.hardware import FixedPointConfig


@pytest.fixture(scope="module")
def images():
    rng = np.random.default_rng(5)
    yy, xx = np.mgrid[0:48, 0:64]
    smooth = np.stack([(xx * 4) % 256, (yy * 5) % 256, ((xx + yy) * 2) % 256], -1)
    return [("smooth", smooth.astype(np.uint8)),
            ("noise", rng.integers(0, 256, (48, 64, 3), dtype=np.uint8))]


def test_measure_error_counts_every_z_site(images):
    cases = H.prepare_cases(images, "mask1", "sg")
    err = H.measure_error(cases, "sg", FixedPointConfig())
    assert set(err) == {"linear", "srgb"}
    for e in err.values():
        assert e["images"] == 2 and e["sites"] == 2 * 48 * 64 // 4
        assert sum(e["hist"].values()) == e["sites"]
        assert e["within_1lsb_pct"] == pytest.approx(
            100 * (e["hist"]["-1"] + e["hist"]["0"] + e["hist"]["1"]) / e["sites"])
    # the exact mean: bilinear is float64 bit for bit
    exact = H.measure_error(H.prepare_cases(images, "mask2", "bilinear"), "bilinear",
                            FixedPointConfig(exp_bits=2))
    assert all(e["hist"]["0"] == e["sites"] and e["dpsnr_mean"] == 0 for e in exact.values())


def test_narrow_widths_lose_quality(images):
    cases = H.prepare_cases(images, "mask2", "edi_line", ("linear",))
    good = H.measure_error(cases, "edi_line", FixedPointConfig())["linear"]
    poor = H.measure_error(cases, "edi_line", FixedPointConfig(weight_bits=3, recip_bits=3,
                                                               exp_bits=3))["linear"]
    assert good["within_1lsb_pct"] > poor["within_1lsb_pct"]
    assert H.meets_target({"linear": good}) and not H.meets_target({"linear": poor})


def test_report_and_its_markdown(images):
    rep = H.hardware_report("sg", "mask2", width=1920, images=images)
    assert rep["cost"]["line_buffers"]["count"] == 5 and rep["cost"]["width"] == 1920
    assert rep["opcounts"]["table1"]["green"] == {"add": 142, "mul": 61, "div": 39, "exp": 12}
    md = H.format_report(rep)
    for text in ("line buffers | 5 x 1920 x 11 bits", "BRAM_18K", "Table 1, green",
                 "float64, red/blue", "| linear | 2 |", "Note: the border rule"):
        assert text in md, text


def test_sweep_gives_a_front_and_a_plot(images, tmp_path):
    base = FixedPointConfig()
    configs = [("default", base), ("weight_bits=4", base.replace(weight_bits=4)),
               ("weight_bits=24", base.replace(weight_bits=24)),
               ("too wide", base.replace(register_bits=20))]
    rows = H.run_sweep("sg", "mask2", images=images[:1], configs=configs, bit_depth=11)
    by = {r["label"]: r for r in rows}
    assert "refused" not in by["default"] and "register_bits" in by["too wide"]["refused"]
    assert by["weight_bits=24"]["bits"]["datapath"] > by["default"]["bits"]["datapath"]
    front = {r["label"] for r in rows if r.get("pareto")}
    assert "weight_bits=4" in front or by["weight_bits=4"]["within_1lsb_pct"] <= min(
        r["within_1lsb_pct"] for r in rows if r["label"] in front)
    assert not ({"default", "weight_bits=24"} <= front and by["weight_bits=24"][
        "within_1lsb_pct"] == by["default"]["within_1lsb_pct"])
    png = hardware_sweep_plot(rows, "sg on mask2")
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 1000
    md = H.format_sweep(rows)
    assert md.count("\n") == len(rows) + 1 and "refused" in md


def test_threads_do_not_change_the_error_or_the_sweep(images):
    """The frames (measure_error) and the configurations (run_sweep) run side by side on
    threads: the same numbers, rows and front as one at a time, and one tick per
    configuration, a refused one included."""
    cases = H.prepare_cases(images, "mask2", "sg")
    assert (H.measure_error(cases, "sg", FixedPointConfig(), workers=2)
            == H.measure_error(cases, "sg", FixedPointConfig(), workers=1))
    base = FixedPointConfig()
    configs = [("default", base), ("exp_bits=6", base.replace(exp_bits=6)),
               ("recip_bits=8", base.replace(recip_bits=8)),
               ("too wide", base.replace(register_bits=20))]
    runs = {}
    for w in (1, 2):
        ticks = []
        runs[w] = H.run_sweep("sg", "mask2", images=images, configs=configs, workers=w,
                              tick=lambda: ticks.append(1))
        assert len(ticks) == len(configs)
    assert runs[1] == runs[2]
    assert [r["label"] for r in runs[2]] == [lab for lab, _ in configs]
    with pytest.raises(ValueError, match="workers"):
        H.measure_error(cases, "sg", base, workers=0)


def test_sweep_configurations_cover_every_field():
    labels = [lab for lab, _ in H.sweep_configs(FixedPointConfig())]
    for field in H.SWEEP:
        assert any(lab.startswith(field + "=") for lab in labels), field
    assert "every width -2" in labels and any(lab.startswith("exp=") for lab in labels)
    assert rz.FixedPointConfig is FixedPointConfig


@pytest.mark.parametrize("source", ["samples", "kodak"])
def test_the_default_meets_the_target_on_real_images(source):
    """The default configuration within 0.05 dB and 1 LSB at >= 99.9 % of the Z sites of
    float64, every method the model runs, both masks, both protocols: on centre crops of two
    images the search used (the scikit-image samples) and of two it did not (Kodak)."""
    from _support import load_kodak

    from rgbz_fast.hardware import FIXED_METHODS

    if source == "kodak":
        imgs = [(f"kodim{n:02d}", load_kodak(n, (192, 192))) for n in (5, 19)]
    else:
        imgs = [(n, img[:192, :192]) for n, img in H.load_images()[:2]]
    for pattern in ("mask1", "mask2"):
        for m in FIXED_METHODS:
            err = H.measure_error(H.prepare_cases(imgs, pattern, m), m, FixedPointConfig())
            assert H.meets_target(err), (pattern, m, err)


def test_learned_sweep_configurations_cover_its_fields():
    labels = [lab for lab, _ in H.sweep_configs(FixedPointConfig(), "learned")]
    for field in H.SWEEP_LEARNED:
        assert any(lab.startswith(field + "=") for lab in labels), field
    assert "every width -2" in labels and not any(lab.startswith("exp=") for lab in labels)


@pytest.mark.parametrize("source", ["samples", "kodak"])
def test_the_learned_default_meets_the_target_on_real_images(source):
    """The learned filters' default fields within the target of float64 on every Bayer phase
    of both masks, both protocols: centre crops of two images the search used and of two it
    did not (Kodak)."""
    from _support import load_kodak

    if source == "kodak":
        imgs = [(f"kodim{n:02d}", load_kodak(n, (192, 192))) for n in (5, 19)]
    else:
        imgs = [(n, img[:192, :192]) for n, img in H.load_images()[:2]]
    for pattern in ("mask1", "mask1_bggr", "mask2", "mask2_rggb", "mask2_gbrg"):
        err = H.measure_error(H.prepare_cases(imgs, pattern, "learned"), "learned",
                              FixedPointConfig())
        assert H.meets_target(err), (pattern, err)


def test_json_text_is_strict_inside_arrays():
    from rgbz_fast._devtools._common import json_text

    assert json.loads(json_text({"a": np.array([np.nan, 1.0]), "b": float("inf")})) == \
        {"a": [None, 1.0], "b": None}


def test_table1_is_found_on_every_bayer_phase_of_the_presets():
    """H86: the report looked Table 1 up by the pattern's own name, so mask1_rggb (or the
    tile ZR/BG) had no Table 1 row while opcount gave it one."""
    for p in ("mask1", "mask1_rggb", "ZR/BG", "mask1_gbrg"):
        assert H._float_opcounts(p, "sg")[1]["green"] == {"add": 72, "mul": 28, "div": 28,
                                                            "exp": 8}
    assert H._float_opcounts("mask2_bggr", "bi")[1]["red/blue"] == {"add": 128, "mul": 32,
                                                                     "div": 8, "exp": 0}



def test_the_report_tables_have_as_many_cells_as_their_header(images):
    """Probe round 24 (TB-01): the header cell 'max |diff|' split in two, so the float64
    against fixed-point table had 10 header cells over 8 separators and did not render."""
    import re

    md = H.format_report(H.hardware_report("sg", "mask1", width=1920, images=images[:1]))
    lines = md.splitlines()
    for k, line in enumerate(lines):
        if re.fullmatch(r"(\|---)+\|", line):              # a separator: its header above
            n = line.count("|")
            assert lines[k - 1].replace("\\|", "").count("|") == n, lines[k - 1]
            for row in lines[k + 1:]:
                if not row.startswith("|"):
                    break
                assert row.replace("\\|", "").count("|") == n, row
