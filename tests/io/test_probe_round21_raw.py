"""Probe round 21 (B2-B4): raw levels and rgbz-fast's own CFA TIFFs.

B2, a saturation level at or below the black level: refused where it enters (read_raw's
clip_level, the command line's --saturation-level) in plain numbers; it had come from the
reconstruction as ``--clip-level: (np.float64(20.0), ...)``. B3, a white level far below the
data (a typo: 102 for 1023) clipped most of the frame without a word. B4, the CFA TIFF of
``reconstruct`` did not record its black and white levels, and the reader did not read its
description back. The real raw files of ../shared/data/raw (skipped when absent) and small
frames written to tmp_path; each test takes a few seconds."""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest
from _support import shared_path

from rgbz_fast import RawFrame, bayer
from rgbz_fast._cli import main
from rgbz_fast.io import frame_clip_level, load_frame, read_raw, save_frame

# conventions of the three files (../shared/data/raw/SOURCE.md)
PNG_ARGS = dict(phase="GRBG", black_level=25, white_level=1023)


def test_a_saturation_level_at_the_black_level_is_refused_at_load_naming_the_flag(
        tmp_path, capsys):
    """B2: the error names --saturation-level (not --clip-level, given as auto), in plain
    numbers, per quad site only where they differ, before anything is written."""
    png = shared_path("raw", "halide_bayer_small.png")
    out = tmp_path / "out"
    rc = main(["reconstruct", str(png), "--rgbz-pattern", "mask2", "--phase", "GRBG",
               "--black-level", "25", "--white-level", "1023", "--saturation-level", "20",
               "--clip-level", "auto", "--out", str(out)])
    err = capsys.readouterr().err
    assert rc == 2
    assert "error: --saturation-level: 20 is at or below the black level 25" in err
    assert "--clip-level" not in err and "np.float64" not in err
    assert not out.exists()
    # the library: read_raw's clip_level, where it enters
    with pytest.raises(ValueError, match=r"^clip_level: \(20, 30, 30, 30\) is at or below the "
                                         r"black level 25: "):
        read_raw(png, clip_level=(20, 30, 30, 30), **PNG_ARGS)
    with pytest.raises(ValueError, match=r"^clip_level: 25\.2 is less than half a code"):
        read_raw(png, clip_level=25.2, bit_depth=10, **PNG_ARGS)
    # a frame that carries such a level (built by hand): named as the frame's, plain numbers
    meta = {"black_level": (25,) * 4, "white_level": (1023,) * 4, "clip_level": (20,) * 4}
    with pytest.raises(ValueError, match=r"^frame: its saturation level .* 20 is at or below "
                                         r"its black level 25: ") as info:
        frame_clip_level(RawFrame(np.zeros((2, 2), np.uint16), bayer("RGGB"), meta=meta))
    assert "np.float64" not in str(info.value)


def test_a_white_level_far_below_the_data_is_warned_about(tmp_path, capsys):
    """B3: --white-level 102 (for 1023) clips 59.4 % of the 10-bit frame: a warning naming
    the white level, the share and the largest value; the real files at their correct levels
    (bright ones included: openisp's clipped white chart) stay below the threshold."""
    png = shared_path("raw", "halide_bayer_small.png")
    with pytest.warns(UserWarning, match=r"^white_level: 59\.4 % of the pixels of "
                                         r"halide_bayer_small\.png are at or above its white "
                                         r"level 102 .*the largest value found is 1053") as seen:
        frame = read_raw(png, phase="GRBG", black_level=25, white_level=102)
    assert "1023 for 10-bit data" in str(seen[0].message)
    from rgbz_fast.io._raw import WHITE_SHARE_WARN

    assert frame.meta["clipped_fraction"] > WHITE_SHARE_WARN
    raw = shared_path("raw", "openisp_test.RAW")
    with warnings.catch_warnings():
        warnings.simplefilter("error")                     # no warning at the right levels
        read_raw(png, **PNG_ARGS)
        f = read_raw(raw, shape=(1080, 1920), phase="RGGB", black_level=0, bit_depth_in=10,
                     clip_level=1020)
        assert 0.09 < f.meta["clipped_fraction"] < WHITE_SHARE_WARN
        try:
            import rawpy  # noqa: F401
        except ImportError:
            pass
        else:
            read_raw(shared_path("raw", "colorchart.dng"))
    # the command line: the flag, on a 'warning:' line; the outputs are written (exit 0)
    with warnings.catch_warnings():
        warnings.simplefilter("always")                    # printed, as a user sees it
        rc = main(["reconstruct", str(png), "--rgbz-pattern", "mask2", "--phase", "GRBG",
                   "--black-level", "25", "--white-level", "102", "--quiet",
                   "--out", str(tmp_path / "out")])
    err = capsys.readouterr().err
    assert rc == 0
    assert "warning: --white-level: 59.4 % of the pixels" in err
    assert "--bit-depth-in BITS" in err


