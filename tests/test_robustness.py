"""The bad-input contract of docs/reports/robustness.md, row by row, plus large frames and interrupted runs.

Every row of the contract table is one entry of ``ROWS`` (Python API) or
``CLI_ROWS`` (command line), identified by the id shown in the first column of
docs/reports/robustness.md; the tests are ``test_api_contract[<id>]`` and
``test_cli_contract[<id>]``. ``test_docs_table_matches_the_rows`` keeps the
document and this file in step: regenerate the tables with
``python tests/test_robustness.py``.

Rows marked with a bug id are the contract as it should be; they are strict
xfails until the bug is fixed (docs/reports/robustness.md, "Known bugs").
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from _support import frame_header, npy_bytes, write_npz


import rgbz_fast as rz  # noqa: E402
from rgbz_fast import evaluation as ev
from rgbz_fast import io as rio  # noqa: E402
from rgbz_fast import io as frameio  # noqa: E402
from rgbz_fast import io as rawio  # noqa: E402
from rgbz_fast import isp, metrics  # noqa: E402
from rgbz_fast import simulation as scene  # noqa: E402
from rgbz_fast import simulation as sensor  # noqa: E402
from rgbz_fast import tof as tof_isp  # noqa: E402
from rgbz_fast._cli import main  # noqa: E402
from rgbz_fast.isp import demosaic  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
DOC = REPO / "docs" / "reports" / "robustness.md"

# open bugs: id -> what is wrong (docs/reports/robustness.md describes each, fixed ones too);
# a row with ``bug=`` is a strict xfail until the bug is fixed. None is open.
BUGS: dict[str, str] = {}


# --------------------------------------------------------------------------- fixtures
def _u16(shape=(8, 8), value=0):
    return np.full(shape, value, np.uint16)


def _f64(shape=(8, 8), value=0.0):
    return np.full(shape, value, np.float64)


def _with(value, dtype=np.float64, at=(1, 1), shape=(8, 8)):
    a = np.zeros(shape, dtype)
    a[at] = value
    return a


def _rgb(shape=(16, 16), value=0.5):
    return np.full(shape + (3,), value)


def _u8img(shape=(16, 16, 3), value=0):
    return np.full(shape, value, np.uint8)


def _frame(pattern="mask1", shape=(8, 8)):
    return rz.RawFrame(_u16(shape, 100), pattern)


def _sim(pattern="mask1", shape=(16, 16)):
    return sensor.simulate(scene.Scene(_rgb(shape), depth=np.full(shape, 1.5)), pattern,
                           noise=False)


def _calibration(shape):
    """A calibration of a noise-free Mask1 sweep of ``shape`` (a 16x16 frame has 64 sites)."""
    ds = np.linspace(0.6, 2.6, 10)
    sweep = [sensor.simulate_tof(scene.Scene(_rgb(shape), depth=np.full(shape, d)), "mask1",
                                 sensor.ToFSensor(), noise=False) for d in ds]
    return tof_isp.calibrate(sweep, ds, orders=2)


def _sim_tof(shape=(16, 16), **tof_sensor):
    return sensor.simulate_tof(scene.Scene(_rgb(shape), depth=np.full(shape, 1.5)), "mask1",
                               sensor.ToFSensor(**tof_sensor), noise=False)


def _bad_frame(id_, name, what, reason, **kw):
    """A contract row: load_frame of the hostile NPZ ``name`` is 'not a readable frame'."""
    return Row(f"frameio.load-{id_}", f"load_frame({what})",
               lambda f: frameio.load_frame(f / f"{name}.npz", **kw), ValueError,
               f"path: {{d}}/{name}.npz is not a readable rgbz-fast frame ({reason}")


def _taps_with_sites(row):
    return rz.simulation.ToFTaps(np.zeros((1, 4, 1)), [20e6], ([row], [0]), 1, 12, [1.0],
                                 [True], [False], sensor.ToFSensor(), (4, 4))


def _with_env(key, value, fn):
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
    """Sample files for the rows that read files, made once per session."""

    def __init__(self, d: Path):
        import imageio.v3 as iio

        self.d = d
        frame = rz.mosaic(np.random.default_rng(0).random((16, 16, 3)), "mask1")
        frameio.save_frame(d / "ok.npz", frame)
        blob = (d / "ok.npz").read_bytes()
        (d / "truncated.npz").write_bytes(blob[:len(blob) // 2])
        (d / "junk.npz").write_bytes(b"this is not a zip file")
        np.savez(d / "foreign.npz", a=np.zeros(3))
        np.savez(d / "nokeys.npz", data=_u16(), header=np.array("{}"))
        np.savez(d / "notjson.npz", data=_u16(), header=np.array("{not json"))
        iio.imwrite(d / "rgb.png", np.zeros((16, 16, 3), np.uint8))
        iio.imwrite(d / "tiny.png", np.zeros((1, 1, 3), np.uint8))
        iio.imwrite(d / "small.png", np.random.default_rng(1).integers(
            0, 256, (20, 20, 3), dtype=np.uint8))
        iio.imwrite(d / "plain.tif", _u16((8, 8), 5))
        (d / "truncated.tif").write_bytes((d / "plain.tif").read_bytes()[:20])
        (d / "corrupt.png").write_bytes(b"not a png at all")
        (d / "corrupt.mat").write_bytes(b"not a mat file")
        (d / "corrupt.dng").write_bytes(b"not a dng" * 10)
        (d / "notes.xyz").write_text("?")
        (d / "file.txt").write_text("a file where a folder is expected")
        np.arange(16, dtype="<u2").tofile(d / "bayer.raw")
        (d / "one.raw").write_bytes(b"\x00\x00")
        (d / "empty").mkdir()
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
        write_npz(d / "deep.npz", header=np.array("[" * 100000 + "]" * 100000), data=_u16())
        write_npz(d / "metalist.npz", header=frame_header(meta=[1, 2]), data=_u16())
        write_npz(d / "toflist.npz", header=frame_header(tof=[1]), data=_u16(),
                  tof_taps=np.zeros((1, 4, 2)))
        write_npz(d / "hdrint.npz", header=np.array(5), data=_u16())
        write_npz(d / "objects.npz", header=frame_header(), data=npy_bytes((2, 2), object))
        tile = np.tile(np.array([[1, 0], [2, 1]]), (256, 256))
        tile[::3, ::5] = 3
        write_npz(d / "bigtile.npz", data=np.zeros((512, 512), np.uint16), header=frame_header(
            pattern="/".join("".join("RGBZ"[c] for c in row) for row in tile)))
        sim = _sim()
        frameio.save_frame(d / "tof.npz", sim)
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
    msg: str                  # the message starts with this
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


R = Row
ROWS = [
    # -- patterns ------------------------------------------------------------------
    R("pattern.none", "get_pattern(None)", lambda f: rz.get_pattern(None), TypeError,
      "pattern: expected a Pattern, a preset name or a tile string"),
    R("pattern.unknown", "get_pattern('mask7')", lambda f: rz.get_pattern("mask7"),
      ValueError, "pattern: 'mask7' is neither a preset"),
    R("pattern.tile-empty", "Pattern('')", lambda f: rz.Pattern(""), ValueError,
      "tile: empty row"),
    R("pattern.tile-ragged", "Pattern('ZR/B')", lambda f: rz.Pattern("ZR/B"), ValueError,
      "tile: ragged rows"),
    R("pattern.tile-letter", "Pattern('ZX/BG')", lambda f: rz.Pattern("ZX/BG"), ValueError,
      "tile: unknown channel letter"),
    R("pattern.tile-only-z", "Pattern('ZZ/ZZ')", lambda f: rz.Pattern("ZZ/ZZ"), ValueError,
      "tile: the tile holds no colour site"),
    R("pattern.tile-ndim", "Pattern(3-D array)", lambda f: rz.Pattern(np.zeros((2, 2, 2), int)),
      ValueError, "tile: expected a non-empty 2-D array"),
    R("pattern.tile-float", "Pattern(float array)", lambda f: rz.Pattern(np.zeros((2, 2))),
      TypeError, "tile: expected integer channel codes"),
    R("pattern.tile-code", "Pattern(code 5)", lambda f: rz.Pattern(np.full((2, 2), 5)),
      ValueError, "tile: channel codes must be"),
    R("pattern.bayer-unknown", "Pattern('ZR/BG', bayer='XXXX')",
      lambda f: rz.Pattern("ZR/BG", bayer="XXXX"), ValueError, "bayer: expected one of"),
    R("pattern.bayer-mismatch", "Pattern('ZR/BG', bayer='RGGB')",
      lambda f: rz.Pattern("ZR/BG", bayer="RGGB"), ValueError,
      "bayer: the colour sites of tile"),
    R("pattern.phase-mask1", "mask1('XXXX')", lambda f: rz.mask1("XXXX"), ValueError,
      "phase: expected one of GRBG"),
    R("pattern.phase-mask2", "mask2(None)", lambda f: rz.mask2(None), ValueError,
      "phase: expected one of GRBG"),
    R("pattern.phase-rows", "rows('')", lambda f: rz.rows(""), ValueError,
      "phase: expected one of GRBG"),
    R("pattern.phase-bayer", "bayer(3)", lambda f: rz.bayer(3), ValueError,
      "phase: expected one of GRBG"),
    R("pattern.shape-ndim", "mask1().z_mask((4,))", lambda f: rz.mask1().z_mask((4,)),
      ValueError, "shape: expected a 2-D (rows, cols) frame shape"),
    R("pattern.shape-small", "mask2().z_mask((3, 3))", lambda f: rz.mask2().z_mask((3, 3)),
      ValueError, "shape: frame 3x3 is smaller than one period (4x4)"),
    R("pattern.shape-none", "mask1().z_mask(None)", lambda f: rz.mask1().z_mask(None),
      TypeError, "shape: expected a (rows, cols) tuple"),
    R("pattern.shape-text", "mask1().z_mask('ab')", lambda f: rz.mask1().z_mask("ab"),
      TypeError, "shape: expected a (rows, cols) tuple"),
    R("pattern.no-bayer", "Pattern('ZR/RG').bayer_tile()",
      lambda f: rz.Pattern("ZR/RG").bayer_tile(), ValueError,
      "pattern: tile 'ZR/RG' fits no Bayer phase"),
    R("pattern.tile-too-large", "Pattern(64x64 array)",
      lambda f: rz.Pattern(np.tile([[3, 0], [2, 1]], (32, 32))), ValueError,
      "tile: 64x64 sites, more than the largest tile (32x32)"),
    R("pattern.tile-too-large-text", "Pattern(a 33-row tile string)",
      lambda f: rz.Pattern("/".join(["ZR", "BG"] * 16 + ["ZR"])), ValueError,
      "tile: 33x2 sites, more than the largest tile (32x32)"),

    # -- RawFrame, mosaic ------------------------------------------------------------
    R("rawframe.ndim", "RawFrame(3-D array)", lambda f: rz.RawFrame(_u16((4, 4, 3)), "mask1"),
      ValueError, "data: expected a 2-D array"),
    R("rawframe.dtype", "RawFrame(int64 list)", lambda f: rz.RawFrame([[1, 2], [3, 4]], "mask1"),
      TypeError, "data: dtype int64 is not supported"),
    R("rawframe.nan", "RawFrame(NaN)", lambda f: rz.RawFrame(_with(np.nan), "mask1"),
      ValueError, "data: holds 1 NaN or infinite value(s)"),
    R("rawframe.range", "RawFrame(value 4000, 11 bits)",
      lambda f: rz.RawFrame(_with(4000.0), "mask1"), ValueError, "data: values span"),
    R("rawframe.uint8-bits", "RawFrame(uint8, bit_depth=11)",
      lambda f: rz.RawFrame(np.zeros((4, 4), np.uint8), "mask1"), ValueError,
      "data: a uint8 frame cannot hold 11-bit data"),
    R("rawframe.small", "RawFrame(1x1, mask1)", lambda f: rz.RawFrame(_u16((1, 1)), "mask1"),
      ValueError, "data: frame 1x1 is smaller than one period"),
    R("rawframe.bit_depth-type", "RawFrame(bit_depth='11')",
      lambda f: rz.RawFrame(_u16(), "mask1", bit_depth="11"), TypeError,
      "bit_depth: expected an integer number of bits"),
    R("rawframe.bit_depth-range", "RawFrame(bit_depth=17)",
      lambda f: rz.RawFrame(_u16(), "mask1", bit_depth=17), ValueError,
      "bit_depth: expected 1..16 bits"),
    R("rawframe.pattern", "RawFrame(pattern='mask7')", lambda f: rz.RawFrame(_u16(), "mask7"),
      ValueError, "pattern: 'mask7' is neither a preset"),
    R("rawframe.reference-shape", "RawFrame(reference of another shape)",
      lambda f: rz.RawFrame(_u16(), "mask1", reference=_u16((8, 6))), ValueError,
      "reference: shape (8, 6) differs from data (8, 8)"),
    R("rawframe.reference-range", "RawFrame(reference beyond the bit depth)",
      lambda f: rz.RawFrame(_u16(), "mask1", reference=_u16(value=5000)), ValueError,
      "reference: values span"),
    R("mosaic.ndim", "mosaic(2-D)", lambda f: rz.mosaic(_f64(), "mask1"), ValueError,
      "rgb: expected a 3-D array"),
    R("mosaic.channels", "mosaic(4 channels)", lambda f: rz.mosaic(np.zeros((4, 4, 4)), "mask1"),
      ValueError, "rgb: expected 3 channels in the last axis"),
    R("mosaic.float-range", "mosaic(float 1.5)", lambda f: rz.mosaic(_rgb(value=1.5), "mask1"),
      ValueError, "rgb: float values span"),
    R("mosaic.int-negative", "mosaic(int32 -1)",
      lambda f: rz.mosaic(np.full((4, 4, 3), -1, np.int32), "mask1"), ValueError,
      "rgb: integer values span"),
    R("mosaic.nan", "mosaic(NaN)", lambda f: rz.mosaic(_rgb(value=np.nan), "mask1"),
      ValueError, "rgb: holds 768 NaN or infinite value(s)"),
    R("mosaic.small", "mosaic(1x1)", lambda f: rz.mosaic(_rgb((1, 1)), "mask1"), ValueError,
      "rgb: frame 1x1 is smaller than one period"),
    R("mosaic.dtype", "mosaic(dtype=int32)", lambda f: rz.mosaic(_rgb(), "mask1", dtype=np.int32),
      TypeError, "dtype: expected one of uint8, uint16, float32, float64"),
    R("mosaic.dtype-unknown", "mosaic(dtype='junk')",
      lambda f: rz.mosaic(_rgb(), "mask1", dtype="junk"), TypeError,
      "dtype: expected one of uint8, uint16, float32, float64, got 'junk'"),
    R("mosaic.uint8-bits", "mosaic(dtype=uint8, bit_depth=11)",
      lambda f: rz.mosaic(_rgb(), "mask1", dtype=np.uint8), ValueError,
      "dtype: uint8 cannot hold 11-bit data"),
    R("mosaic.bit_depth", "mosaic(bit_depth=17)", lambda f: rz.mosaic(_rgb(), "mask1", 17),
      ValueError, "bit_depth: expected 1..16 bits"),
    R("mosaic.input_bits", "mosaic(input_bits=0)",
      lambda f: rz.mosaic(_u8img(), "mask1", input_bits=0), ValueError,
      "input_bits: expected 1..8 bits for uint8 input, got 0"),
    R("mosaic.input_bits-type", "mosaic(input_bits='8')",
      lambda f: rz.mosaic(_u8img(), "mask1", input_bits="8"), TypeError,
      "input_bits: expected an integer number of bits"),
    R("mosaic.input_bits-wide", "mosaic(uint16 image, input_bits=17)",
      lambda f: rz.mosaic(np.ones((4, 4, 3), np.uint16), "mask1", input_bits=17), ValueError,
      "input_bits: expected 1..16 bits for uint16 input, got 17"),
    R("mosaic.input_bits-100", "mosaic(uint8 image, input_bits=100): was an all-zero frame",
      lambda f: rz.mosaic(_u8img(), "mask1", input_bits=100), ValueError,
      "input_bits: expected 1..8 bits for uint8 input, got 100"),
    R("mosaic.input_bits-float", "mosaic(float image, input_bits=8)",
      lambda f: rz.mosaic(_rgb(), "mask1", input_bits=8), ValueError,
      "input_bits: applies to integer input only"),
    R("frame.tof-shape", "RawFrame(8x8 data, tof of a 16x16 frame)",
      lambda f: rz.RawFrame(_u16(), "mask1", tof=_sim().tof), ValueError,
      "tof: taps of a 16x16 frame, the data is 8x8"),
    R("frame.tof-sites", "ToFTaps(sites outside the frame)",
      lambda f: _taps_with_sites(1000), ValueError,
      "sites: rows span [1000, 1000], outside the 4x4 frame"),

    # -- reconstruct -----------------------------------------------------------------
    R("reconstruct.ndim-3", "reconstruct(3-D)",
      lambda f: rz.reconstruct(_u16((4, 4, 3)), pattern="mask1"), ValueError,
      "frame: expected a 2-D array, got shape (4, 4, 3)"),
    R("reconstruct.ndim-1", "reconstruct(1-D)",
      lambda f: rz.reconstruct(_u16((16,)), pattern="mask1"), ValueError,
      "frame: expected a 2-D array"),
    R("reconstruct.ndim-0", "reconstruct(scalar)",
      lambda f: rz.reconstruct(np.uint16(3), pattern="mask1"), ValueError,
      "frame: expected a 2-D array, got shape ()"),
    R("reconstruct.empty", "reconstruct(0x4)",
      lambda f: rz.reconstruct(_u16((0, 4)), pattern="mask1"), ValueError,
      "frame: the array is empty"),
    R("reconstruct.small", "reconstruct(3x3, mask2)",
      lambda f: rz.reconstruct(_u16((3, 3)), pattern="mask2"), ValueError,
      "frame: frame 3x3 is smaller than one period (4x4)"),
    R("reconstruct.dtype-int32", "reconstruct(int32)",
      lambda f: rz.reconstruct(np.zeros((4, 4), np.int32), pattern="mask1"), TypeError,
      "frame: dtype int32 is not supported"),
    R("reconstruct.dtype-bool", "reconstruct(bool)",
      lambda f: rz.reconstruct(np.zeros((4, 4), bool), pattern="mask1"), TypeError,
      "frame: dtype bool is not supported"),
    R("reconstruct.dtype-float16", "reconstruct(float16)",
      lambda f: rz.reconstruct(np.zeros((4, 4), np.float16), pattern="mask1"), TypeError,
      "frame: dtype float16 is not supported"),
    R("reconstruct.dtype-big-endian", "reconstruct('>u2')",
      lambda f: rz.reconstruct(np.zeros((4, 4), ">u2"), pattern="mask1"), TypeError,
      "frame: dtype >u2 is not supported"),
    R("reconstruct.dtype-complex", "reconstruct(complex)",
      lambda f: rz.reconstruct(np.zeros((4, 4), complex), pattern="mask1"), TypeError,
      "frame: expected a real numeric array"),
    R("reconstruct.dtype-object", "reconstruct(object)",
      lambda f: rz.reconstruct(np.zeros((4, 4), object), pattern="mask1"), TypeError,
      "frame: expected a real numeric array"),
    R("reconstruct.nan", "reconstruct(NaN)",
      lambda f: rz.reconstruct(_with(np.nan), pattern="mask1"), ValueError,
      "frame: holds 1 NaN or infinite value(s)"),
    R("reconstruct.nan-at-z", "reconstruct(NaN at a Z site)",
      lambda f: rz.reconstruct(_with(np.nan, at=(0, 0)), pattern="mask1"), ValueError,
      "frame: holds 1 NaN or infinite value(s)"),
    R("reconstruct.inf", "reconstruct(inf)",
      lambda f: rz.reconstruct(_with(np.inf), pattern="mask1"), ValueError,
      "frame: holds 1 NaN or infinite value(s)"),
    R("reconstruct.negative", "reconstruct(-1.0)",
      lambda f: rz.reconstruct(_with(-1.0), pattern="mask1"), ValueError,
      "frame: values span [-1.0, 0.0], beyond the 11-bit range"),
    R("reconstruct.above-bit-depth", "reconstruct(4096, bit_depth=12)",
      lambda f: rz.reconstruct(_with(4096, np.uint16), pattern="mask1", bit_depth=12),
      ValueError, "frame: values span [0, 4096], beyond the 12-bit range"),
    R("reconstruct.uint8-bits", "reconstruct(uint8, bit_depth=11)",
      lambda f: rz.reconstruct(np.zeros((4, 4), np.uint8), pattern="mask1"), ValueError,
      "frame: a uint8 frame cannot hold 11-bit data"),
    R("reconstruct.no-pattern", "reconstruct(array) without pattern",
      lambda f: rz.reconstruct(_u16()), TypeError,
      "pattern: required when frame is a plain array"),
    R("reconstruct.pattern-unknown", "reconstruct(pattern='foo')",
      lambda f: rz.reconstruct(_u16(), pattern="foo"), ValueError,
      "pattern: 'foo' is neither a preset"),
    R("reconstruct.pattern-type", "reconstruct(pattern=3)",
      lambda f: rz.reconstruct(_u16(), pattern=3), TypeError,
      "pattern: expected a Pattern, a preset name or a tile string"),
    R("reconstruct.pattern-no-bayer", "reconstruct(pattern='ZR/RG')",
      lambda f: rz.reconstruct(_u16(), pattern="ZR/RG"), ValueError,
      "pattern: tile 'ZR/RG' fits no Bayer phase"),
    R("reconstruct.pattern-no-candidate", "reconstruct(pattern='GZ/ZG')",
      lambda f: rz.reconstruct(_u16(), pattern="GZ/ZG"), ValueError,
      "pattern: the Z site (0, 1) of 'GZ/ZG' has no known pixel of its colour"),
    R("reconstruct.pattern-frame-mismatch", "reconstruct(RawFrame mask1, pattern='mask2')",
      lambda f: rz.reconstruct(_frame(), pattern="mask2"), ValueError,
      "pattern: 'mask2' differs from the frame's pattern 'mask1'"),
    R("reconstruct.bit_depth-frame-mismatch", "reconstruct(RawFrame 11 bits, bit_depth=12)",
      lambda f: rz.reconstruct(_frame(), bit_depth=12), ValueError,
      "bit_depth: 12 differs from the frame's 11"),
    R("reconstruct.bit_depth-0", "reconstruct(bit_depth=0)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", bit_depth=0), ValueError,
      "bit_depth: expected 1..16 bits, got 0"),
    R("reconstruct.bit_depth-17", "reconstruct(bit_depth=17)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", bit_depth=17), ValueError,
      "bit_depth: expected 1..16 bits, got 17"),
    R("reconstruct.bit_depth-float", "reconstruct(bit_depth=11.0)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", bit_depth=11.0), TypeError,
      "bit_depth: expected an integer number of bits"),
    R("reconstruct.bit_depth-bool", "reconstruct(bit_depth=True)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", bit_depth=True), TypeError,
      "bit_depth: expected an integer number of bits"),
    R("reconstruct.method-unknown", "reconstruct(method='bicubic')",
      lambda f: rz.reconstruct(_u16(), "bicubic", pattern="mask1"), ValueError,
      "method: expected one of 'bilinear', 'bi', 'edi_central', 'edi_line', 'sg', 'edi_rows'"),
    R("reconstruct.method-none", "reconstruct(method=None)",
      lambda f: rz.reconstruct(_u16(), None, pattern="mask1"), ValueError,
      "method: expected one of"),
    R("reconstruct.edi_rows-mask1", "reconstruct(method='edi_rows', pattern='mask1')",
      lambda f: rz.reconstruct(_u16(), "edi_rows", pattern="mask1"), ValueError,
      "method: 'edi_rows' needs the pixels two rows above and below"),
    R("reconstruct.precision", "reconstruct(precision='float16')",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", precision="float16"), ValueError,
      "precision: expected one of 'float32', 'float64'"),
    R("reconstruct.sg_mode", "reconstruct(sg_mode='mixed')",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", sg_mode="mixed"), ValueError,
      "sg_mode: expected one of 'auto', 'pure', 'combined'"),
    R("reconstruct.exp", "reconstruct(exp='approx')",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", exp="approx"), ValueError,
      "exp: expected one of 'auto', 'libm', 'fast'"),
    R("reconstruct.out-shape", "reconstruct(out=<array of another shape or dtype>)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", out=np.empty((8, 9), np.uint16)),
      ValueError, "out: expected shape (8, 8) and dtype uint16"),
    R("reconstruct.out-type", "reconstruct(out=[[...]])",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", out=[[0] * 8] * 8), TypeError,
      "out: expected a numpy array"),
    R("reconstruct.out-strided", "reconstruct(out=<strided or read-only view>)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", out=np.empty((8, 16), np.uint16)[:, ::2]),
      ValueError, "out: expected a C-contiguous, writeable array"),
    R("reconstruct.out-overlap", "reconstruct(frame, out=frame)",
      lambda f: (lambda a: rz.reconstruct(a, pattern="mask1", out=a))(_u16()), ValueError,
      "out: overlaps the input frame"),
    R("reconstruct.domain", "reconstruct(domain='lab')",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", domain="lab"), ValueError,
      "domain: expected one of 'intensity', 'colour_difference'"),
    R("reconstruct.workers-0", "reconstruct(workers=0)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", workers=0), ValueError,
      "workers: expected None, -1 or a positive number of threads"),
    R("reconstruct.workers-negative", "reconstruct(workers=-2)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", workers=-2), ValueError,
      "workers: expected None, -1 or a positive number of threads"),
    R("reconstruct.workers-float", "reconstruct(workers=1.5)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", workers=1.5), ValueError,
      "workers: expected None, -1 or a positive number of threads"),
    R("reconstruct.workers-huge", "reconstruct(workers=100000)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", workers=100_000), ValueError,
      "workers: expected at most"),
    R("reconstruct.workers-overflow", "reconstruct(workers=10**12)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", workers=10**12), ValueError,
      "workers: expected at most"),
    R("reconstruct.sigma_floor-0", "reconstruct(sigma_floor=0)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", sigma_floor=0), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("reconstruct.sigma_floor-negative", "reconstruct(sigma_floor=-1e-3)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", sigma_floor=-1e-3), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("reconstruct.sigma_floor-nan", "reconstruct(sigma_floor=nan)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", sigma_floor=np.nan), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("reconstruct.sigma_floor-text", "reconstruct(sigma_floor='small')",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", sigma_floor="small"), TypeError,
      "sigma_floor: expected a number"),
    R("reconstruct.sigma_rel-negative", "reconstruct(sigma_rel=-1)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", sigma_rel=-1), ValueError,
      "sigma_rel: expected a finite number >= 0 and <= 10"),
    R("reconstruct.sigma_rel-nan", "reconstruct(sigma_rel=nan)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", sigma_rel=np.nan), ValueError,
      "sigma_rel: expected a finite number >= 0 and <= 10"),
    R("reconstruct.sigma_rel-none", "reconstruct(sigma_rel=None)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", sigma_rel=None), TypeError,
      "sigma_rel: expected a number, got None"),
    R("reconstruct.edge_ratio-0", "reconstruct(edge_ratio=0)",
      lambda f: rz.reconstruct(_u16((12, 8)), "edi_rows", pattern="rows", edge_ratio=0),
      ValueError, "edge_ratio: expected a finite number > 0"),
    R("reconstruct.edge_ratio-inf", "reconstruct(edge_ratio=inf)",
      lambda f: rz.reconstruct(_u16((12, 8)), "edi_rows", pattern="rows", edge_ratio=np.inf),
      ValueError, "edge_ratio: expected a finite number > 0"),
    R("reconstruct.clip_level-nan", "reconstruct(clip_level=nan)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", clip_level=np.nan), ValueError,
      "clip_level: expected a finite number > 0"),
    R("reconstruct.clip_level-negative", "reconstruct(clip_level=-1)",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", clip_level=-1), ValueError,
      "clip_level: expected a finite number > 0"),
    R("reconstruct.clip_level-text", "reconstruct(clip_level='high')",
      lambda f: rz.reconstruct(_u16(), pattern="mask1", clip_level="high"), TypeError,
      "clip_level: expected a positive number, None or 'auto'"),

    # -- demosaic --------------------------------------------------------------------
    R("demosaic.ndim", "demosaic(3-D)", lambda f: demosaic(np.zeros((4, 4, 3))), ValueError,
      "cfa: expected a 2-D array"),
    R("demosaic.small", "demosaic(1x5)", lambda f: demosaic(np.zeros((1, 5))), ValueError,
      "cfa: expected at least one 2x2 Bayer period"),
    R("demosaic.nan", "demosaic(NaN)", lambda f: demosaic(_with(np.nan)), ValueError,
      "cfa: holds 1 NaN or infinite value(s)"),
    R("demosaic.complex", "demosaic(complex)", lambda f: demosaic(np.zeros((4, 4), complex)),
      TypeError, "cfa: expected a real numeric array"),
    R("demosaic.phase", "demosaic(phase='ZZZZ')", lambda f: demosaic(_f64(), "ZZZZ"),
      ValueError, "phase: expected one of GRBG, RGGB, BGGR, GBRG"),
    R("demosaic.phase-rgbz", "demosaic(phase=mask1())", lambda f: demosaic(_f64(), rz.mask1()),
      ValueError, "phase: expected a plain 2x2 Bayer pattern"),
    R("demosaic.method", "demosaic(method='ahd')", lambda f: demosaic(_f64(), method="ahd"),
      ValueError, "method: expected one of 'malvar2004', 'menon2007', 'bilinear'"),
    R("demosaic.mode", "demosaic(mode='wrap')", lambda f: demosaic(_f64(), mode="wrap"),
      ValueError, "mode: expected one of 'reflect', 'period'"),
    R("demosaic.dtype", "demosaic(dtype=int32)", lambda f: demosaic(_f64(), dtype=np.int32),
      TypeError, "dtype: expected float32 or float64"),
    R("demosaic.dtype-unknown", "demosaic(dtype='junk')", lambda f: demosaic(_f64(), dtype="junk"),
      TypeError, "dtype: expected float32 or float64"),
    R("demosaic.workers", "demosaic(workers=0)", lambda f: demosaic(_f64(), workers=0),
      ValueError, "workers: expected None, -1 or a positive number of threads"),

    # -- metrics ---------------------------------------------------------------------
    R("metrics.cfa_psnr-range-neither", "cfa_psnr(ref, test) without data_range/bit_depth",
      lambda f: metrics.cfa_psnr(_f64(), _f64()), ValueError,
      "data_range: pass exactly one of data_range"),
    R("metrics.cfa_psnr-range-both", "cfa_psnr(data_range=1, bit_depth=1)",
      lambda f: metrics.cfa_psnr(_f64(), _f64(), data_range=1, bit_depth=1), ValueError,
      "data_range: pass exactly one of data_range"),
    R("metrics.cfa_psnr-shape", "cfa_psnr(8x8, 4x8)",
      lambda f: metrics.cfa_psnr(_f64(), _f64((4, 8)), bit_depth=8), ValueError,
      "test: shape (4, 8) differs from reference shape (8, 8)"),
    R("metrics.cfa_psnr-ndim", "cfa_psnr(1-D)",
      lambda f: metrics.cfa_psnr(np.zeros(4), np.zeros(4), bit_depth=8), ValueError,
      "reference: expected a 2-D or 3-D array"),
    R("metrics.cfa_psnr-nan", "cfa_psnr(NaN)",
      lambda f: metrics.cfa_psnr(_with(np.nan), _f64(), bit_depth=8), ValueError,
      "reference: holds 1 NaN or infinite value(s)"),
    R("metrics.cfa_psnr-mask-dtype", "cfa_psnr(mask of ints)",
      lambda f: metrics.cfa_psnr(_f64(), _f64(), np.ones((8, 8), int), bit_depth=8), TypeError,
      "mask: expected a boolean array"),
    R("metrics.cfa_psnr-mask-shape", "cfa_psnr(mask 4x8)",
      lambda f: metrics.cfa_psnr(_f64(), _f64(), np.ones((4, 8), bool), bit_depth=8),
      ValueError, "mask: shape (4, 8) matches neither"),
    R("metrics.cfa_psnr-mask-empty", "cfa_psnr(all-False mask)",
      lambda f: metrics.cfa_psnr(_f64(), _f64(), np.zeros((8, 8), bool), bit_depth=8),
      ValueError, "mask: selects no pixel"),
    R("metrics.cfa_psnr-bit_depth", "cfa_psnr(bit_depth=33)",
      lambda f: metrics.cfa_psnr(_f64(), _f64(), bit_depth=33), ValueError,
      "bit_depth: expected 1..32 bits"),
    R("metrics.cfa_psnr-data_range", "cfa_psnr(data_range=0)",
      lambda f: metrics.cfa_psnr(_f64(), _f64(), data_range=0), ValueError,
      "data_range: expected a finite number > 0"),
    R("metrics.cfa_psnr-data_range-type", "cfa_psnr(data_range='1')",
      lambda f: metrics.cfa_psnr(_f64(), _f64(), data_range="1"), TypeError,
      "data_range: expected a number"),
    R("metrics.cfa_psnr-int-range", "cfa_psnr(uint16 300, bit_depth=8)",
      lambda f: metrics.cfa_psnr(_u16(value=300), _u16(value=300), bit_depth=8), ValueError,
      "bit_depth: reference holds integer values in [300, 300], outside [0, 255]"),
    R("metrics.cpsnr-ndim", "cpsnr(2-D)", lambda f: metrics.cpsnr(_f64(), _f64()), ValueError,
      "reference: expected a 3-D array"),
    R("metrics.cpsnr-channels", "cpsnr(4 channels)",
      lambda f: metrics.cpsnr(np.zeros((4, 4, 4)), np.zeros((4, 4, 4))), ValueError,
      "reference: expected a colour image of shape (rows, cols, 3)"),
    R("metrics.cpsnr-crop-large", "cpsnr(16x16, crop=8)",
      lambda f: metrics.cpsnr(_u8img(), _u8img(), crop=8), ValueError,
      "crop: crop=8 leaves 0 x 0 pixels"),
    R("metrics.cpsnr-crop-negative", "cpsnr(crop=-1)",
      lambda f: metrics.cpsnr(_u8img(), _u8img(), crop=-1), ValueError,
      "crop: expected an integer >= 0"),
    R("metrics.cpsnr-crop-float", "cpsnr(crop=1.0)",
      lambda f: metrics.cpsnr(_u8img(), _u8img(), crop=1.0), TypeError,
      "crop: expected an integer"),
    R("metrics.cpsnr-int-range", "cpsnr(uint16 300, data_range=255)",
      lambda f: metrics.cpsnr(np.full((4, 4, 3), 300, np.uint16),
                              np.full((4, 4, 3), 300, np.uint16)), ValueError,
      "data_range: reference holds integer values"),
    R("metrics.cpsnr_pooled-empty", "cpsnr_pooled([], [])",
      lambda f: metrics.cpsnr_pooled([], []), ValueError, "references: the sequence is empty"),
    R("metrics.cpsnr_pooled-length", "cpsnr_pooled([a], [a, a])",
      lambda f: metrics.cpsnr_pooled([_u8img()], [_u8img()] * 2), ValueError,
      "tests: 2 images for 1 references"),
    R("metrics.cpsnr_pooled-array", "cpsnr_pooled(one 3-D array)",
      lambda f: metrics.cpsnr_pooled(_u8img(), _u8img()), TypeError,
      "references: expected a sequence of (rows, cols, 3) images"),
    R("metrics.cpsnr_pooled-generator", "cpsnr_pooled(generator)",
      lambda f: metrics.cpsnr_pooled((x for x in [_u8img()]), [_u8img()]), TypeError,
      "references: expected a sequence of images"),
    R("metrics.ssim-small", "ssim(5x5)", lambda f: metrics.ssim(_f64((5, 5)), _f64((5, 5))),
      ValueError, "crop: crop=0 leaves 5 x 5 pixels"),
    R("metrics.ssim-win-even", "ssim(win_size=4)",
      lambda f: metrics.ssim(_u8img(), _u8img(), win_size=4), ValueError,
      "win_size: expected an odd window size"),
    R("metrics.ssim-sigma", "ssim(sigma=0)", lambda f: metrics.ssim(_u8img(), _u8img(), sigma=0),
      ValueError, "sigma: expected a finite number > 0"),
    R("metrics.ssim-channel_axis-none", "ssim(3-D, channel_axis=None)",
      lambda f: metrics.ssim(_u8img(), _u8img(), channel_axis=None), ValueError,
      "channel_axis: a 3-D image needs the axis of its channels"),
    R("metrics.ssim-channel_axis-range", "ssim(channel_axis=5)",
      lambda f: metrics.ssim(_u8img(), _u8img(), channel_axis=5), ValueError,
      "channel_axis: 5 is out of range"),
    R("metrics.ssim-channel_axis-type", "ssim(channel_axis='x')",
      lambda f: metrics.ssim(_u8img(), _u8img(), channel_axis="x"), TypeError,
      "channel_axis: expected an integer or None"),
    # SSIM's constants (0.01 L)**2 leave the doubles beyond these bounds (B4, fixed)
    R("metrics.ssim-data_range-huge", "ssim(data_range=1e300)",
      lambda f: metrics.ssim(_f64((16, 16), 1.0), _f64((16, 16)), data_range=1e300),
      ValueError, "data_range: expected a number in [1e-100, 1e+100] for SSIM"),
    R("metrics.ssim-data_range-tiny", "ssim(data_range=1e-300)",
      lambda f: metrics.ssim(_f64((16, 16)), _f64((16, 16)), data_range=1e-300),
      ValueError, "data_range: expected a number in [1e-100, 1e+100] for SSIM"),
    R("metrics.ms_ssim-small", "ms_ssim(16x16)",
      lambda f: metrics.ms_ssim(_u8img(), _u8img()), ValueError,
      "reference: MS-SSIM with 5 scales needs at least 161 x 161 pixels"),
    R("metrics.ms_ssim-data_range-huge", "ms_ssim(data_range=1e300)",
      lambda f: metrics.ms_ssim(_f64((161, 161), 1.0), _f64((161, 161)), data_range=1e300),
      ValueError, "data_range: expected a number in [1e-100, 1e+100] for SSIM"),
    R("metrics.ms_ssim-weights-empty", "ms_ssim(weights=[])",
      lambda f: metrics.ms_ssim(_u8img(), _u8img(), weights=[]), ValueError,
      "weights: expected a non-empty 1-D sequence"),
    R("metrics.ms_ssim-weights-text", "ms_ssim(weights='abc')",
      lambda f: metrics.ms_ssim(_u8img(), _u8img(), weights="abc"), TypeError,
      "weights: expected a sequence of numbers"),
    R("metrics.ms_ssim-weights-negative", "ms_ssim(weights=[-1])",
      lambda f: metrics.ms_ssim(_u8img(), _u8img(), weights=[-1]), ValueError,
      "weights: expected finite exponents >= 0"),
    R("metrics.zipper-small", "zipper(2x2)",
      lambda f: metrics.zipper(np.zeros((2, 2, 3)), np.zeros((2, 2, 3))), ValueError,
      "crop: crop=0 leaves 2 x 2 pixels"),
    R("metrics.zipper-delta", "zipper(delta=-1)",
      lambda f: metrics.zipper(_u8img(), _u8img(), delta=-1), ValueError,
      "delta: expected a finite number >= 0"),
    R("metrics.zipper-input", "zipper(input='xyz')",
      lambda f: metrics.zipper(_u8img(), _u8img(), input="xyz"), ValueError,
      "input: expected one of 'srgb8', 'srgb16', 'srgb01', 'lab'"),
    R("metrics.zipper-int-range", "zipper(uint16 300, input='srgb8')",
      lambda f: metrics.zipper(np.full((4, 4, 3), 300, np.uint16),
                               np.full((4, 4, 3), 300, np.uint16)), ValueError,
      "input: reference holds integer values"),
    R("metrics.delta_e_map-ndim", "delta_e_map(2-D)",
      lambda f: metrics.delta_e_map(_f64(), _f64()), ValueError,
      "reference: expected a 3-D array"),
    R("metrics.all_metrics-small", "all_metrics(16x16)",
      lambda f: metrics.all_metrics(_u8img(), _u8img()), ValueError,
      "reference: MS-SSIM with 5 scales needs"),

    # -- scene -----------------------------------------------------------------------
    R("scene.ndim", "Scene(2-D)", lambda f: scene.Scene(_f64()), ValueError,
      "image: expected a 3-D array"),
    R("scene.channels", "Scene(4 channels, no wavelengths)",
      lambda f: scene.Scene(np.zeros((4, 4, 4))), ValueError,
      "image: an RGB scene needs 3 channels"),
    R("scene.negative", "Scene(-1.0)", lambda f: scene.Scene(_rgb(value=-1.0)), ValueError,
      "image: holds negative values"),
    R("scene.nan", "Scene(NaN)", lambda f: scene.Scene(_rgb(value=np.nan)), ValueError,
      "image: holds 768 NaN or infinite value(s)"),
    R("scene.int-negative", "Scene(int16 -1)",
      lambda f: scene.Scene(np.full((4, 4, 3), -1, np.int16)), ValueError,
      "image: signed integer data holds negative values"),
    R("scene.depth-shape", "Scene(depth of another shape)",
      lambda f: scene.Scene(_rgb(), depth=_f64((4, 4), 1.0)), ValueError,
      "depth: shape (4, 4) differs from the image's (16, 16)"),
    R("scene.depth-negative", "Scene(depth -1)",
      lambda f: scene.Scene(_rgb(), depth=_f64((16, 16), -1.0)), ValueError,
      "depth: holds negative distances"),
    R("scene.depth-zero", "Scene(depth 0 at a valid pixel)",
      lambda f: scene.Scene(_rgb(), depth=_f64((16, 16))), ValueError,
      "depth: a valid pixel is at distance 0 m"),
    R("scene.depth-nan", "Scene(depth NaN)",
      lambda f: scene.Scene(_rgb(), depth=_f64((16, 16), np.nan)), ValueError,
      "depth: holds 256 NaN or infinite value(s)"),
    R("scene.depth_valid-alone", "Scene(depth_valid without depth)",
      lambda f: scene.Scene(_rgb(), depth_valid=np.ones((16, 16), bool)), ValueError,
      "depth_valid: given without a depth map"),
    R("scene.depth_valid-dtype", "Scene(depth_valid of ints)",
      lambda f: scene.Scene(_rgb(), depth=_f64((16, 16), 1.0),
                            depth_valid=np.ones((16, 16), int)), TypeError,
      "depth_valid: expected a bool array"),
    R("scene.ir-range", "Scene(ir_reflectance 2)",
      lambda f: scene.Scene(_rgb(), ir_reflectance=_f64((16, 16), 2.0)), ValueError,
      "ir_reflectance: values span [2.0, 2.0]"),
    R("scene.wavelengths-count", "Scene(5 bands, 2 wavelengths)",
      lambda f: scene.Scene(np.ones((4, 4, 5)), wavelengths=[400, 500]), ValueError,
      "wavelengths: expected 5 band centres"),
    R("scene.wavelengths-range", "Scene(wavelength 100 nm)",
      lambda f: scene.Scene(np.ones((4, 4, 2)), wavelengths=[100, 500]), ValueError,
      "wavelengths: expected finite values in 300..1100 nm"),
    R("scene.wavelengths-order", "Scene(decreasing wavelengths)",
      lambda f: scene.Scene(np.ones((4, 4, 2)), wavelengths=[500, 400]), ValueError,
      "wavelengths: expected strictly increasing band centres"),
    R("scene.from_rgb-encoding", "Scene.from_rgb(encoding='xyz')",
      lambda f: scene.Scene.from_rgb(_rgb(), encoding="xyz"), ValueError,
      "encoding: expected one of 'auto', 'srgb', 'linear'"),
    R("scene.from_rgb-srgb-range", "Scene.from_rgb(1.5, encoding='srgb')",
      lambda f: scene.Scene.from_rgb(_rgb(value=1.5), encoding="srgb"), ValueError,
      "image: sRGB-encoded floats must lie in [0, 1]"),
    R("scene.from_rgb-depth-and-disparity", "Scene.from_rgb(depth=..., disparity=...)",
      lambda f: scene.Scene.from_rgb(_rgb(), depth=_f64((16, 16), 1.0),
                                     disparity=_f64((16, 16), 1.0)), ValueError,
      "disparity: give either depth or disparity, not both"),
    R("scene.from_rgb-disparity-no-focal", "Scene.from_rgb(disparity without focal_px)",
      lambda f: scene.Scene.from_rgb(_rgb(), disparity=_f64((16, 16), 1.0)), ValueError,
      "disparity: focal_px and baseline_m are needed"),
    R("scene.from_spectral-no-wavelengths", "Scene.from_spectral(cube, None)",
      lambda f: scene.Scene.from_spectral(np.ones((4, 4, 3)), None), ValueError,
      "wavelengths: a spectral scene needs its band centres"),
    R("scene.disparity-all-invalid", "disparity_to_depth(all 0)",
      lambda f: scene.disparity_to_depth(_f64(), 100, 0.1), ValueError,
      "disparity: every pixel is marked invalid"),
    R("scene.disparity-focal", "disparity_to_depth(focal_px=0)",
      lambda f: scene.disparity_to_depth(_f64(value=1.0), 0, 0.1), ValueError,
      "focal_px: expected a finite number > 0"),
    R("scene.disparity-negative", "disparity_to_depth(-1, invalid=None)",
      lambda f: scene.disparity_to_depth(_f64(value=-1.0), 100, 0.1, invalid=None), ValueError,
      "disparity: 64 known pixel(s) have disparity + offset <= 0"),
    R("scene.load-missing", "load_scene('missing.png')",
      lambda f: scene.load_scene(f / "missing.png"), FileNotFoundError, "path: "),
    R("scene.load-unknown", "load_scene('notes.xyz')",
      lambda f: scene.load_scene(f / "notes.xyz"), ValueError,
      "path: cannot tell what kind of scene notes.xyz holds"),
    R("scene.load-corrupt-image", "load_scene(corrupt .png)",
      lambda f: scene.load_scene(f / "corrupt.png"), ValueError, "path: cannot read "),
    R("scene.load-corrupt-mat", "load_scene(corrupt .mat)",
      lambda f: scene.load_scene(f / "corrupt.mat"), ValueError, "path: cannot read "),
    R("scene.load-empty-folder", "load_scene(empty folder)",
      lambda f: scene.load_scene(f / "empty"), FileNotFoundError,
      "path: no PNG band files in folder"),
    R("scene.load_rgbd-missing", "load_rgbd('missing')",
      lambda f: scene.load_rgbd(f / "missing"), FileNotFoundError, "folder: "),
    R("scene.load_rgbd-incomplete", "load_rgbd(folder without rgb.png, disp1.png, dmin.txt)",
      lambda f: scene.load_rgbd(f / "rgbd_incomplete"), FileNotFoundError, "folder: "),
    R("scene.load-grey", "load_scene(grey .png)",
      lambda f: scene.load_scene(f / "grey.png"), ValueError,
      "path: {d}/grey.png is a grey image (16x16); a colour sensor needs colour: pass "
      "grey=True"),
    R("scene.load-fifo", "load_scene(FIFO named fifo.tif)",
      lambda f: scene.load_scene(f / "fifo.tif"), ValueError,
      "path: {d}/fifo.tif is a FIFO (named pipe), not a regular file"),

    # -- sensor ----------------------------------------------------------------------
    R("sensor.colour-full_well", "ColourSensor(full_well=0)",
      lambda f: sensor.ColourSensor(full_well=0), ValueError,
      "ColourSensor.full_well: expected a number > 0, got 0"),
    R("sensor.colour-bit_depth", "ColourSensor(bit_depth=17)",
      lambda f: sensor.ColourSensor(bit_depth=17), ValueError,
      "ColourSensor.bit_depth: expected 1..16 bits"),
    R("sensor.colour-black_level", "ColourSensor(black_level=2047)",
      lambda f: sensor.ColourSensor(black_level=2047), ValueError,
      "ColourSensor.black_level: expected a finite number >= 0 and < 2047"),
    R("sensor.colour-qe", "ColourSensor(qe=(1, 2))", lambda f: sensor.ColourSensor(qe=(1, 2)),
      ValueError, "ColourSensor.qe: expected 3 quantum efficiencies in (0, 1]"),
    R("sensor.colour-exposure-negative", "ColourSensor(exposure=-1)",
      lambda f: sensor.ColourSensor(exposure=-1), ValueError,
      "ColourSensor.exposure: expected a finite number > 0 and <= 3600"),
    R("sensor.colour-exposure-text", "ColourSensor(exposure='long')",
      lambda f: sensor.ColourSensor(exposure="long"), ValueError,
      "ColourSensor.exposure: expected seconds > 0 or 'auto'"),
    R("sensor.colour-exposure-nan", "ColourSensor(exposure=nan)",
      lambda f: sensor.ColourSensor(exposure=np.nan), ValueError,
      "ColourSensor.exposure: expected a finite number"),
    R("sensor.colour-prnu", "ColourSensor(prnu=1)", lambda f: sensor.ColourSensor(prnu=1),
      ValueError, "ColourSensor.prnu: expected a finite number >= 0 and < 1"),
    R("sensor.colour-flag", "ColourSensor(shot_noise=1)",
      lambda f: sensor.ColourSensor(shot_noise=1), TypeError,
      "ColourSensor.shot_noise: expected True or False"),
    R("sensor.colour-fpn_seed", "ColourSensor(fpn_seed=-1)",
      lambda f: sensor.ColourSensor(fpn_seed=-1), ValueError,
      "ColourSensor.fpn_seed: expected an integer >= 0"),
    R("sensor.colour-read_noise", "ColourSensor(read_noise=inf)",
      lambda f: sensor.ColourSensor(read_noise=np.inf), ValueError,
      "ColourSensor.read_noise: expected a finite number"),
    R("sensor.colour-pitch-type", "ColourSensor(pixel_pitch_um='a')",
      lambda f: sensor.ColourSensor(pixel_pitch_um="a"), TypeError,
      "ColourSensor.pixel_pitch_um: expected a number"),
    R("sensor.colour-sensitivities-shape", "ColourSensor(sensitivities=([1], [1]))",
      lambda f: sensor.ColourSensor(sensitivities=([1], [1])), ValueError,
      "ColourSensor.sensitivities: expected wavelengths (N,) and values (N, 3)"),
    R("sensor.colour-illuminant-type", "ColourSensor(illuminant=5)",
      lambda f: sensor.ColourSensor(illuminant=5), TypeError,
      "ColourSensor.illuminant: expected a colour-science dataset name"),
    R("sensor.colour-sensitivities-name", "simulate(spectral scene, sensitivities='nope')",
      lambda f: sensor.simulate(scene.Scene(np.ones((4, 4, 5)),
                                            wavelengths=[400, 450, 500, 550, 600]),
                                "mask1", sensor.ColourSensor(sensitivities="nope")),
      ValueError, "ColourSensor.sensitivities: 'nope' is not in colour-science's"),
    R("sensor.tof-frequencies-empty", "ToFSensor(frequencies=())",
      lambda f: sensor.ToFSensor(frequencies=()), ValueError,
      "ToFSensor.frequencies: expected 1 or more frequencies in [100 kHz, 1 GHz]"),
    R("sensor.tof-frequencies-range", "ToFSensor(frequencies=(1e3,))",
      lambda f: sensor.ToFSensor(frequencies=(1e3,)), ValueError,
      "ToFSensor.frequencies: expected 1 or more frequencies in [100 kHz, 1 GHz]"),
    R("sensor.tof-frequencies-repeated", "ToFSensor(frequencies=(80e6, 80e6))",
      lambda f: sensor.ToFSensor(frequencies=(80e6, 80e6)), ValueError,
      "ToFSensor.frequencies: repeated frequency"),
    R("sensor.tof-frequencies-type", "ToFSensor(frequencies='abc')",
      lambda f: sensor.ToFSensor(frequencies="abc"), TypeError,
      "ToFSensor.frequencies: expected numbers in Hz"),
    R("sensor.tof-z_block", "ToFSensor(z_block=3)", lambda f: sensor.ToFSensor(z_block=3),
      ValueError, "ToFSensor.z_block: expected None, 1 or 2"),
    R("sensor.tof-fov", "ToFSensor(fov_deg=(0, 45))",
      lambda f: sensor.ToFSensor(fov_deg=(0, 45)), ValueError,
      "ToFSensor.fov_deg: expected two angles in (0, 180) degrees"),
    R("sensor.tof-contrast", "ToFSensor(modulation_contrast=0)",
      lambda f: sensor.ToFSensor(modulation_contrast=0), ValueError,
      "ToFSensor.modulation_contrast: expected a finite number > 0 and <= 1"),
    R("sensor.tof-wavelength", "ToFSensor(wavelength_nm=500)",
      lambda f: sensor.ToFSensor(wavelength_nm=500), ValueError,
      "ToFSensor.wavelength_nm: expected a finite number >= 700 and <= 1700"),
    R("sensor.tof-contrast-count", "ToFSensor(modulation_contrast=(0.8, 0.8))",
      lambda f: sensor.ToFSensor(modulation_contrast=(0.8, 0.8)), ValueError,
      "ToFSensor.modulation_contrast: expected one number or one per frequency (3), got 2"),
    R("sensor.tof-harmonics-order", "ToFSensor(harmonics=((1, 0.1, 0),))",
      lambda f: sensor.ToFSensor(harmonics=((1, 0.1, 0),)), ValueError,
      "ToFSensor.harmonics order: expected an integer >= 2 and <= 64"),
    R("sensor.tof-harmonics-amplitude", "ToFSensor(harmonics=((3, 2.0, 0),))",
      lambda f: sensor.ToFSensor(harmonics=((3, 2.0, 0),)), ValueError,
      "ToFSensor.harmonics amplitude: expected a finite number >= 0 and <= 1"),
    R("sensor.tof-harmonics-type", "ToFSensor(harmonics=3)",
      lambda f: sensor.ToFSensor(harmonics=3), TypeError,
      "ToFSensor.harmonics: expected a sequence of (order, amplitude, phase) triples"),
    R("sensor.tof-tap_contrast", "ToFSensor(tap_contrast=(1, 1, 1))",
      lambda f: sensor.ToFSensor(tap_contrast=(1, 1, 1)), ValueError,
      "ToFSensor.tap_contrast: expected 4 numbers (one per tap), got 3"),
    R("sensor.tof-delay_fpn", "ToFSensor(delay_fpn_ps=-1)",
      lambda f: sensor.ToFSensor(delay_fpn_ps=-1), ValueError,
      "ToFSensor.delay_fpn_ps: expected a finite number >= 0"),
    R("sensor.tof-multipath", "ToFSensor(multipath=(0.5,))",
      lambda f: sensor.ToFSensor(multipath=(0.5,)), TypeError,
      "ToFSensor.multipath: expected None or (relative_amplitude, extra_path_m)"),
    R("sensor.tof-ambient_suppression", "ToFSensor(ambient_suppression=1)",
      lambda f: sensor.ToFSensor(ambient_suppression=1), ValueError,
      "ToFSensor.ambient_suppression: expected a finite number >= 0 and < 1"),
    R("sensor.tof-duty_cycle", "ToFSensor(duty_cycle=0)",
      lambda f: sensor.ToFSensor(duty_cycle=0), ValueError,
      "ToFSensor.duty_cycle: expected a finite number > 0 and <= 1"),
    R("sensor.optics-f_number", "Optics(f_number=0)", lambda f: sensor.Optics(f_number=0),
      ValueError, "Optics.f_number: expected a finite number >= 0.5 and <= 64"),
    R("sensor.optics-olpf", "Optics(olpf=3)", lambda f: sensor.Optics(olpf=3), ValueError,
      "Optics.olpf: expected a finite number >= 0 and <= 2"),
    R("sensor.optics-defocus", "Optics(defocus_um=-1)", lambda f: sensor.Optics(defocus_um=-1),
      ValueError, "Optics.defocus_um: expected a finite number >= 0 and <= 1000"),
    R("sensor.optics-fill_factor", "Optics(fill_factor=0)",
      lambda f: sensor.Optics(fill_factor=0), ValueError,
      "Optics.fill_factor: expected a finite number > 0 and <= 1"),
    R("sensor.optics-bands", "Optics(bands_nm=((500, 600),))",
      lambda f: sensor.Optics(bands_nm=((500, 600),)), ValueError,
      "Optics.bands_nm: expected 3 bands (R, G, B), got 1"),
    R("sensor.optics-band-order", "Optics(bands_nm=((600, 500), ...))",
      lambda f: sensor.Optics(bands_nm=((600, 500), (500, 580), (420, 510))), ValueError,
      "Optics.bands_nm: expected a wavelength or a (low, high) band within 200..2000 nm"),
    R("sensor.optics-psf-wavelength", "Optics().psf(100 nm)",
      lambda f: sensor.Optics().psf(100.0, pixel_pitch_um=2.8), ValueError,
      "wavelength_nm: expected a wavelength or a (low, high) band"),
    R("sensor.apply_optics-type", "apply_optics(image, optics='f/2')",
      lambda f: sensor.apply_optics(_rgb(), "f/2", pixel_pitch_um=2.8), TypeError,
      "optics: expected an Optics, got str"),
    R("sensor.simulate-optics-type", "simulate(optics='f/2')",
      lambda f: sensor.simulate(_rgb(), "mask1", optics="f/2"), TypeError,
      "optics: expected an Optics or None, got str"),
    R("sensor.taps-shape", "ToFTaps(taps of shape (3, 4))",
      lambda f: sensor.ToFTaps(np.zeros((3, 4)), [1], (np.zeros(0), np.zeros(0)), 1, 11,
                               np.zeros(0), np.zeros(0, bool), np.zeros(0, bool),
                               sensor.ToFSensor(), (4, 4)), ValueError,
      "taps: expected shape (F, 4, n_sites)"),
    R("sensor.simulate-seed-negative", "simulate(seed=-1)",
      lambda f: sensor.simulate(_rgb(), "mask1", seed=-1), ValueError,
      "seed: expected an integer >= 0"),
    R("sensor.simulate-seed-float", "simulate(seed=1.5)",
      lambda f: sensor.simulate(_rgb(), "mask1", seed=1.5), ValueError,
      "seed: expected an integer >= 0"),
    R("sensor.simulate-scene-type", "simulate(scene=5)", lambda f: sensor.simulate(5, "mask1"),
      TypeError, "scene: expected a Scene, an image array or a path"),
    R("sensor.simulate-scene-missing", "simulate('missing.png')",
      lambda f: sensor.simulate(f / "missing.png", "mask1"), FileNotFoundError, "path: "),
    R("sensor.simulate-colour_sensor-type", "simulate(colour_sensor=ToFSensor())",
      lambda f: sensor.simulate(_rgb(), "mask1", sensor.ToFSensor()), TypeError,
      "colour_sensor: expected a ColourSensor"),
    R("sensor.simulate-tof_sensor-type", "simulate(tof_sensor=ColourSensor())",
      lambda f: sensor.simulate(_rgb(), "mask1", tof_sensor=sensor.ColourSensor()), TypeError,
      "tof_sensor: expected a ToFSensor"),
    R("sensor.simulate-black-scene", "simulate(black scene, auto exposure)",
      lambda f: sensor.simulate(_rgb(value=0.0), "mask1"), ValueError,
      "scene: the 99th percentile of the signal is 0"),
    R("sensor.simulate-small", "simulate(1x1 scene)",
      lambda f: sensor.simulate(_rgb((1, 1)), "mask1"), ValueError,
      "scene: frame 1x1 is smaller than one period"),
    R("sensor.simulate-no-bayer", "simulate(pattern='ZR/RG')",
      lambda f: sensor.simulate(_rgb(), "ZR/RG"), ValueError,
      "pattern: 'ZR/RG' fits no Bayer phase"),
    R("sensor.simulate-pitch-mismatch", "simulate(tof_sensor pitch 5 um, colour 2.8 um)",
      lambda f: sensor.simulate(scene.Scene(_rgb(), depth=_f64((16, 16), 1.0)), "mask1",
                                tof_sensor=sensor.ToFSensor(pixel_pitch_um=5)), ValueError,
      "tof_sensor.pixel_pitch_um: 5.0 um differs"),
    R("sensor.simulate_tof-no-depth", "simulate_tof(scene without depth)",
      lambda f: sensor.simulate_tof(scene.Scene(_rgb()), "mask1"), ValueError,
      "scene: has no depth map"),
    R("sensor.simulate_tof-no-z", "simulate_tof(pattern='bayer')",
      lambda f: sensor.simulate_tof(scene.Scene(_rgb(), depth=_f64((16, 16), 1.0)), "bayer"),
      ValueError, "pattern: 'bayer_grbg' has no Z site"),
    R("sensor.simulate_tof-block", "simulate_tof(mask1, ToFSensor(z_block=2))",
      lambda f: sensor.simulate_tof(scene.Scene(_rgb(), depth=_f64((16, 16), 1.0)), "mask1",
                                    sensor.ToFSensor(z_block=2)), ValueError,
      "ToFSensor.z_block: 2 needs Z sites in aligned 2x2 squares"),
    R("sensor.simulate_colour-seed", "simulate_colour(seed='a')",
      lambda f: sensor.simulate_colour(_rgb(), seed="a"), ValueError,
      "seed: expected an integer >= 0"),

    # -- rawio -----------------------------------------------------------------------
    R("rawio.read_raw-no-shape", "read_raw(headerless, no shape)",
      lambda f: rawio.read_raw(f / "bayer.raw", phase="GRBG", black_level=0, bit_depth_in=10),
      ValueError, "shape: the headerless file bayer.raw needs shape=(rows, cols)"),
    R("rawio.read_raw-size", "read_raw(headerless, wrong shape)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 5), phase="GRBG", black_level=0,
                               bit_depth_in=10), ValueError,
      "shape: bayer.raw holds 32 bytes, but 4x5 uint16 pixels need 40"),
    R("rawio.read_raw-shape-negative", "read_raw(shape=(-4, -4))",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(-4, -4), phase="GRBG", black_level=0,
                               bit_depth_in=10), ValueError,
      "shape: expected positive (rows, cols)"),
    R("rawio.read_raw-no-phase", "read_raw(headerless, no phase)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), black_level=0, bit_depth_in=10),
      ValueError, "phase: bayer.raw does not record its CFA phase"),
    R("rawio.read_raw-phase", "read_raw(phase='XXXX')",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="XXXX", black_level=0,
                               bit_depth_in=10), ValueError, "phase: expected one of"),
    R("rawio.read_raw-no-black", "read_raw(headerless, no black_level)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", bit_depth_in=10),
      ValueError, "black_level: bayer.raw does not record its black level"),
    R("rawio.read_raw-no-white", "read_raw(headerless, no white_level)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0),
      ValueError, "white_level: bayer.raw does not record its white level"),
    R("rawio.read_raw-white-below-black", "read_raw(black_level=100, white_level=50)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=100,
                               white_level=50), ValueError, "white_level: "),
    R("rawio.read_raw-black-nan", "read_raw(black_level=nan)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG",
                               black_level=np.nan, white_level=50), ValueError,
      "black_level: expected finite non-negative values"),
    R("rawio.read_raw-black-text", "read_raw(black_level='a')",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG",
                               black_level="a", white_level=50), TypeError,
      "black_level: expected a number or four numbers"),
    R("rawio.read_raw-black-count", "read_raw(black_level=[1, 2, 3])",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG",
                               black_level=[1, 2, 3], white_level=50), ValueError,
      "black_level: expected one value or four"),
    R("rawio.read_raw-byteorder", "read_raw(byteorder='=')",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                               bit_depth_in=10, byteorder="="), ValueError,
      "byteorder: expected '<' (little-endian) or '>' (big-endian)"),
    R("rawio.read_raw-downsample", "read_raw(downsample=0)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                               bit_depth_in=10, downsample=0), ValueError,
      "downsample: expected a positive integer binning factor"),
    R("rawio.read_raw-downsample-large", "read_raw(4x4, downsample=3)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                               bit_depth_in=10, downsample=3), ValueError,
      "downsample: a 4x4 frame holds no 6x6 block to bin"),
    R("rawio.read_raw-dtype", "read_raw(dtype=int32)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                               bit_depth_in=10, dtype=np.int32), TypeError,
      "dtype: expected one of uint8, uint16, float32, float64"),
    R("rawio.read_raw-dtype-unknown", "read_raw(dtype='junk')",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                               bit_depth_in=10, dtype="junk"), TypeError,
      "dtype: expected one of uint8, uint16, float32, float64, got 'junk'"),
    R("rawio.read_raw-uint8-bits", "read_raw(dtype=uint8, bit_depth=11)",
      lambda f: rawio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                               bit_depth_in=10, dtype=np.uint8), ValueError,
      "dtype: uint8 cannot hold 11-bit data"),
    R("rawio.read_raw-reader", "read_raw(reader='xyz')",
      lambda f: rawio.read_raw(f / "bayer.raw", reader="xyz"), ValueError,
      "reader: expected one of 'libraw', 'image', 'headerless'"),
    R("rawio.read_raw-missing", "read_raw('missing.raw')",
      lambda f: rawio.read_raw(f / "missing.raw", shape=(4, 4)), FileNotFoundError,
      "path: no such file"),
    R("rawio.read_raw-extension", "read_raw('notes.xyz')",
      lambda f: rawio.read_raw(f / "notes.xyz"), ValueError,
      "path: unknown raw extension '.xyz' of notes.xyz"),
    R("rawio.read_raw-shape-not-headerless", "read_raw('rgb.png', shape=(4, 4))",
      lambda f: rawio.read_raw(f / "rgb.png", shape=(4, 4)), ValueError,
      "shape: only headerless files take a shape"),
    R("rawio.read_raw-1x1", "read_raw(1x1 headerless)",
      lambda f: rawio.read_raw(f / "one.raw", shape=(1, 1), phase="GRBG", black_level=0,
                               bit_depth_in=10), ValueError,
      "one.raw: frame 1x1 is smaller than one Bayer quad"),
    R("rawio.read_raw-rgb", "read_raw(RGB .png)",
      lambda f: rawio.read_raw(f / "rgb.png", phase="GRBG", black_level=0, bit_depth_in=8),
      ValueError, "rgb.png: expected a single-channel Bayer mosaic"),
    R("rawio.read_raw-corrupt-dng", "read_raw(corrupt .dng)",
      lambda f: rawio.read_raw(f / "corrupt.dng"), ValueError, "path: LibRaw cannot read"),
    R("rawio.read_raw-corrupt-png", "read_raw(corrupt .png)",
      lambda f: rawio.read_raw(f / "corrupt.png", phase="GRBG", black_level=0, bit_depth_in=8),
      ValueError, "path: cannot read"),
    R("rawio.read_raw-corrupt-tiff", "read_raw(truncated .tif)",
      lambda f: rawio.read_raw(f / "truncated.tif", phase="GRBG", black_level=0,
                               bit_depth_in=8), ValueError, "path: cannot read"),
    R("rawio.list_raw_files-not-folder", "list_raw_files(a file)",
      lambda f: rawio.list_raw_files(f / "file.txt"), NotADirectoryError,
      "folder: not a directory"),
    R("rawio.to_rgbz-array", "to_rgbz(ndarray)", lambda f: rawio.to_rgbz(_u16(), "mask1"),
      TypeError, "frame: expected a RawFrame"),
    R("rawio.to_rgbz-has-z", "to_rgbz(mask1 frame)",
      lambda f: rawio.to_rgbz(_frame(), "mask1"), ValueError,
      "frame: pattern 'mask1' already has Z sites"),
    R("rawio.to_rgbz-pattern", "to_rgbz(pattern='bayer')",
      lambda f: rawio.to_rgbz(_frame("bayer"), "bayer"), ValueError,
      "pattern: expected one of 'mask1', 'mask2', 'rows'"),
    R("rawio.to_rgbz-phase", "to_rgbz(GRBG frame, 'mask1_rggb')",
      lambda f: rawio.to_rgbz(_frame("bayer"), "mask1_rggb"), ValueError,
      "pattern: 'mask1_rggb' asks for Bayer phase 'RGGB'"),
    R("rawio.to_rgbz-pattern-type", "to_rgbz(pattern=3)",
      lambda f: rawio.to_rgbz(_frame("bayer"), 3), TypeError,
      "pattern: expected a preset name or a Pattern"),
    R("rawio.to_rgbz-small", "to_rgbz(2x2, 'mask2')",
      lambda f: rawio.to_rgbz(_frame("bayer", (2, 2)), "mask2"), ValueError,
      "frame: 2x2 is smaller than one period (4x4)"),
    R("rawio.clipped_mask-no-level", "clipped_mask(array)",
      lambda f: rawio.clipped_mask(_f64()), ValueError,
      "clip_level: a plain array needs clip_level="),
    R("rawio.clipped_mask-ndim", "clipped_mask(3-D, 5)",
      lambda f: rawio.clipped_mask(np.zeros((4, 4, 3)), 5), ValueError,
      "frame: expected a 2-D array"),
    R("rawio.clipped_mask-radius", "clipped_mask(radius=-1)",
      lambda f: rawio.clipped_mask(_f64(), 5, radius=-1), ValueError,
      "radius: expected a non-negative integer"),
    R("rawio.clipped_mask-radius-float", "clipped_mask(radius=1.5)",
      lambda f: rawio.clipped_mask(_f64(), 5, radius=1.5), ValueError,
      "radius: expected a non-negative integer"),
    R("rawio.clipped_mask-level-nan", "clipped_mask(clip_level=nan)",
      lambda f: rawio.clipped_mask(_f64(), np.nan), ValueError,
      "clip_level: expected a finite number, got nan"),
    R("rawio.clipped_mask-level-text", "clipped_mask(clip_level='a')",
      lambda f: rawio.clipped_mask(_f64(), "a"), TypeError,
      "clip_level: expected a number, got 'a'"),

    # -- frameio ---------------------------------------------------------------------
    R("frameio.save-type", "save_frame(path, ndarray)",
      lambda f: frameio.save_frame(f / "x.npz", _u16()), TypeError,
      "frame: expected a RawFrame"),
    R("frameio.save-suffix", "save_frame('x.jpg', frame)",
      lambda f: frameio.save_frame(f / "x.jpg", _frame()), ValueError,
      "path: unsupported frame file type '.jpg'"),
    R("frameio.load-missing", "load_frame('missing.npz')",
      lambda f: frameio.load_frame(f / "missing.npz"), ValueError, "path: "),
    R("frameio.load-foreign", "load_frame(NPZ without header/data)",
      lambda f: frameio.load_frame(f / "foreign.npz"), ValueError, "path: "),
    R("frameio.load-truncated", "load_frame(truncated NPZ)",
      lambda f: frameio.load_frame(f / "truncated.npz"), ValueError, "path: "),
    R("frameio.load-junk", "load_frame(NPZ that is not a zip)",
      lambda f: frameio.load_frame(f / "junk.npz"), ValueError, "path: "),
    R("frameio.load-header-keys", "load_frame(NPZ whose header lacks pattern/bit_depth)",
      lambda f: frameio.load_frame(f / "nokeys.npz"), ValueError, "path: "),
    R("frameio.load-header-json", "load_frame(NPZ whose header is not JSON)",
      lambda f: frameio.load_frame(f / "notjson.npz"), ValueError, "path: "),
    R("frameio.load-plain-tiff", "load_frame(plain TIFF, no pattern)",
      lambda f: frameio.load_frame(f / "plain.tif"), ValueError,
      "phase: plain.tif does not record its CFA phase"),
    R("frameio.load-plain-tiff-bits", "load_frame(plain TIFF, pattern, no bit_depth)",
      lambda f: frameio.load_frame(f / "plain.tif", pattern="mask1"), ValueError,
      "bit_depth: required for a plain TIFF/PNG mosaic with a pattern"),
    R("frameio.load-corrupt-tiff", "load_frame(truncated TIFF)",
      lambda f: frameio.load_frame(f / "truncated.tif"), ValueError, "path: cannot read"),
    R("frameio.load-corrupt-png", "load_frame(corrupt PNG, pattern, bit_depth)",
      lambda f: frameio.load_frame(f / "corrupt.png", pattern="mask1", bit_depth=11),
      ValueError, "path: cannot read"),
    R("frameio.load-folder", "load_frame(a folder)",
      lambda f: frameio.load_frame(f / "empty"), ValueError, "path: unknown raw extension"),
    R("frameio.load-fifo", "load_frame(FIFO named fifo.npz): hung",
      lambda f: frameio.load_frame(f / "fifo.npz"), ValueError,
      "path: {d}/fifo.npz is a FIFO (named pipe), not a regular file"),
    _bad_frame("zip-bomb", "bomb", "2 MB of zeros deflated to 2 kB, max_bytes=1e6",
               "its arrays declare 2097", max_bytes=1_000_000),
    _bad_frame("npy-liar", "liar", ".npy header declaring 40000x40000 in 228 bytes",
               "member data.npy declares 3200000000 bytes of data in"),
    _bad_frame("deep-json", "deep", "header nested 100000 deep: was a RecursionError",
               "the header is nested too deeply"),
    _bad_frame("meta-list", "metalist", "header meta=[1, 2]: was an AttributeError",
               "the header field 'meta' is [1, 2], expected an object"),
    _bad_frame("tof-list", "toflist", "header tof=[1]",
               "the header's 'tof' is a JSON list, not an object"),
    _bad_frame("header-int", "hdrint", "header stored as an integer array",
               "the header is a int64 array"),
    _bad_frame("objects", "objects", "data member of Python objects",
               "member data.npy holds Python objects"),
    _bad_frame("big-tile", "bigtile", "4 kB NPZ, 512x512 tile",
               "tile: 512x512 sites, more than the largest tile (32x32))"),
    _bad_frame("tof-sites", "tofsites", "ToF sites outside the frame",
               "sites: rows span [1000, "),
    R("frameio.load-max_pixels", "load_frame(16x16 frame, max_pixels=10)",
      lambda f: frameio.load_frame(f / "ok.npz", max_pixels=10), ValueError,
      "path: {d}/ok.npz declares a 16x16 image (0.0 megapixels), more than the limit of 10 "
      "pixels; raise it with max_pixels=, --max-pixels or RGBZ_FAST_MAX_PIXELS"),

    # -- files and limits ------------------------------------------------------------
    R("io.read_file-fifo", "read_file(FIFO named fifo.tif)",
      lambda f: rio.read_file(f / "fifo.tif"), ValueError,
      "path: {d}/fifo.tif is a FIFO (named pipe), not a regular file"),
    R("io.read_file-device", "read_raw(zero.raw -> /dev/zero): read until MemoryError",
      lambda f: rio.read_raw(f / "zero.raw", shape=(4, 4), phase="RGGB", black_level=0,
                             white_level=1023), ValueError,
      "path: {d}/zero.raw is a character device, not a regular file"),
    R("io.read_file-folder", "read_file(a folder)",
      lambda f: rio.read_file(f / "empty"), ValueError,
      "path: {d}/empty is a folder, not a regular file"),
    R("io.read_file-max_bytes", "read_file(ok.npz, max_bytes=10)",
      lambda f: rio.read_file(f / "ok.npz", max_bytes=10), ValueError,
      "path: {d}/ok.npz is "),
    R("io.read_image-max_pixels", "read_image(16x16 PNG, max_pixels=10)",
      lambda f: rio.read_image(f / "rgb.png", max_pixels=10), ValueError,
      "path: {d}/rgb.png declares a 16x16x3 image (0.0 megapixels), more than the limit of 10 "
      "pixels"),
    R("io.read_image-max_bytes", "read_image(16x16 RGB PNG, max_bytes=700)",
      lambda f: rio.read_image(f / "rgb.png", max_bytes=700), ValueError,
      "path: {d}/rgb.png declares 16x16x3 values of 1 bytes (768 bytes), more than the limit "
      "of 700 bytes"),
    R("io.limits-value", "read_limits(max_pixels=0)",
      lambda f: rio.read_limits(max_pixels=0), ValueError,
      "max_pixels: expected a positive integer, got 0"),
    R("io.limits-type", "read_limits(max_bytes='1G')",
      lambda f: rio.read_limits(max_bytes="1G"), TypeError,
      "max_bytes: expected a positive integer, got '1G'"),
    R("io.limits-environment", "RGBZ_FAST_MAX_PIXELS=lots",
      lambda f: _with_env("RGBZ_FAST_MAX_PIXELS", "lots", rio.read_limits), ValueError,
      "RGBZ_FAST_MAX_PIXELS: expected a positive integer, got 'lots'"),
    R("io.atomic_write-data", "atomic_write(path, 5)",
      lambda f: rio.atomic_write(f / "x.txt", 5), TypeError,
      "data: expected str or bytes, got int"),

    # -- isp -------------------------------------------------------------------------
    R("isp.ColourISP-output_bits", "ColourISP(output_bits=12)",
      lambda f: isp.ColourISP(output_bits=12), ValueError,
      "ColourISP.output_bits: expected 8 or 16"),
    R("isp.ColourISP-precision", "ColourISP(precision='f16')",
      lambda f: isp.ColourISP(precision="f16"), ValueError,
      "ColourISP.precision: expected one of 'float32', 'float64'"),
    R("isp.ColourISP-stage-type", "ColourISP(defects=5)", lambda f: isp.ColourISP(defects=5),
      TypeError, "ColourISP.defects: expected DefectCorrection"),
    R("isp.run-no-pattern", "ColourISP().run(array)",
      lambda f: isp.ColourISP().run(_u16()), TypeError,
      "pattern: required when frame is a plain array"),
    R("isp.run-no-reference", "ColourISP().run(frame, reference=True), no reference",
      lambda f: isp.ColourISP().run(_frame(), reference=True), ValueError,
      "reference: the frame holds no reference Bayer CFA"),
    R("isp.run-gains", "ColourISP().run(gains=(1, 2))",
      lambda f: isp.ColourISP().run(_frame(), gains=(1, 2)), ValueError,
      "gains: expected three positive finite gains"),
    R("isp.run-black", "ColourISP().run(black_level=5000)",
      lambda f: isp.ColourISP().run(_frame(), black_level=5000), ValueError,
      "black_level: 5000 must be below the white level 2047"),
    R("isp.run-defects-map", "ColourISP().run(defects=3x3 map)",
      lambda f: isp.ColourISP().run(_frame(), defects=np.zeros((3, 3), bool)), ValueError,
      "known: expected a bool map of shape (8, 8)"),
    R("isp.run-method", "ColourISP(Reconstruction('nope')).run(frame)",
      lambda f: isp.ColourISP(reconstruction=isp.Reconstruction(method="nope")).run(_frame()),
      ValueError, "Reconstruction.method: expected one of"),
    R("isp.run_pair-type", "ColourISP().run_pair(array)",
      lambda f: isp.ColourISP().run_pair(_u16()), TypeError,
      "frame: expected a RawFrame with a reference CFA"),
    R("isp.Reconstruction-method", "Reconstruction(method=5)",
      lambda f: isp.Reconstruction(method=5), ValueError,
      "Reconstruction.method: expected one of 'bilinear', 'bi'"),
    R("isp.Reconstruction-params", "Reconstruction(params=5)",
      lambda f: isp.Reconstruction(params=5), TypeError,
      "Reconstruction.params: expected a ReconstructParams, a dict of its fields or None"),
    R("isp.Reconstruction-params-unknown", "Reconstruction(params={'nonsense': 1})",
      lambda f: isp.Reconstruction(params={"nonsense": 1}), TypeError,
      "Reconstruction.params got an unexpected keyword argument 'nonsense'"),
    R("isp.Reconstruction-params-value", "Reconstruction(params={'sigma_floor': -1})",
      lambda f: isp.Reconstruction(params={"sigma_floor": -1}), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("isp.Reconstruction-params-workers", "Reconstruction(params={'workers': 2})",
      lambda f: isp.Reconstruction(params={"workers": 2}), TypeError,
      "Reconstruction.params got an unexpected keyword argument 'workers'"),
    R("params.precision", "ReconstructParams(precision='float16')",
      lambda f: rz.ReconstructParams(precision="float16"), ValueError,
      "precision: expected one of 'float32', 'float64'"),
    R("params.exp", "ReconstructParams(exp='approx')",
      lambda f: rz.ReconstructParams(exp="approx"), ValueError,
      "exp: expected one of 'auto', 'libm', 'fast'"),
    R("isp.DefectCorrection-threshold", "DefectCorrection(threshold=0)",
      lambda f: isp.DefectCorrection(threshold=0), ValueError,
      "DefectCorrection.threshold: expected a finite number > 0 and <= 1"),
    R("isp.WhiteBalance-method", "WhiteBalance(method='x')",
      lambda f: isp.WhiteBalance(method="x"), ValueError,
      "WhiteBalance.method: expected one of 'grey_world', 'none'"),
    R("isp.WhiteBalance-gains", "WhiteBalance(gains=(0, 1, 1))",
      lambda f: isp.WhiteBalance(gains=(0, 1, 1)), ValueError,
      "WhiteBalance.gains: expected three positive finite gains"),
    R("isp.Demosaic-method", "Demosaic(method='x')", lambda f: isp.Demosaic(method="x"),
      ValueError, "Demosaic.method: expected one of"),
    R("isp.ColourCorrection-shape", "ColourCorrection(2x2)",
      lambda f: isp.ColourCorrection(matrix=((1, 0), (0, 1))), ValueError,
      "ColourCorrection.matrix: expected a finite 3x3 matrix"),
    R("isp.correct_defects-known", "correct_defects(known=int map)",
      lambda f: isp.correct_defects(_u16(), "mask1", known=np.zeros((8, 8), int)), ValueError,
      "known: expected a bool map of shape (8, 8)"),
    R("isp.detect_defects-white", "detect_defects(white_level=0)",
      lambda f: isp.detect_defects(_u16(), "mask1", white_level=0), ValueError,
      "white_level: expected a finite number > 0"),
    R("isp.white_balance-z", "white_balance(cfa, 'mask1')",
      lambda f: isp.white_balance(_u16(), "mask1"), ValueError,
      "phase: the white balance needs a complete Bayer CFA"),
    R("isp.white_balance-dtype", "white_balance(dtype=int32)",
      lambda f: isp.white_balance(_u16(), "bayer", dtype=np.int32), TypeError,
      "dtype: expected float32 or float64, got int32"),
    R("isp.grey_world_gains-z", "grey_world_gains(cfa, 'mask1')",
      lambda f: isp.grey_world_gains(_u16(), "mask1"), ValueError,
      "phase: the white balance needs a complete Bayer CFA"),
    R("isp.fill_missing-params", "fill_missing(params=5)",
      lambda f: isp.fill_missing(_u16(), "mask1", params=5), TypeError,
      "params: expected Reconstruction"),
    R("isp.correct_colour-ndim", "correct_colour(2-D)",
      lambda f: isp.correct_colour(_f64()), ValueError, "rgb: expected a 3-D array"),
    R("isp.srgb_oetf-nan", "srgb_oetf(NaN)", lambda f: isp.srgb_oetf(np.array([np.nan])),
      ValueError, "linear: holds 1 NaN or infinite value(s)"),
    R("isp.srgb_encode-bits", "srgb_encode(bits=12)",
      lambda f: isp.srgb_encode(np.zeros((2, 2, 3)), bits=12), ValueError,
      "bits: expected 8 or 16"),

    # -- tof_isp ---------------------------------------------------------------------
    R("tof.depth-no-taps", "tof_depth(frame without taps)",
      lambda f: tof_isp.tof_depth(_frame()), ValueError, "tof: the frame holds no ToF taps"),
    R("tof.depth-type", "tof_depth(ndarray)", lambda f: tof_isp.tof_depth(np.zeros((3, 4, 5))),
      TypeError, "tof: expected ToFTaps or a RawFrame with taps"),
    R("tof.depth-window", "tof_depth(window=4)", lambda f: tof_isp.tof_depth(_sim(), window=4),
      ValueError, "window: expected an odd positive integer"),
    R("tof.depth-min_snr", "tof_depth(min_snr=-1)",
      lambda f: tof_isp.tof_depth(_sim(), min_snr=-1), ValueError,
      "min_snr: expected a finite number >= 0"),
    R("tof.depth-max_residual", "tof_depth(max_residual=0)",
      lambda f: tof_isp.tof_depth(_sim(), max_residual=0), ValueError,
      "max_residual: expected a finite number > 0"),
    R("tof.depth-max_range-nan", "tof_depth(max_range=nan)",
      lambda f: tof_isp.tof_depth(_sim(), max_range=np.nan), ValueError,
      "max_range: expected a finite number > 0"),
    R("tof.depth-max_range-huge", "tof_depth(max_range=1e12)",
      lambda f: tof_isp.tof_depth(_sim(), max_range=1e12), ValueError,
      "max_range: 1e+12 m is beyond the 7.49481 m unambiguous range"),
    R("tof.depth-denoise", "tof_depth(denoise=1)",
      lambda f: tof_isp.tof_depth(_sim(), denoise=1), ValueError,
      "denoise: expected one of 'bilateral', 'box', 'none'"),
    R("tof.depth-range_scale", "tof_depth(range_scale=0)",
      lambda f: tof_isp.tof_depth(_sim(), range_scale=0), ValueError,
      "range_scale: expected a finite number > 0"),
    R("tof.depth-max_sigma", "tof_depth(max_sigma=0)",
      lambda f: tof_isp.tof_depth(_sim(), max_sigma=0), ValueError,
      "max_sigma: expected a finite number > 0"),
    R("tof.depth-flying_step", "tof_depth(flying_step=-1)",
      lambda f: tof_isp.tof_depth(_sim(), flying_step=-1), ValueError,
      "flying_step: expected a finite number > 0"),
    R("tof.depth-min_reflectance", "tof_depth(min_reflectance=2)",
      lambda f: tof_isp.tof_depth(_sim(), min_reflectance=2), ValueError,
      "min_reflectance: expected a finite number >= 0 and <= 1"),
    R("tof.depth-calibration-type", "tof_depth(calibration='cal.npz')",
      lambda f: tof_isp.tof_depth(_sim(), calibration="cal.npz"), TypeError,
      "calibration: expected a ToFCalibration or None, got str"),
    R("tof.depth-calibration-layout", "tof_depth(16x16 taps, calibration of 16x20)",
      lambda f: tof_isp.tof_depth(_sim(), calibration=_calibration((16, 20))), ValueError,
      "calibration: made for 80 Z measurements of a 16x20 frame (block 1), the taps hold 64"),
    R("tof.bilateral-var", "denoise_phasors_bilateral(var 0)",
      lambda f: tof_isp.denoise_phasors_bilateral(np.zeros((1, 2)), np.zeros((1, 2)),
                                                  np.zeros((1, 2)), ([0, 0], [0, 2])),
      ValueError, "var: expected positive variances"),
    R("tof.flying-shape", "flying_pixels(depth of 3, sigma of 2, 3 sites)",
      lambda f: tof_isp.flying_pixels(np.zeros(3), np.zeros(2), ([0, 0, 0], [0, 2, 4])),
      ValueError, "depth, sigma: expected shape (3,), got (3,) and (2,)"),
    R("tof.calibrate-one-frame", "calibrate([taps], [1.0])",
      lambda f: tof_isp.calibrate([_sim_tof()], [1.0]), ValueError,
      "sweep: expected at least 2 frames, got 1"),
    R("tof.calibrate-distances", "calibrate(2 frames, 3 distances)",
      lambda f: tof_isp.calibrate([_sim_tof(), _sim_tof()], [1.0, 1.2, 1.4]), ValueError,
      "distances: expected 2 values (one per frame), got 3"),
    R("tof.calibrate-positions", "calibrate(2 positions, orders=8)",
      lambda f: tof_isp.calibrate([_sim_tof(), _sim_tof()], [1.0, 1.2]), ValueError,
      "distances: 2 distinct wall positions cannot fit 8 harmonics"),
    R("tof.calibration-load", "ToFCalibration.load(corrupt file)",
      lambda f: tof_isp.ToFCalibration.load(f / "junk.npz"), ValueError,
      "path: "),
    R("tof.ToFISP-window", "ToFISP(window=2)", lambda f: tof_isp.ToFISP(window=2), ValueError,
      "window: expected an odd positive integer"),
    R("tof.demodulate-ndim", "demodulate(2-D)", lambda f: tof_isp.demodulate(_f64((4, 5))),
      ValueError, "taps: expected shape (F, 4, n_sites)"),
    R("tof.demodulate-taps", "demodulate(3 taps)",
      lambda f: tof_isp.demodulate(np.zeros((1, 3, 5))), ValueError,
      "taps: expected shape (F, 4, n_sites)"),
    R("tof.demodulate-no-frequency", "demodulate(F=0)",
      lambda f: tof_isp.demodulate(np.zeros((0, 4, 5))), ValueError,
      "taps: expected shape (F, 4, n_sites)"),
    R("tof.demodulate-nan", "demodulate(NaN)",
      lambda f: tof_isp.demodulate(np.full((1, 4, 2), np.nan)), ValueError,
      "taps: holds NaN or infinite values"),
    R("tof.demodulate-complex", "demodulate(complex)",
      lambda f: tof_isp.demodulate(np.zeros((1, 4, 2), complex)), TypeError,
      "taps: expected real numbers"),
    R("tof.demodulate-bool", "demodulate(bool)",
      lambda f: tof_isp.demodulate(np.zeros((1, 4, 2), bool)), TypeError,
      "taps: expected real numbers"),
    R("tof.demodulate-workers", "demodulate(workers=0)",
      lambda f: tof_isp.demodulate(np.zeros((1, 4, 2)), workers=0), ValueError,
      "workers: expected None, -1 or a positive number of threads"),
    R("tof.phasors-taps", "phasors(3 taps)", lambda f: tof_isp.phasors(np.zeros((1, 3, 2))),
      ValueError, "taps: expected shape (F, 4, n_sites)"),
    R("tof.unwrap-ndim", "unwrap(1-D phase)", lambda f: tof_isp.unwrap(np.zeros(3), [80e6]),
      ValueError, "phase: expected shape (F, n)"),
    R("tof.unwrap-nan", "unwrap(NaN phase)",
      lambda f: tof_isp.unwrap(np.full((1, 3), np.nan), [80e6]), ValueError,
      "phase: holds NaN or infinite values"),
    R("tof.unwrap-frequencies", "unwrap(2 phases, 1 frequency)",
      lambda f: tof_isp.unwrap(np.zeros((2, 3)), [80e6]), ValueError,
      "frequencies: expected 2 positive values in Hz"),
    R("tof.unwrap-frequency-zero", "unwrap(frequency 0)",
      lambda f: tof_isp.unwrap(np.zeros((1, 3)), [0]), ValueError,
      "frequencies: expected 1 positive values in Hz"),
    R("tof.unwrap-17", "unwrap(17 frequencies)",
      lambda f: tof_isp.unwrap(np.zeros((17, 3)), np.arange(1, 18) * 1e6), ValueError,
      "phase: at most 16 frequencies"),
    R("tof.unwrap-weights", "unwrap(weights=[0])",
      lambda f: tof_isp.unwrap(np.zeros((1, 3)), [80e6], weights=[0]), ValueError,
      "weights: expected 1 non-negative values, not all 0"),
    R("tof.unwrap-max_range", "unwrap(max_range=0)",
      lambda f: tof_isp.unwrap(np.zeros((1, 3)), [80e6], max_range=0), ValueError,
      "max_range: expected a finite number > 0"),
    R("tof.unwrap-max_range-overflow", "unwrap(max_range=1e12)",
      lambda f: tof_isp.unwrap(np.zeros((1, 3)), [80e6], max_range=1e12), ValueError,
      "max_range: 1e+12 m is beyond the 1.8737 m unambiguous range"),
    R("tof.unwrap-max_range-slow", "unwrap(n=1, max_range=1e8): 5e7 wrap candidates",
      lambda f: tof_isp.unwrap(np.zeros((3, 1)), [80e6, 100e6, 120e6], max_range=1e8),
      ValueError, "max_range: 1e+08 m is beyond the 7.49481 m unambiguous range"),
    R("tof.unwrap-max_range-wraps", "unwrap(frequencies (80e6 + 10, 100e6) Hz, max_range=1e4)",
      lambda f: tof_isp.unwrap(np.zeros((2, 1)), [80e6 + 10, 100e6], max_range=1e4),
      ValueError, "max_range: 10000 m holds 5338 wraps of the 1.8737 m interval"),
    R("tof.unwrap-near-coprime", "unwrap(n=1, frequencies (80e6 + 10, 100e6) Hz): range 1.5e7 m",
      lambda f: tof_isp.unwrap(np.zeros((2, 1)), [80e6 + 10, 100e6]), ValueError,
      "frequencies: the unambiguous range of 80.00001, 100 MHz is 1.49896e+07 m"),
    R("tof.depth-near-coprime", "tof_depth(taps of 80e6 + 1, 100e6, 120e6 Hz): range 1.5e8 m",
      lambda f: tof_isp.tof_depth(_sim_tof(frequencies=(80e6 + 1, 100e6, 120e6))),
      ValueError, "frequencies: the unambiguous range of 80.000001, 100, 120 MHz"),
    R("tof.unwrap-phase-range", "unwrap(phase 1e300)",
      lambda f: tof_isp.unwrap(np.full((1, 3), 1e300), [80e6]), ValueError,
      "phase: values span [1e+300, 1e+300]; expected wrapped phases in [0, 2 pi)"),
    R("tof.unwrap-phase-negative", "unwrap(phase -0.1)",
      lambda f: tof_isp.unwrap(np.full((1, 3), -0.1), [80e6]), ValueError,
      "phase: values span [-0.1, -0.1]; expected wrapped phases in [0, 2 pi)"),
    R("tof.unwrap-phase-two-pi", "unwrap(phase 2 pi)",
      lambda f: tof_isp.unwrap(np.full((1, 3), 2 * np.pi), [80e6]), ValueError,
      "phase: values span [6.283185307179586, 6.283185307179586]; expected wrapped"),
    R("tof.denoise-shapes", "denoise_phasors(i (1, 3), q (1, 4))",
      lambda f: tof_isp.denoise_phasors(np.zeros((1, 3)), np.zeros((1, 4)),
                                        (np.arange(3), np.arange(3))), ValueError,
      "i, q: expected two arrays of the same shape"),
    R("tof.denoise-sites", "denoise_phasors(sites of 2 for 3 measurements)",
      lambda f: tof_isp.denoise_phasors(np.zeros((1, 3)), np.zeros((1, 3)),
                                        (np.arange(2), np.arange(3))), ValueError,
      "sites: expected two arrays of shape (3,)"),
    R("tof.denoise-block", "denoise_phasors(block=3)",
      lambda f: tof_isp.denoise_phasors(np.zeros((1, 3)), np.zeros((1, 3)),
                                        (np.arange(3), np.arange(3)), block=3), ValueError,
      "block: expected 1 or 2"),
    R("tof.denoise-use", "denoise_phasors(use of 2 for 3 measurements)",
      lambda f: tof_isp.denoise_phasors(np.zeros((1, 3)), np.zeros((1, 3)),
                                        (np.arange(3), np.arange(3)), use=np.ones(2, bool)),
      ValueError, "use: expected shape (3,)"),
    R("tof.to_frame-field", "ToFDepth.to_frame('nope')",
      lambda f: tof_isp.tof_depth(_sim()).to_frame("nope"), ValueError,
      "values: unknown field 'nope'"),

    # -- evaluate --------------------------------------------------------------------
    R("evaluate.config-empty", "EvalConfig(patterns=())",
      lambda f: ev.EvalConfig(patterns=()), ValueError,
      "patterns, methods and metrics must each name at least one entry"),
    R("evaluate.config-pattern", "EvalConfig(patterns=('foo',))",
      lambda f: ev.EvalConfig(patterns=("foo",)), ValueError, "pattern: 'foo' is neither"),
    R("evaluate.config-method", "EvalConfig(methods=('foo',))",
      lambda f: ev.EvalConfig(methods=("foo",)), ValueError, "methods: unknown method(s)"),
    R("evaluate.config-metric", "EvalConfig(metrics=('foo',))",
      lambda f: ev.EvalConfig(metrics=("foo",)), ValueError, "metrics: unknown metric(s)"),
    R("evaluate.config-demosaic", "EvalConfig(demosaic='x')",
      lambda f: ev.EvalConfig(demosaic="x"), ValueError, "demosaic: expected one of 'malvar2004', 'menon2007', 'bilinear'"),
    R("evaluate.config-crop", "EvalConfig(crop=-1)", lambda f: ev.EvalConfig(crop=-1),
      ValueError, "crop: expected an integer >= 0"),
    R("evaluate.config-optics", "EvalConfig(optics=2.8)", lambda f: ev.EvalConfig(optics=2.8),
      TypeError, "optics: expected an Optics or None, got float"),
    R("evaluate.depth-sections", "evaluate_depth(sections=('speed',))",
      lambda f: ev.evaluate_depth(None, sections=("speed",)), ValueError,
      "sections: unknown ['speed']"),
    R("evaluate.depth-isp", "evaluate_depth(isp='box')",
      lambda f: ev.evaluate_depth(None, sections=("noise",), isp="box"), TypeError,
      "isp: expected a ToFISP"),
    R("evaluate.config-bit_depth", "EvalConfig(bit_depth=40)",
      lambda f: ev.EvalConfig(bit_depth=40), ValueError, "bit_depth: expected 1..16 bits"),
    R("evaluate.config-bit_depth-type", "EvalConfig(bit_depth='11')",
      lambda f: ev.EvalConfig(bit_depth="11"), TypeError,
      "bit_depth: expected an integer number of bits"),
    R("evaluate.config-params", "EvalConfig(params={'foo': 1})",
      lambda f: ev.EvalConfig(params={"foo": 1}), TypeError,
      "params got an unexpected keyword argument 'foo'"),
    R("evaluate.config-params-value", "EvalConfig(params={'sigma_floor': -1})",
      lambda f: ev.EvalConfig(params={"sigma_floor": -1}), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("evaluate.config-params-type", "EvalConfig(params='sg_mode=pure')",
      lambda f: ev.EvalConfig(params="sg_mode=pure"), TypeError,
      "params: expected a ReconstructParams, a dict of its fields or None"),
    R("evaluate.config-params-workers", "EvalConfig(params={'workers': 2})",
      lambda f: ev.EvalConfig(params={"workers": 2}), TypeError,
      "params got an unexpected keyword argument 'workers'"),
    R("evaluate.config-seed", "EvalConfig(seed=-1)", lambda f: ev.EvalConfig(seed=-1),
      ValueError, "seed: expected an integer >= 0"),
    R("evaluate.config-noise", "EvalConfig(noise='yes')", lambda f: ev.EvalConfig(noise="yes"),
      TypeError, "noise: expected True or False"),
    R("evaluate.empty", "evaluate([])", lambda f: ev.evaluate([], ev.EvalConfig()), ValueError,
      "dataset: no images"),
    R("evaluate.override-unknown", "evaluate(ds, config, cropp=1)",
      lambda f: ev.evaluate([], ev.EvalConfig(), cropp=1), TypeError,
      "evaluate() got an unexpected keyword argument 'cropp' (fields of EvalConfig: "),
    R("evaluate.config-type", "evaluate(ds, config='sg')",
      lambda f: ev.evaluate([], "sg"), TypeError,
      "config: expected an EvalConfig, a dict of its fields or None, got str"),
    R("evaluate.processes", "evaluate(processes=0)",
      lambda f: ev.evaluate(f / "ds", metrics=("cfa_psnr",), processes=0, progress=False),
      ValueError, "processes: expected None or a positive number of processes"),
    R("evaluate.workers", "evaluate(workers=0)",
      lambda f: ev.evaluate(f / "ds", metrics=("cfa_psnr",), workers=0, progress=False),
      ValueError, "workers: expected None, -1 or a positive number of threads"),
    R("evaluate.duplicate-names", "evaluate(two images named 'a')",
      lambda f: ev.evaluate([rio.ImageSource("a", "skimage:coffee")] * 2, progress=False),
      ValueError, "dataset: image names must be unique"),
    R("evaluate.missing-folder", "evaluate('missing')",
      lambda f: ev.evaluate(f / "missing", progress=False), ValueError, "dataset: "),
    R("evaluate.dataset-type", "evaluate(dataset=5)",
      lambda f: ev.evaluate(5, progress=False), TypeError,
      "dataset: expected a list of ImageSource, a folder or None, got int"),
    R("evaluate.dataset-entries", "evaluate(['a.png'])",
      lambda f: ev.evaluate([str(f / "rgb.png")], progress=False), TypeError,
      "dataset: expected ImageSource entries"),
    R("evaluate.image-corrupt", "ImageSource(corrupt .png).load()",
      lambda f: rio.ImageSource("c", str(f / "corrupt.png")).load(), ValueError,
      "dataset: cannot read"),
    R("evaluate.image-too-small", "evaluate(1x1 image)",
      lambda f: ev.evaluate([rio.ImageSource("t", str(f / "tiny.png"))], metrics=("cfa_psnr",),
                            workers=1, progress=False), ValueError,
      "rgb: frame 1x1 is smaller than one period"),
    R("evaluate.crop-too-large", "evaluate(20x20 image, crop=8, ssim)",
      lambda f: ev.evaluate([rio.ImageSource("s", str(f / "small.png"))], metrics=("ssim",),
                            workers=1, progress=False), ValueError, "crop: crop=8 leaves"),
    R("evaluate.folder-empty", "folder_dataset(empty folder)",
      lambda f: rio.folder_dataset(f / "empty"), ValueError, "dataset: no image files in"),
    R("evaluate.folder-limit", "folder_dataset(limit=0)",
      lambda f: rio.folder_dataset(f / "ds", limit=0), ValueError,
      "limit: expected a positive number of images, got 0"),
    R("evaluate.folder-limit-negative", "folder_dataset(limit=-1)",
      lambda f: rio.folder_dataset(f / "ds", limit=-1), ValueError,
      "limit: expected a positive number of images, got -1"),
    R("evaluate.folder-same-stem", "folder_dataset(a.png and a.tif)",
      lambda f: rio.folder_dataset(f / "ds_stems"), ValueError,
      "dataset: several files are named 'a' (e.g. a.png, a.tif)"),
    R("evaluate.image-grey", "ImageSource(grey .png).load(): was made RGB silently",
      lambda f: rio.ImageSource("g", str(f / "grey.png")).load(), ValueError,
      "dataset: {d}/grey.png is a grey image (16x16)"),
    R("evaluate.skip_bad", "evaluate(skip_bad='yes')",
      lambda f: ev.evaluate(f / "ds", metrics=("cfa_psnr",), skip_bad="yes", progress=False),
      TypeError, "skip_bad: expected True or False"),
    R("evaluate.paired-one-method", "paired_chart(results of one method)",
      lambda f: ev.paired_chart(ev.Results([{"image": "a", "pattern": "mask1", "method": "sg",
                                            "metric": "cfa_psnr", "value": 1.0}],
                                           ev.EvalConfig(methods=("sg",))), "cfa_psnr"),
      ValueError, "baseline: 'sg' is the only method; nothing to compare"),
    R("evaluate.write_reports-empty", "write_reports(Results([]))",
      lambda f: ev.write_reports(ev.Results([], ev.EvalConfig()), f / "reports_empty"),
      ValueError, "results: no rows to report"),
    R("evaluate.write_reports-type", "write_reports(list of rows)",
      lambda f: ev.write_reports([], f / "reports_list"), TypeError,
      "results: expected Results"),
]

C = CliRow
CLI_ROWS = [
    C("cli.no-command", ("nope",), "argument COMMAND: invalid choice", usage=True),
    C("cli.simulate-no-scene", ("simulate",), "the following arguments are required",
      usage=True),
    C("cli.simulate-missing", ("simulate", "{d}/missing.png"), "scene {d}/missing.png does not"),
    C("cli.simulate-pattern", ("simulate", "{d}/rgb.png", "--pattern", "mask7"),
      "pattern: 'mask7' is neither a preset"),
    C("cli.simulate-no-bayer", ("simulate", "{d}/rgb.png", "--pattern", "ZR/RG"),
      "pattern: 'ZR/RG' fits no Bayer phase"),
    C("cli.simulate-seed", ("simulate", "{d}/rgb.png", "--seed", "-1"),
      "argument --seed: expected an integer >= 0, got '-1'", usage=True),
    C("cli.simulate-tiny", ("simulate", "{d}/tiny.png"),
      "scene: frame 1x1 is smaller than one period"),
    C("cli.simulate-corrupt", ("simulate", "{d}/corrupt.png"), "path: cannot read"),
    C("cli.simulate-out-is-file", ("simulate", "{d}/rgb.png", "--out", "{d}/file.txt"), ""),
    C("cli.reconstruct-missing", ("reconstruct", "{d}/missing.npz"), "path: "),
    C("cli.reconstruct-rgb", ("reconstruct", "{d}/rgb.png"),
      "rgb.png: expected a single-channel Bayer mosaic"),
    C("cli.reconstruct-plain-bits", ("reconstruct", "{d}/plain.tif", "--pattern", "mask1"),
      "bit_depth: required for a plain TIFF/PNG mosaic"),
    C("cli.reconstruct-bits", ("reconstruct", "{d}/plain.tif", "--pattern", "mask1",
                               "--bit-depth", "99"), "bit_depth: expected 1..16 bits"),
    C("cli.reconstruct-extension", ("reconstruct", "{d}/notes.xyz"),
      "path: unknown raw extension"),
    C("cli.reconstruct-method", ("reconstruct", "{d}/ok.npz", "--method", "edi_rows"),
      "method: 'edi_rows' needs"),
    C("cli.reconstruct-method-unknown", ("reconstruct", "{d}/ok.npz", "--method", "nope"),
      "method: expected one of"),
    C("cli.reconstruct-workers", ("reconstruct", "{d}/ok.npz", "--workers", "0"),
      "argument --workers: expected a positive integer, got '0'", usage=True),
    C("cli.reconstruct-precision", ("reconstruct", "{d}/ok.npz", "--precision", "float16"),
      "argument --precision: invalid choice", usage=True),
    C("cli.reconstruct-truncated", ("reconstruct", "{d}/truncated.npz"),
      "path: {d}/truncated.npz is not a readable rgbz-fast frame"),
    C("cli.reconstruct-header", ("reconstruct", "{d}/nokeys.npz"),
      "path: {d}/nokeys.npz is not a readable rgbz-fast frame (missing key 'pattern')"),
    C("cli.reconstruct-corrupt-png", ("reconstruct", "{d}/corrupt.png", "--pattern", "mask1",
                                      "--bit-depth", "11"), "path: cannot read {d}/corrupt.png"),
    C("cli.evaluate-empty", ("evaluate", "--dataset", "{d}/empty"),
      "dataset: no image files in"),
    C("cli.evaluate-missing", ("evaluate", "--dataset", "{d}/missing"), "dataset: "),
    C("cli.evaluate-crop", ("evaluate", "--dataset", "{d}/ds", "--crop", "-1"),
      "argument --crop: expected an integer >= 0, got '-1'", usage=True),
    C("cli.evaluate-methods", ("evaluate", "--dataset", "{d}/ds", "--methods", "nope"),
      "methods: unknown method(s)"),
    C("cli.evaluate-metrics", ("evaluate", "--dataset", "{d}/ds", "--metrics", "nope"),
      "metrics: unknown metric(s)"),
    C("cli.evaluate-patterns", ("evaluate", "--dataset", "{d}/ds", "--patterns", "foo"),
      "pattern: 'foo' is neither"),
    C("cli.evaluate-processes", ("evaluate", "--dataset", "{d}/ds", "--processes", "0"),
      "argument --processes: expected a positive integer, got '0'", usage=True),
    C("cli.evaluate-workers", ("evaluate", "--dataset", "{d}/ds", "--workers", "0"),
      "argument --workers: expected a positive integer, got '0'", usage=True),
    C("cli.evaluate-image-small", ("evaluate", "--dataset", "{d}/small.png", "--processes", "1",
                                   "--no-cache", "--no-plots"), "crop: crop=8 leaves"),
    C("cli.evaluate-corrupt", ("evaluate", "--dataset", "{d}/ds_corrupt", "--processes", "1",
                               "--no-cache", "--metrics", "cfa_psnr"),
      "dataset: cannot read {d}/ds_corrupt/a.png"),
    C("cli.evaluate-out-is-file", ("evaluate", "--dataset", "{d}/ds", "--processes", "1",
                                   "--metrics", "cfa_psnr", "--out", "{d}/file.txt"), ""),
    C("cli.simulate-grey", ("simulate", "{d}/grey.png"),
      "path: {d}/grey.png is a grey image (16x16); a colour sensor needs colour: pass --grey"),
    C("cli.simulate-max-pixels", ("simulate", "{d}/rgb.png", "--max-pixels", "0"),
      "argument --max-pixels: expected a positive integer, got '0'", usage=True),
    C("cli.reconstruct-plain-bayer", ("reconstruct", "{d}/plain.tif", "--phase", "RGGB",
                                      "--black-level", "0", "--white-level", "1023"),
      "--rgbz-pattern: {d}/plain.tif is a plain Bayer frame (bayer_rggb, no Z sites), so there "
      "is nothing to reconstruct"),
    C("cli.reconstruct-rgbz-on-rgbz", ("reconstruct", "{d}/ok.npz", "--rgbz-pattern", "mask1"),
      "--rgbz-pattern: {d}/ok.npz already has Z sites (pattern mask1)"),
    C("cli.reconstruct-raw-flag-on-frame", ("reconstruct", "{d}/ok.npz", "--phase", "RGGB"),
      "--phase: {d}/ok.npz is an rgbz-fast frame file"),
    C("cli.reconstruct-two-patterns", ("reconstruct", "{d}/plain.tif", "--pattern", "mask1",
                                       "--rgbz-pattern", "mask1"),
      "--pattern: names the pattern of a plain mosaic that already holds Z sites"),
    C("cli.reconstruct-png-phase", ("reconstruct", "{d}/bayer16.png", "--rgbz-pattern",
                                    "mask1"),
      "phase: bayer16.png does not record its CFA phase; pass --phase one of"),
    C("cli.reconstruct-headerless-shape", ("reconstruct", "{d}/bayer.raw", "--rgbz-pattern",
                                           "mask1", "--phase", "RGGB", "--black-level", "0",
                                           "--white-level", "1023"),
      "shape: the headerless file bayer.raw needs --shape ROWSxCOLS"),
    C("cli.reconstruct-shape-syntax", ("reconstruct", "{d}/bayer.raw", "--shape", "4*4"),
      "argument --shape: expected ROWSxCOLS such as 1080x1920 (rows first), got '4*4'",
      usage=True),
    C("cli.reconstruct-levels-syntax", ("reconstruct", "{d}/bayer.raw", "--black-level", "1,2"),
      "argument --black-level: expected one value or four, got 2", usage=True),
    C("cli.reconstruct-raw-options", ("reconstruct", "{d}/bayer16.png", "--rgbz-pattern",
                                      "mask1", "--raw-options", "{d}/raw_options.json"),
      "--raw-options: {d}/raw_options.json should map file names"),
    C("cli.reconstruct-same-output", ("reconstruct", "{d}/ok.npz", "{d}/sub/ok.npz"),
      "--out: {d}/ok.npz and {d}/sub/ok.npz would both write"),
    C("cli.reconstruct-fifo", ("reconstruct", "{d}/fifo.npz"),
      "path: {d}/fifo.npz is a FIFO (named pipe), not a regular file"),
    C("cli.reconstruct-device", ("reconstruct", "{d}/zero.raw", "--shape", "4x4", "--phase",
                                 "RGGB", "--black-level", "0", "--white-level", "1023",
                                 "--rgbz-pattern", "mask1"),
      "path: {d}/zero.raw is a character device, not a regular file"),
    C("cli.reconstruct-max-pixels", ("reconstruct", "{d}/ok.npz", "--max-pixels", "10"),
      "path: {d}/ok.npz declares a 16x16 image (0.0 megapixels), more than the limit of 10 "
      "pixels; raise it with --max-pixels or RGBZ_FAST_MAX_PIXELS"),
    C("cli.reconstruct-zip-bomb", ("reconstruct", "{d}/bomb.npz", "--max-bytes", "1000000"),
      "path: {d}/bomb.npz is not a readable rgbz-fast frame (its arrays declare 2097"),
    C("cli.depth-no-taps", ("depth", "{d}/ok.npz"), "path: {d}/ok.npz holds no ToF taps"),
    C("cli.depth-range", ("depth", "{d}/tof.npz", "--range", "2:1"),
      "argument --range: expected 0 <= MIN < MAX, got '2:1'", usage=True),
    C("cli.evaluate-limit-zero", ("evaluate", "--dataset", "{d}/ds", "--limit", "0"),
      "argument --limit: expected a positive integer, got '0'", usage=True),
    C("cli.evaluate-limit-negative", ("evaluate", "--dataset", "{d}/ds", "--limit", "-1"),
      "argument --limit: expected a positive integer, got '-1'", usage=True),
    C("cli.evaluate-grey", ("evaluate", "--dataset", "{d}/ds_grey", "--processes", "1",
                            "--no-cache", "--metrics", "cfa_psnr"),
      "dataset: {d}/ds_grey/g.png is a grey image (16x16); a colour sensor needs colour: pass "
      "--grey"),
    C("cli.bench-shape", ("bench", "--shape", "1920*1080"),
      "--shape: expected ROWSxCOLS such as 1080x1920 (rows first), got '1920*1080'"),
    C("cli.opcount-shape", ("opcount", "--shape", "64"),
      "--shape: expected ROWSxCOLS such as 1080x1920 (rows first), got '64'"),
    C("cli.bench-workers", ("bench", "--workers", "0"), "--workers: expected a positive integer"),
    C("cli.bench-argument", ("bench", "--nope"), "unrecognized arguments: --nope"),
    C("cli.opcount-pattern", ("opcount", "--patterns", "nope"), "pattern: 'nope' is neither"),
    C("cli.opcount-argument", ("opcount", "--nope"), "unrecognized arguments: --nope"),
    C("cli.tradeoff-workers", ("tradeoff", "--workers", "0"),
      "--workers: expected a positive integer"),
    C("cli.tradeoff-argument", ("tradeoff", "--nope"), "unrecognized arguments: --nope"),
    C("cli.evaluate-optics-options", ("evaluate", "--dataset", "{d}/ds", "--olpf", "1"),
      "--f-number, --olpf and --defocus-um need --optics"),
    C("cli.calibrate-no-frames", ("calibrate",),
      "no frames: give .npz frame files with their --distances, or --simulate"),
    C("cli.calibrate-no-distances", ("calibrate", "{d}/ok.npz"),
      "--distances: one distance per frame is needed"),
    C("cli.calibrate-no-taps", ("calibrate", "{d}/ok.npz", "{d}/ok.npz", "--distances", "1,2",
                                "--out", "{d}/cal.npz"), "sweep: the frame holds no ToF taps"),
    C("cli.calibrate-both", ("calibrate", "{d}/ok.npz", "--simulate"),
      "give frame files or --simulate, not both"),
    C("cli.calibrate-sensor", ("calibrate", "--simulate", "--sensor", "[1]"),
      "--sensor: expected a JSON object of ToFSensor arguments"),
    C("cli.calibrate-sensor-value", ("calibrate", "--simulate", "--sensor",
                                     '{"duty_cycle": 0}'),
      "ToFSensor.duty_cycle: expected a finite number > 0 and <= 1"),
    C("cli.evaluate-depth-sections", ("evaluate-depth", "--sections", "speed"),
      "sections: unknown ['speed']"),
    C("cli.config-argument", ("config", "--nope"), "unrecognized arguments: --nope",
      usage=True),
]


def _params(rows):
    return [pytest.param(r, id=r.id, marks=[pytest.mark.xfail(
        strict=True, reason=f"bug {r.bug} (docs/reports/robustness.md): {BUGS[r.bug]}")]
        if r.bug else []) for r in rows]


# --------------------------------------------------------------------------- API rows
@pytest.mark.parametrize("row", _params(ROWS))
def test_api_contract(row, files):
    if row.id == "rawio.read_raw-corrupt-dng":
        pytest.importorskip("rawpy")
    with pytest.raises(row.exc) as info:
        row.fn(files)
    msg = str(info.value)
    want = row.msg.replace("{d}", str(files.d))
    if isinstance(info.value, FileNotFoundError) and not msg.startswith(want):
        msg = str(info.value.args[0]) if info.value.args else msg
    assert msg.startswith(want), f"message {msg!r} does not start with {want!r}"


def test_contract_rows_are_unique_and_documented_bugs_exist():
    ids = [r.id for r in ROWS + CLI_ROWS]
    assert len(ids) == len(set(ids))
    assert {r.bug for r in ROWS + CLI_ROWS if r.bug} <= set(BUGS)


# --------------------------------------------------------------------------- CLI rows
def _argv(row, d):
    argv = [a.replace("{d}", str(d)) for a in row.argv]
    if argv[0] in ("simulate", "reconstruct", "depth", "evaluate") and "--out" not in argv:
        argv += ["--out", str(d / f"out_{row.id}")]
    if argv[0] in ("simulate", "reconstruct", "depth", "evaluate") and not row.usage:
        argv.append("--quiet")
    return argv


def _cli_prefix(command):
    """Subcommands report as `rgbz-fast CMD: error:`; the top-level parser (unknown
    command, `config`'s unknown arguments) as `rgbz-fast: error:`."""
    if command in ("simulate", "reconstruct", "depth", "evaluate", "calibrate", "evaluate-depth",
                   "bench", "opcount", "tradeoff"):
        return f"rgbz-fast {command}: error: "
    return "rgbz-fast: error: "


@pytest.mark.parametrize("row", _params(CLI_ROWS))
def test_cli_contract(row, files, capsys):
    argv = _argv(row, files.d)
    try:
        code = main(argv)
    except SystemExit as e:                           # argparse
        code = e.code
    err = [line for line in capsys.readouterr().err.splitlines() if line.strip()]
    assert code == 2, err
    assert err, "no reason on stderr"
    prefix = _cli_prefix(argv[0])
    if row.usage:
        assert err[0].startswith("usage: ")          # argparse: usage, then the reason
    else:
        assert len(err) == 1, err                    # one line, no traceback
    want = prefix + row.msg.replace("{d}", str(files.d))
    assert err[-1].startswith(want), f"{err[-1]!r} does not start with {want!r}"


def test_cli_interrupt_exits_130(monkeypatch, capsys):
    import rgbz_fast._cli as cli

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli, "_config", interrupted)
    assert main(["config"]) == 130
    assert capsys.readouterr().err.strip() == "rgbz-fast config: interrupted"


