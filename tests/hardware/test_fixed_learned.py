"""precision="fixed" with method "learned": the C streaming model (csrc/hw_learned.c) against
the NumPy integer reference of tests/_reference/fixed_learned.py, bit for bit; refits of any
shape; what it refuses; its silicon.

The reference takes the taps and hash pairs from its own window (the channel codes), derives
the integer constants from the configuration's fields and processes the frame whole (no line
buffers), so agreement checks the constants, the streaming (borders included) and the
arithmetic at once.
"""

from __future__ import annotations

import numpy as np
import pytest

import rgbz_fast as rz
from _reference.fixed_learned import reference_fixed_learned
from rgbz_fast.hardware import hardware_cost
from rgbz_fast.reconstruction import FixedPointConfig, LearnedFilters, default_filters
from rgbz_fast.reconstruction._fixed_learned import learned_registers, quantise_learned

PATTERNS = ("mask1", "mask2", "mask1_rggb", "mask2_bggr", "mask2_gbrg")
NARROW = FixedPointConfig(tap_bits=7, hash_bits=5, hash_const_bits=3, hash_norm_bits=2)
CONFIGS = {"default": FixedPointConfig(), "narrow": NARROW,
           "wide": FixedPointConfig(tap_bits=24, hash_bits=18, hash_const_bits=20,
                                    hash_norm_bits=20)}


