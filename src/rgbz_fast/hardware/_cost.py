"""What the fixed-point streaming model costs in silicon, counted from its plans.

The datapath of docs/guide/hardware.md is enumerated unit by unit for each plan
of a pattern (one plan per Z position of the tile): every subtractor, adder,
comparator, multiplier (with its two input widths), barrel shifter, priority
encoder and table lookup, each with the width :func:`register_widths` declares
for its output. A pattern's datapath serves all its plans (they are different
pixels in time), so the design holds, per operator group, the largest count
and width over the plans; the groups of one plan add up (:func:`merge_plan_units`).
The counts are analytic -- the model's per-site work does not depend on the
data -- and are the fixed model's operation counts beside the paper's Table 1.

Memory: the line buffers and the window of hw_recon.h; BRAM_18K blocks at
18 Kbit each, a buffer mapped onto the best of the block's aspect ratios
(16K x 1 .. 512 x 36). Tables: each lookup per site needs a read port at one
pixel per clock; a block RAM gives two, so a table is held ceil(reads / 2)
times ("pwl" reads two entries per lookup).
"""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass, field

from .._patterns import get_pattern
from .._validate import check_int
from ..reconstruction import ReconstructParams
from ..reconstruction._fixed import (ALL_FIXED_METHODS, LIMITS, _group_counts, fixed_setup,
                                     hw_constants, register_widths)
from ..reconstruction._fixed_config import (FIELDS_USED, FixedPointConfig, check_fields_used,
                                            named_fixed_point)
from ..reconstruction._plans import build_plans

__all__ = ["HardwareCost", "Unit", "hardware_cost", "bram18_blocks", "BRAM18_BITS", "FIELDS_USED"]

BRAM18_BITS = 18 * 1024
#: the aspect ratios of an 18 Kbit block RAM: (depth, width)
_BRAM18_SHAPES = ((16384, 1), (8192, 2), (4096, 4), (2048, 9), (1024, 18), (512, 36))
#: unit kinds, in report order
KINDS = ("sub", "abs", "add", "cmp", "mul", "cmul", "shift", "lzd", "exp_lookup",
         "recip_lookup")


def bram18_blocks(depth, width):
    """BRAM_18K blocks holding a depth x width memory (the best aspect ratio); ``depth`` words
    of ``width`` bits, integers from 0 up to 2**40 (a ValueError or TypeError naming them)."""
    depth = check_int(depth, "depth", lo=0, hi=1 << 40)
    width = check_int(width, "width", lo=0, hi=1 << 40)
    return min(math.ceil(depth / d) * math.ceil(width / w) for d, w in _BRAM18_SHAPES)


@dataclass(frozen=True)
class Unit:
    """``count`` operators of one kind in one stage of the datapath."""
    stage: str
    kind: str
    count: int
    width: int                    # output bits
    inputs: tuple = ()            # input widths (multipliers: the two operands)


