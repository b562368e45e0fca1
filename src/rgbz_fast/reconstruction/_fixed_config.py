"""The widths and tables of the fixed-point reconstruction: :class:`FixedPointConfig`."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import asdict, dataclass, fields, replace

from .._validate import check_bit_depth, check_choice, check_int, merge_params

__all__ = ["FixedPointConfig", "TABLE_MODES", "FIELDS_USED", "check_fields_used",
           "named_fixed_point"]

#: how a table is read: the nearest entry (midpoint values), or linear interpolation between
#: two entries (piecewise-linear, one multiplier more per lookup)
TABLE_MODES = ("table", "pwl")

#: the inclusive bounds of every integer field (the model's registers are 64-bit integers)
_BOUNDS = {
    "exp_table_size": (2, 1 << 16),
    "exp_bits": (2, 30),
    "exp_range_bits": (1, 10),
    "recip_table_size": (2, 1 << 16),
    "recip_bits": (2, 30),
    "ratio_bits": (0, 24),
    "sigma_bits": (0, 24),
    "alpha_bits": (2, 30),
    "weight_bits": (2, 40),
    "register_bits": (8, 63),
    "hash_norm_bits": (1, 24),
    "hash_bits": (4, 30),
    "hash_const_bits": (2, 30),
    "tap_bits": (4, 32),
}


@dataclass(frozen=True)
class FixedPointConfig:
    """The widths and table sizes of the fixed-point model (``precision="fixed"``).

    The defaults are the narrowest configuration found to keep, with a margin,
    the model within 1 LSB of float64 at >= 99.9 % of the Z sites and within
    0.05 dB of its CFA PSNR, for every method on Mask1 and Mask2 (learned: every
    Bayer phase of both) with 11-bit frames, at the default ``sigma_rel=0.5``
    (a smaller relative floor of eq. 7, the paper's 0 among them, takes G / sigma
    beyond the exponent's range: EDICentral on Mask1 then moves about a quarter of
    the Z sites of Kodak by more than 1 LSB, and ``reconstruct`` warns)
    (tools/hardware_default.py, with
    ``--method learned`` for the learned filters' fields;
    docs/reports/hardware.md gives the searches and the numbers). Wider frames keep the relative error, so their
    error in LSB grows with the range: :meth:`for_bit_depth` widens the
    defaults for them.

    Every field is checked when the object is made; whether the widths fit a
    given plan and bit depth (no register wider than ``register_bits``) is
    checked when a frame is reconstructed, before any pixel is read. The
    datapath is specified in docs/guide/hardware.md; its integer parts (the
    sums of differences, the weighted sums) take the widths their worst case
    needs, derived from the plan and the bit depth: the fields below set the
    fractional precision and the tables.

    Parameters
    ----------
    exp : {"table", "pwl"}
        How eq. 7's exponential is read from its table: ``"table"`` the
        nearest entry, ``"pwl"`` linear interpolation between two entries.
        The table holds 2^-u for u in [0, 1) (the integer part of the
        exponent is a shift).
    exp_table_size : int
        Entries of the exponential table: a power of two, 2 .. 65536.
    exp_bits : int
        Bits of the exponential's mantissa (the gammas), 2 .. 30.
    exp_range_bits : int
        Integer bits of the exponent y = r^2 log2(e) / 2 (r = gradient / sigma),
        1 .. 10: y saturates at 2^exp_range_bits (a gamma below
        2^-(2^exp_range_bits) is held there, never wrapped).
    recip : {"table", "pwl"}
        How the reciprocals (eq. 4's beta, eq. 7's 1/sigma, eq. 12's
        normalisation) are read from their table.
    recip_table_size : int
        Entries of the reciprocal table (indexed by the mantissa after the
        leading one): a power of two, 2 .. 65536.
    recip_bits : int
        Bits of a reciprocal's mantissa, 2 .. 30.
    ratio_bits : int
        Fractional bits of the scaled ratio gradient / sigma and of the
        exponent y, 0 .. 24.
    sigma_bits : int
        Fractional bits of sigma (the relative floor ``sigma_rel`` / n is a
        constant of this many fractional bits), 0 .. 24.
    alpha_bits : int
        Bits of the mantissa of the distance factor alpha (eq. 3), 2 .. 30.
    weight_bits : int
        Bits of a weight's mantissa after each product (eqs. 2, 6, 19), 2 .. 40.
    register_bits : int
        The widest register the datapath may use, 8 .. 63 (the C model holds
        every register in a 64-bit integer). A plan and bit depth whose worst
        case needs a wider one is refused, naming the register.
    hash_norm_bits : int
        ``method="learned"``: bits of the constants round(2^N / n) that turn
        the hash's sums of squared differences into means (N = this field),
        1 .. 24.
    hash_bits : int
        ``method="learned"``: bits kept of the structure terms a, b, t and of
        the colour energies after the normalising shift (their leading one
        decides it) for the orientation, coherence and spread tests, 4 .. 30.
    hash_const_bits : int
        ``method="learned"``: fractional bits of cos and sin of 22.5 degrees
        and of the quantised coherence (squared) and spread thresholds, 2 .. 30.
    tap_bits : int
        ``method="learned"``: signed width of a filter tap in the filter ROM,
        4 .. 32; its fractional bits are the most that hold every weight of
        the filters (a refit with larger weights keeps fewer).

    Examples
    --------
    >>> from rgbz_fast.reconstruction import FixedPointConfig
    >>> FixedPointConfig().exp, FixedPointConfig().exp_table_size
    ('pwl', 4)
    >>> FixedPointConfig(exp_table_size=0)
    Traceback (most recent call last):
    ...
    ValueError: exp_table_size: expected a power of two from 2 to 65536 entries, got 0
    """

    exp: str = "pwl"
    exp_table_size: int = 4
    exp_bits: int = 11
    exp_range_bits: int = 4
    recip: str = "pwl"
    recip_table_size: int = 32
    recip_bits: int = 13
    ratio_bits: int = 9
    sigma_bits: int = 1
    alpha_bits: int = 9
    weight_bits: int = 16
    register_bits: int = 63
    hash_norm_bits: int = 18
    hash_bits: int = 16
    hash_const_bits: int = 14
    tap_bits: int = 15

    def __post_init__(self):
        put = object.__setattr__
        put(self, "exp", check_choice(self.exp, TABLE_MODES, "exp"))
        put(self, "recip", check_choice(self.recip, TABLE_MODES, "recip"))
        for name, (lo, hi) in _BOUNDS.items():
            value = getattr(self, name)
            if name.endswith("_table_size"):
                v = check_int(value, name)
                if not lo <= v <= hi or v & (v - 1):
                    raise ValueError(f"{name}: expected a power of two from {lo} to {hi} "
                                     f"entries, got {value!r}")
            else:
                v = check_int(value, name, lo=lo, hi=hi)
            put(self, name, v)

    @property
    def exp_index_bits(self):
        """log2 of ``exp_table_size``: the bits of the exponent's fraction that index it."""
        return self.exp_table_size.bit_length() - 1

    @property
    def recip_index_bits(self):
        """log2 of ``recip_table_size``: the mantissa bits after the leading one that index it."""
        return self.recip_table_size.bit_length() - 1

    @classmethod
    def for_bit_depth(cls, bit_depth, **changes):
        """The defaults widened for ``bit_depth``-bit frames: beyond 11 bits, every width one bit
        more per bit and each table twice the entries per three bits begun (a piecewise-linear
        table's error falls with the square of its size); the defaults up to 11 bits.

        >>> c = FixedPointConfig.for_bit_depth(16)
        >>> c.recip_bits, c.weight_bits, c.recip_table_size
        (18, 21, 128)
        """
        extra = max(check_bit_depth(bit_depth) - 11, 0)
        base = cls()
        widths = ("exp_bits", "recip_bits", "ratio_bits", "alpha_bits", "weight_bits",
                  "tap_bits")
        tab = 1 << ((extra + 2) // 3)
        wide = {f: getattr(base, f) + extra for f in widths}
        wide.update(exp_table_size=base.exp_table_size * tab,
                    recip_table_size=base.recip_table_size * tab)
        return cls(**{**wide, **changes})

    def replace(self, **changes):
        """A copy with some fields changed (and checked)."""
        return replace(self, **changes)

    def as_dict(self):
        """The fields as a plain dict (for reports and cache keys)."""
        return asdict(self)

    @classmethod
    def field_names(cls):
        """The names of the fields of :class:`FixedPointConfig`, in order (the keys a mapping of
        them may hold)."""
        return tuple(f.name for f in fields(cls))

    @classmethod
    def build(cls, value, name="fixed_point"):
        """``value`` as a FixedPointConfig: one, a mapping of its fields, or None (the default)."""
        return merge_params(cls, value, name=name)


_PLAN_FIELDS = ("exp", "exp_table_size", "exp_bits", "exp_range_bits", "recip",
                "recip_table_size", "recip_bits", "ratio_bits", "sigma_bits", "alpha_bits",
                "weight_bits", "register_bits")
#: the FixedPointConfig fields that reach each method's datapath (the others leave its
#: result and its cost as they are: bilinear is exact, BI has no eq. 7, learned its own model);
#: register_bits bounds every register of all of them
FIELDS_USED = {
    "bilinear": ("register_bits",),
    "bi": ("recip", "recip_table_size", "recip_bits", "alpha_bits", "weight_bits",
           "register_bits"),
    "edi_central": _PLAN_FIELDS, "edi_line": _PLAN_FIELDS, "sg": _PLAN_FIELDS,
    "learned": ("hash_norm_bits", "hash_bits", "hash_const_bits", "tap_bits", "register_bits"),
}


def named_fixed_point(params, options=None):
    """The ``fixed_point`` a caller named for one call: the keyword (``options``) or the
    entry of a ``params`` mapping; None for a ReconstructParams object, which may carry a
    design's configuration into a float reference run."""
    if options and options.get("fixed_point") is not None:
        return options["fixed_point"]
    if isinstance(params, Mapping):
        return params.get("fixed_point")
    return None


def check_fields_used(method, given, name="fixed_point"):
    """A ValueError naming ``name`` when the fields a caller names (the keys of a mapping
    ``given``; a FixedPointConfig object names none: one design's configuration may carry the
    fields of other methods) include one that does not reach ``method``'s datapath
    (:data:`FIELDS_USED`): it would change nothing and be recorded as applied."""
    if not isinstance(given, Mapping) or method not in FIELDS_USED:
        return
    unused = [k for k in given if k not in FIELDS_USED[method]]
    if unused:
        raise ValueError(f"{name}: {unused[0]} does not reach {method}'s datapath (it takes "
                         f"{', '.join(FIELDS_USED[method])})")
