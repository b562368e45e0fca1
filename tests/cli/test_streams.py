"""What the command line prints, as a user's shell meets it: a reader that closes the pipe
early (``| head``) does not cut a batch short, and a library warning is one line."""

from __future__ import annotations

import subprocess
import sys
import warnings

import numpy as np
import pytest

from rgbz_fast import ToFSensor
from rgbz_fast._cli import main
from rgbz_fast.io import save_frame
from rgbz_fast.simulation import Scene, simulate


def _frame_file(path, seed):
    rng = np.random.default_rng(seed)
    scene = Scene(rng.random((32, 32, 3)), depth=np.full((32, 32), 1.5))
    return save_frame(path, simulate(scene, "mask1", tof_sensor=ToFSensor(), seed=seed))


def _raw_folder(tmp_path):
    """tmp_path/raw holding the shared colour chart DNG as chart.dng (skips without rawpy or
    the data)."""
    import shutil

    pytest.importorskip("rawpy")
    from _support import shared_path

    dng = shared_path("raw", "colorchart.dng")          # skips when the data is absent
    (tmp_path / "raw").mkdir()
    shutil.copy(dng, tmp_path / "raw" / "chart.dng")
    return tmp_path / "raw"


def test_a_reader_closing_the_pipe_early_does_not_cut_a_batch_short(tmp_path):
    """`rgbz-fast depth a.npz b.npz --out D | head -0` wrote a's files, never b's, and ended
    with 'error: [Errno 32] Broken pipe'."""
    frames = [_frame_file(tmp_path / f"{n}.npz", i) for i, n in enumerate("ab")]
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "rgbz_fast", "depth", *map(str, frames),
                             "--out", str(out)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    proc.stdout.close()                                  # the reader is gone at once
    with proc.stderr:
        err = proc.stderr.read().decode()
    assert proc.wait(timeout=120) == 0, err
    assert "Broken pipe" not in err and "Traceback" not in err
    assert sorted(p.name for p in out.iterdir()) == sorted(
        f"{n}_depth{k}" for n in "ab" for k in (".tif", ".png", "-flags.tif", "-flags.png"))


