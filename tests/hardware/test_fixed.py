"""precision="fixed": the C streaming model (csrc/hw_recon.c) against the NumPy integer
reference of tests/_reference/fixed.py, bit for bit, and what it refuses.

The reference is written from the datapath of docs/guide/hardware.md, gathers every
site's window directly (no line buffers) and finds candidates and groups from the
channel codes, so agreement checks the plans' integer constants, the line-buffered
streaming (borders included: look-ahead, the bottom rows served from the buffers) and
the arithmetic at once.
"""

from __future__ import annotations

import zlib

import numpy as np
import pytest

import rgbz_fast as rz
from _reference.fixed import exp_table, recip_table, reference_fixed
from rgbz_fast.reconstruction import FixedPointConfig
from rgbz_fast.reconstruction import build_plans
from rgbz_fast.reconstruction._fixed import FIXED_METHODS, hw_constants, register_widths, tables

PATTERNS = {
    "mask1": lambda: rz.mask1(),
    "mask2": lambda: rz.mask2(),
    "mask1_rggb": lambda: rz.mask1("RGGB"),
    "mask2_bggr": lambda: rz.mask2("BGGR"),
    "custom_ZR/BG": lambda: rz.Pattern("ZR/BG"),
    "z_on_red": lambda: rz.Pattern("GRGR/BGBG/GZGR/BGBG"),
    "rows": lambda: rz.rows(),               # period 6: a look-ahead of 5 rows
}
NARROW = FixedPointConfig(exp="pwl", exp_table_size=8, exp_bits=6, exp_range_bits=3,
                          recip="table", recip_table_size=8, recip_bits=6, ratio_bits=4,
                          sigma_bits=2, alpha_bits=4, weight_bits=6)
CONFIGS = {"default": FixedPointConfig(), "narrow": NARROW,
           "wide": FixedPointConfig(exp="pwl", recip="table", exp_bits=24, recip_bits=20,
                                    ratio_bits=20, weight_bits=22, alpha_bits=20,
                                    exp_table_size=4096, recip_table_size=4096,
                                    sigma_bits=12)}


