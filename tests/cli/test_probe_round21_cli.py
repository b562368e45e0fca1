"""Probe round 21 (B): evaluate's reports.txt of a user's, options evaluate had ignored,
depth and hardware reruns that left a previous run's files without a word, ``simulate .``
and the lens options' errors. Small images written here; each test takes seconds."""

from __future__ import annotations

import numpy as np
import pytest

from rgbz_fast import io as frameio
from rgbz_fast._cli import main
from _support import rgbd_folder  # noqa: E402


def _image(path, shape=(64, 64), seed=0):
    """A small textured colour image (smooth, so that every method has edges to follow)."""
    import imageio.v3 as iio

    path.parent.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(seed)
    yy, xx = np.mgrid[:shape[0], :shape[1]]
    base = np.stack([np.sin(xx / 5.0 + k) * np.cos(yy / 7.0 - k) for k in range(3)], -1)
    img = np.clip(128 + 90 * base + rng.normal(0, 4, base.shape), 0, 255).astype(np.uint8)
    iio.imwrite(path, img)
    return path


def _evaluate(ds, out, *extra):
    return ["evaluate", "--dataset", str(ds), "--patterns", "mask1", "--methods", "bilinear",
            "--metrics", "cfa_psnr", "--no-plots", "--quiet", "--out", str(out), *extra]


# --------------------------------------------------------------------------- B1
def test_evaluate_refuses_a_foreign_reports_txt_and_removes_only_its_own_reports(tmp_path,
                                                                                 capsys):
    """A reports.txt the user wrote is no manifest: evaluate refuses the folder before it runs,
    naming --out, and deletes nothing (it had deleted every file the lines named). A manifest
    of rgbz-fast's own removes only the reports evaluate names, plain files in the folder."""
    from rgbz_fast.evaluation import write_reports
    from rgbz_fast.evaluation._reports import MANIFEST_HEAD

    ds = tmp_path / "ds"
    _image(ds / "a.png")
    mine = tmp_path / "myproject"
    mine.mkdir()
    (mine / "thesis.tex").write_text("my thesis")
    (mine / "measurements.csv").write_text("data")
    listing = "Weekly reports\nthesis.tex\nmeasurements.csv\n"
    (mine / "reports.txt").write_text(listing)
    assert main(_evaluate(ds, mine)) == 2
    err = capsys.readouterr().err
    assert "--out: " in err and "reports.txt exists and was not written by rgbz-fast" in err
    assert sorted(p.name for p in mine.iterdir()) == ["measurements.csv", "reports.txt",
                                                      "thesis.tex"]
    assert (mine / "reports.txt").read_text() == listing
    # the library refuses it as well, naming its parameter, and writes nothing
    from rgbz_fast.evaluation import evaluate

    res = evaluate(str(ds), patterns=("mask1",), methods=("bilinear",),
                   metrics=("cfa_psnr",), progress=False)
    with pytest.raises(ValueError, match=r"^out_dir: .*reports\.txt exists and was not "
                                         r"written by rgbz-fast"):
        write_reports(res, mine, plots=False)
    assert sorted(p.name for p in mine.iterdir()) == ["measurements.csv", "reports.txt",
                                                      "thesis.tex"]
    # a manifest of rgbz-fast's: a report it names goes; a name evaluate never gives a report,
    # a path out of the folder and a link stay
    out = tmp_path / "out"
    out.mkdir()
    (tmp_path / "outside.png").write_text("keep")
    for name in ("thesis.tex", "bars_cfa_psnr.png", "paired_ssim.png", "target.png"):
        (out / name).write_text("x")
    (out / "crops_link.png").symlink_to(out / "target.png")
    (out / "reports.txt").write_text(MANIFEST_HEAD + "thesis.tex\n../outside.png\n"
                                     "bars_cfa_psnr.png\npaired_ssim.png\ncrops_link.png\n"
                                     f"{tmp_path / 'outside.png'}\n")
    assert main(_evaluate(ds, out)) == 0
    left = {p.name for p in out.iterdir()}
    assert {"thesis.tex", "crops_link.png", "target.png"} <= left
    assert not {"bars_cfa_psnr.png", "paired_ssim.png"} & left
    assert (tmp_path / "outside.png").read_text() == "keep"
    assert (out / "reports.txt").read_text().startswith(MANIFEST_HEAD)
    capsys.readouterr()


