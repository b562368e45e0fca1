"""rgbz_fast.hardware.hardware_cost: the fixed-point model's silicon, counted from the plans."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast.hardware import FixedPointConfig, bram18_blocks, hardware_cost
from rgbz_fast.reconstruction import build_plans


def test_line_buffers_window_and_latency_follow_the_border_rule():
    """A 5x5 window needs 4 line buffers; the period-shift border of a 4-periodic tile reaches
    row 3 from the top row, one buffer more (hw_recon.h)."""
    m1 = hardware_cost("mask1", "sg", width=4000)
    assert (m1.line_buffers, m1.latency_rows, m1.latency_pixels, m1.window) == (4, 2, 2,
                                                                                 (5, 5, 11))
    assert m1.line_buffer_bits == 4 * 4000 * 11
    m2 = hardware_cost("mask2", "sg", width=4000)
    assert (m2.line_buffers, m2.latency_rows, m2.latency_pixels, m2.window) == (5, 3, 3,
                                                                                 (5, 6, 11))
    assert m2.notes and "line buffer" in m2.notes[0]
    rows = hardware_cost("rows", "bi", width=640, bit_depth=10)       # period 6
    assert rows.line_buffers == 2 + 5 and rows.line_buffer_bits == 7 * 640 * 10


def test_bram18_mapping():
    assert bram18_blocks(4000, 11) == 3          # 4K x 4, three wide
    assert bram18_blocks(1024, 18) == 1 and bram18_blocks(1025, 18) == 2
    assert bram18_blocks(3840, 16) == 4
    c = hardware_cost("mask1", "bilinear", width=3840, bit_depth=16)
    assert c.line_buffer_bram18 == 4 * 4
    assert bram18_blocks(0, 16) == 0 and bram18_blocks(np.int64(1024), 18) == 1


@pytest.mark.parametrize("depth,exc,match", [
    (float("inf"), TypeError, "depth: expected an integer, got inf"),
    (float("nan"), TypeError, "depth: expected an integer, got nan"),
    ("a", TypeError, "depth: expected an integer, got 'a'"),
    (2.5, TypeError, "depth: expected an integer, got 2.5"),
    (-1, ValueError, "depth: expected an integer >= 0"),
    (2**41, ValueError, "depth: expected an integer >= 0 and <= ")])
def test_bram18_blocks_checks_its_sizes(depth, exc, match):
    with pytest.raises(exc, match="^" + re.escape(match)):
        bram18_blocks(depth, 5)
    with pytest.raises(exc, match="^" + re.escape(match.replace("depth", "width"))):
        bram18_blocks(5, depth)


def test_operators_follow_the_plan():
    """Counts read from the plans: the differences, beta's pairs, one reciprocal per
    candidate plus sigma and the normalisation, one exponential per group with differences."""
    for pattern in ("mask1", "mask2"):
        _, plans = build_plans(rz.get_pattern(pattern), "sg")
        c = hardware_cost(pattern, "sg")
        for p in plans:
            group = "green" if int(p["target"]) == 1 else "red/blue"
            ops = c.ops[group]
            nc = int(p["n_cand"])
            combined = bool(p["use_ab"])
            assert ops["abs"] == int(p["n_pairs"]) + combined * nc * (nc - 1) // 2
            assert ops["recip_lookup"] == 1 + 1 + combined * (nc + 1)
            assert ops["exp_lookup"] == 8 + 4 * combined
    bi = hardware_cost("mask1", "bi")
    assert "exp" not in bi.tables and bi.ops["green"]["recip_lookup"] == 4 + 1
    lin = hardware_cost("mask2", "bilinear")
    assert not lin.tables and not lin.multipliers() and lin.dsp48() == 0


def test_tables_and_totals():
    cfg = FixedPointConfig(exp="table", exp_table_size=64, exp_bits=12, recip="pwl",
                           recip_table_size=32, recip_bits=14)
    c = hardware_cost("mask2", "sg", fixed_point=cfg)
    e, r = c.tables["exp"], c.tables["recip"]
    assert (e["entries"], e["bits"], e["copies"]) == (64, 12, math.ceil(e["reads_per_site"] / 2))
    assert (r["entries"], r["bits"], r["copies"]) == (33, 15, r["reads_per_site"])
    assert c.table_bits == e["total_bits"] + r["total_bits"]
    assert c.total_bits == c.line_buffer_bits + c.table_bits + c.datapath_bits
    wider = hardware_cost("mask2", "sg", fixed_point=cfg.replace(weight_bits=cfg.weight_bits + 4))
    assert wider.datapath_bits > c.datapath_bits and wider.table_bits == c.table_bits
    d = c.as_dict()
    assert d["bits"]["total"] == c.total_bits and d["registers"]["weight"] == cfg.weight_bits


def test_bad_arguments_name_the_parameter():
    with pytest.raises(ValueError, match="method: expected one of 'bilinear'"):
        hardware_cost("mask1", "z_guided")
    with pytest.raises(ValueError, match="width: expected an integer >= 1 and <= 16384"):
        hardware_cost("mask1", "sg", width=20000)
    with pytest.raises(ValueError, match="register_bits: the register"):
        hardware_cost("mask2", "sg", bit_depth=16, fixed_point={"register_bits": 20})


@pytest.mark.parametrize("method", ["bilinear", "bi", "edi_central", "edi_line", "sg",
                                    "learned"])
def test_the_datapath_holds_every_operator_of_a_plan(method):
    """Operators of one plan that share a stage and a kind add up (they run at once): Mask1 has
    one plan, so its datapath holds exactly its operations per site. They had been merged by
    their maximum (Mask1 SG: 21 multipliers for 30 per site, 21 DSP48E2 for 30)."""
    from collections import Counter

    c = hardware_cost("mask1", method, width=64)
    units = Counter()
    for u in c.units:
        units[u.kind] += u.count
    (ops,) = c.ops.values()
    assert dict(units) == {k: n for k, n in ops.items() if k != "rom_read"}


@pytest.mark.parametrize("method", ["bi", "edi_line", "sg", "learned"])
def test_a_shared_datapath_holds_each_plans_operators(method):
    """Mask2's four plans share one datapath: it holds at least every plan's operators of each
    kind, and as many exponential lookups as its table serves per site."""
    from collections import Counter

    c = hardware_cost("mask2", method, width=64)
    units = Counter()
    for u in c.units:
        units[u.kind] += u.count
    for ops in c.ops.values():
        for kind, n in ops.items():
            if kind != "rom_read":
                assert units[kind] >= n, (kind, units[kind], n)
    if "exp" in c.tables:
        assert units["exp_lookup"] == c.tables["exp"]["reads_per_site"]


#: a value of every field other than its default
_OTHER = {"exp": "table", "exp_table_size": 8, "exp_bits": 12, "exp_range_bits": 5,
          "recip": "table", "recip_table_size": 64, "recip_bits": 14, "ratio_bits": 10,
          "sigma_bits": 2, "alpha_bits": 10, "weight_bits": 17, "hash_norm_bits": 19,
          "hash_bits": 17, "hash_const_bits": 15, "tap_bits": 16}


@pytest.mark.parametrize("method", ["bilinear", "bi", "edi_central", "edi_line", "sg",
                                    "learned"])
def test_fields_used_are_those_that_reach_the_datapath(method, rng):
    """FIELDS_USED (what `rgbz-fast hardware --fixed-point` and its sweep take): a field
    outside it changes neither the cost nor a bit of the result; one inside it changes the
    cost (register_bits, a bound, is in every set). hardware_cost refuses a field outside it
    named in a mapping (round 25, PARITY p03: it had recorded it as applied); a
    FixedPointConfig object, one design's configuration, may carry other methods' fields."""
    import dataclasses

    import rgbz_fast as rz
    from rgbz_fast.hardware import FIELDS_USED, FixedPointConfig

    base = FixedPointConfig()
    data = rng.integers(0, 2048, (24, 28)).astype(np.uint16)
    for field, value in _OTHER.items():
        cfg = dataclasses.replace(base, **{field: value})
        if field not in FIELDS_USED[method]:
            # named in a mapping, as the command line's --fixed-point names it: refused
            with pytest.raises(ValueError, match=rf"^fixed_point: {field} does not reach "
                                                 rf"{method}'s datapath"):
                hardware_cost("mask1", method, fixed_point={field: value})
            with pytest.raises(ValueError, match=rf"^fixed_point: {field} does not reach"):
                rz.reconstruct(data, method, pattern="mask1", precision="fixed",
                               fixed_point={field: value})
        costs = [(c.table_bits, c.datapath_bits, c.registers) for c in
                 (hardware_cost(p, method, fixed_point=f) for p in ("mask1", "mask2")
                  for f in (base, cfg))]
        changed = costs[0] != costs[1] or costs[2] != costs[3]
        if field in FIELDS_USED[method]:
            assert changed, field
            continue
        assert not changed, field
        for p in ("mask1", "mask2"):
            a, b = (rz.reconstruct(data, method, pattern=p, precision="fixed", fixed_point=f)
                    for f in (base, cfg))
            assert np.array_equal(a, b), (field, p)


def test_fixed_point_with_a_float_precision_is_refused():
    """Round 25 (PARITY p04): fixed_point named for a float run (the keyword, or a params
    mapping) ran the float kernels and ignored it. A ReconstructParams object carrying a
    design's configuration into a float reference run is taken (the hardware report's
    float64 reference does that), and hardware_cost, always fixed-point, takes
    params={"fixed_point": ...} as its docstring says (the review's r01, r06)."""
    import rgbz_fast as rz
    from rgbz_fast.reconstruction import ReconstructParams

    data = np.zeros((16, 16), np.uint16)
    for precision in ("float32", "float64"):
        with pytest.raises(ValueError, match=rf"^fixed_point: the fixed-point model's widths "
                                             rf"and tables \(precision='fixed'\); "
                                             rf"precision='{precision}' runs the float"):
            rz.reconstruct(data, "sg", pattern="mask1", precision=precision,
                           fixed_point={"exp_bits": 6})
        with pytest.raises(ValueError, match=r"^fixed_point: "):
            rz.reconstruct(data, "sg", pattern="mask1",
                           params={"precision": precision, "fixed_point": {"exp_bits": 6}})
        design = ReconstructParams(precision="fixed", fixed_point={"exp_bits": 6})
        rz.reconstruct(data, "sg", pattern="mask1", params=design, precision=precision)
    assert hardware_cost("mask1", "sg", params={"fixed_point": {"recip_bits": 10}}).table_bits
    # named through params, in any case of the method's name, in any Mapping: checked too
    from types import MappingProxyType
    for call in (lambda: hardware_cost("mask1", "sg",
                                       params={"fixed_point": {"hash_bits": 8}}),
                 lambda: hardware_cost("mask1", "sg",
                                       fixed_point=MappingProxyType({"hash_bits": 8})),
                 lambda: rz.reconstruct(data, "SG", pattern="mask1", precision="fixed",
                                        fixed_point={"hash_bits": 8}),
                 lambda: rz.reconstruct(data, "sg", pattern="mask1", params={
                     "precision": "fixed", "fixed_point": {"hash_bits": 8}})):
        with pytest.raises(ValueError, match=r"^fixed_point: hash_bits does not reach sg's"):
            call()


def test_dsp48_puts_each_multipliers_operands_on_the_cheaper_ports():
    """H86: a multiplier's wider operand always went to the 27-bit port; 37 x 19 is 2 x 2
    slices that way and 2 x 1 the other (SG at 16 bits: 33 -> 32 on Mask1, 109 -> 108 on
    Mask2)."""
    from rgbz_fast.hardware import FixedPointConfig, hardware_cost

    cfg = FixedPointConfig.for_bit_depth(16)
    for pattern, want in (("mask1", 32), ("mask2", 108)):
        c = hardware_cost(pattern, "sg", width=3840, bit_depth=16, fixed_point=cfg)
        assert c.dsp48() == want
        assert c.dsp48() == sum(n * min(-(-a // 27) * -(-b // 18), -(-b // 27) * -(-a // 18))
                                for (a, b), n in c.multipliers().items())


def test_by_kind_refuses_a_kind_that_is_none():
    """Round 25 (API10): by_kind("adder") returned {}, which read as "no adder"; the kinds
    are KINDS, and every unit's kind is one of them."""
    from rgbz_fast.hardware._cost import KINDS

    cost = hardware_cost("mask1", "sg")
    assert {u.kind for u in cost.units} <= set(KINDS)
    assert cost.by_kind("add") == cost.as_dict()["adders"] and cost.by_kind("add")
    with pytest.raises(ValueError, match=r"^kind: 'adder' is not a kind of operator \(expected "
                                         r"one of sub, abs, add, "):
        cost.by_kind("adder")
