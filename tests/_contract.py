"""The runner of the bad-input contract (docs/reports/robustness.md), shared by its files.

The contract is one file per subpackage, ``test_contract.py`` beside the other
tests of that subpackage (``tests/io/test_contract.py``, ...; the package root's
patterns and frames in ``tests/test_contract.py``, the command line in
``tests/cli/test_contract.py``). Each holds its rows, ``ROWS`` (Python API) and/or
``CLI_ROWS`` (command line), and gets its tests from here::

    test_api_contract = api_tests(ROWS)      # test_api_contract[<id>]
    test_cli_contract = cli_tests(CLI_ROWS)  # test_cli_contract[<id>]

A row id is ``<module>.<function or class>-<case>``, the module being where the
function lives today (``io.read_raw-no-shape``, ``simulation.ToFSensor-fov``).
``python tools/robustness_tables.py`` rewrites the two tables of the report from every
contract file; ``tests/test_contract.py::test_docs_tables_match_the_rows`` fails
when they drift apart.

Rows marked with a bug id are the contract as it should be; they are strict
xfails until the bug is fixed (:data:`BUGS`, and "Open bugs" in the report).
"""

from __future__ import annotations

import importlib.util
import os
import re
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

TESTS = Path(__file__).resolve().parent
if str(TESTS) not in sys.path:              # run as a script: the helpers beside this file
    sys.path.insert(0, str(TESTS))

from _support import frame_header, npy_bytes, write_npz  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from rgbz_fast import io as rio  # noqa: E402
from rgbz_fast import simulation as sim  # noqa: E402
from rgbz_fast import tof  # noqa: E402

REPO = TESTS.parent
DOC = REPO / "docs" / "reports" / "robustness.md"
#: the contract files, in the order of the report's tables
FILES = ("test_contract.py", "reconstruction/test_contract.py", "hardware/test_contract.py",
         "isp/test_contract.py", "metrics/test_contract.py", "simulation/test_contract.py",
         "io/test_contract.py", "tof/test_contract.py", "evaluation/test_contract.py",
         "cli/test_contract.py")

# open bugs: id -> what is wrong (docs/reports/robustness.md describes each, fixed ones too);
# a row with ``bug=`` is a strict xfail until the bug is fixed. None is open.
BUGS: dict[str, str] = {}

__all__ = ["Row", "CliRow", "api_tests", "cli_tests", "files", "all_rows", "markdown_tables",
           "u16", "f64", "with_value", "rgb", "u8img", "small_frame", "sim_frame", "sim_tof",
           "calibration", "taps_with_sites", "with_env"]


# --------------------------------------------------------------------------- inputs
def u16(shape=(8, 8), value=0):
    return np.full(shape, value, np.uint16)


def f64(shape=(8, 8), value=0.0):
    return np.full(shape, value, np.float64)


def with_value(value, dtype=np.float64, at=(1, 1), shape=(8, 8)):
    """Zeros with one ``value`` at ``at``."""
    a = np.zeros(shape, dtype)
    a[at] = value
    return a


def rgb(shape=(16, 16), value=0.5):
    return np.full(shape + (3,), value)


def u8img(shape=(16, 16, 3), value=0):
    return np.full(shape, value, np.uint8)


def small_frame(pattern="mask1", shape=(8, 8)):
    return rz.RawFrame(u16(shape, 100), pattern)


def sim_frame(pattern="mask1", shape=(16, 16)):
    """A noise-free simulated frame with ToF taps (depth 1.5 m)."""
    return sim.simulate(sim.Scene(rgb(shape), depth=np.full(shape, 1.5)), pattern, noise=False)


def calibration(shape):
    """A calibration of a noise-free Mask1 sweep of ``shape`` (a 16x16 frame has 64 sites)."""
    ds = np.linspace(0.6, 2.6, 10)
    sweep = [sim.simulate_tof(sim.Scene(rgb(shape), depth=np.full(shape, d)), "mask1",
                              sim.ToFSensor(), noise=False) for d in ds]
    return tof.calibrate(sweep, ds, orders=1)     # its usable walls cover 59 % of a wrap


def sim_tof(shape=(16, 16), **tof_sensor):
    return sim.simulate_tof(sim.Scene(rgb(shape), depth=np.full(shape, 1.5)), "mask1",
                            sim.ToFSensor(**tof_sensor), noise=False)


