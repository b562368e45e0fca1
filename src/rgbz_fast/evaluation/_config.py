"""What an evaluation runs: :class:`EvalConfig`, with the labels and the paper's Table 3."""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, field

from .._patterns import Pattern, check_z_patterns, get_pattern
from .._validate import (as_list, check_bit_depth, check_choice, check_entries, check_flag,
                         check_int, check_seed)
from ..isp import ColourISP, DefectCorrection, Demosaic
from ..reconstruction import METHODS, NEEDS_TOF, ReconstructParams
from ..reconstruction._learned import resolve_filters
from ..reconstruction._params import check_domain
from ..reconstruction._z_guided import learned_only, resolve_z_filters
from ..simulation import Optics

__all__ = ["EvalConfig", "IMAGE_METRICS", "ALL_METRICS", "METRIC_LABELS", "HIGHER_IS_BETTER",
           "METHOD_LABELS", "PAPER_TABLE3"]

IMAGE_METRICS = ("cpsnr", "ssim", "ms_ssim", "zipper")
ALL_METRICS = ("cfa_psnr",) + IMAGE_METRICS
METRIC_LABELS = {"cfa_psnr": "CFA PSNR (dB)", "cpsnr": "CPSNR (dB)", "ssim": "SSIM",
                 "ms_ssim": "MS-SSIM", "zipper": "Zipper (%)"}
#: the better direction of every metric
HIGHER_IS_BETTER = {"cfa_psnr": True, "cpsnr": True, "ssim": True, "ms_ssim": True,
                    "zipper": False}
METHOD_LABELS = {"bilinear": "bilinear", "bi": "BI", "edi_central": "EDICentral",
                 "edi_line": "EDILine", "sg": "SG", "edi_rows": "EDI rows (Shi)",
                 "learned": "learned", "z_guided": "z_guided"}

#: the paper's Table 3 (kodim09), for the comparison in the reports
PAPER_TABLE3 = {
    "mask1": {"bi": (24.55, 30.64, 0.9595, 0.9861, 12.493),
              "edi_central": (24.46, 30.81, 0.9607, 0.9861, 12.087),
              "edi_line": (24.97, 31.02, 0.9636, 0.9872, 11.504),
              "sg": (26.9, 32.99, 0.9751, 0.9918, 8.591)},
    "mask2": {"bi": (22.93, 26.70, 0.9163, 0.9676, 9.810),
              "edi_central": (24.83, 29.12, 0.9565, 0.9832, 5.420),
              "edi_line": (25.13, 29.13, 0.9600, 0.9835, 5.434),
              "sg": (26.13, 30.31, 0.9652, 0.9868, 5.041)},
}

_DEMOSAICS = ("malvar2004", "menon2007", "bilinear")


def _default_params():
    return ReconstructParams(precision="float64")


#: what an evaluation needs the Z sites for, said when a pattern has none
Z_WHY = "the evaluation measures what is made at the Z sites"


def _pattern_name(p):
    """A pattern of :class:`EvalConfig` as the string that names it: a string as it is, a
    Pattern as its preset name when that gives it back, else its tile."""
    if isinstance(p, str) or not isinstance(p, Pattern):
        return p
    for label in (p.name, p.tile_string):
        try:
            if get_pattern(label) == p:
                return label
        except ValueError:
            continue
    raise ValueError(f"patterns: the Pattern {p.tile_string!r} with the Bayer phase "
                     f"{p.bayer_phase!r} is not the one its tile implies; an evaluation names "
                     "its patterns by string (a preset name or a tile)")