@dataclass
class HardwareCost:
    """The cost of one pattern, method, configuration, width and bit depth (:func:`hardware_cost`)."""
    pattern: str
    method: str
    width: int
    bit_depth: int
    config: FixedPointConfig
    line_buffers: int
    line_buffer_bits: int
    line_buffer_bram18: int
    window: tuple                 # (rows, columns, bits)
    latency_rows: int
    latency_pixels: int
    depth: int                    # operations on the datapath's longest path
    units: list                   # the shared datapath: Unit per operator group (merge_plan_units)
    tables: dict                  # name -> {entries, bits, reads, copies, total_bits}
    registers: dict               # register name -> bits (widest over the plans)
    ops: dict                     # {"green"/"red/blue": {kind: count per site}}
    pixels_per_clock: int = 1
    notes: list = field(default_factory=list)

    @property
    def window_bits(self):
        r, c, b = self.window
        return r * c * b

    @property
    def table_bits(self):
        return sum(t["total_bits"] for t in self.tables.values())

    @property
    def datapath_bits(self):
        """Output bits of every operator (the datapath's pipeline registers) plus the window."""
        return sum(u.count * u.width for u in self.units) + self.window_bits

    @property
    def total_bits(self):
        return self.line_buffer_bits + self.table_bits + self.datapath_bits

    def multipliers(self, constant=False):
        """{(a bits, b bits): count} of the variable (or constant) multipliers."""
        out = defaultdict(int)
        for u in self.units:
            if u.kind == ("cmul" if constant else "mul"):
                out[tuple(sorted(u.inputs, reverse=True))] += u.count
        return dict(sorted(out.items(), reverse=True))

    def by_kind(self, kind):
        """{width: count} of the operators of one kind: one of :data:`KINDS` (``"sub"``,
        ``"abs"``, ``"add"``, ``"cmp"``, ``"mul"``, ``"cmul"`` (a constant multiplier),
        ``"shift"``, ``"lzd"`` (a leading-zero detector), ``"exp_lookup"``,
        ``"recip_lookup"``); another is a ValueError naming ``kind`` (``"adder"`` had
        returned {}, which read as no adder)."""
        if kind not in KINDS:
            raise ValueError(f"kind: {kind!r:.40} is not a kind of operator (expected one of "
                             f"{', '.join(KINDS)})")
        out = defaultdict(int)
        for u in self.units:
            if u.kind == kind:
                out[u.width] += u.count
        return dict(sorted(out.items(), reverse=True))

    def dsp48(self):
        """DSP48E2 slices of the variable multipliers (27 x 18 each, wider ones tiled), each
        with its operands on the two ports the way that takes fewer slices (a 37 x 19
        product is 2 x 2 one way and 2 x 1 the other: 3 slices had been 4)."""
        return sum(n * min(math.ceil(a / 27) * math.ceil(b / 18),
                           math.ceil(b / 27) * math.ceil(a / 18))
                   for (a, b), n in self.multipliers().items())

    def as_dict(self):
        """The cost as a JSON-ready dict (the ``cost`` of ``rgbz-fast hardware --json``): the
        design, line buffers, window, latency, multipliers and DSP48 slices, adders,
        subtractors and comparators by width, tables, registers, operations per site, bits
        and notes."""
        return {
            "pattern": self.pattern, "method": self.method, "width": self.width,
            "bit_depth": self.bit_depth, "config": self.config.as_dict(),
            "line_buffers": {"count": self.line_buffers, "width": self.width,
                             "bits_per_pixel": self.bit_depth, "bits": self.line_buffer_bits,
                             "bram18": self.line_buffer_bram18},
            "window": {"rows": self.window[0], "columns": self.window[1],
                       "bits": self.window_bits},
            "latency": {"rows": self.latency_rows, "pixels": self.latency_pixels,
                        "datapath_depth": self.depth},
            "pixels_per_clock": self.pixels_per_clock,
            "multipliers": {f"{a}x{b}": n for (a, b), n in self.multipliers().items()},
            "constant_multipliers": {f"{a}x{b}": n
                                     for (a, b), n in self.multipliers(True).items()},
            "dsp48": self.dsp48(),
            "adders": self.by_kind("add") | {},
            "subtractors": self.by_kind("sub"),
            "comparators": self.by_kind("cmp"),
            "tables": self.tables,
            "registers": self.registers,
            "ops_per_site": self.ops,
            "bits": {"line_buffers": self.line_buffer_bits, "tables": self.table_bits,
                     "datapath": self.datapath_bits, "total": self.total_bits},
            "notes": self.notes,
        }


