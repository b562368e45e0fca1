"""The depth measurements (rgbz_fast.evaluation.evaluate_depth): sections, their rows and
the report; the numbers of docs/reports/isp.md come from the same code."""

from __future__ import annotations

import numpy as np
import pytest

from _support import shared_path  # noqa: E402

from rgbz_fast.evaluation import DEPTH_SECTIONS, depth_report, evaluate_depth
from rgbz_fast.tof import ToFISP


def test_range_and_sunlight_sections_without_scene_data():
    res = evaluate_depth(None, sections=("range", "sunlight"))
    assert set(res) == {"range", "sunlight"}
    walls = [r for r in res["range"] if r["case"] == "wall"]
    assert len(walls) == 2 * 2 * 3 * 6
    # the default source: every beyond-range measurement flagged, at every distance
    for r in walls:
        if r["power_w"] == 0.5 or r["distance"] <= 9.0:
            assert r["flagged"] == r["n"], r
    # the 10x source, a bright wall far beyond the range: the documented limit
    limit = [r for r in walls if r["power_w"] == 5.0 and r["reflectance"] == 1.0
             and r["distance"] == 12.0 and r["pattern"] == "mask2"]
    assert limit[0]["flagged"] < limit[0]["n"]
    below = [r for r in res["range"] if r["case"] == "below"]
    assert below and all(r["read_near_flagged"] == r["read_near"] for r in below)
    sun = {(r["config"], r["distance"]): r["valid"] for r in res["sunlight"]}
    assert sun["continuous wave (default)", 1.0] == 0.0
    assert all(sun["burst 0.1 + suppression 0.9", d] > 0.97 for d in (0.3, 0.5, 1.0, 2.0))
    text = depth_report(res)
    assert "Beyond the unambiguous range" in text and "Sunlight" in text
    assert "| mask2 | 0.5 | 1 |" in text


def test_scenes_section_on_the_middlebury_scenes():
    data = shared_path("rgbd")
    res = evaluate_depth(data, sections=("scenes",), patterns=("mask2",))
    rows = res["scenes"]
    assert [r["scene"] for r in rows][-1] == "all" and len(rows) == 7
    total = rows[-1]
    assert total["wrong_valid"] <= 0.001 * total["known"]
    assert total["wrong"] - total["wrong_valid"] >= 0.95 * total["wrong"]
    assert "| all | mask2 |" in depth_report(res)
    # the paper's box denoise without the noise and flying-pixel tests lets mixtures at the
    # depth edges through as valid
    old = evaluate_depth(data, sections=("scenes",), patterns=("mask2",),
                         isp=ToFISP(denoise="box", max_sigma=None, flying_step=None))
    assert old["scenes"][-1]["wrong_valid"] > 0.02 * old["scenes"][-1]["known"]


def test_bad_arguments():
    with pytest.raises(ValueError, match="sections: unknown"):
        evaluate_depth(None, sections=("scenes", "speed"))
    with pytest.raises(TypeError, match="isp"):
        evaluate_depth(None, sections=("noise",), isp="box")
    with pytest.raises(FileNotFoundError, match="data"):
        evaluate_depth("/nonexistent/rgbd", sections=("scenes",))
    assert DEPTH_SECTIONS == ("scenes", "range", "noise", "sunlight", "calibration")
    assert evaluate_depth(None, sections="scenes") == {}          # no data: nothing to run
    assert np.isfinite(1.0)
