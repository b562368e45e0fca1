"""SG on Mask2 as straight-line code (csrc/recon_mask2.h) against the plan interpreter.

The header is written by tools/gen_recon_mask2.py from the plans of ``_plans.py``;
the frame loop runs its functions on a plan equal to one of them byte for byte
(float32, the fast exponential) and the interpreter on any other. Its results
must be the interpreter's bit for bit: the same IEEE operations in the same order.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import rgbz_fast as rz
from _support import REPO
from rgbz_fast import _kernels, _kernels_count
from rgbz_fast._patterns import get_pattern
from rgbz_fast.reconstruction import _plans
from rgbz_fast.reconstruction._reconstruct import plans_only


def _indices(kernels, pattern, method="sg", **kw):
    _, plans = _plans.build_plans(get_pattern(pattern), method, **kw)
    return [kernels.mask2_plan_index(np.frombuffer(p.tobytes(), np.uint8)) for p in plans]


def test_header_is_the_generators_output():
    """csrc/recon_mask2.h is what tools/gen_recon_mask2.py writes for today's plans."""
    r = subprocess.run([sys.executable, str(REPO / "tools" / "gen_recon_mask2.py"), "--check"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, (r.stdout + r.stderr).strip() or "run tools/gen_recon_mask2.py"


def test_which_plans_run_the_straight_line_code():
    """SG combined on Mask2, intensity domain, every Bayer phase: its plans; nothing else."""
    assert _indices(_kernels, "mask2") == [0, 1, 2, 3]
    seen = set()
    for phase in rz.BAYER_PHASES:
        idx = _indices(_kernels, f"mask2_{phase.lower()}")
        assert min(idx) >= 0, phase
        seen.update(idx)
    assert len(seen) == 12                                   # the distinct plans
    assert _indices(_kernels, "mask2", sg_mode="combined") == [0, 1, 2, 3]
    assert _indices(_kernels, "mask2", sg_mode="pure") == [-1] * 4
    assert _indices(_kernels, "mask2", domain="colour_difference") == [-1] * 4
    assert _indices(_kernels, "mask2", "edi_line") == [-1] * 4
    assert _indices(_kernels, "mask1") == [-1]
    # the counting build counts the interpreter's operations (the same ones)
    assert _indices(_kernels_count, "mask2") == [-1] * 4


def test_the_generic_switch():
    before = _kernels.mask2_generic()
    assert before == 0
    assert _kernels.mask2_generic(1) == 0 and _kernels.mask2_generic() == 1
    assert _kernels.mask2_generic(0) == 1 and _kernels.mask2_generic() == 0
    assert _kernels_count.mask2_generic() == -1                # no such code there


def test_plan_index_rejects_a_wrong_size():
    with pytest.raises(ValueError, match="plan: expected"):
        _kernels.mask2_plan_index(np.zeros(10, np.uint8))


def _frame(kind, shape, rng, pattern="mask2"):
    if kind == "smooth":
        y, x = np.mgrid[0:shape[0], 0:shape[1]]
        img = 0.5 + 0.4 * np.sin(x / 7.0)[..., None] * np.cos(y / 5.0)[..., None] * [1, 0.8, 0.6]
    elif kind == "noise":
        img = rng.random(shape + (3,))
    elif kind == "flat":
        img = np.full(shape + (3,), 0.37)
    elif kind == "spiky":                     # mostly near 0, a few large values
        img = rng.random(shape + (3,)) ** 12
    else:                                     # edges: a step and a thin line
        img = np.zeros(shape + (3,))
        img[:, shape[1] // 3:] = 0.9
        img[shape[0] // 2, :] = 0.5
    return rz.mosaic(img, pattern).data


@pytest.fixture(params=["cpu", "generic"])
def instance(request):
    """Each test on the CPU's instance of the code (AVX-512F here where it runs) and on the
    generic one (what other CPUs run)."""
    before = _kernels.mask2_generic(int(request.param == "generic"))
    yield request.param
    _kernels.mask2_generic(before)


def _same(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("kind", ["smooth", "noise", "flat", "spiky", "edges"])
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
def test_same_bits_as_the_interpreter(kind, dtype, instance):
    """Every element type, sizes whose Z rows end in a partial vector, 1 and 2 threads."""
    rng = np.random.default_rng(sum(map(ord, kind + np.dtype(dtype).name)))
    for shape in [(12, 12), (37, 53), (64, 270)]:
        d = _frame(kind, shape, rng)
        if dtype == np.uint8:
            d = (d >> 3).astype(np.uint8)
        elif dtype != np.uint16:                # DN with fractions
            d = (d * np.float64(0.999)).astype(dtype)
        kw = {"bit_depth": 8} if dtype == np.uint8 else {}
        for workers in (1, 2):
            fast = rz.reconstruct(d, "sg", pattern="mask2", workers=workers, **kw)
            with plans_only():
                slow = rz.reconstruct(d, "sg", pattern="mask2", workers=workers, **kw)
            assert _same(fast, slow), (kind, np.dtype(dtype).name, shape, workers)


@pytest.mark.parametrize("phase", ["RGGB", "BGGR", "GBRG"])
def test_same_bits_at_every_bayer_phase(phase, instance):
    rng = np.random.default_rng(11)
    pat = f"mask2_{phase.lower()}"
    for kind in ("noise", "edges"):
        d = _frame(kind, (36, 61), rng, pat)
        for workers in (1, 2):
            fast = rz.reconstruct(d, "sg", pattern=pat, workers=workers)
            with plans_only():
                slow = rz.reconstruct(d, "sg", pattern=pat, workers=workers)
            assert _same(fast, slow), (kind, workers)
            df = (d * np.float64(0.999)).astype(np.float32)
            fast = rz.reconstruct(df, "sg", pattern=pat, workers=workers)
            with plans_only():
                slow = rz.reconstruct(df, "sg", pattern=pat, workers=workers)
            assert _same(fast, slow), (kind, workers, "float32")


@pytest.mark.parametrize("params", [
    {"sigma_rel": 0},                      # eq. 7 as printed: sigma the least gradient
    {"sigma_rel": 0.5},
    {"sigma_rel": 10},
    {"sigma_floor": 1e-9},
    {"sigma_floor": 500.0},
    {"clip_level": 0.7},                   # clipped sites computed again on the plans
])
def test_same_bits_for_every_setting(params, instance):
    rng = np.random.default_rng(7)
    d = (_frame("noise", (40, 70), rng) / 2047.0).astype(np.float32)
    fast = rz.reconstruct(d, "sg", pattern="mask2", **params)
    with plans_only():
        slow = rz.reconstruct(d, "sg", pattern="mask2", **params)
    assert _same(fast, slow)


def test_same_bits_at_the_extremes(instance):
    """Subnormal, zero and full-scale taps (the frame check refuses NaN, infinities and values
    beyond the bit depth before the kernel), where weights underflow or the sums of beta
    and of the gradients are 0, and the result falls back to the candidates' mean."""
    rng = np.random.default_rng(3)
    for scale in (1e-40, 1e-30, 0.0, 1.0):
        d = (_frame("noise", (30, 45), rng) * scale).astype(np.float32)
        d[::3, ::5] = np.float32(2047.0)
        d[1::4, ::7] = np.float32(1e-45)
        fast = rz.reconstruct(d, "sg", pattern="mask2")
        with plans_only():
            slow = rz.reconstruct(d, "sg", pattern="mask2")
        assert _same(fast, slow), scale


def test_other_exponentials_run_the_interpreter():
    """exp='libm' (float32) and float64 are not the straight-line code's: same as plans_only."""
    rng = np.random.default_rng(5)
    d = _frame("smooth", (24, 40), rng)
    for kw in ({"exp": "libm"}, {"precision": "float64"}):
        a = rz.reconstruct(d, "sg", pattern="mask2", **kw)
        with plans_only():
            b = rz.reconstruct(d, "sg", pattern="mask2", **kw)
        assert _same(a, b)