def _plan_units(plan, hw, regs, config, b):
    """The operators of one plan's datapath, and its depth (operations on the longest path)."""
    R = {r.name: r.bits for r in regs}
    nc = int(plan["n_cand"])
    Wr, Wg, Ww, Wa = config.recip_bits, config.exp_bits, config.weight_bits, config.alpha_bits
    rp, ep = config.recip == "pwl", config.exp == "pwl"
    U = []

    def add(stage, kind, count, width, inputs=()):
        if count > 0:
            U.append(Unit(stage, kind, int(count), int(width), tuple(int(i) for i in inputs)))

    lg = lambda n: math.ceil(math.log2(n)) if n > 1 else 0     # noqa: E731 (adder tree depth)

    def recip(stage, n, in_bits):
        add(stage, "lzd", n, max(in_bits.bit_length(), 1), (in_bits,))
        add(stage, "shift", n, config.recip_index_bits + (Wr if rp else 0), (in_bits,))
        add(stage, "recip_lookup", n, Wr + rp)
        if rp:
            # the step between two entries is below 2^recip_bits / size: that many bits
            step = Wr - config.recip_index_bits + 1
            add(stage, "sub", n, step)
            add(stage, "mul", n, step + Wr, (step, Wr))
            add(stage, "sub", n, Wr + 1)
        return 3 + 3 * rp

    # the plain mean (bilinear, and the fallback)
    add("mean", "add", nc - 1, R["cand_sum"])
    if (2 * nc) & (2 * nc - 1):          # 1 / n by a constant multiplier; a shift for n = 2^k
        add("mean", "cmul", 1, R["mean_product"],
            (R["cand_sum"] + 1, R["mean_product"] - R["cand_sum"]))
    depth = lg(nc) + 1
    if int(plan["method"]) == 0:
        return U, depth
    counts = _group_counts(plan)
    fams = [(0, 0, 8)] * bool(plan["use_sg"]) + [(1, 8, 12)] * bool(plan["use_grad"])
    d_gamma = 0
    if fams and int(plan["n_pairs"]):
        npairs = int(plan["n_pairs"])
        add("differences", "sub", npairs, b + 1)
        add("differences", "abs", npairs, b)
        d_gamma = 2
        for f, g0, g1 in fams:
            known = [g for g in range(g0, g1) if counts[g] > 0]
            nk = len(known)
            if not nk:
                continue
            add("group sums", "add", sum(int(counts[g]) - 1 for g in known), R["group_sum"])
            add("group scaling", "cmul", sum(int(hw["group_mult"][g]) > 1 for g in known),
                R["group_scaled"], (R["group_sum"], R["group_scaled"] - R["group_sum"]))
            add("sigma", "cmp", nk - 1, R["group_scaled"])
            add("sigma", "add", nk - 1, R["group_total"])
            nb = nk.bit_length()
            # n x min (n sigma = max(n min, n floor, rel x sum): the mean without a division)
            add("sigma", "cmul", int(nk > 1), R["sigma"], (R["group_scaled"], nb))
            if int(hw["fam_rel"][f]):
                add("sigma", "cmul", 1, R["sigma"], (R["group_total"], config.sigma_bits))
            add("sigma", "cmp", 2, R["sigma"])
            d_rec = recip("sigma", 1, R["sigma"])
            add("ratio", "cmul", 1, Wr, (Wr + rp, Wr))          # x sqrt(log2(e) / 2)
            add("ratio", "cmul", int(nk > 1), Wr + nb, (Wr, nb))  # x n
            add("ratio", "mul", nk, R["ratio_product"], (R["group_scaled"], Wr + nb))
            add("ratio", "shift", nk, R["ratio"], (R["ratio_product"],))
            add("ratio", "cmp", nk, R["ratio"])
            add("exponent", "mul", nk, R["ratio_square"], (R["ratio"], R["ratio"]))
            add("exponent", "cmp", nk, R["exponent"])
            add("exponent", "exp_lookup", nk, Wg + ep)
            fi = max(config.ratio_bits - config.exp_index_bits, 0)
            if ep and fi:               # no fraction bits left: the entry itself
                step = max(Wg - config.exp_index_bits + 1, 1)    # 2^-u falls < 2^Wg / size
                add("exponent", "sub", nk, step)
                add("exponent", "mul", nk, step + fi, (step, fi))
                add("exponent", "sub", nk, Wg + 1)
            d = (max(lg(int(counts[g])) for g in known) + 1 + lg(nk) + 2 + d_rec + 1 + 1
                 + 2 + 2 + 1 + 3 * ep)
            d_gamma = max(d_gamma, 2 + d)
    d_w = 0
    ebits = R["exponent"] - config.ratio_bits + 2 if "exponent" in R else 2
    if plan["use_ab"]:
        pairs = nc * (nc - 1) // 2
        add("beta", "sub", pairs, b + 1)
        add("beta", "abs", pairs, b)
        add("beta", "add", nc * (nc - 1), R["beta_sum"])
        d_rec = recip("beta", nc, R["beta_sum"])
        add("weights", "mul", nc, Ww, (Wa, Wr + rp))
        d_w = 2 + lg(nc) + d_rec + 1
        if plan["use_grad"]:
            add("weights", "mul", nc, Ww, (Ww, Wg + ep))
        d_w = max(d_w, d_gamma) + int(bool(plan["use_grad"]))
    if plan["use_sg"]:
        svb = int(hw["sv_bits"])
        n_cov = [bin(int(plan["cand_sgmask"][k])).count("1") for k in range(nc)]
        add("semi-gradient factor", "cmp", sum(max(n - 1, 0) for n in n_cov), ebits)
        add("semi-gradient factor", "sub", sum(n_cov), ebits)
        add("semi-gradient factor", "shift", sum(n_cov), Wg + ep, (Wg + ep,))
        add("semi-gradient factor", "add", sum(max(n - 1, 0) for n in n_cov), svb)
        add("semi-gradient factor", "cmul", sum(int(hw["cand_svmult"][k]) > 1 for k in range(nc)),
            svb, (svb - 3, 3))
        d_sv = d_gamma + lg(max(n_cov)) * 2 + 2
        if plan["use_ab"]:
            add("weights", "mul", nc, Ww, (Ww, svb))
            d_w = max(d_w, d_sv) + 1
        else:
            d_w = d_sv
    # the weighted mean: exponents, alignment, sums, the reciprocal of the weight sum
    E = max(ebits + 6, 8)
    add("weights", "add", nc * (int(bool(plan["use_ab"])) + int(bool(plan["use_grad"]))
                           + int(bool(plan["use_sg"]) and bool(plan["use_ab"]))), E)
    add("alignment", "cmp", nc - 1, E)
    add("alignment", "sub", nc, E)
    add("alignment", "shift", nc, R["weight"], (R["weight"],))
    add("weighted mean", "add", nc - 1, R["den"])
    add("weighted mean", "sub", nc - 1, b + 1)
    add("weighted mean", "mul", nc - 1, R["num"], (R["weight"], b + 1))
    add("weighted mean", "add", nc - 2, R["num"])
    d_rec = recip("normalisation", 1, R["den"])
    add("normalisation", "mul", 1, R["quotient_product"], (R["num"], Wr + rp))
    add("normalisation", "add", 2, b + 2)
    add("normalisation", "cmp", 2, b + 2)
    depth = d_w + lg(nc) + 2 + 1 + lg(nc) + d_rec + 1 + 2 + 1
    return U, depth


