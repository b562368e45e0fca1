"""The fixed-point reconstruction (``precision="fixed"``): plans quantised for the C model.

The C streaming model (csrc/hw_recon.c) interprets the float core's plans
(:func:`~rgbz_fast.reconstruction.build_plans`) and, per plan, the integer
constants built here: the group multipliers that turn a sum of differences into
L times its mean, eq. 7's floors as integers, alpha as a mantissa and an
exponent, eq. 19's scale factors, the constant of the exact rounded mean. The
tables (2^-u and 1/(1+f)) are built here too; the C model reads them as ROM
contents. :func:`register_widths` derives the worst-case width of every
register of the datapath from the plan, the bit depth and the configuration:
the widths the cost model reports (:mod:`rgbz_fast.hardware`) and the check
that no register outgrows ``register_bits`` (a refusal naming the field, never
a wrap-around). docs/guide/hardware.md specifies the datapath.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import _kernels
from ._fixed_config import FixedPointConfig
from ._params import warn_small_sigma
from ._plans import NGROUPS, build_plans

__all__ = ["HW_PLAN_DTYPE", "HW_CONFIG_DTYPE", "FIXED_METHODS", "ALL_FIXED_METHODS", "Register", "tables",
           "hw_constants", "register_widths", "fixed_setup", "run_fixed", "LIMITS",
           "check_fixed_call", "check_widths"]

#: the methods of the plans' fixed-point model (csrc/hw_recon.c)
FIXED_METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg")
#: every method precision "fixed" runs: the plans' and the learned filters' (csrc/hw_learned.c)
ALL_FIXED_METHODS = (*FIXED_METHODS, "learned")
_MAX_CAND = _kernels.PLAN_LIMITS["max_cand"]
_LN2 = math.log(2.0)

HW_PLAN_DTYPE = np.dtype([
    ("group_mult", "<i8", NGROUPS), ("fam_known", "<i8", 2), ("fam_rel", "<i8", 2),
    ("fam_floor", "<i8", 2), ("cand_ma", "<i8", _MAX_CAND), ("cand_ea", "<i8", _MAX_CAND),
    ("cand_svmult", "<i8", _MAX_CAND), ("sv_bits", "<i8"), ("mean_mult", "<i8"),
    ("mean_shift", "<i8"), ("pad_", "<i8"),
])
HW_CONFIG_DTYPE = np.dtype([(name, "<i8") for name in (
    "bit_depth", "exp_pwl", "exp_index_bits", "exp_bits", "exp_range_bits", "recip_pwl",
    "recip_index_bits", "recip_bits", "ratio_bits", "sigma_bits", "alpha_bits", "weight_bits",
    "cq", "tcap", "ymax", "pad_")])

#: the compiled sizes and limits: (plan, config, state bytes, max width, max period, radius,
#: max table entries)
_LAYOUT = _kernels.hw_layout()
LIMITS = {"max_width": _LAYOUT[3], "max_period": _LAYOUT[4], "radius": _LAYOUT[5]}
if (_LAYOUT[0], _LAYOUT[1]) != (HW_PLAN_DTYPE.itemsize, HW_CONFIG_DTYPE.itemsize):
    raise ImportError(f"rgbz_fast: the compiled rgbz_hw_plan/rgbz_hw_config sizes {_LAYOUT[:2]} "
                      f"differ from the Python ones; rebuild the package")


# -- tables and constants ----------------------------------------------------------------

def tables(config):
    """(exp_table, recip_table), int32: the ROM contents of the two table units.

    exp: 2^-u for u in [0, 1), ``exp_bits`` bits; ``"table"``: at the midpoints
    (j + 1/2) / size, ``"pwl"``: at the size + 1 end points j / size. recip:
    1 / (1 + f) for f in [0, 1), ``recip_bits`` bits, the same way. Values are
    round-half-up of the float64 function, the midpoint tables clamped below 2^bits.
    """
    T, W = config.exp_table_size, config.exp_bits
    if config.exp == "table":
        i = np.arange(T, dtype=np.float64)
        et = np.minimum(np.floor(2.0 ** W * np.exp2(-(i + 0.5) / T) + 0.5), 2.0 ** W - 1)
    else:
        j = np.arange(T + 1, dtype=np.float64)
        et = np.floor(2.0 ** W * np.exp2(-j / T) + 0.5)
    T, W = config.recip_table_size, config.recip_bits
    if config.recip == "table":
        i = np.arange(T, dtype=np.float64)
        rt = np.minimum(np.floor(2.0 ** W / (1.0 + (i + 0.5) / T) + 0.5), 2.0 ** W - 1)
    else:
        j = np.arange(T + 1, dtype=np.float64)
        rt = np.floor(2.0 ** W / (1.0 + j / T) + 0.5)
    return et.astype(np.int32), rt.astype(np.int32)


def _alpha(d2, bits):
    """exp(-d2 / 2) = 2^-u as (mantissa, exponent): u = d2 / (2 ln 2)."""
    u = np.float64(d2) / (2.0 * _LN2)
    e = np.floor(u)
    m = min(np.floor(2.0 ** bits * np.exp2(-(u - e)) + 0.5), 2.0 ** bits - 1)
    return int(m), int(e)


def _mean_constants(nc, bit_depth):
    """(M, s) with floor(X / d) = (X M) >> s for every X < 2^N, d = 2 nc (Granlund-Montgomery:
    s = N + ceil(log2 d), M = floor(2^s / d) + 1); X = 2 S + nc, S a sum of nc b-bit values."""
    N = (2 * nc * ((1 << bit_depth) - 1) + nc).bit_length()
    d = 2 * nc
    s = N + (d - 1).bit_length()
    return (1 << s) // d + 1, s


def _group_counts(plan):
    """Differences per group of a plan (from its pairs' group masks)."""
    counts = np.zeros(NGROUPS, np.int64)
    for i in range(int(plan["n_pairs"])):
        m = int(plan["pair_gmask"][i])
        for g in range(NGROUPS):
            counts[g] += (m >> g) & 1
    return counts


def check_sigma_bits(config, sigma_rel):
    """ValueError naming ``sigma_bits`` when it cannot hold ``sigma_rel`` to 1/256 of its value
    (the relative floor of eq. 7 is the constant round(sigma_rel 2^sigma_bits))."""
    def held(bits):
        return abs(np.floor(sigma_rel * 2.0 ** bits + 0.5) / 2.0 ** bits - sigma_rel) \
            <= sigma_rel / 256

    if sigma_rel > 0 and not held(config.sigma_bits):
        need = next((b for b in range(config.sigma_bits, 25) if held(b)), 24)
        raise ValueError(f"sigma_bits: {config.sigma_bits} fractional bits hold sigma_rel="
                         f"{sigma_rel:g} as "
                         f"{int(np.floor(sigma_rel * 2.0 ** config.sigma_bits + 0.5))}"
                         f"/2^{config.sigma_bits}; raise sigma_bits to {need} or more")


def hw_constants(plans, config, bit_depth, sigma_floor, sigma_rel):
    """The rgbz_hw_plan of every plan (HW_PLAN_DTYPE), from the plan and the configuration."""
    if any(p["use_grad"] or p["use_sg"] for p in plans):      # eq. 7 is computed
        check_sigma_bits(config, sigma_rel)
    if sigma_floor > 2.0 ** bit_depth:
        # the floor's constant is an integer of the model's registers (1e20 overflowed
        # int64); beyond the largest code every weight is already equal
        raise ValueError(f"sigma_floor: {sigma_floor:g} DN is beyond the {bit_depth}-bit "
                         f"codes the fixed-point model computes in (at most "
                         f"{2 ** bit_depth} with precision='fixed')")
    out = np.zeros(len(plans), HW_PLAN_DTYPE)
    Mg = (1 << config.exp_bits) - (config.exp == "table")
    sR = config.sigma_bits
    for i, p in enumerate(plans):
        h = out[i]
        counts = _group_counts(p)
        for f, (g0, g1) in enumerate(((0, 8), (8, NGROUPS))):
            known = [g for g in range(g0, g1) if counts[g] > 0]
            if not known:
                continue
            L = math.lcm(*(int(counts[g]) for g in known))
            for g in known:
                h["group_mult"][g] = L // int(counts[g])
            h["fam_known"][f] = len(known)
            # n sigma = max(n min, n floor, rel * sum): the mean without a division
            h["fam_rel"][f] = int(np.floor(sigma_rel * 2.0 ** sR + 0.5)) if sigma_rel > 0 else 0
            h["fam_floor"][f] = max(1, int(np.floor(sigma_floor * len(known) * L * 2.0 ** sR
                                                    + 0.5)))
        nc = int(p["n_cand"])
        ncov = []
        for k in range(nc):
            t = int(p["cand_tap"][k])
            dy, dx = int(p["tap_dy"][t]), int(p["tap_dx"][t])
            h["cand_ma"][k], h["cand_ea"][k] = _alpha(dy * dy + dx * dx, config.alpha_bits)
            ncov.append(bin(int(p["cand_sgmask"][k])).count("1"))
        if p["use_sg"] and p["sg_scaled"]:
            Lc = math.lcm(*(max(n, 1) for n in ncov))
            mult = [Lc // max(n, 1) for n in ncov]
        else:
            mult = [1] * nc
        h["cand_svmult"][:nc] = mult
        K = max(n * m for n, m in zip(ncov, mult))
        h["sv_bits"] = (K * Mg).bit_length()
        h["mean_mult"], h["mean_shift"] = _mean_constants(nc, bit_depth)
    return out


def _config_struct(config, bit_depth):
    c = np.zeros((), HW_CONFIG_DTYPE)
    Wr, Ft = config.recip_bits, config.ratio_bits
    ymax = (1 << (config.exp_range_bits + Ft)) - 1
    vals = dict(bit_depth=bit_depth, exp_pwl=int(config.exp == "pwl"),
                exp_index_bits=config.exp_index_bits, exp_bits=config.exp_bits,
                exp_range_bits=config.exp_range_bits, recip_pwl=int(config.recip == "pwl"),
                recip_index_bits=config.recip_index_bits, recip_bits=Wr, ratio_bits=Ft,
                sigma_bits=config.sigma_bits, alpha_bits=config.alpha_bits,
                weight_bits=config.weight_bits,
                cq=int(math.floor(math.sqrt(0.5 / _LN2) * 2.0 ** Wr + 0.5)),
                tcap=math.isqrt(ymax << Ft) + 1, ymax=ymax)
    for k, v in vals.items():
        c[k] = v
    return c


# -- the registers and their worst-case widths ---------------------------------------------

@dataclass(frozen=True)
class Register:
    """One register of the datapath: its name, worst-case magnitude and width in bits."""
    name: str
    bound: int
    signed: bool
    what: str
    fields: tuple = ()

    @property
    def bits(self):
        """Bits to hold every value: magnitude bits, plus one for the sign of a signed one."""
        return int(self.bound).bit_length() + int(self.signed)


def register_widths(plan, hw, config, bit_depth):
    """Every register of one plan's datapath with its worst case (a list of :class:`Register`).

    Bounds follow the datapath of docs/guide/hardware.md for b-bit inputs:
    differences < 2^b, a group sum n_g (2^b - 1), its scaled value L_f (2^b - 1),
    and so on to the quotient product of eq. 12. The integer parts come from the
    plan and ``bit_depth``; ``fields`` names the configuration fields a register
    grows with.
    """
    b = bit_depth
    top = (1 << b) - 1
    nc = int(plan["n_cand"])
    Wr, Wg, Ww, Wa, Ft, sR = (config.recip_bits, config.exp_bits, config.weight_bits,
                              config.alpha_bits, config.ratio_bits, config.sigma_bits)
    rp = config.recip == "pwl"
    Mr = (1 << Wr) if rp else (1 << Wr) - 1
    Mg = (1 << Wg) - (config.exp == "table")
    cfg = _config_struct(config, b)
    M, s = int(hw["mean_mult"]), int(hw["mean_shift"])
    regs = [Register("cand_sum", nc * top, False, "sum of the candidates (the plain mean)"),
            Register("mean_product", (2 * nc * top + nc) * M, False,
                     "(2 S + n) times the mean's constant multiplier")]
    method = int(plan["method"])
    if method == _kernels.METHODS["bilinear"]:
        return regs
    counts = _group_counts(plan)
    fams = [(0, 0, 8)] * bool(plan["use_sg"]) + [(1, 8, NGROUPS)] * bool(plan["use_grad"])
    if fams and int(plan["n_pairs"]):
        regs.append(Register("diff", top, False, "|a - b| of one pair"))
        regs.append(Register("group_sum", int(counts.max()) * top, False,
                             "sum of a group's differences"))
        # L_f = group_mult x count of any group of the family with differences
        Lmax = max([int(hw["group_mult"][g] * counts[g]) for _, g0, g1 in fams
                    for g in range(g0, g1) if counts[g]] or [1])
        nk = max(int(hw["fam_known"][f]) for f, _, _ in fams)
        rel = max(int(hw["fam_rel"][f]) for f, _, _ in fams)
        flo = max(int(hw["fam_floor"][f]) for f, _, _ in fams)
        regs += [
            Register("group_scaled", Lmax * top, False, "group sum x L_f / n_g (L_f x its mean)"),
            Register("group_total", nk * Lmax * top, False, "sum of a family's scaled groups"),
            Register("sigma", max(nk * Lmax * top << sR, flo, rel * nk * Lmax * top), False,
                     "n x sigma x L_f x 2^sigma_bits (n: the family's groups)", ("sigma_bits",)),
            Register("ratio_product", nk * Lmax * top * int(cfg["cq"]), False,
                     "scaled group x (1/sigma) x sqrt(log2(e)/2)", ("recip_bits",)),
            Register("ratio", int(cfg["tcap"]), False, "G / sigma x sqrt(log2(e)/2), saturated",
                     ("ratio_bits", "exp_range_bits")),
            Register("ratio_square", int(cfg["tcap"]) ** 2, False, "the ratio squared",
                     ("ratio_bits", "exp_range_bits")),
            Register("exponent", int(cfg["ymax"]), False, "y = ratio^2 (eq. 7's exponent)",
                     ("ratio_bits", "exp_range_bits")),
            Register("gamma", Mg, False, "mantissa of eq. 7's exp()", ("exp_bits",)),
        ]
        if config.exp == "pwl":
            fi = max(Ft - config.exp_index_bits, 0)
            regs.append(Register("exp_interp", Mg * ((1 << fi) - 1), False,
                                 "table step x fraction (pwl exp)", ("exp_bits", "ratio_bits")))
    if plan["use_sg"]:
        regs.append(Register("sg_sum", (1 << int(hw["sv_bits"])) - 1, False,
                             "eq. 19: the covering semi-gradients' gammas", ("exp_bits",)))
    recip_in = []
    if plan["use_ab"]:
        S = 1 + (nc - 1) * top
        recip_in.append(S)
        regs += [Register("beta_sum", S, False, "1 + sum |c_k - c_m| (eq. 4)"),
                 Register("alpha_beta", ((1 << Wa) - 1) * Mr, False, "alpha x beta mantissas",
                          ("alpha_bits", "recip_bits"))]
        if plan["use_grad"]:
            regs.append(Register("weight_gamma", ((1 << Ww) - 1) * Mg, False,
                                 "weight x gamma mantissas", ("weight_bits", "exp_bits")))
        if plan["use_sg"]:
            regs.append(Register("weight_sg", ((1 << Ww) - 1) * ((1 << int(hw["sv_bits"])) - 1),
                                 False, "weight x eq. 19's factor", ("weight_bits", "exp_bits")))
        wmax = (1 << Ww) - 1
    else:
        wmax = (1 << int(hw["sv_bits"])) - 1
    regs.append(Register("weight", wmax, False, "mantissa of a weight", ("weight_bits",)))
    den = nc * wmax
    num = (nc - 1) * wmax * top
    q_shift = (den.bit_length() - 1) + Wr
    regs += [Register("den", den, False, "sum of the aligned weights (eq. 12)", ("weight_bits",)),
             Register("num", num, True, "sum of weight x (c_k - c_0) (eq. 13)", ("weight_bits",)),
             Register("quotient_product", num * Mr + (1 << (q_shift - 1)), True,
                      "num x (1/den), rounded (eq. 12)", ("weight_bits", "recip_bits"))]
    recip_in.append(den)
    recip_in += [r.bound for r in regs if r.name == "sigma"]
    if rp:
        regs.append(Register("recip_interp", Mr * Mr, False, "table step x fraction (pwl 1/x)",
                             ("recip_bits",)))
    regs.append(Register("recip_in", max(recip_in), False, "the input of a reciprocal"))
    return regs


def check_widths(plans, hw, config, bit_depth, pattern_name, method):
    """ValueError naming ``register_bits`` (and what drives it) for a register that outgrows it."""
    for p, h in zip(plans, hw):
        for r in register_widths(p, h, config, bit_depth):
            if r.bits > config.register_bits:
                drivers = ", ".join(f"{f}={getattr(config, f)}" for f in r.fields)
                raise ValueError(
                    f"register_bits: the register {r.name} ({r.what}) needs {r.bits} bits for "
                    f"{bit_depth}-bit frames with {method!r} on {pattern_name!r}"
                    f"{' and ' + drivers if drivers else ''}, more than register_bits="
                    f"{config.register_bits}" + (f"; lower {' or '.join(r.fields)}" if r.fields
                                                 else ""))


# -- the call ---------------------------------------------------------------------------------

@lru_cache(maxsize=64)
def fixed_setup(pattern, method, sg_mode, config, bit_depth, sigma_floor, sigma_rel):
    """(plan_map, plans bytes, hw bytes, config struct, exp table, recip table, n_plans) of a call,
    after checking that every register fits ``config.register_bits``."""
    plan_map, plans = build_plans(pattern, method, sg_mode, "intensity")
    hw = hw_constants(plans, config, bit_depth, sigma_floor, sigma_rel)
    check_widths(plans, hw, config, bit_depth, pattern.name, method)
    et, rt = tables(config)
    arrays = (plan_map, plans.view(np.uint8).reshape(-1), hw.view(np.uint8).reshape(-1),
              _config_struct(config, bit_depth).reshape(1).view(np.uint8).reshape(-1), et, rt)
    for a in arrays:
        a.setflags(write=False)
    return arrays + (len(plans),)


def check_fixed_call(data, pattern, method):
    """What the fixed-point model takes, refused by name before any work: a method it
    models, an integer frame no wider than its line buffers, a pattern of periods <= 8."""
    if method not in ALL_FIXED_METHODS:
        raise ValueError(f"method: precision='fixed' has no model of {method!r} yet; it runs "
                         f"{', '.join(map(repr, ALL_FIXED_METHODS))}")
    if data.dtype not in (np.uint8, np.uint16):
        raise TypeError(f"frame: precision='fixed' takes integer frames (uint8 or uint16), got "
                        f"{data.dtype}")
    if data.shape[1] > LIMITS["max_width"]:
        raise ValueError(f"frame: the fixed-point model's line buffers hold rows of at most "
                         f"{LIMITS['max_width']} pixels; got {data.shape[1]}")
    if max(pattern.period) > LIMITS["max_period"]:
        raise ValueError(f"pattern: the fixed-point model holds periods up to "
                         f"{LIMITS['max_period']} (its look-ahead); {pattern.name!r} has "
                         f"{pattern.period}")


def run_fixed(src, out, pattern, method, params, bit_depth):
    """The fixed-point streaming model over ``src`` (uint8/uint16, checked) into ``out``."""
    config = params.fixed_point if params.fixed_point is not None else FixedPointConfig()
    plan_map, plans, hw, cfg, et, rt, n = fixed_setup(
        pattern, method, params.sg_mode, config, bit_depth, params.sigma_floor,
        params.sigma_rel)
    warn_small_sigma(params, method)
    P, Q = pattern.period
    state = np.empty(_LAYOUT[2], np.uint8)
    _kernels.reconstruct_fixed(src, out, P, Q, plan_map, plans, n, hw, cfg, et, rt, state)
    return out
