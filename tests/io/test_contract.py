"""The bad-input contract of rgbz_fast.io: raw files, frame files, guarded reads, datasets.

Rows of docs/reports/robustness.md (``io.*``), run by the shared runner of
``tests/_contract.py``; then the guarantees about files: a failed call changes no
input and no existing file, a failed write keeps the old file, and every way a file
can be broken is one ValueError naming it, with no file handle left open.
"""

from __future__ import annotations

import json
import os

import numpy as np
import pytest

import rgbz_fast as rz
from _contract import (Row, api_tests, f64, files, small_frame, u16, with_env,  # noqa: F401
                       with_value)
from rgbz_fast import io as rio
from rgbz_fast import simulation as sim

R = Row


def bad_frame(id_, name, what, reason, **kw):
    """A row: load_frame of the hostile NPZ ``name`` is 'not a readable frame'."""
    return Row(f"io.load_frame-{id_}", f"load_frame({what})",
               lambda f: rio.load_frame(f / f"{name}.npz", **kw), ValueError,
               f"path: {{d}}/{name}.npz is not a readable rgbz-fast frame ({reason}")


ROWS = [
    # -- read_raw, list_raw_files, to_rgbz, clipped_mask -----------------------------------
    R("io.read_raw-no-shape", "read_raw(headerless, no shape)",
      lambda f: rio.read_raw(f / "bayer.raw", phase="GRBG", black_level=0, bit_depth_in=10),
      ValueError, "shape: the headerless file bayer.raw needs shape=(rows, cols)"),
    R("io.read_raw-size", "read_raw(headerless, wrong shape)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 5), phase="GRBG", black_level=0,
                             bit_depth_in=10), ValueError,
      "shape: bayer.raw holds 32 bytes, but 4x5 uint16 pixels need 40"),
    R("io.read_raw-shape-negative", "read_raw(shape=(-4, -4))",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(-4, -4), phase="GRBG", black_level=0,
                             bit_depth_in=10), ValueError,
      "shape: expected positive (rows, cols)"),
    R("io.read_raw-no-phase", "read_raw(headerless, no phase)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), black_level=0, bit_depth_in=10),
      ValueError, "phase: bayer.raw does not record its CFA phase"),
    R("io.read_raw-phase", "read_raw(phase='XXXX')",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="XXXX", black_level=0,
                             bit_depth_in=10), ValueError, "phase: expected one of"),
    R("io.read_raw-no-black", "read_raw(headerless, no black_level)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", bit_depth_in=10),
      ValueError, "black_level: bayer.raw does not record its black level"),
    R("io.read_raw-no-white", "read_raw(headerless, no white_level)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0),
      ValueError, "white_level: bayer.raw does not record its white level"),
    R("io.read_raw-white-below-black", "read_raw(black_level=100, white_level=50)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=100,
                             white_level=50), ValueError, "white_level: "),
    R("io.read_raw-black-nan", "read_raw(black_level=nan)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG",
                             black_level=np.nan, white_level=50), ValueError,
      "black_level: expected finite non-negative values"),
    R("io.read_raw-black-text", "read_raw(black_level='a')",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG",
                             black_level="a", white_level=50), TypeError,
      "black_level: expected a number or four numbers"),
    R("io.read_raw-black-count", "read_raw(black_level=[1, 2, 3])",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG",
                             black_level=[1, 2, 3], white_level=50), ValueError,
      "black_level: expected one value or four"),
    R("io.read_raw-byteorder", "read_raw(byteorder='=')",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                             bit_depth_in=10, byteorder="="), ValueError,
      "byteorder: expected '<' (little-endian) or '>' (big-endian)"),
    R("io.read_raw-downsample", "read_raw(downsample=0)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                             bit_depth_in=10, downsample=0), ValueError,
      "downsample: expected a positive integer binning factor"),
    R("io.read_raw-downsample-large", "read_raw(4x4, downsample=3)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                             bit_depth_in=10, downsample=3), ValueError,
      "downsample: a 4x4 frame holds no 6x6 block to bin"),
    R("io.read_raw-dtype", "read_raw(dtype=int32)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                             bit_depth_in=10, dtype=np.int32), TypeError,
      "dtype: expected one of uint8, uint16, float32, float64"),
    R("io.read_raw-dtype-unknown", "read_raw(dtype='junk')",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                             bit_depth_in=10, dtype="junk"), TypeError,
      "dtype: expected one of uint8, uint16, float32, float64, got 'junk'"),
    R("io.read_raw-uint8-bits", "read_raw(dtype=uint8, bit_depth=11)",
      lambda f: rio.read_raw(f / "bayer.raw", shape=(4, 4), phase="GRBG", black_level=0,
                             bit_depth_in=10, dtype=np.uint8), ValueError,
      "dtype: uint8 cannot hold 11-bit data"),
    R("io.read_raw-reader", "read_raw(reader='xyz')",
      lambda f: rio.read_raw(f / "bayer.raw", reader="xyz"), ValueError,
      "reader: expected one of 'libraw', 'image', 'headerless'"),
    R("io.read_raw-missing", "read_raw('missing.raw')",
      lambda f: rio.read_raw(f / "missing.raw", shape=(4, 4)), FileNotFoundError,
      "path: no such file"),
    R("io.read_raw-extension", "read_raw('notes.xyz')",
      lambda f: rio.read_raw(f / "notes.xyz"), ValueError,
      "path: unknown raw extension '.xyz' of notes.xyz"),
    R("io.read_raw-shape-not-headerless", "read_raw('rgb.png', shape=(4, 4))",
      lambda f: rio.read_raw(f / "rgb.png", shape=(4, 4)), ValueError,
      "shape: only headerless files take a shape"),
    R("io.read_raw-1x1", "read_raw(1x1 headerless)",
      lambda f: rio.read_raw(f / "one.raw", shape=(1, 1), phase="GRBG", black_level=0,
                             bit_depth_in=10), ValueError,
      "one.raw: frame 1x1 is smaller than one Bayer quad"),
    R("io.read_raw-rgb", "read_raw(RGB .png)",
      lambda f: rio.read_raw(f / "rgb.png", phase="GRBG", black_level=0, bit_depth_in=8),
      ValueError, "rgb.png: expected a single-channel Bayer mosaic"),
    R("io.read_raw-corrupt-dng", "read_raw(corrupt .dng)",
      lambda f: rio.read_raw(f / "corrupt.dng"), ValueError, "path: LibRaw cannot read"),
    R("io.read_raw-corrupt-png", "read_raw(corrupt .png)",
      lambda f: rio.read_raw(f / "corrupt.png", phase="GRBG", black_level=0, bit_depth_in=8),
      ValueError, "path: cannot read"),
    R("io.read_raw-corrupt-tiff", "read_raw(truncated .tif)",
      lambda f: rio.read_raw(f / "truncated.tif", phase="GRBG", black_level=0,
                             bit_depth_in=8), ValueError, "path: cannot read"),
    R("io.list_raw_files-not-folder", "list_raw_files(a file)",
      lambda f: rio.list_raw_files(f / "file.txt"), NotADirectoryError,
      "folder: not a directory"),
    R("io.to_rgbz-array", "to_rgbz(ndarray)", lambda f: rio.to_rgbz(u16(), "mask1"),
      TypeError, "frame: expected a RawFrame"),
    R("io.to_rgbz-has-z", "to_rgbz(mask1 frame)",
      lambda f: rio.to_rgbz(small_frame(), "mask1"), ValueError,
      "frame: pattern 'mask1' already has Z sites"),
    R("io.to_rgbz-pattern", "to_rgbz(pattern='bayer')",
      lambda f: rio.to_rgbz(small_frame("bayer"), "bayer"), ValueError,
      "pattern: 'bayer_grbg' has no Z sites; expected 'mask1', 'mask2', 'rows' or a tile"),
    R("io.to_rgbz-phase", "to_rgbz(GRBG frame, 'mask1_rggb')",
      lambda f: rio.to_rgbz(small_frame("bayer"), "mask1_rggb"), ValueError,
      "pattern: 'mask1_rggb' asks for Bayer phase 'RGGB'"),
    R("io.to_rgbz-pattern-type", "to_rgbz(pattern=3)",
      lambda f: rio.to_rgbz(small_frame("bayer"), 3), TypeError,
      "pattern: expected a preset name or a Pattern"),
    R("io.to_rgbz-small", "to_rgbz(2x2, 'mask2')",
      lambda f: rio.to_rgbz(small_frame("bayer", (2, 2)), "mask2"), ValueError,
      "frame: 2x2 is smaller than one period (4x4)"),
    R("io.clipped_mask-no-level", "clipped_mask(array)",
      lambda f: rio.clipped_mask(f64()), ValueError,
      "clip_level: a plain array needs clip_level="),
    R("io.clipped_mask-ndim", "clipped_mask(3-D, 5)",
      lambda f: rio.clipped_mask(np.zeros((4, 4, 3)), 5), ValueError,
      "frame: expected a 2-D array"),
    R("io.clipped_mask-radius", "clipped_mask(radius=-1)",
      lambda f: rio.clipped_mask(f64(), 5, radius=-1), ValueError,
      "radius: expected a non-negative integer"),
    R("io.clipped_mask-radius-float", "clipped_mask(radius=1.5)",
      lambda f: rio.clipped_mask(f64(), 5, radius=1.5), ValueError,
      "radius: expected a non-negative integer"),
    R("io.clipped_mask-level-nan", "clipped_mask(clip_level=nan)",
      lambda f: rio.clipped_mask(f64(), np.nan), ValueError,
      "clip_level: expected a finite number, got nan"),
    R("io.clipped_mask-level-text", "clipped_mask(clip_level='a')",
      lambda f: rio.clipped_mask(f64(), "a"), TypeError,
      "clip_level: expected a number, got 'a'"),
    # -- save_frame, load_frame ------------------------------------------------------------
    R("io.save_frame-type", "save_frame(path, ndarray)",
      lambda f: rio.save_frame(f / "x.npz", u16()), TypeError,
      "frame: expected a RawFrame"),
    R("io.save_frame-suffix", "save_frame('x.jpg', frame)",
      lambda f: rio.save_frame(f / "x.jpg", small_frame()), ValueError,
      "path: unsupported frame file type '.jpg'"),
    R("io.load_frame-missing", "load_frame('missing.npz')",
      lambda f: rio.load_frame(f / "missing.npz"), ValueError, "path: "),
    R("io.load_frame-foreign", "load_frame(NPZ without header/data)",
      lambda f: rio.load_frame(f / "foreign.npz"), ValueError, "path: "),
    R("io.load_frame-truncated", "load_frame(truncated NPZ)",
      lambda f: rio.load_frame(f / "truncated.npz"), ValueError, "path: "),
    R("io.load_frame-junk", "load_frame(NPZ that is not a zip)",
      lambda f: rio.load_frame(f / "junk.npz"), ValueError, "path: "),
    R("io.load_frame-header-keys", "load_frame(NPZ whose header lacks pattern/bit_depth)",
      lambda f: rio.load_frame(f / "nokeys.npz"), ValueError, "path: "),
    R("io.load_frame-header-json", "load_frame(NPZ whose header is not JSON)",
      lambda f: rio.load_frame(f / "notjson.npz"), ValueError, "path: "),
    R("io.load_frame-plain-tiff", "load_frame(plain TIFF, no pattern)",
      lambda f: rio.load_frame(f / "plain.tif"), ValueError,
      "phase: plain.tif does not record its CFA phase"),
    R("io.load_frame-plain-tiff-bits", "load_frame(plain TIFF, pattern, no bit_depth)",
      lambda f: rio.load_frame(f / "plain.tif", pattern="mask1"), ValueError,
      "bit_depth: required for a plain TIFF/PNG mosaic with a pattern"),
    R("io.load_frame-corrupt-tiff", "load_frame(truncated TIFF)",
      lambda f: rio.load_frame(f / "truncated.tif"), ValueError, "path: cannot read"),
    R("io.load_frame-corrupt-png", "load_frame(corrupt PNG, pattern, bit_depth)",
      lambda f: rio.load_frame(f / "corrupt.png", pattern="mask1", bit_depth=11),
      ValueError, "path: cannot read"),
    R("io.load_frame-folder", "load_frame(a folder)",
      lambda f: rio.load_frame(f / "empty"), ValueError, "path: unknown raw extension"),
    R("io.load_frame-fifo", "load_frame(FIFO named fifo.npz): hung",
      lambda f: rio.load_frame(f / "fifo.npz"), ValueError,
      "path: {d}/fifo.npz is a FIFO (named pipe), not a regular file"),
    bad_frame("zip-bomb", "bomb", "2 MB of zeros deflated to 2 kB, max_bytes=1e6",
              "its arrays declare 2097", max_bytes=1_000_000),
    bad_frame("npy-liar", "liar", ".npy header declaring 40000x40000 in 228 bytes",
              "member data.npy declares 3200000000 bytes of data in"),
    bad_frame("deep-json", "deep", "header nested 100000 deep",
              "the header is nested too deeply"),
    bad_frame("meta-list", "metalist", "header meta=[1, 2]",
              "the header field 'meta' is [1, 2], expected an object"),
    bad_frame("tof-list", "toflist", "header tof=[1]",
              "the header's 'tof' is a JSON list, not an object"),
    bad_frame("header-int", "hdrint", "header stored as an integer array",
              "the header is a int64 array"),
    bad_frame("objects", "objects", "data member of Python objects",
              "member data.npy holds Python objects"),
    bad_frame("big-tile", "bigtile", "4 kB NPZ, 512x512 tile",
              "tile: 512x512 sites, more than the largest tile (32x32))"),
    bad_frame("tof-sites", "tofsites", "ToF sites outside the frame",
              "sites: rows span [1000, "),
    R("io.load_frame-max_pixels", "load_frame(16x16 frame, max_pixels=10)",
      lambda f: rio.load_frame(f / "ok.npz", max_pixels=10), ValueError,
      "path: {d}/ok.npz declares a 16x16 image (256 pixels), more than the limit of 10 "
      "pixels; raise it with max_pixels= or RGBZ_FAST_MAX_PIXELS"),
    # -- guarded reads, limits, atomic writes ----------------------------------------------
    R("io.read_file-fifo", "read_file(FIFO named fifo.tif)",
      lambda f: rio.read_file(f / "fifo.tif"), ValueError,
      "path: {d}/fifo.tif is a FIFO (named pipe), not a regular file"),
    R("io.read_file-device", "read_raw(zero.raw -> /dev/zero)",
      lambda f: rio.read_raw(f / "zero.raw", shape=(4, 4), phase="RGGB", black_level=0,
                             white_level=1023), ValueError,
      "path: {d}/zero.raw is a character device, not a regular file"),
    R("io.read_file-folder", "read_file(a folder)",
      lambda f: rio.read_file(f / "empty"), ValueError,
      "path: {d}/empty is a folder, not a regular file"),
    R("io.read_file-max_bytes", "read_file(ok.npz, max_bytes=10)",
      lambda f: rio.read_file(f / "ok.npz", max_bytes=10), ValueError,
      "path: {d}/ok.npz is "),
    R("io.read_image-cmyk-jpeg", "read_image(CMYK JPEG)",
      lambda f: rio.read_image(f / "cmyk.jpg"), ValueError,
      "path: cannot read {d}/cmyk.jpg as an image (it holds CMYK samples, not RGB or grey; "
      "convert it to RGB first"),
    R("io.read_image-cmyk-tiff", "read_image(CMYK TIFF)",
      lambda f: rio.read_image(f / "cmyk.tif"), ValueError,
      "path: cannot read {d}/cmyk.tif as an image (it holds CMYK (separated) samples"),
    R("io.read_image-lab-tiff", "read_image(CIELAB TIFF)",
      lambda f: rio.read_image(f / "lab.tif"), ValueError,
      "path: cannot read {d}/lab.tif as an image (it holds CIELAB samples"),
    R("io.read_image-pgm-truncated", "read_image(truncated 16-bit PGM)",
      lambda f: rio.read_image(f / "short.pgm"), ValueError,
      "path: cannot read {d}/short.pgm as an image (truncated: 100 bytes of samples, 512 "
      "needed)"),
    R("io.read_image-max_pixels", "read_image(16x16 PNG, max_pixels=10)",
      lambda f: rio.read_image(f / "rgb.png", max_pixels=10), ValueError,
      "path: {d}/rgb.png declares a 16x16x3 image (256 pixels), more than the limit of 10 "
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
      lambda f: with_env("RGBZ_FAST_MAX_PIXELS", "lots", rio.read_limits), ValueError,
      "RGBZ_FAST_MAX_PIXELS: expected a positive integer, got 'lots'"),
    R("io.atomic_write-data", "atomic_write(path, 5)",
      lambda f: rio.atomic_write(f / "x.txt", 5), TypeError,
      "data: expected str or bytes, got int"),
    # -- datasets --------------------------------------------------------------------------
    R("io.ImageSource-corrupt", "ImageSource(corrupt .png).load()",
      lambda f: rio.ImageSource("c", str(f / "corrupt.png")).load(), ValueError,
      "dataset: cannot read"),
    R("io.folder_dataset-raw_options-unknown", "folder_dataset(raw_options={'*': {'phse': ..}})",
      lambda f: rio.folder_dataset(f / "ds", raw_options={"*": {"phse": "RGGB"}}), ValueError,
      "raw_options: 'phse' (for '*') is not a raw option; expected some of phase"),
    R("io.folder_dataset-raw_options-list", "folder_dataset(raw_options=[1])",
      lambda f: rio.folder_dataset(f / "ds", raw_options=[1]), TypeError,
      "raw_options: expected a mapping of file names"),
    R("io.folder_dataset-empty", "folder_dataset(empty folder)",
      lambda f: rio.folder_dataset(f / "empty"), ValueError, "dataset: no image files in"),
    R("io.folder_dataset-limit", "folder_dataset(limit=0)",
      lambda f: rio.folder_dataset(f / "ds", limit=0), ValueError,
      "limit: expected a positive number of images, got 0"),
    R("io.folder_dataset-limit-negative", "folder_dataset(limit=-1)",
      lambda f: rio.folder_dataset(f / "ds", limit=-1), ValueError,
      "limit: expected a positive number of images, got -1"),
    R("io.folder_dataset-same-stem", "folder_dataset(a.png and a.tif)",
      lambda f: rio.folder_dataset(f / "ds_stems"), ValueError,
      "dataset: several files are named 'a' (e.g. a.png, a.tif)"),
    R("io.ImageSource-grey", "ImageSource(grey .png).load()",
      lambda f: rio.ImageSource("g", str(f / "grey.png")).load(), ValueError,
      "dataset: {d}/grey.png is a grey image (16x16)"),
    R("io.read_image-unidentified", "read_image(junk under .bmp)",
      lambda f: rio.read_image(f / "junk.bmp"), ValueError,
      "path: cannot read {d}/junk.bmp as an image (not an image format this library reads"),
    R("io.read_image-long-name", "read_image(a 300-byte name)",
      lambda f: rio.read_image(f / ("a" * 296 + ".png")), ValueError,
      "path: a name in "),
    R("io.load_frame-npz-pattern", "load_frame(NPZ frame, pattern='bayer')",
      lambda f: rio.load_frame(f / "ok.npz", pattern="bayer"), ValueError,
      "pattern: {d}/ok.npz records its own pattern 'mask1'; pattern='bayer' applies to a plain"),
    R("io.load_frame-npz-bit_depth", "load_frame(NPZ frame, bit_depth=12)",
      lambda f: rio.load_frame(f / "ok.npz", bit_depth=12), ValueError,
      "bit_depth: {d}/ok.npz records its own bit depth 11"),
    R("io.atomic_write-folder", "atomic_write(a folder, 'x')",
      lambda f: rio.atomic_write(f / "empty", "x"), ValueError,
      "path: {d}/empty is a folder; expected a file to write"),
]

