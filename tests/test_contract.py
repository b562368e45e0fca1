"""The bad-input contract of the package root: patterns, raw frames, ToF taps, mosaic,
the build report.

Rows of docs/reports/robustness.md (``config.*``, ``patterns.*``, ``frame.*``), run by
the shared runner of ``tests/_contract.py``, and the checks that keep the report's tables
and the rows of every contract file in step.
"""

from __future__ import annotations

import numpy as np

import rgbz_fast as rz
from _contract import (BUGS, DOC, Row, all_rows, api_tests, f64, files,  # noqa: F401
                       markdown_tables, rgb, sim_frame, table_between, taps_with_sites, u16,
                       u8img, with_value)
from rgbz_fast import simulation as sim

R = Row


def _tof():
    """The ToF taps of a simulated 16x16 Mask1 frame."""
    return sim_frame().tof


def _retaps(**changes):
    """Those taps with some fields replaced (and checked again)."""
    import dataclasses

    return dataclasses.replace(_tof(), **changes)

ROWS = [
    # -- the build report (rgbz_fast._config) ----------------------------------------------
    R("config.show_config-file", "show_config(1)", lambda f: rz.show_config(1), TypeError,
      "file: expected a text stream with a write() method (or None for stdout), got int"),
    R("config.memory_pool-negative", "memory_pool(-1)", lambda f: rz.memory_pool(-1),
      ValueError, "limit: expected 0 <= limit < 2**63 bytes, got -1"),
    R("config.memory_pool-float", "memory_pool(1.5e9)", lambda f: rz.memory_pool(1.5e9),
      TypeError, "limit: expected an int number of bytes (or None), got float"),
    R("config.memory_pool-bool", "memory_pool(True)", lambda f: rz.memory_pool(True),
      TypeError, "limit: expected an int number of bytes (or None), got bool"),
    # -- patterns (rgbz_fast._patterns) ----------------------------------------------------
    R("patterns.none", "get_pattern(None)", lambda f: rz.get_pattern(None), TypeError,
      "pattern: expected a Pattern, a preset name or a tile string"),
    R("patterns.unknown", "get_pattern('mask7')", lambda f: rz.get_pattern("mask7"),
      ValueError, "pattern: 'mask7' is neither a preset"),
    R("patterns.preset-empty-phase", "get_pattern('mask1_')",
      lambda f: rz.get_pattern("mask1_"), ValueError, "pattern: 'mask1_' is neither a preset"),
    R("patterns.shape-float", "mask1().z_mask((4.9, 2.5))",
      lambda f: rz.mask1().z_mask((4.9, 2.5)), TypeError,
      "shape: expected a (rows, cols) tuple of integers, got (4.9, 2.5)"),
    R("patterns.shape-digits", "mask1().z_mask(('4', '4'))",
      lambda f: rz.mask1().z_mask(("4", "4")), TypeError,
      "shape: expected a (rows, cols) tuple of integers"),
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
    R("frame.RawFrame-meta-list", "RawFrame(meta=[1, 2])",
      lambda f: rz.RawFrame(u16(), "mask1", meta=[1, 2]), TypeError,
      "meta: expected a dict, got list"),
    R("frame.RawFrame-tof-number", "RawFrame(tof=5)",
      lambda f: rz.RawFrame(u16(), "mask1", tof=5), TypeError,
      "tof: expected ToFTaps or None, got int"),
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
    R("frame.mosaic-int64-list", "mosaic(a list of ints)",
      lambda f: rz.mosaic([[[200, 200, 200]] * 4] * 4, "mask1"), TypeError,
      "rgb: an int64 image (a list of Python ints becomes int64) says nothing about the range "
      "of its values; pass input_bits="),
    R("frame.mosaic-uint32", "mosaic(uint32 image)",
      lambda f: rz.mosaic(np.full((4, 4, 3), 200, np.uint32), "mask1"), TypeError,
      "rgb: a uint32 image says nothing about the range of its values"),
    R("frame.mosaic-input_bits-values", "mosaic(int64 300, input_bits=8)",
      lambda f: rz.mosaic(np.full((4, 4, 3), 300), "mask1", input_bits=8), ValueError,
      "rgb: integer values span [300, 300], beyond the 8-bit input range [0, 255]"),
    R("frame.mosaic-input_bits-float", "mosaic(float image, input_bits=8)",
      lambda f: rz.mosaic(rgb(), "mask1", input_bits=8), ValueError,
      "input_bits: applies to integer input only"),
    R("frame.RawFrame-tof-shape", "RawFrame(8x8 data, tof of a 16x16 frame)",
      lambda f: rz.RawFrame(u16(), "mask1", tof=sim_frame().tof), ValueError,
      "tof: taps of a 16x16 frame, the data is 8x8"),
    R("frame.ToFTaps-sites", "ToFTaps(sites outside the frame)",
      lambda f: taps_with_sites(1000), ValueError,
      "sites: rows span [1000, 1000], outside the 4x4 frame"),
    R("frame.ToFTaps-taps-complex", "ToFTaps(complex taps)",
      lambda f: _retaps(taps=_tof().taps * 1j), TypeError,
      "taps: expected real numbers, got dtype complex128"),
    R("frame.ToFTaps-taps-text", "ToFTaps(taps of text)",
      lambda f: _retaps(taps=_tof().taps.astype(str)), TypeError,
      "taps: expected real numbers, got dtype <U"),
    R("frame.ToFTaps-taps-beyond-bits", "ToFTaps(11-bit taps of 3000)",
      lambda f: _retaps(taps=np.full(_tof().taps.shape, 3000.0)), ValueError,
      "taps: values span [3000, 3000], beyond the 11-bit range [0, 2047]"),
    R("frame.ToFTaps-taps-negative", "ToFTaps(taps of -1)",
      lambda f: _retaps(taps=np.full(_tof().taps.shape, -1.0)), ValueError,
      "taps: values span [-1, -1], beyond the 11-bit range"),
    R("frame.ToFTaps-sites-float", "ToFTaps(sites of floats)",
      lambda f: _retaps(sites=(_tof().sites[0] + 0.5, _tof().sites[1])), TypeError,
      "sites: expected integer pixel indices, got rows of dtype float64"),
    R("frame.ToFTaps-sites-twice", "ToFTaps(a site twice)",
      lambda f: _retaps(sites=(np.r_[_tof().sites[0][:-1], 0], np.r_[_tof().sites[1][:-1], 0])),
      ValueError, "sites: the site (0, 0) is given twice"),
    R("frame.ToFTaps-bit_depth-0", "ToFTaps(bit_depth=0)", lambda f: _retaps(bit_depth=0),
      ValueError, "bit_depth: expected 1..16 bits, got 0"),
    R("frame.ToFTaps-bit_depth-99", "ToFTaps(bit_depth=99)", lambda f: _retaps(bit_depth=99),
      ValueError, "bit_depth: expected 1..16 bits, got 99"),
    R("frame.ToFTaps-frequencies-twice", "ToFTaps(frequencies 80, 80, 120 MHz)",
      lambda f: _retaps(frequencies=[80e6, 80e6, 120e6]), ValueError,
      "frequencies: a frequency is given twice"),
    R("frame.ToFTaps-valid-int", "ToFTaps(valid of ints)",
      lambda f: _retaps(valid=_tof().valid.astype(int)), TypeError,
      "valid: expected a bool array, got dtype int64"),
    R("frame.ToFTaps-depth_true-nan", "ToFTaps(depth_true of NaN)",
      lambda f: _retaps(depth_true=np.full(_tof().depth_true.shape, np.nan)), ValueError,
      "depth_true: holds"),
    R("frame.ToFTaps-depth_true-negative", "ToFTaps(depth_true of -1 m)",
      lambda f: _retaps(depth_true=np.full(_tof().depth_true.shape, -1.0)), ValueError,
      "depth_true: holds negative depths (min -1 m); expected metres >= 0"),
    R("frame.ToFTaps-sensor-frequencies", "ToFTaps(3 frequencies of taps, a 1-frequency sensor)",
      lambda f: _retaps(sensor=sim.ToFSensor(frequencies=(20e6,))), ValueError,
      "sensor: 1 frequencies [20000000.0], the taps 3"),
    R("frame.ToFTaps-sensor-frequency-values", "ToFTaps(taps at 80, 100, 120 MHz, a sensor "
      "at 10, 20, 30 MHz)",
      lambda f: _retaps(sensor=sim.ToFSensor(frequencies=(10e6, 20e6, 30e6))), ValueError,
      "sensor: 3 frequencies [10000000.0, 20000000.0, 30000000.0], the taps 3"),
    R("frame.ToFTaps-sensor-bit-depth", "ToFTaps(11-bit taps, a 12-bit sensor)",
      lambda f: _retaps(sensor=sim.ToFSensor(bit_depth=12)), ValueError,
      "sensor: a 12-bit ADC, the taps 11-bit codes; give the sensor the taps' bit depth"),
    R("frame.ToFTaps-sensor", "ToFTaps(sensor=None)", lambda f: _retaps(sensor=None),
      TypeError, "sensor: expected a ToFSensor, got NoneType"),
    R("frame.RawFrame-tof-colour-site", "RawFrame(tof measured at a colour pixel)",
      lambda f: rz.RawFrame(sim_frame().data, "mask1",
                            tof=_retaps(sites=(_tof().sites[0], _tof().sites[1] + 1))),
      ValueError, "tof: the measurement at (0, 1) (a 1x1 block) covers a colour pixel of "
                  "pattern 'mask1'"),
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
    modules = {"config", "patterns", "frame", "reconstruction", "isp", "metrics", "simulation",
               "io", "tof", "evaluation", "hardware"}
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


def test_integer_images_wider_than_16_bits_need_their_bits():
    """The one dtype rule (``rgbz_fast._validate.integer_bits``): an int32/int64/uint32/uint64
    image -- any list of Python ints -- is never scaled by the width of its type (200 became
    0 in a mosaic and an auto-exposed scene saturated). Every entry that takes the range of
    an image from the image refuses it; stating the bits gives the result of a uint8 image of
    the same values, and an entry given its range (metrics, data_range) reads it as it is."""
    import pytest

    from rgbz_fast import evaluation as ev
    from rgbz_fast import isp, metrics

    u8 = np.random.default_rng(0).integers(0, 256, (16, 16, 3)).astype(np.uint8)
    for dtype in (np.int32, np.int64, np.uint32, np.uint64):
        wide = u8.astype(dtype)
        for call in (lambda a: rz.mosaic(a, "mask1"), lambda a: sim.Scene(a),
                     lambda a: sim.Scene.from_rgb(a, encoding="srgb"),
                     lambda a: sim.simulate(a, "mask1", noise=False),
                     lambda a: ev.image_frames(a, "mask1", ev.EvalConfig()),
                     lambda a: rz.reconstruct(a[..., 0], "bi", pattern="mask1"),
                     lambda a: isp.srgb_encode(a), lambda a: isp.correct_colour(a)):
            with pytest.raises(TypeError, match=f"{np.dtype(dtype)}"):
                call(wide)
        np.testing.assert_array_equal(rz.mosaic(wide, "mask1", input_bits=8).data,
                                      rz.mosaic(u8, "mask1").data)
        np.testing.assert_array_equal(sim.Scene(wide, input_bits=8).image, sim.Scene(u8).image)
        np.testing.assert_array_equal(
            sim.Scene.from_rgb(wide, encoding="linear", input_bits=8).image,
            sim.Scene.from_rgb(u8, encoding="linear").image)
        assert metrics.cpsnr(wide, wide[::-1]) == metrics.cpsnr(u8, u8[::-1])
    # a list of ints is int64; the stated bits apply, values beyond them are refused
    assert rz.mosaic(u8.tolist(), "mask1", input_bits=8).data.max() > 0
    scene = sim.Scene(np.full((4, 4, 3), 4095), input_bits=12)
    assert scene.image.max() == 1.0 and scene.input_bits is None


def _public_flags():
    """(qualified name, parameter) of every parameter of the public API whose default is a
    bool: functions, classes and their public methods, found from the signatures."""
    import inspect

    mods = [rz, rz.simulation, rz.reconstruction, rz.isp, rz.tof, rz.metrics, rz.evaluation,
            rz.io]
    found, seen = set(), set()
    for m in mods:
        for n in m.__all__:
            obj = getattr(m, n)
            if id(obj) in seen or not callable(obj):
                continue
            seen.add(id(obj))
            targets = [(n, obj)]
            if inspect.isclass(obj):
                targets += [(f"{n}.{a}", getattr(obj, a)) for a, f in vars(obj).items()
                            if not a.startswith("_") and inspect.isfunction(f)]
            for qual, fn in targets:
                try:
                    params = inspect.signature(fn).parameters.values()
                except (TypeError, ValueError):
                    continue
                found |= {(qual, p.name) for p in params if isinstance(p.default, bool)}
    return found


def test_every_flag_of_the_public_api_refuses_what_is_not_a_bool(files):
    """One flag check (``_validate.check_flag``) for every boolean parameter: "no", 0 and
    None are a TypeError naming the parameter (``simulate(noise="no")`` ran the noise model,
    ``ssim(gaussian_weights="no")`` used the Gaussian window). The list of flags comes from
    the public signatures, so a new flag without its check fails here."""
    import pytest

    from rgbz_fast import evaluation as ev
    from rgbz_fast import io as rio
    from rgbz_fast import isp, metrics
    from rgbz_fast import reconstruction as rec

    scene = sim.Scene(rgb(), depth=np.full((16, 16), 1.5))
    frame = sim_frame()
    res = ev.Results([{"image": "a", "pattern": "mask1", "method": "bi", "metric": "cfa_psnr",
                       "value": 1.0}], ev.EvalConfig(methods=("bi",), metrics=("cfa_psnr",)))
    ds = dict(metrics=("cfa_psnr",), methods=("bi",), patterns=("mask1",), processes=1)
    raw = dict(shape=(4, 4), phase="RGGB", black_level=0, bit_depth_in=12)
    calls = {
        ("ColourSensor", "shot_noise"): lambda v: sim.ColourSensor(shot_noise=v),
        ("ColourSensor", "quantise"): lambda v: sim.ColourSensor(quantise=v),
        ("ToFSensor", "shot_noise"): lambda v: sim.ToFSensor(shot_noise=v),
        ("ToFSensor", "quantise"): lambda v: sim.ToFSensor(quantise=v),
        ("simulate", "noise"): lambda v: sim.simulate(scene, "mask1", noise=v),
        ("simulate_colour", "noise"): lambda v: sim.simulate_colour(scene, noise=v),
        ("simulate_tof", "noise"): lambda v: sim.simulate_tof(scene, "mask1", noise=v),
        ("ColourISP.run", "reference"): lambda v: isp.ColourISP().run(frame, reference=v),
        ("ColourISP.run", "return_stages"):
            lambda v: isp.ColourISP().run(frame, return_stages=v),
        ("ColourISP.render", "return_stages"):
            lambda v: isp.ColourISP().render(frame.reference, return_stages=v),
        ("ColourISP.run_pair", "return_stages"):
            lambda v: isp.ColourISP().run_pair(frame, return_stages=v),
        ("load_image", "grey"): lambda v: sim.load_image(files / "rgb.png", grey=v),
        ("load_rgbd", "grey"): lambda v: sim.load_rgbd(files / "empty", grey=v),
        ("DefectCorrection", "enabled"): lambda v: isp.DefectCorrection(enabled=v),
        ("WhiteBalance", "clip"): lambda v: isp.WhiteBalance(clip=v),
        ("correct_defects", "return_mask"):
            lambda v: isp.correct_defects(frame.data, "mask1", return_mask=v),
        ("ssim", "gaussian_weights"):
            lambda v: metrics.ssim(f64((16, 16)), f64((16, 16)), gaussian_weights=v),
        ("EvalConfig", "noise"): lambda v: ev.EvalConfig(noise=v),
        ("EvalConfig", "linearise"): lambda v: ev.EvalConfig(linearise=v),
        ("EvalConfig.key", "raw"): lambda v: ev.EvalConfig().key("mask1", "sg", raw=v),
        ("evaluate", "progress"): lambda v: ev.evaluate(files / "ds", progress=v, **ds),
        ("evaluate", "skip_bad"):
            lambda v: ev.evaluate(files / "ds", progress=False, skip_bad=v, **ds),
        ("write_reports", "plots"): lambda v: ev.write_reports(res, files / "rep", plots=v),
        ("train_filters", "noise"): lambda v: ev.train_filters(files / "ds", "mask1", noise=v),
        ("train_filters", "linearise"):
            lambda v: ev.train_filters(files / "ds", "mask1", linearise=v),
        ("train_filters", "progress"):
            lambda v: ev.train_filters(files / "ds", "mask1", progress=v),
        ("train_filters", "z_guided"):
            lambda v: ev.train_filters(files / "ds", "mask1", z_guided=v),
        ("train", "z_guided"): lambda v: rec.train([frame], z_guided=v),
        ("train_z_guided", "guide"): lambda v: rec.train_z_guided([frame], guide=v),
        ("read_raw", "crop_even"):
            lambda v: rio.read_raw(files / "bayer.raw", crop_even=v, **raw),
        ("list_raw_files", "recursive"): lambda v: rio.list_raw_files(files.d, recursive=v),
        ("ImageSource", "raw"): lambda v: rio.ImageSource("a", "a.png", raw=v),
        ("ImageSource", "grey"): lambda v: rio.ImageSource("a", "a.png", grey=v),
        ("folder_dataset", "grey"): lambda v: rio.folder_dataset(files / "ds", grey=v),
        ("rgb_image", "grey"): lambda v: rio.rgb_image(u8img(), "x.png", grey=v),
    }
    assert set(calls) == _public_flags()
    for (qual, param), call in calls.items():
        for bad in ("no", 0, None, np.array([True])):
            with pytest.raises(TypeError, match=rf"^(\w+\.)?{param}: expected True or False"):
                call(bad)


def test_sequences_of_names_refuse_repeated_entries():
    """A configuration naming an entry twice (two spellings of one pattern included) would
    run it twice and count it twice in every mean: refused, naming the field."""
    import re

    import pytest

    from rgbz_fast import evaluation as ev

    for kw, twice in ((dict(patterns=("mask1", "mask1")), "'mask1' is given twice"),
                      (dict(patterns="mask1,mask1_grbg"), "'mask1_grbg' is given twice "
                                                          "(as 'mask1')"),
                      (dict(methods=("sg", "bi", "sg")), "'sg' is given twice"),
                      (dict(metrics="cpsnr,cpsnr"), "'cpsnr' is given twice")):
        field = next(iter(kw))
        with pytest.raises(ValueError, match="^" + re.escape(f"{field}: {twice}; name each")):
            ev.EvalConfig(**kw)
    with pytest.raises(ValueError, match=r"^sections: 'noise' is given twice"):
        ev.evaluate_depth(sections=("noise", "noise"))
    with pytest.raises(TypeError, match=r"^methods: expected names \(strings\), got 5"):
        ev.EvalConfig(methods=("sg", 5))


def _sweep_calls(d):
    """(name, function, args, kwargs) of valid calls of the public API on small inputs,
    each of whose arguments the sweep below replaces by hostile values in turn."""
    from rgbz_fast import evaluation as ev
    from rgbz_fast import io as rio
    from rgbz_fast import isp, metrics
    from rgbz_fast import reconstruction as rec

    rng = np.random.default_rng(0)
    img = rng.random((32, 32, 3))
    u8 = (img * 255).astype(np.uint8)
    big = np.zeros((176, 176, 3), np.uint8)
    scene = sim.Scene(img, depth=np.full((32, 32), 1.5))
    frame = sim.simulate(scene, "mask1", noise=False)
    cfa = frame.reference
    bayer_frame = rz.RawFrame(cfa, rz.bayer())
    cfg = ev.EvalConfig(methods=("bilinear", "sg"), metrics=("cfa_psnr",), patterns=("mask1",))
    res = ev.Results([{"image": "a", "pattern": "mask1", "method": m, "metric": "cfa_psnr",
                       "value": 1.0 + i} for i, m in enumerate(cfg.methods)], cfg)
    src = rio.ImageSource("a", str(d / "ds" / "a.png"))
    one = dict(metrics=("cfa_psnr",), methods=("bi",), patterns=("mask1",))
    raw = dict(shape=(4, 4), phase="RGGB", black_level=0, bit_depth_in=12)
    return [
        ("mosaic", rz.mosaic, (img, "mask1"), {}),
        ("RawFrame", rz.RawFrame, (frame.data, "mask1"), {}),
        ("Pattern", rz.Pattern, ("ZR/BG",), {}),
        ("reconstruct", rz.reconstruct, (frame.data, "sg"), {"pattern": "mask1"}),
        ("build_plans", rec.build_plans, (rz.mask1(), "sg"), {}),
        ("Scene", sim.Scene, (img,), {}),
        ("Scene.from_rgb", sim.Scene.from_rgb, (u8,), {}),
        ("load_image", sim.load_image, (d / "rgb.png",), {}),
        ("simulate", sim.simulate, (scene, "mask1"), {"noise": False}),
        ("simulate_tof", sim.simulate_tof, (scene, "mask1"), {"noise": False}),
        ("apply_optics", sim.apply_optics, (img, sim.Optics()), {"pixel_pitch_um": 2.8}),
        ("Optics.mtf", sim.Optics().mtf, (np.linspace(0, 1, 5), 550),
         {"pixel_pitch_um": 2.8}),
        ("disparity_to_depth", sim.disparity_to_depth, (f64((4, 4), 10.0), 3740, 0.16), {}),
        ("ColourISP.run", isp.ColourISP().run, (frame,), {}),
        ("ColourISP.render", isp.ColourISP().render, (cfa,), {}),
        ("demosaic", isp.demosaic, (cfa,), {}),
        ("white_balance", isp.white_balance, (cfa,), {}),
        ("correct_colour", isp.correct_colour, (img,), {}),
        ("srgb_encode", isp.srgb_encode, (img,), {}),
        ("correct_defects", isp.correct_defects, (frame.data, "mask1"), {}),
        ("cfa_psnr", metrics.cfa_psnr, (cfa, cfa[::-1], frame.z_mask), {"bit_depth": 11}),
        ("cpsnr_pooled", metrics.cpsnr_pooled, ([u8], [u8[::-1]]), {}),
        ("ssim", metrics.ssim, (u8, u8[::-1]), {}),
        ("zipper", metrics.zipper, (u8, u8[::-1]), {}),
        ("all_metrics", metrics.all_metrics, (big, big), {}),
        ("EvalConfig", ev.EvalConfig, (), {}),
        ("evaluate", ev.evaluate, (d / "ds",), {**one, "progress": False, "processes": 1}),
        ("evaluate_image", ev.evaluate_image, (src, ev.EvalConfig(**one)), {}),
        ("image_frames", ev.image_frames, (u8, "mask1", cfg), {}),
        ("Results", ev.Results, (res.rows, res.config), {}),
        ("Results.paired", res.paired, ("mask1", "sg", "cfa_psnr"), {}),
        ("Results.summary_markdown", res.summary_markdown, (), {}),
        ("bar_chart", ev.bar_chart, (res, "cfa_psnr"), {}),
        ("write_reports", ev.write_reports, (res, d / "sweep_reports"), {"plots": False}),
        ("depth_report", ev.depth_report, ({"noise": []},), {}),
        ("load_frame", rio.load_frame, (d / "ok.npz",), {}),
        ("read_npz", rio.read_npz, (d / "ok.npz",), {}),
        ("read_raw", rio.read_raw, (d / "bayer.raw",), raw),
        ("list_raw_files", rio.list_raw_files, (d,), {}),
        ("to_rgbz", rio.to_rgbz, (bayer_frame, "mask1"), {}),
        ("clipped_mask", rio.clipped_mask, (bayer_frame,), {"clip_level": 2000}),
        ("folder_dataset", rio.folder_dataset, (d / "ds",), {}),
        ("read_image", rio.read_image, (d / "rgb.png",), {}),
        ("rgb_image", rio.rgb_image, (u8, "x"), {}),
        ("check_size", rio.check_size, ((4, 4), 2, "x"), {}),
        ("save_frame", rio.save_frame, (d / "sweep.npz", frame), {}),
    ]


def test_every_argument_of_the_public_api_refuses_hostile_values_by_name(files, tmp_path,
                                                                         monkeypatch):
    """Each argument of a sweep of the public API (the calls of :func:`_sweep_calls`)
    replaced in turn by None, text, a negative, a huge or NaN number, a ragged list, an
    object, a 0-d array or bytes: the call either works (finite output from finite input)
    or raises ValueError/TypeError (FileNotFoundError for a missing file) whose message
    starts with the name of what is wrong -- never a NumPy, os or matplotlib message, a
    KeyError, an IndexError, an OverflowError or a MemoryError (each of those was found
    here and fixed where the argument comes in)."""
    import inspect
    import math
    import re
    import warnings

    bad_values = [None, "x", -1, 2**70, 1e308, math.nan, [[1, 2], [3]], object(),
                  np.array(5), b"x", {"a": 1}]
    named = re.compile(r"^[\w.'\[\]()]+(: | got an unexpected keyword argument )"
                       r"|^patterns, methods and metrics must")
    monkeypatch.chdir(tmp_path)                    # a path "x" that works is written here
    for name, fn, args, kwargs in _sweep_calls(files.d):
        sig = inspect.signature(fn)
        bound = sig.bind_partial(*args, **kwargs).arguments
        for p in sig.parameters.values():
            if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
                continue
            for bad in bad_values:
                call = {**bound, p.name: bad}
                for q in sig.parameters.values():
                    if q.kind == q.VAR_KEYWORD and q.name in call:
                        call.update(call.pop(q.name))
                where = f"{name}({p.name}={bad!r:.30})"
                try:
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        out = fn(**call)
                except (ValueError, TypeError, FileNotFoundError) as exc:
                    assert named.match(str(exc)), f"{where}: {type(exc).__name__}: {exc}"
                    continue
                except Exception as exc:                  # noqa: BLE001 - what the test finds
                    raise AssertionError(f"{where} leaked {type(exc).__name__}: {exc}")
                for o in out if isinstance(out, tuple) else (out,):
                    if isinstance(o, np.ndarray) and o.dtype.kind == "f" and bad is not math.nan:
                        assert np.all(np.isfinite(o)), f"{where}: a non-finite result"
