"""The parameters of a reconstruction: one frozen object, checked once, passed straight through."""

from __future__ import annotations

from dataclasses import asdict, dataclass, fields, replace

from .._validate import check_choice, check_number, merge_params
from ._fixed_config import FixedPointConfig
from ._z_guided import check_any_filters

__all__ = ["ReconstructParams", "PRECISIONS", "EXP_CHOICES", "SG_MODES", "DOMAINS"]

#: arithmetic of the kernels: the float core's two, and the fixed-point streaming model
PRECISIONS = ("float32", "float64", "fixed")
#: the exponential of eq. 7 ("auto": the polynomial in float32, libm in float64)
EXP_CHOICES = ("auto", "libm", "fast", "table")
SG_MODES = ("auto", "pure", "combined")
DOMAINS = ("intensity", "colour_difference")


@dataclass(frozen=True)
class ReconstructParams:
    """How :func:`rgbz_fast.reconstruct` computes (the method says what it computes).

    Every field is checked when the object is made, so a bad value fails before
    any frame is read; the object is hashable and picklable, and is what the ISP
    stage (:class:`rgbz_fast.isp.Reconstruction`), the evaluation
    (:class:`rgbz_fast.evaluation.EvalConfig`) and the command line hand to the
    kernels. ``reconstruct(frame, method, **fields)`` builds one from keyword
    arguments.

    Parameters
    ----------
    precision : {"float32", "float64", "fixed"}
        Arithmetic of the kernel. float32 is faster; float64 agrees with the
        NumPy reference to 1e-9 relative. ``"fixed"`` runs the bit-exact
        fixed-point streaming model of a hardware implementation
        (``fixed_point`` sets its widths; docs/guide/hardware.md): integer
        frames (uint8, uint16), the methods bilinear, bi, edi_central,
        edi_line, sg and learned, the intensity domain, no ``clip_level``.
    sigma_floor : float
        Absolute floor of sigma in eq. 7 (DN), used when the smallest gradient
        is 0 (a flat area): > 0.
    sigma_rel : float
        Relative floor of sigma in eq. 7, in [0, 10]: ``sigma >= sigma_rel *``
        the mean gradient of the family. ``sigma_rel=0`` is eq. 7 as printed
        (sigma = the smallest gradient, with only ``sigma_floor`` against 0):
        :meth:`paper` gives it. 0.5 is the library's choice, not the paper's:
        the bare minimum makes every weight but one vanish as soon as one
        gradient is near 0 (docs/guide/interpretation.md, docs/reports/results.md).
    edge_ratio : float
        ``edi_rows`` only: an edge is dominant when its difference is below
        ``edge_ratio`` times the vertical one (> 0).
    sg_mode : {"auto", "pure", "combined"}
        ``sg`` only: ``"pure"`` is the paper's Mask1 method (semi-gradient
        weights alone), ``"combined"`` multiplies them by the EDILine weights;
        ``"auto"`` uses pure where every candidate lies on a diagonal (Mask1)
        and combined elsewhere (Mask2).
    exp : {"auto", "libm", "fast", "table"}
        Exponential of eq. 7: the C library's, or a range-reduced polynomial
        (relative error below 3e-7 in float32, 1e-8 in float64; results below
        the normal range flush to 0) that is faster and vectorises, or
        ``"table"``, a lookup table (``precision="fixed"`` only, where it is
        what ``"auto"`` means; ``fixed_point.exp`` says whether the table is
        read at its nearest entry or interpolated). ``"auto"``
        is ``"fast"`` in float32 -- its error is of the order of float32's own
        rounding, and it changes the mean CFA PSNR on Kodak by less than
        1e-5 dB (docs/reports/tradeoff.md) -- and ``"libm"`` in float64, so
        that float64 stays the accurate reference. ``"libm"`` gives the C
        library's ``exp()`` (``expf()`` in float32) bit for bit; on x86-64
        with AVX-512F and glibc it computes those bits eight sites at a time
        (docs/guide/performance.md).
    domain : {"intensity", "colour_difference"}
        Interpolate the candidates themselves (eq. 13, the paper) or their
        differences to an estimate of the other channel(s) (eq. 5). The
        colour-difference domain is that of the weighted methods (``bi``,
        ``edi_central``, ``edi_line``, ``sg``); the others refuse it (a
        ValueError naming ``domain``).
    clip_level : float, "auto" or None
        The level at which the sensor saturates, in the frame's digital
        numbers: known pixels at or above it are *clipped*, and a difference
        between two clipped pixels is left out of the weights (docs/guide/raw.md,
        "Near clipping"). None (default): nothing is clipped. ``"auto"``: the
        level :func:`rgbz_fast.io.read_raw` recorded for a frame read from a raw
        file (:func:`rgbz_fast.io.frame_clip_level`), none for other frames.
        Not used by ``method="learned"`` (which refuses a frame that reaches it).
    filters : LearnedFilters, str, Path, sequence of them, or None
        ``method="learned"`` only: its filters (:class:`~rgbz_fast.reconstruction.LearnedFilters`
        or a file written by :meth:`~rgbz_fast.reconstruction.LearnedFilters.save`;
        files are read when the parameters are made). With several, the one
        fitted for the frame's pattern and bit depth is used; given filters of
        which none fits are a ValueError (the shipped ones are not used in their
        place). None (default):
        the filters shipped for the frame's pattern and bit depth
        (:func:`~rgbz_fast.reconstruction.default_filters`). ``method="z_guided"``
        takes :class:`~rgbz_fast.reconstruction.ZGuidedFilters` (or their
        files) from the same field; each method picks its own kind.
    fixed_point : FixedPointConfig, dict or None
        ``precision="fixed"`` only: the widths and table sizes of the
        fixed-point model (:class:`~rgbz_fast.reconstruction.FixedPointConfig`,
        or a dict of its fields). None: its defaults when the precision is
        ``"fixed"`` (read by the float precisions never).

    Examples
    --------
    >>> from rgbz_fast import ReconstructParams
    >>> p = ReconstructParams(precision="float64", sigma_rel=0)
    >>> p.exp_mode, p.replace(precision="float32").exp_mode
    ('libm', 'fast')
    >>> ReconstructParams.paper().sigma_rel
    0.0
    >>> ReconstructParams(sg_mode="purest")
    Traceback (most recent call last):
    ...
    ValueError: sg_mode: expected one of 'auto', 'pure', 'combined', got 'purest'
    """

    precision: str = "float32"
    sigma_floor: float = 1e-3
    sigma_rel: float = 0.5
    edge_ratio: float = 0.5
    sg_mode: str = "auto"
    exp: str = "auto"
    domain: str = "intensity"
    clip_level: object = None
    filters: object = None
    fixed_point: object = None

    def __post_init__(self):
        put = object.__setattr__
        put(self, "precision", check_choice(self.precision, PRECISIONS, "precision"))
        put(self, "sigma_floor", check_number(self.sigma_floor, "sigma_floor", lo=0,
                                              lo_open=True))
        put(self, "sigma_rel", check_number(self.sigma_rel, "sigma_rel", lo=0, hi=10))
        put(self, "edge_ratio", check_number(self.edge_ratio, "edge_ratio", lo=0,
                                             lo_open=True))
        put(self, "sg_mode", check_choice(self.sg_mode, SG_MODES, "sg_mode"))
        put(self, "exp", check_choice(self.exp, EXP_CHOICES, "exp"))
        put(self, "domain", check_choice(self.domain, DOMAINS, "domain"))
        put(self, "clip_level", check_clip_level(self.clip_level))
        put(self, "filters", check_any_filters(self.filters))
        if self.fixed_point is not None or self.precision == "fixed":
            put(self, "fixed_point", FixedPointConfig.build(self.fixed_point))
        if self.precision == "fixed":
            _check_fixed(self)
        elif self.exp == "table":
            raise ValueError(f"exp: 'table' is the fixed-point model's exponential "
                             f"(precision='fixed'); precision={self.precision!r} takes "
                             f"'auto', 'libm' or 'fast'")

    @classmethod
    def paper(cls, **changes):
        """The paper-literal parameters: eq. 7 as printed, sigma = the smallest gradient.

        ``sigma_rel=0``: no relative floor, only ``sigma_floor`` (1e-3 DN)
        against a zero gradient, which the paper leaves open (a flat area
        would divide by 0), in ``precision="float64"``: with sigma that small
        the weights underflow float32 (:func:`rgbz_fast.reconstruct` warns).
        Everything else at the defaults, which follow the paper (intensity
        domain, pure SG on Mask1); ``changes`` override fields. The library's
        default ``sigma_rel=0.5`` is its own choice (docs/reports/results.md
        measures both).
        """
        return cls(**{"sigma_rel": 0.0, "precision": "float64", **changes})

    @property
    def exp_mode(self):
        """The exponential a call runs: ``"auto"`` resolved by the precision; with
        ``precision="fixed"`` the table mode of ``fixed_point`` (``"table"``: its nearest
        entry, ``"pwl"``: interpolated)."""
        if self.precision == "fixed":
            return self.fixed_point.exp
        if self.exp == "auto":
            return "fast" if self.precision == "float32" else "libm"
        return self.exp

    def replace(self, **changes):
        """A copy with some fields changed (and checked)."""
        return replace(self, **changes)

    def as_dict(self):
        """The fields as a plain dict (for reports and cache keys)."""
        return asdict(self)

    @classmethod
    def field_names(cls):
        """The names of the fields of :class:`ReconstructParams`, in order (the keys a mapping of
        them may hold)."""
        return tuple(f.name for f in fields(cls))

    @classmethod
    def build(cls, params=None, options=None, *, name="params", caller="reconstruct()"):
        """``params`` (a ReconstructParams, a mapping of fields or None) with ``options`` applied.

        :func:`~rgbz_fast._validate.merge_params`, the library's one parameter
        rule: unknown option names are a TypeError naming them, as Python gives
        for an unexpected keyword argument of ``caller``.
        """
        return merge_params(cls, params, options, name=name, caller=caller,
                            what="reconstruction options")


