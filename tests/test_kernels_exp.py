"""exp="libm" gives the C library's exp() (expf() in float32) bit for bit, however the kernel
computes it.

Eq. 7's gamma factors run through a vector port of glibc's exp() / expf() (csrc/rgbz_exp.h)
where ``_kernels.libm_exp_vectorised()`` says this machine's function is that algorithm;
everywhere else through the function itself. Either way the values are the C library's:
these tests hold the results to Python's math.exp (which calls the same exp()) and to expf()
called through ctypes, the ports to a Python model of glibc's algorithms (each fused
multiply-add rounded once through Fraction), the tables to 2^(i/128) and 2^(i/32) computed
in 60-digit decimals, and the reconstruction to the counting extension, whose scalar loops
call the function one value at a time. Where the machine's functions are that algorithm and
the CPU runs AVX-512F, the port must be in use.
"""
import math
import platform
import re
from decimal import Decimal, getcontext
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast import _kernels, _kernels_count
from rgbz_fast.reconstruction import ReconstructParams
from rgbz_fast.reconstruction._plans import build_plans
from rgbz_fast.reconstruction._reconstruct import _run_kernel

HEADER = Path(__file__).resolve().parents[1] / "csrc" / "rgbz_exp.h"


def _bits(a):
    return np.asarray(a, np.float64).view(np.uint64)


def test_libm_exp_is_math_exp_bit_for_bit():
    rng = np.random.default_rng(7)
    # eq. 7's arguments are -G^2 / (2 sigma^2) <= 0: in [-128, 0] with the default sigma_rel,
    # anything below with sigma_rel=0; the port covers 2^-54 <= |x| < 512 and exp() the rest
    parts = [-rng.random(40_000) * s for s in (1e-15, 1e-6, 1e-2, 1.0, 8.0, 36.0, 128.0,
                                              511.999, 745.0, 800.0)]
    edges = np.array([0.0, -0.0, -2.0 ** -54, -2.0 ** -55, -2.0 ** -53, -5e-324, -1e-310,
                      -511.99999999999994, -512.0, -708.39, -708.4, -744.44, -745.2,
                      -math.log(2) / 256, -math.log(2) / 128, -1.0, -np.inf, 0.5, 1e-300])
    x = np.concatenate(parts + [edges])
    out = np.empty_like(x)
    _kernels.libm_exp(x, out)
    ref = np.array([math.exp(v) for v in x])
    differ = np.flatnonzero(_bits(out) != _bits(ref))
    assert differ.size == 0, f"{differ.size} differ, first x = {x[differ[0]]!r}"


def _c_expf():
    import ctypes
    import ctypes.util

    name = ctypes.util.find_library("m")
    if name is None:
        pytest.skip("no C math library to call expf() from")
    lib = ctypes.CDLL(name)
    lib.expf.restype, lib.expf.argtypes = ctypes.c_float, [ctypes.c_float]
    return lib.expf


def test_libm_expf_is_the_c_librarys_expf_bit_for_bit():
    expf = _c_expf()
    rng = np.random.default_rng(8)
    parts = [-rng.random(20_000) * s for s in (1e-30, 1e-6, 1.0, 8.0, 36.0, 87.99, 104.0, 200.0)]
    edges = np.array([0.0, -0.0, -1e-45, -87.99999, -88.0, -103.9, -104.0, -np.inf, 1.0, 88.5])
    x = np.concatenate(parts + [edges]).astype(np.float32)
    out = np.empty_like(x)
    _kernels.libm_exp(x, out)
    ref = np.array([expf(float(v)) for v in x], np.float32)
    differ = np.flatnonzero(out.view(np.uint32) != ref.view(np.uint32))
    assert differ.size == 0, f"{differ.size} differ, first x = {x[differ[0]]!r}"


def test_libm_exp_of_nan_is_nan():
    out = np.empty(2)
    _kernels.libm_exp(np.array([np.nan, -np.nan]), out)
    assert np.isnan(out).all()


