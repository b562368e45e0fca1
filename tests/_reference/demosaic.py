"""colour-demosaicing's demosaics, the references of the C kernels (csrc/demosaic.c,
csrc/demosaic_menon.c), with the library's two borders.

``"reflect"`` is colour-demosaicing's own border; ``"period"`` is colour-demosaicing on the
CFA padded by whole Bayer periods, cropped: what ``rgbz_fast.isp.demosaic`` gave for Menon
2007 before its kernel (padding by 8 pixels), and, for bilinear, the same as the kernel's
own shift by periods.
"""

from __future__ import annotations

import numpy as np

from rgbz_fast._deps import import_colour_demosaicing

#: the margin of the period border (csrc/demosaic_menon.c: DMM_PERIOD_PAD)
PERIOD_PAD = 8

#: colour-demosaicing's function of each method
FUNCTIONS = {"malvar2004": "demosaicing_CFA_Bayer_Malvar2004",
             "menon2007": "demosaicing_CFA_Bayer_Menon2007",
             "bilinear": "demosaicing_CFA_Bayer_bilinear"}


def period_index(n, pad):
    """Indices of a CFA axis of length n padded by `pad`, shifting by whole periods (2)."""
    i = np.arange(-pad, n + pad)
    low = i < 0
    i[low] += 2 * ((-i[low] + 1) // 2)
    high = i >= n
    i[high] -= 2 * ((i[high] - n + 2) // 2)
    return i


def reference_demosaic(cfa, phase, method, mode="reflect", pad=PERIOD_PAD):
    """colour-demosaicing's ``method`` of the CFA (as float64; Menon 2007 with its refining
    step), with the border ``mode``: float64 (rows, cols, 3)."""
    fn = getattr(import_colour_demosaicing(), FUNCTIONS[method])
    src = np.asarray(cfa).astype(np.float64)
    if mode == "reflect":
        return fn(src, phase)
    ri, ci = period_index(src.shape[0], pad), period_index(src.shape[1], pad)
    return fn(src[ri[:, None], ci[None, :]], phase)[pad:pad + src.shape[0],
                                                    pad:pad + src.shape[1]]


def menon2007(cfa, phase, mode="reflect"):
    """colour-demosaicing's Menon 2007 (refining step on) with the border ``mode``."""
    return reference_demosaic(cfa, phase, "menon2007", mode)
