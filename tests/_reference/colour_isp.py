"""NumPy reference of the fused colour render (csrc/colour_isp.c: rgbz_ci_render).

White balance, colour-demosaicing's Malvar 2004 (NumPy/SciPy, float64, the 'reflect' border),
the 3x3 matrix, the sRGB OETF of IEC 61966-2-1 through np.power and the quantisation, each in
plain NumPy without the library's kernels. The fused kernel computes the demosaic in double
and rounds to the chain's precision, where this reference rounds colour-demosaicing's float64
result (equal to about 1e-15): a code may differ by one where a value lies at a step.
"""

from __future__ import annotations

import warnings

import numpy as np

from rgbz_fast._patterns import CHANNELS


def reference_render(cfa, phase, *, black, white, gains, clip=True, matrix=None, bits=8,
                     dtype=np.float32):
    """8/16-bit sRGB of a complete Bayer CFA (GRBG, RGGB, ...), the stages in NumPy."""
    dt = np.dtype(dtype)
    scale = (np.asarray(gains, np.float64) / (white - black)).astype(dt)
    b = cfa.astype(dt) - dt.type(black)
    for py in range(2):
        for px in range(2):
            b[py::2, px::2] *= scale[CHANNELS.index(phase[2 * py + px])]
    if clip:
        b = np.clip(b, 0, 1)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        from colour_demosaicing import demosaicing_CFA_Bayer_Malvar2004
        rgb = demosaicing_CFA_Bayer_Malvar2004(b.astype(np.float64), phase).astype(dt)
    if matrix is not None:
        rgb = np.einsum("ij,yxj->yxi", np.asarray(matrix, dt), rgb)
    v = np.clip(rgb, 0, 1)
    t = dt.type
    e = np.where(v <= t(0.0031308), v * t(12.92),
                 t(1.055) * np.power(np.maximum(v, t(0.0031308)), t(1 / 2.4)) - t(0.055))
    code = np.floor(e.astype(dt) * t((1 << bits) - 1) + t(0.5))
    return code.astype(np.uint8 if bits == 8 else np.uint16)
