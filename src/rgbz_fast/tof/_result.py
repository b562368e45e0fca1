"""The result of the ToF ISP: one value per Z measurement, and its maps on the frame."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._frame import paint_sites
from .._validate import as_array, check_fill

__all__ = ["ToFDepth"]


@dataclass(frozen=True, eq=False)
class ToFDepth:
    """Output of the ToF ISP: one value per Z measurement.

    Attributes
    ----------
    depth : ndarray of float64, shape (n,)
        Distance in metres (every measurement; trust it where ``valid``).
    residual : ndarray of float64, shape (n,)
        Weighted RMS disagreement of the frequencies after unwrapping (m).
    wraps : ndarray of int32, shape (n,)
        Wrap count of the base (lowest) frequency.
    phase, amplitude, offset : ndarray of float64, shape (F, n)
        Phase in [0, 2 pi) and amplitude ``|I + iQ| / 2`` (DN) after the
        denoise (and the calibration); offset ``mean(A_k)`` (DN; less the dark offsets of a
        calibration that holds them).
    snr : ndarray of float64, shape (n,)
        Smallest over the frequencies of ``|I + iQ| / sigma_I``, with
        ``sigma_I`` the noise of the (averaged) I component from the sensor's
        noise model. The phase noise is about ``1 / snr`` radians.
    sigma : ndarray of float64, shape (n,)
        Predicted noise (standard deviation, m) of ``depth``: the phase
        noise of every frequency through the unwrapping's weighted mean, the
        taps' fixed pattern (DSNU, PRNU) with its correlation across the
        frequencies.
    reflectance : ndarray of float64, shape (n,)
        The NIR reflectance that the amplitude implies at the measured
        distance (the sensor's radiometry, mean over the frequencies; 0 where
        the depth is <= 0). A depth beyond the unambiguous range aliases to a
        shorter one and implies a reflectance ``(d_alias / d_true)^2`` times
        too small.
    count : ndarray of float64, shape (n,)
        Measurements averaged into each one: the window's count (box), the
        effective number ``(sum w)^2 / sum w^2`` (bilateral), 1 without
        denoise.
    valid : ndarray of bool, shape (n,)
        ``flags == 0``.
    flags : ndarray of uint8, shape (n,)
        The bits of :class:`~rgbz_fast.tof.ToFFlag` of the tests the
        measurement failed (bitwise or; 0 = valid).
    frequencies : ndarray, shape (F,)
    sites : (rows, cols)
    block : int
    shape : (rows, cols)
        Frame shape, for :meth:`to_frame`.
    measured : ndarray of float64, shape (n,)
        The depth as measured: ``depth`` itself, except where a guided ISP
        resolved a mixed measurement to the depth of its side
        (:attr:`ToFFlag.RESOLVED`).
    """

    depth: np.ndarray
    residual: np.ndarray
    wraps: np.ndarray
    phase: np.ndarray
    amplitude: np.ndarray
    offset: np.ndarray
    snr: np.ndarray
    sigma: np.ndarray
    reflectance: np.ndarray
    count: np.ndarray
    valid: np.ndarray
    flags: np.ndarray
    frequencies: np.ndarray
    sites: tuple
    block: int
    shape: tuple
    measured: np.ndarray | None = None

    _FIELDS = ("depth", "residual", "snr", "sigma", "reflectance", "valid", "flags", "wraps",
               "count", "phase", "amplitude", "offset", "measured")

    def __post_init__(self):
        if self.measured is None:
            object.__setattr__(self, "measured", self.depth)

    @property
    def n_sites(self):
        return int(self.depth.shape[0])

    def _check_sites(self, name, rows=None, cols=None):
        """ValueError naming ``name`` unless every Z pixel (its ``block`` x ``block`` cells)
        lies on the frame of ``shape`` (a result edited with ``dataclasses.replace``, H76).
        ``rows``, ``cols``: the sites' distinct rows and columns when the caller has them (a
        layout's), else the sites themselves are read."""
        r, c = (np.asarray(a) for a in ((rows, cols) if rows is not None else self.sites))
        if r.size == 0:
            return
        rows, cols = self.shape
        for axis, a, top in (("row", r, rows), ("column", c, cols)):
            lo, hi = int(a.min()), int(a.max())
            if lo < 0 or hi + self.block > top:
                raise ValueError(f"{name}: the Z pixels reach {axis} "
                                 f"{lo if lo < 0 else hi + self.block - 1}, off the frame of "
                                 f"shape {tuple(self.shape)} (sites and shape of different "
                                 "frames?)")

    def to_frame(self, values="depth", fill=np.nan):
        """Paint per-measurement values onto the frame (every cell of each Z pixel).

        Parameters
        ----------
        values : str or ndarray
            A field name (``"depth"``, ``"residual"``, ``"snr"``, ``"sigma"``,
            ``"reflectance"``, ``"valid"``, ``"flags"``, ``"wraps"``,
            ``"count"``, ``"phase"``, ``"amplitude"``, ``"offset"``,
            ``"measured"``) or an
            array of shape (n,) or (F, n).
        fill : scalar
            Value of the pixels that hold no Z measurement (NaN by default: a bool
            or uint8 field then comes as float32; use 0 or False to keep the
            field's type, bool included).

        Returns
        -------
        ndarray, shape (rows, cols) or (F, rows, cols)
        """
        if isinstance(values, str):
            if values not in self._FIELDS:
                raise ValueError(f"values: unknown field {values!r}")
            v = getattr(self, values)
        else:
            v = as_array(values, "values")
        fill = check_fill(fill)
        self._check_sites("sites")
        return paint_sites(v, self.shape, self.sites, self.block, fill)

    def depth_map(self, fill=np.nan):
        """Depth (m) on the frame where valid; ``fill`` elsewhere."""
        fill = check_fill(fill)
        return self.to_frame(np.where(self.valid, self.depth, fill), fill)

    def __repr__(self):
        return (f"ToFDepth({self.n_sites} measurements, block {self.block}, "
                f"{int(self.valid.sum())} valid)")

