"""The ToF ISP's noise model of a tap, from the sensor's parameters (the ISP is calibrated
for its sensor): shared by the depth chain and the calibration."""

from __future__ import annotations

import numpy as np

__all__ = ["tap_variance"]


def tap_variance(offset, sensor):
    """Expected variance (DN^2) of one tap from its offset and the sensor's readout.

    Shot noise of the collected charge, read noise and DSNU (both in
    electrons), quantisation and the tap's PRNU:
    ``K c + K^2 (read^2 + dsnu^2) + 1/12 + (prnu K e)^2`` with ``e = (offset
    - black) / K`` the electrons the tap holds and ``c = e / (1 - s)`` the
    electrons it collected (the ambient suppression ``s`` drains a share of
    the common mode but not its shot noise). PRNU is a fixed gain per tap: it
    enters as a variance because it differs from tap to tap and pixel to pixel
    (the denoise averages it like noise).
    """
    k = sensor.system_gain
    held = np.subtract(offset, sensor.black_level, dtype=np.float64)   # a new array
    np.maximum(held, 0.0, out=held)                                    # DN
    v = held * k
    if sensor.ambient_suppression:
        v /= 1.0 - sensor.ambient_suppression
    v += k * k * (sensor.read_noise ** 2 + sensor.dsnu ** 2)
    v += 1.0 / 12.0
    if sensor.prnu:
        held *= sensor.prnu
        v += held * held
    return v
