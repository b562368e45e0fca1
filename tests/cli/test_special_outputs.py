"""Outputs that are not regular files: a FIFO (a device is the same file type test) at
``--out`` or among the files a command writes is refused before anything is written and is
left as it was; a symbolic link is followed (the file it names is replaced, the link stays).

Only FIFOs and links in a temporary folder are made here: a test must never risk replacing a
real device node."""

from __future__ import annotations

import os
import stat

import numpy as np
import pytest

from rgbz_fast._cli import main
from rgbz_fast.io import atomic_write


def _is_fifo(path):
    return stat.S_ISFIFO(os.lstat(path).st_mode)


def test_atomic_write_refuses_a_fifo_and_follows_a_link(tmp_path):
    fifo = tmp_path / "out.npz"
    os.mkfifo(fifo)
    with pytest.raises(ValueError, match=r"^path: .*out\.npz is a FIFO \(named pipe\), not a "
                                         "regular file; expected a file to write"):
        atomic_write(fifo, b"data")
    assert _is_fifo(fifo) and sorted(os.listdir(tmp_path)) == ["out.npz"]
    link = tmp_path / "to_fifo"
    link.symlink_to(fifo)
    with pytest.raises(ValueError, match="is a FIFO"):
        atomic_write(link, b"data")
    assert link.is_symlink() and _is_fifo(fifo)
    # a link to a regular file (in another folder): the file gets the data, the link stays
    (tmp_path / "real").mkdir()
    target = tmp_path / "real" / "a.txt"
    target.write_text("old")
    link = tmp_path / "a.txt"
    link.symlink_to(target)
    atomic_write(link, "new")
    assert link.is_symlink() and target.read_text() == "new"
    assert sorted(os.listdir(tmp_path / "real")) == ["a.txt"]         # no temporary left
    # a dangling link: the file it names is made
    dangling = tmp_path / "d.txt"
    dangling.symlink_to(tmp_path / "real" / "b.txt")
    atomic_write(dangling, "b")
    assert dangling.is_symlink() and (tmp_path / "real" / "b.txt").read_text() == "b"


@pytest.mark.parametrize("command", ["train", "calibrate"])
def test_out_file_that_is_a_fifo_is_refused(tmp_path, capsys, command):
    fifo = tmp_path / "out.npz"
    os.mkfifo(fifo)
    link = tmp_path / "link.npz"
    link.symlink_to(fifo)
    ds = tmp_path / "ds"
    ds.mkdir()
    import imageio.v3 as iio

    iio.imwrite(ds / "a.png", np.full((32, 32, 3), 128, np.uint8))
    argv = {"train": ["train", "--dataset", str(ds), "--limit", "1"],
            "calibrate": ["calibrate", "--simulate", "--shape", "16x16", "--positions", "20",
                          "--frames-per-position", "1"]}[command]
    for out in (fifo, link):
        assert main([*argv, "--quiet", "--out", str(out)]) == 2
        err = capsys.readouterr().err
        assert f"--out: {str(out)!r} is a FIFO (named pipe), not a regular file" in err
        assert _is_fifo(fifo) and link.is_symlink()


def test_a_fifo_among_the_files_written_is_refused_before_any_is(tmp_path, capsys):
    ds = tmp_path / "ds"
    ds.mkdir()
    import imageio.v3 as iio

    iio.imwrite(ds / "a.png", np.full((32, 32, 3), 128, np.uint8))
    out = tmp_path / "out"
    out.mkdir()
    os.mkfifo(out / "results.csv")
    assert main(["evaluate", "--dataset", str(ds), "--out", str(out), "--quiet",
                 "--metrics", "cfa_psnr", "--methods", "bi", "--no-cache"]) == 2
    err = capsys.readouterr().err
    assert "results.csv (from the reports) is a FIFO (named pipe), not a regular file" in err
    assert sorted(os.listdir(out)) == ["results.csv"] and _is_fifo(out / "results.csv")


def test_a_folder_where_an_output_file_goes_names_out(tmp_path, capsys):
    frame = tmp_path / "f.npz"
    from rgbz_fast import io as rio
    from rgbz_fast import mosaic

    rio.save_frame(frame, mosaic(np.random.default_rng(0).random((16, 16, 3)), "mask1"))
    (tmp_path / "out" / "f_sg_cfa.tif").mkdir(parents=True)
    assert main(["reconstruct", str(frame), "--out", str(tmp_path / "out"), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"--out: {tmp_path / 'out' / 'f_sg_cfa.tif'} (from {frame}) is a folder" in err
    assert sorted(os.listdir(tmp_path / "out")) == ["f_sg_cfa.tif"]


def test_pattern_study_refuses_its_report_in_the_dataset_folder(tmp_path, capsys):
    import imageio.v3 as iio

    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "a.png", np.full((32, 32, 3), 128, np.uint8))
    assert main(["pattern-study", "--dataset", str(ds), "--out", str(ds), "--quiet",
                 "--no-cache"]) == 2
    assert "--out: pattern_study.png (from the report) would be written into" in \
        capsys.readouterr().err
    assert sorted(os.listdir(ds)) == ["a.png"]


def test_pattern_study_refuses_its_report_in_the_train_folder(tmp_path, capsys):
    """The plot written into --train had been fitted on by the next run's learned filters."""
    import imageio.v3 as iio

    ds, train = tmp_path / "ds", tmp_path / "train"
    for d in (ds, train):
        d.mkdir()
        iio.imwrite(d / "a.png", np.full((32, 32, 3), 128, np.uint8))
    assert main(["pattern-study", "--dataset", str(ds), "--train", str(train), "--out",
                 str(train), "--quiet", "--no-cache"]) == 2
    assert "--out: pattern_study.png (from the report) would be written into" in \
        capsys.readouterr().err
    assert sorted(os.listdir(train)) == ["a.png"]
