"""The raw readers (rgbz_fast.io.read_raw, to_rgbz, clipped_mask): the three real files of
../shared/data/raw and synthetic round trips."""

from __future__ import annotations

import sys


import numpy as np  # noqa: E402
import pytest  # noqa: E402
from _support import shared_path  # noqa: E402

from rgbz_fast import RawFrame, bayer, mask1, mask2, reconstruct, rows  # noqa: E402
from rgbz_fast._patterns import BAYER_PHASES
from rgbz_fast.io import clipped_mask, list_raw_files, read_raw, to_rgbz  # noqa: E402

PHASES = ["RGGB", "BGGR", "GRBG", "GBRG"]

# conventions of the three files (../shared/data/raw/SOURCE.md)
PNG_ARGS = dict(phase="GRBG", black_level=25, white_level=1023)
RAW_ARGS = dict(shape=(1080, 1920), phase="RGGB", black_level=0, bit_depth_in=10)


def _green_means(frame):
    """Means of the two green sites of the frame's Bayer quad."""
    tile = frame.pattern.bayer_tile()
    d = frame.data.astype(np.float64)
    return [d[i::2, j::2].mean() for i in range(2) for j in range(2) if tile[i, j] == 1]


def _normalise(raw, black, white, bits=11):
    """Independent reference of the normalisation: per-pixel black and white, round half up."""
    top = (1 << bits) - 1
    v = (raw.astype(np.float64) - black) / (white - black) * top
    return np.floor(np.clip(v, 0, top) + 0.5).astype(np.uint16)