# --------------------------------------------------------------------------- B6
def test_reruns_name_the_files_an_earlier_run_left(tmp_path, capsys):
    """depth without --full-resolution after a run with it, and hardware without --sweep after
    one with it, say which files of the earlier run the folder still holds (kept: nothing is
    deleted); --quiet says nothing."""
    scene = rgbd_folder(tmp_path / "sc")
    assert main(["simulate", str(scene), "--pattern", "mask2", "--quiet", "--out",
                 str(tmp_path / "f")]) == 0
    frame = tmp_path / "f" / "sc_mask2.npz"
    d = tmp_path / "d"
    assert main(["depth", str(frame), "--full-resolution", "--quiet", "--out", str(d)]) == 0
    assert capsys.readouterr().err == ""
    assert main(["depth", str(frame), "--max-range", "1.5", "--out", str(d)]) == 0
    err = capsys.readouterr().err
    assert err == (f"rgbz-fast depth: {d} holds sc_mask2_depth-full.tif, sc_mask2_depth-full.png, "
                   "sc_mask2_depth-full-confidence.tif from an earlier run; this run did not "
                   "write them\n")
    assert (d / "sc_mask2_depth-full.tif").is_file()
    assert main(["depth", str(frame), "--quiet", "--out", str(d)]) == 0
    assert capsys.readouterr().err == ""
    # hardware: the sweep's plot of a run with --sweep
    ds = tmp_path / "ds"
    _image(ds / "a.png", (48, 64))
    hw = ["hardware", "--method", "bi", "--dataset", str(ds), "--width", "64", "--out",
          str(tmp_path / "h")]
    assert main(hw + ["--sweep", "--quiet"]) == 0
    capsys.readouterr()
    assert main(hw) == 0
    assert capsys.readouterr().err == (f"rgbz-fast hardware: {tmp_path / 'h'} holds "
                                       "hardware_sweep.png from an earlier run; this run did "
                                       "not write it\n")
    assert (tmp_path / "h" / "hardware_sweep.png").is_file()


# --------------------------------------------------------------------------- B7
def test_evaluate_refuses_options_it_would_ignore(tmp_path, capsys):
    """--cache with --no-cache (as pattern-study refuses it), and --processes with
    --scheduler (the scheduler's branch dropped --processes): refused before anything runs;
    the library's evaluate() refuses processes with scheduler."""
    ds = tmp_path / "ds"
    _image(ds / "a.png")
    out = tmp_path / "ev"
    assert main(_evaluate(ds, out, "--no-cache", "--cache", str(tmp_path / "c"))) == 2
    assert capsys.readouterr().err == ("rgbz-fast evaluate: error: --cache: names the cache "
                                       "that --no-cache turns off; give one of them\n")
    assert main(_evaluate(ds, out, "--processes", "2", "--scheduler",
                          "tcp://127.0.0.1:8786")) == 2
    err = capsys.readouterr().err
    assert "error: --processes: " in err and "--scheduler" in err
    assert not out.exists() and not (tmp_path / "c").exists()
    from rgbz_fast.evaluation import evaluate

    with pytest.raises(ValueError, match=r"^processes: .*scheduler"):
        evaluate(str(ds), processes=2, scheduler="tcp://127.0.0.1:8786",
                 progress=False)


