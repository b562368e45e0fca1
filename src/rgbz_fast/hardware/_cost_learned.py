"""What the learned filters' fixed-point streaming model costs in silicon (csrc/hw_learned.c).

The datapath of csrc/hw_learned.h, enumerated unit by unit for each phase of the
filters (one per Z position of the tile) with the widths
:func:`~rgbz_fast.reconstruction._fixed_learned.learned_registers` declares; the
design holds, per unit, the largest count and width over the phases (they are
different pixels in time). The filter ROM holds buckets x taps weights of
``tap_bits`` each per phase, read as one word (a bucket's taps) per site; the
hash constants (1/n, the quantised thresholds) are a small ROM beside it.
"""

from __future__ import annotations

import math

from ..reconstruction._fixed_learned import (check_learned_call, check_learned_widths,
                                             learned_registers, quantise_learned)
from ._cost import HardwareCost, Unit, bram18_blocks, design_units, merge_plan_units

__all__ = ["learned_cost"]


def _lg(n):
    return math.ceil(math.log2(n)) if n > 1 else 0


def _phase_units(filters, k, R, config, b, q):
    """The operators of phase k's datapath and its depth (operations on the longest path)."""
    ph = filters.geometry[k]
    U = []

    def add(stage, kind, count, width, inputs=()):
        if count > 0:
            U.append(Unit(stage, kind, int(count), int(width), tuple(int(i) for i in inputs)))

    n_d = [len(pp) for pp in ph["pairs"]]
    n_c = [int(n) for n in ph["colour_pairs"]]
    ns, nc, nk = filters.n_strength, filters.n_coherence, filters.n_spread
    npairs = sum(n_d)
    add("differences", "sub", npairs, R["diff"])
    add("differences", "mul", npairs, R["square"], (R["diff"] - 1, R["diff"] - 1))
    add("direction sums", "add", sum(n - 1 for n in n_d), R["dir_sum"])
    a = q["arrays"]
    pow2 = lambda v: v & (v - 1) == 0          # noqa: E731 (a constant that is a shift)
    add("means", "cmul", sum(not pow2(int(v)) for v in a["knorm"][k]), R["energy"],
        (R["dir_sum"], config.hash_norm_bits + 1))
    add("structure", "sub", 2, R["structure_difference"])
    add("structure", "add", 3, R["structure"])
    add("strength", "cmp", ns - 1, R["structure"])
    add("normalisation", "lzd", 1, max(R["structure"].bit_length(), 1), (R["structure"],))
    add("normalisation", "shift", 3, R["hash_term"], (R["structure"],))
    add("orientation", "cmul", 4, R["rotation"], (R["hash_term"], config.hash_const_bits))
    add("orientation", "add", 2, R["rotation"])
    add("orientation", "cmp", 1, R["rotation"])
    d = 2 + _lg(max(n_d)) + 1 + 1 + 2 + 2 + 3            # to the orientation's octant
    if nc > 1:
        add("coherence", "mul", 3, R["coherence_lhs"], (R["hash_term"], R["hash_term"]))
        add("coherence", "add", 1, R["coherence_lhs"])
        add("coherence", "cmul", nc - 1, R["coherence_rhs"],
            (2 * (R["hash_term"] - 2), config.hash_const_bits + 3))
        add("coherence", "cmp", nc - 1, R["coherence_lhs"])
        d = max(d, 2 + _lg(max(n_d)) + 1 + 1 + 2 + 2 + 3)
    if nk > 1:
        add("spread", "add", sum(n - 1 for n in n_c), R["colour_sum"])
        add("spread", "cmul", sum(not pow2(int(v)) for v in a["kcol"][k]), R["colour_energy"],
            (R["colour_sum"], config.hash_norm_bits + 1))
        add("spread", "cmp", 4, R["colour_energy"])
        add("spread", "lzd", 1, max(R["colour_energy"].bit_length(), 1), (R["colour_energy"],))
        add("spread", "shift", 2, R["spread_lhs"], (R["colour_energy"],))
        add("spread", "cmul", nk - 1, R["spread_rhs"], (R["spread_lhs"], config.hash_const_bits))
        add("spread", "cmp", nk - 1, R["spread_rhs"])
    nb_bits = max((filters.n_buckets - 1).bit_length(), 1)
    add("bucket", "add", 3, nb_bits)
    nt = len(ph["taps"])
    add("filter", "mul", nt, R["product"], (config.tap_bits, b))
    add("filter", "add", nt - 1, R["accumulator"])
    add("filter", "add", 1, R["accumulator"])           # the rounding half
    add("filter", "cmp", 2, b + 1)                       # the clip to [0, 2^b - 1]
    depth = d + 2 + 1 + 1 + _lg(nt) + 1 + 1               # bucket, ROM, dot, round, clip
    return U, depth