test_api_contract = api_tests(ROWS)


def test_clipped_mask_accepts_numpy_levels():
    """The level check of clipped_mask refuses only non-numbers: NumPy scalars and floats
    give the mask of the integer level."""
    a = np.array([[0, 1020], [5, 1023]])
    for level in (1020, np.float32(1020), 1020.0):
        np.testing.assert_array_equal(rio.clipped_mask(a, level), a >= 1020)


# --------------------------------------------------------------------------- no partial output
def test_failed_calls_leave_inputs_and_files_untouched(files, tmp_path):
    """A call that raises modifies neither its input arrays nor existing output files."""
    data = with_value(np.nan)
    before = data.copy()
    with pytest.raises(ValueError):
        rz.reconstruct(data, pattern="mask1")
    np.testing.assert_array_equal(data, before)
    target = tmp_path / "frame.npz"
    rio.save_frame(target, small_frame())
    blob = target.read_bytes()
    with pytest.raises(ValueError):
        rio.save_frame(tmp_path / "frame.jpg", small_frame())
    assert target.read_bytes() == blob
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frame.npz"]


def test_atomic_write_failure_keeps_the_old_file(tmp_path, monkeypatch):
    """A write that fails half-way (bad data, a full disk, a failed rename) keeps the old file."""
    target = tmp_path / "report.json"
    rio.atomic_write(target, '{"old": true}')
    with pytest.raises(TypeError):
        rio.atomic_write(target, 12345)                # not str or bytes
    with pytest.raises(ValueError, match="path: .* is a folder"):
        rio.atomic_write(tmp_path, "x")                # the target is a folder

    def replace_fails(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", replace_fails)
    with pytest.raises(OSError):
        rio.atomic_write(target, '{"new": true}')
    monkeypatch.undo()
    assert json.loads(target.read_text()) == {"old": True}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.json"]   # no temp file left


def test_atomic_write_names_the_file_a_full_disk_refused(tmp_path, monkeypatch):
    """A full disk fails the write or the fsync with an error that names no file:
    `rgbz-fast evaluate --out` on a full disk ended with "error: [Errno 28] No space left on
    device" of nothing in particular (found on a 64 kB tmpfs). The error names the file,
    keeps its errno, and no temporary file stays."""
    import errno

    target = tmp_path / "results.csv"

    def full(fd):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(os, "fsync", full)
    with pytest.raises(OSError) as got:
        rio.atomic_write(target, "a,b\n")
    assert got.value.errno == errno.ENOSPC and got.value.filename == str(target)
    assert "No space left on device" in str(got.value) and str(target) in str(got.value)
    assert list(tmp_path.iterdir()) == []


def test_atomic_write_all_is_all_or_none(tmp_path, monkeypatch):
    """A set of files (a report set, a frame's depth files, a command's report) written one
    by one was left half old and half new by a full disk; atomic_write_all writes every one
    to a temporary file before the first rename: a failure leaves each destination as it was
    and no temporary file, names the file, and never calls before_renames (H126)."""
    import errno

    from _support import disk_full_at
    from rgbz_fast.io._files import atomic_write_all

    items = [(tmp_path / n, f"new {n}\n") for n in ("a.txt", "b.txt", "c.txt")]
    (tmp_path / "a.txt").write_text("old a\n")
    (tmp_path / "c.txt").write_text("old c\n")
    fsync, hook = os.fsync, []
    monkeypatch.setattr(os, "fsync", disk_full_at(2))
    with pytest.raises(OSError) as got:
        atomic_write_all(items, before_renames=lambda: hook.append(1))
    assert got.value.errno == errno.ENOSPC and got.value.filename == str(tmp_path / "b.txt")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt", "c.txt"] and not hook
    assert (tmp_path / "a.txt").read_text() == "old a\n"
    monkeypatch.setattr(os, "fsync", fsync)
    assert atomic_write_all(items, before_renames=lambda: hook.append(1)) == [p for p, _ in items]
    assert hook == [1] and [p.read_text() for p, _ in items] == [d for _, d in items]


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
    """Every way a frame or image file can be broken is one ValueError naming the file and
    what is wrong with it, on one line, and no file handle is left open."""
    blob = (files / "ok.npz").read_bytes()
    flipped = bytearray(blob)
    for i in range(40, len(blob) // 2):          # inside the first member's deflate stream
        flipped[i] ^= 0xFF
    (tmp_path / "flipped.npz").write_bytes(bytes(flipped))
    header = {"format": "rgbz-fast raw frame", "pattern": "ZG/GR", "bit_depth": 11}
    np.save(tmp_path / "array.npy", u16())
    (tmp_path / "array.npz").write_bytes((tmp_path / "array.npy").read_bytes())
    cases = [
        (files / "truncated.npz", lambda p: rio.load_frame(p), "not an NPZ archive"),
        (files / "junk.npz", lambda p: rio.load_frame(p), "no zip signature"),
        (tmp_path / "array.npz", lambda p: rio.load_frame(p), "no zip signature"),
        (files / "foreign.npz", lambda p: rio.load_frame(p), "no header/data"),
        (files / "nokeys.npz", lambda p: rio.load_frame(p), "missing key 'pattern'"),
        (files / "notjson.npz", lambda p: rio.load_frame(p), "the header is not JSON"),
        (_npz(tmp_path / "list.npz", data=u16(), header=np.array("[1]")),
         lambda p: rio.load_frame(p), "the header is a JSON list"),
        (_npz(tmp_path / "bits.npz", data=u16(), header=np.array(json.dumps(
            {**header, "bit_depth": 40}))), lambda p: rio.load_frame(p),
         "bit_depth: expected 1..16 bits"),
        (_npz(tmp_path / "tile.npz", data=u16(), header=np.array(json.dumps(
            {**header, "pattern": "ZX/GR"}))), lambda p: rio.load_frame(p),
         "tile: unknown channel letter"),
        (tmp_path / "flipped.npz", lambda p: rio.load_frame(p), "is not a readable"),
        (files / "truncated.tif", lambda p: rio.load_frame(p), "cannot read"),
        (files / "truncated.tif", lambda p: rio.load_frame(p, pattern="mask1",
                                                           bit_depth=11), "cannot read"),
        (files / "corrupt.png", lambda p: rio.load_frame(p, pattern="mask1",
                                                         bit_depth=11), "cannot read"),
        (files / "corrupt.png", lambda p: rio.read_raw(p, phase="GRBG", black_level=0,
                                                       bit_depth_in=8), "cannot read"),
        (files / "truncated.tif", lambda p: rio.read_raw(p, phase="GRBG", black_level=0,
                                                         bit_depth_in=8), "cannot read"),
        (files / "corrupt.png", lambda p: rio.ImageSource("c", str(p)).load(), "cannot read"),
        (files / "corrupt.png", lambda p: sim.load_image(p), "cannot read"),
    ]
    for path, call, reason in cases:
        err = _call_without_leaks(lambda: call(path))
        assert err is not None, f"{path.name}: no error"
        kind, msg = err
        assert issubclass(kind, ValueError), (path.name, kind, msg)
        assert str(path) in msg and reason in msg, (path.name, msg)
        assert msg.split(":")[0] in ("path", "dataset") and "\n" not in msg, msg


def test_a_frame_file_takes_the_pattern_and_bit_depth_it_records(files):
    """A frame file records its pattern and bit depth: the same ones (or bit_depth="input")
    are accepted, a different one is refused rather than ignored; "." and other paths without
    a name part are valid paths."""
    frame = rio.load_frame(files / "ok.npz")
    for kw in ({"pattern": "mask1"}, {"pattern": rz.mask1()}, {"bit_depth": 11},
               {"bit_depth": "input"}, {"pattern": "mask1", "bit_depth": 11}):
        got = rio.load_frame(files / "ok.npz", **kw)
        assert got.pattern == frame.pattern and got.bit_depth == frame.bit_depth
        np.testing.assert_array_equal(got.data, frame.data)
    from rgbz_fast._validate import check_path

    assert str(check_path(".")) == "." and str(check_path("/")) == "/"
