"""The bad-input contract of rgbz_fast.isp: demosaic, the colour ISP and its stages.

Rows of docs/reports/robustness.md (``isp.*``), run by the shared runner of
``tests/_contract.py``.
"""

from __future__ import annotations

import numpy as np

import rgbz_fast as rz
from _contract import Row, api_tests, f64, files, small_frame, u16, with_value  # noqa: F401
from rgbz_fast import isp
from rgbz_fast.isp import demosaic

R = Row

ROWS = [
    R("isp.WhiteBalance-gains-huge-int", "WhiteBalance(gains=(10**400, 1, 1))",
      lambda f: isp.WhiteBalance(gains=(10**400, 1, 1)), ValueError,
      "WhiteBalance.gains: holds a number too large for float64"),
    R("isp.ColourCorrection-matrix-huge-int", "ColourCorrection(matrix with 10**400)",
      lambda f: isp.ColourCorrection(matrix=[[10**400, 0, 0], [0, 1, 0], [0, 0, 1]]),
      ValueError, "ColourCorrection.matrix: holds a number too large for float64"),
    # -- what a frame records --------------------------------------------------------------
    R("isp.run-meta-black-text", "ColourISP().run(frame of meta colour_black_level='x')",
      lambda f: isp.ColourISP().run(rz.RawFrame(u16((8, 8), 100), "mask1",
                                                meta={"colour_black_level": "x"})), ValueError,
      "frame: its meta records an unusable rendering (colour_black_level: expected a number, "
      "got 'x')"),
    R("isp.run-meta-black-white", "ColourISP().run(frame of meta colour_black_level=5000)",
      lambda f: isp.ColourISP().run(rz.RawFrame(u16((8, 8), 100), "mask1",
                                                meta={"colour_black_level": 5000})), ValueError,
      "frame: its meta records an unusable rendering (colour_black_level: expected a finite "
      "number >= 0 and < 2047, got 5000)"),
    # -- demosaic --------------------------------------------------------------------------
    R("isp.demosaic-ndim", "demosaic(3-D)", lambda f: demosaic(np.zeros((4, 4, 3))), ValueError,
      "cfa: expected a 2-D array"),
    R("isp.demosaic-near-max", "demosaic(float64 maximum)",
      lambda f: demosaic(np.full((4, 4), np.finfo(np.float64).max)), ValueError,
      "cfa: values up to 1.79769e+308 in magnitude; the demosaic's filters overflow float64"),
    R("isp.demosaic-float32-out", "demosaic(1e300, dtype=float32)",
      lambda f: demosaic(np.full((4, 4), 1e300), dtype=np.float32), ValueError,
      "cfa: values up to 1e+300 in magnitude; the demosaic's filters overflow float32 beyond "
      "1.06338e+37, pass dtype=float64"),
    R("isp.demosaic-small", "demosaic(1x5)", lambda f: demosaic(np.zeros((1, 5))), ValueError,
      "cfa: expected at least one 2x2 Bayer period"),
    R("isp.demosaic-nan", "demosaic(NaN)", lambda f: demosaic(with_value(np.nan)), ValueError,
      "cfa: holds 1 NaN or infinite value(s)"),
    R("isp.demosaic-complex", "demosaic(complex)", lambda f: demosaic(np.zeros((4, 4), complex)),
      TypeError, "cfa: expected a real numeric array"),
    R("isp.demosaic-phase", "demosaic(phase='ZZZZ')", lambda f: demosaic(f64(), "ZZZZ"),
      ValueError, "phase: expected one of GRBG, RGGB, BGGR, GBRG"),
    R("isp.demosaic-phase-rgbz", "demosaic(phase=mask1())", lambda f: demosaic(f64(), rz.mask1()),
      ValueError, "phase: expected a plain 2x2 Bayer pattern"),
    R("isp.demosaic-method", "demosaic(method='ahd')", lambda f: demosaic(f64(), method="ahd"),
      ValueError, "method: expected one of 'malvar2004', 'menon2007', 'bilinear'"),
    R("isp.demosaic-mode", "demosaic(mode='wrap')", lambda f: demosaic(f64(), mode="wrap"),
      ValueError, "mode: expected one of 'reflect', 'period'"),
    R("isp.demosaic-dtype", "demosaic(dtype=int32)", lambda f: demosaic(f64(), dtype=np.int32),
      TypeError, "dtype: expected float32 or float64"),
    R("isp.demosaic-dtype-unknown", "demosaic(dtype='junk')",
      lambda f: demosaic(f64(), dtype="junk"),
      TypeError, "dtype: expected float32 or float64"),
    R("isp.demosaic-workers", "demosaic(workers=0)", lambda f: demosaic(f64(), workers=0),
      ValueError, "workers: expected None, -1 or a positive number of threads"),
    # -- the colour ISP and its stages -----------------------------------------------------
    R("isp.ColourISP-output_bits", "ColourISP(output_bits=12)",
      lambda f: isp.ColourISP(output_bits=12), ValueError,
      "ColourISP.output_bits: expected 8 or 16"),
    R("isp.ColourISP-precision", "ColourISP(precision='f16')",
      lambda f: isp.ColourISP(precision="f16"), ValueError,
      "ColourISP.precision: expected one of 'float32', 'float64'"),
    R("isp.ColourISP-stage-type", "ColourISP(defects=5)", lambda f: isp.ColourISP(defects=5),
      TypeError, "ColourISP.defects: expected DefectCorrection"),
    R("isp.run-no-pattern", "ColourISP().run(array)",
      lambda f: isp.ColourISP().run(u16()), TypeError,
      "pattern: required when frame is a plain array"),
    R("isp.run-no-reference", "ColourISP().run(frame, reference=True), no reference",
      lambda f: isp.ColourISP().run(small_frame(), reference=True), ValueError,
      "reference: the frame holds no reference Bayer CFA"),
    R("isp.run-gains", "ColourISP().run(gains=(1, 2))",
      lambda f: isp.ColourISP().run(small_frame(), gains=(1, 2)), ValueError,
      "gains: expected three positive finite gains"),
    R("isp.run-black", "ColourISP().run(black_level=5000)",
      lambda f: isp.ColourISP().run(small_frame(), black_level=5000), ValueError,
      "black_level: 5000 must be below the white level 2047"),
    R("isp.run-defects-map", "ColourISP().run(defects=3x3 map)",
      lambda f: isp.ColourISP().run(small_frame(), defects=np.zeros((3, 3), bool)), ValueError,
      "known: expected a bool map of shape (8, 8)"),
    R("isp.run-method", "ColourISP(Reconstruction('nope')).run(frame)",
      lambda f: isp.ColourISP(reconstruction=isp.Reconstruction(method="nope")).run(small_frame()),
      ValueError, "Reconstruction.method: expected one of"),
    R("isp.run_pair-type", "ColourISP().run_pair(array)",
      lambda f: isp.ColourISP().run_pair(u16()), TypeError,
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
      lambda f: isp.correct_defects(u16(), "mask1", known=np.zeros((8, 8), int)), ValueError,
      "known: expected a bool map of shape (8, 8)"),
    R("isp.detect_defects-white", "detect_defects(white_level=0)",
      lambda f: isp.detect_defects(u16(), "mask1", white_level=0), ValueError,
      "white_level: expected a finite number > 0"),
    R("isp.white_balance-overflow", "white_balance(gains=(1e300, 1, 1), clip=False)",
      lambda f: isp.white_balance(f64(value=1e10), "RGGB", gains=(1e300, 1, 1), clip=False),
      ValueError, "cfa: the balanced values (v - black_level) / (white_level - black_level) * "
                  "gains overflow float32"),
    R("isp.white_balance-z", "white_balance(cfa, 'mask1')",
      lambda f: isp.white_balance(u16(), "mask1"), ValueError,
      "phase: the white balance needs a complete Bayer CFA"),
    R("isp.white_balance-dtype", "white_balance(dtype=int32)",
      lambda f: isp.white_balance(u16(), "bayer", dtype=np.int32), TypeError,
      "dtype: expected float32 or float64, got int32"),
    R("isp.grey_world_gains-z", "grey_world_gains(cfa, 'mask1')",
      lambda f: isp.grey_world_gains(u16(), "mask1"), ValueError,
      "phase: the white balance needs a complete Bayer CFA"),
    R("isp.fill_missing-params", "fill_missing(params=5)",
      lambda f: isp.fill_missing(u16(), "mask1", params=5), TypeError,
      "params: expected Reconstruction"),
    R("isp.correct_colour-ndim", "correct_colour(2-D)",
      lambda f: isp.correct_colour(f64()), ValueError, "rgb: expected a 3-D array"),
    R("isp.srgb_oetf-nan", "srgb_oetf(NaN)", lambda f: isp.srgb_oetf(np.array([np.nan])),
      ValueError, "linear: holds 1 NaN or infinite value(s)"),
    R("isp.srgb_encode-int", "srgb_encode(int64 200)",
      lambda f: isp.srgb_encode(np.full((2, 2, 3), 200)), TypeError,
      "linear: dtype int64 is not supported; expected one of float16, float32, float64"),
    R("isp.srgb_oetf-uint8", "srgb_oetf(uint8)",
      lambda f: isp.srgb_oetf(np.full((2, 2, 3), 200, np.uint8)), TypeError,
      "linear: dtype uint8 is not supported"),
    R("isp.correct_colour-matrix-huge", "correct_colour(float32, matrix with 1e39)",
      lambda f: isp.correct_colour(np.zeros((2, 2, 3), np.float32),
                                   matrix=[[1e39, 0, 0], [0, 1, 0], [0, 0, 1]]), ValueError,
      "ColourCorrection.matrix: entries up to 1e+39 in magnitude, beyond 1e+30"),
    R("isp.correct_colour-int", "correct_colour(int64 200)",
      lambda f: isp.correct_colour(np.full((2, 2, 3), 200)), TypeError,
      "rgb: dtype int64 is not supported"),
    R("isp.srgb_encode-bits", "srgb_encode(bits=12)",
      lambda f: isp.srgb_encode(np.zeros((2, 2, 3)), bits=12), ValueError,
      "bits: expected 8 or 16"),
]

test_api_contract = api_tests(ROWS)


def test_white_balance_accepts_dtype_names():
    """The dtype check of white_balance refuses only integer dtypes: a dtype name is read as
    the dtype, and the normalised output lies in (0, 1]."""
    for dt in (np.float32, "float64"):
        wb, _ = isp.white_balance(u16(value=1000), "bayer", dtype=dt)
        assert wb.dtype == np.dtype(dt) and 0 < wb.min() <= wb.max() <= 1
