"""The colour-guided ToF ISP (tof_depth(guide=), ToFISP.run(guide=)) and upsample_depth: every
C kernel of csrc/tof_guided.c against its NumPy reference (tests/_reference/tof.py), the
chain on simulated frames, and bad guides."""

from __future__ import annotations

import math

import numpy as np
import pytest

from _reference import tof as ref  # noqa: E402

from rgbz_fast import _kernels
from rgbz_fast.isp import ColourISP
from rgbz_fast.simulation import Scene, ToFSensor, simulate
from rgbz_fast.tof import ToFFlag, ToFISP, tof_depth, upsample_depth

#: the filter computes in float, its reference in double
FILTER_TOL = dict(rtol=2e-4, atol=2e-4)


def _frame(pattern="mask2", shape=(48, 64), seed=2, noise=True, sensor=None):
    """Two boxes of their own colour in front of a textured wall, a slanted floor."""
    H, W = shape
    yy, xx = np.mgrid[0:H, 0:W]
    img = np.stack([0.35 + 0.01 * np.sin(xx / 3.0), 0.4 + 0 * xx,
                    0.3 + 0.01 * np.cos(yy / 4.0)], -1)
    depth = 2.0 + 0.004 * yy
    box = (yy > 10) & (yy < 30) & (xx > 12) & (xx < 30)
    img[box] = (0.1, 0.5, 0.15)
    depth[box] = 1.5
    box2 = (yy > 20) & (yy < 44) & (xx > 38) & (xx < 58)
    img[box2] = (0.6, 0.2, 0.1)
    depth[box2] = 1.7
    frame = simulate(Scene(img, depth=depth, ir_reflectance=np.full(shape, 0.6)), pattern,
                     tof_sensor=sensor, seed=seed, noise=noise)
    return frame, ColourISP().run(frame), depth


# --------------------------------------------------------------------------- kernels
@pytest.mark.parametrize("dtype", [np.uint16, np.float32, np.float64])
def test_prepare_matches_numpy(dtype):
    rng = np.random.default_rng(1)
    taps = rng.uniform(0, 2047, (3, 4, 500)).round().astype(dtype)
    taps[1, 2, 7] = 2047
    args = (0.25, 64.0, 1.0 / 0.9, 6.3, 0.01, 2047.0)
    zr, zi = np.empty((3, 500), np.float32), np.empty((3, 500), np.float32)
    v, sat, off = np.empty(500, np.float32), np.zeros(500, np.uint8), np.empty((3, 500))
    phi = np.empty(500, np.float32)
    _kernels.tofg_prepare(taps, *args, zr, zi, v, sat, off, 2, 4.7, phi)
    rzr, rzi, rv, rsat, roff, rphi = ref.guided_prepare(taps, *args, 4.7)
    np.testing.assert_allclose(phi, rphi, rtol=1e-6)
    assert 0 < phi.min() and phi.max() < 1
    np.testing.assert_array_equal(zr, rzr.astype(np.float32))
    np.testing.assert_array_equal(zi, rzi.astype(np.float32))
    np.testing.assert_allclose(v, rv, rtol=1e-6)
    np.testing.assert_array_equal(sat.astype(bool), rsat)
    np.testing.assert_array_equal(off, roff)


@pytest.mark.parametrize("dtype,scale", [(np.uint8, 1 / 255), (np.uint16, 1 / 65535),
                                         (np.float32, 1.0), (np.float64, 1.0)])
@pytest.mark.parametrize("block", [1, 2])
def test_guide_colours_match_numpy(dtype, scale, block):
    rng = np.random.default_rng(3)
    top = {np.uint8: 255, np.uint16: 65535}.get(dtype, 1.0)
    guide = (rng.uniform(0, 1, (30, 41, 3)) * top).astype(dtype)
    rows = np.arange(1, 28, 3, dtype=np.int64)
    cols = np.arange(0, 40, 4, dtype=np.int64)
    N = rows.size * cols.size
    col = np.empty((3, N), np.float32)
    cells = np.empty((block * block, 3, N), np.float32)
    lap = np.zeros(3)
    _kernels.tofg_colour(guide, rows, cols, block, scale, col, cells, lap, 2)
    rcol, rcells, rlap = ref.guided_colour(guide, rows, cols, block, scale)
    np.testing.assert_allclose(col, rcol, rtol=1e-6)
    np.testing.assert_allclose(cells, rcells, rtol=1e-6)
    np.testing.assert_allclose(lap, rlap, rtol=1e-5)


@pytest.mark.parametrize("dtype,scale", [(np.uint8, 1 / 255), (np.uint16, 1 / 65535),
                                         (np.float32, 1.0), (np.float64, 1.0)])
@pytest.mark.parametrize("block", [1, 2])
def test_guide_ring_matches_numpy_bit_for_bit(dtype, scale, block):
    """tofg_ring: the guide around each Z pixel, clamped at every edge of the frame (Z pixels
    on the first and last rows and columns), times the channel's factor, in float32: the
    NumPy reference's values bit for bit, on 1 and 2 threads."""
    rng = np.random.default_rng(4)
    top = {np.uint8: 255, np.uint16: 65535}.get(dtype, 1.0)
    guide = (rng.uniform(0, 1, (30, 41, 3)) * top).astype(dtype)
    rows = np.array([0, 4, 9, 17, 30 - block], np.int64)
    cols = np.array([0, 2, 11, 20, 33, 41 - block], np.int64)
    inv = scale / (math.sqrt(2.0) * np.array([0.011, 0.0073, 0.02]))
    want = ref.guided_ring(guide, rows, cols, block, inv)
    for workers in (1, 2):
        ring = np.full((4 * block + 4, 3, rows.size * cols.size), np.nan, np.float32)
        _kernels.tofg_ring(guide, rows, cols, block, inv, ring, workers)
        np.testing.assert_array_equal(ring, want)
    with pytest.raises(ValueError, match="shapes"):
        _kernels.tofg_ring(guide, rows, cols, block, inv, ring[:-1], 1)
    with pytest.raises(ValueError, match="inv"):
        _kernels.tofg_ring(guide, rows, cols, block, inv[:2].copy(), ring, 1)


@pytest.mark.parametrize("block,R", [(1, 10), (2, 10), (1, 2)])
def test_guide_colours_scaled_in_the_kernel(block, R):
    """With sigma given, the kernel divides col and cells by sqrt(2) sigma_c, sigma_c by
    Immerkaer's formula from its own lap (at least the floor; the floor without an interior),
    bit for bit as the same statement in NumPy on the unscaled outputs."""
    rng = np.random.default_rng(5)
    guide = (rng.uniform(0, 1, (31, 41, 3)) * 255).astype(np.uint8)
    guide[..., 2] = 7                                     # a flat channel: sigma at the floor
    rows = np.arange(0, 3 * R, 3, dtype=np.int64)
    cols = np.arange(0, 40, 4, dtype=np.int64)
    N = rows.size * cols.size
    outs = []
    for sigma in (None, np.empty(3)):
        col = np.empty((3, N), np.float32)
        cells = np.empty((block * block, 3, N), np.float32)
        lap = np.zeros(3)
        _kernels.tofg_colour(guide, rows, cols, block, 1 / 255, col, cells, lap, 2, 0.002,
                             sigma)
        outs.append((col, cells, lap, sigma))
    col, cells, lap, _ = outs[0]
    interior = max(R - 2, 0) * max(cols.size - 2, 0)
    sig = math.sqrt(math.pi / 2.0) / (6.0 * interior) * lap if interior else np.zeros(3)
    sig = np.maximum(sig, 0.002)
    inv = (1.0 / (math.sqrt(2.0) * sig)).astype(np.float32)[:, None]
    np.testing.assert_array_equal(outs[1][3], sig)
    np.testing.assert_array_equal(outs[1][0], col * inv)
    np.testing.assert_array_equal(outs[1][1], cells * inv[None])
    assert outs[1][3][2] == 0.002
    with pytest.raises(ValueError, match="sigma"):
        _kernels.tofg_colour(guide, rows, cols, block, 1 / 255, col, cells, lap, 2, 0.002,
                             np.empty(2))