def _check_fixed(p):
    """The options the fixed-point model has no rule for, refused by name."""
    if p.exp not in ("auto", "table"):
        raise ValueError(f"exp: precision='fixed' reads eq. 7's exponential from a table "
                         f"(fixed_point.exp); expected exp='table' or 'auto', got {p.exp!r}")
    if p.domain != "intensity":
        raise ValueError(f"domain: precision='fixed' runs the intensity domain only; got "
                         f"{p.domain!r}")
    if p.clip_level is not None:
        raise ValueError(f"clip_level: precision='fixed' has no clipped-pixel rule; expected "
                         f"None, got {p.clip_level!r}")


def check_clip_level(value):
    """``clip_level``: None, ``"auto"`` or a positive finite number (as float)."""
    if value is None or (isinstance(value, str) and value == "auto"):
        return value
    if isinstance(value, str):
        raise TypeError(f"clip_level: expected a positive number, None or 'auto', got {value!r}")
    try:
        return check_number(value, "clip_level", lo=0, lo_open=True)
    except TypeError:
        raise TypeError(f"clip_level: expected a positive number, None or 'auto', "
                        f"got {value!r}") from None


#: the relative floor of sigma (eq. 7) down to which the fixed-point model keeps its targets:
#: below it G / sigma leaves the exponent's range, the gammas float64 drives towards 0 are held
#: at 2^-(2^exp_range_bits), and the weights' ratios between them are lost
SIGMA_REL_VALIDATED = 0.5

