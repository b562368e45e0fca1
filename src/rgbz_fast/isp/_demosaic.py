"""Bayer demosaicing: full CFA (rows, cols) -> RGB image (rows, cols, 3).

The RGB-Z chain fills in the colour missing at the Z sites first
(:func:`rgbz_fast.reconstruct`), so the demosaic always sees a plain Bayer
CFA. The same demosaic serves the reference path and the RGB-Z path (paper
Fig. 19).

Methods
-------
``"malvar2004"`` (default)
    Malvar, He & Cutler's gradient-corrected linear interpolation, as a C
    kernel (threaded). It reproduces colour-demosaicing's
    ``demosaicing_CFA_Bayer_Malvar2004`` (to about 1e-15 in float64) with
    ``mode="reflect"``.
``"menon2007"``
    Menon, Andriani & Calvagno's directional filtering with a posteriori
    decision and refining step (the quality option), as a C kernel (threaded):
    colour-demosaicing's ``demosaicing_CFA_Bayer_Menon2007`` bit for bit (the
    kernel repeats its operations in its order, borders included), in either
    border mode; about 1.5 to 2 times the time of Malvar's kernel.
``"bilinear"``
    Bilinear interpolation (a baseline), as a C kernel (threaded): colour-demosaicing's
    ``demosaicing_CFA_Bayer_bilinear`` bit for bit (its filters' weights are powers of
    two, and the kernel adds the taps in scipy's order), in either border mode.

References
----------
.. [1] Malvar, He and Cutler, "High-quality linear interpolation for demosaicing of Bayer-patterned color images" (docs/references.bib: malvar2004)
.. [2] Menon, Andriani and Calvagno, "Demosaicing with directional filtering and a posteriori decision" (docs/references.bib: menon2007)
.. [3] colour-demosaicing, CFA demosaicing algorithms for Python (docs/references.bib: colour_demosaicing)
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._patterns import BAYER_PHASES, CHANNELS, Pattern
from .._validate import (FRAME_DTYPES, check_choice, check_dtype, check_image, check_workers,
                         finite_range, kernel_threads)

__all__ = ["demosaic", "DEMOSAIC_METHODS", "DEMOSAIC_MODES"]

#: the demosaic methods, in order of the docs
DEMOSAIC_METHODS = ("malvar2004", "menon2007", "bilinear")
#: border modes: scipy "reflect" (as colour-demosaicing) or shift by whole periods;
#: {name: code} from the C enum rgbz_demosaic_mode (csrc/rgbz.h)
DEMOSAIC_MODES = dict(_kernels.DEMOSAIC_MODES)


def _bayer_phase(phase):
    """The Bayer arrangement ("GRBG", ...) that the ``phase`` argument names: a string or a
    plain-Bayer Pattern."""
    if isinstance(phase, Pattern):
        if phase.has_z or phase.bayer_phase is None or phase.period != (2, 2):
            raise ValueError(f"phase: expected a plain 2x2 Bayer pattern, got pattern "
                             f"{phase.name!r} ({phase.tile_string}); reconstruct the missing "
                             "colour first (rgbz_fast.reconstruct)")
        return phase.bayer_phase
    if not isinstance(phase, str) or phase.upper() not in BAYER_PHASES:
        raise ValueError(f"phase: expected one of {', '.join(BAYER_PHASES)}, got {phase!r}")
    return phase.upper()


def demosaic(cfa, phase="GRBG", method="malvar2004", *, mode="reflect", dtype=None,
             workers=None):
    """Demosaic a Bayer CFA into an RGB image in the CFA's own scale (DN).

    Parameters
    ----------
    cfa : ndarray, shape (rows, cols)
        A full Bayer mosaic (reconstruct the Z sites of an RGB-Z frame
        first). Any real dtype but bool (a mask); uint8, uint16, float32 and
        float64 are read directly by the C kernel, other integers are
        converted to float64.
        At least 2x2 pixels; finite.
    phase : {"GRBG", "RGGB", "BGGR", "GBRG"} or Pattern
        Colours of the top-left 2x2 quad in raster order (GRBG is the
        paper's), or a plain Bayer :class:`~rgbz_fast.Pattern`.
    method : {"malvar2004", "menon2007", "bilinear"}
        See the module docstring. The same method must be used for the
        reference and the RGB-Z path.
    mode : {"reflect", "period"}
        Borders. ``"reflect"``: colour-demosaicing's own, exactly: scipy.ndimage's
        half-sample mirror (Malvar, bilinear; a mirrored pixel may change colour, as in
        the reference implementation), the whole-sample mirror of each intermediate
        plane (Menon 2007). ``"period"``: a tap outside the frame is
        moved back by whole Bayer periods, so it keeps its colour (the
        library's convention, docs/guide/interpretation.md). Both agree two pixels (Malvar),
        one (bilinear), ten (Menon 2007) or more from the border. Menon 2007's period border is
        colour-demosaicing's result on the CFA padded by 8 pixels this way, cropped.
    dtype : {None, float32, float64}
        Output dtype. None: float64 for float64 input, float32 otherwise.
    workers : int, optional
        Threads of the C kernel at most, every method (None or -1: all cores;
        one per 2**18 pixels at most). The result does not depend on it.

    Returns
    -------
    rgb : ndarray, shape (rows, cols, 3)
        Linear RGB in the CFA's scale, not clipped: Malvar's and Menon's filters
        overshoot at edges, and the values may leave [0, max].

    Raises
    ------
    ValueError
        Unknown ``phase``, ``method`` or ``mode``; a CFA that is not 2-D,
        smaller than 2x2, or holds NaN or inf.
    TypeError
        A non-numeric or bool CFA or an unsupported ``dtype``.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.isp import demosaic
    >>> cfa = np.full((4, 6), 100, np.uint16)
    >>> rgb = demosaic(cfa, "GRBG")
    >>> rgb.shape, rgb.dtype, float(rgb.min()), float(rgb.max())
    ((4, 6, 3), dtype('float32'), 100.0, 100.0)
    """
    a = check_image(cfa, "cfa", ndim=2, finite=False,         # floats: finite_range below
                    values="CFA values")
    if a.shape[0] < 2 or a.shape[1] < 2:
        raise ValueError(f"cfa: expected at least one 2x2 Bayer period, got shape {a.shape}")
    ph = _bayer_phase(phase)
    method = check_choice(method, DEMOSAIC_METHODS, "method")
    mode = check_choice(mode, tuple(DEMOSAIC_MODES), "mode")
    if dtype is None:
        out_dtype = np.dtype(np.float64) if a.dtype == np.float64 else np.dtype(np.float32)
    else:
        out_dtype = check_dtype(dtype, (np.float32, np.float64))
    nthreads = check_workers(workers)
    if a.dtype.kind == "f":
        # finite input, finite output: the filters add up to 16 weighted taps and overshoot
        # the input range 4.5-fold (Malvar's), so beyond 1/32 of the largest float of the
        # output (and of the float64 arithmetic) a value would overflow to inf, or NaN
        # (inf - inf); Menon 2007 keeps the limit it had with colour-demosaicing
        # (tests/test_extremes.py)
        limit = float(np.finfo(out_dtype).max) / 32
        lo, hi = finite_range(a, "cfa")
        top = max(-lo, hi)
        if top > limit:
            raise ValueError(f"cfa: values up to {top:g} in magnitude; the demosaic's filters "
                             f"overflow {out_dtype} beyond {limit:g}"
                             + (", pass dtype=float64 or rescale the CFA"
                                if out_dtype == np.float32 else ", rescale the CFA"))

    src = a if a.dtype in FRAME_DTYPES else a.astype(np.float64)
    src = np.ascontiguousarray(src)
    out = np.empty(a.shape + (3,), out_dtype)
    codes = np.array([CHANNELS.index(c) for c in ph], np.int32)
    _kernels.demosaic_kernel(_kernels.DEMOSAIC_KERNELS[method], src, out, codes,
                             DEMOSAIC_MODES[mode], kernel_threads(nthreads, src.size))
    return out
