"""Patterns (CDFA) and raw frames: the paper's Fig. 1 and Fig. 4, mosaic() and RawFrame."""

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast import B, G, R, Z


def test_mask1_quarter_z_and_no_green_on_z_rows_and_columns():
    p = rz.mask1()
    assert str(p) == "ZR/BG" and p.period == (2, 2) and p.bayer_phase == "GRBG"
    ch = p.channel_map((16, 24))
    z = ch == Z
    assert z.mean() == 0.25
    rows_with_z = np.any(z, axis=1)
    cols_with_z = np.any(z, axis=0)
    assert not np.any(ch[rows_with_z] == G)
    assert not np.any(ch[:, cols_with_z] == G)
    # Fig. 11: the four greens of the 5x5 kernel centred on a Z site are 6, 8, 16, 18
    win = ch[4 - 2:4 + 3, 6 - 2:6 + 3].ravel()
    assert sorted(np.flatnonzero(win == G)) == [6, 8, 16, 18]
    # every Z site stands in for a green of the underlying GRBG Bayer
    assert np.all(p.missing_colour((16, 24))[z] == G)


def test_mask2_each_tile_loses_one_quad():
    p = rz.mask2()
    assert p.period == (4, 4)
    miss = p.missing_colour((8, 8))
    for ty in (0, 4):
        for tx in (0, 4):
            tile = miss[ty:ty + 4, tx:tx + 4]
            lost = tile[tile >= 0]
            assert sorted(lost.tolist()) == sorted([G, R, B, G])
            assert np.array_equal(tile[:2, :2] >= 0, np.ones((2, 2), bool))
    assert p.z_fraction == 0.25
    # Table 1 caption: 11 green candidates, 8 red/blue, in the 5x5 kernel
    ch = p.channel_map((12, 12))
    for (y, x), colour, n in (((4, 4), G, 11), ((4, 5), R, 8), ((5, 4), B, 8), ((5, 5), G, 11)):
        win = ch[y - 2:y + 3, x - 2:x + 3]
        assert np.sum(win == colour) == n


def test_rows_pattern_shi():
    p = rz.rows()
    assert p.period == (6, 2)
    ch = p.channel_map((12, 4))
    assert np.all(ch[4:6] == Z) and np.all(ch[10:12] == Z) and not np.any(ch[:4] == Z)


@pytest.mark.parametrize("phase", rz.BAYER_PHASES)
def test_all_bayer_phases(phase):
    b = rz.bayer(phase)
    assert "".join("RGBZ"[c] for c in b.tile.ravel()) == phase
    assert not b.has_z
    for factory in (rz.mask1, rz.mask2, rz.rows):
        p = factory(phase)
        assert p.bayer_phase == phase
        known = p.tile != Z
        assert np.array_equal(p.tile[known], p.bayer_tile()[known])


def test_custom_tile_and_bayer_inference():
    p = rz.Pattern("ZR/BG")
    assert p == rz.mask1() or p.bayer_phase == "GRBG"
    assert rz.get_pattern("mask2_rggb").bayer_phase == "RGGB"
    assert rz.get_pattern("ZR/BG").z_fraction == 0.25
    amb = rz.Pattern("ZZ/ZG")
    assert amb.bayer_phase == "GRBG"     # GRBG first when several phases agree
    assert rz.Pattern("ZZ/ZG", bayer="GBRG").bayer_phase == "GBRG"
    assert rz.Pattern("RR/RR").bayer_phase is None


@pytest.mark.parametrize("tile, match", [
    ("ZX/BG", "unknown channel"), ("ZRG/BG", "ragged"), ("ZZ/ZZ", "no colour"),
    ("", "empty"), ("ZR//BG", "empty"),
])
def test_invalid_tiles(tile, match):
    with pytest.raises(ValueError, match=f"tile: .*{match}"):
        rz.Pattern(tile)


def test_pattern_errors_name_parameters():
    with pytest.raises(ValueError, match="^bayer:"):
        rz.Pattern("ZR/BG", bayer="RGGB")
    with pytest.raises(ValueError, match="^phase:"):
        rz.mask1("XYZW")
    with pytest.raises(ValueError, match="^pattern:"):
        rz.get_pattern("mask9")
    with pytest.raises(TypeError, match="^pattern:"):
        rz.get_pattern(3)
    with pytest.raises(ValueError, match="^shape:.*smaller than one period"):
        rz.mask2().channel_map((3, 8))
    with pytest.raises(ValueError, match="fits no Bayer"):
        rz.Pattern("RR/RZ").missing_colour((4, 4))