def taps_with_sites(row):
    """ToFTaps of one measurement whose site is at ``row`` of a 4x4 frame."""
    return sim.ToFTaps(np.zeros((1, 4, 1)), [20e6], ([row], [0]), 1, 12, [1.0], [True],
                       [False], sim.ToFSensor(frequencies=(20e6,), bit_depth=12), (4, 4))


def with_env(key, value, fn):
    """``fn()`` with the environment variable ``key`` set to ``value``, restored after."""
    old = os.environ.get(key)
    os.environ[key] = value
    try:
        return fn()
    finally:
        if old is None:
            os.environ.pop(key)
        else:
            os.environ[key] = old


class Files:
    """Sample files for the rows that read files, made once per contract file."""

    def __init__(self, d: Path):
        import imageio.v3 as iio

        self.d = d
        frame = rz.mosaic(np.random.default_rng(0).random((16, 16, 3)), "mask1")
        rio.save_frame(d / "ok.npz", frame)
        shipped = Path(rz.__file__).parent / "reconstruction" / "data"
        for name in ("learned_mask1.npz", "learned_mask2.npz", "z_guided_mask1_11bit.npz"):
            (d / name).write_bytes((shipped / name).read_bytes())     # the shipped filters
        blob = (d / "ok.npz").read_bytes()
        (d / "truncated.npz").write_bytes(blob[:len(blob) // 2])
        (d / "junk.npz").write_bytes(b"this is not a zip file")
        np.savez(d / "foreign.npz", a=np.zeros(3))
        np.savez(d / "nokeys.npz", data=u16(), header=np.array("{}"))
        np.savez(d / "notjson.npz", data=u16(), header=np.array("{not json"))
        iio.imwrite(d / "rgb.png", np.zeros((16, 16, 3), np.uint8))
        iio.imwrite(d / "tiny.png", np.zeros((1, 1, 3), np.uint8))
        iio.imwrite(d / "small.png", np.random.default_rng(1).integers(
            0, 256, (20, 20, 3), dtype=np.uint8))
        iio.imwrite(d / "plain.tif", u16((8, 8), 5))
        (d / "truncated.tif").write_bytes((d / "plain.tif").read_bytes()[:20])
        (d / "corrupt.png").write_bytes(b"not a png at all")
        (d / "corrupt.mat").write_bytes(b"not a mat file")
        (d / "corrupt.dng").write_bytes(b"not a dng" * 10)
        (d / "notes.xyz").write_text("?")
        (d / "file.txt").write_text("a file where a folder is expected")
        np.arange(16, dtype="<u2").tofile(d / "bayer.raw")
        (d / "one.raw").write_bytes(b"\x00\x00")
        (d / "empty").mkdir()
        (d / "cube_folder").mkdir()
        (d / "cube_folder" / "cube_ms.mat").write_bytes(b"a cube's place")
        (d / "rgbd_incomplete").mkdir()
        (d / "ds").mkdir()
        iio.imwrite(d / "ds" / "a.png", np.random.default_rng(2).integers(
            0, 256, (24, 24, 3), dtype=np.uint8))
        (d / "ds_corrupt").mkdir()
        (d / "ds_corrupt" / "a.png").write_bytes(b"not a png")
        # hostile and unusual files (the cases of docs/reports/robustness.md, "Hostile files")
        os.mkfifo(d / "fifo.npz")
        os.mkfifo(d / "fifo.tif")
        (d / "zero.raw").symlink_to("/dev/zero")
        write_npz(d / "bomb.npz", header=frame_header(),
                  data=npy_bytes((1024, 1024), np.uint16, bytes(1024 * 1024 * 2)))
        write_npz(d / "liar.npz", header=frame_header(),
                  data=npy_bytes((40000, 40000), np.uint16, bytes(100)))
        write_npz(d / "deep.npz", header=np.array("[" * 100000 + "]" * 100000), data=u16())
        write_npz(d / "metalist.npz", header=frame_header(meta=[1, 2]), data=u16())
        write_npz(d / "toflist.npz", header=frame_header(tof=[1]), data=u16(),
                  tof_taps=np.zeros((1, 4, 2)))
        write_npz(d / "hdrint.npz", header=np.array(5), data=u16())
        write_npz(d / "objects.npz", header=frame_header(), data=npy_bytes((2, 2), object))
        tile = np.tile(np.array([[1, 0], [2, 1]]), (256, 256))
        tile[::3, ::5] = 3
        write_npz(d / "bigtile.npz", data=np.zeros((512, 512), np.uint16), header=frame_header(
            pattern="/".join("".join("RGBZ"[c] for c in row) for row in tile)))
        rio.save_frame(d / "tof.npz", sim_frame())
        z = dict(np.load(d / "tof.npz"))
        z["tof_sites_rows"] = z["tof_sites_rows"] + 1000
        np.savez(d / "tofsites.npz", **z)
        iio.imwrite(d / "grey.png", np.arange(256, dtype=np.uint8).reshape(16, 16))
        (d / "ds_grey").mkdir()
        iio.imwrite(d / "ds_grey" / "g.png", np.arange(256, dtype=np.uint8).reshape(16, 16))
        (d / "ds_stems").mkdir()
        iio.imwrite(d / "ds_stems" / "a.png", np.zeros((16, 16, 3), np.uint8))
        iio.imwrite(d / "ds_stems" / "a.tif", np.zeros((16, 16, 3), np.uint8))
        (d / "sub").mkdir()
        (d / "sub" / "ok.npz").write_bytes((d / "ok.npz").read_bytes())
        iio.imwrite(d / "bayer16.png", np.full((8, 8), 300, np.uint16))
        (d / "raw_options.json").write_text('{"bayer16.png": {"phase": "GBRG"}, "*": 5}')
        (d / "raw_ok.json").write_text('{"*": {"phase": "GBRG"}}')
        (d / "raw_other.json").write_text('{"bayer16.png": {"phase": "GBRG"}}')  # not in ds
        (d / "raw_twice.json").write_text('{"*": {"phase": "GBRG", "phase": "RGGB"}}')
        # integer samples wider than 16 bits: their type says nothing about their range
        # (photometric named: tifffile before 2023.7 warned that its default would change;
        # the bytes are those of today's default)
        import tifffile
        tifffile.imwrite(d / "int32.tif", np.full((16, 16, 3), 200, np.int32),
                         photometric="rgb")
        # samples that are no RGB or grey, and a damaged 16-bit PGM
        from PIL import Image

        Image.fromarray(np.zeros((16, 16, 3), np.uint8)).convert("CMYK").save(d / "cmyk.jpg")
        Image.fromarray(np.zeros((16, 16, 3), np.uint8)).convert("CMYK").save(d / "cmyk.tif")
        Image.fromarray(np.zeros((16, 16, 3), np.uint8)).convert("LAB").save(d / "lab.tif")
        (d / "short.pgm").write_bytes(b"P5\n16 16\n65535\n" + bytes(100))
        # inputs named like the outputs of other inputs
        (d / "collide").mkdir()
        iio.imwrite(d / "collide" / "a.png", np.zeros((16, 16, 3), np.uint8))
        (d / "collide" / "a_mask1.npz").write_bytes((d / "ok.npz").read_bytes())
        (d / "collide" / "a_mask1_sg_cfa.tif").write_bytes((d / "plain.tif").read_bytes())
        # option files nested too deeply, naming no option, or not text
        (d / "deep.json").write_text("[" * 100000 + "]" * 100000)
        (d / "unknown.json").write_text('{"*": {"phse": "RGGB"}}')
        (d / "binary.json").write_bytes(b"\xff\xfe\x00{")
        # a file no decoder knows under a known suffix
        (d / "junk.bmp").write_bytes(b"junk" * 8)

    def __truediv__(self, name):
        return self.d / name


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    return Files(tmp_path_factory.mktemp("contract"))


# --------------------------------------------------------------------------- rows
@dataclass(frozen=True)
class Row:
    id: str
    call: str                 # how the row reads in docs/reports/robustness.md
    fn: object                # fn(files) -> anything
    exc: type
    msg: str                  # the message starts with this ("{d}": the sample-file folder)
    bug: str | None = None

    @property
    def gets(self):
        return f"{self.exc.__name__} `{self.msg}...`"


@dataclass(frozen=True)
class CliRow:
    id: str
    argv: tuple               # "{d}" is replaced by the sample-file folder
    msg: str                  # the last line of stderr starts with "rgbz-fast CMD: error: " + msg
    bug: str | None = None
    usage: bool = False       # an argparse error: usage lines, then the error line


def _params(rows):
    return [pytest.param(r, id=r.id, marks=[pytest.mark.xfail(
        strict=True, reason=f"bug {r.bug} (docs/reports/robustness.md): {BUGS[r.bug]}")]
        if r.bug else []) for r in rows]


def api_tests(rows):
    """The test of API rows: the call raises ``row.exc`` whose message starts with ``row.msg``."""
    @pytest.mark.parametrize("row", _params(rows))
    def test_api_contract(row, files):
        if row.id == "io.read_raw-corrupt-dng":
            pytest.importorskip("rawpy")
        with pytest.raises(row.exc) as info:
            row.fn(files)
        msg = str(info.value)
        want = row.msg.replace("{d}", str(files.d))
        if isinstance(info.value, FileNotFoundError) and not msg.startswith(want):
            msg = str(info.value.args[0]) if info.value.args else msg
        assert msg.startswith(want), f"message {msg!r} does not start with {want!r}"
    return test_api_contract


#: the commands that write an output folder (the rows get one of their own, and --quiet)
_WRITERS = ("simulate", "reconstruct", "depth", "evaluate")


def _argv(row, d):
    argv = [a.replace("{d}", str(d)) for a in row.argv]
    if argv[0] in _WRITERS and "--out" not in argv:
        argv += ["--out", str(d / f"out_{row.id}")]
    if argv[0] in _WRITERS and not row.usage:
        argv.append("--quiet")
    return argv


def cli_prefix(command):
    """Subcommands report as `rgbz-fast CMD: error:` (their unknown arguments too); the
    top-level parser (an unknown command) as `rgbz-fast: error:`."""
    from rgbz_fast._cli import COMMANDS

    if command in {m.NAME for m in COMMANDS}:
        return f"rgbz-fast {command}: error: "
    return "rgbz-fast: error: "


def cli_tests(rows):
    """The test of CLI rows: exit 2, and the reason on the last line of stderr (one line, no
    traceback; after argparse's usage lines for ``usage`` rows)."""
    @pytest.mark.parametrize("row", _params(rows))
    def test_cli_contract(row, files, capsys):
        from rgbz_fast._cli import main

        argv = _argv(row, files.d)
        try:
            code = main(argv)
        except SystemExit as e:                           # argparse
            code = e.code
        err = [line for line in capsys.readouterr().err.splitlines() if line.strip()]
        assert code == 2, err
        assert err, "no reason on stderr"
        if row.usage:
            assert err[0].startswith("usage: ")          # argparse: usage, then the reason
        else:
            assert len(err) == 1, err                    # one line, no traceback
        want = cli_prefix(argv[0]) + row.msg.replace("{d}", str(files.d))
        assert err[-1].startswith(want), f"{err[-1]!r} does not start with {want!r}"
    return test_cli_contract


# --------------------------------------------------------------------------- the report
def _load(relpath):
    path = TESTS / relpath
    name = "_contract_rows_" + re.sub(r"\W", "_", relpath)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def all_rows():
    """(API rows, CLI rows) of every contract file, in the order of :data:`FILES`."""
    api, cli = [], []
    for relpath in FILES:
        module = _load(relpath)
        api += getattr(module, "ROWS", [])
        cli += getattr(module, "CLI_ROWS", [])
    return api, cli


def _cell(text):
    return text.replace("|", "\\|")


def markdown_tables(api=None, cli=None):
    """The two contract tables of docs/reports/robustness.md, generated from the rows."""
    if api is None:
        api, cli = all_rows()
    lines = ["| id | call (bad input) | gets | status |", "|---|---|---|---|"]
    for r in api:
        status = f"**bug {r.bug}**" if r.bug else "ok"
        lines.append(f"| `{r.id}` | `{_cell(r.call)}` | {_cell(r.exc.__name__)} "
                     f"`{_cell(r.msg.replace('{d}/', ''))}...` | {status} |")
    api_table = "\n".join(lines)
    lines = ["| id | command line | exit, stderr | status |", "|---|---|---|---|"]
    for r in cli:
        argv = " ".join(r.argv).replace("{d}/", "")
        shown = ("usage lines, then " if r.usage else "one line ") + \
            f"`{cli_prefix(r.argv[0])}{_cell(r.msg)}...`".replace("{d}/", "")
        status = f"**bug {r.bug}**" if r.bug else "ok"
        lines.append(f"| `{r.id}` | `rgbz-fast {_cell(argv)}` | 2, {shown} | {status} |")
    return api_table, "\n".join(lines)


def table_between(text, start, end):
    i, j = text.index(start) + len(start), text.index(end)
    return text[i:j].strip()
