"""The colour ISP of an RGB-Z sensor (paper §5.1.4, Figs. 18-19), stage by stage.

::

    raw CFA (DN) -> correct_defects -> fill_missing (reconstruct the Z sites)
        -> white_balance (black level, grey-world gains, clip) -> demosaic
        -> correct_colour (3x3) -> srgb_encode (sRGB OETF, 8 or 16 bit)

Every stage is a plain function of arrays plus a small frozen dataclass of
parameters; :class:`ColourISP` chains them (:meth:`ColourISP.run` for a raw
frame, :meth:`ColourISP.run_pair` for the two paths of Fig. 19,
:meth:`ColourISP.render` for a complete Bayer CFA). The ToF ISP is
:mod:`rgbz_fast.tof`.
"""

from ._chain import STAGES, ColourISP, recorded_rendering
from ._defects import DefectCorrection, correct_defects, detect_defects
from ._demosaic import DEMOSAIC_METHODS, DEMOSAIC_MODES, demosaic
from ._stages import (ColourCorrection, Demosaic, Reconstruction, WhiteBalance, correct_colour,
                      fill_missing, grey_world_gains, srgb_encode, srgb_oetf, white_balance)

__all__ = [
    "ColourISP", "STAGES", "DefectCorrection", "Reconstruction", "WhiteBalance", "Demosaic",
    "ColourCorrection", "detect_defects", "correct_defects", "fill_missing",
    "grey_world_gains", "white_balance", "demosaic", "DEMOSAIC_METHODS", "DEMOSAIC_MODES",
    "correct_colour", "srgb_oetf", "srgb_encode", "recorded_rendering",
]
