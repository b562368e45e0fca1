"""The file primitives: bounded reads of regular files only, size limits checked from the
headers before anything is decoded, 16-bit colour PNGs at full precision, every format's
samples as its header means them, atomic writes."""

from __future__ import annotations

import json
import os

import numpy as np
import pytest
from _support import frame_header, npy_bytes, write_npz

import rgbz_fast as rz
from rgbz_fast import io as rio
from rgbz_fast import simulation as sim
from rgbz_fast.io import read_image

cv2 = pytest.importorskip("cv2")


def _never(blob):
    raise AssertionError("the decoder ran although the header breaks the limits")


# --------------------------------------------------------------------------- regular files only
def test_fifo_device_and_folder_are_refused_before_reading(tmp_path):
    """A FIFO (which would block a read) and a device such as /dev/zero (which would read
    without end) are refused from their file type, before anything is read."""
    fifo = tmp_path / "f.tif"
    os.mkfifo(fifo)
    for reader in (rio.read_file, rio.read_image, rio.load_frame, rio.read_raw):
        with pytest.raises(ValueError, match=r"^path: .*f\.tif is a FIFO \(named pipe\), not a "
                                             "regular file"):
            reader(fifo)
    with pytest.raises(ValueError, match="^path: /dev/zero is a character device"):
        rio.read_raw("/dev/zero", reader="headerless", shape=(4, 4), phase="RGGB",
                     black_level=0, white_level=1023)
    with pytest.raises(ValueError, match="is a folder, not a regular file"):
        rio.read_file(tmp_path)
    with pytest.raises(FileNotFoundError, match="^path: no such file"):
        rio.read_file(tmp_path / "missing.png")


def test_scene_loaders_refuse_a_fifo(tmp_path):
    from rgbz_fast.simulation import load_scene

    for name in ("f.png", "f.mat"):
        os.mkfifo(tmp_path / name)
        with pytest.raises(ValueError, match="is a FIFO"):
            load_scene(tmp_path / name)


def test_read_file_is_bounded(tmp_path, monkeypatch):
    f = tmp_path / "a.bin"
    f.write_bytes(bytes(1000))
    assert len(rio.read_file(f, max_bytes=1000)) == 1000
    with pytest.raises(ValueError, match=r"^path: .*a\.bin is 1000 bytes, more than the limit of "
                                         "999 bytes; raise it with max_bytes= or "
                                         "RGBZ_FAST_MAX_BYTES$"):
        rio.read_file(f, max_bytes=999)
    monkeypatch.setenv("RGBZ_FAST_MAX_BYTES", "999")
    with pytest.raises(ValueError, match="more than the limit of 999 bytes"):
        rio.read_file(f)
    monkeypatch.setenv("RGBZ_FAST_MAX_BYTES", "lots")
    with pytest.raises(ValueError, match="^RGBZ_FAST_MAX_BYTES: expected a positive integer, "
                                         "got 'lots'"):
        rio.read_file(f)


# --------------------------------------------------------------------------- size limits
@pytest.mark.parametrize("suffix", [".png", ".tif", ".jpg", ".bmp"])
def test_declared_size_is_checked_before_decoding(tmp_path, suffix):
    """The limits apply to the size in the header: the decoder never runs on a file beyond them."""
    import imageio.v3 as iio

    path = tmp_path / f"img{suffix}"
    iio.imwrite(path, np.zeros((40, 50, 3), np.uint8))
    with pytest.raises(ValueError, match=r"declares a 40x50(x3)? image \(2000 pixels\), more "
                                         "than the limit of 1999 pixels; raise it with "
                                         "max_pixels= or RGBZ_FAST_MAX_PIXELS$"):
        rio.read_image(path, decode=_never, max_pixels=1999)
    with pytest.raises(ValueError, match="more than the limit of 5999 bytes"):
        rio.read_image(path, decode=_never, max_bytes=5999)
    assert rio.read_image(path, max_pixels=2000).shape == (40, 50, 3)


