"""Missing-colour reconstruction at the Z sites: RGB-Z raw frame -> full Bayer CFA (paper §4).

:func:`reconstruct` runs one of the paper's methods -- bilinear (the baseline),
BI (eqs. 2-5), EDICentral (eqs. 6-7), EDILine (eqs. 8-13), SG (eqs. 14-19) --
or Shi et al.'s row method (eqs. 1a-1e) as a C kernel on any pattern derived
from a Bayer mosaic, or the library's own ``"learned"`` method (hashed linear
filters that :func:`train` fits and :class:`LearnedFilters` holds);
:class:`ReconstructParams` says how (precision, the floors of eq. 7, SG mode,
exponential, domain, clip level; ``precision="fixed"`` runs the bit-exact
fixed-point streaming model of a chip, whose widths :class:`FixedPointConfig`
holds). :func:`build_plans` is the specification the kernel interprets: for
each Z position of a pattern, which kernel pixels are candidates and which
differences form the gradients and semi-gradients (docs/guide/interpretation.md).
"""

from ._fixed_config import FixedPointConfig
from ._learned import LearnedFilters, default_filters, train
from ._params import DOMAINS, EXP_CHOICES, PRECISIONS, SG_MODES, ReconstructParams
from ._plans import ORIENTATIONS, SEMI_GRADIENTS, build_plans
from ._reconstruct import METHODS, reconstruct

__all__ = ["reconstruct", "ReconstructParams", "METHODS", "PRECISIONS", "EXP_CHOICES",
           "SG_MODES", "DOMAINS", "ORIENTATIONS", "SEMI_GRADIENTS", "build_plans",
           "LearnedFilters", "train", "default_filters", "FixedPointConfig"]