def test_the_cfa_tiff_of_reconstruct_is_read_back_with_its_phase_and_levels(tmp_path,
                                                                             capsys):
    """B4: the CFA TIFF records its phase, the black level in its data, its white level and
    bit depth under rgbz-fast's own key; the reader takes them from it (the same CFA values
    back), and takes no such key of a foreign TIFF."""
    import tifffile

    from rgbz_fast.simulation import Scene, simulate

    # a simulated frame: its sensor's black level (64 DN) stays in the data
    rng = np.random.default_rng(0)
    scene = Scene(np.clip(0.5 + 0.3 * rng.standard_normal((48, 64, 3)), 0, 1))
    frame = simulate(scene, "mask2", seed=1)
    save_frame(tmp_path / "f.npz", frame)
    assert main(["reconstruct", str(tmp_path / "f.npz"), "--quiet", "--out",
                 str(tmp_path / "rec")]) == 0
    tif = tmp_path / "rec" / "f_sg_cfa.tif"
    with tifffile.TiffFile(tif) as t:
        desc = json.loads(t.pages[0].description)
        written = t.pages[0].asarray()
    assert desc["format"] == "rgbz-fast CFA" and desc["bayer"] == frame.pattern.bayer_phase
    assert desc["black_level"] == frame.meta["colour_black_level"] > 0
    assert (desc["white_level"], desc["bit_depth"]) == (frame.white_level, frame.bit_depth)
    back = load_frame(tif, bit_depth="input")                   # no phase, no levels given
    assert back.pattern == bayer(desc["bayer"]) and back.bit_depth == frame.bit_depth
    black, white = desc["black_level"], desc["white_level"]
    expect = np.floor(np.clip((written - black) / (white - black), 0, 1) * white + 0.5)
    np.testing.assert_array_equal(back.data, expect)
    # the command line reads it back, as the probe did
    assert main(["reconstruct", str(tif), "--rgbz-pattern", "mask2", "--quiet", "--out",
                 str(tmp_path / "back")]) == 0

    # a raw file's CFA (black level subtracted when read): the very values come back
    import imageio.v3 as iio

    png = shared_path("raw", "halide_bayer_small.png")
    crop = tmp_path / "crop.png"
    iio.imwrite(crop, iio.imread(png)[:96, :128])
    assert main(["reconstruct", str(crop), "--rgbz-pattern", "mask2", "--phase", "GRBG",
                 "--black-level", "25", "--white-level", "1023", "--quiet", "--out",
                 str(tmp_path / "rec2")]) == 0
    for name in ("crop_mask2_sg_cfa.tif", "crop_mask2_reference_cfa.tif"):
        written = tifffile.imread(tmp_path / "rec2" / name)
        again = read_raw(tmp_path / "rec2" / name, bit_depth="input")
        assert again.meta["black_level"] == (0.0,) * 4 and again.pattern == bayer("GRBG")
        np.testing.assert_array_equal(again.data, written)

    # a foreign TIFF with the same keys but not rgbz-fast's: its keys are not taken
    foreign = tmp_path / "foreign.tif"
    tifffile.imwrite(foreign, written, description=json.dumps(
        {"bayer": "GRBG", "black_level": 0, "white_level": 1023, "bit_depth": 10}))
    capsys.readouterr()
    assert main(["reconstruct", str(foreign), "--rgbz-pattern", "mask2", "--quiet",
                 "--out", str(tmp_path / "f")]) == 2
    assert "does not record its CFA phase" in capsys.readouterr().err
