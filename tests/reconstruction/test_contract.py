"""The bad-input contract of rgbz_fast.reconstruction, and what it accepts on purpose.

Rows of docs/reports/robustness.md (``reconstruction.*``), run by the shared runner of
``tests/_contract.py``; then the inputs the report lists as accepted, read-only and
memory-mapped inputs, and a 50-megapixel frame within its memory budget.
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

import rgbz_fast as rz
from _contract import Row, api_tests, files, small_frame, u16, with_value  # noqa: F401
from rgbz_fast import tof
from rgbz_fast.isp import demosaic

R = Row

ROWS = [
    R("reconstruction.reconstruct-fixed-sigma_floor-huge",
      "reconstruct(frame, 'sg', precision='fixed', sigma_floor=1e20)",
      lambda f: rz.reconstruct(u16(), "sg", pattern="mask1", precision="fixed",
                               sigma_floor=1e20), ValueError,
      "sigma_floor: 1e+20 DN is beyond the 11-bit codes the fixed-point model computes in"),
    R("reconstruction.reconstruct-sigma_rel-huge-int", "reconstruct(sigma_rel=10**400)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sigma_rel=10**400), ValueError,
      "sigma_rel: expected a finite number >= 0 and <= 10, got an integer of 401 digits"),
    R("reconstruction.train-ridge-huge", "train(frames, ridge=1e308)",
      lambda f: rz.reconstruction.train([small_frame()], ridge=1e308), ValueError,
      "ridge: expected a finite number >= 0 and <= 1e+06, got 1e+308"),
    R("reconstruction.train-prior-huge", "train(frames, prior=1e308)",
      lambda f: rz.reconstruction.train([small_frame()], prior=1e308), ValueError,
      "prior: expected a finite number >= 0 and <= 1e+06, got 1e+308"),
    # -- reconstruct -----------------------------------------------------------------------
    R("reconstruction.reconstruct-ndim-3", "reconstruct(3-D)",
      lambda f: rz.reconstruct(u16((4, 4, 3)), pattern="mask1"), ValueError,
      "frame: expected a 2-D array, got shape (4, 4, 3)"),
    R("reconstruction.reconstruct-ndim-1", "reconstruct(1-D)",
      lambda f: rz.reconstruct(u16((16,)), pattern="mask1"), ValueError,
      "frame: expected a 2-D array"),
    R("reconstruction.reconstruct-ndim-0", "reconstruct(scalar)",
      lambda f: rz.reconstruct(np.uint16(3), pattern="mask1"), ValueError,
      "frame: expected a 2-D array, got shape ()"),
    R("reconstruction.reconstruct-empty", "reconstruct(0x4)",
      lambda f: rz.reconstruct(u16((0, 4)), pattern="mask1"), ValueError,
      "frame: the array is empty"),
    R("reconstruction.reconstruct-small", "reconstruct(3x3, mask2)",
      lambda f: rz.reconstruct(u16((3, 3)), pattern="mask2"), ValueError,
      "frame: frame 3x3 is smaller than one period (4x4)"),
    R("reconstruction.reconstruct-dtype-int32", "reconstruct(int32)",
      lambda f: rz.reconstruct(np.zeros((4, 4), np.int32), pattern="mask1"), TypeError,
      "frame: dtype int32 is not supported"),
    R("reconstruction.reconstruct-dtype-bool", "reconstruct(bool)",
      lambda f: rz.reconstruct(np.zeros((4, 4), bool), pattern="mask1"), TypeError,
      "frame: dtype bool is not supported"),
    R("reconstruction.reconstruct-dtype-float16", "reconstruct(float16)",
      lambda f: rz.reconstruct(np.zeros((4, 4), np.float16), pattern="mask1"), TypeError,
      "frame: dtype float16 is not supported"),
    R("reconstruction.reconstruct-dtype-complex", "reconstruct(complex)",
      lambda f: rz.reconstruct(np.zeros((4, 4), complex), pattern="mask1"), TypeError,
      "frame: expected a real numeric array"),
    R("reconstruction.reconstruct-dtype-object", "reconstruct(object)",
      lambda f: rz.reconstruct(np.zeros((4, 4), object), pattern="mask1"), TypeError,
      "frame: expected a real numeric array"),
    R("reconstruction.reconstruct-nan", "reconstruct(NaN)",
      lambda f: rz.reconstruct(with_value(np.nan), pattern="mask1"), ValueError,
      "frame: holds 1 NaN or infinite value(s)"),
    R("reconstruction.reconstruct-nan-at-z", "reconstruct(NaN at a Z site)",
      lambda f: rz.reconstruct(with_value(np.nan, at=(0, 0)), pattern="mask1"), ValueError,
      "frame: holds 1 NaN or infinite value(s)"),
    R("reconstruction.reconstruct-inf", "reconstruct(inf)",
      lambda f: rz.reconstruct(with_value(np.inf), pattern="mask1"), ValueError,
      "frame: holds 1 NaN or infinite value(s)"),
    R("reconstruction.reconstruct-negative", "reconstruct(-1.0)",
      lambda f: rz.reconstruct(with_value(-1.0), pattern="mask1"), ValueError,
      "frame: values span [-1.0, 0.0], beyond the 11-bit range"),
    R("reconstruction.reconstruct-above-bit-depth", "reconstruct(4096, bit_depth=12)",
      lambda f: rz.reconstruct(with_value(4096, np.uint16), pattern="mask1", bit_depth=12),
      ValueError, "frame: values span [0, 4096], beyond the 12-bit range"),
    R("reconstruction.reconstruct-uint8-bits", "reconstruct(uint8, bit_depth=11)",
      lambda f: rz.reconstruct(np.zeros((4, 4), np.uint8), pattern="mask1"), ValueError,
      "frame: a uint8 frame cannot hold 11-bit data"),
    R("reconstruction.reconstruct-no-pattern", "reconstruct(array) without pattern",
      lambda f: rz.reconstruct(u16()), TypeError,
      "pattern: required when frame is a plain array"),
    R("reconstruction.reconstruct-pattern-unknown", "reconstruct(pattern='foo')",
      lambda f: rz.reconstruct(u16(), pattern="foo"), ValueError,
      "pattern: 'foo' is neither a preset"),
    R("reconstruction.reconstruct-pattern-type", "reconstruct(pattern=3)",
      lambda f: rz.reconstruct(u16(), pattern=3), TypeError,
      "pattern: expected a Pattern, a preset name or a tile string"),
    R("reconstruction.reconstruct-pattern-no-bayer", "reconstruct(pattern='ZR/RG')",
      lambda f: rz.reconstruct(u16(), pattern="ZR/RG"), ValueError,
      "pattern: tile 'ZR/RG' fits no Bayer phase"),
    R("reconstruction.reconstruct-pattern-no-candidate", "reconstruct(pattern='GZ/ZG')",
      lambda f: rz.reconstruct(u16(), pattern="GZ/ZG"), ValueError,
      "pattern: the Z site (0, 1) of 'GZ/ZG' has no known pixel of its colour"),
    R("reconstruction.reconstruct-pattern-frame-mismatch",
      "reconstruct(RawFrame mask1, pattern='mask2')",
      lambda f: rz.reconstruct(small_frame(), pattern="mask2"), ValueError,
      "pattern: 'mask2' differs from the frame's pattern 'mask1'"),
    R("reconstruction.reconstruct-bit_depth-frame-mismatch",
      "reconstruct(RawFrame 11 bits, bit_depth=12)",
      lambda f: rz.reconstruct(small_frame(), bit_depth=12), ValueError,
      "bit_depth: 12 differs from the frame's 11"),
    R("reconstruction.reconstruct-bit_depth-0", "reconstruct(bit_depth=0)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", bit_depth=0), ValueError,
      "bit_depth: expected 1..16 bits, got 0"),
    R("reconstruction.reconstruct-bit_depth-17", "reconstruct(bit_depth=17)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", bit_depth=17), ValueError,
      "bit_depth: expected 1..16 bits, got 17"),
    R("reconstruction.reconstruct-bit_depth-float", "reconstruct(bit_depth=11.0)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", bit_depth=11.0), TypeError,
      "bit_depth: expected an integer number of bits"),
    R("reconstruction.reconstruct-bit_depth-bool", "reconstruct(bit_depth=True)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", bit_depth=True), TypeError,
      "bit_depth: expected an integer number of bits"),
    R("reconstruction.reconstruct-method-unknown", "reconstruct(method='bicubic')",
      lambda f: rz.reconstruct(u16(), "bicubic", pattern="mask1"), ValueError,
      "method: expected one of 'bilinear', 'bi', 'edi_central', 'edi_line', 'sg', 'edi_rows'"),
    R("reconstruction.reconstruct-method-none", "reconstruct(method=None)",
      lambda f: rz.reconstruct(u16(), None, pattern="mask1"), ValueError,
      "method: expected one of"),
    R("reconstruction.reconstruct-edi_rows-mask1",
      "reconstruct(method='edi_rows', pattern='mask1')",
      lambda f: rz.reconstruct(u16(), "edi_rows", pattern="mask1"), ValueError,
      "method: 'edi_rows' needs the pixels two rows above and below"),
    R("reconstruction.reconstruct-precision", "reconstruct(precision='float16')",
      lambda f: rz.reconstruct(u16(), pattern="mask1", precision="float16"), ValueError,
      "precision: expected one of 'float32', 'float64'"),
    R("reconstruction.reconstruct-sg_mode", "reconstruct(sg_mode='mixed')",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sg_mode="mixed"), ValueError,
      "sg_mode: expected one of 'auto', 'pure', 'combined'"),
    R("reconstruction.reconstruct-exp", "reconstruct(exp='approx')",
      lambda f: rz.reconstruct(u16(), pattern="mask1", exp="approx"), ValueError,
      "exp: expected one of 'auto', 'libm', 'fast'"),
    R("reconstruction.reconstruct-out-shape", "reconstruct(out=<array of another shape or dtype>)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", out=np.empty((8, 9), np.uint16)),
      ValueError, "out: expected shape (8, 8) and dtype uint16"),
    R("reconstruction.reconstruct-out-type", "reconstruct(out=[[...]])",
      lambda f: rz.reconstruct(u16(), pattern="mask1", out=[[0] * 8] * 8), TypeError,
      "out: expected a numpy array"),
    R("reconstruction.reconstruct-out-strided", "reconstruct(out=<strided or read-only view>)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", out=np.empty((8, 16), np.uint16)[:, ::2]),
      ValueError, "out: expected a C-contiguous, writeable array"),
    R("reconstruction.reconstruct-out-overlap", "reconstruct(frame, out=frame)",
      lambda f: (lambda a: rz.reconstruct(a, pattern="mask1", out=a))(u16()), ValueError,
      "out: overlaps the input frame"),
    R("reconstruction.reconstruct-domain", "reconstruct(domain='lab')",
      lambda f: rz.reconstruct(u16(), pattern="mask1", domain="lab"), ValueError,
      "domain: expected one of 'intensity', 'colour_difference'"),
    R("reconstruction.reconstruct-workers-0", "reconstruct(workers=0)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", workers=0), ValueError,
      "workers: expected None, -1 or a positive number of threads"),
    R("reconstruction.reconstruct-workers-negative", "reconstruct(workers=-2)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", workers=-2), ValueError,
      "workers: expected None, -1 or a positive number of threads"),
    R("reconstruction.reconstruct-workers-float", "reconstruct(workers=1.5)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", workers=1.5), TypeError,
      "workers: expected None, -1 or a positive number of threads"),
    R("reconstruction.reconstruct-workers-text", "reconstruct(workers='2')",
      lambda f: rz.reconstruct(u16(), pattern="mask1", workers="2"), TypeError,
      "workers: expected None, -1 or a positive number of threads, got '2'"),
    R("reconstruction.reconstruct-workers-huge", "reconstruct(workers=100000)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", workers=100_000), ValueError,
      "workers: expected at most"),
    R("reconstruction.reconstruct-workers-overflow", "reconstruct(workers=10**12)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", workers=10**12), ValueError,
      "workers: expected at most"),
    R("reconstruction.reconstruct-sigma_floor-0", "reconstruct(sigma_floor=0)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sigma_floor=0), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("reconstruction.reconstruct-sigma_floor-negative", "reconstruct(sigma_floor=-1e-3)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sigma_floor=-1e-3), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("reconstruction.reconstruct-sigma_floor-nan", "reconstruct(sigma_floor=nan)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sigma_floor=np.nan), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("reconstruction.reconstruct-sigma_floor-text", "reconstruct(sigma_floor='small')",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sigma_floor="small"), TypeError,
      "sigma_floor: expected a number"),
    R("reconstruction.reconstruct-sigma_rel-negative", "reconstruct(sigma_rel=-1)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sigma_rel=-1), ValueError,
      "sigma_rel: expected a finite number >= 0 and <= 10"),
    R("reconstruction.reconstruct-sigma_rel-nan", "reconstruct(sigma_rel=nan)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sigma_rel=np.nan), ValueError,
      "sigma_rel: expected a finite number >= 0 and <= 10"),
    R("reconstruction.reconstruct-sigma_rel-none", "reconstruct(sigma_rel=None)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", sigma_rel=None), TypeError,
      "sigma_rel: expected a number, got None"),
    R("reconstruction.reconstruct-edge_ratio-0", "reconstruct(edge_ratio=0)",
      lambda f: rz.reconstruct(u16((12, 8)), "edi_rows", pattern="rows", edge_ratio=0),
      ValueError, "edge_ratio: expected a finite number > 0"),
    R("reconstruction.reconstruct-edge_ratio-inf", "reconstruct(edge_ratio=inf)",
      lambda f: rz.reconstruct(u16((12, 8)), "edi_rows", pattern="rows", edge_ratio=np.inf),
      ValueError, "edge_ratio: expected a finite number > 0"),
    R("reconstruction.reconstruct-clip_level-nan", "reconstruct(clip_level=nan)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", clip_level=np.nan), ValueError,
      "clip_level: expected a finite number > 0"),
    R("reconstruction.reconstruct-clip_level-negative", "reconstruct(clip_level=-1)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", clip_level=-1), ValueError,
      "clip_level: expected a finite number > 0"),
    R("reconstruction.reconstruct-clip_level-text", "reconstruct(clip_level='high')",
      lambda f: rz.reconstruct(u16(), pattern="mask1", clip_level="high"), TypeError,
      "clip_level: expected a positive number, None or 'auto'"),
    # -- ReconstructParams -----------------------------------------------------------------
    R("reconstruction.ReconstructParams-precision", "ReconstructParams(precision='float16')",
      lambda f: rz.ReconstructParams(precision="float16"), ValueError,
      "precision: expected one of 'float32', 'float64'"),
    R("reconstruction.ReconstructParams-exp", "ReconstructParams(exp='approx')",
      lambda f: rz.ReconstructParams(exp="approx"), ValueError,
      "exp: expected one of 'auto', 'libm', 'fast'"),
    # -- precision='fixed': what the fixed-point model has no rule for ----------------------
    R("reconstruction.reconstruct-fixed-float-frame", "reconstruct(float64, precision='fixed')",
      lambda f: rz.reconstruct(np.zeros((8, 8)), pattern="mask1", precision="fixed"), TypeError,
      "frame: precision='fixed' takes integer frames (uint8 or uint16), got float64"),
    R("reconstruction.reconstruct-fixed-z_guided", "reconstruct('z_guided', precision='fixed')",
      lambda f: rz.reconstruct(u16(), "z_guided", pattern="mask1", precision="fixed"),
      ValueError, "method: precision='fixed' has no model of 'z_guided' yet"),
    R("reconstruction.reconstruct-fixed-learned-register",
      "reconstruct('learned', precision='fixed', hash_bits=24, hash_const_bits=24)",
      lambda f: rz.reconstruct(u16(), "learned", pattern="mask1", precision="fixed",
                               fixed_point={"hash_bits": 24, "hash_const_bits": 24}),
      ValueError, "register_bits: the register coherence_lhs"),
    R("reconstruction.reconstruct-fixed-clip_level",
      "reconstruct(precision='fixed', clip_level=1000)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", precision="fixed", clip_level=1000),
      ValueError, "clip_level: precision='fixed' has no clipped-pixel rule; expected None"),
    R("reconstruction.reconstruct-fixed-wide-frame", "reconstruct(2x16386, precision='fixed')",
      lambda f: rz.reconstruct(u16((2, 16386)), pattern="mask1", precision="fixed"), ValueError,
      "frame: the fixed-point model's line buffers hold rows of at most 16384 pixels; got 16386"),
    R("reconstruction.reconstruct-fixed-period", "reconstruct(period 10, precision='fixed')",
      lambda f: rz.reconstruct(u16((10, 10)), pattern=rz.Pattern("RGRGRGRGRZ/GBGBGBGBGB"),
                               precision="fixed"), ValueError,
      "pattern: the fixed-point model holds periods up to 8 (its look-ahead)"),
    R("reconstruction.reconstruct-fixed-register",
      "reconstruct(mask2, precision='fixed', register_bits=24)",
      lambda f: rz.reconstruct(u16(), pattern="mask2", precision="fixed",
                               fixed_point={"register_bits": 24}), ValueError,
      "register_bits: the register mean_product"),
    R("reconstruction.reconstruct-learned-domain", "reconstruct(frame, 'learned', "
      "domain='colour_difference')",
      lambda f: rz.reconstruct(u16(), "learned", pattern="mask1", domain="colour_difference"),
      ValueError, "domain: method 'learned' applies its filters to the intensities"),
    R("reconstruction.reconstruct-bilinear-domain", "reconstruct(frame, 'bilinear', "
      "domain='colour_difference')",
      lambda f: rz.reconstruct(u16(), "bilinear", pattern="mask2", domain="colour_difference"),
      ValueError, "domain: method 'bilinear' interpolates the intensities"),
    R("reconstruction.reconstruct-edi_rows-domain", "reconstruct(mask2 frame, 'edi_rows', "
      "domain='colour_difference')",
      lambda f: rz.reconstruct(u16(), "edi_rows", pattern="mask2", domain="colour_difference"),
      ValueError, "domain: method 'edi_rows' interpolates the intensities"),
    R("reconstruction.reconstruct-fixed-sigma_bits",
      "reconstruct(precision='fixed', sigma_rel=0.3, sigma_bits=4)",
      lambda f: rz.reconstruct(u16(), pattern="mask1", precision="fixed", sigma_rel=0.3,
                               fixed_point={"sigma_bits": 4}), ValueError,
      "sigma_bits: 4 fractional bits hold sigma_rel=0.3 as 5/2^4; raise sigma_bits to 8"),
    R("reconstruction.ReconstructParams-fixed-domain",
      "ReconstructParams(precision='fixed', domain='colour_difference')",
      lambda f: rz.ReconstructParams(precision="fixed", domain="colour_difference"),
      ValueError, "domain: precision='fixed' runs the intensity domain only"),
    R("reconstruction.ReconstructParams-fixed-exp",
      "ReconstructParams(precision='fixed', exp='libm')",
      lambda f: rz.ReconstructParams(precision="fixed", exp="libm"), ValueError,
      "exp: precision='fixed' reads eq. 7's exponential from a table"),
    R("reconstruction.ReconstructParams-exp-table-float",
      "ReconstructParams(precision='float32', exp='table')",
      lambda f: rz.ReconstructParams(precision="float32", exp="table"), ValueError,
      "exp: 'table' is the fixed-point model's exponential (precision='fixed')"),
    R("reconstruction.ReconstructParams-fixed_point-unknown",
      "ReconstructParams(fixed_point={'exp_size': 8})",
      lambda f: rz.ReconstructParams(precision="fixed", fixed_point={"exp_size": 8}), TypeError,
      "fixed_point got an unexpected keyword argument 'exp_size'"),
    R("reconstruction.ReconstructParams-fixed_point-type", "ReconstructParams(fixed_point=3)",
      lambda f: rz.ReconstructParams(precision="fixed", fixed_point=3), TypeError,
      "fixed_point: expected a FixedPointConfig, a dict of its fields or None, got int"),
    # -- FixedPointConfig --------------------------------------------------------------------
    R("reconstruction.FixedPointConfig-table-size-0", "FixedPointConfig(exp_table_size=0)",
      lambda f: rz.FixedPointConfig(exp_table_size=0), ValueError,
      "exp_table_size: expected a power of two from 2 to 65536 entries, got 0"),
    R("reconstruction.FixedPointConfig-table-size-3", "FixedPointConfig(recip_table_size=3)",
      lambda f: rz.FixedPointConfig(recip_table_size=3), ValueError,
      "recip_table_size: expected a power of two from 2 to 65536 entries, got 3"),
    R("reconstruction.FixedPointConfig-mode", "FixedPointConfig(exp='cubic')",
      lambda f: rz.FixedPointConfig(exp="cubic"), ValueError,
      "exp: expected one of 'table', 'pwl', got 'cubic'"),
    R("reconstruction.FixedPointConfig-width-1", "FixedPointConfig(weight_bits=1)",
      lambda f: rz.FixedPointConfig(weight_bits=1), ValueError,
      "weight_bits: expected an integer >= 2 and <= 40, got 1"),
    R("reconstruction.FixedPointConfig-width-bool", "FixedPointConfig(weight_bits=True)",
      lambda f: rz.FixedPointConfig(weight_bits=True), TypeError,
      "weight_bits: expected an integer, got True"),
    R("reconstruction.FixedPointConfig-register-64", "FixedPointConfig(register_bits=64)",
      lambda f: rz.FixedPointConfig(register_bits=64), ValueError,
      "register_bits: expected an integer >= 8 and <= 63, got 64"),
    R("reconstruction.FixedPointConfig-tap_bits", "FixedPointConfig(tap_bits=3)",
      lambda f: rz.FixedPointConfig(tap_bits=3), ValueError,
      "tap_bits: expected an integer >= 4 and <= 32, got 3"),
    R("reconstruction.FixedPointConfig-hash_bits", "FixedPointConfig(hash_bits=0)",
      lambda f: rz.FixedPointConfig(hash_bits=0), ValueError,
      "hash_bits: expected an integer >= 4 and <= 30, got 0"),
]

test_api_contract = api_tests(ROWS)


# --------------------------------------------------------------------------- more bad input
def _run(data, pattern, method, bit_depth=11, **kw):
    return rz.reconstruct(data, method, pattern=pattern, bit_depth=bit_depth, **kw)


def _f(shape=(8, 8), dtype=np.float64):
    return np.zeros(shape, dtype)


def _with(value, at=(1, 1), dtype=np.float64):
    d = _f(dtype=dtype)
    d[at] = value
    return d


BAD_INPUTS = {
    "unknown method": (lambda: _run(_f(), rz.mask1(), "bicubic"), ValueError, "method"),
    "method not a string": (lambda: _run(_f(), rz.mask1(), 3), ValueError, "method"),
    "edi_rows on mask1": (lambda: _run(_f(), rz.mask1(), "edi_rows"), ValueError, "edi_rows"),
    "edi_rows on ZZGR/ZZBG": (lambda: _run(_f(), rz.Pattern("ZZGR/ZZBG"), "edi_rows"),
                              ValueError, "edi_rows"),
    "edi_rows on GRGR/BGZG": (lambda: _run(_f(), rz.Pattern("GRGR/BGZG"), "edi_rows"),
                              ValueError, "edi_rows"),
    "no candidates ZZ/ZG": (lambda: _run(_f(), rz.Pattern("ZZ/ZG"), "sg"), ValueError, "pattern"),
    "no candidates GZ/BG": (lambda: _run(_f(), rz.Pattern("GZ/BG"), "bi"), ValueError, "pattern"),
    "NaN": (lambda: _run(_with(np.nan), rz.mask1(), "sg"), ValueError, "frame"),
    "NaN at a Z site": (lambda: _run(_with(np.nan, (0, 0)), rz.mask1(), "sg"), ValueError,
                        "frame"),
    "inf": (lambda: _run(_with(np.inf), rz.mask1(), "sg"), ValueError, "frame"),
    "above 2^b-1 (float)": (lambda: _run(_with(2048.0), rz.mask1(), "sg"), ValueError,
                            "frame|data"),
    "above 2^b-1 (uint16)": (lambda: _run(_with(4096, dtype=np.uint16), rz.mask1(), "sg",
                                          bit_depth=12), ValueError, "frame|data"),
    "negative": (lambda: _run(_with(-1.0), rz.mask1(), "sg"), ValueError, "frame|data"),
    "1-D array": (lambda: _run(np.zeros(16), rz.mask1(), "sg"), ValueError, "frame"),
    "3-D array": (lambda: _run(np.zeros((4, 4, 3)), rz.mask1(), "sg"), ValueError, "frame"),
    "smaller than period": (lambda: _run(_f((3, 3)), rz.mask2(), "sg"), ValueError,
                            "frame.*period"),
    "smaller than rows period": (lambda: _run(_f((5, 8)), rz.rows(), "edi_rows"), ValueError,
                                 "period"),
    "negative sigma_floor": (lambda: _run(_f(), rz.mask1(), "sg", sigma_floor=-1e-3),
                             ValueError, "sigma_floor"),
    "zero sigma_floor": (lambda: _run(_f(), rz.mask1(), "sg", sigma_floor=0), ValueError,
                         "sigma_floor"),
    "NaN sigma_floor": (lambda: _run(_f(), rz.mask1(), "sg", sigma_floor=np.nan), ValueError,
                        "sigma_floor"),
    "string sigma_floor": (lambda: _run(_f(), rz.mask1(), "sg", sigma_floor="small"),
                           TypeError, "sigma_floor"),
    "negative edge_ratio": (lambda: _run(_f((12, 8)), rz.rows(), "edi_rows", edge_ratio=-0.5),
                            ValueError, "edge_ratio"),
    "bad precision": (lambda: _run(_f(), rz.mask1(), "sg", precision="float16"), ValueError,
                      "precision"),
    "bad sg_mode": (lambda: _run(_f(), rz.mask1(), "sg", sg_mode="mixed"), ValueError, "sg_mode"),
    "bad exp": (lambda: _run(_f(), rz.mask1(), "sg", exp="approx"), ValueError, "exp"),
    "workers=0": (lambda: _run(_f(), rz.mask1(), "sg", workers=0), ValueError, "workers"),
    "int32 frame": (lambda: _run(_f(dtype=np.int32), rz.mask1(), "sg"), TypeError, "frame"),
    "complex frame": (lambda: _run(_f(dtype=np.complex128), rz.mask1(), "sg"), TypeError,
                      "frame"),
    "no pattern": (lambda: rz.reconstruct(_f(), "sg"), TypeError, "pattern"),
    "bit_depth 17": (lambda: _run(_f(dtype=np.uint16), rz.mask1(), "sg", bit_depth=17),
                     ValueError, "bit_depth"),
    "bit_depth 0": (lambda: _run(_f(dtype=np.uint16), rz.mask1(), "sg", bit_depth=0),
                    ValueError, "bit_depth"),
    "pattern differs from frame's": (
        lambda: rz.reconstruct(rz.RawFrame(_f(), rz.mask1()), "sg", pattern="mask2"),
        ValueError, "pattern"),
    "bit_depth differs from frame's": (
        lambda: rz.reconstruct(rz.RawFrame(_f(), rz.mask1()), "sg", bit_depth=12),
        ValueError, "bit_depth"),
}


@pytest.mark.parametrize("case", list(BAD_INPUTS))
def test_bad_input_raises(case):
    fn, exc, pattern = BAD_INPUTS[case]
    with pytest.raises(exc, match=pattern):
        fn()


def test_range_error_names_the_frame_parameter():
    with pytest.raises(ValueError, match="^frame"):
        _run(_with(5000.0), rz.mask1(), "sg")


@pytest.mark.parametrize("call", [lambda f, **k: rz.reconstruct(f, "sg", **k),
                                  lambda f, **k: rz.ColourISP().run(f, **k)],
                         ids=["reconstruct", "ColourISP.run"])
def test_frame_arguments_are_read_alike_by_every_caller(call):
    """One reading of ``frame, pattern=, bit_depth=`` (rgbz_fast._frame.frame_inputs)."""
    frame = rz.RawFrame(np.full((8, 8), 100, np.uint16), "mask1")
    cases = [(lambda: call(frame.data), TypeError,
              "pattern: required when frame is a plain array"),
             (lambda: call(frame, pattern="mask2"), ValueError,
              "pattern: 'mask2' differs from the frame's pattern 'mask1'"),
             (lambda: call(frame, bit_depth=12), ValueError,
              "bit_depth: 12 differs from the frame's 11"),
             (lambda: call(np.full((8, 8), 4000, np.uint16), pattern="mask1"), ValueError,
              "frame: values span [4000, 4000], beyond the 11-bit range")]
    for make, exc, msg in cases:
        with pytest.raises(exc) as info:
            make()
        assert str(info.value).startswith(msg), info.value
    call(frame, pattern="mask1", bit_depth=11)             # agreeing values are accepted


# --------------------------------------------------------------------------- accepted on purpose
def test_accepted_on_purpose():
    """The inputs docs/reports/robustness.md lists as accepted, not errors: values beyond the
    bit depth at Z sites (never read), masked, Fortran-ordered and strided arrays, the
    largest thread count, and the smallest sigma floor."""
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
                          sigma_rel=0.0, precision="float64")
    assert np.all(np.isfinite(tiny)) and tiny.max() <= 2047
    with pytest.warns(RuntimeWarning, match="precision='float32' with sigma_rel=0: eq. 7's "
                                            "weights underflow float32"):
        tiny = rz.reconstruct(d.astype(np.float64), "edi_line", pattern=p,
                              sigma_floor=5e-324, sigma_rel=0.0)
    assert np.all(np.isfinite(tiny)) and tiny.max() <= 2047
    # the paper-literal parameters run where their weights do not underflow
    assert rz.ReconstructParams.paper().precision == "float64"


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
    tof.demodulate(taps)


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
    About 5 s on two cores; ``pytest -m slow tests/reconstruction/test_contract.py`` runs
    it alone.
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