@pytest.fixture(scope="module")
def huge_tiff(tmp_path_factory):
    """A 400 kB deflate TIFF declaring 20000 x 20000 pixels (written tile by tile)."""
    import tifffile

    path = tmp_path_factory.mktemp("huge") / "big.tif"
    tile = np.zeros((1024, 1024), np.uint8)
    n = (-(-20000 // 1024)) ** 2
    tifffile.imwrite(path, (tile for _ in range(n)), shape=(20000, 20000), dtype=np.uint8,
                     tile=(1024, 1024), compression="zlib")
    assert path.stat().st_size < 2_000_000
    return path


def test_deflate_tiff_declaring_400_megapixels_is_refused(huge_tiff, tmp_path):
    want = "declares a 20000x20000 image (400.0 megapixels), more than the limit of 200000000"
    for read in (rio.read_image, rio.load_frame,
                 lambda p: rio.read_raw(p, phase="RGGB", black_level=0, white_level=255)):
        with pytest.raises(ValueError, match=f"^path: .*{want.replace('(', '.').replace(')', '.')}"):
            read(huge_tiff)
    # raised, the limit lets it through to the decoder
    with pytest.raises(ValueError, match="the decoder ran"):
        rio.read_image(huge_tiff, decode=_never, max_pixels=400_000_000)


def test_npz_zip_bomb_is_refused_from_the_zip_directory(tmp_path):
    """An NPZ whose members inflate beyond max_bytes fails before any inflating."""
    path = write_npz(tmp_path / "bomb.npz", header=frame_header(),
                     data=npy_bytes((2048, 2048), np.uint16, bytes(2048 * 2048 * 2)))
    assert path.stat().st_size < 20_000                   # 8 MB of zeros
    with pytest.raises(ValueError, match=r"^path: .*bomb\.npz is not a readable rgbz-fast frame "
                                         r"\(its arrays declare \d+ bytes uncompressed, more "
                                         "than the limit of 1000000 bytes; raise it with "
                                         r"max_bytes= or RGBZ_FAST_MAX_BYTES\)$"):
        rio.load_frame(path, max_bytes=1_000_000)
    assert rio.load_frame(path).shape == (2048, 2048)


def test_npz_member_lying_about_its_shape_is_refused(tmp_path):
    """A .npy header declaring 40000 x 40000 values in a 100-byte member allocates nothing."""
    path = write_npz(tmp_path / "liar.npz", header=frame_header(),
                     data=npy_bytes((40000, 40000), np.uint16, bytes(100)))
    with pytest.raises(ValueError, match=r"\(member data\.npy declares 3200000000 bytes of data "
                                         r"in \d+ bytes\)"):
        rio.load_frame(path)


def test_npz_512_tile_is_refused_at_once(tmp_path):
    """A small NPZ whose pattern is a 512 x 512 tile is refused at once, before the work (and
    the memory) such a tile would cost."""
    t = np.tile(np.array([[1, 0], [2, 1]]), (256, 256))
    t[::3, ::5] = 3
    tile = "/".join("".join("RGBZ"[c] for c in row) for row in t)
    path = tmp_path / "tile.npz"
    np.savez_compressed(path, header=np.array(json.dumps({"pattern": tile, "bit_depth": 11})),
                        data=np.zeros((512, 512), np.uint16))
    with pytest.raises(ValueError, match=r"\(tile: 512x512 sites, more than the largest tile "
                                         r"\(32x32\)\)$"):
        rio.load_frame(path)


# --------------------------------------------------------------------------- 16-bit PNG
@pytest.mark.parametrize("channels", [3, 4])
def test_16_bit_colour_png_is_read_at_full_precision(tmp_path, channels):
    """Pillow (imageio's PNG plugin) keeps the high byte of 16-bit colour PNGs only."""
    rng = np.random.default_rng(channels)
    img = rng.integers(0, 65536, (37, 53, channels), dtype=np.uint16)
    path = tmp_path / "c16.png"
    cv2.imwrite(str(path), img[..., [2, 1, 0, 3][:channels]])       # OpenCV writes BGR(A)
    got = rio.read_image(path)
    assert got.dtype == np.uint16
    np.testing.assert_array_equal(got, img)
    src = rio.ImageSource("c16", str(path))
    np.testing.assert_array_equal(src.load(), img[..., :3])
    from rgbz_fast.simulation import load_image

    scene = load_image(path)
    lin = rz.simulation.srgb_to_linear(img[..., :3] / 65535.0)
    np.testing.assert_allclose(scene.image, lin, rtol=1e-12, atol=1e-15)


def test_8_bit_png_reads_as_imageio_reads_it():
    """The 8-bit PNGs read through Pillow directly give imageio's array (values, shape,
    dtype, a writeable array) in every mode, interlaced too; palettes and animated PNGs,
    which imageio converts or stacks, are left to it."""
    import io

    import imageio.v3 as iio
    from PIL import Image

    from rgbz_fast.io._files import _decode_default, _decode_png8

    rng = np.random.default_rng(8)
    for mode, shape in (("L", (5, 7)), ("LA", (5, 7, 2)), ("RGB", (9, 6, 3)),
                        ("RGBA", (5, 7, 4))):
        for interlace in (False, True):
            buf = io.BytesIO()
            Image.fromarray(rng.integers(0, 256, shape, dtype=np.uint8), mode).save(
                buf, "PNG", interlace=interlace)
            got, want = _decode_default(buf.getvalue(), ".png"), iio.imread(buf.getvalue(),
                                                                            extension=".png")
            assert got.dtype == want.dtype and got.flags.writeable, (mode, interlace)
            np.testing.assert_array_equal(got, want)
    frames = [Image.fromarray(rng.integers(0, 256, (4, 6, 3), dtype=np.uint8)) for _ in "ab"]
    buf = io.BytesIO()
    frames[0].save(buf, "PNG", save_all=True, append_images=frames[1:])
    assert _decode_png8(buf.getvalue()) is None
    np.testing.assert_array_equal(_decode_default(buf.getvalue(), ".png"),
                                  iio.imread(buf.getvalue(), extension=".png"))
    buf = io.BytesIO()
    frames[0].convert("P").save(buf, "PNG")
    assert _decode_png8(buf.getvalue()) is None
    np.testing.assert_array_equal(_decode_default(buf.getvalue(), ".png"),
                                  iio.imread(buf.getvalue(), extension=".png"))


def test_grey_images_are_refused_unless_asked_for(tmp_path):
    """One policy for scenes and datasets: grey is refused, grey=True repeats it into RGB."""
    import imageio.v3 as iio
    from rgbz_fast.simulation import load_image

    path = tmp_path / "g.png"
    iio.imwrite(path, np.arange(64, dtype=np.uint8).reshape(8, 8))
    for load in (lambda **k: load_image(path, **k).image,
                 lambda **k: rio.ImageSource("g", str(path), **k).load()):
        with pytest.raises(ValueError, match="is a grey image .8x8.; a colour sensor needs "
                                             "colour: pass grey=True"):
            load()
        rgb = load(grey=True)
        assert rgb.shape == (8, 8, 3) and np.all(rgb[..., 0] == rgb[..., 2])
    assert all(s.grey for s in rio.folder_dataset(tmp_path, grey=True))


# --------------------------------------------------------------------------- errors
def test_errors_carry_the_parameter_and_the_settings_that_fix_it(tmp_path):
    """A reader's error names its parameter (``param``) and spells the settings of its advice
    from parts, so that the command line gives its flags without rewriting the text; it
    survives pickling (evaluate's worker processes return it)."""
    import pickle

    f = tmp_path / "a.bin"
    f.write_bytes(bytes(100))
    with pytest.raises(rio.ParameterError) as e:
        rio.read_file(f, max_bytes=99)
    assert e.value.param == "path" and e.value.settings == ("max_bytes",)
    assert str(e.value).endswith("raise it with max_bytes= or RGBZ_FAST_MAX_BYTES")
    assert e.value.render(lambda s: f"--{s.name}").endswith("with --max_bytes or "
                                                            "RGBZ_FAST_MAX_BYTES")
    with pytest.raises(rio.ParameterError) as e:
        rio.read_raw(f, shape=None, phase="RGGB", black_level=0, white_level=1)
    assert e.value.param == "shape" and str(e.value).endswith("needs shape=(rows, cols)")
    back = pickle.loads(pickle.dumps(e.value))
    assert type(back) is rio.ParameterError and back.parts == e.value.parts
    assert str(back) == str(e.value) and back.param == "shape"
    assert isinstance(back, ValueError)
    with pytest.raises(rio.ParameterError) as e:
        rio.read_raw(f, shape=(5, 10))
    # every setting the file lacks, in one error named after the first
    assert e.value.param == "phase" and e.value.settings == ("phase", "black_level",
                                                             "white_level", "bit_depth_in")
    nested = rio.ParameterError(None, "its arrays declare 9 bytes", "; raise it with ",
                                rio.Setting("max_bytes")).within("path", "x.npz is bad (", ")")
    assert str(nested) == "path: x.npz is bad (its arrays declare 9 bytes; raise it with " \
                          "max_bytes=)" and nested.settings == ("max_bytes",)


def test_readers_agree_on_the_suffixes_of_images_and_raw_files(tmp_path):
    """One list per kind of file: a scene, a dataset and read_raw recognise the same names."""
    from rgbz_fast.simulation import _loaders

    assert rio.IMAGE_SUFFIXES >= set(rio.IMAGE_EXTENSIONS)
    assert rio.RAW_SUFFIXES == set(rio.LIBRAW_EXTENSIONS + rio.HEADERLESS_EXTENSIONS)
    assert set(rio.RAW_EXTENSIONS) == rio.RAW_SUFFIXES | set(rio.IMAGE_EXTENSIONS)
    assert _loaders._IMAGE_SUFFIXES is rio.IMAGE_SUFFIXES
    for name in ("a.pgm", "b.webp", "c.nrw", "d.txt"):
        (tmp_path / name).write_bytes(b"")
    sources = rio.folder_dataset(tmp_path)
    assert [(s.name, s.is_raw) for s in sources] == [("a", False), ("b", False), ("c", True)]


# --------------------------------------------------------------------------- atomic writes
def test_atomic_write_leaves_no_temporary_when_interrupted(tmp_path, monkeypatch):
    """An interrupt (KeyboardInterrupt, or SystemExit from a SIGTERM handler) anywhere in the
    write removes the temporary file and keeps the old one."""
    target = tmp_path / "r.txt"
    rio.atomic_write(target, "old")
    real_fsync = os.fsync

    def interrupted(fd):
        raise SystemExit(143)

    monkeypatch.setattr(os, "fsync", interrupted)
    with pytest.raises(SystemExit):
        rio.atomic_write(target, "new")
    monkeypatch.setattr(os, "fsync", real_fsync)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.txt"]
    assert target.read_text() == "old"
    with pytest.raises(TypeError, match="^data: expected str or bytes, got int"):
        rio.atomic_write(target, 5)
    rio.atomic_write(target, "±")
    assert target.read_bytes() == "±".encode()


def _pnm(path, arr, maxval):
    """A binary PGM (2-D) or PPM (3-D) of ``arr`` with ``maxval``, big-endian when 16-bit."""
    magic = b"P5" if arr.ndim == 2 else b"P6"
    dtype = ">u2" if maxval > 255 else "u1"
    path.write_bytes(magic + f"\n{arr.shape[1]} {arr.shape[0]}\n{maxval}\n".encode()
                     + arr.astype(dtype).tobytes())
    return path


def test_image_formats_are_read_as_what_they_mean(tmp_path):
    """Each format's samples as its header means them, or a clear refusal: 16-bit PGM/PPM
    at 16 bits (Pillow gave int32 or 8 bits), a 12-bit one scaled to the full 16 bits, ASCII
    ones; a palette TIFF's colours (not its indices, which grey=True made a grey image);
    MINISWHITE inverted; planar RGB interleaved; CMYK JPEG/TIFF, CIELAB and YCbCr TIFF
    refused (they were read as RGB plus alpha); 32-bit integer TIFFs need their bits."""
    import tifffile
    from PIL import Image

    rng = np.random.default_rng(0)
    g16 = rng.integers(0, 65536, (8, 8), dtype=np.uint16)
    c12 = rng.integers(0, 4096, (8, 8, 3), dtype=np.uint16)
    g8 = rng.integers(0, 256, (8, 8), dtype=np.uint8)
    rgb = rng.integers(0, 256, (8, 8, 3), dtype=np.uint8)
    assert np.array_equal(read_image(_pnm(tmp_path / "g16.pgm", g16, 65535)), g16)
    got = read_image(_pnm(tmp_path / "c12.ppm", c12, 4095))
    assert got.dtype == np.uint16
    assert np.array_equal(got, (c12.astype(np.int64) * 131070 + 4095) // 8190)
    assert np.array_equal(read_image(_pnm(tmp_path / "g8.pgm", g8, 255)), g8)
    (tmp_path / "a.pgm").write_text("P2\n# a comment\n3 1\n1000\n0 500 1000\n")
    assert read_image(tmp_path / "a.pgm").tolist() == [[0, 32768, 65535]]
    scene = sim.load_image(tmp_path / "g16.pgm", grey=True)
    assert np.allclose(scene.image[..., 0], sim.srgb_to_linear(g16 / 65535.0))
    for bad, why in ((b"P5\n4 4\n255\n\x00", "truncated"), (b"P2 2 1 10 5 11", "above its"),
                     (b"P5 4 4 70000 ", "maxval")):
        (tmp_path / "bad.pgm").write_bytes(bad)
        with pytest.raises(ValueError, match=f"^path: cannot read .*bad.pgm as an image .*{why}"):
            read_image(tmp_path / "bad.pgm")

    cmap = np.zeros((3, 256), np.uint16)
    cmap[:, :4] = rng.integers(0, 65536, (3, 4))
    idx = rng.integers(0, 4, (8, 8), dtype=np.uint8)
    tifffile.imwrite(tmp_path / "pal.tif", idx, photometric="palette", colormap=cmap)
    assert np.array_equal(read_image(tmp_path / "pal.tif"), cmap.T[idx])
    assert sim.load_image(tmp_path / "pal.tif", grey=True).image.shape == (8, 8, 3)
    Image.fromarray(g8).convert("P").save(tmp_path / "palgrey.png")
    assert np.array_equal(rio.rgb_image(read_image(tmp_path / "palgrey.png"), "p", grey=True),
                          np.repeat(g8[..., None], 3, axis=2))
    tifffile.imwrite(tmp_path / "white.tif", g8, photometric="miniswhite")
    assert np.array_equal(read_image(tmp_path / "white.tif"), 255 - g8)
    tifffile.imwrite(tmp_path / "white16.tif", g16, photometric="miniswhite")
    assert np.array_equal(read_image(tmp_path / "white16.tif"), 65535 - g16)
    tifffile.imwrite(tmp_path / "planar.tif", np.moveaxis(rgb, 2, 0), photometric="rgb",
                     planarconfig="separate")
    assert np.array_equal(read_image(tmp_path / "planar.tif"), rgb)

    Image.fromarray(rgb).convert("CMYK").save(tmp_path / "cmyk.jpg")
    tifffile.imwrite(tmp_path / "cmyk.tif", np.zeros((8, 8, 4), np.uint8),
                     photometric="separated")
    Image.fromarray(rgb).convert("LAB").save(tmp_path / "lab.tif")
    Image.fromarray(rgb).convert("YCbCr").save(tmp_path / "ycbcr.tif")
    for name, kind in (("cmyk.jpg", "CMYK"), ("cmyk.tif", "CMYK"), ("lab.tif", "CIELAB"),
                       ("ycbcr.tif", "YCbCr")):
        for read in (read_image, sim.load_image):
            with pytest.raises(ValueError, match=f"^path: cannot read .*{name} as an image "
                                                 f"\\(it holds {kind}"):
                read(tmp_path / name)

    for dtype in (np.int32, np.uint32):
        tifffile.imwrite(tmp_path / "wide.tif", c12.astype(dtype), photometric="rgb")
        with pytest.raises(ValueError, match=f"^path: .*wide.tif holds {np.dtype(dtype)} "
                                             "samples, a type that says nothing"):
            sim.load_image(tmp_path / "wide.tif")
        assert np.array_equal(sim.load_image(tmp_path / "wide.tif", input_bits=12).image,
                              sim.Scene(c12, input_bits=12).image)


def test_output_names_up_to_the_longest_file_name_are_written(tmp_path):
    """A name of 234 to 255 bytes is a valid file name, but its temporary name (22 bytes
    more) was not: atomic_write failed with 'File name too long'. The temporary name keeps
    as much of the name as fits; a name beyond 255 bytes is the command line's clear error."""
    from rgbz_fast._cli import main

    for size in (233, 234, 240, 255):
        path = tmp_path / ("n" * (size - 4) + ".txt")
        rio.atomic_write(path, "x")
        assert path.read_text() == "x"
    wide = tmp_path / ("é" * 125 + ".txt")                   # 254 bytes in UTF-8
    rio.atomic_write(wide, "x")
    assert wide.read_text() == "x"
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == []
    import imageio.v3 as iio

    img = np.random.default_rng(0).integers(0, 256, (16, 16, 3), dtype=np.uint8)
    iio.imwrite(tmp_path / ("s" * 236 + ".png"), img)      # simulate writes 246 bytes
    assert main(["simulate", str(tmp_path / ("s" * 236 + ".png")), "--out",
                 str(tmp_path / "o"), "--quiet"]) == 0
    iio.imwrite(tmp_path / ("t" * 248 + ".png"), img)      # 258 bytes: no such file
    assert main(["simulate", str(tmp_path / ("t" * 248 + ".png")), "--out",
                 str(tmp_path / "o2"), "--quiet"]) == 2
    assert not (tmp_path / "o2").exists()


def _tiff_with_bad_first_offset(path):
    """A valid 8x8 RGB TIFF whose offset to its first page points past the file."""
    import struct

    import tifffile

    tifffile.imwrite(path, np.zeros((8, 8, 3), np.uint8))
    data = bytearray(path.read_bytes())
    data[4:8] = struct.pack("<I" if data[:2] == b"II" else ">I", 0x5A5A5A52)
    path.write_bytes(bytes(data))
    return path


def test_a_tiff_without_a_readable_page_is_one_error_and_no_log_line(tmp_path, capsys):
    """tifffile logged '<tifffile.TiffPages @...> invalid offset to first page' on stderr
    beside the error, which said 'index 0 out of range(0)'."""
    import logging

    from rgbz_fast._cli import main

    f = _tiff_with_bad_first_offset(tmp_path / "bad.tif")
    records = []
    handler = logging.Handler()
    handler.emit = records.append
    logging.getLogger("tifffile").addHandler(handler)
    try:
        with pytest.raises(ValueError, match=r"it holds no readable page: invalid offset to "
                                             r"first page 1515870802"):
            rio.read_image(f)
        assert main(["simulate", str(f), "--out", str(tmp_path / "out"), "--quiet"]) == 2
        assert records == []                              # nothing reached the log
        err = capsys.readouterr().err.strip().splitlines()
        assert err == [f"rgbz-fast simulate: error: path: cannot read {f} as an image (it "
                       "holds no readable page: invalid offset to first page 1515870802)"]
        assert not (tmp_path / "out").exists()
        # outside the library's reads, tifffile logs as it always did
        import tifffile

        with tifffile.TiffFile(f) as tf:
            assert len(tf.pages) == 0
        assert len(records) == 1 and "invalid offset to first page" in records[0].getMessage()
    finally:
        logging.getLogger("tifffile").removeHandler(handler)


@pytest.mark.parametrize("logger", ["tifffile", "tifffile.tifffile"])
def test_open_tiff_keeps_the_records_of_either_tifffile_logger(tmp_path, logger):
    """tifffile 2023.1 (the floor) logs on its module's logger, "tifffile.tifffile", today's
    on "tifffile": a filter on "tifffile" alone let the older one's records through to stderr
    (a DNG with a damaged tag printed a line before the frame was read, H119). Records of
    either logger logged inside open_tiff are kept out of the log; outside, they log."""
    import logging

    import tifffile

    from rgbz_fast.io._tiff import open_tiff

    tifffile.imwrite(tmp_path / "ok.tif", np.zeros((4, 4), np.uint8))
    blob = (tmp_path / "ok.tif").read_bytes()
    records = []
    handler = logging.Handler()
    handler.emit = records.append
    root = logging.getLogger("tifffile")
    root.addHandler(handler)
    try:
        with open_tiff(blob) as tf:
            assert len(tf.pages) == 1
            logging.getLogger(logger).warning("<tifffile.TiffPage 0 @8> invalid value offset 2")
        assert records == []
        logging.getLogger(logger).warning("outside")
        assert [r.getMessage() for r in records] == ["outside"]
    finally:
        root.removeHandler(handler)


def test_a_bad_pixel_limit_in_the_environment_leaves_reads_with_a_given_limit(tmp_path,
                                                                            monkeypatch):
    """RGBZ_FAST_MAX_PIXELS=abc broke every file read, --max-pixels given: the byte read
    resolved both limits, and the frame loader reported it as the file's fault."""
    f = rio.save_frame(tmp_path / "f.npz", rz.mosaic(np.zeros((8, 8, 3)), "mask1"))
    monkeypatch.setenv("RGBZ_FAST_MAX_PIXELS", "abc")
    assert rio.load_frame(f, max_pixels=1000).data.shape == (8, 8)
    assert rio.read_file(f)[:2] == b"PK"
    with pytest.raises(ValueError, match=r"RGBZ_FAST_MAX_PIXELS: expected a positive integer, "
                                         r"got 'abc'"):
        rio.load_frame(f)


def test_frame_meta_round_trips(tmp_path):
    """An NPZ frame keeps its meta: arrays (read_raw's clipped mask) as members, nested lists,
    tuples and objects and NumPy scalars as JSON; a TIFF says what it cannot keep."""
    import rgbz_fast as rz
    from rgbz_fast.io import load_frame, save_frame

    d = rz.mosaic(np.full((8, 8, 3), 128, np.uint8), rz.mask1()).data
    clipped = np.zeros((8, 8), bool)
    clipped[1, 2] = True
    meta = {"a": np.int64(3), "gains": [np.float32(1.5), 2.0], "nested": {"x": [1, None]},
            "pairs": ((1, 2), (3, 4)), "clipped": clipped}
    f = rz.RawFrame(d, rz.mask1(), 11, meta=meta)
    save_frame(tmp_path / "f.npz", f)
    back = load_frame(tmp_path / "f.npz").meta
    assert back["a"] == 3 and back["gains"] == [1.5, 2.0] and back["nested"] == {"x": [1, None]}
    # tuples come back tuples (they had come back lists: unequal to what was saved)
    assert back["pairs"] == ((1, 2), (3, 4)) and type(back["pairs"][0]) is tuple
    np.testing.assert_array_equal(back["clipped"], clipped)
    with pytest.warns(UserWarning, match=r"does not keep meta 'clipped'"):
        save_frame(tmp_path / "f.tif", f)
    assert load_frame(tmp_path / "f.tif").meta["pairs"] == ((1, 2), (3, 4))
    # a dict that is the marker itself would load as a tuple: not kept, said (the review)
    g = rz.RawFrame(d, rz.mask1(), 11, meta={"x": {"__tuple__": [1, 2]}})
    with pytest.warns(UserWarning, match=r"does not keep meta 'x' \(not JSON\)"):
        save_frame(tmp_path / "g.npz", g)
    assert "x" not in load_frame(tmp_path / "g.npz").meta
    # a file of an earlier version holds the tuple as a list: it stays a list
    from rgbz_fast.io._frames import _from_json
    assert _from_json({"pairs": [[1, 2]], "x": {"__tuple__": [1, {"__tuple__": []}]}}) == {
        "pairs": [[1, 2]], "x": (1, ())}


def test_a_tiff_says_it_drops_the_reference_and_the_taps(tmp_path):
    """A TIFF had dropped a simulated frame's reference CFA and ToF taps without a word, and
    kept the meta 'tof' that described the taps."""
    from rgbz_fast.io import load_frame, save_frame
    from rgbz_fast.simulation import Scene, simulate

    f = simulate(Scene(np.full((16, 16, 3), 0.5), depth=np.full((16, 16), 1.5)), "mask2")
    assert f.reference is not None and f.tof is not None and "tof" in f.meta
    with pytest.warns(UserWarning, match=r"f.tif does not keep the reference CFA and the ToF "
                                         r"taps \(a TIFF holds the mosaic; .npz keeps them\)"):
        save_frame(tmp_path / "f.tif", f)
    back = load_frame(tmp_path / "f.tif")
    assert back.reference is None and back.tof is None and "tof" not in back.meta
    assert "tof" in f.meta                                   # the caller's frame unchanged


def test_raw_options_for_a_frame_file_are_refused(tmp_path):
    """load_frame had ignored raw options for an rgbz-fast frame file (and for a plain mosaic
    read with pattern=): a black level of 100 subtracted nothing."""
    import imageio.v3 as iio

    import rgbz_fast as rz
    from rgbz_fast.io import load_frame, save_frame

    f = rz.mosaic(np.full((8, 8, 3), 128, np.uint8), rz.mask1())
    for name in ("f.npz", "f.tif"):
        save_frame(tmp_path / name, f)
        with pytest.raises(ValueError, match=rf"black_level: .*{name} is an rgbz-fast frame "
                                             r"file, which records its own pattern"):
            load_frame(tmp_path / name, black_level=100)
    iio.imwrite(tmp_path / "plain.png", np.full((8, 8), 300, np.uint16))
    with pytest.raises(ValueError, match=r"phase: .*plain.png is read as a plain mosaic"):
        load_frame(tmp_path / "plain.png", pattern="mask1", bit_depth=11, phase="RGGB")


def _packed_tiff(path, samples, bits):
    """A baseline TIFF (one strip, uncompressed, little-endian) of grey or RGB samples packed
    MSB first at ``bits`` bits per sample, as TIFF 6.0 stores them."""
    import struct

    rows, cols = samples.shape[:2]
    spp = 1 if samples.ndim == 2 else samples.shape[2]
    packed = bytearray()
    for row in samples.reshape(rows, -1):
        acc = n = 0
        for v in row:
            acc, n = (acc << bits) | int(v), n + bits
            while n >= 8:
                n -= 8
                packed.append((acc >> n) & 0xFF)
        if n:
            packed.append((acc << (8 - n)) & 0xFF)
    bps = struct.pack(f"<{spp}H", *[bits] * spp)
    entries = [(256, 4, 1, cols), (257, 4, 1, rows), (258, 3, spp, None), (259, 3, 1, 1),
               (262, 3, 1, 2 if spp == 3 else 1), (273, 4, 1, None), (277, 3, 1, spp),
               (278, 4, 1, rows), (279, 4, 1, len(packed)), (284, 3, 1, 1)]
    ifd = 8
    extra = ifd + 2 + 12 * len(entries) + 4
    data = extra + (len(bps) if len(bps) > 4 else 0)
    out = b"II*\0" + struct.pack("<IH", ifd, len(entries))
    for tag, typ, count, val in entries:
        if tag == 258:
            raw = bps if len(bps) <= 4 else struct.pack("<I", extra)
        elif tag == 273:
            raw = struct.pack("<I", data)
        else:
            raw = struct.pack("<H" if typ == 3 else "<I", val)
        out += struct.pack("<HHI", tag, typ, count) + raw.ljust(4, b"\0")
    out += struct.pack("<I", 0) + (bps if len(bps) > 4 else b"") + bytes(packed)
    path.write_bytes(out)
    return path


def test_a_tiff_of_fewer_bits_than_its_type_is_scaled_to_its_full_range(tmp_path):
    """H84: tifffile (with imagecodecs) unpacks a 12-bit TIFF into uint16 codes of 0-4095,
    and every reader after it took the range from the type: white read as 0.0625. Images
    now scale them to the full range as a PNM's maxval is; a raw mosaic keeps its codes."""
    from rgbz_fast.io._decode import _to_full_range

    v = np.array([0, 1, 2048, 4094, 4095], np.uint16)
    assert _to_full_range(v, 12).tolist() == [(int(x) * 131070 + 4095) // 8190 for x in v]
    assert _to_full_range(v, 12)[-1] == 65535
    assert _to_full_range(np.array([0, 15], np.uint8), 4).tolist() == [0, 255]
    np.testing.assert_array_equal(_to_full_range(v, 16), v)          # fills its type
    # MINISWHITE of fewer bits: inverted against its bits' top, then scaled (review of H84:
    # inverted against 65535 first, every 12-bit sample read above its range)
    from rgbz_fast.io._decode import _invert
    np.testing.assert_array_equal(_invert(v, 12), 4095 - v)
    np.testing.assert_array_equal(_invert(v), 65535 - v)
    with pytest.raises(ValueError, match="above its 12-bit range"):
        _to_full_range(np.array([4096], np.uint16), 12)
    pytest.importorskip("imagecodecs")    # tifffile unpacks 12-bit samples with it only
    rng = np.random.default_rng(0)
    c12 = rng.integers(0, 4096, (6, 8, 3))
    c12[0, 0] = 4095
    got = read_image(_packed_tiff(tmp_path / "c12.tif", c12, 12))
    np.testing.assert_array_equal(got, (c12 * 131070 + 4095) // 8190)
    g12 = c12[..., 0]
    raw = rio.read_raw(_packed_tiff(tmp_path / "g12.tif", g12, 12), phase="RGGB",
                       black_level=0, bit_depth_in=12, bit_depth=12)
    np.testing.assert_array_equal(raw.data, g12)


def test_a_planar_grey_and_alpha_tiff_reads_as_grey_and_alpha(tmp_path):
    """H84: a planar (PlanarConfiguration 2) grey + alpha TIFF came back (2, rows, cols): 3 or
    4 pixels wide it read as two rows of colour, else an error about its shape."""
    import tifffile

    rng = np.random.default_rng(1)
    for cols in (3, 4, 9):
        planes = rng.integers(0, 256, (2, 6, cols), dtype=np.uint8)
        tifffile.imwrite(tmp_path / "ga.tif", planes, photometric="minisblack",
                         planarconfig="separate", extrasamples=["unassalpha"])
        np.testing.assert_array_equal(read_image(tmp_path / "ga.tif"),
                                      np.moveaxis(planes, 0, -1))


def _palette_png(path, indices, palette, trns=None):
    """An 8-bit palette PNG written chunk by chunk (its PLTE exactly ``palette``)."""
    import struct
    import zlib

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    rows, cols = indices.shape
    raw = b"".join(b"\0" + bytes(r) for r in indices.astype(np.uint8))
    header = struct.pack(">IIBBBBB", cols, rows, 8, 3, 0, 0, 0)
    blob = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"PLTE", bytes(np.asarray(palette, np.uint8).ravel()))
            + (chunk(b"tRNS", trns) if trns is not None else b"")
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
    path.write_bytes(blob)
    return path


def test_palette_and_damaged_pngs_read_as_they_mean_or_one_clear_error(tmp_path, capfd):
    """H84: a palette PNG whose indices pass its PLTE read those pixels black (a palette TIFF
    was refused); one with a transparency chunk printed Pillow's advice to convert it as a
    warning; a damaged PNG went through imageio's other plugins, OpenCV's and libpng's lines
    on stderr before an error about "index `Ellipsis`"."""
    from rgbz_fast._cli import main

    rng = np.random.default_rng(0)
    pal = rng.integers(0, 256, (8, 3))
    idx = rng.integers(0, 8, (16, 16))
    np.testing.assert_array_equal(read_image(_palette_png(tmp_path / "p.png", idx, pal)),
                                  pal[idx])
    bad = idx.copy()
    bad[:4] = 12
    with pytest.raises(ValueError, match=r"palette index 12 beyond its PLTE of 8 entries"):
        read_image(_palette_png(tmp_path / "oob.png", bad, pal))
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = read_image(_palette_png(tmp_path / "t.png", idx, pal, trns=bytes([0, 128])))
    np.testing.assert_array_equal(got, pal[idx])        # the colours, as without tRNS
    blob = bytearray((tmp_path / "p.png").read_bytes())
    blob[33 + 8 + 24 + 2] ^= 0xFF                        # a byte of the PLTE chunk's CRC
    (tmp_path / "crc.png").write_bytes(bytes(blob))
    capfd.readouterr()
    assert main(["simulate", str(tmp_path / "crc.png"), "--out", str(tmp_path / "o"),
                 "--quiet"]) == 2
    err = capfd.readouterr().err.strip().splitlines()
    assert err == [f"rgbz-fast simulate: error: path: cannot read {tmp_path / 'crc.png'} as an "
                   "image (a damaged PNG that Pillow cannot identify: a chunk's CRC or the "
                   "header)"], err


def test_a_dataset_says_which_entries_it_leaves_out(tmp_path):
    """H84: a broken link or a FIFO under an image's name in a dataset folder was left out
    without a word (the run evaluated one image of three); a folder named like an image is
    no image and stays out silently."""
    from PIL import Image

    Image.fromarray(np.zeros((8, 8, 3), np.uint8)).save(tmp_path / "a.png")
    (tmp_path / "dangling.png").symlink_to(tmp_path / "gone" / "b.png")
    os.mkfifo(tmp_path / "f.tif")
    (tmp_path / "sub.png").mkdir()
    with pytest.warns(UserWarning, match=r"^dataset: left out 'dangling.png', 'f.tif' of .*: "
                                         "not regular files"):
        assert [s.name for s in rio.folder_dataset(tmp_path)] == ["a"]


def test_image_source_keeps_raw_options_as_folder_dataset_does(tmp_path):
    """Round 25 (API11): a dict of read_raw's options was kept as it was: the frozen source
    was unhashable and unequal to folder_dataset's source of the same file and options."""
    from rgbz_fast.io import ImageSource, folder_dataset

    (tmp_path / "a.raw").write_bytes(np.zeros(16, np.uint16).tobytes())
    opts = {"phase": "GRBG", "white_level": 1023, "black_level": 0, "shape": [4, 4],
            "bit_depth_in": 10}
    (src,) = folder_dataset(tmp_path, raw_options={"a.raw": opts})
    mine = ImageSource("a", str(tmp_path / "a.raw"), opts, raw=True)
    assert mine == src and hash(mine) == hash(src)
    assert mine.raw_options == (("bit_depth_in", 10), ("black_level", 0), ("phase", "GRBG"),
                                ("shape", (4, 4)), ("white_level", 1023))
    assert ImageSource("a", "a.raw", mine.raw_options) == ImageSource("a", "a.raw", opts)
    with pytest.raises(TypeError, match=r"^ImageSource.raw_options: expected a dict"):
        ImageSource("a", "a.raw", 3)


def test_a_16_bit_grey_png_in_pillows_int32_mode_reads_as_uint16(tmp_path, monkeypatch):
    """H118: with the dependency floors (Pillow 10.1, imageio 2.30) Pillow opens a 16-bit grey
    PNG in mode "I" and imageio gives int32 samples, which every raw reader refused ("expected
    uint8 or uint16 samples, got int32"): the codes are taken as uint16."""
    from rgbz_fast.io import _files

    codes = np.arange(0, 65536, 257, dtype=np.uint16).reshape(16, 16)
    path = tmp_path / "grey16.png"
    import imageio.v3 as iio
    iio.imwrite(path, codes)
    real = _files._decode_png_pillow
    monkeypatch.setattr(_files, "_decode_png_pillow",
                        lambda data: real(data).astype(np.int32))   # what the floors give
    got = read_image(path)
    assert got.dtype == np.uint16 and np.array_equal(got, codes)
    mosaic, _ = rio._raw._read_image(path, (None, None))
    assert mosaic.dtype == np.uint16 and np.array_equal(mosaic, codes)
