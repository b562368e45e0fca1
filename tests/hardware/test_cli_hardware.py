"""``rgbz-fast hardware``: the report, the sweep, and its refusals, on a small dataset."""

from __future__ import annotations

import json

import numpy as np
import pytest

from rgbz_fast._cli import main


@pytest.fixture(scope="module")
def dataset(tmp_path_factory):
    import imageio.v3 as iio

    d = tmp_path_factory.mktemp("images")
    rng = np.random.default_rng(2)
    yy, xx = np.mgrid[0:40, 0:56]
    iio.imwrite(d / "ramp.png", np.stack([xx * 4, yy * 6, (xx + yy) * 2], -1).astype(np.uint8))
    iio.imwrite(d / "noise.png", rng.integers(0, 256, (40, 56, 3), dtype=np.uint8))
    return d


def test_report_files_and_json(dataset, tmp_path, capsys):
    out = tmp_path / "hw"
    rc = main(["hardware", "--method", "edi_line", "--pattern", "mask2", "--width", "1920",
               "--dataset", str(dataset), "--out", str(out), "--json", "--quiet"])
    assert rc == 0
    rep = json.loads(capsys.readouterr().out)
    assert rep["pattern"] == "mask2" and rep["images"] == ["noise", "ramp"]
    assert rep["cost"]["line_buffers"] == {"count": 5, "width": 1920, "bits_per_pixel": 11,
                                           "bits": 5 * 1920 * 11, "bram18": 10}
    assert set(rep["error"]) == {"linear", "srgb"}
    assert rep["opcounts"]["table1"]["red/blue"] == {"add": 88, "mul": 20, "div": 24, "exp": 4}
    md = (out / "hardware.md").read_text()
    assert "| line buffers | 5 x 1920 x 11 bits" in md
    assert json.loads((out / "hardware.json").read_text())["method"] == "edi_line"


def test_sweep_writes_its_table_and_plot(dataset, tmp_path, capsys):
    out = tmp_path / "sw"
    rc = main(["hardware", "--method", "sg", "--pattern", "mask1", "--dataset", str(dataset),
               "--limit", "1", "--sweep", "--out", str(out), "--quiet",
               "--fixed-point", "weight_bits=12,exp=table"])
    assert rc == 0
    text = capsys.readouterr().out
    assert "## Sweep" in text and "| default |" in text and "every width -2" in text
    assert (out / "hardware_sweep.png").stat().st_size > 1000
    rows = json.loads((out / "hardware.json").read_text())["sweep"]
    assert rows[0]["config"]["weight_bits"] == 12 and any(r["pareto"] for r in rows)


@pytest.mark.parametrize("argv, message", [
    (["--fixed-point", "exp_table_size=0"], "--fixed-point: exp_table_size: expected a power "
                                            "of two"),
    (["--fixed-point", "exp_size=8"],
     "--fixed-point: fixed_point got an unexpected keyword argument 'exp_size'"),
    (["--pattern", "ZZZZ/ZZZZ"], "pattern"),
    (["--width", "20000"], "width: expected an integer >= 1 and <= 16384"),
])
def test_bad_input_exits_2_naming_it(argv, message, dataset, tmp_path, capsys):
    rc = main(["hardware", "--dataset", str(dataset), "--out", str(tmp_path / "x"), *argv])
    assert rc == 2
    err = capsys.readouterr().err
    assert err.startswith("rgbz-fast hardware: error:") and message in err
    assert not (tmp_path / "x").exists()


def test_a_flat_image_is_no_change_and_the_json_stays_strict(dataset, tmp_path, capsys):
    """A flat image reconstructs exactly in both models (CFA PSNR +inf twice): its change is 0
    dB, not inf - inf = NaN, which had made the table 'inf | inf | +nan', the verdict MISSES
    and hardware.json hold NaN and Infinity."""
    import shutil

    import imageio.v3 as iio

    d = tmp_path / "ds"
    d.mkdir()
    shutil.copy(dataset / "noise.png", d)
    iio.imwrite(d / "flat.png", np.full((40, 56, 3), (120, 60, 30), np.uint8))
    out = tmp_path / "hw"
    assert main(["hardware", "--dataset", str(d), "--width", "128", "--quiet",
                 "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "nan" not in text and "MISSES" not in text
    assert "leave out the images that both reconstruct exactly at every Z site" in text
    rep = json.loads((out / "hardware.json").read_text(),
                     parse_constant=lambda c: pytest.fail(f"not strict JSON: {c}"))
    for e in rep["error"].values():
        assert e["exact_images"] == 1 and np.isfinite(e["psnr_float"])
        assert abs(e["dpsnr_mean"]) <= 0.05
