"""The spectral integration of the colour pixels: camera sensitivities times an illuminant,
integrated over the bands of a reflectance cube (paper §5.1.1; the "Noise model" and
radiometry of :mod:`rgbz_fast.simulation._simulate`)."""

from __future__ import annotations

import numpy as np

from .._deps import import_colour

__all__ = ["_spectral_weights", "_spectral_integrate"]


def _resolve_spectrum(value, kind):
    """(wavelengths, values) arrays from a colour-science name or explicit arrays."""
    if not isinstance(value, str):
        wl, vals = value
        return np.asarray(wl, np.float64), np.asarray(vals, np.float64)
    colour = import_colour()
    table = (colour.MSDS_CAMERA_SENSITIVITIES if kind == "sensitivities"
             else colour.SDS_ILLUMINANTS)
    if value not in table:
        table_name = ("MSDS_CAMERA_SENSITIVITIES" if kind == "sensitivities"
                      else "SDS_ILLUMINANTS")
        raise ValueError(f"ColourSensor.{kind}: {value!r} is not in colour-science's "
                         f"{table_name} (known: {', '.join(sorted(table))[:300]})")
    sd = table[value]
    wl = np.asarray(sd.wavelengths, np.float64)
    vals = np.asarray(sd.values, np.float64)
    if vals.ndim == 1:
        vals = vals[:, None]
    return wl, vals


def _band_widths(wl):
    """Trapezoid weights of a wavelength sampling (nm)."""
    if wl.size == 1:
        return np.ones(1)
    d = np.diff(wl)
    w = np.empty_like(wl)
    w[0] = d[0] / 2
    w[-1] = d[-1] / 2
    w[1:-1] = (d[:-1] + d[1:]) / 2
    return w


def _spectral_weights(sensor, wavelengths):
    """Weights (K, 3): relative channel response per band of a reflectance cube.

    ``w_c(l) = S_c(l) E(l) dl / sum_l S_G(l) E(l) dl`` with ``S_c`` the
    sensitivities (per unit energy, each normalised to a peak of 1) and ``E``
    the illuminant, both interpolated linearly onto the scene's bands (0
    outside their range). A perfect white reflector gives 1 in green and the
    camera's white-balance ratios in red and blue.
    """
    swl, svals = _resolve_spectrum(sensor.sensitivities, "sensitivities")
    iwl, ivals = _resolve_spectrum(sensor.illuminant, "illuminant")
    svals = svals / np.maximum(svals.max(axis=0, keepdims=True), 1e-300)
    s = np.stack([np.interp(wavelengths, swl, svals[:, c], left=0.0, right=0.0)
                  for c in range(3)], axis=1)
    e = np.interp(wavelengths, iwl, ivals[:, 0], left=0.0, right=0.0)
    w = s * (e * _band_widths(wavelengths))[:, None]
    green_white = w[:, 1].sum()
    if not green_white > 0:
        raise ValueError("ColourSensor.sensitivities: the green sensitivity times the "
                         "illuminant is zero over the scene's wavelengths "
                         f"({wavelengths[0]:g}-{wavelengths[-1]:g} nm)")
    return w / green_white


def _spectral_integrate(cube, weights, colour_map):
    """Relative channel value at every CFA site: ``cube[r, c, :] @ weights[:, colour]``.

    Integrates only the channel each site needs (one dot product per site).
    """
    out = np.empty(colour_map.shape, np.float64)
    for c in range(3):
        m = colour_map == c
        if m.any():
            out[m] = cube[m].astype(np.float64, copy=False) @ weights[:, c]
    return out
