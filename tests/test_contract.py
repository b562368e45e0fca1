"""The bad-input contract of the package root: patterns, raw frames, ToF taps, mosaic.

Rows of docs/reports/robustness.md (``patterns.*``, ``frame.*``), run by the shared
runner of ``tests/_contract.py``, and the checks that keep the report's tables and
the rows of every contract file in step.
"""

from __future__ import annotations

import numpy as np

import rgbz_fast as rz
from _contract import (BUGS, DOC, Row, all_rows, api_tests, f64, files,  # noqa: F401
                       markdown_tables, rgb, sim_frame, table_between, taps_with_sites, u16,
                       u8img, with_value)
from rgbz_fast import simulation as sim

R = Row

ROWS = [
    # -- patterns (rgbz_fast._patterns) ----------------------------------------------------
    R("patterns.none", "get_pattern(None)", lambda f: rz.get_pattern(None), TypeError,
      "pattern: expected a Pattern, a preset name or a tile string"),
    R("patterns.unknown", "get_pattern('mask7')", lambda f: rz.get_pattern("mask7"),
      ValueError, "pattern: 'mask7' is neither a preset"),
    R("patterns.tile-empty", "Pattern('')", lambda f: rz.Pattern(""), ValueError,
      "tile: empty row"),
    R("patterns.tile-ragged", "Pattern('ZR/B')", lambda f: rz.Pattern("ZR/B"), ValueError,
      "tile: ragged rows"),
    R("patterns.tile-letter", "Pattern('ZX/BG')", lambda f: rz.Pattern("ZX/BG"), ValueError,
      "tile: unknown channel letter"),
    R("patterns.tile-only-z", "Pattern('ZZ/ZZ')", lambda f: rz.Pattern("ZZ/ZZ"), ValueError,
      "tile: the tile holds no colour site"),
    R("patterns.tile-ndim", "Pattern(3-D array)", lambda f: rz.Pattern(np.zeros((2, 2, 2), int)),
      ValueError, "tile: expected a non-empty 2-D array"),
    R("patterns.tile-float", "Pattern(float array)", lambda f: rz.Pattern(np.zeros((2, 2))),
      TypeError, "tile: expected integer channel codes"),
    R("patterns.tile-code", "Pattern(code 5)", lambda f: rz.Pattern(np.full((2, 2), 5)),
      ValueError, "tile: channel codes must be"),
    R("patterns.bayer-unknown", "Pattern('ZR/BG', bayer='XXXX')",
      lambda f: rz.Pattern("ZR/BG", bayer="XXXX"), ValueError, "bayer: expected one of"),
    R("patterns.bayer-mismatch", "Pattern('ZR/BG', bayer='RGGB')",
      lambda f: rz.Pattern("ZR/BG", bayer="RGGB"), ValueError,
      "bayer: the colour sites of tile"),
    R("patterns.phase-mask1", "mask1('XXXX')", lambda f: rz.mask1("XXXX"), ValueError,
      "phase: expected one of GRBG"),
    R("patterns.phase-mask2", "mask2(None)", lambda f: rz.mask2(None), ValueError,
      "phase: expected one of GRBG"),
    R("patterns.phase-rows", "rows('')", lambda f: rz.rows(""), ValueError,
      "phase: expected one of GRBG"),
    R("patterns.phase-bayer", "bayer(3)", lambda f: rz.bayer(3), ValueError,
      "phase: expected one of GRBG"),
    R("patterns.shape-ndim", "mask1().z_mask((4,))", lambda f: rz.mask1().z_mask((4,)),
      ValueError, "shape: expected a 2-D (rows, cols) frame shape"),
    R("patterns.shape-small", "mask2().z_mask((3, 3))", lambda f: rz.mask2().z_mask((3, 3)),
      ValueError, "shape: frame 3x3 is smaller than one period (4x4)"),
    R("patterns.shape-none", "mask1().z_mask(None)", lambda f: rz.mask1().z_mask(None),
      TypeError, "shape: expected a (rows, cols) tuple"),
    R("patterns.shape-text", "mask1().z_mask('ab')", lambda f: rz.mask1().z_mask("ab"),
      TypeError, "shape: expected a (rows, cols) tuple"),
    R("patterns.no-bayer", "Pattern('ZR/RG').bayer_tile()",
      lambda f: rz.Pattern("ZR/RG").bayer_tile(), ValueError,
      "pattern: tile 'ZR/RG' fits no Bayer phase"),
    R("patterns.tile-too-large", "Pattern(64x64 array)",
      lambda f: rz.Pattern(np.tile([[3, 0], [2, 1]], (32, 32))), ValueError,
      "tile: 64x64 sites, more than the largest tile (32x32)"),
    R("patterns.tile-too-large-text", "Pattern(a 33-row tile string)",
      lambda f: rz.Pattern("/".join(["ZR", "BG"] * 16 + ["ZR"])), ValueError,
      "tile: 33x2 sites, more than the largest tile (32x32)"),
    # -- RawFrame, ToFTaps, mosaic (rgbz_fast._frame) --------------------------------------
    R("frame.RawFrame-ndim", "RawFrame(3-D array)", lambda f: rz.RawFrame(u16((4, 4, 3)), "mask1"),
      ValueError, "data: expected a 2-D array"),
    R("frame.RawFrame-dtype", "RawFrame(int64 list)",
      lambda f: rz.RawFrame([[1, 2], [3, 4]], "mask1"),
      TypeError, "data: dtype int64 is not supported"),
    R("frame.RawFrame-nan", "RawFrame(NaN)", lambda f: rz.RawFrame(with_value(np.nan), "mask1"),
      ValueError, "data: holds 1 NaN or infinite value(s)"),
    R("frame.RawFrame-range", "RawFrame(value 4000, 11 bits)",
      lambda f: rz.RawFrame(with_value(4000.0), "mask1"), ValueError, "data: values span"),
    R("frame.RawFrame-uint8-bits", "RawFrame(uint8, bit_depth=11)",
      lambda f: rz.RawFrame(np.zeros((4, 4), np.uint8), "mask1"), ValueError,
      "data: a uint8 frame cannot hold 11-bit data"),
    R("frame.RawFrame-small", "RawFrame(1x1, mask1)", lambda f: rz.RawFrame(u16((1, 1)), "mask1"),
      ValueError, "data: frame 1x1 is smaller than one period"),
    R("frame.RawFrame-bit_depth-type", "RawFrame(bit_depth='11')",
      lambda f: rz.RawFrame(u16(), "mask1", bit_depth="11"), TypeError,
      "bit_depth: expected an integer number of bits"),
    R("frame.RawFrame-bit_depth-range", "RawFrame(bit_depth=17)",
      lambda f: rz.RawFrame(u16(), "mask1", bit_depth=17), ValueError,
      "bit_depth: expected 1..16 bits"),
    R("frame.RawFrame-pattern", "RawFrame(pattern='mask7')", lambda f: rz.RawFrame(u16(), "mask7"),
      ValueError, "pattern: 'mask7' is neither a preset"),
    R("frame.RawFrame-reference-shape", "RawFrame(reference of another shape)",
      lambda f: rz.RawFrame(u16(), "mask1", reference=u16((8, 6))), ValueError,
      "reference: shape (8, 6) differs from data (8, 8)"),
    R("frame.RawFrame-reference-range", "RawFrame(reference beyond the bit depth)",
      lambda f: rz.RawFrame(u16(), "mask1", reference=u16(value=5000)), ValueError,
      "reference: values span"),
    R("frame.mosaic-ndim", "mosaic(2-D)", lambda f: rz.mosaic(f64(), "mask1"), ValueError,
      "rgb: expected a 3-D array"),
    R("frame.mosaic-channels", "mosaic(4 channels)",
      lambda f: rz.mosaic(np.zeros((4, 4, 4)), "mask1"),
      ValueError, "rgb: expected 3 channels in the last axis"),
    R("frame.mosaic-float-range", "mosaic(float 1.5)",
      lambda f: rz.mosaic(rgb(value=1.5), "mask1"),
      ValueError, "rgb: float values span"),
    R("frame.mosaic-int-negative", "mosaic(int32 -1)",
      lambda f: rz.mosaic(np.full((4, 4, 3), -1, np.int32), "mask1"), ValueError,
      "rgb: integer values span"),
    R("frame.mosaic-nan", "mosaic(NaN)", lambda f: rz.mosaic(rgb(value=np.nan), "mask1"),
      ValueError, "rgb: holds 768 NaN or infinite value(s)"),
    R("frame.mosaic-small", "mosaic(1x1)", lambda f: rz.mosaic(rgb((1, 1)), "mask1"), ValueError,
      "rgb: frame 1x1 is smaller than one period"),
    R("frame.mosaic-dtype", "mosaic(dtype=int32)",
      lambda f: rz.mosaic(rgb(), "mask1", dtype=np.int32),
      TypeError, "dtype: expected one of uint8, uint16, float32, float64"),
    R("frame.mosaic-dtype-unknown", "mosaic(dtype='junk')",
      lambda f: rz.mosaic(rgb(), "mask1", dtype="junk"), TypeError,
      "dtype: expected one of uint8, uint16, float32, float64, got 'junk'"),
    R("frame.mosaic-uint8-bits", "mosaic(dtype=uint8, bit_depth=11)",
      lambda f: rz.mosaic(rgb(), "mask1", dtype=np.uint8), ValueError,
      "dtype: uint8 cannot hold 11-bit data"),
    R("frame.mosaic-bit_depth", "mosaic(bit_depth=17)", lambda f: rz.mosaic(rgb(), "mask1", 17),
      ValueError, "bit_depth: expected 1..16 bits"),
    R("frame.mosaic-input_bits", "mosaic(input_bits=0)",
      lambda f: rz.mosaic(u8img(), "mask1", input_bits=0), ValueError,
      "input_bits: expected 1..8 bits for uint8 input, got 0"),
    R("frame.mosaic-input_bits-type", "mosaic(input_bits='8')",
      lambda f: rz.mosaic(u8img(), "mask1", input_bits="8"), TypeError,
      "input_bits: expected an integer number of bits"),
    R("frame.mosaic-input_bits-wide", "mosaic(uint16 image, input_bits=17)",
      lambda f: rz.mosaic(np.ones((4, 4, 3), np.uint16), "mask1", input_bits=17), ValueError,
      "input_bits: expected 1..16 bits for uint16 input, got 17"),
    R("frame.mosaic-input_bits-100", "mosaic(uint8 image, input_bits=100)",
      lambda f: rz.mosaic(u8img(), "mask1", input_bits=100), ValueError,
      "input_bits: expected 1..8 bits for uint8 input, got 100"),
    R("frame.mosaic-input_bits-float", "mosaic(float image, input_bits=8)",
      lambda f: rz.mosaic(rgb(), "mask1", input_bits=8), ValueError,
      "input_bits: applies to integer input only"),
    R("frame.RawFrame-tof-shape", "RawFrame(8x8 data, tof of a 16x16 frame)",
      lambda f: rz.RawFrame(u16(), "mask1", tof=sim_frame().tof), ValueError,
      "tof: taps of a 16x16 frame, the data is 8x8"),
    R("frame.ToFTaps-sites", "ToFTaps(sites outside the frame)",
      lambda f: taps_with_sites(1000), ValueError,
      "sites: rows span [1000, 1000], outside the 4x4 frame"),
    R("frame.ToFTaps-shape", "ToFTaps(taps of shape (3, 4))",
      lambda f: sim.ToFTaps(np.zeros((3, 4)), [1], (np.zeros(0), np.zeros(0)), 1, 11,
                            np.zeros(0), np.zeros(0, bool), np.zeros(0, bool),
                            sim.ToFSensor(), (4, 4)), ValueError,
      "taps: expected shape (F, 4, n_sites)"),
]