def test_a_library_warning_is_one_line_naming_the_command(monkeypatch, capsys):
    """Python printed the warning's source file and line (the library's code) on two lines
    before the command's own error."""
    from rgbz_fast._cli import config

    def run(args):
        warnings.warn("something the user should know\n  over two lines", UserWarning)
        return 0

    monkeypatch.setattr(config, "run", run)
    with warnings.catch_warnings():
        warnings.simplefilter("always")
        assert main(["config"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == ["rgbz-fast config: warning: something the user should know over two lines"]
    assert warnings.showwarning is not None                # restored after the command


def test_reconstruct_takes_z_guided_filters_files(tmp_path, capsys):
    """`--filters` read learned files only: a z_guided file (the shipped one, or one of
    `train --z-guided`) was 'not a rgbz-fast filters file'."""
    from pathlib import Path

    import rgbz_fast as rz

    frame = _frame_file(tmp_path / "a.npz", 3)
    shipped = Path(rz.__file__).parent / "reconstruction" / "data" / "z_guided_mask1_11bit.npz"
    out = tmp_path / "out"
    assert main(["reconstruct", str(frame), "--method", "z_guided", "--filters", str(shipped),
                 "--out", str(out)]) == 0, capsys.readouterr().err
    assert main(["reconstruct", str(frame), "--method", "z_guided", "--out",
                 str(tmp_path / "default")]) == 0
    # the shipped filters given as a file are the default ones: the same image
    assert (out / "a_z-guided_cfa.tif").read_bytes() == \
        (tmp_path / "default" / "a_z-guided_cfa.tif").read_bytes()


@pytest.mark.parametrize("argv,flags,why", [
    (["evaluate", "--no-plots", "--out", "{t}/out"],
     (["--noise"], ["--optics"], ["--bit-depth", "4"], ["--no-linearise"], ["--grey"]),
     "applies to the RGB images the evaluation mosaics; the dataset's raw files are measured "
     "as they are (their own bit depth, noise and lens)"),
    (["train", "--out", "{t}/out"],
     (["--noise"], ["--bit-depth", "8"], ["--no-linearise"], ["--encoding", "srgb"]),
     "applies to the RGB images the fit mosaics; the dataset's raw files are fitted on as they "
     "are (their own bit depth, noise and encoding)"),
])
def test_the_simulation_options_are_refused_on_a_dataset_of_raw_files(tmp_path, capsys, argv,
                                                                       flags, why):
    """On raw files (measured as they are) these options changed nothing: evaluate's header
    still said 'noisy', 'optics', '4-bit'; train wrote them into the filters' metadata as
    applied."""
    raw = _raw_folder(tmp_path)
    argv = [a.replace("{t}", str(tmp_path)) for a in argv]
    for flag in flags:
        assert main([argv[0], "--dataset", str(raw), *flag, *argv[1:]]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert err == [f"rgbz-fast {argv[0]}: error: {flag[0]}: {why}"]
    assert not (tmp_path / "out").exists()


def test_tradeoff_quick_refuses_raw_files(tmp_path, capsys):
    """--quick crops images; a raw frame had failed with "'RawFrame' object is not
    subscriptable"."""
    _raw_folder(tmp_path)
    assert main(["tradeoff", "--dataset", str(tmp_path / "raw"), "--quick", "--methods",
                 "bilinear", "--patterns", "mask1", "--out", str(tmp_path / "t")]) == 2
    assert capsys.readouterr().err.strip().splitlines() == [
        "rgbz-fast tradeoff: error: --quick: crops the dataset's first two images to 128 x 128, "
        "and chart is a raw file, measured whole; run without --quick, or on RGB images"]


def test_reconstruct_refuses_raw_options_file_entries_for_a_frame_file(tmp_path, capsys):
    """An entry of --raw-options naming a frame file had been accepted and ignored (a flag
    was refused)."""
    f = _frame_file(tmp_path / "f.npz", 1)
    (tmp_path / "ro.json").write_text('{"f.npz": {"black_level": 100}}')
    assert main(["reconstruct", str(f), "--raw-options", str(tmp_path / "ro.json"), "--out",
                 str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()[-1]
    assert err.startswith("rgbz-fast reconstruct: error: --raw-options: black_level for f.npz: ")
    assert "is an rgbz-fast frame file, which records its own pattern" in err
    assert not (tmp_path / "out").exists()


def test_evaluate_depth_refuses_scene_sections_without_scenes(tmp_path, monkeypatch, capsys):
    """--sections scenes with no RGB-D scenes (no --data, no ../shared/data/rgbd beside the
    current folder) had printed a note, or {} with --json, and exited 0."""
    monkeypatch.chdir(tmp_path)
    for section, extra in (("upsample", []), ("upsample", ["--json"]), ("rgbnir", [])):
        assert main(["evaluate-depth", "--sections", section, *extra]) == 2
        assert capsys.readouterr().err.strip().splitlines() == [
            f"rgbz-fast evaluate-depth: error: --sections: {section} needs the data folders: "
            "pass --data DIR, the RGB-D scenes (../shared/data/rgbd, the default, is not "
            "beside the current folder; the RGB-NIR pairs are read from rgbnir beside it)"]


def test_a_batch_stopped_by_a_bad_input_says_what_it_wrote(tmp_path, capfd):
    """H84: ``simulate a bad c`` (and reconstruct, depth) wrote a's outputs, stopped at bad
    and never ran c, its error naming bad alone; the line now says what stayed written and
    what did not run. A batch whose first input fails says nothing more."""
    from PIL import Image

    for name in ("a", "c"):
        Image.fromarray(np.random.default_rng(0).integers(30, 220, (16, 16, 3), np.uint8)
                        ).save(tmp_path / f"{name}.png")
    (tmp_path / "b.png").write_bytes((tmp_path / "a.png").read_bytes()[:60])
    frames = [_frame_file(tmp_path / f"{n}.npz", s) for n, s in (("fa", 1), ("fc", 2))]
    (tmp_path / "fb.npz").write_bytes(b"not a frame")
    runs = [(["simulate", *(str(tmp_path / f"{n}.png") for n in "abc")], "b.png"),
            (["reconstruct", str(frames[0]), str(tmp_path / "fb.npz"), str(frames[1])], "fb.npz"),
            (["depth", str(frames[0]), str(tmp_path / "fb.npz"), str(frames[1])], "fb.npz")]
    for k, (argv, bad) in enumerate(runs):
        out = tmp_path / f"out{k}"
        capfd.readouterr()
        assert main(argv + ["--out", str(out), "--quiet"]) == 2
        err = capfd.readouterr().err.strip().splitlines()
        assert len(err) == 1 and bad in err[0], err
        assert err[0].endswith(f"(1 input before it written to {out}, 1 after it not run)"), err
        written = sorted(p.name for p in out.iterdir())
        assert written and all(n.startswith(("a_", "fa_")) for n in written), written
    capfd.readouterr()
    assert main(["simulate", str(tmp_path / "b.png"), str(tmp_path / "a.png"), "--out",
                 str(tmp_path / "first"), "--quiet"]) == 2
    assert "written" not in capfd.readouterr().err


def test_a_learned_method_on_a_clipped_raw_names_the_commands_off(tmp_path, capfd):
    """The library's advice clip_level=None reached the command line as --clip-level None,
    a word --help does not list (it offers off|auto|DN)."""
    from _support import shared_path

    png = shared_path("raw", "halide_bayer_small.png")     # skips when the data is absent
    capfd.readouterr()
    assert main(["reconstruct", str(png), "--rgbz-pattern", "mask2", "--phase", "GRBG",
                 "--black-level", "25", "--white-level", "1023", "--method", "learned",
                 "--clip-level", "auto", "--out", str(tmp_path / "o"), "--quiet"]) == 2
    err = capfd.readouterr().err
    assert err.rstrip().endswith("use another method or --clip-level off"), err