def _bin2(a):
    """Manual 2x2 binning of each colour plane (a's shape a multiple of 4)."""
    out = np.empty((a.shape[0] // 2, a.shape[1] // 2))
    for i in range(2):
        for j in range(2):
            p = a[i::2, j::2].astype(np.float64)
            out[i::2, j::2] = (p[0::2, 0::2] + p[0::2, 1::2] + p[1::2, 0::2] + p[1::2, 1::2]) / 4
    return out


def _synthetic_cfa(phase, shape=(12, 16), seed=0, levels=(300, 500, 900), noise=20):
    """A 10-bit Bayer mosaic whose R, G, B sites sit near distinct levels."""
    rng = np.random.default_rng(seed)
    colour = bayer(phase).bayer_map(shape)
    base = np.asarray(levels)[colour]
    return (base + rng.integers(-noise, noise + 1, shape)).astype(np.uint16), colour


# --------------------------------------------------------------------------
# the three real files
# --------------------------------------------------------------------------
@pytest.fixture(scope="module")
def dng_path():
    pytest.importorskip("rawpy")
    return shared_path("raw", "colorchart.dng")


@pytest.fixture(scope="module")
def png_path():
    return shared_path("raw", "halide_bayer_small.png")


@pytest.fixture(scope="module")
def raw_path():
    return shared_path("raw", "openisp_test.RAW")


@pytest.fixture(scope="module")
def dng(dng_path):
    return read_raw(dng_path)


@pytest.fixture(scope="module")
def dng_data(dng_path):
    import rawpy

    with rawpy.imread(str(dng_path)) as raw:
        return raw.raw_image_visible.copy()


def test_dng_phase_levels_shape(dng):
    assert isinstance(dng, RawFrame)
    assert dng.pattern == bayer("RGGB")
    assert dng.meta["phase"] == "RGGB"
    assert dng.shape == (1156, 1734)
    assert dng.data.dtype == np.uint16 and dng.bit_depth == 11
    assert dng.meta["black_level"] == (2056.0,) * 4
    assert dng.meta["white_level"] == (15000.0,) * 4
    assert dng.meta["make"] == "Canon"
    assert dng.meta["model"] == "Canon EOS Kiss X4"
    assert dng.meta["reader"] == "libraw"
    assert dng.meta["clipped_count"] == 0           # SOURCE.md: no clipping
    assert dng.meta["clipped"].shape == dng.shape and not dng.meta["clipped"].any()


def test_dng_values(dng, dng_data):
    np.testing.assert_array_equal(dng.data, _normalise(dng_data, 2056, 15000))


def test_dng_arguments_override_file(dng_path, dng_data):
    f = read_raw(dng_path, white_level=16383, black_level=2048, bit_depth=12)
    assert f.meta["white_level"] == (16383.0,) * 4 and f.meta["black_level"] == (2048.0,) * 4
    np.testing.assert_array_equal(f.data, _normalise(dng_data, 2048, 16383, bits=12))
    assert read_raw(dng_path, phase="grbg").pattern == bayer("GRBG")


def test_png_phase_levels_shape(png_path):
    f = read_raw(png_path, **PNG_ARGS)
    assert f.pattern == bayer("GRBG")
    assert f.shape == (344, 256)
    assert f.meta["black_level"] == (25.0,) * 4 and f.meta["white_level"] == (1023.0,) * 4
    assert f.meta["reader"] == "image"
    assert f.meta["clipped_count"] == 3             # SOURCE.md: 3 pixels > 1023


def test_raw_phase_levels_shape(raw_path):
    f = read_raw(raw_path, **RAW_ARGS)
    assert f.pattern == bayer("RGGB")
    assert f.shape == (1080, 1920)
    assert f.meta["black_level"] == (0.0,) * 4
    assert f.meta["white_level"] == (1023.0,) * 4   # 2**10 - 1 from bit_depth_in
    assert f.meta["bit_depth_in"] == 10 and f.meta["byteorder"] == "<"
    raw = np.fromfile(raw_path, "<u2").reshape(1080, 1920)
    np.testing.assert_array_equal(f.data, _normalise(raw, 0, 1023))


@pytest.mark.parametrize("which", ["dng", "png", "raw"])
def test_real_greens_agree(which, request):
    if which == "dng":
        f = request.getfixturevalue("dng")
    elif which == "png":
        f = read_raw(request.getfixturevalue("png_path"), **PNG_ARGS)
    else:
        f = read_raw(request.getfixturevalue("raw_path"), **RAW_ARGS)
    g1, g2 = _green_means(f)
    np.testing.assert_allclose(g1, g2, rtol=0.02)


def test_openisp_clipping(raw_path):
    raw = np.fromfile(raw_path, "<u2").reshape(1080, 1920)
    # white level 1023, but the sensor stops at 1020: the default finds nothing
    assert read_raw(raw_path, **RAW_ARGS).meta["clipped_count"] == 0
    f = read_raw(raw_path, clip_level=1020, **RAW_ARGS)
    assert f.meta["clip_level"] == (1020.0,) * 4
    np.testing.assert_array_equal(f.meta["clipped"], raw >= 1020)
    assert f.meta["clipped_count"] == int((raw >= 1020).sum())
    assert 0.09 < f.meta["clipped_fraction"] < 0.105    # SOURCE.md: about 9.8 %
    np.testing.assert_array_equal(clipped_mask(f), raw >= 1020)
    np.testing.assert_array_equal(clipped_mask(raw, 1020), raw >= 1020)
    # binned: a pixel is clipped when any of the four it averages is
    g = read_raw(raw_path, clip_level=1020, downsample=2, **RAW_ARGS)
    np.testing.assert_array_equal(g.meta["clipped"], _bin2(raw >= 1020) > 0)
    assert g.meta["clipped_count"] == f.meta["clipped_count"]   # counted on the data as read


def test_clipped_mask_radius_and_frames():
    m = np.zeros((9, 9), np.uint16)
    m[4, 4] = 1023
    grown = clipped_mask(m, 1023, radius=2)
    assert grown.sum() == 25 and grown[2:7, 2:7].all()
    # a frame without meta["clipped"]: pixels at the white level, Z sites never
    data = np.full((4, 4), 2047, np.uint16)
    f = RawFrame(data, mask1("GRBG"))
    assert clipped_mask(f).sum() == 12
    with pytest.raises(ValueError, match="clip_level"):
        clipped_mask(m)


# --------------------------------------------------------------------------
# downsampling
# --------------------------------------------------------------------------
def test_dng_downsample_matches_manual_binning(dng, dng_data):
    f = read_raw(dng.meta["source"], downsample=2)
    assert f.pattern == bayer("RGGB")
    r, c = dng_data.shape
    r, c = r - r % 4, c - c % 4
    assert f.shape == (r // 2, c // 2) == (578, 866)
    binned = _bin2(dng_data[:r, :c].astype(np.float64) - 2056)
    expected = np.floor(np.clip(binned / (15000 - 2056) * 2047, 0, 2047) + 0.5)
    np.testing.assert_array_equal(f.data, expected.astype(np.uint16))
    # the greens still agree, so the phase is kept
    g1, g2 = _green_means(f)
    np.testing.assert_allclose(g1, g2, rtol=0.02)


@pytest.mark.parametrize("phase", PHASES)
def test_downsample_keeps_phase(tmp_path, phase):
    cfa, colour = _synthetic_cfa(phase, shape=(16, 24))
    path = tmp_path / "x.raw"
    cfa.tofile(path)
    f = read_raw(path, shape=cfa.shape, phase=phase, black_level=0, white_level=1023,
                 downsample=2, dtype=np.float64)
    assert f.shape == (8, 12) and f.pattern == bayer(phase)
    np.testing.assert_allclose(f.data, _bin2(cfa) / 1023 * 2047, rtol=1e-12)
    # every binned site stays near the level of its colour
    binned_colour = bayer(phase).bayer_map(f.shape)
    for ch, level in enumerate((300, 500, 900)):
        assert np.all(np.abs(f.data[binned_colour == ch] - level / 1023 * 2047) < 50)


def test_downsample_crops_to_whole_blocks(tmp_path):
    cfa, _ = _synthetic_cfa("GBRG", shape=(10, 14))
    path = tmp_path / "x.raw"
    cfa.tofile(path)
    f = read_raw(path, shape=cfa.shape, phase="GBRG", black_level=0, white_level=1023,
                 downsample=2)
    assert f.shape == (4, 6) and f.meta["crop"] == (8, 12)
    with pytest.raises(ValueError, match="downsample"):
        read_raw(path, shape=cfa.shape, phase="GBRG", black_level=0, white_level=1023,
                 downsample=0)


# --------------------------------------------------------------------------
# synthetic round trips, all four phases
# --------------------------------------------------------------------------
@pytest.mark.parametrize("phase", PHASES)
@pytest.mark.parametrize("fmt", ["png", "tif", "raw_le", "raw_be"])
def test_round_trip(tmp_path, phase, fmt):
    cfa, colour = _synthetic_cfa(phase, shape=(12, 16), seed=PHASES.index(phase))
    args = dict(phase=phase, black_level=64, white_level=1023)
    if fmt == "png":
        import imageio.v3 as iio

        path = tmp_path / "cfa.png"
        iio.imwrite(path, cfa)
    elif fmt == "tif":
        import tifffile

        path = tmp_path / "cfa.tif"
        tifffile.imwrite(path, cfa)
    else:
        order = "<" if fmt == "raw_le" else ">"
        path = tmp_path / "cfa.bin"
        cfa.astype(order + "u2").tofile(path)
        args.update(shape=cfa.shape, byteorder=order)
    f = read_raw(path, **args)
    assert f.pattern == bayer(phase) and f.pattern.bayer_phase == phase
    np.testing.assert_array_equal(f.data, _normalise(cfa, 64, 1023))
    # the recorded phase puts every colour where the mosaic has it
    np.testing.assert_array_equal(f.pattern.bayer_map(f.shape), colour)


def test_wrong_byte_order_differs(tmp_path):
    cfa, _ = _synthetic_cfa("RGGB", shape=(4, 6))
    path = tmp_path / "be.raw"
    cfa.astype(">u2").tofile(path)
    args = dict(shape=(4, 6), phase="RGGB", black_level=0, white_level=65535, bit_depth=16)
    np.testing.assert_array_equal(read_raw(path, byteorder=">", **args).data, cfa)
    assert not np.array_equal(read_raw(path, byteorder="<", **args).data, cfa)


def test_per_channel_black_level(tmp_path):
    cfa = np.array([[110, 220], [330, 440]] * 2, np.uint16).reshape(4, 2)
    cfa = np.tile(cfa, (1, 3))
    path = tmp_path / "x.raw"
    cfa.tofile(path)
    f = read_raw(path, shape=cfa.shape, phase="BGGR", black_level=[10, 20, 30, 40],
                 white_level=1010, dtype=np.float64, bit_depth=10)
    black = np.tile([[10, 20], [30, 40]], (2, 3))
    np.testing.assert_allclose(f.data, (cfa - black) / (1010 - black) * 1023, rtol=1e-12)
    assert f.meta["black_level"] == (10.0, 20.0, 30.0, 40.0)


def test_black_clipped_at_zero_and_crop_even(tmp_path):
    cfa = np.full((5, 7), 10, np.uint16)
    path = tmp_path / "x.raw"
    cfa.tofile(path)
    f = read_raw(path, shape=(5, 7), phase="GRBG", black_level=64, white_level=1023)
    assert f.shape == (5, 7) and not f.data.any()
    g = read_raw(path, shape=(5, 7), phase="GRBG", black_level=64, white_level=1023,
                 crop_even=True)
    assert g.shape == (4, 6) and g.meta["shape_in"] == (5, 7)


# --------------------------------------------------------------------------
# errors
# --------------------------------------------------------------------------
def test_headerless_wrong_size(tmp_path):
    path = tmp_path / "x.raw"
    np.zeros((4, 6), np.uint16).tofile(path)
    with pytest.raises(ValueError, match=r"48 bytes.*4x7"):
        read_raw(path, shape=(4, 7), phase="RGGB", black_level=0, white_level=1023)
    with pytest.raises(ValueError, match="shape"):
        read_raw(path, phase="RGGB", black_level=0, white_level=1023)


def test_levels_the_data_cannot_reach_are_refused(tmp_path):
    """A white level beyond the data type's codes made every pixel 0 (a CFA PSNR of inf); a
    stated bit depth the data exceeds clipped it silently; the levels print as numbers."""
    path = tmp_path / "x.raw"
    data = np.arange(24, dtype=np.uint16).reshape(4, 6) * 40        # up to 920: 10 bits
    data.tofile(path)
    kw = dict(shape=(4, 6), phase="RGGB", black_level=0)
    with pytest.raises(ValueError, match=r"^white_level: 1e\+308 is beyond the largest code "
                                         r"of the uint16 data \(65535\)"):
        read_raw(path, white_level=1e308, **kw)
    with pytest.raises(ValueError, match=r"^bit_depth_in: the data of x.raw reaches 920, "
                                         r"beyond the 8-bit range \[0, 255\]"):
        read_raw(path, bit_depth_in=8, **kw)
    assert read_raw(path, bit_depth_in=10, **kw).meta["clipped_count"] == 0
    with pytest.raises(ValueError, match=r"^white_level: 100 must exceed black_level "
                                         r"\(0, 200, 0, 0\) at every quad site"):
        read_raw(path, **{**kw, "black_level": (0, 200, 0, 0)}, white_level=100)


@pytest.mark.parametrize("missing", ["phase", "black_level", "white_level"])
def test_missing_parameter_is_named(tmp_path, missing):
    path = tmp_path / "x.raw"
    np.zeros((4, 6), np.uint16).tofile(path)
    args = dict(phase="RGGB", black_level=0, white_level=1023)
    del args[missing]
    with pytest.raises(ValueError, match=f"^{missing}:"):
        read_raw(path, shape=(4, 6), **args)


def test_missing_levels_png(png_path):
    with pytest.raises(ValueError, match="^black_level:"):
        read_raw(png_path, phase="GRBG")
    with pytest.raises(ValueError, match="^phase:"):
        read_raw(png_path, black_level=25, white_level=1023)


def test_bad_arguments(tmp_path):
    path = tmp_path / "x.raw"
    np.zeros((4, 6), np.uint16).tofile(path)
    args = dict(shape=(4, 6), phase="RGGB", black_level=0)
    with pytest.raises(ValueError, match="white_level"):
        read_raw(path, white_level=0, **args)
    with pytest.raises(ValueError, match="byteorder"):
        read_raw(path, white_level=1023, byteorder="big", **args)
    with pytest.raises(ValueError, match="phase"):
        read_raw(path, white_level=1023, shape=(4, 6), phase="RGBG", black_level=0)
    with pytest.raises(ValueError, match="black_level"):
        read_raw(path, white_level=1023, shape=(4, 6), phase="RGGB", black_level=[1, 2])
    with pytest.raises(ValueError, match="unknown raw extension"):
        read_raw(tmp_path / "x.jpg")
    with pytest.raises(ValueError, match="uint8 cannot"):
        read_raw(path, white_level=1023, dtype=np.uint8, **args)


def test_rgb_image_is_not_raw(tmp_path):
    import imageio.v3 as iio

    path = tmp_path / "rgb.png"
    iio.imwrite(path, np.zeros((4, 4, 3), np.uint8))
    with pytest.raises(ValueError, match="single-channel"):
        read_raw(path, phase="RGGB", black_level=0, white_level=255)


def test_missing_rawpy_message(tmp_path, monkeypatch):
    path = tmp_path / "x.dng"
    path.write_bytes(b"\0" * 16)
    monkeypatch.setitem(sys.modules, "rawpy", None)
    with pytest.raises(ImportError, match="pip install rawpy"):
        read_raw(path)


def test_unreadable_camera_raw(tmp_path):
    pytest.importorskip("rawpy")
    path = tmp_path / "x.nef"
    path.write_bytes(b"not a raw file" * 8)
    with pytest.raises(ValueError, match="LibRaw cannot read"):
        read_raw(path)


# --------------------------------------------------------------------------
# listing and RGB-Z frames
# --------------------------------------------------------------------------
def test_list_raw_files(tmp_path):
    for name in ["b.DNG", "a.png", "c.raw", "notes.txt", ".hidden.png", "d.tiff"]:
        (tmp_path / name).write_bytes(b"")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "e.nef").write_bytes(b"")
    assert [p.name for p in list_raw_files(tmp_path)] == ["a.png", "b.DNG", "c.raw", "d.tiff"]
    assert [p.name for p in list_raw_files(tmp_path, recursive=True)][-1] == "e.nef"
    assert [p.name for p in list_raw_files(tmp_path, extensions=["dng"])] == ["b.DNG"]


def test_list_shared_raw_files():
    folder = shared_path("raw")
    names = [p.name for p in list_raw_files(folder)]
    assert names == ["colorchart.dng", "halide_bayer_small.png", "openisp_test.RAW"]


@pytest.mark.parametrize("phase", PHASES)
@pytest.mark.parametrize("preset", [mask1, mask2, rows])
def test_to_rgbz(phase, preset):
    cfa, _ = _synthetic_cfa(phase, shape=(13, 18))
    frame = RawFrame(cfa, bayer(phase), bit_depth=10,
                     meta={"clipped": cfa >= 900, "source": "synthetic"})
    rgbz, ref = to_rgbz(frame, preset.__name__)
    pattern = preset(phase)
    assert rgbz.pattern == pattern and rgbz.pattern.bayer_phase == phase
    P, Q = pattern.period
    r, c = 13 - 13 % P, 18 - 18 % Q
    assert rgbz.shape == ref.shape == (r, c)
    np.testing.assert_array_equal(ref, cfa[:r, :c])
    np.testing.assert_array_equal(rgbz.reference, ref)
    z = pattern.z_mask((r, c))
    assert not rgbz.data[z].any()
    np.testing.assert_array_equal(rgbz.data[~z], ref[~z])
    # the Z sites stand in for the colour the reference has there
    np.testing.assert_array_equal(pattern.bayer_map((r, c)), bayer(phase).bayer_map((r, c)))
    np.testing.assert_array_equal(rgbz.meta["clipped"], cfa[:r, :c] >= 900)
    assert rgbz.meta["source"] == "synthetic" and rgbz.meta["rgbz_pattern"] == pattern.name
    # and the reconstruction runs on it
    out = reconstruct(rgbz, "bilinear")
    assert out.shape == ref.shape


def test_to_rgbz_errors():
    cfa, _ = _synthetic_cfa("RGGB", shape=(8, 8))
    frame = RawFrame(cfa, bayer("RGGB"), bit_depth=10)
    with pytest.raises(ValueError, match="phase"):
        to_rgbz(frame, "mask1_grbg")
    with pytest.raises(ValueError, match="phase"):
        to_rgbz(frame, mask1("GRBG"))
    assert to_rgbz(frame, "mask1_rggb")[0].pattern == mask1("RGGB")
    with pytest.raises(ValueError, match="has no Z sites; expected 'mask1'"):
        to_rgbz(frame, "bayer")
    # a tile is shifted onto the frame's phase: its Z sites replace the raw's greens
    tiled, _ = to_rgbz(frame, "ZRGR/BGBG/GRZR/BGBG")
    assert tiled.pattern.bayer_phase == "RGGB"
    assert tiled.pattern.tile_string == "RGRZ/GBGB/RZRG/GBGB"
    rgbz, _ = to_rgbz(frame, "mask1")
    with pytest.raises(ValueError, match="Z sites"):
        to_rgbz(rgbz, "mask1")


def test_real_frame_to_rgbz_reconstructs(raw_path):
    f = read_raw(raw_path, clip_level=1020, downsample=2, **RAW_ARGS)
    rgbz, ref = to_rgbz(f, "mask1")
    assert rgbz.pattern == mask1("RGGB")
    out = reconstruct(rgbz, "bilinear")
    z = rgbz.z_mask
    err = np.abs(out[z].astype(np.float64) - ref[z])
    assert err.mean() < 0.05 * 2047
    assert set(BAYER_PHASES) == set(PHASES)


def test_a_truncated_or_damaged_camera_raw_is_one_clear_error(tmp_path, capfd):
    """LibRaw reads a camera raw lazily: a truncated DNG passed the header and failed when its
    pixels were unpacked, with rawpy's LibRawIOError and LibRaw's own lines on stderr. Every
    failure of LibRaw is now one ValueError naming the file, LibRaw's complaints inside it,
    nothing else on stderr; the command line prints one line."""
    pytest.importorskip("rawpy")
    from rgbz_fast._cli import main

    blob = shared_path("raw", "colorchart.dng").read_bytes()
    for keep in (0.9, 0.3, 0.01):
        f = tmp_path / f"cut{keep}.dng"
        f.write_bytes(blob[:int(len(blob) * keep)])
        capfd.readouterr()
        with pytest.raises(ValueError, match=f"^path: LibRaw cannot read {f.name}: LibRaw"):
            read_raw(f)
        assert capfd.readouterr().err == ""
        assert main(["reconstruct", str(f), "--rgbz-pattern", "mask1", "--out",
                     str(tmp_path / "out"), "--quiet"]) == 2
        err = capfd.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith(f"rgbz-fast reconstruct: error: path: "
                                                   f"LibRaw cannot read {f.name}"), err
    flipped = bytearray(blob)
    flipped[8:4000:7] = b"\xff" * len(flipped[8:4000:7])
    (tmp_path / "flip.dng").write_bytes(bytes(flipped))
    try:
        read_raw(tmp_path / "flip.dng")                   # LibRaw may still read it
    except ValueError as exc:
        assert str(exc).startswith("path: ")


def test_dng_with_a_damaged_tag_reads_without_log_lines(dng_path, tmp_path, caplog):
    """A DNG whose TIFF tags are damaged where LibRaw does not look is read; the metadata
    reader skips the tags it cannot read without logging each one to stderr (on the command
    line those lines came before its own)."""
    blob = bytearray(dng_path.read_bytes())
    rng = np.random.default_rng(0)
    for _ in range(3):                                 # the third draw damages tag 296 only
        damaged = bytearray(blob)
        for i in rng.integers(8, 4096, 20):
            damaged[i] = rng.integers(0, 256)
    (tmp_path / "d.dng").write_bytes(bytes(damaged))
    caplog.set_level("DEBUG")
    frame = read_raw(tmp_path / "d.dng")
    assert frame.shape == (1156, 1734)
    assert [r.getMessage() for r in caplog.records if r.name.startswith("tifffile")] == []


def test_a_clip_level_beyond_every_code_clips_nothing(tmp_path):
    """read_raw's clip level above the white level flags no pixel; clip_level='auto' had
    clamped it to full scale and taken the white pixels for clipped."""
    import rgbz_fast as rz
    from rgbz_fast import io as rio

    a = np.random.default_rng(0).integers(64, 1024, (32, 48)).astype("<u2")
    a[4:12, 4:14] = 1023
    a.tofile(tmp_path / "c.raw")
    f = rio.read_raw(tmp_path / "c.raw", shape=(32, 48), phase="RGGB", black_level=64,
                     bit_depth_in=10, clip_level=1024)
    g, _ = rio.to_rgbz(f, "mask1")
    assert f.meta["clipped_count"] == 0 and rio.frame_clip_level(g) is None
    np.testing.assert_array_equal(rz.reconstruct(g, "sg", clip_level="auto"),
                                  rz.reconstruct(g, "sg"))


@pytest.mark.parametrize("codes, letters", [((3, 4, 4, 5), "CMMY"), ((6, 1, 1, 2), "WGGB"),
                                            ((0, 1, 1, 3), "RGGC")])
def test_a_dng_of_other_colour_filters_is_refused(dng_path, tmp_path, codes, letters):
    """H83: LibRaw maps a DNG's cyan, magenta, yellow or white filters onto its R, G, B
    labels, and read_raw took a CMY or RGBW sensor for an RGB Bayer one (CMMY read as
    bayer_rggb) without a word. Its CFAPattern tag decides now, and the message gives the
    file's own colours."""
    import tifffile

    with tifffile.TiffFile(dng_path) as tif:
        tag = tif.pages[0].tags[33422]
        assert bytes(tag.value) == bytes((0, 1, 1, 2))  # RGGB, four bytes held in the entry
        at = tag.valueoffset
    blob = bytearray(dng_path.read_bytes())
    blob[at:at + 4] = bytes(codes)
    (tmp_path / "cmy.dng").write_bytes(bytes(blob))
    with pytest.raises(ValueError, match=f"^path: cmy.dng has the colour filters '{letters}' "
                                         r"\(its CFAPattern"):
        read_raw(tmp_path / "cmy.dng")


def _write_dng(path, data, black=0, white=4095):
    """A minimal uncompressed 16-bit RGGB DNG (tifffile) that LibRaw reads."""
    import tifffile

    tags = [(33421, "H", 2, (2, 2), True), (33422, "B", 4, bytes((0, 1, 1, 2)), True),
            (50706, "B", 4, b"\x01\x04\x00\x00", True), (50707, "B", 4, b"\x01\x01\x00\x00", True),
            (50708, "s", 0, "Test Camera", True), (271, "s", 0, "Test", True),
            (272, "s", 0, "Camera", True),
            (50721, "2i", 9, (1, 1, 0, 1, 0, 1, 0, 1, 1, 1, 0, 1, 0, 1, 0, 1, 1, 1), True),
            (50728, "2I", 3, (1, 1, 1, 1, 1, 1), True), (50714, "I", 1, (black,), True),
            (50717, "I", 1, (white,), True)]
    tifffile.imwrite(path, data, photometric=32803, extratags=tags, metadata=None)
    return path


def test_an_uncompressed_dng_cut_by_one_byte_is_refused(tmp_path):
    """H83: LibRaw, given the file's bytes, read an uncompressed 16-bit DNG cut by exactly one
    byte without an error, its last pixel wrong (842 for 3658). The mosaic's strips are now
    checked against the file's length."""
    pytest.importorskip("rawpy")
    data = np.random.default_rng(0).integers(100, 4000, (32, 48)).astype(np.uint16)
    whole = read_raw(_write_dng(tmp_path / "whole.dng", data), bit_depth=12)
    np.testing.assert_array_equal(whole.data, data)
    blob = (tmp_path / "whole.dng").read_bytes()
    (tmp_path / "cut.dng").write_bytes(blob[:-1])
    with pytest.raises(ValueError, match=r"^path: cut.dng is truncated: its mosaic's strips "
                                         r"end at byte \d+, the file holds \d+"):
        read_raw(tmp_path / "cut.dng", bit_depth=12)


def test_a_dng_whose_own_levels_cannot_be_is_named(tmp_path):
    """H83: a DNG whose black level lies above its white level was refused blaming
    --white-level (reconstruct), which nobody gave, or `white_level` without the file
    (evaluate); the file is named now, and levels given override it as before."""
    pytest.importorskip("rawpy")
    data = np.random.default_rng(0).integers(100, 4000, (32, 48)).astype(np.uint16)
    f = _write_dng(tmp_path / "levels.dng", data, black=5000, white=4095)
    with pytest.raises(ValueError, match=r"^path: levels.dng records a white level of 4095, "
                                         "not above its black level 5000"):
        read_raw(f)
    with pytest.raises(ValueError, match=r"^white_level: 4095 must exceed black_level 5000"):
        read_raw(f, black_level=5000)
    assert read_raw(f, black_level=0).meta["black_level"] == (0.0,) * 4