test_api_contract = api_tests(ROWS)


def test_mosaic_accepts_dtype_names_and_numpy_integers():
    """The checks of mosaic's dtype and input_bits refuse only what is wrong: a dtype name
    and a NumPy integer number of bits give the result of their Python spellings."""
    img = u8img(value=200)
    want = rz.mosaic(img, "mask1").data
    np.testing.assert_array_equal(rz.mosaic(img, "mask1", dtype="uint16").data, want)
    np.testing.assert_array_equal(rz.mosaic(img, "mask1", input_bits=np.int64(8)).data, want)


def test_merge_params_is_the_one_parameter_rule():
    """rgbz_fast._validate.merge_params: an object or a dict of its fields or None, with
    keyword overrides; the class checks the result; unknown names and other types are a
    TypeError naming what took them."""
    import pytest

    from rgbz_fast._validate import merge_params

    P = rz.ReconstructParams
    base = P(precision="float64")
    assert merge_params(P, base) is base                      # nothing to override: as it is
    assert merge_params(P, base, {"sigma_rel": 0}) == P(precision="float64", sigma_rel=0.0)
    assert merge_params(P, {"precision": "float64"}, {"sigma_rel": 0}) == \
        merge_params(P, None, {"precision": "float64", "sigma_rel": 0})
    assert merge_params(P) == P()
    with pytest.raises(TypeError, match=r"^run\(\) got an unexpected keyword argument 'sigma' "
                                        r"\(fields of ReconstructParams: precision, "):
        merge_params(P, base, {"sigma": 1}, caller="run()")
    with pytest.raises(TypeError, match="^opts got an unexpected keyword argument 'sigma'"):
        merge_params(P, {"sigma": 1}, name="opts")
    with pytest.raises(TypeError, match="^opts: expected a ReconstructParams, a dict of its "
                                        "fields or None, got str"):
        merge_params(P, "float64", name="opts")
    with pytest.raises(ValueError, match="^sigma_rel: "):
        merge_params(P, base, {"sigma_rel": -1})


# --------------------------------------------------------------------------- every contract file
def test_contract_rows_are_unique_and_documented_bugs_exist():
    api, cli = all_rows()
    ids = [r.id for r in api + cli]
    assert len(ids) == len(set(ids)), sorted(i for i in ids if ids.count(i) > 1)
    assert {r.bug for r in api + cli if r.bug} <= set(BUGS)
    # an id names the module of the function it calls: one contract file per module
    modules = {"patterns", "frame", "reconstruction", "isp", "metrics", "simulation", "io",
               "tof", "evaluation"}
    assert {r.id.split(".")[0] for r in api} <= modules
    assert {r.id.split(".")[0] for r in cli} == {"cli"}


def test_docs_tables_match_the_rows():
    """docs/reports/robustness.md lists exactly the rows of the contract files
    (regenerate: python tools/robustness_tables.py)."""
    text = DOC.read_text()
    api, cli = markdown_tables()
    assert table_between(text, "<!-- api-table:start -->", "<!-- api-table:end -->") == api
    assert table_between(text, "<!-- cli-table:start -->", "<!-- cli-table:end -->") == cli
    for bug, what in BUGS.items():
        assert f"**{bug} — " in text, f"{bug} is not described in docs/reports/robustness.md"
