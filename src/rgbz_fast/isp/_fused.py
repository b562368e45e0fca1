"""The colour chain without its stages, in C passes over the frame (csrc/colour_isp.c).

:meth:`ColourISP.run` and :meth:`ColourISP.render` take this path when no stage is
kept (``return_stages=False``) and the demosaic is one of :data:`DEMOSAICS` (every method);
the stage functions stay the reference and the path of ``return_stages``. Three passes:

1. tests 1 and 2 of the defect detection on every colour pixel, then test 3 on the few
   candidates (:func:`defect_fixes`; :func:`._defects._candidates` and
   :func:`._defects._confirm` are their NumPy references); the median fixes of the
   defects stay in NumPy (:func:`._defects._fixes`);
2. the grey-world sums of each 2x2 phase of the complete CFA (:func:`gains`);
3. white balance, demosaic, colour matrix and sRGB encoding (:func:`render`): with Malvar
   or bilinear (:data:`ROW_DEMOSAICS`) one pass row by row, the white-balanced rows in
   cache and the codes from :func:`._encode_table.encode_thresholds`; Menon 2007, whose
   stages read whole planes, runs as three: the white balance into a frame (C), Menon's
   own kernel (csrc/demosaic_menon.c, the stage's demosaic), then the row pass's tail
   (colour matrix and the same codes) over the RGB image.

The images are those of the stages bit for bit, except with a colour matrix (NumPy's
matmul rounds its own way: a code may differ by one) or a float CFA's grey-world sums
(another order of the additions); tests/isp/test_fused.py checks both.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .. import _kernels, _memory
from .._patterns import CHANNELS, Z
from .._validate import kernel_threads
from ._defects import _colour_offsets, _fixes, _thresholds
from ._demosaic import DEMOSAIC_MODES, demosaic
from ._encode_table import encode_thresholds
from ._stages import _check_gains, _fits, _gains_from_sums, white_balance

__all__ = ["defect_fixes", "gains", "render"]

#: the demosaic methods of the render pass (ci_render's method, a code of
#: _kernels.DEMOSAIC_KERNELS)
ROW_DEMOSAICS = ("malvar2004", "bilinear")
#: the demosaic methods of this path: the row pass's, and Menon 2007 (its kernel between
#: the white balance and the tail, ci_balance and ci_encode_rgb)
DEMOSAICS = ROW_DEMOSAICS + ("menon2007",)

#: candidates the first call of the defect pass has room for (more: a second call)
_CANDIDATE_ROOM = 1 << 14


@lru_cache(maxsize=32)
def _tile_neighbours(tile_bytes, shape):
    """(noff, offs) of a tile for the C defect pass: the same-colour offsets of every tile
    position (:func:`._defects._colour_offsets`), -1 neighbours at a Z position."""
    tile = np.frombuffer(tile_bytes, np.int64).reshape(shape)
    P, Q = shape
    noff = np.full(P * Q, -1, np.int32)
    offs = np.zeros((P, Q, _kernels.CI_MAX_NEIGHBOURS, 2), np.int32)
    for py in range(P):
        for px in range(Q):
            if tile[py, px] == Z:
                continue
            o = _colour_offsets(tile, py, px)
            noff[py * Q + px] = len(o)
            if o:
                offs[py, px, :len(o)] = o
    noff.setflags(write=False)
    offs.setflags(write=False)
    return noff, offs


def _candidates(data, tile, params, white_level, threads):
    """:func:`._defects._candidates`'s result from the C pass (the same pixels and floats)."""
    t = np.ascontiguousarray(tile, np.int64)
    noff, offs = _tile_neighbours(t.tobytes(), t.shape)
    thr, k = _thresholds(params, white_level)
    room = _CANDIDATE_ROOM
    while True:
        rr, cc = np.empty(room, np.int64), np.empty(room, np.int64)
        hot, cold, spread = (np.empty(room, np.float32) for _ in range(3))
        n = _kernels.ci_defect_candidates(data, noff, offs, thr, k, rr, cc, hot, cold, spread,
                                          threads)
        if n <= room:
            return (rr[:n].astype(np.intp), cc[:n].astype(np.intp), hot[:n], cold[:n],
                    spread[:n])
        room = n


def _confirmed(data, tile, params, white_level, candidates):
    """:func:`._defects._confirm`'s defects from the C test 3 (the same pixels, in the
    candidates' order)."""
    rr, cc, hot, cold, spread = candidates
    if rr.size == 0:
        return rr, cc
    t = np.ascontiguousarray(tile, np.int64)
    noff, offs = _tile_neighbours(t.tobytes(), t.shape)
    thr, k = _thresholds(params, white_level)
    ok = np.empty(rr.size, np.uint8)
    _kernels.ci_defect_confirm(data, noff, offs, np.ascontiguousarray(rr, np.int64),
                               np.ascontiguousarray(cc, np.int64), hot, cold, spread,
                               float(thr), float(k), float(params.cross_factor), ok)
    ok = ok.view(bool)
    return rr[ok], cc[ok]


