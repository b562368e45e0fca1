"""The i-ToF ISP: four-tap demodulation, edge-aware denoise, phase unwrapping, depth, validity.

Paper §5.1.4 and Fig. 17: the depth is computed at the Z measurements only,
and the ISP's 3x3 averaging filter becomes a 5x5 kernel in which only the Z
sites count (:func:`denoise_phasors`, ``tof_depth(denoise="box")``). The
default denoise is edge-aware (:func:`denoise_phasors_bilateral`), and the
validity flags add flying pixels at depth edges (:func:`flying_pixels`) and
out-of-range depths. :func:`tof_depth` (or :class:`ToFISP`) runs the chain;
each stage is a function of its own (:func:`demodulate`, :func:`phasors`,
:func:`unwrap`, :func:`demodulate_unwrap`). :func:`calibrate` fits a sensor's
cyclic error and per-pixel phase offsets from a flat-wall sweep
(:class:`ToFCalibration`, applied with ``tof_depth(calibration=...)``).
"""

from ._calibration import ToFCalibration, calibrate
from ._chain import ToFISP, tof_depth
from ._filters import denoise_phasors_bilateral
from ._guided import upsample_depth
from ._result import ToFDepth
from ._stages import (MAX_WRAPS, demodulate, demodulate_unwrap, denoise_phasors, phasors,
                      unambiguous_range, unwrap)
from ._validity import (FLAG_FLYING, FLAG_INCONSISTENT, FLAG_LOW_SIGNAL, FLAG_OUT_OF_RANGE,
                        FLAG_RESOLVED, FLAG_SATURATED, ToFFlag, flying_pixels)

__all__ = ["ToFISP", "ToFDepth", "tof_depth", "demodulate", "phasors", "denoise_phasors",
           "denoise_phasors_bilateral", "flying_pixels", "unwrap", "demodulate_unwrap",
           "unambiguous_range", "calibrate", "ToFCalibration", "MAX_WRAPS", "ToFFlag",
           "FLAG_SATURATED", "FLAG_LOW_SIGNAL", "FLAG_INCONSISTENT", "FLAG_FLYING",
           "FLAG_OUT_OF_RANGE", "FLAG_RESOLVED", "upsample_depth"]
