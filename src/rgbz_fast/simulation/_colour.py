"""The colour of a simulated sensor: its white balance and its colour matrix to sRGB.

A spectral scene reaches the colour pixels through the sensor's spectral
sensitivities, which are not the CIE observer's: the raw R, G, B of a camera
are not sRGB, and shown as sRGB they look washed out (the sensitivities
overlap) and tinted (the illuminant is not balanced). A camera corrects both
with two numbers it knows for its sensor: the **white gains** (the raw R, G, B
of a perfect white reflector under the illuminant, inverted and normalised to
green: the as-shot white balance of a camera that knows its light) and the
**colour matrix** from white-balanced camera RGB to linear sRGB.

The matrix is fitted, as a camera maker does, on reflectances of known
colour: the 24 patches of the ColorChecker (colour-science's
``SDS_COLOURCHECKERS["ColorChecker N Ohta"]``). Each patch's camera response
(the simulation's own spectral weights) is fitted in least squares to its
colour under the same illuminant, adapted to D65 when the light is another
(CAT02) and expressed in linear sRGB, with every row of the matrix summing to
1, so that a white stays white [1]_. :func:`simulate` records both for a
spectral scene (``frame.meta["white_gains"]``, ``frame.meta["colour_matrix"]``,
the nine numbers row by row), and the colour ISP uses what a frame records
(:class:`~rgbz_fast.isp.ColourISP`).

References
----------
.. [1] Finlayson and Drew, "White-point preserving color correction" (docs/references.bib: finlayson1997whitepoint)
"""

from __future__ import annotations

import numpy as np

from .._deps import import_colour
from .._sensors import ColourSensor
from ._simulate import _resolve_spectrum, _spectral_weights

__all__ = ["white_gains", "colour_matrix"]

#: the wavelengths of the fit when none are given: CAVE's 31 bands, 400-700 nm
_DEFAULT_WAVELENGTHS = 400.0 + 10.0 * np.arange(31)


def _sensor_and_bands(sensor, wavelengths):
    sensor = ColourSensor() if sensor is None else sensor
    if not isinstance(sensor, ColourSensor):
        raise TypeError(f"sensor: expected a ColourSensor, got {type(sensor).__name__}")
    wl = _DEFAULT_WAVELENGTHS if wavelengths is None else np.asarray(wavelengths, np.float64)
    if wl.ndim != 1 or wl.size < 3 or not np.all(np.isfinite(wl)) or np.any(np.diff(wl) <= 0):
        raise ValueError(f"wavelengths: expected at least 3 increasing band centres in nm, got "
                         f"{wavelengths!r}")
    return sensor, wl


def _camera_weights(sensor, wl):
    """(K, 3): the response of each channel to each band, quantum efficiency included."""
    return _spectral_weights(sensor, wl) * np.asarray(sensor.qe)[None]


def white_gains(sensor=None, wavelengths=None):
    """The white-balance gains (R, G, B) that make a perfect white reflector neutral.

    ``G = 1``; ``R`` and ``B`` divide the green response of the white by theirs,
    under the sensor's illuminant, over ``wavelengths`` (default: 400-700 nm
    in 10 nm steps, the CAVE bands).

    Examples
    --------
    >>> from rgbz_fast.simulation import white_gains
    >>> [round(float(g), 3) for g in white_gains()]
    [2.152, 1.0, 1.674]
    """
    sensor, wl = _sensor_and_bands(sensor, wavelengths)
    white = _camera_weights(sensor, wl).sum(axis=0)
    return white[1] / white


def colour_matrix(sensor=None, wavelengths=None):
    """The 3x3 matrix from white-balanced camera RGB to linear sRGB, rows summing to 1.

    Fitted on the 24 ColorChecker reflectances under the sensor's illuminant
    (module docstring), over ``wavelengths`` (default 400-700 nm in 10 nm
    steps). Apply it after the white balance of :func:`white_gains`:
    ``ColourISP(white_balance={"gains": g}, colour_correction={"matrix": M})``,
    which is what the ISP does by itself with a frame of a spectral scene.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.simulation import colour_matrix
    >>> m = colour_matrix()
    >>> m.shape, bool(np.allclose(m.sum(axis=1), 1.0))
    ((3, 3), True)
    """
    sensor, wl = _sensor_and_bands(sensor, wavelengths)
    colour = import_colour()
    patches = colour.SDS_COLOURCHECKERS["ColorChecker N Ohta"].values()
    refl = np.stack([np.interp(wl, sd.wavelengths, sd.values) for sd in patches])   # (24, K)
    cam = _camera_weights(sensor, wl)
    white = cam.sum(axis=0)
    balanced = refl @ cam / white                       # white-balanced camera RGB, white = 1
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
    xbar = np.stack([np.interp(wl, cmfs.wavelengths, cmfs.values[:, c]) for c in range(3)],
                    axis=1)
    iwl, ivals = _resolve_spectrum(sensor.illuminant, "illuminant")
    light = np.interp(wl, iwl, ivals[:, 0], left=0.0, right=0.0)
    w = xbar * light[:, None]
    xyz = refl @ w / w[:, 1].sum()                     # the patches, white Y = 1
    xyz_white = w.sum(axis=0) / w[:, 1].sum()
    srgb = colour.RGB_COLOURSPACES["sRGB"]
    d65 = colour.xy_to_XYZ(srgb.whitepoint)
    if not np.allclose(xyz_white, d65, atol=1e-3):
        xyz = colour.adaptation.chromatic_adaptation_VonKries(xyz, xyz_white, d65,
                                                              transform="CAT02")
    target = np.asarray(xyz @ np.asarray(srgb.matrix_XYZ_to_RGB).T)
    # least squares per row with the row's sum fixed at 1 (a white stays white): the KKT
    # system [[A'A, 1], [1', 0]] [m; lambda] = [A't; 1]
    ata = balanced.T @ balanced
    kkt = np.zeros((4, 4))
    kkt[:3, :3] = ata
    kkt[:3, 3] = kkt[3, :3] = 1.0
    rows = []
    for c in range(3):
        rhs = np.append(balanced.T @ target[:, c], 1.0)
        rows.append(np.linalg.solve(kkt, rhs)[:3])
    return np.array(rows)
