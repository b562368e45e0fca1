"""rgbz-fast: simulate a monolithic RGB-Z CMOS imager and reconstruct its images.

The colour sites and the indirect time-of-flight depth (Z) sites share one
pixel matrix; the colour missing at every Z site is reconstructed (bilateral,
edge-directed and semi-gradient methods of Rebiere et al.) before the usual
ISP. The per-pixel kernels are C (csrc/), threaded with OpenMP.
"""

from ._build_config import VERSION as __version__
from ._config import config, show_config
from ._frame import RawFrame, mosaic
from ._patterns import (B, BAYER_PHASES, G, Pattern, R, Z, bayer, get_pattern, mask1, mask2,
                        rows)
from ._reconstruct import METHODS, PRECISIONS, reconstruct
from . import demosaic, evaluate, frameio, isp, metrics, rawio, scene, sensor, tof_isp
from .isp import ColourISP
from .scene import Scene, load_scene
from .sensor import ColourSensor, ToFSensor, ToFTaps, simulate
from .tof_isp import ToFDepth, ToFISP, tof_depth

__all__ = [
    "__version__", "show_config", "config",
    "Pattern", "bayer", "mask1", "mask2", "rows", "get_pattern", "R", "G", "B", "Z",
    "BAYER_PHASES", "RawFrame", "mosaic", "reconstruct", "METHODS", "PRECISIONS",
    "Scene", "load_scene", "ColourSensor", "ToFSensor", "ToFTaps", "simulate",
    "ColourISP", "tof_depth", "ToFISP", "ToFDepth",
    "demosaic", "evaluate", "frameio", "isp", "metrics", "rawio", "scene", "sensor", "tof_isp",
]
