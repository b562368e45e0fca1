"""Probe round 24 (K): the command line's streams and its checks before the work. A stderr
whose reader is gone, a closed stdout, an ASCII console and a Ctrl-C while the command loads
cost lines, never the run; train and calibrate check --out FILE before the fit; train names
a --dataset that is a loop of links; evaluate's list of reports is status (stderr); --help
and docs/guide/cli.md agree on --workers, --input-bits and --skip-bad."""

from __future__ import annotations

import io
import os
import re
import subprocess
import sys
import textwrap
import warnings

import numpy as np
import pytest

from rgbz_fast._cli import main
from _support import REPO


def _dataset(folder, bad=(), images="c"):
    """``folder`` with a small RGB image per letter of ``images`` (c.png) and a file that
    does not decode per name of ``bad``."""
    import imageio.v3 as iio

    folder.mkdir()
    y, x = np.mgrid[0:48, 0:64]
    for i, name in enumerate(images):
        iio.imwrite(folder / f"{name}.png", np.stack(
            [(x * (7 + i) + y) % 256, (y * 5) % 256, (x + 3 * y) % 256], -1).astype(np.uint8))
    for name in bad:
        (folder / name).write_bytes(b"not a png")
    return folder


def _evaluate(dataset, out, *extra):
    return ["evaluate", "--dataset", str(dataset), "--patterns", "mask1", "--methods", "bi",
            "--metrics", "cfa_psnr", "--no-plots", "--out", str(out), *extra]


class _GoneReader(io.TextIOBase):
    """A stream whose reader has left: every write and flush is a broken pipe, but for the
    flush of its own close() when the test's object is collected (Python 3.13 reports an
    error there as unraisable, which pytest makes a test error)."""

    def write(self, text):
        raise BrokenPipeError(32, "Broken pipe")

    def flush(self):
        if not getattr(self, "_closing", False):
            raise BrokenPipeError(32, "Broken pipe")

    def close(self):
        self._closing = True
        super().close()


def test_a_reader_of_stderr_gone_does_not_lose_the_run(tmp_path, monkeypatch, capsys):
    """Probe round 24 (K-08): `rgbz-fast evaluate --skip-bad ... 2>&1 | head -1`: the first
    line to stderr after the reader left (a `skipped` line, a warning) raised BrokenPipeError,
    main() took it for the command's error, whose own line failed again: exit 1, no table,
    no reports, after the whole evaluation."""
    ds = _dataset(tmp_path / "ds", bad=("a.png", "b.png"))
    monkeypatch.setattr(sys, "stderr", _GoneReader())
    assert main(_evaluate(ds, tmp_path / "ev", "--skip-bad")) == 0
    assert "CFA PSNR" in capsys.readouterr().out
    assert (tmp_path / "ev" / "results.csv").is_file()


def test_a_warning_to_a_stderr_whose_reader_is_gone_is_dropped(monkeypatch, capsys):
    """Probe round 24 (K-08): a warning goes through warnings.showwarning to sys.stderr; a
    closed pipe there had ended the command with exit 1 and a traceback."""
    from rgbz_fast._cli import config

    def run(args):
        warnings.warn("the user should know", UserWarning)
        print("the output")
        return 0

    monkeypatch.setattr(config, "run", run)
    monkeypatch.setattr(sys, "stderr", _GoneReader())
    with warnings.catch_warnings():
        warnings.simplefilter("always")
        assert main(["config"]) == 0
    assert capsys.readouterr().out == "the output\n"


def test_an_ascii_console_takes_the_tables_escaped(tmp_path, monkeypatch):
    """Probe round 24 (K-01): with PYTHONIOENCODING=ascii (a non-UTF-8 console) evaluate's
    '±', opcount's 'β', tradeoff's 'Δ', pattern-study's 'σ' and simulate's accented file
    names stopped the command after its work: "'ascii' codec can't encode character",
    exit 2 (simulate had written its first file only). The characters are escaped; the
    stream's encoding and its strictness are as they were after the command."""
    from rgbz_fast._cli import config

    raw = io.BytesIO()
    out = io.TextIOWrapper(raw, encoding="ascii", write_through=True)

    def run(args):
        print("\u00b1 \u0394 \u03b2 \u03c3 sc\u00e8ne.png")
        return 0

    monkeypatch.setattr(config, "run", run)
    monkeypatch.setattr(sys, "stdout", out)
    assert main(["config"]) == 0
    assert raw.getvalue() == b"\\xb1 \\u0394 \\u03b2 \\u03c3 sc\\xe8ne.png\n"
    assert (out.encoding, out.errors) == ("ascii", "strict")
    ds = _dataset(tmp_path / "ds", images="cd")       # a mean '±' its spread
    raw.seek(0)
    raw.truncate()
    assert main(_evaluate(ds, tmp_path / "ev", "--quiet")) == 0
    assert b"\\xb1" in raw.getvalue() and b"CFA PSNR" in raw.getvalue()