#: the methods whose weights follow eq. 7's exponential of G / sigma
_SIGMA_METHODS = ("edi_central", "edi_line", "sg")
#: below this relative floor of sigma, float32 weights underflow (measured on Kodak: from 0.25
#: on, float32 stays within 1 DN of float64)
FLOAT32_SIGMA_REL = 0.25
#: per precision, the relative floor of sigma (eq. 7) below which its results depart from
#: float64's, and why
_SIGMA_LIMITS = {
    "float32": (FLOAT32_SIGMA_REL,
                "eq. 7's weights underflow float32 where sigma is small against the gradients, "
                "and a site whose weights all vanish takes the plain mean of its candidates (on "
                "kodim01, EDICentral on Mask1 with the paper's sigma_rel=0: 4.9 % of the Z "
                "sites more than 1 DN from float64, up to 389 DN); pass precision='float64'"),
    "fixed": (SIGMA_REL_VALIDATED,
              "eq. 7's exponent leaves the model's range (exp_range_bits) where sigma is small, "
              "and the result departs from float64 (on Kodak, EDICentral on Mask1 with the "
              "paper's sigma_rel=0: about a quarter of the Z sites by more than 1 LSB, up to "
              f"400 DN); the model's targets hold for sigma_rel >= {SIGMA_REL_VALIDATED:g}"),
}


def warn_small_sigma(params, method):
    """A RuntimeWarning, at the caller's line, when ``params`` put eq. 7's sigma below what
    their precision computes faithfully (:data:`_SIGMA_LIMITS`)."""
    limit = _SIGMA_LIMITS.get(params.precision)
    if limit is not None and method in _SIGMA_METHODS and params.sigma_rel < limit[0]:
        import warnings

        from .._validate import outside_stacklevel

        warnings.warn(f"precision={params.precision!r} with sigma_rel={params.sigma_rel:g}: "
                      f"{limit[1]}", RuntimeWarning, stacklevel=outside_stacklevel())


def check_domain(method, domain):
    """A ValueError naming ``domain`` when ``method`` does not take it: the colour-difference
    domain is the weighted methods' (bi, edi_central, edi_line, sg); the learned filters apply
    to the intensities (H60), and bilinear and edi_rows interpolate them (H75)."""
    if domain == "intensity":
        return
    if method in ("learned", "z_guided"):
        raise ValueError(f"domain: method {method!r} applies its filters to the intensities; "
                         f"domain={domain!r} applies to the weighted methods")
    if method in ("bilinear", "edi_rows"):
        raise ValueError(f"domain: method {method!r} interpolates the intensities; "
                         f"domain={domain!r} applies to the weighted methods (bi, edi_central, "
                         "edi_line, sg)")