def test_the_tables_are_powers_of_two():
    # tab[2i + 1] + (i << 45) is the double nearest 2^(i/128); tab[2i] the relative
    # correction to it, rounded
    text = HEADER.read_text()
    body = re.search(r"rgbz_exp_tab\[256\] = \{(.*?)\};", text, re.S).group(1)
    tab = [int(v, 16) for v in re.findall(r"0x([0-9a-f]{16})u", body)]
    assert len(tab) == 256
    getcontext().prec = 60
    for i in range(128):
        exact = Decimal(2) ** (Decimal(i) / 128)
        s = float(exact)
        tail = float((exact - Decimal(s)) / Decimal(s))
        assert (tab[2 * i + 1] + (i << 45)) % 2 ** 64 == int(_bits(s)), i
        assert tab[2 * i] == int(_bits(tail)), i
    # expf()'s: tabf[i] + (i << 47) is the double nearest 2^(i/32)
    body = re.search(r"rgbz_expf_tab\[32\] = \{(.*?)\};", text, re.S).group(1)
    tabf = [int(v, 16) for v in re.findall(r"0x([0-9a-f]{16})u", body)]
    assert len(tabf) == 32
    for i in range(32):
        s = float(Decimal(2) ** (Decimal(i) / 32))
        assert (tabf[i] + (i << 47)) % 2 ** 64 == int(_bits(s)), i


def _cpu_flags():
    try:
        text = Path("/proc/cpuinfo").read_text()
    except OSError:
        return set()
    line = next((ln for ln in text.splitlines() if ln.startswith("flags")), "")
    return set(line.split(":", 1)[-1].split())


# -- a model of glibc's algorithms: every fused multiply-add rounded once, exactly (Fraction) --

_H = float.fromhex

def _fma(a, b, c):
    return float(Fraction(a) * Fraction(b) + Fraction(c))


def _u64(x):
    return int(np.float64(x).view(np.uint64))


def _f64(u):
    return float(np.uint64(u % 2 ** 64).view(np.float64))


def _tables():
    text = HEADER.read_text()
    out = []
    for name in ("rgbz_exp_tab", "rgbz_expf_tab"):
        body = re.search(name + r"\[\d+\] = \{(.*?)\};", text, re.S).group(1)
        out.append([int(v, 16) for v in re.findall(r"0x([0-9a-f]{16})u", body)])
    return out


def _exp_model(x, tab):
    """glibc's exp() (its x86-64 FMA build, __exp_fma) for 2^-54 <= |x| < 512."""
    shift = _H("0x1.8p52")
    kd = _fma(x, _H("0x1.71547652b82fep7"), shift)
    ki = _u64(kd)
    kd -= shift
    r = _fma(kd, -_H("0x1.cf79abc9e3b3ap-47"), _fma(kd, -_H("0x1.62e42fefa0000p-8"), x))
    idx = 2 * (ki & 127)
    tail, scale = _f64(tab[idx]), _f64(tab[idx + 1] + (ki << 45))
    r2 = r * r
    p23 = _fma(r, _H("0x1.555555555543cp-3"), _H("0x1.ffffffffffdbdp-2"))
    p45 = _fma(r, _H("0x1.1111167a4d017p-7"), _H("0x1.55555cf172b91p-5"))
    return _fma(scale, _fma(r2 * r2, p45, _fma(p23, r2, r + tail)), scale)


def _expf_model(x, tabf):
    """glibc's expf() (__expf_fma) for |x| < 88, x a float32."""
    xd, shift, inv = float(x), _H("0x1.8p52"), _H("0x1.71547652b82fep5")
    kd = _fma(inv, xd, shift)
    ki = _u64(kd)
    kd -= shift
    r = _fma(inv, xd, -kd)
    s = _f64(tabf[ki & 31] + (ki << 47))
    z = _fma(r, _H("0x1.c6af84b912394p-20"), _H("0x1.ebfce50fac4f3p-13"))
    y = _fma(z, r * r, _fma(r, _H("0x1.62e42ff0c52d6p-6"), 1.0))
    return np.float32(y * s)