def defect_fixes(data, pattern, params, white_level, known, workers):
    """The defect-corrected CFA of validated arguments, and whether anything changed:
    :func:`._defects.correct_defects` (the input itself when nothing is corrected)."""
    data = np.ascontiguousarray(data)
    threads = kernel_threads(workers, data.size)
    confirmed = None
    if params.enabled:
        cands = _candidates(data, pattern.tile, params, white_level, threads)
        confirmed = _confirmed(data, pattern.tile, params, white_level, cands)
    rr, cc, values, _ = _fixes(data, pattern, params, white_level, known, confirmed=confirmed)
    if rr.size == 0:
        return data
    out = _memory.empty_like(data)      # the pool: no fresh pages in a loop of calls
    np.copyto(out, data)
    out[rr, cc] = values
    return out


def gains(full, bayer, wb, black, white, given, workers):
    """The white-balance gains :func:`._stages.white_balance` uses (float64, (3,))."""
    if given is not None:
        return _check_gains(given, "gains")
    if wb.gains is not None:
        return np.asarray(wb.gains, np.float64)
    if wb.method not in ("grey_world", "as_shot"):      # an array records no gains
        return np.ones(3)
    sums, counts = np.zeros(4), np.zeros(4, np.int64)
    _kernels.ci_phase_sums(full, float(white), sums, counts,
                           kernel_threads(workers, full.size))
    return _gains_from_sums(list(sums), list(counts), bayer.bayer_tile(), black, full, white)


def render(full, bayer, chain, black, white, given, workers, matrix=None):
    """White balance .. output of a complete Bayer CFA (validated) by ``chain`` (a
    :class:`ColourISP` whose demosaic is one of :data:`DEMOSAICS`): ``(image, gains)``.
    ``matrix``: the colour matrix when the chain has none (a frame's recorded one)."""
    dt = np.dtype(chain.precision)
    full = np.ascontiguousarray(full)
    g = gains(full, bayer, chain.white_balance, black, white, given, workers)
    scale = (g / (white - black)).astype(dt)
    m = chain.colour_correction.matrix if chain.colour_correction.matrix is not None \
        else matrix
    matrix = np.zeros(0, dt) if m is None else np.asarray(m, dt).reshape(-1)
    phase = np.array([CHANNELS.index(c) for c in bayer.bayer_phase], np.int32)
    bits = chain.output_bits
    out = _memory.empty(full.shape + (3,), np.uint8 if bits == 8 else np.uint16)
    threads = kernel_threads(workers, full.size)
    method = chain.demosaicing.method
    if method not in ROW_DEMOSAICS:
        rgb = _balanced_rgb(full, bayer, chain, black, white, g, scale, phase, threads)
        _kernels.ci_encode_rgb(rgb, matrix, encode_thresholds(dt, bits), out, threads)
        return out, g
    _kernels.ci_render(full, phase, DEMOSAIC_MODES[chain.demosaicing.mode], scale,
                       dt.type(black), int(chain.white_balance.clip), matrix,
                       encode_thresholds(dt, bits), out, threads,
                       _kernels.DEMOSAIC_KERNELS[method])
    return out, g


def _balanced_rgb(full, bayer, chain, black, white, g, scale, phase, threads):
    """The demosaic stage's image of a complete CFA (Menon 2007): the white balance by
    ci_balance (clipped, in the chain's precision: :func:`._stages.white_balance`'s values
    and operations) or, when the stage would leave the precision or not clip, by the stage
    itself; then the stage's demosaic."""
    dt = scale.dtype
    wb = chain.white_balance
    mode = chain.demosaicing.mode
    if wb.clip and _fits(full, dt, black, white, scale):
        balanced = np.empty(full.shape, dt)
        _kernels.ci_balance(full, phase, scale, dt.type(black), 1, balanced, threads)
        # in [0, 1]: demosaic()'s range check has nothing to refuse
        rgb = np.empty(full.shape + (3,), dt)
        _kernels.demosaic_kernel(_kernels.DEMOSAIC_KERNELS[chain.demosaicing.method],
                                 balanced, rgb, phase, DEMOSAIC_MODES[mode], threads)
        return rgb
    balanced, _ = white_balance(full, bayer, wb, black_level=black, white_level=white, gains=g,
                                dtype=dt)
    return demosaic(balanced, bayer.bayer_phase, chain.demosaicing.method, mode=mode, dtype=dt,
                    workers=threads)