# --------------------------------------------------------------------------- accepted on purpose
def test_accepted_on_purpose():
    """The inputs docs/reports/robustness.md lists as accepted, not errors."""
    p = rz.mask1()
    d = np.random.default_rng(0).integers(0, 2048, (12, 10)).astype(np.uint16)
    d[p.z_mask(d.shape)] = 0
    want = rz.reconstruct(d, "sg", pattern=p)
    junk = d.copy()
    junk[p.z_mask(d.shape)] = 65535                     # beyond 11 bits, at Z sites only
    np.testing.assert_array_equal(rz.reconstruct(junk, "sg", pattern=p), want)
    masked = np.ma.array(d, mask=np.ones(d.shape, bool))
    np.testing.assert_array_equal(rz.reconstruct(masked, "sg", pattern=p), want)
    np.testing.assert_array_equal(rz.reconstruct(np.asfortranarray(d), "sg", pattern=p), want)
    wide = np.zeros((12, 20), np.uint16)
    wide[:, ::2] = d
    np.testing.assert_array_equal(rz.reconstruct(wide[:, ::2], "sg", pattern=p), want)
    np.testing.assert_array_equal(rz.reconstruct(d, "sg", pattern=p, workers=1024), want)
    tiny = rz.reconstruct(d.astype(np.float64), "edi_line", pattern=p, sigma_floor=5e-324,
                          sigma_rel=0.0)
    assert np.all(np.isfinite(tiny)) and tiny.max() <= 2047
    with pytest.warns(RuntimeWarning):
        assert metrics.cfa_psnr(_f64(), _f64(value=1e300), data_range=1.0) == -np.inf


