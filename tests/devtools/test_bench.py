"""The benchmark and trade-off commands and engines run and produce well-formed output.

No timing is asserted (speed is measured in benchmarks,
never in timed tests); only the structure and the invariants of the reports.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from rgbz_fast._cli import main
from rgbz_fast._devtools import bench, timing, tradeoff
from rgbz_fast._devtools.plots import tradeoff_plot


def _finite_positive(x):
    return isinstance(x, float) and math.isfinite(x) and x > 0


REFERENCE = Path(__file__).resolve().parents[1] / "_reference" / "reconstruction.py"


def _bench_json(capsys, tmp_path, *extra):
    rc = main(["bench", "--json", "--quiet", "--repeat", "1", "--shape", "48x64",
                     "--kernels", "sg mask1,bilinear mask2 float32,demosaic,tof",
                     "--no-memory", "--out", str(tmp_path), "--numpy-reference",
                     str(REFERENCE), *extra])
    assert rc == 0
    return json.loads(capsys.readouterr().out)


def _check_speeds(res, tmp_path):
    assert set(res) >= {"machine", "frame", "results", "opencv", "memory", "targets", "repeat",
                        "warmup_calls", "quick", "verdict"}
    assert res["frame"]["shape"] == [48, 64] and res["warmup_calls"] == 1
    assert res["machine"]["logical_cores"] >= 1 and res["machine"]["cpu_model"]
    labels = {(r["kernel"], r["method"], r["pattern"], r["precision"], r["exp"])
              for r in res["results"]}
    assert ("reconstruct", "sg", "mask1", "float32", "auto") in labels     # the default
    assert ("reconstruct", "sg", "mask1", "float32", "libm") in labels
    assert ("reconstruct", "bilinear", "mask2", "float32", "auto") in labels
    assert any(k[0] == "demosaic" for k in labels)
    assert {k[0] for k in labels} >= {"tof_demodulate", "tof_unwrap"}
    for r in res["results"]:
        for label in ("1", "all"):
            t = r["threads"][label]
            assert t["n"] == 1 and _finite_positive(t["mpix_s"])
            assert t["mpix_s_lo"] <= t["mpix_s"] <= t["mpix_s_hi"]
        assert r["threads"]["1"]["threads"] == 1
        # a 48x64 frame is far below 2**18 pixels a thread: one thread for the pixel kernels
        if r["kernel"] in ("reconstruct", "demosaic"):
            assert r["threads"]["all"]["threads"] == 1
    tof = res["tof_sites"]
    assert tof["n_sites"] == 48 * 64 // 4 and tof["pattern"] == "mask1"
    for key in ("c_1", "c_all", "c_stages_all", "numpy"):
        assert _finite_positive(tof[key]["msites_s"]) and tof[key]["n"] == 1
    assert tof["agreement"]["wraps_equal"] and tof["agreement"]["max_abs_depth_diff_m"] < 1e-9
    assert res["memory"] is None and res["colour_chain"] is None and res["tof_isp"] is None
    assert json.loads((tmp_path / "bench.json").read_text())["frame"]["pixels"] == 48 * 64
    return tof


def test_bench_quick_is_a_smoke_test(capsys, tmp_path):
    """--quick: speeds only; no ratio and no verdict, and the report says why."""
    res = _bench_json(capsys, tmp_path, "--quick")
    tof = _check_speeds(res, tmp_path)
    assert res["quick"] and not res["verdict"]
    assert res["numpy_reference"]["available"]
    for r in res["results"]:
        assert r["vs_numpy"] is None
        assert all(r[f"vs_opencv_{k}_{t}"] is None for k in ("bilinear", "ea")
                   for t in ("1", "all"))
    assert res["targets"] == {}
    assert tof["x_numpy_1"] is None and tof["x_numpy_all"] is None and tof["target_met"] is None
    text = (tmp_path / "bench.txt").read_text()
    assert text.startswith("Quick run: numbers not comparable, no verdict")
    assert "1 warm-up call" in text and "Mpix/s" in text and "M measurements/s" in text
    for word in ("xNumPy ", "xCV", "met", "NOT met", "target:", "x NumPy:"):
        assert word not in text.replace("no xNumPy, xCV or target columns", "")


def test_bench_small_frame_gives_ratios_but_no_verdict(capsys, tmp_path):
    """A full run on a frame other than the target's 4000x3000: ratios, no verdict."""
    res = _bench_json(capsys, tmp_path)
    tof = _check_speeds(res, tmp_path)
    assert not res["quick"] and not res["verdict"]
    sg = next(r for r in res["results"] if r["method"] == "sg" and r["exp"] == "auto")
    assert _finite_positive(sg["vs_numpy"])        # the NumPy reference given on the line
    t = res["targets"]
    assert t["target_mpix_s"] == 150.0 and t["target_met"] is None
    assert _finite_positive(t["sg_mask1_float32_all_threads_mpix_s"])
    assert _finite_positive(tof["x_numpy_all"]) and tof["target_x_numpy"] == 5.0
    assert t["tof_target_met"] is None
    if res["opencv"] is not None:
        # the OpenCV ratios are paired (calls alternated round by round), and the target
        # line quotes the SG case's
        for r in res["results"]:
            assert all(_finite_positive(r[f"vs_opencv_{k}_{lab}"]) for k in ("bilinear", "ea")
                       for lab in ("1", "all"))
            # with the spread of the rounds' ratios around their median
            for k in ("bilinear", "ea"):
                for lab in ("1", "all"):
                    lo, hi = r[f"vs_opencv_{k}_{lab}_iqr"]
                    assert 0 < lo <= r[f"vs_opencv_{k}_{lab}"] <= hi
        m1 = next(r for r in res["results"] if r["method"] == "sg" and r["exp"] == "auto"
                  and r["pattern"] == "mask1" and r["precision"] == "float32")
        assert t["fraction_of_opencv_ea"] == m1["vs_opencv_ea_all"]
        assert t["fraction_of_opencv_ea_iqr"] == m1["vs_opencv_ea_all_iqr"]
        med, (lo, hi) = m1["vs_opencv_ea_all"], m1["vs_opencv_ea_all_iqr"]
        assert f"{med:.2f} [{lo:.2f}-{hi:.2f}]" in (tmp_path / "bench.txt").read_text()
    text = (tmp_path / "bench.txt").read_text()
    assert "no verdict: the target is defined on the 3000x4000 frame (--shape)" in text
    assert "xNumPy" in text and "Quick run" not in text
    assert " met" not in text.replace("NOT met", "")


