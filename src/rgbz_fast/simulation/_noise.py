"""The noise chain both sensor models share: mean electrons -> digital numbers.

Fixed-pattern noise (PRNU, DSNU), dark signal, shot noise, the full well,
read noise and the ADC, in the order of the "Noise model" section of
:mod:`rgbz_fast.simulation._simulate` (the conventions of the sensor models).
The colour model and the ToF model draw from their own random streams
(:data:`STREAM_COLOUR_TEMPORAL` ...), so that running one never changes the
draws of the other.

Two versions of the random numbers (``rng_version`` of the models, recorded
in ``frame.meta["rng_version"]``):

* **2** (the default): counter-based. Every draw is Threefry4x32-20
  (Random123's) of the stream's key (:func:`stream_keys`: the seed, or the
  sensor's ``fpn_seed``, and the stream) and of the sample's position (pixel
  row and column; Z pixel, frequency and tap), computed in C (csrc/sim.h
  lists the counters). The result is the same on any number of threads, and a
  pixel's fixed pattern does not depend on the frame's size.
* **1**: NumPy's ``default_rng([seed, stream])`` (PCG64) drawn over whole
  arrays, :func:`expose`: the frames of rgbz-fast 0.1 bit for bit, single
  threaded.

Without noise no random number is drawn but for a ToF delay pattern
(``delay_fpn_ps``, a fixed pattern of the mean), and both versions give the same
frame but for that pattern, which version 1 draws in the sites' order (version 2 at
each Z pixel's position).
"""

from __future__ import annotations

import numpy as np

from .. import _kernels

__all__ = ["expose", "STREAM_COLOUR_TEMPORAL", "STREAM_COLOUR_FPN", "STREAM_TOF_TEMPORAL",
           "STREAM_TOF_FPN", "STREAM_TOF_DELAY", "RNG_VERSION", "RNG_VERSIONS",
           "check_rng_version", "noise_fields", "stream_keys"]

#: the random numbers of the sensor models by default, and the versions there are
RNG_VERSION = 2
RNG_VERSIONS = (1, 2)
#: The revision of the noisy frames a version draws: caches of results measured on the sensor
#: model's frames hold it, so that a result of an earlier draw is not served (2: the shot
#: noise of version 2 no longer depends on the neighbours' means, and the delay pattern is
#: the pixel's, 2026-11-27, H80).
SIM_REVISION = 2

# sub-stream keys of the random generators: temporal noise follows the frame
# seed, fixed-pattern noise the sensor's fpn_seed; each model has its own
# stream so that running (or not running) one never changes the other.
STREAM_COLOUR_TEMPORAL = 0
STREAM_COLOUR_FPN = 1
STREAM_TOF_TEMPORAL = 2
STREAM_TOF_FPN = 3
STREAM_TOF_DELAY = 4


def _fpn_maps(seed, stream, shape, dsnu, prnu):
    """Fixed-pattern maps (PRNU gain, DSNU offset), None when off.

    Both standard-normal maps are always drawn, in a fixed order, so that
    turning one term off leaves the other's pattern unchanged.
    """
    if dsnu == 0 and prnu == 0:
        return None, None
    rng = np.random.default_rng([seed, stream])
    n = rng.standard_normal((2,) + tuple(shape))
    gain = 1.0 + prnu * n[0] if prnu else None
    offset = dsnu * n[1] if dsnu else None
    return gain, offset


def expose(mean_e, dark_e, sensor, *, noise, seed, temporal_stream, fpn_stream,
            fpn_shape=None, suppress=None):
    """Mean electrons -> DN through the noise chain of the module docstring.

    ``mean_e`` is the mean signal (before PRNU), ``dark_e`` the mean dark
    signal. The fixed-pattern maps have shape ``fpn_shape`` (default
    ``mean_e.shape``) and broadcast against ``mean_e`` from the right: the
    ToF draws one map per physical tap, (4, n), shared by every frequency.
    ``suppress`` (electrons, broadcast against ``mean_e``) is drained after
    the shot noise and before the well (the ToF ambient suppression), at most
    what a sample holds: one that holds less is emptied and flagged.
    Returns the DN array and a bool array of the samples at full well or
    full scale (or emptied by the suppression).
    """
    gain = offset = None
    if noise:
        gain, offset = _fpn_maps(sensor.fpn_seed, fpn_stream,
                                 mean_e.shape if fpn_shape is None else fpn_shape,
                                 sensor.dsnu, sensor.prnu)
    e = mean_e if gain is None else np.maximum(mean_e * gain, 0.0)
    e = e + dark_e
    rng = None
    if noise and (sensor.shot_noise or sensor.read_noise > 0):
        rng = np.random.default_rng([seed, temporal_stream])
    if rng is not None and sensor.shot_noise:
        e = rng.poisson(e).astype(np.float64)
    drained = None
    if suppress is not None:
        # at most what the tap holds (csrc/sim.c, sim_post): an emptied tap is flagged
        drained = e < suppress
        e = np.where(drained, 0.0, e - suppress)
    if offset is not None:
        e = e + offset
    well_full = e >= sensor.full_well
    if drained is not None:
        well_full = well_full | drained
    e = np.minimum(e, sensor.full_well)
    if rng is not None and sensor.read_noise > 0:
        e = e + sensor.read_noise * rng.standard_normal(e.shape)
    dn = sensor.black_level + sensor.system_gain * e
    if sensor.quantise:
        dn = np.floor(dn + 0.5)
    top = sensor.white_level
    # the ADC's floor clips too (csrc/sim.c, sim_post): a tap drained below it is flagged
    saturated = well_full | (dn >= top) | (dn < 0)
    dn = np.clip(dn, 0, top)
    return (dn.astype(np.uint16) if sensor.quantise else dn), saturated


def check_rng_version(value, name="rng_version"):
    """``value`` as an int of :data:`RNG_VERSIONS`, else a ValueError naming ``name``."""
    if isinstance(value, (bool, np.bool_)) or value not in RNG_VERSIONS:
        raise ValueError(f"{name}: expected one of {', '.join(map(str, RNG_VERSIONS))} "
                         f"(the random numbers of the sensor models), got {value!r}")
    return int(value)


def noise_fields(sensor, *, noise, dark_e):
    """The noise chain of ``sensor`` as the C kernels take it (csrc/sim.h, rgbz_sim_noise)."""
    return {"noise": int(bool(noise)), "shot": int(bool(sensor.shot_noise)),
            "quantise": int(bool(sensor.quantise)), "prnu": float(sensor.prnu),
            "dsnu": float(sensor.dsnu), "read_noise": float(sensor.read_noise),
            "full_well": float(sensor.full_well), "black": float(sensor.black_level),
            "gain": float(sensor.system_gain), "top": float(sensor.white_level),
            "dark": float(dark_e)}


def _seed_words(seed):
    """A seed >= 0 as 64-bit words, least significant first (at least one)."""
    words = []
    while True:
        words.append(seed & 0xFFFF_FFFF_FFFF_FFFF)
        seed >>= 64
        if not seed:
            return np.array(words, np.uint64)


def stream_keys(seed, fpn_seed, temporal_stream, fpn_stream):
    """The keys (uint32 (8,): temporal, then fixed pattern) of a frame's two streams."""
    keys = [_kernels.sim_key(_seed_words(int(s)), stream)
            for s, stream in ((seed, temporal_stream), (fpn_seed, fpn_stream))]
    return np.array(keys[0] + keys[1], np.uint32)