# --------------------------------------------------------------------------- no partial output
def test_failed_calls_leave_inputs_and_files_untouched(files, tmp_path):
    """A call that raises modifies neither its input arrays nor existing output files."""
    data = _with(np.nan)
    before = data.copy()
    with pytest.raises(ValueError):
        rz.reconstruct(data, pattern="mask1")
    np.testing.assert_array_equal(data, before)
    target = tmp_path / "frame.npz"
    frameio.save_frame(target, _frame())
    blob = target.read_bytes()
    with pytest.raises(ValueError):
        frameio.save_frame(tmp_path / "frame.jpg", _frame())
    assert target.read_bytes() == blob
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frame.npz"]


def test_atomic_write_failure_keeps_the_old_file(tmp_path, monkeypatch):
    """A write that fails half-way (bad data, a full disk, a failed rename) keeps the old file."""
    target = tmp_path / "report.json"
    rio.atomic_write(target, '{"old": true}')
    with pytest.raises(TypeError):
        rio.atomic_write(target, 12345)                # not str or bytes
    with pytest.raises(IsADirectoryError):
        rio.atomic_write(tmp_path, "x")                # the target is a folder

    def replace_fails(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", replace_fails)
    with pytest.raises(OSError):
        rio.atomic_write(target, '{"new": true}')
    monkeypatch.undo()
    assert json.loads(target.read_text()) == {"old": True}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.json"]   # no temp file left


# --------------------------------------------------------------------------- unreadable files
def _call_without_leaks(fn):
    """Call ``fn`` and collect garbage; fail on an unclosed file (ResourceWarning).

    Returns the exception ``fn`` raised as (type, message), or None: the
    exception itself is not kept, since its traceback would keep a leaked file
    object alive past the garbage collection.
    """
    import gc
    import warnings

    err = None
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ResourceWarning)
        try:
            fn()
        except Exception as exc:  # noqa: BLE001 - the caller checks type and message
            err = (type(exc), str(exc))
        gc.collect()
    leaks = [str(w.message) for w in caught if issubclass(w.category, ResourceWarning)]
    assert not leaks, leaks
    return err