def merge_plan_units(design, units):
    """Add one plan's operators ``units`` to ``design`` ({key: Unit}, the shared datapath).

    Within a plan each operator group (one call of the enumeration: its own widths) is its own
    unit, even when another group of the plan has the same stage and kind: they compute
    different things at once, so their counts add up. Across plans, the n-th group of a stage
    and kind keeps the largest count and widths (the plans are different pixels in time)."""
    nth = defaultdict(int)
    for u in units:
        key = (u.stage, u.kind, nth[(u.stage, u.kind)])
        nth[(u.stage, u.kind)] += 1
        old = design.get(key)
        design[key] = u if old is None else Unit(
            u.stage, u.kind, max(old.count, u.count), max(old.width, u.width),
            tuple(max(a, c) for a, c in zip(old.inputs, u.inputs)) or u.inputs)


def design_units(design):
    """The units of ``design`` (:func:`merge_plan_units`) in report order (by kind)."""
    return [design[k] for k in sorted(design, key=lambda k: KINDS.index(k[1]))]


def _site_ops(units):
    """Operation counts of one site from its operators (Table 1's categories and the rest)."""
    ops = defaultdict(int)
    for u in units:
        ops[u.kind] += u.count
    return dict(ops)


def hardware_cost(pattern="mask1", method="sg", *, width=4000, bit_depth=11, params=None,
                  fixed_point=None):
    """The silicon of the fixed-point model of ``method`` on ``pattern`` for frames ``width`` wide.

    Parameters
    ----------
    pattern, method : str or Pattern, str
        A Bayer-derived pattern (periods up to 8) and one of bilinear, bi,
        edi_central, edi_line, sg, learned (its filters: ``params.filters``, or
        the shipped ones for the pattern).
    width : int
        Pixels per row (the depth of a line buffer), 1 .. 16384.
    bit_depth : int
        Bits per pixel (a line buffer's width), 1 .. 16.
    params : ReconstructParams, optional
        The method's parameters (``sigma_floor``, ``sigma_rel``, ``sg_mode``;
        ``filters`` for learned).
    fixed_point : FixedPointConfig or dict, optional
        The widths and tables; default ``params.fixed_point`` or
        :class:`FixedPointConfig`'s defaults.

    Returns
    -------
    HardwareCost
        Line buffers (count x width x bits, BRAM_18K), the window, the latency
        (rows and pixels of look-ahead, the operations on the longest path),
        the operators (multipliers by their input widths, adders,
        comparators...), the tables (entries x bits x copies), the declared
        register widths, operations per site, and the bit totals.

    Examples
    --------
    >>> from rgbz_fast.hardware import hardware_cost
    >>> c = hardware_cost("mask1", "sg", width=4000)
    >>> c.line_buffers, c.line_buffer_bram18, c.latency_rows
    (4, 12, 2)
    """
    from .._validate import check_bit_depth, check_choice, check_int
    pattern = get_pattern(pattern)
    method = check_choice(method, ALL_FIXED_METHODS, "method")
    width = check_int(width, "width", lo=1, hi=LIMITS["max_width"])
    b = check_bit_depth(bit_depth)
    named = fixed_point if fixed_point is not None else named_fixed_point(params)
    params = ReconstructParams.build(params)
    config = FixedPointConfig.build(fixed_point if fixed_point is not None
                                    else params.fixed_point)
    check_fields_used(method, named)
    if not pattern.has_z:       # line buffers and a window had been costed for no work
        raise ValueError(f"pattern: {pattern.name!r} has no Z site; the model reconstructs "
                         "the Z sites of an RGB-Z pattern")
    P, Q = pattern.period
    if max(P, Q) > LIMITS["max_period"]:
        raise ValueError(f"pattern: the streaming model holds periods up to "
                         f"{LIMITS['max_period']}; {pattern.name!r} has {pattern.period}")
    if method == "learned":
        from ..reconstruction._learned import resolve_filters
        from ..reconstruction._z_guided import learned_only
        from ._cost_learned import learned_cost
        filters = resolve_filters(learned_only(params.filters), pattern)
        return learned_cost(pattern, filters, config, width=width, bit_depth=b)
    fixed_setup(pattern, method, params.sg_mode, config, b, params.sigma_floor,
                params.sigma_rel)          # every width checked against register_bits
    plan_map, plans = build_plans(pattern, method, params.sg_mode, "intensity")
    hw = hw_constants(plans, config, b, params.sigma_floor, params.sigma_rel)
    r = LIMITS["radius"]
    A, Ax = max(r, P - 1), max(r, Q - 1)
    units, registers, ops, depth = {}, {}, {}, 0
    reads = {"exp": 0, "recip": 0}
    for p, h in zip(plans, hw):
        regs = register_widths(p, h, config, b)
        for reg in regs:
            registers[reg.name] = max(registers.get(reg.name, 0), reg.bits)
        us, d = _plan_units(p, h, regs, config, b)
        depth = max(depth, d)
        merge_plan_units(units, us)
        so = _site_ops(us)
        group = "green" if int(p["target"]) == 1 else "red/blue"
        ops.setdefault(group, so)
        reads["exp"] = max(reads["exp"], so.get("exp_lookup", 0))
        reads["recip"] = max(reads["recip"], so.get("recip_lookup", 0))
    tables = {}
    for name, mode, size, bits in (("exp", config.exp, config.exp_table_size, config.exp_bits),
                                   ("recip", config.recip, config.recip_table_size,
                                    config.recip_bits)):
        n = reads[name]
        if not n:
            continue
        entries = size + (mode == "pwl")
        ports = n * (2 if mode == "pwl" else 1)
        copies = math.ceil(ports / 2)
        tb = bits + (mode == "pwl")
        tables[name] = {"mode": mode, "entries": entries, "bits": tb, "reads_per_site": n,
                        "copies": copies, "total_bits": entries * tb * copies,
                        "bram18": copies * bram18_blocks(entries, tb)}
    nlb = r + A
    notes = []
    if A > r:
        notes.append(f"the border rule (taps moved by whole periods) reaches {A} rows below the "
                     f"top row: {A - r} line buffer(s) more than the 5x5 window needs")
    return HardwareCost(
        pattern=pattern.name, method=method, width=width, bit_depth=b, config=config,
        line_buffers=nlb, line_buffer_bits=nlb * width * b,
        line_buffer_bram18=nlb * bram18_blocks(width, b),
        window=(2 * r + 1, r + Ax + 1, b), latency_rows=A, latency_pixels=Ax, depth=depth,
        units=design_units(units),
        tables=tables, registers=registers, ops=ops, notes=notes)