def _sample():
    rng = np.random.default_rng(11)
    x = np.concatenate([-rng.random(300) * s for s in (1e-6, 1.0, 8.0, 36.0, 128.0, 511.9)])
    return np.concatenate([x, [0.0, -0.0, -2.0 ** -54, -1.0, 1.0, 88.5]])


def test_the_ports_are_glibcs_algorithms():
    # the C ports, value by value, against the model of glibc's algorithms: the same bits
    # (on any machine: fma() is exact wherever it runs)
    tab, tabf = _tables()
    x = _sample()
    out = np.empty_like(x)
    _kernels.exp_port(x, out)
    model = np.array([_exp_model(float(v), tab) for v in x])
    assert np.array_equal(_bits(out), _bits(model))
    xf = np.clip(x, -87.9, 87.9).astype(np.float32)
    outf = np.empty_like(xf)
    _kernels.exp_port(xf, outf)
    modelf = np.array([_expf_model(v, tabf) for v in xf], np.float32)
    assert np.array_equal(outf.view(np.uint32), modelf.view(np.uint32))


def test_vectorised_where_the_c_library_is_that_algorithm():
    # where the CPU runs AVX-512F and this machine's exp() / expf() give the model's bits,
    # the start-up sweep must find it and vectorise; a port that had drifted would fail the
    # sweep and leave every call on the C library's function
    if platform.machine() != "x86_64" or platform.libc_ver()[0] != "glibc" \
            or not {"avx512f", "fma"} <= _cpu_flags():
        pytest.skip("the vector port runs on x86-64 glibc with AVX-512F only")
    tab, tabf = _tables()
    x = _sample()
    if any(math.exp(v) != _exp_model(float(v), tab) for v in x):
        pytest.skip("this machine's exp() is not the algorithm of glibc's FMA build")
    assert _kernels.libm_exp_vectorised()
    expf = _c_expf()
    xf = np.clip(x, -87.9, 87.9).astype(np.float32)
    if any(np.float32(expf(float(v))) != _expf_model(v, tabf) for v in xf):
        pytest.skip("this machine's expf() is not the algorithm of glibc's FMA build")
    assert _kernels.libm_exp_vectorised(single=True)


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
@pytest.mark.parametrize("method", ["sg", "edi_line", "bi"])
@pytest.mark.parametrize("sigma_rel", [0.5, 0.0])
@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_reconstruction_with_libm_equals_the_scalar_exp_build(pattern, method, sigma_rel,
                                                              precision):
    # the counting extension runs one site per block and calls exp() per value: the frame
    # loop of _kernels (vectorised exponentials where it can) must give the same bits.
    # sigma_rel=0 leaves arguments below -512, which go to exp() one by one.
    rng = np.random.default_rng(3)
    pat = rz.get_pattern(pattern)
    y, x = np.mgrid[:48, :64]
    img = np.stack([np.sin(x / 5.0 + c) * np.cos(y / 7.0) for c in range(3)], -1) * 0.4 + 0.5
    img = np.clip(img + rng.normal(0, 0.02, img.shape), 0, 1)
    img[:, :20] = 0.3                                             # flat: G = 0, exp(-0)
    frame = rz.mosaic(img, pat, 11)
    src = np.ascontiguousarray(frame.data)
    params = ReconstructParams(precision=precision, exp="libm", sigma_rel=sigma_rel)
    plan_map, plans = build_plans(pat, method)
    n_plans = len(plans)
    plans = plans.view(np.uint8).reshape(-1)
    out = np.empty_like(src)
    _run_kernel(src, out, pat, method, params, plan_map, plans, n_plans, 11, None, 1)
    ref = np.empty_like(src)
    counts = np.zeros(n_plans * _kernels_count.NOPS, np.uint64)
    _run_kernel(src, ref, pat, method, params, plan_map, plans, n_plans, 11, None, 1,
                opcounts=counts, kernels=_kernels_count)
    assert np.array_equal(out, ref)