def test_mosaic_scaling_rule():
    img = np.zeros((4, 4, 3), np.uint8)
    img[..., 0], img[..., 1], img[..., 2] = 255, 128, 1
    f = rz.mosaic(img, rz.bayer(), bit_depth=11)
    # round(v / (2^k - 1) * (2^b - 1)), k = 8, b = 11
    assert f.data[0, 1] == 2047                       # R
    assert f.data[0, 0] == round(128 / 255 * 2047)    # G
    assert f.data[1, 0] == round(1 / 255 * 2047)      # B
    img16 = (img.astype(np.uint16) * 257)
    assert np.array_equal(rz.mosaic(img16, rz.bayer()).data, f.data)
    flt = rz.mosaic(img / 255.0, rz.bayer(), dtype=np.float64)   # float output: not rounded
    assert flt.data.dtype == np.float64 and flt.data[0, 1] == 2047.0
    assert flt.data[0, 0] == pytest.approx(128 / 255 * 2047, rel=1e-15)


def test_mosaic_rgbz_equals_bayer_except_z():
    img = np.random.default_rng(0).integers(0, 256, (12, 16, 3), dtype=np.uint8)
    ref = rz.mosaic(img, rz.bayer())
    for p in (rz.mask1(), rz.mask2(), rz.rows()):
        f = rz.mosaic(img, p)
        z = f.z_mask
        assert np.array_equal(f.data[~z], ref.data[~z])
        assert np.all(f.data[z] == 0)
        assert np.array_equal(z, p.z_mask(img.shape[:2]))


@pytest.mark.parametrize("bad, exc, match", [
    (np.zeros((4, 4)), ValueError, "^rgb: expected a 3-D"),
    (np.zeros((4, 4, 2)), ValueError, "^rgb: expected 3 channels"),
    (np.full((4, 4, 3), np.nan), ValueError, "^rgb: .*NaN"),
    (np.full((4, 4, 3), 1.5), ValueError, r"^rgb: .*\[0, 1\]"),
    (np.zeros((1, 4, 3)), ValueError, "^rgb: .*smaller than one period"),
    (np.zeros((4, 4, 3), complex), TypeError, "^rgb:"),
])
def test_mosaic_bad_input(bad, exc, match):
    with pytest.raises(exc, match=match):
        rz.mosaic(bad, rz.mask1())


def test_mosaic_bad_parameters():
    img = np.zeros((4, 4, 3), np.uint8)
    with pytest.raises(ValueError, match="^bit_depth:"):
        rz.mosaic(img, rz.mask1(), bit_depth=17)
    with pytest.raises(TypeError, match="^bit_depth:"):
        rz.mosaic(img, rz.mask1(), bit_depth=11.0)
    with pytest.raises(ValueError, match="^dtype:"):
        rz.mosaic(img, rz.mask1(), bit_depth=11, dtype=np.uint8)
    with pytest.raises(TypeError, match="^dtype:"):
        rz.mosaic(img, rz.mask1(), dtype=np.int32)


def test_rawframe_validation_and_reference():
    p = rz.mask1()
    data = np.full((4, 4), 100, np.uint16)
    data[p.z_mask(data.shape)] = 60000        # Z sites hold no colour: ignored by the range check
    f = rz.RawFrame(data, "mask1", 11, reference=np.full((4, 4), 100, np.uint16))
    assert f.white_level == 2047 and f.shape == (4, 4) and "with reference" in repr(f)
    with pytest.raises(ValueError, match="^data: values span"):
        rz.RawFrame(np.full((4, 4), 3000, np.uint16), p, 11)
    with pytest.raises(ValueError, match="^reference: shape"):
        rz.RawFrame(data, p, 11, reference=np.zeros((2, 2), np.uint16))
    with pytest.raises(ValueError, match="^reference: values span"):
        rz.RawFrame(data, p, 11, reference=np.full((4, 4), 5000, np.uint16))
    with pytest.raises(ValueError, match="^data: a uint8 frame cannot hold 12-bit"):
        rz.RawFrame(np.zeros((4, 4), np.uint8), p, 12)
    with pytest.raises(TypeError, match="^data: dtype int32"):
        rz.RawFrame(np.zeros((4, 4), np.int32), p, 11)


def test_read_only_input_accepted_and_not_modified():
    img = np.random.default_rng(1).integers(0, 256, (8, 8, 3), dtype=np.uint8)
    f = rz.mosaic(img, rz.mask2())
    data = f.data.copy()
    data.setflags(write=False)
    before = data.copy()
    out = rz.reconstruct(data, "sg", pattern="mask2")
    assert np.array_equal(data, before) and out.flags.writeable