def test_a_closed_stdout_is_a_sink(tmp_path, monkeypatch, capsys):
    """Probe round 24 (K-07): with stdout closed (`rgbz-fast ... >&-`, sys.stdout None)
    every command died at its first print, "'NoneType' object has no attribute 'write'",
    and a batch stopped after its first input."""
    monkeypatch.setattr(sys, "stdout", None)
    assert main(["config"]) == 0
    assert sys.stdout is None                     # put back as it was
    assert "Traceback" not in capsys.readouterr().err
    import imageio.v3 as iio

    y, x = np.mgrid[0:32, 0:48]
    for i, n in enumerate("ab"):
        iio.imwrite(tmp_path / f"{n}.png", np.stack(
            [(x * (i + 2)) % 256, (y * 3) % 256, (x + y) % 256], -1).astype(np.uint8))
    proc = subprocess.run([sys.executable, "-m", "rgbz_fast", "simulate",
                           str(tmp_path / "a.png"), str(tmp_path / "b.png"),
                           "--out", str(tmp_path / "fr")],
                          preexec_fn=lambda: os.close(1), stderr=subprocess.PIPE, text=True,
                          timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr
    assert sorted(p.name for p in (tmp_path / "fr").iterdir()) == ["a_mask1.npz",
                                                                   "b_mask1.npz"]


_LOADING = """
import sys
import rgbz_fast

class Interrupt:
    # Ctrl-C at the moment the command's modules load
    def find_spec(self, name, path=None, target=None):
        if name == "rgbz_fast._cli._main":
            raise KeyboardInterrupt

sys.meta_path.insert(0, Interrupt())
from rgbz_fast._cli import main
"""


def test_ctrl_c_while_the_command_loads_is_no_traceback(tmp_path):
    """Probe round 24 (K-06): Ctrl-C while the console script imported the command printed
    a KeyboardInterrupt traceback through the imports instead of `interrupted` and exit
    130; a program that imports the package keeps its KeyboardInterrupt."""
    script = tmp_path / "rgbz-fast"                # the console script's name
    script.write_text(textwrap.dedent(_LOADING))
    proc = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                          timeout=60)
    assert (proc.returncode, proc.stderr) == (130, "rgbz-fast: interrupted\n")
    other = tmp_path / "program.py"
    other.write_text(textwrap.dedent(_LOADING))
    proc = subprocess.run([sys.executable, str(other)], capture_output=True, text=True,
                          timeout=60)
    assert "KeyboardInterrupt" in proc.stderr and proc.returncode != 130


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="needs Linux's /proc")
@pytest.mark.parametrize("argv", [["calibrate", "--simulate"], ["train", "--dataset", "DS"]])
def test_out_file_that_cannot_be_written_is_refused_before_the_work(tmp_path, capsys, argv):
    """Probe round 24 (K-02): `train --out FILE` and `calibrate --out FILE` ran the whole fit,
    then failed on the hidden temporary file of the write ('path: /proc/.f.npz.<hex>.tmp:
    No such file or directory'); cli.md says --out is checked before the work."""
    ds = _dataset(tmp_path / "ds")
    argv = [str(ds) if a == "DS" else a for a in argv]
    assert main([*argv, "--out", "/proc/k02.npz", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err == (f"rgbz-fast {argv[0]}: error: --out: '/proc/k02.npz': cannot write in "
                   "'/proc' (No such file or directory)\n")
    (tmp_path / "file").write_text("")
    assert main([*argv, "--out", str(tmp_path / "file" / "f.npz"), "--quiet"]) == 2
    assert (f"error: --out: '{tmp_path}/file/f.npz': '{tmp_path}/file' is not a folder"
            in capsys.readouterr().err)


def test_train_names_a_dataset_that_is_a_loop_of_links(tmp_path, capsys):
    """Probe round 24 (K-03): `train --dataset LOOP` (ln -s loop loop) printed a RuntimeError
    traceback from Path.resolve(), where every other command says in one line that the
    --dataset does not exist."""
    loop = tmp_path / "loop"
    os.symlink("loop", loop)
    assert main(["train", "--dataset", str(loop), "--out", str(tmp_path / "f.npz")]) == 2
    assert capsys.readouterr().err == f"rgbz-fast train: error: --dataset: {loop} does not exist\n"


def test_evaluate_lists_its_reports_on_stderr(tmp_path, capsys):
    """Probe round 24 (K-05): `rgbz-fast evaluate > table.txt` wrote the line `reports:
    OUT/results.csv, ...` into the file after the table: status, as the progress, on stderr
    now (and --quiet still removes it)."""
    ds = _dataset(tmp_path / "ds")
    assert main(_evaluate(ds, tmp_path / "ev")) == 0
    cap = capsys.readouterr()
    assert "CFA PSNR" in cap.out and "reports:" not in cap.out
    assert f"reports: {tmp_path / 'ev' / 'results.csv'}" in cap.err
    assert main(_evaluate(ds, tmp_path / "ev", "--quiet")) == 0
    cap = capsys.readouterr()
    assert "CFA PSNR" in cap.out and "reports:" not in cap.out + cap.err


def _help(command, capsys):
    with pytest.raises(SystemExit):
        main([command, "--help"])
    return " ".join(capsys.readouterr().out.split())


@pytest.mark.parametrize("command", ["reconstruct", "depth", "pattern-study", "evaluate"])
def test_each_command_gives_its_own_workers_default(command, capsys):
    """Probe round 24 (K-10): reconstruct, depth and pattern-study --help said for --workers
    "(default: all cores; evaluate: 1 per process when it runs several)": evaluate's
    default, in the help of three other commands."""
    text = _help(command, capsys)
    line = re.search(r"--workers N (.*?\))", text).group(1)
    if command == "evaluate":
        assert "default: 1 while images run side by side" in line
    else:
        assert line == "threads of each kernel call (default: all cores)"


@pytest.mark.parametrize("command,option", [("simulate", "--input-bits"),
                                            ("evaluate", "--skip-bad")])
def test_cli_md_lists_every_option_of_simulate_and_evaluate(command, option, capsys):
    """Probe round 24 (K-10): `simulate --input-bits` and `evaluate --skip-bad` were in the
    parsers and --help, not in docs/guide/cli.md's option tables."""
    assert option in _help(command, capsys)
    page = (REPO / "docs" / "guide" / "cli.md").read_text()
    section = page.split(f"## `rgbz-fast {command}`", 1)[1].split("\n## ", 1)[0]
    assert f"\n| `{option}` |" in section