@dataclass(frozen=True)
class EvalConfig:
    """What an evaluation runs; every field enters the cache key.

    Parameters
    ----------
    patterns, methods, metrics : tuple of str
        Patterns (``mask1``, ``mask2``, ``rows``, tile strings; a Pattern is
        kept as its preset name or its tile), reconstruction methods and metrics (``cfa_psnr``, ``cpsnr``, ``ssim``, ``ms_ssim``,
        ``zipper``); a comma-separated string is split.
    bit_depth : int
        ADC bits of the simulated raw frames (11, as in the paper), 1..16.
    noise : bool
        False: the noise-free mosaic of the image. True: the sensor model of
        :mod:`rgbz_fast.simulation` (same exposure and noise draw on both paths).
    linearise : bool
        True (default): 8-bit (integer) sRGB images are linearised with the
        sRGB EOTF before they are mosaicked. False: the 8-bit sRGB protocol,
        the encoded values mosaicked as they are (noise-free only).
    demosaic : str
        Bayer demosaic of both paths (``malvar2004``, ``menon2007`` or
        ``bilinear``).
    crop : int
        Border (pixels) left out of the image metrics.
    params : ReconstructParams
        How every method reconstructs (default: float64 arithmetic, otherwise
        :class:`~rgbz_fast.ReconstructParams`'s defaults). ``clip_level="auto"``
        clips raw sources at the level their file records and RGB sources not
        at all.
    seed : int
        Noise seed (noisy runs), an integer >= 0.
    optics : Optics, optional
        The lens in front of the sensor (:class:`~rgbz_fast.simulation.Optics`):
        the linear image is blurred through it (each channel over its band,
        and the pixel aperture) before the mosaic is sampled, on both paths.
        None (the default): no blur, the image's pixels are the scene's.

    Raises
    ------
    ValueError, TypeError
        At construction, naming the field, for any value the run could not
        use (so that a bad configuration never reaches a worker process).

    Examples
    --------
    >>> from rgbz_fast.evaluation import EvalConfig
    >>> cfg = EvalConfig(patterns="mask1", methods=("bilinear", "sg"), metrics=("cfa_psnr",))
    >>> cfg.methods, cfg.params.precision
    (('bilinear', 'sg'), 'float64')
    """

    patterns: tuple[str, ...] | str | Sequence[str | Pattern] = ("mask1", "mask2")
    methods: tuple[str, ...] | str | Sequence[str] = ("bilinear", "bi", "edi_central", "edi_line",
                                                      "sg")
    metrics: tuple[str, ...] | str | Sequence[str] = ALL_METRICS
    bit_depth: int = 11
    noise: bool = False
    linearise: bool = True
    demosaic: str = "malvar2004"
    crop: int = 8
    params: ReconstructParams = field(default_factory=_default_params)
    seed: int = 0
    optics: Optics | None = None

    def __post_init__(self):
        for name in ("patterns", "methods", "metrics"):
            v = getattr(self, name)
            if isinstance(v, str):
                v = tuple(s.strip() for s in v.split(",") if s.strip())
            else:
                v = as_list(v, name, "a sequence of names or a comma-separated string")
            object.__setattr__(self, name, tuple(v))
        if not self.patterns or not self.methods or not self.metrics:
            raise ValueError("patterns, methods and metrics must each name at least one entry")
        # a Pattern object as its name or tile: the results, the reports and the cache key
        # are keyed by strings (a Pattern ran the whole evaluation, then every table failed
        # with a bare TypeError, H104)
        object.__setattr__(self, "patterns", tuple(_pattern_name(p) for p in self.patterns))
        # each once: a repeated entry (mask1 and mask1_grbg are one pattern) would be run
        # twice and counted twice in every mean
        check_z_patterns(self.patterns, "patterns", Z_WHY)
        check_entries(self.methods, "methods")
        check_entries(self.metrics, "metrics")
        bad = [m for m in self.methods if m not in METHODS]
        if bad:
            raise ValueError(f"methods: unknown method(s) {bad}; expected some of {list(METHODS)}")
        bad = [m for m in self.metrics if m not in ALL_METRICS]
        if bad:
            raise ValueError(f"metrics: unknown metric(s) {bad}; expected some of "
                             f"{list(ALL_METRICS)}")
        # checked here, not in a worker: a bad value fails before any image is read
        object.__setattr__(self, "demosaic", check_choice(self.demosaic, _DEMOSAICS,
                                                          "demosaic"))
        object.__setattr__(self, "crop", check_int(self.crop, "crop", lo=0))
        object.__setattr__(self, "bit_depth", check_bit_depth(self.bit_depth))
        object.__setattr__(self, "noise", check_flag(self.noise, "noise"))
        object.__setattr__(self, "linearise", check_flag(self.linearise, "linearise"))
        if self.noise and not self.linearise:
            raise ValueError("linearise: the sensor model (noise=True) takes linear light; "
                             "linearise=False is a noise-free protocol")
        # None and a mapping of changes start from the evaluation's own default (float64),
        # not reconstruct()'s (float32): {"sigma_rel": 0} had also changed the arithmetic
        base, changes = self.params, None
        if base is None or isinstance(base, Mapping):
            base, changes = _default_params(), base
        object.__setattr__(self, "params", ReconstructParams.build(
            base, changes, name="params", caller="params"))
        object.__setattr__(self, "seed", check_seed(self.seed, "seed"))
        # which method reconstructs which pattern, before any image: a pair that does not
        # apply is left out of the run with its reason (:meth:`not_applicable`); a run in
        # which no pair applies fails with the first reason
        skips = {}
        for p in self.patterns:
            for m in self.methods:
                why = _does_not_apply(get_pattern(p), m,
                                      method_params(self.params, m, self.methods),
                                      self.bit_depth)
                if why is not None:
                    skips[(p, m)] = why
        if len(skips) == len(self.patterns) * len(self.methods):
            raise next(iter(skips.values()))
        object.__setattr__(self, "_skips", skips)
        if self.needs_tof and not self.linearise:
            raise ValueError(f"linearise: methods {sorted(set(self.methods) & NEEDS_TOF)} read "
                             "the sensor model's frames, which take linear light")
        if self.optics is not None and not isinstance(self.optics, Optics):
            raise TypeError(f"optics: expected an Optics or None, got "
                            f"{type(self.optics).__name__}")
        if self.optics is not None and not self.linearise:
            raise ValueError("optics: a lens blurs linear light; it needs linearise=True (the "
                             "8-bit sRGB protocol mosaics the encoded values)")

    def not_applicable(self):
        """``{(pattern, method): reason}`` of the pairs this configuration leaves out: the
        method does not reconstruct the pattern (``edi_rows`` off row patterns, ``learned``
        without filters that fit it). ``reason`` is the ValueError the reconstruction would
        raise; the other pairs run."""
        return dict(self._skips)

    def applies(self, pattern, method):
        """Whether ``method`` runs on ``pattern`` in this configuration."""
        return (pattern, method) not in self._skips

    def params_for(self, method):
        """The reconstruction parameters ``method`` runs with (:func:`method_params`)."""
        return method_params(self.params, method, self.methods)

    @property
    def needs_tof(self):
        """True if a method reads the Z pixels' measurements (:data:`rgbz_fast.NEEDS_TOF`):
        every frame of the run then comes from the sensor model (:func:`image_frames`)."""
        return any(m in NEEDS_TOF for m in self.methods)

    @property
    def image_metrics(self):
        return tuple(m for m in self.metrics if m in IMAGE_METRICS)

    def colour_isp(self):
        """The colour chain of both paths (Fig. 19): the library's :class:`~rgbz_fast.ColourISP`
        in float64 with this configuration's demosaic. Its :meth:`~rgbz_fast.ColourISP.render`
        takes the complete CFAs (the evaluation reconstructs them itself, for the CFA PSNR);
        the inputs are linear and black-free, so no defect correction and black level 0."""
        return ColourISP(defects=DefectCorrection(enabled=False),
                         demosaicing=Demosaic(method=self.demosaic), precision="float64",
                         black_level=0.0)

    def key(self, pattern, method, raw=False):
        """Cache key of one (pattern, method) under this configuration.

        ``raw``: the key of a raw source. ``clip_level=None`` (no clip handling),
        and ``"auto"`` for RGB sources, which it gives no level, leave the clip
        level out of the key; raw sources are clipped by ``"auto"``, so their
        key includes it.
        """
        raw = check_flag(raw, "raw")
        d = asdict(self)
        for k in ("patterns", "methods", "metrics"):
            d.pop(k)
        # options at their defaults stay out of the key, so that a key names only what a run
        # changes and adding an option never invalidates the cached results of runs without it
        if d["linearise"]:
            d.pop("linearise")
        params = d.pop("params")
        if d["optics"] is None:
            d.pop("optics")
        if params["clip_level"] is None or (params["clip_level"] == "auto" and not raw):
            params.pop("clip_level")
        if params["filters"] is None or method not in ("learned", "z_guided"):
            params.pop("filters")
        else:
            params["filters"] = [f.digest for f in params["filters"]]
        if params["fixed_point"] is None:
            params.pop("fixed_point")      # the keys of the float precisions stay what they were
        if self.needs_tof:          # the sensor model's frames, for every method of the run
            d["tof_frames"] = 1
        if self.noise or self.needs_tof:
            # the sensor model's draws (H80 changed them): not served from before
            from ..simulation._noise import SIM_REVISION
            d["sim_revision"] = SIM_REVISION
        if (self.noise or self.needs_tof) and self.bit_depth != 11:
            # the sensor model's frames at the bit depth (before, at 11 bits whatever it was):
            # the results cached then are not served for these runs (11 bits: the same frames)
            d["sensor_bits"] = 1
        d.update(params, pattern=str(get_pattern(pattern)), method=method,
                 version=_cache_version())
        blob = json.dumps(d, sort_keys=True, default=str).encode()
        return hashlib.sha1(blob).hexdigest()[:16]

    def label(self, raw_files=0, rgb_images=0):
        """One line saying what the numbers are (noise, bits, demosaic, crop, precision...).

        ``raw_files``: how many of the images were camera raw or bare Bayer files, measured at
        their own bit depth, noise and lens; ``rgb_images``: how many were not (the mosaic's
        noise and bit depth apply to those alone)."""
        clip = self.params.clip_level
        if clip is None:
            clip = ""
        elif clip == "auto":
            clip = ", clip level of the raw files"
        else:
            clip = f", clip level {clip:g} DN"
        extra = []
        defaults = ReconstructParams()
        for name in ("domain", "sg_mode", "sigma_rel", "sigma_floor", "exp"):
            v = getattr(self.params, name)
            if v != getattr(defaults, name):
                extra.append(f"{name}={v}")
        lens = None
        if self.optics is not None:
            o = self.optics
            lens = (f"optics f/{o.f_number:g}" + (f" OLPF {o.olpf:g}" if o.olpf else "")
                    + (f" defocus {o.defocus_um:g} um" if o.defocus_um else "")
                    + (f" fill {o.fill_factor:g}" if o.fill_factor != 1 else ""))
            if not raw_files:
                extra.append(lens)
        if self.params.filters is not None:
            extra.append("filters " + ", ".join(
                f"{f.pattern.name} {f.meta.get('training_set', '?')} {f.digest[:8]}"
                for f in self.params.filters))
        protocol = "" if self.linearise else " sRGB values (not linearised)"
        inputs = f"{'noisy' if self.noise else 'noise-free'}, {self.bit_depth}-bit{protocol}"
        if self.needs_tof:
            # every method's frames come from the sensor model then, not only z_guided's: the
            # scores of the others differ from a run without it (its noise-free frames are
            # mosaics of the linearised images)
            inputs += (", every method on the sensor model's frames (for "
                       f"{', '.join(m for m in self.methods if m in NEEDS_TOF)}'s Z taps)")
        if raw_files:
            own = f"at {'its' if raw_files == 1 else 'their'} own bit depth, noise and lens"
            if lens is not None:            # the lens is the RGB images' (a raw file has its own)
                inputs += ", " + lens
            inputs = (f"{rgb_images} RGB image{'s' if rgb_images > 1 else ''} ({inputs}) and "
                      f"{raw_files} raw file{'s' if raw_files > 1 else ''} {own}"
                      if rgb_images else f"raw file{'s' if raw_files > 1 else ''} {own}")
        return (f"{inputs}, "
                f"demosaic {self.demosaic}, border crop {self.crop} px, "
                f"{self.params.precision}{clip}" + "".join(", " + e for e in extra))