def test_rawframe_owns_its_data():
    """Writes to the caller's arrays after construction cannot reach the frame (NaN, 1e9)."""
    a = np.zeros((8, 8))
    ref = np.zeros((8, 8))
    f = rz.RawFrame(a, "mask1", reference=ref)
    a[1, 1], a[0, 1], ref[0, 0] = np.nan, 1e9, 1e9
    assert not np.shares_memory(f.data, a) and not np.shares_memory(f.reference, ref)
    assert not f.data.flags.writeable and not f.reference.flags.writeable
    assert f.data.flags.c_contiguous
    np.testing.assert_array_equal(rz.reconstruct(f, "sg"), np.zeros((8, 8)))
    assert f.reference.max() == 0
    with pytest.raises(ValueError, match="read-only"):
        f.data[0, 0] = 5
    # a Fortran-ordered or strided input is stored C-contiguous, with the same values
    g = rz.RawFrame(np.asfortranarray(np.arange(64, dtype=np.uint16).reshape(8, 8)), "mask1")
    assert g.data.flags.c_contiguous and g.data[0, 3] == 3


def test_tof_taps_own_their_arrays():
    """ToFTaps copies what it is given: the caller's arrays keep their flags and values."""
    from rgbz_fast._frame import ToFTaps
    from rgbz_fast.simulation import ToFSensor

    taps = np.ones((1, 4, 2), np.uint16)
    depth, valid, sat = np.ones(2), np.ones(2, bool), np.zeros(2, bool)
    t = ToFTaps(taps, [20e6], (np.array([0, 2]), np.array([0, 0])), 1, 12, depth, valid, sat,
                ToFSensor(frequencies=(20e6,), bit_depth=12), (4, 4))
    taps[...] = 9
    depth[...] = -1
    assert taps.flags.writeable and depth.flags.writeable    # not frozen behind the caller
    assert t.taps.max() == 1 and t.depth_true.min() == 1
    assert not (t.taps.flags.writeable or t.valid.flags.writeable)


@pytest.mark.parametrize("dtype, width", [(np.uint8, 8), (np.uint16, 16), (np.int32, 31),
                                          (np.bool_, 1)])
def test_mosaic_input_bits_within_the_dtype(dtype, width):
    """input_bits beyond the dtype's width scaled every value to ~0 (100: an all-zero frame)."""
    img = np.ones((4, 4, 3), dtype)
    assert rz.mosaic(img, "bayer", input_bits=width).data.max() == round(2047 / (2**width - 1))
    for bad in (0, width + 1, 100, 2000):
        with pytest.raises(ValueError, match=f"^input_bits: expected 1..{width} bits for "):
            rz.mosaic(img, "bayer", input_bits=bad)
    with pytest.raises(ValueError, match="^input_bits: applies to integer input only"):
        rz.mosaic(np.zeros((4, 4, 3)), "bayer", input_bits=8)


def test_a_tile_written_at_a_multiple_of_its_period_is_the_same_pattern():
    """Probe round 24 (I-02): Mask1 written as ZRZR/BGBG/ZRZR/BGBG moved the border taps by 4,
    not 2 (up to 449 DN at a frame's edges), costed 9 line buffers for Mask2 at period 8,
    and found no shipped learned filters. A tile is kept at its smallest period."""
    import rgbz_fast as rz

    long1 = rz.Pattern("ZRZR/BGBG/ZRZR/BGBG")
    assert long1 == rz.mask1() and long1.period == (2, 2) and long1.tile_string == "ZR/BG"
    m2 = rz.mask2()
    long2 = rz.Pattern(np.tile(m2.tile, (2, 2)))
    assert long2 == m2 and long2.period == (4, 4)
    assert rz.Pattern("ZRGR/BGBG/GRZR/BGBG").period == (4, 4)       # irreducible: as written
    rng = np.random.default_rng(0)
    img = rng.random((40, 48, 3))
    for method in ("bilinear", "sg", "learned"):
        a = rz.reconstruct(rz.mosaic(img, "mask1"), method)
        b = rz.reconstruct(rz.mosaic(img, "ZRZR/BGBG/ZRZR/BGBG"), method)
        assert np.array_equal(a, b), method


def test_reconstruct_refuses_a_tile_of_no_bayer_phase_without_z():
    """Probe round 24 (I-03): RR/RR (no Z, no Bayer phase) came back as "the full Bayer CFA"
    where the guide says reconstruct refuses it (the ISP, mosaic and simulate did)."""
    import rgbz_fast as rz

    data = np.zeros((8, 8), np.uint16)
    for tile in ("RR/RR", "GR/GR", "RGB/GBR"):
        with pytest.raises(ValueError, match=r"^pattern: tile .* fits no Bayer phase, so it "
                                             r"is no Bayer CFA to return$"):
            rz.reconstruct(data, "sg", pattern=tile, bit_depth=11)
    assert np.array_equal(rz.reconstruct(data, "sg", pattern="bayer", bit_depth=11), data)