def _planes(R, C, F=3, seed=0):
    """Phasors of two surfaces with a step, their noise, colours that mostly follow it."""
    rng = np.random.default_rng(seed)
    N = R * C
    step = (np.arange(C) >= C // 2)[None, :].repeat(R, 0).reshape(-1)
    base = np.where(step, 300.0, -200.0)
    zr = (base[None] + rng.normal(0, 20, (F, N))).astype(np.float32)
    zi = (0.5 * base[None] + rng.normal(0, 20, (F, N))).astype(np.float32)
    v = rng.uniform(300, 500, N).astype(np.float32)
    col = (np.where(step, 5.0, 0.0)[None] + rng.normal(0, 0.7, (3, N))).astype(np.float32)
    use = (rng.random(N) > 0.05).astype(np.uint8)
    return zr, zi, v, col, use


def _with_phi(col, seed=9):
    """col (3, N) with a fourth row: fixed-pattern shares in [0, 0.9)."""
    phi = np.random.default_rng(seed).uniform(0, 0.9, col.shape[1]).astype(np.float32)
    return np.ascontiguousarray(np.vstack([col, phi[None]]))


@pytest.mark.parametrize("fixed", [False, True])
@pytest.mark.parametrize("axis", [0, 1])
@pytest.mark.parametrize("second", [False, True])
@pytest.mark.parametrize("R,C,F", [(23, 37, 3), (20, 70, 1), (9, 40, 5), (12, 300, 3)])
def test_guided_pass_matches_numpy(axis, second, R, C, F, fixed):
    """Both axes, a first pass and a pass over a first pass's output (n_eff in), regular lines
    (the blocked fast path and the edges) and frequencies beyond the fast path's 4; with the
    fixed-pattern shares (col's fourth row: the Mahalanobis range term) and without."""
    zr, zi, v, col, use = _planes(R, C, F)
    if fixed:
        col = _with_phi(col)
    N = R * C
    px = np.arange(C if axis == 1 else R, dtype=np.int64) * 2
    nin = np.random.default_rng(5).uniform(0.5, 9, N).astype(np.float32) if second else None
    if second:
        nin[::7] = 0.0
    gr, gi, gv = zr + 3, zi - 2, v * 1.5
    outs = [np.empty((F, N), np.float32), np.empty((F, N), np.float32),
            np.empty(N, np.float32), np.empty(N, np.float32)]
    _kernels.tofg_pass(zr, zi, v, nin, gr, gi, gv, col, use, R, C, axis, px, 5, 10, 0.125, 0.02,
                       outs[0], outs[1], None, None, outs[2], outs[3], 2)
    want = ref.guided_pass(zr, zi, v, nin, gr, gi, gv, col, use, R, C, axis, px, 5, 10, 0.125,
                           0.02)
    scale = np.abs(zr).max()
    np.testing.assert_allclose(outs[0], want[0], rtol=0, atol=2e-4 * scale)
    np.testing.assert_allclose(outs[1], want[1], rtol=0, atol=2e-4 * scale)
    np.testing.assert_allclose(outs[2], want[2], **FILTER_TOL)
    np.testing.assert_allclose(outs[3], want[3], **FILTER_TOL)


def test_guided_pass_on_uneven_lines_and_double_output():
    """Grid lines at uneven pixel spacing (a neighbour beyond the radius stays out), and the
    double-precision output of the last pass."""
    R, C = 15, 33
    zr, zi, v, col, use = _planes(R, C)
    px = np.cumsum(np.r_[0, np.random.default_rng(2).integers(1, 5, C - 1)]).astype(np.int64)
    o64 = (np.empty((3, R * C)), np.empty((3, R * C)))
    ov, on = np.empty(R * C, np.float32), np.empty(R * C, np.float32)
    _kernels.tofg_pass(zr, zi, v, None, zr, zi, v, col, use, R, C, 1, px, 4, 6, 0.125, 0.02,
                       None, None, o64[0], o64[1], ov, on, 1)
    want = ref.guided_pass(zr, zi, v, None, zr, zi, v, col, use, R, C, 1, px, 4, 6, 0.125, 0.02)
    np.testing.assert_allclose(o64[0], want[0], rtol=0, atol=2e-4 * np.abs(zr).max())
    np.testing.assert_allclose(on, want[3], **FILTER_TOL)


def _four_passes(zr, zi, v, col, use, R, C, rows, cols, reach_r, reach_c, radius, hc):
    """The four passes of the guided denoise by tofg_pass, one call each."""
    F, N = zr.shape

    def run(data, nin, guide, axis, out64=False):
        px, reach = (cols, reach_c) if axis == 1 else (rows, reach_r)
        ov, on = np.empty(N, np.float32), np.empty(N, np.float32)
        o = (np.empty((F, N)), np.empty((F, N))) if out64 else \
            (np.empty((F, N), np.float32), np.empty((F, N), np.float32))
        _kernels.tofg_pass(*data, nin, *guide, col, use, R, C, axis, px, reach, radius, 0.125,
                           hc, *(((None, None) + o) if out64 else (o + (None, None))), ov, on, 2)
        return (o[0], o[1], ov), on

    raw = (zr, zi, v)
    rows1, n1 = run(raw, None, raw, 1)
    guide1, _ = run(rows1, n1, rows1, 0)
    rows2, n2 = run(raw, None, guide1, 1)
    (mr, mi, var), neff = run(rows2, n2, guide1, 0, out64=True)
    return mr, mi, var, neff


@pytest.mark.parametrize("fixed", [False, True])
@pytest.mark.parametrize("R,C,F,reach_r,reach_c,radius,uneven,hc", [
    (150, 300, 3, 5, 5, 10, False, 0.02),     # bands of rows, tiled column passes
    (40, 1100, 3, 5, 5, 10, False, 0.02),     # tiles of columns with their views
    (200, 270, 4, 3, 5, 6, False, 0.02),      # rows reach farther than the radius allows
    (130, 37, 5, 4, 4, 8, False, 0.1),        # beyond the fast blocks' 4 frequencies
    (3, 5, 3, 5, 5, 10, False, 0.02),         # a grid smaller than a window
    (90, 300, 3, 5, 5, 10, True, 0.02)])      # uneven grid rows: the generic column pass
def test_guided_denoise_is_the_four_passes(R, C, F, reach_r, reach_c, radius, uneven, hc,
                                           fixed):
    """tofg_denoise (the passes fused strip by strip) gives the four tofg_pass calls' outputs
    bit for bit, on 1 and 2 threads, and agrees with the NumPy reference; with the
    fixed-pattern shares and without."""
    zr, zi, v, col, use = _planes(R, C, F, seed=R + C)
    if fixed:
        col = _with_phi(col, R)
    rows = (np.cumsum(np.r_[0, np.random.default_rng(2).integers(1, 5, R - 1)]) if uneven
            else np.arange(R) * 2).astype(np.int64)
    cols = np.arange(C, dtype=np.int64) * (1 if reach_c > reach_r else 2)
    want = _four_passes(zr, zi, v, col, use, R, C, rows, cols, reach_r, reach_c, radius, hc)
    N = R * C
    for workers, strip in ((1, 0), (2, 0), (2, 1), (1, 7)):
        got = (np.empty((F, N)), np.empty((F, N)), np.empty(N, np.float32),
               np.empty(N, np.float32))
        _kernels.tofg_denoise(zr, zi, v, col, use, rows, cols, reach_r, reach_c, radius, 0.125,
                              hc, *got, workers, strip=strip)
        for a, b in zip(got, want):
            np.testing.assert_array_equal(a, b)
        # n_eff in double instead (count), with or without the float plane
        for neff in (None, np.empty(N, np.float32)):
            count = np.empty(N)
            _kernels.tofg_denoise(zr, zi, v, col, use, rows, cols, reach_r, reach_c, radius,
                                  0.125, hc, *got[:3], neff, workers, strip=strip, count=count)
            np.testing.assert_array_equal(count, want[3].astype(np.float64))
    ref_out = ref.guided_denoise(zr, zi, v, col, use, R, C, rows, cols, reach_r, reach_c,
                                 radius, 0.125, hc)
    scale = np.abs(zr).max()
    np.testing.assert_allclose(got[0], ref_out[0], rtol=0, atol=2e-4 * scale)
    np.testing.assert_allclose(got[1], ref_out[1], rtol=0, atol=2e-4 * scale)
    np.testing.assert_allclose(got[2], ref_out[2], **FILTER_TOL)
    np.testing.assert_allclose(got[3], ref_out[3], **FILTER_TOL)


# (frequency count, strip, max_range, frequency order, weights): 7.49 m is four wrap counts
# of 80 MHz (the ISP's default set and range, the row unwrapping's path of its own), 7.5 m five
@pytest.mark.parametrize("F,strip,max_range,order,weights", [
    (3, 0, 7.5, [0, 1, 2], "ones"), (2, 5, 7.5, [0, 1, 2], "ones"),
    (1, 0, 7.5, [0, 1, 2], "ones"), (3, 0, 7.49, [0, 1, 2], "ones"),
    (3, 5, 7.49, [2, 0, 1], "squares"), (3, 0, 7.49, [1, 2, 0], "squares")])
def test_guided_denoise_unwraps_as_tof_depth_iq(F, strip, max_range, order, weights):
    """With the unwrapping's arrays, tofg_denoise unwraps each strip's means as tof_depth_iq
    unwraps the stored means, bit for bit; a non-finite phasor is reported (False) and its
    sites as tof_depth_iq reports them."""
    R, C = 140, 60
    zr, zi, v, col, use = _planes(R, C, F, seed=11)
    rows, cols = np.arange(R, dtype=np.int64) * 2, np.arange(C, dtype=np.int64) * 2
    f = np.array([80e6, 100e6, 120e6])[order][:F]
    w = np.ones(F) if weights == "ones" else (f / 1e8) ** 2
    N = R * C
    mr, mi = np.empty((F, N)), np.empty((F, N))
    var, neff = np.empty(N, np.float32), np.empty(N, np.float32)
    args = (zr, zi, v, col, use, rows, cols, 5, 5, 10, 0.125, 0.02)
    assert _kernels.tofg_denoise(*args, mr, mi, var, neff, 2)
    want = [np.empty(N), np.empty(N), np.empty(N, np.int32), np.empty((F, N)), np.empty((F, N))]
    assert _kernels.tof_depth_iq(mr, mi, f, w, max_range, *want, workers=2)
    got = [np.empty(N), np.empty(N), np.empty(N, np.int32), np.empty((F, N)), np.empty((F, N))]
    var2, neff2 = np.empty(N, np.float32), np.empty(N, np.float32)
    assert _kernels.tofg_denoise(*args, None, None, var2, neff2, 2, f, w, max_range, *got,
                                 strip=strip)
    for a, b in zip(got + [var2, neff2], want + [var, neff]):
        np.testing.assert_array_equal(a, b)
    count = np.empty(N)
    assert _kernels.tofg_denoise(*args, None, None, var2, None, 2, f, w, max_range, *got,
                                 strip=strip, count=count)
    np.testing.assert_array_equal(count, neff.astype(np.float64))
    with pytest.raises(TypeError, match="out_neff"):
        _kernels.tofg_denoise(*args, None, None, var2, None, 2, f, w, max_range, *got)
    zr[0, 3] = np.nan
    _kernels.tofg_denoise(*args, mr, mi, var, neff, 2)               # the means, NaN around
    assert not _kernels.tof_depth_iq(mr, mi, f, w, max_range, *want, workers=2)
    assert not _kernels.tofg_denoise(*args, None, None, var2, neff2, 2, f, w, max_range, *got)
    assert (want[2] == -1).any()
    for a, b in zip(got, want):
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("uneven", [False, True])
@pytest.mark.parametrize("fixed", ["none", "pattern", "pattern+delay"])
def test_guided_denoise_makes_the_validity_of_the_kernels_after_it(uneven, fixed):
    """With flags given, tofg_denoise makes each unwrapped row's snr, sigma, reflectance and
    bits as tofg_validity does after it, with the fixed pattern's correction (offset given)
    as tof_fixed_pattern (shared) plus delay_var / max(count, 1): flags, snr and reflectance
    bit for bit; sigma bit for bit on uneven grid lines (the strips, which take the cosines
    from the phases as tof_fixed_pattern does), within 1e-12 on even ones (the sliding rows
    take them from the means, I / (2 amp), a few ulps from the polynomial of the phase)."""
    R, C, F = 60, 70, 3
    zr, zi, v, col, use = _planes(R, C, F, seed=5)
    N = R * C
    rows = np.arange(R, dtype=np.int64) * 2
    cols = np.arange(C, dtype=np.int64) * 2
    if uneven:
        cols[C // 2:] += 1                      # not evenly spaced: the strips' path
    rng = np.random.default_rng(6)
    f = np.array([80e6, 100e6, 120e6])
    w = np.ones(F)
    sat = (rng.random(N) < 0.03).astype(np.uint8)
    scale, coef = rng.uniform(1e-5, 1e-4, F), rng.uniform(1e-3, 1e-2, F)
    limits = np.array([4.0, 110.0, 0.015, 0.15, 0.001, 7.49, 33.8])
    offset = rng.uniform(200.0, 900.0, (F, N))
    noise = np.array([64.0, 1.3, 4.0, 4.0, 0.01, 2e-5 if fixed == "pattern+delay" else 0.0])
    args = (zr, zi, v, col, use, rows, cols, 5, 5, 10, 0.125, 0.02)
    got = [np.empty(N), np.empty(N), np.empty(N, np.int32), np.empty((F, N)), np.empty((F, N))]
    var, count = np.empty(N, np.float32), np.empty(N)
    snr, sigma, refl, flags = np.empty(N), np.empty(N), np.empty(N), np.empty(N, np.uint8)
    pattern = fixed != "none"
    usable = np.full(N, 7, np.uint8)
    present = (rng.random(N) > 0.1).astype(np.uint8)
    assert _kernels.tofg_denoise(*args, None, None, var, None, 2, f, w, 7.49, *got,
                                 count=count, sat=sat, sigma_scale=scale, refl_coef=coef,
                                 limits=limits, snr=snr, sigma=sigma, refl=refl, flags=flags,
                                 offset=offset if pattern else None,
                                 fixed=noise if pattern else None, usable=usable,
                                 present=present if uneven else None, usable_bits=3)
    depth, residual, _, phase, amp = got
    delta = None
    if pattern:
        delta = np.empty(N)
        _kernels.tof_fixed_pattern(phase, amp, offset, count, scale, *noise[:5], True, delta, 2)
        delta += noise[5] / np.maximum(count, 1.0)
    want = [np.empty(N), np.empty(N), np.empty(N), np.empty(N, np.uint8)]
    _kernels.tofg_validity(amp, var, depth, residual, sat, scale, coef, *limits[:6], *want, 2,
                           delta, limits[6])
    np.testing.assert_array_equal(flags, want[3])
    np.testing.assert_array_equal(snr, want[0])
    np.testing.assert_array_equal(refl, want[2])
    usable_want = np.empty(N, np.uint8)                  # and tofg_usable of them
    _kernels.tofg_usable(flags, depth, sigma, present if uneven else None, 3, usable_want, 2)
    np.testing.assert_array_equal(usable, usable_want)
    assert 0 < usable.sum() < N
    if uneven or not pattern:
        np.testing.assert_array_equal(sigma, want[1])
    else:
        np.testing.assert_allclose(sigma, want[1], rtol=1e-12, atol=0)
    assert len(np.unique(flags)) > 3 and (flags == 0).sum() > N // 10     # every kind of bit
    with pytest.raises(TypeError, match="flags needs"):
        _kernels.tofg_denoise(*args, None, None, var, None, 2, f, w, 7.49, *got, count=count,
                              flags=flags)
    with pytest.raises(ValueError, match="offset"):
        _kernels.tofg_denoise(*args, None, None, var, None, 2, f, w, 7.49, *got, count=count,
                              sat=sat, sigma_scale=scale, refl_coef=coef, limits=limits,
                              snr=snr, sigma=sigma, refl=refl, flags=flags,
                              offset=offset[:2], fixed=noise)


@pytest.mark.parametrize("dtype", [np.uint16, np.float32, np.float64])
@pytest.mark.parametrize("uneven,strip,fixed", [(False, 0, True), (False, 7, True),
                                                (False, 0, False), (True, 0, True)])
def test_guided_denoise_makes_the_prepare_stage_of_tofg_prepare(dtype, uneven, strip, fixed):
    """With taps given, tofg_denoise makes the prepare stage itself, row by row: the same
    outputs, sat (|= a tap at full scale) and offset as tofg_prepare then tofg_denoise of its
    planes, bit for bit, with use taken before the stage, on the sliding rows (one band and
    bands of 7 rows, whose rows beyond the band are made twice and written once) and on
    uneven grid lines (the strips, after the stage over the frame)."""
    R, C, F = 45, 70, 3
    N = R * C
    rng = np.random.default_rng(8)
    rows = np.arange(R, dtype=np.int64) * 2
    cols = np.arange(C, dtype=np.int64) * 2
    if uneven:
        cols[C // 2:] += 1
    step = np.arange(C) >= C // 2
    base = np.where(step, 900.0, 300.0)[None, :].repeat(R, 0).reshape(-1)
    phase = np.array([0.4, 1.1, 2.0])[:, None, None] + np.array(
        [0.0, np.pi / 2, np.pi, 1.5 * np.pi])[None, :, None]
    taps = base[None, None] + 250.0 * np.cos(phase) + rng.normal(0, 15, (F, 4, N))
    white = 1500.0
    taps[:, 1, rng.integers(0, N, 40)] = white           # at full scale: left out
    taps = np.clip(np.round(taps), 0, white).astype(dtype)
    col = rng.normal(0, 0.7, (4 if fixed else 3, N)).astype(np.float32)
    col[:3] += np.where(step, 5.0, 0.0).repeat(1)[None, :].repeat(R, 0).reshape(-1)[None]
    sat0 = (rng.random(N) < 0.02).astype(np.uint8)
    use = ((sat0 == 0) & (rng.random(N) > 0.03)).astype(np.uint8)
    prep = np.array([0.8, 64.0, 1.0, 6.0, 0.01, white, 4.0])
    f, w = np.array([80e6, 100e6, 120e6]), np.ones(F)

    def outputs():
        return [np.empty(N), np.empty(N), np.empty(N, np.int32), np.empty((F, N)),
                np.empty((F, N)), np.empty(N, np.float32), np.empty(N)]

    # the stages apart: tofg_prepare, use without its hits, the denoise of its planes
    zr, zi = np.empty((F, N), np.float32), np.empty((F, N), np.float32)
    v = np.empty(N, np.float32)
    sat_w, off_w = sat0.copy(), np.empty((F, N))
    col_w = col.copy()
    _kernels.tofg_prepare(taps, *prep[:6], zr, zi, v, sat_w, off_w, 2, prep[6],
                          col_w[3] if fixed else None)
    use_w = (use & (sat_w == 0)).astype(np.uint8)
    want = outputs()
    assert _kernels.tofg_denoise(zr, zi, v, col_w, use_w, rows, cols, 5, 5, 10, 0.125, 0.02,
                                 None, None, want[5], None, 2, f, w, 7.49, *want[:5],
                                 strip=strip, count=want[6])
    assert (sat_w != sat0).sum() > 20                   # the stage's hits are in the test
    # the stage inside
    sat_g, off_g = sat0.copy(), np.full((F, N), np.nan)
    got = outputs()
    assert _kernels.tofg_denoise(None, None, None, col.copy(), use, rows, cols, 5, 5, 10,
                                 0.125, 0.02, None, None, got[5], None, 2, f, w, 7.49,
                                 *got[:5], strip=strip, count=got[6], sat=sat_g,
                                 offset=off_g, taps=taps, prepare=prep)
    np.testing.assert_array_equal(sat_g, sat_w)
    np.testing.assert_array_equal(off_g, off_w)
    for a, b in zip(got, want):
        np.testing.assert_array_equal(a, b)
    with pytest.raises(TypeError, match="taps needs"):
        _kernels.tofg_denoise(None, None, None, col, use, rows, cols, 5, 5, 10, 0.125, 0.02,
                              None, None, got[5], None, 2, f, w, 7.49, *got[:5],
                              count=got[6], taps=taps, prepare=prep)
    with pytest.raises(TypeError, match="taps: expected"):
        _kernels.tofg_denoise(None, None, None, col, use, rows, cols, 5, 5, 10, 0.125, 0.02,
                              None, None, got[5], None, 2, f, w, 7.49, *got[:5],
                              count=got[6], sat=sat_g, offset=off_g,
                              taps=taps.astype(np.int32), prepare=prep)


def test_validity_snr_at_zero_and_infinite_noise():
    """The least 2 a / sd over the frequencies in one division is the per-frequency minimum
    bit for bit, and a quotient that is NaN (0 / 0, inf / inf, a NaN variance) counts as not
    there (snr inf when every one is), as the per-frequency loop had it."""
    amp = np.array([[0.0, 0.0, 3.0, np.inf, np.inf, 2.0, 1e-300, 7.0],
                    [0.0, 5.0, 0.0, np.inf, 4.0, np.nan, 1e-300, 1e300]])
    var = np.array([0.0, 0.0, 0.0, np.inf, np.inf, 2.0, 1e-30, np.nan], np.float32)
    N = amp.shape[1]
    out = [np.empty(N), np.empty(N), np.empty(N), np.empty(N, np.uint8)]
    z = np.zeros(N)
    _kernels.tofg_validity(amp, var, z + 1.0, z, z.astype(np.uint8), np.ones(2), np.ones(2),
                           4.0, 0.0, -1.0, 1.0, 0.0, 7.49, *out, 1)
    sd = np.sqrt(var.astype(np.float64))
    with np.errstate(divide="ignore", invalid="ignore"):
        q = 2.0 * amp / sd[None]
    want = np.where(np.isnan(q), np.inf, q).min(axis=0)
    np.testing.assert_array_equal(out[0], want)


def test_validity_matches_numpy():
    rng = np.random.default_rng(4)
    N, F = 2000, 3
    amp = rng.uniform(0, 80, (F, N))
    amp[:, :3] = 0.0
    var = rng.uniform(50, 500, N).astype(np.float32)
    depth = rng.uniform(-0.5, 8, N)
    residual = rng.uniform(0, 0.3, N)
    sat = (rng.random(N) < 0.05).astype(np.uint8)
    scale, coef = rng.uniform(1e-5, 1e-4, F), rng.uniform(1e-3, 1e-2, F)
    out = [np.empty(N), np.empty(N), np.empty(N), np.empty(N, np.uint8)]
    args = (4.0, 1.0, 0.015, 0.15, 0.05, 7.49)
    _kernels.tofg_validity(amp, var, depth, residual, sat, scale, coef, *args, *out, 2)
    want = ref.guided_validity(amp, var, depth, residual, sat, scale, coef, *args)
    for a, b in zip(out[:3], want[:3]):
        np.testing.assert_allclose(a, b, rtol=1e-12)
    np.testing.assert_array_equal(out[3], want[3])
    # with the fixed-pattern correction: some negative enough to be refused (sum <= 0)
    delta = rng.uniform(-2e-5, 2e-5, N)
    _kernels.tofg_validity(amp, var, depth, residual, sat, scale, coef, *args, *out, 2, delta)
    want = ref.guided_validity(amp, var, depth, residual, sat, scale, coef, *args, delta=delta)
    for a, b in zip(out[:3], want[:3]):
        np.testing.assert_allclose(a, b, rtol=1e-12)
    np.testing.assert_array_equal(out[3], want[3])
    # the upper bound on the implied reflectance (an aliased depth): out of range above it
    bound = float(np.median(want[2][want[2] > 0]))
    _kernels.tofg_validity(amp, var, depth, residual, sat, scale, coef, *args, *out, 2, delta,
                           bound)
    want2 = ref.guided_validity(amp, var, depth, residual, sat, scale, coef, *args, delta=delta,
                                max_reflectance=bound)
    np.testing.assert_array_equal(out[3], want2[3])
    assert ((want2[3] & 16) > (want[3] & 16)).sum() > N // 10


def test_usable_matches_numpy():
    rng = np.random.default_rng(4)
    n = 10_003
    flags = rng.integers(0, 64, n).astype(np.uint8)
    depth, sigma = rng.uniform(0, 5, n), rng.uniform(0, 0.1, n)
    depth[rng.integers(0, n, 300)] = np.nan
    depth[rng.integers(0, n, 30)] = np.inf
    sigma[rng.integers(0, n, 300)] = np.inf
    sigma[rng.integers(0, n, 30)] = -np.nan
    present = (rng.random(n) > 0.2).astype(np.uint8)
    for pres in (present, None):
        for workers in (1, 2):
            out = np.full(n, 7, np.uint8)
            _kernels.tofg_usable(flags, depth, sigma, pres, 3, out, workers)
            np.testing.assert_array_equal(out, ref.guided_usable(flags, depth, sigma, pres, 3))
    with pytest.raises(ValueError, match="present"):
        _kernels.tofg_usable(flags, depth, sigma, present[:-1], 3, out, 1)


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_guided_flying_matches_numpy(pattern):
    frame, guide, _ = _frame(pattern, shape=(64, 80))
    res = tof_depth(frame.tof, guide=guide, flying_step=None)
    from rgbz_fast.tof._guided import _Layout, guide_colours, guide_ring
    lay = _Layout(frame.tof.sites, frame.tof.block, frame.tof.shape)
    col, cells, sig = guide_colours(guide, 1 / 255, lay, 1)
    ring = guide_ring(guide, 1 / 255, lay, sig, 1)
    assert (ring is None) == (pattern == "mask1")
    usable = ((res.flags & 3) == 0).astype(np.uint8)
    flags, out = np.zeros(lay.N, np.uint8), np.empty(lay.N)
    valid = np.full(lay.N, 7, np.uint8)
    _kernels.tofg_flying(res.depth, res.sigma, usable, col, cells, ring, lay.R, lay.C, 0.05, 2.0,
                         12.5, 0.15, 1, flags, out, 2, valid=valid)
    want_flags, want = ref.guided_flying(res.depth, res.sigma, usable, col, cells, ring, lay.R,
                                         lay.C, 0.05, 2.0, 12.5, 0.15, 1)
    assert (flags & 8).any()
    np.testing.assert_array_equal(flags, want_flags)
    np.testing.assert_array_equal(out, want)
    np.testing.assert_array_equal(valid, want_flags == 0)       # the final flags' zeros
    if ring is not None:
        # without the ring test some of the flagged measurements pass as pure
        loose = np.zeros(lay.N, np.uint8)
        _kernels.tofg_flying(res.depth, res.sigma, usable, col, cells, None, lay.R, lay.C, 0.05,
                             2.0, 12.5, 0.15, 1, loose, np.empty(lay.N), 2)
        assert ((flags & 8) >= (loose & 8)).all()
        assert ((flags & 8) > (loose & 8)).any()
        # the ring pixels of every Z pixel: the 12 pixels bordering its 2x2 cells
        r0, c0 = lay.rows[1], lay.cols[1]
        m = 1 * lay.C + 1
        want_ring = [guide[r0 + a, c0 + b] for a in range(-1, 3) for b in range(-1, 3)
                     if not (0 <= a < 2 and 0 <= b < 2)]
        np.testing.assert_allclose(ring[:, :, m] * (np.sqrt(2.0) * sig) * 255,
                                   np.asarray(want_ring, np.float64), rtol=1e-6)


@pytest.mark.parametrize("pattern,ambiguity", [("mask1", 1.0), ("mask2", 1.0), ("mask1", 0.2),
                                               ("mask2", 0.2)])
def test_upsample_matches_numpy(pattern, ambiguity):
    frame, guide, _ = _frame(pattern, shape=(24, 32))
    res = tof_depth(frame.tof, guide=guide)
    from rgbz_fast.tof._guided import _Layout, guide_colours
    lay = _Layout(res.sites, res.block, res.shape)
    col, _, sig = guide_colours(guide, 1 / 255, lay, 1)
    depth = np.where(res.valid, res.depth, np.nan)
    depth[::5] = np.nan                                  # holes: the fallback runs too
    half = 0.5 * (res.block - 1)
    rc, cc = lay.rows + half, lay.cols + half
    cscale = 1.0 / (np.sqrt(2.0) * sig)
    out, conf = np.empty(res.shape, np.float32), np.empty(res.shape, np.float32)
    args = (2 * res.block, 4, 0.125, 0.02, 3.0, 0.02)
    # own measurements in some holes: a constant, far from the rest (vetoes) or the
    # measured depth (agrees)
    own = np.full(depth.shape, np.nan)
    own[::10] = res.depth[::10] + np.where(np.arange(depth.size)[::10] % 20 == 0, 0.0, 0.5)
    sigma = np.ascontiguousarray(np.minimum(res.sigma, 0.05))
    _kernels.tofg_upsample(guide, 1 / 255, cscale, depth, sigma, col, lay.R, lay.C, rc, cc,
                           *args, own, 2.0, ambiguity, 0.05, out, conf, 2)
    want, wconf = ref.guided_upsample(guide, 1 / 255, cscale, depth, sigma, col, lay.R,
                                      lay.C, rc, cc, *args, own, 2.0, ambiguity, 0.05)
    if ambiguity < 1:
        assert np.isnan(want).any()
    np.testing.assert_array_equal(np.isnan(out), np.isnan(want))
    ok = np.isfinite(want)
    np.testing.assert_allclose(out[ok], want[ok], rtol=0, atol=1e-5)
    np.testing.assert_allclose(conf, wconf, rtol=1e-4, atol=1e-6)


@pytest.mark.parametrize("workers", [1, 2])
def test_agree_matches_numpy(workers):
    """rgbz_tofg_agree: usable measurements, candidates near and far from them, NaN ones,
    candidates side by side (which never confirm each other) and grid borders."""
    rng = np.random.default_rng(4)
    R, C = 23, 31
    depth = rng.uniform(1.0, 1.2, R * C)
    depth[rng.random(R * C) < 0.4] = np.nan                    # holes
    lone = (np.isnan(depth) & (rng.random(R * C) < 0.7)).astype(np.uint8)
    low = np.where(lone > 0, rng.uniform(0.95, 1.4, R * C), np.nan)
    low[rng.random(R * C) < 0.05] = np.nan                     # a candidate without a depth
    sigma = rng.uniform(0.001, 0.03, R * C)
    sigma[::17] = np.inf
    sigma[5::23] = np.nan                                      # tol_min alone, as for tol_k 0
    for tol_k in (3.0, 0.0):
        want_d, want_low = ref.guided_agree(depth, low, lone, sigma, R, C, tol_k, 0.02)
        d, lo = depth.copy(), low.copy()
        _kernels.tofg_agree(d, lo, lone, sigma, R, C, tol_k, 0.02, workers)
        taken = np.isnan(depth) & np.isfinite(d)
        assert 0 < taken.sum() < (lone > 0).sum()               # some confirmed, some not
        np.testing.assert_array_equal(d, want_d)               # copies: exact
        np.testing.assert_array_equal(lo, want_low)
    with pytest.raises(ValueError, match="tofg_agree"):
        _kernels.tofg_agree(d, lo, lone, sigma, R, C + 1, 3.0, 0.02, 1)


# --------------------------------------------------------------------------- the chain
@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_guided_chain_keeps_surfaces_apart(pattern):
    frame, guide, depth = _frame(pattern)
    tof = frame.tof
    plain = tof_depth(tof)
    res = tof_depth(tof, guide=guide)
    known = tof.valid
    err = np.abs(res.depth - tof.depth_true)
    assert res.valid[known].mean() >= plain.valid[known].mean()
    assert not np.any(res.valid & known & (err > 0.05))
    wall = (frame.tof.sites[0] < 8) & plain.valid & res.valid     # textured wall, no edge
    # the guide's wider window: 0.61x (Mask1), 0.81x (Mask2; 0.79x before the range term
    # took the fixed pattern's correlation, which weighs differences it cannot explain more)
    assert np.median(res.sigma[wall]) < 0.85 * np.median(plain.sigma[wall])
    assert np.array_equal(res.measured[res.flags & ToFFlag.RESOLVED == 0],
                          res.depth[res.flags & ToFFlag.RESOLVED == 0])
    a = ToFISP().run(tof, guide=guide, workers=1)
    b = ToFISP().run(tof, guide=guide.astype(np.float64) / 255, workers=2)
    np.testing.assert_array_equal(a.flags, res.flags)
    np.testing.assert_allclose(b.depth, a.depth, rtol=0, atol=1e-6)


def test_without_guide_the_isp_is_unchanged():
    frame, guide, _ = _frame("mask2")
    a, b = tof_depth(frame.tof), ToFISP().run(frame.tof, guide=None)
    for name in ("depth", "flags", "sigma", "count"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name))
    assert a.measured is a.depth


@pytest.mark.parametrize("denoise", ["box", "none"])
def test_guide_with_the_other_denoise_uses_the_colour_edges(denoise):
    frame, guide, _ = _frame("mask2", noise=False)
    plain = tof_depth(frame.tof, denoise=denoise)
    res = tof_depth(frame.tof, denoise=denoise, guide=guide)
    np.testing.assert_array_equal(res.measured, plain.depth)
    assert np.count_nonzero(res.flags & ToFFlag.FLYING) <= np.count_nonzero(
        plain.flags & ToFFlag.FLYING)


def test_guide_with_a_calibration_and_an_irregular_layout():
    from rgbz_fast.tof import calibrate

    sensor = ToFSensor(delay_ps=200.0)
    walls = []
    for d in np.linspace(0.6, 2.6, 20):
        fr = simulate(Scene(np.full((12, 16, 3), 0.5), depth=np.full((12, 16), d)), "mask2",
                      tof_sensor=sensor, noise=False)
        walls.append(fr.tof)
    cal = calibrate(walls, np.linspace(0.6, 2.6, 20))
    fr = simulate(Scene(np.full((12, 16, 3), 0.5), depth=np.full((12, 16), 1.3)), "mask2",
                  tof_sensor=sensor, noise=False)
    res = tof_depth(fr.tof, calibration=cal, guide=ColourISP().run(fr))
    np.testing.assert_allclose(res.depth, tof_depth(fr.tof, calibration=cal).depth, atol=1e-4)
    # measurements that do not fill their grid (here: every third one dropped)
    from dataclasses import replace

    wall = simulate(Scene(np.full((16, 24, 3), 0.5), depth=np.full((16, 24), 1.2)), "mask1",
                    noise=False)
    t = wall.tof
    keep = np.arange(t.n_sites) % 3 != 1
    holes = replace(t, taps=t.taps[..., keep], sites=tuple(a[keep] for a in t.sites),
                    depth_true=t.depth_true[keep], valid=t.valid[keep],
                    saturated=t.saturated[keep])
    res = tof_depth(holes, guide=ColourISP().run(wall))
    assert res.n_sites == keep.sum()
    np.testing.assert_allclose(res.depth, tof_depth(holes).depth, atol=1e-4)


def test_upsample_gives_a_depth_where_the_colour_can_choose():
    frame, guide, depth = _frame("mask2")
    res = tof_depth(frame.tof, guide=guide)
    up, conf = upsample_depth(res, guide)
    assert up.shape == conf.shape == res.shape and up.dtype == np.float32
    good = np.isfinite(up)
    # a 48 x 64 frame is mostly box edges: the pixels between two boxes' measurements whose
    # colour does not pick one get none
    assert good.mean() > 0.8
    assert np.mean(np.abs(up[good] - depth[good]) <= 0.05) > 0.98
    assert np.all((conf >= 0) & (conf <= 1)) and np.all(conf[~good] == 0)
    same, _ = upsample_depth(res, guide, workers=1)
    np.testing.assert_array_equal(same, up)
    # never abstaining covers (nearly) every pixel, with more of them off by 5 cm
    every, _ = upsample_depth(res, guide, ambiguity=1.0)
    assert np.isfinite(every).mean() > 0.97
    off = lambda u: int(np.sum(np.abs(u - depth)[np.isfinite(u)] > 0.05))   # noqa: E731
    assert off(up) < off(every) / 2


def test_resolved_depths_beyond_the_range_are_flagged_and_left_out():
    """H76: a resolved measurement takes a side's depth, and a side may be an aliased surface
    (beyond max_range) or inconsistent measurements: a resolved depth below 0 or beyond the
    range is flagged out of range, and upsample_depth takes no measurement flagged otherwise
    than flying or resolved (before: depths of -0.045 m and beyond max_range in the map)."""
    h, w = 48, 64
    img = np.full((h, w, 3), 0.4)
    img[:, w // 2:] = (0.1, 0.5, 0.2)                       # grey wall | green box
    z = np.where(np.arange(w) < w // 2, 2.0, 1.0) * np.ones((h, 1))
    frame = simulate(Scene(img, depth=z), "mask1", seed=1)
    guide = ColourISP().run(frame)
    res = ToFISP(max_range=1.5).run(frame.tof, guide=guide)
    resolved = (res.flags & ToFFlag.RESOLVED) > 0
    assert resolved.any()
    kept = resolved & ((res.flags & ToFFlag.OUT_OF_RANGE) == 0)
    assert np.all((res.depth[kept] >= 0) & (res.depth[kept] <= 1.5 - 5 * res.sigma[kept]))
    up, conf = upsample_depth(res, guide)
    good = np.isfinite(up)
    assert good.any() and np.all((up[good] >= 0) & (up[good] <= 1.5))


def test_upsample_takes_low_signal_measurements_below_max_sigma():
    """A measurement flagged low-signal alone with a sigma of at most max_sigma gives the
    map its depth when a usable neighbour agrees; above max_sigma, with another flag besides,
    or agreeing with no neighbour (a mixture at a depth edge), it only vetoes: its pixel
    refuses the neighbours' surface when that lies beyond 2 of its sigma."""
    import dataclasses
    frame, guide, _ = _frame("mask1")
    res = tof_depth(frame.tof, guide=guide)
    r, c = res.sites
    inbox = (r > 12) & (r < 28) & (c > 14) & (c < 28)       # the first box, 1.5 m
    marked = inbox & ((r // 2 + c // 2) % 2 == 0)            # every other measurement
    assert res.valid[inbox].all() and marked.sum() >= 20
    mixed = marked & (r == 20) & (c == 20)                   # one between box and wall

    def result(flag, sigma):
        flags, sig, d = res.flags.copy(), res.sigma.copy(), res.depth.copy()
        flags[marked], sig[marked] = flag, sigma
        d[marked] = res.depth[marked] + 0.01                # within 2 cm of the box
        d[mixed] = 1.75
        return dataclasses.replace(res, flags=flags, sigma=sig, depth=d, valid=flags == 0)

    low, both = int(ToFFlag.LOW_SIGNAL), int(ToFFlag.LOW_SIGNAL | ToFFlag.INCONSISTENT)
    agreeing = marked & ~mixed
    for flag, sigma, max_sigma, taken in [(low, 0.018, 0.02, True), (low, 0.018, np.inf, True),
                                          (low, 0.025, 0.02, False), (low, 0.018, None, False),
                                          (low, 0.018, 0, False), (both, 0.018, 0.02, False)]:
        given = result(flag, sigma)
        up, conf = upsample_depth(given, guide, max_sigma=max_sigma)
        at = up[r[agreeing], c[agreeing]]                   # Mask1: a Z site's pixel takes
        if taken:                                           # its own node alone
            np.testing.assert_allclose(at, given.depth[agreeing], atol=1e-6)
        else:                                               # filled from the box around
            assert np.all(np.abs(at - res.depth[agreeing] - 0.01) > 1e-3)
            assert np.all(np.abs(at - 1.5) < 0.03)
        assert np.isnan(up[20, 20]) and conf[20, 20] == 0   # the mixture: a veto
    with pytest.raises(ValueError, match="max_sigma"):
        upsample_depth(res, guide, max_sigma=-0.01)
    with pytest.raises(TypeError, match="max_sigma"):
        upsample_depth(res, guide, max_sigma="0.02")


@pytest.mark.parametrize("guide,exc,msg", [
    (np.zeros((48, 64)), ValueError, "guide: expected a colour image of shape"),
    (np.zeros((40, 64, 3)), ValueError, "guide: the image is 40x64, the frame 48x64"),
    (np.full((48, 64, 3), np.nan), ValueError, "guide: holds 9216 NaN"),
    (np.full((48, 64, 3), 2.0), ValueError, r"guide: float values span \[2, 2\]"),
    (np.zeros((48, 64, 3), bool), TypeError, "guide: expected colour values"),
    ("image.png", TypeError, "guide: "),
])
def test_bad_guides_name_the_guide(guide, exc, msg):
    frame, _, _ = _frame("mask2")
    with pytest.raises(exc, match=msg):
        tof_depth(frame.tof, guide=guide)
    res = tof_depth(frame.tof)
    with pytest.raises(exc, match=msg):
        upsample_depth(res, guide)


def test_upsample_refuses_what_is_not_a_result():
    with pytest.raises(TypeError, match="result: expected a ToFDepth"):
        upsample_depth(np.zeros(4), np.zeros((2, 2, 3)))
    frame, guide, _ = _frame("mask2")
    with pytest.raises(ValueError, match="colour_scale"):
        upsample_depth(tof_depth(frame.tof), guide, colour_scale=0)
    for bad in (-0.1, 1.5):
        with pytest.raises(ValueError, match="ambiguity"):
            upsample_depth(tof_depth(frame.tof), guide, ambiguity=bad)


def test_the_layout_is_made_once_per_read_only_sites():
    from rgbz_fast.tof import _guided

    frame, guide, _ = _frame("mask1")
    tof = frame.tof
    first = _guided._layout_of(tof.sites, tof.block, tof.shape)
    assert _guided._layout_of(tof.sites, tof.block, tof.shape) is first   # a ToFTaps' own
    res = tof_depth(tof, guide=guide)
    assert _guided._layout_of(res.sites, res.block, res.shape) is first   # its result's
    # arrays a caller may still write, or other arrays of the same values: made again
    rows, cols = (a.copy() for a in tof.sites)
    again = _guided._layout_of((rows, cols), tof.block, tof.shape)
    assert again is not first and _guided._layout_of((rows, cols), tof.block, tof.shape) \
        is not again
    np.testing.assert_array_equal(again.rows, first.rows)
    # a second call on the cached layout gives the first's result bit for bit
    again_res = tof_depth(tof, guide=guide)
    for k in ("depth", "flags", "count", "phase", "measured"):
        np.testing.assert_array_equal(getattr(again_res, k), getattr(res, k))
    assert len(_guided._LAYOUTS) <= _guided._LAYOUTS_KEPT


def test_clipped_taps_are_saturated_with_a_dark_calibration():
    """The guided chain tests the raw taps against the white level before the dark offsets
    come off, as the unguided one does: a tap clipped at 2047 with a 3 DN dark offset had read
    2044, and 96 clipped measurements of a wall at 1.2 m came out valid at 7.49 m."""
    import dataclasses

    from rgbz_fast import isp, tof
    from rgbz_fast.simulation import Scene, simulate

    frame = simulate(Scene(np.full((32, 48, 3), 0.4), depth=np.full((32, 48), 1.2)), "mask2",
                     seed=1)
    t = frame.tof
    taps = t.taps.copy()
    taps[:, 0, :] = t.white_level                     # tap 0 clipped, no sensor flag
    t = dataclasses.replace(t, taps=taps, saturated=np.zeros(t.n_sites, bool))
    n, F = t.n_sites, len(t.frequencies)
    cal = tof.ToFCalibration(t.frequencies, np.zeros((F, n)), np.zeros((F, 1, 2)), t.sites,
                             t.block, t.shape, dark=np.full((4, n), 3.0))
    guide = isp.ColourISP().run(frame)
    for g in (None, guide):
        r = tof.tof_depth(t, guide=g, calibration=cal)
        assert not r.valid.any()
        assert np.all(r.flags & tof.FLAG_SATURATED)


def test_to_frame_of_a_flag_field_with_a_nan_fill_is_float32():
    from rgbz_fast import tof
    from rgbz_fast.simulation import Scene, simulate

    frame = simulate(Scene(np.full((16, 16, 3), 0.5), depth=np.full((16, 16), 1.5)), "mask1",
                     seed=0)
    r = tof.tof_depth(frame.tof)
    assert r.to_frame("valid").dtype == np.float32 and r.to_frame("flags").dtype == np.float32
    assert r.to_frame("valid", fill=False).dtype == np.bool_
    assert r.to_frame("depth").dtype == np.float64


@pytest.mark.parametrize("guided", [True, False])
def test_low_signal_window_reruns_only_the_low_signal_measurements(guided):
    """ToFISP(low_signal_window=W): the measurements the default flags low-signal alone take
    the wider window's result where the two depths agree within the default's sigma; every
    other measurement keeps the default's result, field by field."""
    sensor = ToFSensor(optical_power_w=0.2)                      # photon-limited
    frame, guide, _ = _frame("mask1", shape=(64, 96), sensor=sensor)
    g = guide if guided else None
    base = ToFISP().run(frame.tof, guide=g)
    wide = ToFISP(window=41).run(frame.tof, guide=g)     # wider than Mask1's guided 31
    both = ToFISP(low_signal_window=41).run(frame.tof, guide=g)
    take = (base.flags == ToFFlag.LOW_SIGNAL) & (np.abs(wide.depth - base.depth) <= base.sigma)
    assert 0 < take.sum() < take.size and both.valid.sum() > base.valid.sum()
    for name in ("depth", "sigma", "flags", "valid", "snr", "amplitude", "phase"):
        got, a, b = (np.asarray(getattr(r, name)) for r in (both, base, wide))
        np.testing.assert_array_equal(got[..., ~take], a[..., ~take])
        np.testing.assert_array_equal(got[..., take], b[..., take])
    with pytest.raises(ValueError, match="low_signal_window"):
        ToFISP(low_signal_window=40)


@pytest.mark.parametrize("pattern,shape,d", [("mask1", (256, 256), 0.3),
                                             ("mask1", (256, 256), 1.0),
                                             ("mask2", (384, 384), 0.5),
                                             ("mask2", (384, 384), 2.0)])
def test_guided_sigma_matches_the_spread_on_walls(pattern, shape, d):
    """The guided ISP's sigma against the spread of the valid depths of a flat wall
    (reflectance 0.5, 3 frames, the measurements away from the border): within 0.9-1.2x.
    Near the wall, where the taps' PRNU dominates, sigma had summed each frequency's share
    of the fixed pattern as independent: 1.21x (Mask1, 0.3 m) and 1.34x (Mask2, 0.5 m) on
    these frames; now 1.09x and 1.16x (docs/reports/isp.md)."""
    scene = Scene(np.full(shape + (3,), 0.5), depth=np.full(shape, d),
                  ir_reflectance=np.full(shape, 0.5))
    errs, sig = [], []
    for j in range(3):
        frame = simulate(scene, pattern, seed=21 + 1000 * j)
        res = tof_depth(frame.tof, guide=ColourISP().run(frame))
        r, c = frame.tof.sites
        m = 12 * frame.tof.block
        inner = (r >= m) & (r < shape[0] - m) & (c >= m) & (c < shape[1] - m) & res.valid
        assert inner.mean() > 0.7
        errs.append(res.depth[inner] - d)
        sig.append(res.sigma[inner])
    e, s = np.concatenate(errs), np.concatenate(sig)
    ratio = e.std() / np.sqrt(np.mean(s ** 2))
    assert 0.9 < ratio < 1.2, ratio


def test_a_low_signal_window_must_be_wider_than_the_chains():
    """Review of 2026-11-27: with Mask1's guided window at 31, low_signal_window=31 ran the
    chain twice for nothing and 21 gave the low-signal measurements a narrower window than
    the others, while the docs call it the wider one."""
    frame, guide, _ = _frame("mask1", shape=(32, 48))
    for w, g in ((31, guide), (21, guide), (9, None)):
        with pytest.raises(ValueError, match=r"^low_signal_window: \d+ is not wider than the "
                                             r"window the chain runs with here"):
            ToFISP(low_signal_window=w).run(frame.tof, guide=g)
    ToFISP(low_signal_window=11).run(frame.tof)                   # unguided: 9
    ToFISP(low_signal_window=33).run(frame.tof, guide=guide)
