"""Probe round 21 (B5): ``evaluate-depth --json`` printed ``NaN`` (not JSON) in the scenes
section's totals, whose RMSE and median were never computed. Small RGB-D scenes written
here; the test takes a second."""

from __future__ import annotations

import json
from types import SimpleNamespace

import numpy as np

from rgbz_fast._cli import main
from rgbz_fast.evaluation import _depth
from _support import rgbd_folder  # noqa: E402


def _strict(text):
    def refuse(constant):
        raise ValueError(f"not JSON: {constant}")
    return json.loads(text, parse_constant=refuse)


def test_evaluate_depth_json_is_strict_and_totals_pool_the_valid_measurements(
        tmp_path, monkeypatch, capsys):
    """Two scenes, one without a single valid measurement (its ISP results replaced by
    all-invalid ones): its own RMSE and median are null, not NaN, and the totals are the
    numbers over the valid measurements of the other scene, not NaN."""
    rgbd_folder(tmp_path / "data" / "a", seed=3)
    rgbd_folder(tmp_path / "data" / "b", seed=5)
    real = _depth.scene_runs

    def runs(*args, **kwargs):
        for run in real(*args, **kwargs):
            if run["scene"] == "b":            # nothing valid in this scene
                for key in ("plain", "guided"):
                    res = run[key]
                    run[key] = SimpleNamespace(depth=res.depth, flags=res.flags,
                                               valid=np.zeros_like(res.valid))
            yield run

    monkeypatch.setattr(_depth, "scene_runs", runs)
    rc = main(["evaluate-depth", "--data", str(tmp_path / "data"), "--sections", "scenes",
               "--patterns", "mask2", "--json"])
    out = capsys.readouterr().out
    assert rc == 0
    rows = _strict(out)["scenes"]                 # no NaN, Infinity: strict JSON
    assert "NaN" not in out
    by = {(r["scene"], r["guide"]): r for r in rows}
    for guide in ("none", "colour"):
        a, b, total = by["a", guide], by["b", guide], by["all", guide]
        assert b["valid"] == 0 and b["rmse_valid"] is None and b["median_valid"] is None
        assert a["valid"] > 0 and total["valid"] == a["valid"]
        assert total["rmse_valid"] is not None and total["median_valid"] is not None
        assert np.isclose(total["rmse_valid"], a["rmse_valid"], rtol=1e-12)
        assert np.isclose(total["median_valid"], a["median_valid"], rtol=1e-12)