# --------------------------------------------------------------------------- B8
def test_evaluate_refuses_zoom_without_an_image_metric(tmp_path, capsys):
    """--zoom places the crop figure, which only the image metrics make: with --metrics
    cfa_psnr it had been accepted and ignored, even outside the image."""
    ds = tmp_path / "ds"
    _image(ds / "a.png")
    out = tmp_path / "ev"
    argv = ["evaluate", "--dataset", str(ds), "--patterns", "mask1", "--methods", "bilinear",
            "--metrics", "cfa_psnr", "--zoom", "100000,100000", "--quiet", "--out", str(out)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("rgbz-fast evaluate: error: --zoom: places the crop figure")
    assert "--metrics cfa_psnr" in err
    assert not out.exists()


# --------------------------------------------------------------------------- B9
def test_simulate_of_the_current_folder_names_it(tmp_path, capsys, monkeypatch):
    """``simulate .`` in a scene folder: the frame is <folder>_mask1.npz and its meta's scene
    is the folder's name (both had been empty: '_mask1.npz', scene '')."""
    scene = rgbd_folder(tmp_path / "aloe")
    monkeypatch.chdir(scene)
    assert main(["simulate", ".", "--quiet", "--out", str(tmp_path / "f")]) == 0
    assert [p.name for p in (tmp_path / "f").iterdir()] == ["aloe_mask1.npz"]
    assert frameio.load_frame(tmp_path / "f" / "aloe_mask1.npz").meta["scene"] == "aloe"
    from rgbz_fast.simulation import load_scene

    assert load_scene(".").name == "aloe"
    (scene / "sub").mkdir()
    assert load_scene(scene / "sub" / "..").name == "aloe"
    capsys.readouterr()


# --------------------------------------------------------------------------- B10
@pytest.mark.parametrize("option", [("--f-number", "0.1"), ("--olpf", "5"),
                                    ("--defocus-um", "1e9")])
def test_evaluate_lens_errors_name_the_flag(tmp_path, capsys, option):
    """An --optics value out of the lens model's range is named by its flag, as the guide
    promises (the message had named Optics.f_number)."""
    ds = tmp_path / "ds"
    _image(ds / "a.png")
    assert main(_evaluate(ds, tmp_path / "ev", "--optics", *option)) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"rgbz-fast evaluate: error: {option[0]}: expected")
    assert "Optics." not in err


# --------------------------------------------------------------------------- E1, E5
def test_depth_takes_min_snr_0_and_max_reflectance_off(tmp_path, capsys, monkeypatch):
    """``depth --min-snr 0`` turns the SNR test off, as the API's min_snr=0 does (it had been
    refused: 'expected a positive number'); ``--max-reflectance off`` keeps the measurements
    the implied-reflectance bound flags (retroreflectors), a number below 1 is refused."""
    scene = rgbd_folder(tmp_path / "aloe")
    assert main(["simulate", str(scene), "--pattern", "mask2", "--quiet",
                 "--out", str(tmp_path / "f")]) == 0
    frame = tmp_path / "f" / "aloe_mask2.npz"
    import rgbz_fast.tof as tof

    seen = []
    real = tof.tof_depth

    def spy(*a, **kw):
        seen.append({k: kw.get(k) for k in ("min_snr", "max_reflectance")})
        return real(*a, **kw)

    monkeypatch.setattr(tof, "tof_depth", spy)
    assert main(["depth", str(frame), "--min-snr", "0", "--max-reflectance", "off", "--quiet",
                 "--out", str(tmp_path / "d")]) == 0
    assert main(["depth", str(frame), "--quiet", "--out", str(tmp_path / "d1")]) == 0
    assert main(["depth", str(frame), "--max-reflectance", "2.5", "--quiet",
                 "--out", str(tmp_path / "d3")]) == 0
    assert seen == [{"min_snr": 0.0, "max_reflectance": None},
                    {"min_snr": 4.0, "max_reflectance": 4.0},
                    {"min_snr": 4.0, "max_reflectance": 2.5}]
    with pytest.raises(SystemExit) as exc:
        main(["depth", str(frame), "--max-reflectance", "0.5", "--quiet",
              "--out", str(tmp_path / "d2")])
    assert exc.value.code == 2 and "--max-reflectance" in capsys.readouterr().err


def test_a_report_named_after_an_image_of_dots_is_removed_by_the_next_run(tmp_path):
    """An image named ``..`` (an ImageSource's name is the caller's) gives ``table_...md``,
    a plain file name of the folder; the manifest lists it, and a later run that writes
    another table removes it (its field of dots had been taken for a path and the file left
    behind)."""
    from rgbz_fast.evaluation import evaluate, write_reports
    from rgbz_fast.evaluation._reports import _report_name
    from rgbz_fast.io import ImageSource

    assert _report_name("table_...md") and _report_name("crops_..png")
    assert not _report_name("../table_a.md") and not _report_name("table_a/b.md")
    path = _image(tmp_path / "ds" / "a.png")
    out = tmp_path / "out"

    def run(name):
        res = evaluate([ImageSource(name, str(path))], patterns=("mask1",),
                       methods=("bilinear",), metrics=("cfa_psnr",), progress=False)
        write_reports(res, out, plots=False)

    run("..")
    assert (out / "table_...md").is_file()
    assert "table_...md" in (out / "reports.txt").read_text().splitlines()
    run("b")
    left = {p.name for p in out.iterdir()}
    assert "table_b.md" in left and "table_...md" not in left