def test_bench_colour_chain_section(capsys):
    assert main(["bench", "--quick", "--quiet", "--repeat", "1", "--shape", "48x64",
                 "--kernels", "demosaic malvar2004 bayer float32", "--no-memory",
                 "--no-reference", "--chain", "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    assert res["tof_sites"] is None                                    # --kernels left it out
    ch = res["colour_chain"]
    assert list(ch["stages_s"]) == list(__import__("rgbz_fast.isp").isp.STAGES)
    assert ch["reconstruction"] == "sg" and ch["demosaic"] == "malvar2004"
    assert 0 < sum(ch["stages_s"].values()) <= ch["total_s"] * 1.5 + 1e-3
    assert ch["fused_s"] > 0 and ch["identical"] is True
    text = bench.format_chain(ch)
    assert "defect_correction" in text and "gamma" in text and "fused (C passes)" in text
    sim = res["simulate"]
    assert set(sim["patterns"]) == {"mask1", "mask2"} and sim["frame_shape"] == [48, 64]
    for r in sim["patterns"].values():
        assert all(r[k]["median_s"] > 0 for k in ("noise_free", "noisy"))
    assert {t["met"] for t in sim["targets"].values()} == {None}      # not the target frame
    text = bench.format_simulate(sim)
    assert "noise-free" in text and "no verdict" in text
    t = res["tof_isp"]
    assert t["frame_shape"] == [48, 64] and t["n_sites"] == 48 * 64 // 4 and t["pattern"] == "mask1"
    assert t["guided"]["msites_s"] > 0 and t["unguided"]["msites_s"] > 0
    assert t["upsample"]["mpix_s"] > 0 and 0 < t["valid_share"] <= 1
    assert set(t["targets"]) == {"guided", "upsample"}
    assert {g["met"] for g in t["targets"].values()} == {None}         # not the target frame
    text = bench.format_tof_isp(t)
    assert "ToFISP().run(tof, guide=image)" in text and "upsample_depth" in text
    assert "target guided >= 20 M measurements/s" in text and "no verdict" in text


def test_measure_memory_tiny_frame(tmp_path, monkeypatch):
    import rgbz_fast as rz

    # another rgbz_fast in the current folder (a checkout's src/): the child had imported
    # it (`python -c` puts the folder first) instead of the package measured (round 25, PKG05)
    (tmp_path / "rgbz_fast").mkdir()
    (tmp_path / "rgbz_fast" / "__init__.py").write_text("raise ImportError('the wrong one')")
    monkeypatch.chdir(tmp_path)
    frame = rz.mosaic(np.zeros((48, 64, 3), np.uint8), rz.mask1())
    mem = bench.measure_memory(frame.data, "mask1", "sg", "float32", 1)
    if mem is None:
        pytest.skip("no /proc on this platform")
    assert "error" not in mem, mem
    for kind in ("array", "rawframe"):
        m = mem[kind]
        assert m["in_bytes"] == m["out_bytes"] == 48 * 64 * 2
        assert m["rss_growth"] >= 0 and m["traced_peak"] >= m["out_bytes"]
        assert isinstance(m["within_budget"], bool)


def test_bench_table_and_opencv_optional(capsys, monkeypatch, tmp_path):
    monkeypatch.setitem(__import__("sys").modules, "cv2", None)     # import cv2 -> ImportError
    monkeypatch.chdir(tmp_path)      # no reference is looked for in the current directory
    assert main(["bench", "--quiet", "--repeat", "1", "--shape", "48x64",
                 "--kernels", "bilinear mask1 float64", "--no-memory"]) == 0
    out = capsys.readouterr().out
    assert "reconstruct bilinear" in out and "n/a" in out
    assert "cv2 not installed" in out and "without --numpy-reference FILE" in out


def test_bench_numpy_reference_must_be_a_reference(capsys, tmp_path):
    (tmp_path / "other.py").write_text("x = 1\n")
    for path, msg in ((tmp_path / "missing.py", "is not a file"),
                      (tmp_path / "other.py", "defines no reference_reconstruct")):
        assert main(["bench", "--quick", "--quiet", "--no-memory", "--numpy-reference",
                     str(path)]) == 2
        err = capsys.readouterr().err
        assert "--numpy-reference" in err and msg in err and err.count("\n") == 1


@pytest.mark.parametrize("args,msg", [
    (["--shape", "48x63"], "--shape: rows must be a multiple of 12"),
    (["--shape", "64x48"], "--shape: rows must be a multiple of 12"),
    (["--kernels", "nothing-matches"], "--kernels: no case matches"),
    # G3 (2026-11-27): an entry matching nothing beside one that does had been dropped
    (["--kernels", "sg mask1 float64,edi_centrl"], "--kernels: no case matches 'edi_centrl'"),
])
def test_bench_bad_input(capsys, args, msg):
    assert main(["bench", "--quick", "--quiet", "--no-memory", "--no-reference"] + args) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"rgbz-fast bench: error: {msg}") and err.count("\n") == 1


@pytest.mark.parametrize("command", ["bench", "tradeoff"])
@pytest.mark.parametrize("args,msg", [
    (["--repeat", "0"], "argument --repeat: expected an integer in [1, 1000], got '0'"),
    (["--workers", "0"], "argument --workers: expected a positive integer, got '0'"),
    (["--shape", "48*64"], "argument --shape: expected ROWSxCOLS"),
    (["--nope"], "unrecognized arguments: --nope"),
])
def test_measuring_commands_parse_as_every_command(capsys, command, args, msg):
    """bench and tradeoff take their options through the one parser: the same usage errors,
    under the command's name, as every other command."""
    if command == "tradeoff" and args[0] == "--shape":
        args, msg = ["--limit", "0"], "argument --limit: expected a positive integer, got '0'"
    with pytest.raises(SystemExit) as e:
        main([command, "--quick"] + args)
    assert e.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[0].startswith(f"usage: rgbz-fast {command}")
    assert err[-1].startswith(f"rgbz-fast {command}: error: {msg}")


def test_timing_alternates_the_functions_after_the_warm_up():
    calls = []
    times = timing.interleaved({"a": lambda: calls.append("a"), "b": lambda: calls.append("b")},
                               3, warmup=2)
    assert calls == ["a", "a", "b", "b"] + ["a", "b"] * 3
    assert set(times) == {"a", "b"} and all(t.shape == (3,) and (t >= 0).all()
                                            for t in times.values())
    st = timing.rate_stats(np.array([1.0, 2.0, 4.0]), 2e6)
    assert st["mpix_s"] == 1.0 and st["mpix_s_best"] == 2.0 and st["n"] == 3
    assert st["mpix_s_lo"] <= st["mpix_s"] <= st["mpix_s_hi"]
    assert timing.rate_stats([2.0], 4e6, "msites")["msites_s"] == 2.0


class _Image:
    """An in-memory dataset entry (name + load())."""

    def __init__(self, name, img):
        self.name, self.img = name, img

    def load(self):
        return self.img


def test_tradeoff_one_tiny_image(capsys, tmp_path):
    img = np.random.default_rng(0).integers(0, 256, (48, 64, 3), dtype=np.uint8)
    res = tradeoff.run_tradeoff([_Image("noise", img)], methods=("bilinear", "sg", "learned"),
                                speed_shape=(48, 64), repeat=1)
    rows = res["rows"]
    # bilinear: libm only (no exponential); sg: 2 precisions x 2 exps, and the
    # colour-difference domain in float64/libm and float32/fast; learned: 2 precisions, no
    # exponential; x 2 masks
    assert len(rows) == 2 * (2 + 4 + 2 + 2)
    assert sum(r["domain"] == "colour_difference" for r in rows) == 2 * 2
    assert {r["exp"] for r in rows if r["method"] == "learned"} == {"-"}
    for r in rows:
        assert _finite_positive(r["mpix_s"]) and math.isfinite(r["cfa_psnr"])
        base = r["precision"] == "float64" and r["exp"] in ("libm", "-")
        assert (r["max_abs_diff_dn"] is None) == base
        assert r["frac_diff"] is None or 0 <= r["frac_diff"] <= 1
    for p in ("mask1", "mask2"):
        assert any(r["pareto"] for r in rows if r["pattern"] == p)
    assert tradeoff_plot(res)[:8] == b"\x89PNG\r\n\x1a\n"
    md = tradeoff.format_markdown(res, "t.png")
    assert md.startswith("# Speed/accuracy") and "| sg |" in md.replace("**", "")
    assert "Accuracy: noise-free 11-bit mosaics of 1 linearised image (" in md
    assert not res["ir_estimated"] and "leaks" not in md


def test_tradeoff_says_how_z_guided_frames_were_made():
    """With z_guided every frame comes from the sensor model (the other rows move), and its
    NIR estimated from the RGB leaks the answer: the report had said neither."""
    img = np.random.default_rng(0).integers(0, 256, (48, 64, 3), dtype=np.uint8)
    res = tradeoff.run_tradeoff([_Image("noise", img)], methods=("bilinear", "z_guided"),
                                patterns=("mask1",), speed_shape=(48, 64), repeat=1)
    assert res["sensor_model"] and res["ir_estimated"] == ["noise"]
    for text in (tradeoff.format_markdown(res), tradeoff.format_text(res)):
        assert "z_guided: the NIR was estimated from the RGB on 1 of 1 image (noise)" in text
    assert "frames of the sensor model (with ToF taps" in tradeoff.format_markdown(res)


def test_tradeoff_cli(capsys, tmp_path):
    assert main(["tradeoff", "--quick", "--quiet", "--limit", "1", "--methods", "bi",
                 "--patterns", "mask1", "--repeat", "1", "--out", str(tmp_path), "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    assert [(r["method"], r["domain"]) for r in res["rows"]] == [
        ("bi", "intensity"), ("bi", "intensity"), ("bi", "colour_difference"),
        ("bi", "colour_difference")]
    assert {p.name for p in tmp_path.iterdir()} == {"tradeoff.md", "tradeoff.png",
                                                    "tradeoff.json"}
    assert res["command"].startswith("rgbz-fast tradeoff --quick")
    assert main(["tradeoff", "--quick", "--quiet", "--methods", "nope"]) == 2
    assert main(["tradeoff", "--quick", "--quiet", "--dataset", str(tmp_path / "none")]) == 2
    err = capsys.readouterr().err.splitlines()
    assert err[-2].startswith("rgbz-fast tradeoff: error: --methods: unknown nope")
    assert err[-1].startswith("rgbz-fast tradeoff: error: --dataset: ")


def test_pareto_front():
    pts = [(1, 1), (2, 0.5), (0.5, 2), (0.9, 0.9), (2, 0.4)]
    assert tradeoff.pareto_front(pts) == [0, 1, 2]
    # equal quality within the tolerance: only the fastest stays
    assert tradeoff.pareto_front([(1, 30.0), (2, 30.0 - 1e-6)]) == [1]


def test_tradeoff_findings_name_the_variant_of_each_figure():
    """H86: the share of differing Z pixels is one variant's and the largest difference
    maybe another's; the sentence named the second after the first."""
    def row(method, precision, exp, frac, dn, psnr=30.0, speed=100.0):
        return {"pattern": "mask1", "method": method, "domain": "intensity",
                "precision": precision, "exp": exp, "frac_diff": frac,
                "max_abs_diff_dn": dn, "cfa_psnr": psnr, "mpix_s": speed}
    rows = [row("bi", "float64", "libm", 0, 0), row("sg", "float64", "libm", 0, 0),
            row("bi", "float32", "libm", 0.0001, 2), row("sg", "float32", "libm", 0.0017, 1)]
    text = tradeoff._findings({"rows": rows})[0]
    assert "0.17 % of the Z pixels of one variant differ (sg mask1), by at most 2 DN " \
           "(bi mask1)" in text, text
    # G4 (2026-11-27): the colour-difference row named as its intensity row
    cd = [dict(r, domain="colour_difference") for r in rows[:1] + rows[2:3]]
    cd[1].update(frac_diff=0.003, max_abs_diff_dn=1)
    text = tradeoff._findings({"rows": rows + cd})[0]
    assert "0.3 % of the Z pixels of one variant differ (bi cd mask1), by at most 2 DN " \
           "(bi mask1)" in text, text


def test_tradeoff_leaves_an_exactly_reconstructed_image_out_of_every_mean():
    """Probe round 24 (J-01): a flat image (every method exact: CFA PSNR +inf) beside a
    textured one had made every mean +inf, the findings' differences NaN and the plot
    refuse its log axis. The means are over the images every variant of the pattern gives a
    finite PSNR, and the outputs name the ones left out."""
    rng = np.random.default_rng(0)
    tex = rng.integers(0, 256, (48, 64, 3), dtype=np.uint8)
    flat = np.empty((48, 64, 3), np.uint8)
    flat[...] = (120, 140, 90)
    res = tradeoff.run_tradeoff([_Image("flat", flat), _Image("tex", tex)],
                                methods=("bilinear", "sg"), patterns=("mask1",),
                                speed_shape=(48, 64), repeat=1)
    assert res["left_out"] == {"mask1": {"cfa_psnr": ["flat"], "cpsnr": ["flat"]}}
    for r in res["rows"]:
        assert math.isinf(r["cfa_psnr_per_image"][0])
        assert r["cfa_psnr"] == r["cfa_psnr_per_image"][1]
        assert r["cpsnr"] == r["cpsnr_per_image"][1]
    note = "CFA PSNR on mask1 leaves out flat; CPSNR on mask1 leaves out flat."
    for text in (tradeoff.format_markdown(res), tradeoff.format_text(res)):
        assert note in text and "nan" not in text
    assert tradeoff_plot(res)[:8] == b"\x89PNG\r\n\x1a\n"
    # only a flat image: every variant exact (inf, never NaN), the fastest alone on the front
    # (a NaN had put every row on it, in bold); the plot's panel and the findings say so
    alone = tradeoff.run_tradeoff([_Image("flat", flat)], methods=("bilinear", "sg"),
                                  patterns=("mask1",), speed_shape=(48, 64), repeat=1)
    rows = alone["rows"]
    assert all(r["cfa_psnr"] == math.inf for r in rows)
    assert [r["pareto"] for r in rows].count(True) == 1
    assert max(rows, key=lambda r: r["mpix_s"])["pareto"]
    assert "no image with a finite CFA PSNR for every variant" in tradeoff.format_text(alone)
    assert "| inf | inf |" in tradeoff.format_markdown(alone)
    assert tradeoff_plot(alone)[:8] == b"\x89PNG\r\n\x1a\n"