def method_params(params, method, methods):
    """``params`` for ``method`` in a run of ``methods``: filters of one kind given for a run
    that holds that kind's method serve it, and the other filter method runs its shipped
    filters (as it did before ``reconstruct`` refused filters of the other kind alone); in a
    run where no method takes the given kind they stay, and are refused
    (:func:`_does_not_apply`: never silently unused)."""
    from ..reconstruction._z_guided import holds_kind

    if method not in ("learned", "z_guided") or holds_kind(params.filters, method):
        return params
    taker = "z_guided" if method == "learned" else "learned"
    # (the checked filters are of the two kinds: none of the method's is all the other's)
    return params.replace(filters=None) if taker in methods else params


def _does_not_apply(pattern, method, params, bit_depth):
    """The ValueError ``reconstruct(frame, method, params=params)`` raises for any frame of
    ``pattern`` because of the pattern alone, or None when the method applies."""
    from ..reconstruction._learned import learned_geometry
    from ..reconstruction._reconstruct import _plans_for

    try:
        if pattern.bayer_phase is None:
            pattern.bayer_tile()                 # the error that names the missing phase
        check_domain(method, params.domain)
        if method == "learned":
            learned_geometry(pattern)
            resolve_filters(learned_only(params.filters), pattern)
        elif method == "z_guided":
            learned_geometry(pattern)
            resolve_z_filters(params.filters, pattern, bit_depth)
        else:
            _plans_for(pattern, method, params.sg_mode, params.domain)
    except ValueError as exc:
        return exc
    return None


def _cache_version():
    from ._cache import results_version

    return results_version()