def _frame(kind, shape, bit_depth, rng):
    top = (1 << bit_depth) - 1
    rows, cols = shape
    if kind == "random":
        data = rng.integers(0, top + 1, size=shape)
    elif kind == "edges":                  # steps, a ramp and a line: the cases the weights decide
        yy, xx = np.mgrid[0:rows, 0:cols]
        data = np.where(xx * 3 > cols + yy, top, top // 7) + (yy * 5) % 11
        data[rows // 2] = top // 2
        data = np.clip(data, 0, top)
    elif kind == "extremes":               # 0 and full scale only
        data = rng.integers(0, 2, size=shape) * top
    else:
        data = np.full(shape, top // 3)
    return np.ascontiguousarray(data.astype(np.uint8 if bit_depth <= 8 else np.uint16))


def _check(data, pattern, method, bit_depth, config, **kw):
    got = rz.reconstruct(data, method, pattern=pattern, bit_depth=bit_depth, precision="fixed",
                         fixed_point=config, **kw)
    ref = reference_fixed(data, pattern, method, config, bit_depth, **kw)
    bad = np.argwhere(got.astype(np.int64) != ref)
    assert not bad.size, (f"{len(bad)} pixels differ, first at {tuple(bad[0])}: C "
                          f"{got[tuple(bad[0])]}, reference {ref[tuple(bad[0])]}")
    return got


@pytest.mark.parametrize("method", FIXED_METHODS)
@pytest.mark.parametrize("pname", sorted(PATTERNS))
@pytest.mark.parametrize("bit_depth", (8, 11, 16))
def test_c_model_equals_the_reference_bit_for_bit(method, pname, bit_depth):
    """Every method x pattern x bit depth, on random and structured frames whose sizes are
    not whole periods (the bottom and right borders cut a tile)."""
    pattern = PATTERNS[pname]()
    rng = np.random.default_rng(zlib.crc32(f"{method} {pname} {bit_depth}".encode()))
    P, Q = pattern.period
    for kind, shape in (("random", (3 * P + 3, 4 * Q + 1)), ("edges", (4 * P + 1, 5 * Q + 3)),
                        ("extremes", (2 * P + 1, 3 * Q + 1)), ("flat", (P, Q))):
        _check(_frame(kind, shape, bit_depth, rng), pattern, method, bit_depth,
               FixedPointConfig())


@pytest.mark.parametrize("cname", sorted(CONFIGS))
@pytest.mark.parametrize("method", ("bi", "edi_central", "edi_line", "sg"))
def test_configurations_and_options_agree(cname, method, rng):
    """Both table modes, narrow and wide widths, the paper's sigma (sigma_rel=0, where eq. 7's
    exponent saturates), SG forced pure or combined."""
    config = CONFIGS[cname]
    for pattern in (rz.mask1(), rz.mask2()):
        data = _frame("random", (18, 22), 11, rng)
        for kw in ({}, {"sigma_rel": 0.0}, {"sigma_rel": 1.5, "sigma_floor": 0.2}):
            if kw.get("sigma_rel") == 0.0 and method != "bi":     # eq. 7 beyond its range
                with pytest.warns(RuntimeWarning, match="sigma_rel=0: eq. 7's exponent leaves"):
                    _check(data, pattern, method, 11, config, **kw)
            else:
                _check(data, pattern, method, 11, config, **kw)
        if method == "sg":
            for mode in ("pure", "combined"):
                _check(data, pattern, method, 11, config, sg_mode=mode)


def test_flat_frames_stay_flat_and_colour_sites_are_copied(rng):
    for pattern in (rz.mask1(), rz.mask2()):
        flat = np.full((12, 16), 1234, np.uint16)
        for m in FIXED_METHODS:
            out = rz.reconstruct(flat, m, pattern=pattern, precision="fixed")
            assert np.all(out == 1234)
        data = _frame("random", (12, 16), 11, rng)
        out = rz.reconstruct(data, "sg", pattern=pattern, precision="fixed")
        z = pattern.z_mask(data.shape)
        assert np.array_equal(out[~z], data[~z])


def test_bilinear_is_float64_exactly(rng):
    """The plain mean is exact (a constant multiplier, Granlund-Montgomery): the float64
    kernel's rounded output, at every bit depth."""
    for bd in (8, 11, 16):
        for pattern in (rz.mask1(), rz.mask2(), rz.rows()):
            data = _frame("random", (24, 24), bd, rng)
            a = rz.reconstruct(data, "bilinear", pattern=pattern, bit_depth=bd,
                               precision="fixed")
            b = rz.reconstruct(data, "bilinear", pattern=pattern, bit_depth=bd,
                               precision="float64")
            assert np.array_equal(a, b)


def test_out_and_raw_frames():
    img = np.random.default_rng(3).integers(0, 256, (20, 24, 3), dtype=np.uint8)
    frame = rz.mosaic(img, "mask2")
    buf = np.empty_like(frame.data)
    assert rz.reconstruct(frame, "sg", precision="fixed", out=buf) is buf
    assert np.array_equal(buf, rz.reconstruct(frame.data, "sg", pattern="mask2",
                                              precision="fixed"))


def test_tables_are_the_references():
    for cfg in CONFIGS.values():
        et, rt = tables(cfg)
        assert np.array_equal(et, exp_table(cfg)) and np.array_equal(rt, recip_table(cfg))


@pytest.mark.parametrize("method", ("bi", "edi_line", "sg"))
@pytest.mark.parametrize("cname", ("default", "wide"))
def test_declared_widths_hold_every_value(method, cname, rng):
    """The reference records the largest magnitude of each register on extreme 16-bit frames;
    none exceeds the width register_widths declares for it."""
    config = CONFIGS[cname]
    for pattern in (rz.mask1(), rz.mask2()):
        probe = {}
        for kind in ("random", "extremes", "edges"):
            data = _frame(kind, (24, 24), 16, rng)
            reference_fixed(data, pattern, method, config, 16, probe=probe)
            reference_fixed(data, pattern, method, config, 16, sigma_rel=0.0, probe=probe)
        _, plans = build_plans(pattern, method)
        hw = hw_constants(plans, config, 16, 1e-3, 0.5)
        declared = {}
        for p, h in zip(plans, hw):
            for r in register_widths(p, h, config, 16):
                declared[r.name] = max(declared.get(r.name, 0), r.bits)
        for name, seen in probe.items():
            assert seen.bit_length() <= declared[name], (name, seen, declared[name])


# -- what it refuses --------------------------------------------------------------------------

def test_refusals_name_the_parameter():
    data = np.zeros((8, 8), np.uint16)
    with pytest.raises(TypeError, match="frame: precision='fixed' takes integer frames"):
        rz.reconstruct(data.astype(np.float32), "sg", pattern="mask1", precision="fixed")
    for m in ("z_guided", "edi_rows"):
        with pytest.raises(ValueError, match=f"method: precision='fixed' has no model of '{m}'"):
            rz.reconstruct(data, m, pattern="mask2", precision="fixed")
    with pytest.raises(ValueError, match="clip_level: precision='fixed' has no clipped-pixel"):
        rz.reconstruct(data, "sg", pattern="mask1", precision="fixed", clip_level=1000)
    with pytest.raises(ValueError, match="domain: precision='fixed' runs the intensity"):
        rz.ReconstructParams(precision="fixed", domain="colour_difference")
    with pytest.raises(ValueError, match="exp: precision='fixed' reads"):
        rz.ReconstructParams(precision="fixed", exp="libm")
    with pytest.raises(ValueError, match="frame: the fixed-point model's line buffers hold rows "
                                         "of at most 16384"):
        rz.reconstruct(np.zeros((2, 16386), np.uint16), "sg", pattern="mask1",
                       precision="fixed")
    big = rz.Pattern("/".join(["GRGRGRGRGR", "BGBGBGBGBG"] * 4 + ["GRGRGRGRGR", "BGBGBGBGBZ"]))
    with pytest.raises(ValueError, match="pattern: the fixed-point model holds periods up to 8"):
        rz.reconstruct(np.zeros((10, 10), np.uint16), "sg", pattern=big, precision="fixed")


@pytest.mark.parametrize("field, value, message", [
    ("exp_table_size", 0, "exp_table_size: expected a power of two from 2 to 65536 entries, "
                          "got 0"),
    ("recip_table_size", 48, "recip_table_size: expected a power of two"),
    ("weight_bits", 1, "weight_bits: expected an integer >= "),
    ("exp", "spline", "exp: expected one of 'table', 'pwl'"),
    ("register_bits", 64, "register_bits: expected an integer >= "),
])
def test_bad_configurations_name_the_field(field, value, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(")):
        FixedPointConfig(**{field: value})


def test_a_register_that_cannot_hold_its_sum_is_refused_not_wrapped():
    data = np.zeros((8, 8), np.uint16)
    small = FixedPointConfig(register_bits=24)
    with pytest.raises(ValueError, match=r"register_bits: the register \w+ .* needs \d+ bits for "
                                         r"16-bit frames"):
        rz.reconstruct(data, "sg", pattern="mask2", bit_depth=16, precision="fixed",
                       fixed_point=small)
    wide = FixedPointConfig(weight_bits=40, recip_bits=30)
    with pytest.raises(ValueError, match="register_bits: the register quotient_product .* lower "
                                         "weight_bits or recip_bits"):
        rz.reconstruct(data, "sg", pattern="mask2", bit_depth=16, precision="fixed",
                       fixed_point=wide)
    with pytest.raises(ValueError, match=r"sigma_bits: 4 fractional bits hold sigma_rel=0.3 as "
                                         r"5/2\^4; raise sigma_bits to 8 or more"):
        rz.reconstruct(data, "sg", pattern="mask1", precision="fixed", sigma_rel=0.3,
                       fixed_point=FixedPointConfig(sigma_bits=4))
    with pytest.raises(TypeError,
                       match="fixed_point got an unexpected keyword argument 'exp_size'"):
        rz.ReconstructParams(precision="fixed", fixed_point={"exp_size": 8})


def test_for_bit_depth_fits_16_bit_frames(rng):
    """The widened defaults hold every register of every method at 16 bits, and agree with
    the reference there."""
    cfg = FixedPointConfig.for_bit_depth(16)
    assert FixedPointConfig.for_bit_depth(11) == FixedPointConfig() == \
        FixedPointConfig.for_bit_depth(8)
    assert cfg.weight_bits == FixedPointConfig().weight_bits + 5
    for pattern in (rz.mask1(), rz.mask2()):
        data = _frame("random", (16, 20), 16, rng)
        for m in FIXED_METHODS:
            _check(data, pattern, m, 16, cfg)


def test_the_params_carry_the_configuration():
    p = rz.ReconstructParams(precision="fixed")
    assert p.fixed_point == FixedPointConfig() and p.exp_mode == "pwl"
    q = rz.ReconstructParams(precision="fixed", fixed_point={"exp": "table"})
    assert q.fixed_point.exp == "table" and q.exp_mode == "table"
    assert rz.ReconstructParams().fixed_point is None
    assert "fixed" in rz.PRECISIONS
    # exp="table" names the fixed model's exponential: the same call as exp="auto" there
    t = rz.ReconstructParams(precision="fixed", exp="table")
    assert t.exp_mode == "pwl" and t.fixed_point == p.fixed_point


def test_exp_table_runs_the_same_model_and_is_refused_for_the_floats(rng):
    data = _frame("random", (12, 16), 11, rng)
    a = rz.reconstruct(data, "sg", pattern="mask1", precision="fixed")
    b = rz.reconstruct(data, "sg", pattern="mask1", precision="fixed", exp="table")
    assert np.array_equal(a, b)
    with pytest.raises(ValueError, match="exp: 'table' is the fixed-point model's exponential "
                                         r"\(precision='fixed'\); precision='float32' takes"):
        rz.reconstruct(data, "sg", pattern="mask1", exp="table")


def test_the_c_dispatch_takes_the_fixed_precision():
    """precision 'fixed' is the third entry of the C precisions (RGBZ_PRECISIONS): its entry
    point runs through the bridge's one switch, with its tables and line buffers in
    rgbz_params; the learned filters' one (learned_fixed) likewise with its integer constants;
    the shared reconstruct and learned bridges (which hand over no such constants) and the
    counting module refuse it naming the precision."""
    from rgbz_fast import _kernels, _kernels_count
    from rgbz_fast.reconstruction._plans import build_plans

    code = _kernels.PRECISIONS["fixed"]
    assert code == int(_kernels.rgbz_precision.RGBZ_P_FIXED) == 2
    assert _kernels_count.PRECISIONS == _kernels.PRECISIONS
    assert hasattr(_kernels, "reconstruct_fixed") and \
        not hasattr(_kernels_count, "reconstruct_fixed")
    assert hasattr(_kernels, "learned_fixed") and not hasattr(_kernels_count, "learned_fixed")
    d = np.zeros((8, 8), np.uint16)
    phase_map, plans = build_plans(rz.mask1(), "bi")
    for k in (_kernels, _kernels_count):
        counts = {"opcounts": np.zeros(k.NOPS, np.uint64)} if k.counting_build() else {}
        with pytest.raises(ValueError, match="precision"):
            k.reconstruct(d, np.empty_like(d), code, 2, 2, phase_map,
                          plans.view(np.uint8).reshape(-1), 1, 1e-3, 0.0, 0.5, 2047.0, 0, 1,
                          **counts)
        i32, f64 = np.zeros((1, 1), np.int32), np.zeros((1, 1), np.float64)
        with pytest.raises(ValueError, match="precision"):
            k.learned(d, np.empty_like(d), code, 2, 2, phase_map, np.ones(1, np.int32), i32,
                      i32, np.ones((1, 4), np.int32), np.zeros((1, 4, 1), np.int32),
                      np.zeros((1, 4, 1), np.int32), np.zeros((1, 4, 1), np.int32),
                      np.ones((1, 3)), np.array([1, 0, 2, 1], np.int32), f64, f64, f64,
                      np.zeros((1, 1, 8), np.float32), np.zeros((1, 1, 8)), 0, 0, 2047.0, 1,
                      **counts)