def learned_cost(pattern, filters, config, *, width, bit_depth):
    """:class:`HardwareCost` of the learned fixed model (``filters`` already fitted to
    ``pattern``)."""
    check_learned_call(filters, pattern)
    check_learned_widths(filters, config, bit_depth)
    b = bit_depth
    q = quantise_learned(filters, config, b)
    R = {r.name: r.bits for r in learned_registers(filters, config, b)}
    P, Q = pattern.period
    r = filters.radius
    A, Ax = max(r, P - 1), max(r, Q - 1)
    units, ops, depth = {}, {}, 0
    for k, ph in enumerate(filters.geometry):
        us, dk = _phase_units(filters, k, R, config, b, q)
        depth = max(depth, dk)
        merge_plan_units(units, us)
        so = {}
        for u in us:
            so[u.kind] = so.get(u.kind, 0) + u.count
        so["rom_read"] = 1
        ops.setdefault("green" if int(ph["target"]) == 1 else "red/blue", so)
    n_ph, nb, nt = filters.weights.shape
    word = nt * config.tap_bits
    n_thr = n_ph * ((filters.n_strength - 1) + (filters.n_coherence - 1)
                    + (filters.n_spread - 1))
    thr_bits = max(R["strength_threshold"], config.hash_const_bits + 4)
    tables = {
        "filter ROM": {"mode": "rom", "entries": n_ph * nb, "bits": word, "reads_per_site": 1,
                       "copies": 1, "total_bits": n_ph * nb * word,
                       "bram18": bram18_blocks(n_ph * nb, word),
                       "what": f"{n_ph} phases x {nb} buckets x {nt} taps x "
                               f"{config.tap_bits} bits (fraction {q['tap_frac']} bits)"},
        "hash constants": {"mode": "rom", "entries": n_thr + 7 * n_ph, "bits": thr_bits,
                           "reads_per_site": 1, "copies": 1,
                           "total_bits": (n_thr + 7 * n_ph) * thr_bits, "bram18": 0,
                           "what": "per phase: 4 + 3 constants round(2^N / n) and the "
                                   "quantised thresholds (registers)"},
    }
    nlb = r + A
    notes = [f"filter taps: {config.tap_bits}-bit signed words with {q['tap_frac']} fractional "
             "bits (the most that hold every weight of these filters)"]
    if A > r:
        notes.append(f"the border rule (taps moved by whole periods) reaches {A} rows below the "
                     f"top row: {A - r} line buffer(s) more than the window needs")
    return HardwareCost(
        pattern=pattern.name, method="learned", width=width, bit_depth=b, config=config,
        line_buffers=nlb, line_buffer_bits=nlb * width * b,
        line_buffer_bram18=nlb * bram18_blocks(width, b),
        window=(2 * r + 1, r + Ax + 1, b), latency_rows=A, latency_pixels=Ax, depth=depth,
        units=design_units(units),
        tables=tables, registers={k: v for k, v in R.items()}, ops=ops, notes=notes)
