"""The sensor models of the RGB-Z imager (paper §5.1, Figs. 16, 18, 19).

* scenes: :class:`Scene` (an RGB image or a spectral cube, optional depth and
  NIR reflectance) and its loaders (:func:`load_scene`, :func:`load_image`,
  :func:`load_rgbd` for Middlebury-style RGB-D folders, :func:`load_spectral`
  for CAVE-style cubes);
* the sensors: :class:`ColourSensor` (§5.1.1) and :class:`ToFSensor` (§5.1.2),
  frozen parameter sets with ISETCam-like defaults;
* the optics: :class:`Optics` (a diffraction-limited lens with optional
  defocus and OLPF, and the pixel aperture) and :func:`apply_optics`, used by
  the models when ``optics=`` is given;
* the models: :func:`simulate_colour` (the plain Bayer CFA of a scene),
  :func:`simulate_tof` (four taps per Z pixel and frequency) and :func:`simulate`
  (the RGB-Z build, §5.1.3: a :class:`~rgbz_fast.RawFrame` with the reference
  CFA of the same exposure and the ToF taps);
* the colour of a simulated sensor: :func:`white_gains` and :func:`colour_matrix` (camera
  RGB to sRGB), which a frame of a spectral scene records for the colour ISP.

The conventions (tap phases, noise chain, radiometry) are in the docstring of
:mod:`rgbz_fast.simulation._simulate` and in docs/guide/sensor.md.
"""

from .._frame import ToFTaps
from .._sensors import SPEED_OF_LIGHT, ColourSensor, ToFSensor
from ._loaders import (MIDDLEBURY_BASELINE_M, MIDDLEBURY_FOCAL_PX, load_image, load_rgbd,
                       load_scene, load_spectral)
from ._optics import Optics, apply_optics
from ._scene import (CAVE_WAVELENGTHS, Scene, disparity_to_depth, estimate_ir_reflectance,
                     srgb_to_linear)
from ._simulate import UnambiguousRangeWarning, simulate, simulate_colour, simulate_tof
from ._colour import colour_matrix, white_gains

__all__ = [
    "Scene", "load_scene", "load_image", "load_rgbd", "load_spectral", "srgb_to_linear",
    "disparity_to_depth", "estimate_ir_reflectance", "CAVE_WAVELENGTHS",
    "MIDDLEBURY_FOCAL_PX", "MIDDLEBURY_BASELINE_M",
    "ColourSensor", "ToFSensor", "ToFTaps", "SPEED_OF_LIGHT", "UnambiguousRangeWarning",
    "simulate", "simulate_colour", "simulate_tof", "Optics", "apply_optics",
    "white_gains", "colour_matrix",
]
