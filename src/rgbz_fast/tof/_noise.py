"""The ToF ISP's noise model of a tap, from the sensor's parameters (the ISP is calibrated
for its sensor): shared by the depth chain and the calibration."""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._validate import kernel_threads

__all__ = ["tap_variance"]


def tap_variance(offset, sensor, *, scale=1.0, count=None, workers=1):
    """Expected variance (DN^2) of one tap from its offset and the sensor's readout.

    Shot noise of the collected charge, read noise and DSNU (both in
    electrons), quantisation and the tap's PRNU:
    ``K^2 c + K^2 (read^2 + dsnu^2) + 1/12 + (prnu K e)^2`` with ``e = (offset
    - black) / K`` the electrons the tap holds and ``c = e / (1 - s)`` the
    electrons it collected (the ambient suppression ``s`` drains a share of
    the common mode but not its shot noise). PRNU is a fixed gain per tap: it
    enters as a variance because it differs from tap to tap and pixel to pixel
    (the denoise averages it like noise).

    The NumPy operations of this formula run as one C pass (csrc/tof_filter.c,
    ``rgbz_tof_tap_variance``; tests/_reference/tof.py holds it to them bit for bit),
    which also applies the caller's ``scale`` (``scale * v``) and divides by
    ``max(count, 1)`` (``count``: one value per measurement, the offsets' last axis).
    """
    k = float(sensor.system_gain)
    off = np.asarray(offset)
    flat = np.ascontiguousarray(off, np.float64).reshape(-1)
    out = np.empty(off.shape)
    s = sensor.ambient_suppression
    cnt = None
    if count is not None:
        cnt = np.ascontiguousarray(count, np.float64).reshape(-1)
        if off.ndim == 0 or cnt.size != off.shape[-1]:
            raise ValueError(f"count: expected {off.shape[-1:]} values, got {cnt.size}")
    _kernels.tof_tap_variance(flat, float(sensor.black_level), k, 1.0 - s if s else 0.0,
                              k * k * (sensor.read_noise ** 2 + sensor.dsnu ** 2),
                              float(sensor.prnu), float(scale), cnt, out.reshape(-1),
                              kernel_threads(workers, flat.size))
    return out