def _frame(kind, shape, bit_depth, rng):
    top = (1 << bit_depth) - 1
    rows, cols = shape
    if kind == "random":
        data = rng.integers(0, top + 1, size=shape)
    elif kind == "edges":                   # steps, a ramp and a line: the buckets differ
        yy, xx = np.mgrid[0:rows, 0:cols]
        data = np.where(xx * 3 > cols + yy, top, top // 7) + (yy * 5) % 11
        data[rows // 2] = top // 2
        data = np.clip(data, 0, top)
    elif kind == "extremes":
        data = rng.integers(0, 2, size=shape) * top
    else:
        data = np.full(shape, top // 3)
    return np.ascontiguousarray(data.astype(np.uint8 if bit_depth <= 8 else np.uint16))


def _check(data, filters, bit_depth, config):
    got = rz.reconstruct(data, "learned", pattern=filters.pattern, bit_depth=bit_depth,
                         precision="fixed", fixed_point=config, filters=filters)
    ref = reference_fixed_learned(data, filters, config, bit_depth)
    bad = np.argwhere(got.astype(np.int64) != ref)
    assert not bad.size, (f"{len(bad)} pixels differ, first at {tuple(bad[0])}: C "
                          f"{got[tuple(bad[0])]}, reference {ref[tuple(bad[0])]}")
    return got


@pytest.mark.parametrize("pname", PATTERNS)
@pytest.mark.parametrize("cname", CONFIGS)
def test_c_model_equals_the_reference_bit_for_bit(pname, cname, rng):
    filters = default_filters(pname)
    for kind, shape, bd in (("random", (21, 26), 11), ("edges", (16, 19), 11),
                            ("extremes", (12, 12), 8), ("flat", (8, 9), 12)):
        _check(_frame(kind, shape, bd, rng), filters, bd, CONFIGS[cname])


def test_natural_image_agrees_and_stays_near_float64():
    from skimage import data as skd
    img = skd.astronaut()[100:196, 120:232]
    for p in ("mask1", "mask2"):
        frame = rz.mosaic(img, p)
        filters = default_filters(p)
        got = _check(frame.data, filters, 11, FixedPointConfig())
        exact = rz.reconstruct(frame, "learned", precision="float64")
        d = np.abs(got[frame.z_mask].astype(int) - exact[frame.z_mask].astype(int))
        assert np.mean(d <= 1) >= 0.995, (p, np.mean(d <= 1))


def _refit(pattern, radius, hash_radius, n_str, n_coh, n_spr, rng, scale=0.3):
    """Filters of another shape, as another engineer's refit could give (random weights,
    thresholds of their own level counts)."""
    from rgbz_fast.reconstruction._learned_hash import learned_geometry
    geom = learned_geometry(rz.get_pattern(pattern), radius, hash_radius)
    n_ph, nt = len(geom), max(len(g["taps"]) for g in geom)
    nb = 8 * n_str * n_coh * n_spr
    w = rng.normal(0, scale, size=(n_ph, nb, nt))
    w[..., 0] += 0.5
    s = np.sort(rng.uniform(10, 20000, size=(n_ph, n_str - 1)), axis=1)
    c = np.sort(rng.uniform(0.05, 1.5, size=(n_ph, n_coh - 1)), axis=1)
    k = np.sort(rng.uniform(1, 40, size=(n_ph, n_spr - 1)), axis=1) if n_spr > 1 else None
    return LearnedFilters(pattern, 11, w, s, c, k, radius=radius, hash_radius=hash_radius)


@pytest.mark.parametrize("pattern,radius,hash_radius,levels", [
    ("mask2", 5, 4, (4, 2, 1)),          # the widest window: 5 rows of look-ahead
    ("mask1", 2, 2, (2, 4, 3)),
    ("mask2_rggb", 4, 3, (3, 3, 2)),
    ("mask1_gbrg", 3, 3, (1, 1, 1)),     # no thresholds at all
])
def test_refits_of_any_shape_agree(pattern, radius, hash_radius, levels, rng):
    filters = _refit(pattern, radius, hash_radius, *levels, rng)
    for kind, shape, bd in (("random", (23, 30), 11), ("edges", (18, 17), 10)):
        for cfg in (FixedPointConfig(), NARROW):
            _check(_frame(kind, shape, bd, rng), filters, bd, cfg)


def test_declared_widths_hold_every_value(rng):
    """The quantised weights fit tap_bits, and the accumulator's declared width holds the
    largest dot product the ROM allows."""
    for p in ("mask1", "mask2"):
        f = default_filters(p)
        for cfg in CONFIGS.values():
            q = quantise_learned(f, cfg, 11)
            wq = q["arrays"]["wq"].astype(np.int64)
            assert np.abs(wq).max() <= (1 << (cfg.tap_bits - 1)) - 1
            regs = {r.name: r for r in learned_registers(f, cfg, 11)}
            assert regs["tap"].bits <= cfg.tap_bits
            worst = int(np.abs(wq).sum(axis=2).max()) * 2047
            assert worst.bit_length() + 1 <= regs["accumulator"].bits
            # the fraction bits: the most that hold every weight
            wmax = np.abs(f.weights).max()
            assert np.floor(wmax * 2.0 ** (q["tap_frac"] + 1) + 0.5) > (1 << (cfg.tap_bits - 1)) - 1


def test_16_bit_frames_fit_and_agree(rng):
    f = default_filters("mask2")
    data = _frame("random", (16, 20), 16, rng)
    _check(data, f, 16, FixedPointConfig())


def test_refusals_name_the_field(rng):
    f = default_filters("mask2")
    data = _frame("random", (16, 16), 11, rng)
    with pytest.raises(ValueError, match="tap_bits"):
        FixedPointConfig(tap_bits=3)
    with pytest.raises(ValueError, match="hash_bits"):
        FixedPointConfig(hash_bits=31)
    with pytest.raises(ValueError, match="hash_const_bits"):
        FixedPointConfig(hash_const_bits=0)
    with pytest.raises(ValueError, match="hash_norm_bits"):
        FixedPointConfig(hash_norm_bits=25)
    with pytest.raises(ValueError, match="register_bits.*coherence_lhs|register_bits"):
        rz.reconstruct(data, "learned", pattern="mask2", bit_depth=11, precision="fixed",
                       fixed_point=FixedPointConfig(hash_bits=24, hash_const_bits=24))
    big = _refit("mask2", 3, 3, 2, 2, 2, rng, scale=200.0)
    with pytest.raises(ValueError, match="tap_bits: a weight of"):
        rz.reconstruct(data, "learned", pattern="mask2", bit_depth=11, precision="fixed",
                       fixed_point=FixedPointConfig(tap_bits=5), filters=big)
    with pytest.raises(TypeError, match="frame"):
        rz.reconstruct(data.astype(np.float32), "learned", pattern="mask2", bit_depth=11,
                       precision="fixed")


def test_the_cost_counts_the_filter_rom_and_the_hash():
    for p in ("mask1", "mask2"):
        f = default_filters(p)
        n_ph, nb, nt = f.weights.shape
        for cfg in (FixedPointConfig(), NARROW):
            c = hardware_cost(p, "learned", width=4000, fixed_point=cfg)
            rom = c.tables["filter ROM"]
            assert rom["total_bits"] == n_ph * nb * nt * cfg.tap_bits
            P, Q = f.pattern.period
            A = max(f.radius, P - 1)
            assert c.line_buffers == f.radius + A
            assert c.line_buffer_bits == c.line_buffers * 4000 * 11
            assert c.window == (2 * f.radius + 1, f.radius + max(f.radius, Q - 1) + 1, 11)
            mults = c.multipliers()
            taps = max(len(g["taps"]) for g in f.geometry)
            dot = tuple(sorted((cfg.tap_bits, 11), reverse=True))
            assert mults[dot] == taps                       # the dot product
            assert c.dsp48() > 0 and c.depth > 0
            assert c.as_dict()["tables"]["filter ROM"]["bram18"] >= 1
        narrow = hardware_cost(p, "learned", fixed_point=NARROW)
        wide = hardware_cost(p, "learned", fixed_point=CONFIGS["wide"])
        assert narrow.total_bits < wide.total_bits


def test_thresholds_outside_the_range_of_the_structure_decide_as_in_float(rng):
    """A strength threshold below 0 or beyond the largest T is held at the ends of T's range
    (its declared width): the decisions do not change, and the model still agrees."""
    f = _refit("mask2", 3, 3, 3, 2, 2, rng)
    s = np.tile([-5.0, 1e12], (f.weights.shape[0], 1))
    g = LearnedFilters(f.pattern, 11, f.weights, s, f.coherence_thresholds,
                       f.spread_thresholds, radius=3, hash_radius=3)
    data = _frame("random", (20, 24), 11, rng)
    got = _check(data, g, 11, FixedPointConfig())
    q = quantise_learned(g, FixedPointConfig(), 11)["arrays"]["str_q"]
    regs = {r.name: r for r in learned_registers(g, FixedPointConfig(), 11)}
    assert q.min() == -1 and int(q.max()).bit_length() <= regs["strength_threshold"].bits
    exact = rz.reconstruct(data, "learned", pattern=g.pattern, bit_depth=11,
                           precision="float64", filters=g)
    z = g.pattern.z_mask(data.shape)
    assert np.mean(np.abs(got[z].astype(int) - exact[z].astype(int)) <= 1) > 0.99
