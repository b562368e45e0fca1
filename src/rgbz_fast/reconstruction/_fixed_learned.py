"""The fixed-point learned reconstruction (``method="learned"``, ``precision="fixed"``).

The C streaming model (csrc/hw_learned.c) reads the filters' geometry (taps and
hash pairs, as the float kernel does) and the integer constants built here from
the filters and a :class:`FixedPointConfig`: the constants round(2^N / n) of
the hash means, the strength thresholds as integers of the energy T (exact: T
is an integer, so ``T > 4 2^N thr`` is ``T > floor(4 2^N thr)``), the
coherence (squared) and spread thresholds with ``hash_const_bits`` fractional
bits, and the weights as ``tap_bits``-bit signed integers with the most
fractional bits that hold them all. :func:`learned_registers` derives the
worst-case width of every register from the filters, the bit depth and the
configuration: the widths the cost model reports and the check that none
outgrows ``register_bits``. csrc/hw_learned.h and docs/guide/hardware.md
specify the datapath.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from .. import _kernels
from ._fixed import Register
from ._fixed_config import FixedPointConfig

__all__ = ["HWL_CONFIG_DTYPE", "quantise_learned", "learned_registers", "run_fixed_learned",
           "check_learned_widths", "HWL_LIMITS"]

HWL_CONFIG_DTYPE = np.dtype([(name, "<i8") for name in (
    "bit_depth", "tap_frac", "hash_bits", "const_bits", "cos_q", "sin_q", "pad0", "pad1")])
_LAYOUT = _kernels.hwl_layout()
HWL_LIMITS = {"max_width": _LAYOUT[2], "max_period": _LAYOUT[3], "max_radius": _LAYOUT[4]}
if _LAYOUT[0] != HWL_CONFIG_DTYPE.itemsize:
    raise ImportError(f"rgbz_fast: the compiled rgbz_hwl_config size {_LAYOUT[0]} differs "
                      f"from the Python one; rebuild the package")
_COS, _SIN = math.cos(math.pi / 8), math.sin(math.pi / 8)


def _round(x):
    """Round half up of float64 values, as int64."""
    return np.floor(np.asarray(x, np.float64) + 0.5).astype(np.int64)


def tap_fraction(weights, tap_bits):
    """The most fractional bits F (0 .. 40) with every round(w 2^F) within a signed
    ``tap_bits``-bit word; ValueError naming ``tap_bits`` when even F = 0 does not hold them."""
    wmax = float(np.abs(weights).max()) if weights.size else 0.0
    lim = (1 << (tap_bits - 1)) - 1
    for F in range(40, -1, -1):
        if np.floor(wmax * 2.0 ** F + 0.5) <= lim:
            return F
    need = int(np.floor(wmax + 0.5)).bit_length() + 1
    raise ValueError(f"tap_bits: a weight of {wmax:g} needs {need} signed bits; got "
                     f"tap_bits={tap_bits}")


@lru_cache(maxsize=32)
def quantise_learned(filters, config, bit_depth):
    """The integer constants of the fixed model: a dict of the arrays of
    :func:`rgbz_fast._kernels.learned_fixed` (geometry, ``cfg`` bytes, ``knorm``,
    ``kcol``, ``str_q``, ``coh_q``, ``spr_q``, ``wq``) and ``tap_frac``."""
    g = filters.geometry
    n_ph, nb, nt = filters.weights.shape
    N, K = config.hash_norm_bits, config.hash_const_bits
    ka = filters.kernel_arrays(bit_depth)
    knorm = np.zeros((n_ph, 4), np.int64)
    kcol = np.zeros((n_ph, 3), np.int64)
    for k, ph in enumerate(g):
        knorm[k] = [int(np.floor(2.0 ** N / len(pp) + 0.5)) for pp in ph["pairs"]]
        kcol[k] = [int(np.floor(2.0 ** N / n + 0.5)) for n in ph["colour_pairs"]]
    s_thr, c_thr, k_thr = filters.thresholds(bit_depth)
    # exact (a power of two), then held within T's range [0, Tmax]: a threshold outside it
    # decides the same (T >= 0 exceeds a negative one, never one at or above Tmax)
    top2 = ((1 << bit_depth) - 1) ** 2
    E = ka["n_pairs"].astype(np.int64) * top2 * knorm
    tmax = int((2 * (E[:, 0] + E[:, 1]) + E[:, 2] + E[:, 3]).max())
    str_q = np.clip(np.floor(s_thr * (4.0 * 2.0 ** N)), -1, tmax).astype(np.int64)
    coh_q = _round((c_thr ** 2) * 2.0 ** K)
    spr_q = _round(k_thr * 2.0 ** K)
    F = tap_fraction(filters.weights, config.tap_bits)
    wq = np.ascontiguousarray(_round(filters.weights * 2.0 ** F).astype(np.int32))
    cfg = np.zeros((), HWL_CONFIG_DTYPE)
    for name, v in dict(bit_depth=bit_depth, tap_frac=F, hash_bits=config.hash_bits,
                        const_bits=K, cos_q=int(np.floor(_COS * 2.0 ** K + 0.5)),
                        sin_q=int(np.floor(_SIN * 2.0 ** K + 0.5))).items():
        cfg[name] = v

    def flat(a):
        a = np.ascontiguousarray(a.reshape(-1), np.int64)
        return a if a.size else np.zeros(1, np.int64)

    out = dict(n_taps=ka["n_taps"], tap_dy=ka["tap_dy"], tap_dx=ka["tap_dx"],
               n_pairs=ka["n_pairs"], pair_a=ka["pair_a"], pair_b=ka["pair_b"],
               pair_col=ka["pair_col"], n_str=filters.n_strength, n_coh=filters.n_coherence,
               n_spr=filters.n_spread, radius=filters.radius,
               cfg=cfg.reshape(1).view(np.uint8).reshape(-1), knorm=knorm, kcol=kcol,
               str_q=flat(str_q), coh_q=flat(coh_q), spr_q=flat(spr_q), wq=wq)
    for a in out.values():
        if isinstance(a, np.ndarray):
            a.setflags(write=False)
    return {"arrays": out, "tap_frac": F}


def learned_registers(filters, config, bit_depth):
    """Every register of the learned datapath with its worst case (a list of
    :class:`~rgbz_fast.reconstruction._fixed.Register`), from the filters, the bit depth
    and the configuration (hw_learned.h's steps)."""
    q = quantise_learned(filters, config, bit_depth)
    a = q["arrays"]
    top = (1 << bit_depth) - 1
    sq = top * top
    H, K = config.hash_bits, config.hash_const_bits
    n_pairs = a["n_pairs"].astype(np.int64)
    colour_pairs = np.array([ph["colour_pairs"] for ph in filters.geometry], np.int64)
    E = n_pairs * sq * a["knorm"]                    # per phase and direction
    Ec = colour_pairs * sq * a["kcol"]
    Tmax = int((2 * (E[:, 0] + E[:, 1]) + E[:, 2] + E[:, 3]).max())
    cos_q = int(np.frombuffer(a["cfg"].tobytes(), HWL_CONFIG_DTYPE)["cos_q"][0])
    amax = 2 << H                                     # |a|, |b| <= 2 t + 1 <= 2^(H + 1)
    coh = int(a["coh_q"].max()) if filters.n_coherence > 1 else 0
    spr = int(a["spr_q"].max()) if filters.n_spread > 1 else 0
    wq = a["wq"].astype(np.int64)
    absw = np.abs(wq).sum(axis=2).max()
    acc = int(absw) * top + (1 << max(q["tap_frac"] - 1, 0))
    regs = [
        Register("diff", top, True, "v_a - v_b of a hash pair"),
        Register("square", sq, False, "(v_a - v_b)^2"),
        Register("dir_sum", int(n_pairs.max()) * sq, False, "S_d: a direction's sum of squares"),
        Register("energy", int(E.max()), False, "E_d = S_d round(2^N / n_d)",
                 ("hash_norm_bits",)),
        Register("structure", Tmax, False, "T = 2 (E_h + E_v) + E_d1 + E_d2",
                 ("hash_norm_bits",)),
        Register("structure_difference", 2 * Tmax, True,
                 "A = 4 (E_h - E_v), B = 2 (E_d1 - E_d2)", ("hash_norm_bits",)),
        Register("strength_threshold", Tmax, False, "the strength thresholds, in T's units",
                 ("hash_norm_bits",)),
        Register("hash_term", amax, True, "a, b, t after the normalising shift",
                 ("hash_bits",)),
        Register("rotation", 2 * cos_q * amax, True, "cos a - sin b, sin a + cos b",
                 ("hash_bits", "hash_const_bits")),
    ]
    if filters.n_coherence > 1:
        regs += [Register("coherence_lhs", (2 * amax * amax) << K, False,
                          "(a^2 + b^2) 2^const_bits", ("hash_bits", "hash_const_bits")),
                 Register("coherence_rhs", coh * (1 << (2 * H)), False,
                          "the coherence threshold times t^2", ("hash_bits", "hash_const_bits"))]
    if filters.n_spread > 1:
        regs += [Register("colour_sum", int(colour_pairs.max()) * sq, False,
                          "S_c: a colour's sum of squares"),
                 Register("colour_energy", int(Ec.max()), False, "E_c = S_c round(2^N / n_c)",
                          ("hash_norm_bits",)),
                 Register("spread_lhs", ((1 << H) - 1) << K, False,
                          "the largest colour energy, normalised, times 2^const_bits",
                          ("hash_bits", "hash_const_bits")),
                 Register("spread_rhs", spr * ((1 << H) - 1), False,
                          "the spread threshold times the smallest colour energy",
                          ("hash_bits", "hash_const_bits"))]
    regs += [Register("tap", int(np.abs(wq).max()), True, "a quantised filter weight",
                      ("tap_bits",)),
             Register("product", int(np.abs(wq).max()) * top, True, "weight x pixel",
                      ("tap_bits",)),
             Register("accumulator", acc, True, "the dot product, plus the rounding half",
                      ("tap_bits",))]
    return regs


def check_learned_widths(filters, config, bit_depth):
    """ValueError naming ``register_bits`` (and what drives it) for a register that outgrows it."""
    for r in learned_registers(filters, config, bit_depth):
        if r.bits > config.register_bits:
            drivers = ", ".join(f"{f}={getattr(config, f)}" for f in r.fields)
            raise ValueError(
                f"register_bits: the register {r.name} ({r.what}) needs {r.bits} bits for "
                f"{bit_depth}-bit frames with 'learned' on {filters.pattern.name!r}"
                f"{' and ' + drivers if drivers else ''}, more than register_bits="
                f"{config.register_bits}" + (f"; lower {' or '.join(r.fields)}" if r.fields
                                             else ""))


def check_learned_call(filters, pattern):
    """What the learned fixed model holds, refused by name: the filters' radius and the
    pattern's periods within its static buffers."""
    if filters.radius > HWL_LIMITS["max_radius"]:
        raise ValueError(f"filters: the fixed-point model holds windows of radius up to "
                         f"{HWL_LIMITS['max_radius']}; got {filters.radius}")
    if max(pattern.period) > HWL_LIMITS["max_period"]:
        raise ValueError(f"pattern: the fixed-point model holds periods up to "
                         f"{HWL_LIMITS['max_period']} (its look-ahead); {pattern.name!r} has "
                         f"{pattern.period}")


def run_fixed_learned(src, out, pattern, filters, config, bit_depth):
    """The learned fixed-point streaming model over ``src`` (uint8/uint16) into ``out``."""
    config = config if config is not None else FixedPointConfig()
    check_learned_call(filters, pattern)
    check_learned_widths(filters, config, bit_depth)
    a = quantise_learned(filters, config, bit_depth)["arrays"]
    P, Q = pattern.period
    phase_map = np.full(P * Q, -1, np.int32)
    for k, ph in enumerate(filters.geometry):
        r, c = ph["rc"]
        phase_map[r * Q + c] = k
    state = np.empty(_LAYOUT[1], np.uint8)
    _kernels.learned_fixed(src, out, P, Q, phase_map, maxval=float((1 << bit_depth) - 1),
                           state=state, **a)
    return out