def _npz(path, **arrays):
    np.savez(path, **arrays)
    return path


def test_unreadable_files_name_the_path_and_leak_no_handle(files, tmp_path):
    """B1, B7: every way a frame or image file can be broken is one ValueError naming the
    file and what is wrong with it, on one line, and no file handle is left open."""
    blob = (files / "ok.npz").read_bytes()
    flipped = bytearray(blob)
    for i in range(40, len(blob) // 2):          # inside the first member's deflate stream
        flipped[i] ^= 0xFF
    (tmp_path / "flipped.npz").write_bytes(bytes(flipped))
    header = {"format": "rgbz-fast raw frame", "pattern": "ZG/GR", "bit_depth": 11}
    np.save(tmp_path / "array.npy", _u16())
    (tmp_path / "array.npz").write_bytes((tmp_path / "array.npy").read_bytes())
    cases = [
        (files / "truncated.npz", lambda p: frameio.load_frame(p), "not an NPZ archive"),
        (files / "junk.npz", lambda p: frameio.load_frame(p), "no zip signature"),
        (tmp_path / "array.npz", lambda p: frameio.load_frame(p), "no zip signature"),
        (files / "foreign.npz", lambda p: frameio.load_frame(p), "no header/data"),
        (files / "nokeys.npz", lambda p: frameio.load_frame(p), "missing key 'pattern'"),
        (files / "notjson.npz", lambda p: frameio.load_frame(p), "the header is not JSON"),
        (_npz(tmp_path / "list.npz", data=_u16(), header=np.array("[1]")),
         lambda p: frameio.load_frame(p), "the header is a JSON list"),
        (_npz(tmp_path / "bits.npz", data=_u16(), header=np.array(json.dumps(
            {**header, "bit_depth": 40}))), lambda p: frameio.load_frame(p),
         "bit_depth: expected 1..16 bits"),
        (_npz(tmp_path / "tile.npz", data=_u16(), header=np.array(json.dumps(
            {**header, "pattern": "ZX/GR"}))), lambda p: frameio.load_frame(p),
         "tile: unknown channel letter"),
        (tmp_path / "flipped.npz", lambda p: frameio.load_frame(p), "is not a readable"),
        (files / "truncated.tif", lambda p: frameio.load_frame(p), "cannot read"),
        (files / "truncated.tif", lambda p: frameio.load_frame(p, pattern="mask1",
                                                               bit_depth=11), "cannot read"),
        (files / "corrupt.png", lambda p: frameio.load_frame(p, pattern="mask1",
                                                             bit_depth=11), "cannot read"),
        (files / "corrupt.png", lambda p: rawio.read_raw(p, phase="GRBG", black_level=0,
                                                         bit_depth_in=8), "cannot read"),
        (files / "truncated.tif", lambda p: rawio.read_raw(p, phase="GRBG", black_level=0,
                                                           bit_depth_in=8), "cannot read"),
        (files / "corrupt.png", lambda p: rio.ImageSource("c", str(p)).load(), "cannot read"),
        (files / "corrupt.png", lambda p: scene.load_image(p), "cannot read"),
    ]
    for path, call, reason in cases:
        err = _call_without_leaks(lambda: call(path))
        assert err is not None, f"{path.name}: no error"
        kind, msg = err
        assert kind is ValueError, (path.name, kind, msg)
        assert str(path) in msg and reason in msg, (path.name, msg)
        assert msg.split(":")[0] in ("path", "dataset") and "\n" not in msg, msg


def test_cli_reconstruct_of_a_broken_frame_writes_nothing(files, tmp_path, capsys):
    """B1: exit 2, one line naming the file, no traceback, no output file."""
    out = tmp_path / "out"
    for name in ("truncated.npz", "nokeys.npz", "notjson.npz"):
        assert main(["reconstruct", str(files / name), "--out", str(out), "--quiet"]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1, err
        assert err[0].startswith(f"rgbz-fast reconstruct: error: path: {files / name} is not "
                                 "a readable rgbz-fast frame"), err
    assert not out.exists() or not [p for p in out.rglob("*") if p.is_file()]


def test_write_reports_of_no_rows_writes_nothing(tmp_path):
    """B9: an empty Results is an error before anything is written; old reports stay."""
    empty = ev.Results([], ev.EvalConfig())
    with pytest.raises(ValueError, match="^results: no rows to report"):
        ev.write_reports(empty, tmp_path / "new")
    assert not (tmp_path / "new").exists()
    rows = [{"image": "a", "pattern": "mask1", "method": "sg", "metric": "cfa_psnr",
             "value": 30.0}]
    full = ev.Results(rows, ev.EvalConfig(patterns=("mask1",), methods=("sg",),
                                          metrics=("cfa_psnr",)))
    written = ev.write_reports(full, tmp_path / "old", plots=False)
    before = {p: p.read_bytes() for p in written}
    with pytest.raises(ValueError, match="^results: no rows to report"):
        ev.write_reports(empty, tmp_path / "old", plots=False)
    with pytest.raises(ValueError, match="^table_image: 'b' is not in the results"):
        ev.write_reports(full, tmp_path / "old", plots=False, table_image="b")
    assert {p: p.read_bytes() for p in (tmp_path / "old").iterdir()} == before


def test_eval_config_is_checked_and_normalised_at_construction():
    """B6: a bad field fails at EvalConfig(...), naming it; good values are normalised so
    that equal configurations share their cache key."""
    cfg = ev.EvalConfig(params=rz.ReconstructParams(precision="float64", sg_mode="pure",
                                                    exp="fast"))
    as_dict = ev.EvalConfig(params={"precision": "float64", "exp": "fast", "sg_mode": "pure"})
    assert as_dict.params == cfg.params and isinstance(as_dict.params, rz.ReconstructParams)
    assert as_dict.key("mask1", "sg") == cfg.key("mask1", "sg")
    assert cfg.key("mask1", "sg") != ev.EvalConfig().key("mask1", "sg")
    hash(as_dict)                                              # still hashable
    np_typed = ev.EvalConfig(bit_depth=np.int64(11), noise=np.False_, seed=np.uint8(0))
    assert np_typed.key("mask1", "sg") == ev.EvalConfig().key("mask1", "sg")
    assert type(np_typed.bit_depth) is int and np_typed.noise is False
    # every field of the parameters is accepted, and what is accepted runs
    frame = rz.mosaic(_rgb((8, 8)), "mask1")
    for k, v in rz.ReconstructParams().as_dict().items():
        params = ev.EvalConfig(params={k: v}).params
        rz.reconstruct(frame, "sg", params=params)
    for bad, exc in (({"method": "sg"}, TypeError), ({"pattern": "mask1"}, TypeError),
                     ({"sigma_rel": None}, TypeError), ({1: 2}, TypeError),
                     ({"domain": "lab"}, ValueError), ({"clip_level": -1}, ValueError),
                     ({"clip_level": "high"}, TypeError), ({"out": None}, TypeError)):
        with pytest.raises(exc):
            ev.EvalConfig(params=bad)


def test_ssim_data_range_at_its_bounds_is_scale_invariant():
    """B4: within [1e-100, 1e100] SSIM and MS-SSIM are finite and do not depend on the
    scale of the data (the constants scale with data_range), without any warning."""
    rng = np.random.default_rng(0)
    a = rng.random((161, 161))
    b = np.clip(a + rng.normal(0, 0.05, a.shape), 0, 1)
    want_ssim = metrics.ssim(a, b, data_range=1.0)
    want_ms = metrics.ms_ssim(a, b, data_range=1.0)
    assert 0 < want_ms < 1 and 0 < want_ssim < 1
    for L in metrics.SSIM_DATA_RANGE:
        assert metrics.ssim(a * L, b * L, data_range=L) == pytest.approx(want_ssim, rel=1e-9)
        assert metrics.ms_ssim(a * L, b * L, data_range=L) == pytest.approx(want_ms, rel=1e-9)
    assert metrics.ssim(np.zeros((16, 16)), np.zeros((16, 16)), data_range=1e-100) == 1.0


def test_fixed_checks_keep_the_valid_calls():
    """B5, B9: the new checks reject only what was wrong before."""
    img = _u8img(value=200)
    want = rz.mosaic(img, "mask1").data
    np.testing.assert_array_equal(rz.mosaic(img, "mask1", dtype="uint16").data, want)
    np.testing.assert_array_equal(rz.mosaic(img, "mask1", input_bits=np.int64(8)).data, want)
    a = np.array([[0, 1020], [5, 1023]])
    for level in (1020, np.float32(1020), 1020.0):
        np.testing.assert_array_equal(rawio.clipped_mask(a, level), a >= 1020)
    for dt in (np.float32, "float64"):
        wb, _ = isp.white_balance(_u16(value=1000), "bayer", dtype=dt)
        assert wb.dtype == np.dtype(dt) and 0 < wb.min() <= wb.max() <= 1
    sources = (rio.ImageSource(n, f"skimage:{n}") for n in ["coffee"])   # any iterable
    res = ev.evaluate(sources, metrics=("cfa_psnr",), methods=("bilinear",),
                      patterns=("mask1",), workers=1, progress=False)
    assert len(res) == 1 and np.isfinite(res.rows[0]["value"])


# --------------------------------------------------------------------------- read-only, large
def test_read_only_and_memory_mapped_inputs_are_accepted(tmp_path):
    d = np.random.default_rng(0).integers(0, 2048, (64, 96)).astype(np.uint16)
    d[rz.mask1().z_mask(d.shape)] = 0
    want = rz.reconstruct(d, "sg", pattern="mask1")
    ro = d.copy()
    ro.setflags(write=False)
    np.testing.assert_array_equal(rz.reconstruct(ro, "sg", pattern="mask1"), want)
    np.save(tmp_path / "d.npy", d)
    mm = np.load(tmp_path / "d.npy", mmap_mode="r")
    np.testing.assert_array_equal(rz.reconstruct(mm, "sg", pattern="mask1"), want)
    np.testing.assert_array_equal(rz.reconstruct(rz.RawFrame(mm, "mask1"), "sg"), want)
    rgb = demosaic(want, "GRBG")
    ro_cfa = want.copy()
    ro_cfa.setflags(write=False)
    np.testing.assert_array_equal(demosaic(ro_cfa, "GRBG"), rgb)
    taps = np.random.default_rng(1).integers(0, 2048, (3, 4, 50)).astype(np.uint16)
    taps.setflags(write=False)
    tof_isp.demodulate(taps)


LARGE_SCRIPT = textwrap.dedent("""
    import json, resource, sys, time, tracemalloc
    import numpy as np
    import rgbz_fast as rz

    def rss_mb():                 # resident now (Linux), else the high-water mark
        try:
            with open("/proc/self/status") as fh:
                return next(int(l.split()[1]) for l in fh if l.startswith("VmRSS:")) / 1024
        except (OSError, StopIteration):
            return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024

    rows, cols = 8660, 5776
    data = np.zeros((rows, cols), np.uint16)
    rng = np.random.default_rng(0)
    for r0 in range(0, rows, 1024):                       # 11-bit content, chunk by chunk
        data[r0:r0 + 1024] = rng.integers(0, 2048, data[r0:r0 + 1024].shape, dtype=np.uint16)
    zero = np.tile(np.array([[0, 1], [1, 1]], np.uint16), (1, cols // 2))
    for r0 in range(0, rows, 1024):                       # Z sites (Mask1: even rows, even cols)
        data[r0:r0 + 1024] *= np.tile(zero, (512, 1))[:data[r0:r0 + 1024].shape[0]]
    data.setflags(write=False)                            # a read-only input is accepted
    rz.reconstruct(data[:64, :64], "sg", pattern="mask1")  # warm up (plans, imports)
    def status_mb(key):
        with open("/proc/self/status") as fh:
            return next(int(l.split()[1]) for l in fh if l.startswith(key)) / 1024

    with open("/proc/self/clear_refs", "w") as fh:      # reset the high-water mark (VmHWM)
        fh.write("5")
    base = rss_mb()
    peak_before = status_mb("VmHWM:")
    tracemalloc.start()
    t0 = time.perf_counter()
    out = rz.reconstruct(data, "sg", pattern="mask1", precision="float32")
    dt = time.perf_counter() - t0
    _, traced_peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    peak = status_mb("VmHWM:")
    assert out.shape == data.shape and out.dtype == np.uint16
    assert int(out.max()) <= 2047 and int(out[0, 0]) > 0
    print(json.dumps({"seconds": dt, "input_mb": data.nbytes / 2**20,
                      "output_mb": out.nbytes / 2**20, "rss_before_mb": base,
                      "rss_peak_mb": peak, "rss_delta_mb": peak - base,
                      "peak_was_set_by_this_call": peak >= peak_before,
                      "traced_peak_mb": traced_peak / 2**20}))
""")


@pytest.mark.slow
def test_50_megapixel_reconstruction_runs_within_memory():
    """8660x5776 uint16 Mask1, SG, float32, read-only input: peak memory near input + output.

    Run in a fresh process whose preparation stays below the call's own peak, so that
    ru_maxrss (a high-water mark) minus the resident size before the call is the
    call's peak: it must stay below the output plus two input-sized temporaries (the
    validation's masks); tracemalloc's peak of the call (numpy allocations) likewise.
    About 5 s on two cores; ``pytest -m slow tests/test_robustness.py`` runs it alone.
    """
    if not Path("/proc/self/clear_refs").exists():
        pytest.skip("needs Linux /proc/self/clear_refs to reset the peak-RSS counter")
    r = subprocess.run([sys.executable, "-c", LARGE_SCRIPT], capture_output=True, text=True,
                       timeout=900)
    assert r.returncode == 0, r.stderr[-3000:]
    m = json.loads(r.stdout.strip().splitlines()[-1])
    print("\n50 MP reconstruction:", json.dumps(m))
    budget = m["output_mb"] + 2.0 * m["input_mb"]
    assert m["peak_was_set_by_this_call"] and m["rss_delta_mb"] < budget, m
    assert m["traced_peak_mb"] < budget, m


# --------------------------------------------------------------------------- interrupted runs
def _cache_files(cache):
    return sorted(p for p in Path(cache).rglob("*") if p.is_file())


def test_killed_evaluate_resumes_from_its_cache(tmp_path):
    """SIGKILL `rgbz-fast evaluate` once its first cache file exists; the rerun resumes.

    Nothing visible is ever half-written: every cache file of the killed run parses,
    temporary files are hidden (".name.XXXX.tmp") and never carry a final name, and
    the reports are either absent or complete. The resumed run reuses every cached
    result (the files are not rewritten) and gives the numbers of a fresh run.
    """
    import imageio.v3 as iio

    ds = tmp_path / "ds"
    ds.mkdir()
    rng = np.random.default_rng(0)
    for i in range(4):
        img = rng.integers(0, 256, (96, 128, 3), dtype=np.uint8)
        iio.imwrite(ds / f"img{i}.png", img)
    out, cache = tmp_path / "out", tmp_path / "cache"
    argv = [sys.executable, "-m", "rgbz_fast", "evaluate", "--dataset", str(ds), "--out",
            str(out), "--cache", str(cache), "--processes", "1", "--quiet", "--no-plots",
            "--metrics", "cfa_psnr,cpsnr", "--methods", "bilinear,bi,edi_central,edi_line,sg",
            "--patterns", "mask1,mask2"]
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 300
    visible = []
    while time.monotonic() < deadline and proc.poll() is None:
        visible = [p for p in _cache_files(cache) if not p.name.startswith(".")]
        if visible:
            break
        time.sleep(0.005)
    assert proc.poll() is None, "evaluate finished before it could be killed"
    assert visible, "no cache file appeared"
    proc.send_signal(signal.SIGKILL)
    proc.communicate(timeout=60)
    assert proc.returncode == -signal.SIGKILL

    # nothing half-written under a final name
    survivors = _cache_files(cache)
    finals = [p for p in survivors if not p.name.startswith(".")]
    assert finals
    for p in finals:
        assert p.suffix == ".json" and isinstance(json.loads(p.read_text()), dict), p
    for p in survivors:
        if p.name.startswith("."):
            assert p.name.endswith(".tmp"), p
    for p in _cache_files(out) if out.exists() else []:
        if p.suffix == ".json" and p.parent == out:
            json.loads(p.read_text())
    mtimes = {p: p.stat().st_mtime_ns for p in finals}

    # resume: the rerun finishes, reuses the cached results and equals a fresh run
    r = subprocess.run(argv + ["--json"], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr[-3000:]
    resumed = json.loads(r.stdout)
    for p, t in mtimes.items():
        assert p.stat().st_mtime_ns == t, f"{p} was recomputed"
    fresh = ev.evaluate(rio.folder_dataset(ds), ev.EvalConfig(
        patterns=("mask1", "mask2"), methods=("bilinear", "bi", "edi_central", "edi_line", "sg"),
        metrics=("cfa_psnr", "cpsnr")), workers=1, progress=False)
    for (p, m, k), (mean, _, n) in fresh.summary().items():
        got = resumed[f"{p}/{m}/{k}"]
        assert got["n"] == n and got["mean"] == pytest.approx(mean, rel=1e-12), (p, m, k)
    reports = sorted(q.name for q in out.iterdir() if q.is_file())
    assert {"results.csv", "results.json", "summary.md"} <= set(reports)
    assert not [q for q in out.iterdir() if q.name.endswith(".tmp")]


WRITE_LOOP = textwrap.dedent("""
    import signal, sys
    from pathlib import Path
    from rgbz_fast import _cli, io as rio
    signal.signal(signal.SIGTERM, _cli._terminate)      # what `rgbz-fast CMD` installs
    blob = bytes(range(256)) * (1 << 17)                # 32 MiB per write
    print("ready", flush=True)
    i = 0
    try:
        while True:
            rio.atomic_write(Path(sys.argv[1]) / f"f{i % 3}.bin", blob)
            i += 1
    except _cli.Terminated as exc:
        sys.exit(exc.code)
""")


@pytest.mark.skipif(not hasattr(signal, "SIGTERM"), reason="POSIX signals")
def test_sigterm_during_writes_leaves_no_temporary_file(tmp_path):
    """SIGTERM used to kill the process inside atomic_write and leave its hidden .tmp file;
    the command line's handler turns it into an exception, and the write cleans up."""
    out = tmp_path / "w"
    out.mkdir()
    for delay in (0.02, 0.13, 0.31, 0.57):
        proc = subprocess.Popen([sys.executable, "-c", WRITE_LOOP, str(out)],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert proc.stdout.readline().strip() == "ready", proc.stderr.read()
        time.sleep(delay)
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=60)
        assert proc.returncode == 128 + signal.SIGTERM, err[-2000:]
        left = sorted(p.name for p in out.iterdir())
        assert not [n for n in left if n.endswith(".tmp")], left
        for p in out.iterdir():
            assert p.stat().st_size == 256 << 17          # whole files only


def _children(pid):
    """Live (non-zombie) processes whose parent is ``pid``, from /proc."""
    out = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            fields = stat.rsplit(")", 1)[1].split()
            if int(fields[1]) == pid and fields[0] != "Z":
                out.append(int(entry.name))
    return out


def _alive(pid):
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc: Linux")
def test_sigterm_stops_the_evaluation_pool(tmp_path):
    """SIGTERM to `rgbz-fast evaluate --processes 2` left its two workers running; now the
    pool is stopped before the process exits (143), and no temporary cache file is left."""
    import imageio.v3 as iio

    ds = tmp_path / "ds"
    ds.mkdir()
    rng = np.random.default_rng(1)
    for i in range(6):
        iio.imwrite(ds / f"img{i}.png", rng.integers(0, 256, (256, 320, 3), dtype=np.uint8))
    cache = tmp_path / "cache"
    argv = [sys.executable, "-m", "rgbz_fast", "evaluate", "--dataset", str(ds), "--out",
            str(tmp_path / "out"), "--cache", str(cache), "--processes", "2", "--quiet",
            "--no-plots"]
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 300
    workers = []
    while time.monotonic() < deadline and proc.poll() is None:
        workers = [c for c in _children(proc.pid)
                   if "multiprocessing" in Path(f"/proc/{c}/cmdline").read_text()]
        if len(workers) >= 2 and list(cache.rglob("*.json")):
            break
        time.sleep(0.02)
    assert proc.poll() is None and len(workers) >= 2, "the pool never ran"
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 128 + signal.SIGTERM, err[-2000:]
    assert err.strip().splitlines()[-1] == "rgbz-fast evaluate: terminated"
    time.sleep(0.5)
    assert not [w for w in workers if _alive(w)], "orphaned worker processes"
    assert not [p for p in cache.rglob("*") if p.name.endswith(".tmp")]


REPORT_LOOP = textwrap.dedent("""
    import sys
    from pathlib import Path
    from rgbz_fast import evaluation as ev
    rows = [{"image": f"img{i}", "pattern": p, "method": m, "metric": k, "value": i * 0.5}
            for i in range(60) for p in ("mask1", "mask2")
            for m in ("bilinear", "bi", "edi_central", "edi_line", "sg")
            for k in ("cfa_psnr", "cpsnr", "ssim", "ms_ssim", "zipper")]
    res = ev.Results(rows, ev.EvalConfig())
    print("ready", flush=True)
    while True:
        ev.write_reports(res, Path(sys.argv[1]), plots=False)
""")


def test_reports_are_never_half_written_when_killed(tmp_path):
    """Kill a process that rewrites the reports in a loop, at several moments; every
    visible report is complete (CSV rows, JSON that parses, Markdown tables whole).

    Each file is all-or-nothing; the set is written file by file, so a kill between
    two files leaves the earlier ones new and the later ones from the previous run.
    """
    out = tmp_path / "reports"
    checked = 0
    for delay in (0.05, 0.37, 0.81):            # one round of reports takes ~0.35 s
        proc = subprocess.Popen([sys.executable, "-c", REPORT_LOOP, str(out)],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert proc.stdout.readline().strip() == "ready", proc.stderr.read()
        time.sleep(delay)
        proc.kill()
        proc.communicate(timeout=60)
        for p in (out.iterdir() if out.exists() else ()):
            if p.name.startswith("."):
                assert p.name.endswith(".tmp")      # a temporary file, never a final name
                continue
            text = p.read_text()
            checked += 1
            if p.name == "results.csv":
                assert len(text.splitlines()) == 1 + 60 * 2 * 5 * 5 and text.endswith("\n")
            elif p.name == "results.json":
                assert len(json.loads(text)["rows"]) == 60 * 2 * 5 * 5
            elif p.name == "summary.md":
                # per mask: the means table and the paired differences to bilinear
                assert text.endswith("\n") and text.count("| SG |") == 4, text[-200:]
            elif p.suffix == ".md":
                assert text.endswith("\n") and text.count("| Zipper (%) |") == 2, text[-200:]
    assert checked >= 4, "the reports were never written before the kills"


# --------------------------------------------------------------------------- the document
def _cell(text):
    return text.replace("|", "\\|")


def markdown_tables():
    """The two contract tables of docs/reports/robustness.md, generated from ROWS and CLI_ROWS."""
    lines = ["| id | call (bad input) | gets | status |", "|---|---|---|---|"]
    for r in ROWS:
        status = f"**bug {r.bug}**" if r.bug else "ok"
        lines.append(f"| `{r.id}` | `{_cell(r.call)}` | {_cell(r.exc.__name__)} "
                     f"`{_cell(r.msg.replace('{d}/', ''))}...` | {status} |")
    api = "\n".join(lines)
    lines = ["| id | command line | exit, stderr | status |", "|---|---|---|---|"]
    for r in CLI_ROWS:
        argv = " ".join(r.argv).replace("{d}/", "")
        shown = ("usage lines, then " if r.usage else "one line ") + \
            f"`{_cli_prefix(r.argv[0])}{_cell(r.msg)}...`".replace("{d}/", "")
        status = f"**bug {r.bug}**" if r.bug else "ok"
        lines.append(f"| `{r.id}` | `rgbz-fast {_cell(argv)}` | 2, {shown} | {status} |")
    cli = "\n".join(lines)
    return api, cli


def _between(text, start, end):
    i, j = text.index(start) + len(start), text.index(end)
    return text[i:j].strip()


def test_docs_table_matches_the_rows():
    """docs/reports/robustness.md lists exactly these rows (regenerate: python tests/test_robustness.py)."""
    text = DOC.read_text()
    api, cli = markdown_tables()
    assert _between(text, "<!-- api-table:start -->", "<!-- api-table:end -->") == api
    assert _between(text, "<!-- cli-table:start -->", "<!-- cli-table:end -->") == cli
    for bug, what in BUGS.items():
        assert f"**{bug} — " in text, f"{bug} is not described in docs/reports/robustness.md"


if __name__ == "__main__":      # regenerate the tables of docs/reports/robustness.md
    import re

    api, cli = markdown_tables()
    text = DOC.read_text()
    for name, table in (("api", api), ("cli", cli)):
        text = re.sub(rf"(<!-- {name}-table:start -->\n).*?(<!-- {name}-table:end -->)",
                      lambda m, t=table: m.group(1) + t + "\n" + m.group(2), text, flags=re.S)
    DOC.write_text(text)
    print(f"wrote {len(ROWS)} API rows and {len(CLI_ROWS)} CLI rows to {DOC}")
