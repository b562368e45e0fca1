"""The compiled modules themselves: exported symbols, the counting split, the constants
taken from the C enums, the Mask1 plans compiled into C, the fast exponential."""

from __future__ import annotations

import math
import shutil
import subprocess

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast import _kernels, _kernels_count
from rgbz_fast.reconstruction._plans import PLAN_DTYPE, build_plans

MODULES = {"_kernels": _kernels, "_kernels_count": _kernels_count}


# -- symbols ------------------------------------------------------------------------------------

def _dynamic_symbols(path):
    out = subprocess.run(["nm", "-D", "--defined-only", str(path)], check=True,
                         capture_output=True, text=True).stdout
    return sorted(line.split()[-1] for line in out.splitlines() if line.strip())


@pytest.mark.parametrize("name", sorted(MODULES))
def test_extension_exports_only_its_init_function(name):
    # -fvisibility=hidden and the linker version script (src/rgbz_fast/meson.build): the C
    # core's names (the same in both extensions) stay private
    if shutil.which("nm") is None:
        pytest.skip("nm is not available")
    assert _dynamic_symbols(MODULES[name].__file__) == [f"PyInit_{name}"]


def test_counting_code_only_in_the_counting_module():
    assert not _kernels.counting_build() and _kernels_count.counting_build()
    d = np.zeros((8, 8), np.uint16)
    phase_map, plans = build_plans(rz.mask1(), "bi")
    args = (d, np.empty_like(d), 1, 2, 2, phase_map, plans.view(np.uint8).reshape(-1), 1,
            1e-3, 0.0, 0.5, 2047.0, 0, 1)
    with pytest.raises(ValueError, match="_kernels_count"):
        _kernels.reconstruct(*args, opcounts=np.zeros(_kernels.NOPS, np.uint64))
    with pytest.raises(ValueError, match="opcounts"):
        _kernels_count.reconstruct(*args)
    counts = np.zeros(_kernels_count.NOPS, np.uint64)
    _kernels_count.reconstruct(*args, opcounts=counts)
    assert counts[_kernels_count.OP_CATEGORIES["div"]] > 0
    if shutil.which("nm") is not None:
        out = subprocess.run(["nm", str(_kernels.__file__)], capture_output=True, text=True)
        assert "rgbz_opc_cur" not in out.stdout          # (an empty table if stripped)


def test_counting_module_bridges_the_counted_kernels_only():
    # _kernels_count.pyx is _kernels_common.pxi alone: the counted kernels and the constants,
    # the same objects' names and values as in _kernels
    public = {n for n in dir(_kernels_count) if not n.startswith("_")}
    assert {"reconstruct", "learned", "tof_demodulate", "plan_layout"} <= public
    assert not {"demosaic_malvar", "ssim_sums", "oetf_finish", "tof_bilateral"} & public
    assert public <= set(dir(_kernels))
    for name in ("NOPS", "PLAN_LIMITS", "METHODS", "PRECISIONS", "EXP_MODES", "OP_CATEGORIES"):
        assert getattr(_kernels_count, name) == getattr(_kernels, name)


@pytest.mark.parametrize("name", sorted(MODULES))
def test_a_precision_code_without_a_kernel_is_refused(name):
    # _kernels_of, the bridge's one switch over the precisions, names the parameter
    k = MODULES[name]
    bad = max(k.PRECISIONS.values()) + 1
    d = np.zeros((8, 8), np.uint16)
    phase_map, plans = build_plans(rz.mask1(), "bi")
    counts = {"opcounts": np.zeros(k.NOPS, np.uint64)} if k.counting_build() else {}
    with pytest.raises(ValueError, match="precision"):
        k.reconstruct(d, np.empty_like(d), bad, 2, 2, phase_map,
                      plans.view(np.uint8).reshape(-1), 1, 1e-3, 0.0, 0.5, 2047.0, 0, 1,
                      **counts)
    i32, f64 = np.zeros((1, 1), np.int32), np.zeros((1, 1), np.float64)
    with pytest.raises(ValueError, match="precision"):
        k.learned(d, np.empty_like(d), bad, 2, 2, phase_map, np.ones(1, np.int32), i32, i32,
                  np.ones((1, 4), np.int32), np.zeros((1, 4, 1), np.int32),
                  np.zeros((1, 4, 1), np.int32), np.zeros((1, 4, 1), np.int32),
                  np.ones((1, 3)), np.array([1, 0, 2, 1], np.int32), f64, f64, f64,
                  np.zeros((1, 1, 8), np.float32), np.zeros((1, 1, 8)), 0, 0, 2047.0, 1,
                  **counts)


# -- constants from the C enums -----------------------------------------------------------------

def test_tables_come_from_the_c_enums():
    from rgbz_fast._devtools import opcount
    from rgbz_fast.isp import DEMOSAIC_METHODS, DEMOSAIC_MODES
    from rgbz_fast.reconstruction import METHODS as ALL_METHODS
    from rgbz_fast.reconstruction import PRECISIONS
    from rgbz_fast.reconstruction._plans import METHODS
    from rgbz_fast.reconstruction._reconstruct import _EXP_CODES, _PRECISION_CODES

    assert METHODS == {"bilinear": 0, "bi": 1, "edi_central": 2, "edi_line": 3, "sg": 4,
                       "edi_rows": 5}
    assert METHODS == {m.name[len("RGBZ_M_"):].lower(): int(m) for m in _kernels.rgbz_method}
    assert ALL_METHODS == (*METHODS, "learned", "z_guided")   # the plan methods, csrc/learned.c
    assert _PRECISION_CODES == {"float32": 0, "float64": 1, "fixed": 2}
    assert tuple(_PRECISION_CODES) == PRECISIONS          # the names ReconstructParams accepts
    assert _EXP_CODES == {"libm": 0, "fast": 1}
    assert DEMOSAIC_MODES == {"reflect": 0, "period": 1}
    assert _kernels.DEMOSAIC_KERNELS == {"malvar2004": 0, "bilinear": 1, "menon2007": 2}
    assert set(_kernels.DEMOSAIC_KERNELS) <= set(DEMOSAIC_METHODS)
    assert opcount.CATEGORIES == ("add", "mul", "div", "exp", "abs", "cmp", "sqrt", "atan2")
    assert len(opcount.CATEGORIES) == _kernels.NOPS
    assert int(_kernels.rgbz_status.RGBZ_EINVAL) == 1


def test_plan_dtype_matches_the_compiled_struct():
    from rgbz_fast.reconstruction._plans import check_layout

    layout = _kernels.plan_layout()
    assert layout[0] == PLAN_DTYPE.itemsize
    check_layout(layout)
    check_layout(_kernels_count.plan_layout())


# -- the Mask1 plans of csrc/recon_mask1.h ------------------------------------------------------

def _offsets(plan):
    n = int(plan["n_taps"])
    return [(int(plan["tap_dy"][t]), int(plan["tap_dx"][t])) for t in range(n)]


def _pairs(plan):
    off = _offsets(plan)
    return sorted((tuple(sorted((off[plan["pair_a"][i]], off[plan["pair_b"][i]]))),
                   int(plan["pair_gmask"][i])) for i in range(int(plan["n_pairs"])))


@pytest.mark.parametrize("method,sg_mode", [("bilinear", "auto"), ("bi", "auto"),
                                            ("edi_central", "auto"), ("edi_line", "auto"),
                                            ("sg", "pure"), ("sg", "combined")])
@pytest.mark.parametrize("phase", ["GRBG", "RGGB", "BGGR", "GBRG"])
def test_compiled_mask1_plans_are_those_of_the_python_builder(method, sg_mode, phase):
    # the interior sites of Mask1 run constant plans compiled into C; they must be the plans
    # _plans.py builds, up to the order of the pairs (the historical order of each path,
    # csrc/recon_mask1.h) and the two fields that keep the operation counts of each path
    _, plans = build_plans(rz.mask1(phase), method, sg_mode)
    py = plans[0]
    c = np.frombuffer(_kernels.mask1_plan(_kernels.METHODS[method], sg_mode == "combined"),
                      PLAN_DTYPE)[0]
    for f in ("method", "n_cand", "n_pairs", "use_ab", "use_grad", "use_sg", "sg_scaled",
              "target", "use_cd"):
        assert c[f] == py[f], f
    n = int(py["n_cand"])
    oc, op = _offsets(c), _offsets(py)
    assert [oc[t] for t in c["cand_tap"][:n]] == [op[t] for t in py["cand_tap"][:n]]
    for f in ("cand_ori", "cand_sgmask"):
        assert list(c[f][:n]) == list(py[f][:n]), f
    assert c["cand_alpha"][:n].tobytes() == py["cand_alpha"][:n].tobytes()   # bit for bit
    assert c["group_scale"].tobytes() == py["group_scale"].tobytes()
    assert _pairs(c) == _pairs(py)
    assert sorted(set(oc)) == sorted(set(op))
    assert py["sum_from_zero"] == 1 and c["sum_from_zero"] == 0
    assert c["gamma_mask"] & ~py["gamma_mask"] == 0          # a subset: the gammas it reads
    used = {8 + int(o) for o in c["cand_ori"][:n]} if c["use_grad"] else set()
    used |= {g for m in c["cand_sgmask"][:n] for g in range(8) if (int(m) >> g) & 1}
    assert {g for g in range(12) if (int(c["gamma_mask"]) >> g) & 1} >= used


def test_mask1_plan_for_a_method_without_one():
    with pytest.raises(RuntimeError, match="status 1"):
        _kernels.mask1_plan(_kernels.METHODS["edi_rows"])


# -- the fast exponential (csrc/rgbz_ops.h) -----------------------------------------------------

def test_fast_exp_against_libm():
    # the figures csrc/rgbz_ops.h and reconstruct's docstring give: relative error below
    # 3e-7 in float32 and 1e-8 in float64 wherever exp(x) is a normal number above the
    # flush threshold; exactly 1 at 0; 0 at and below the threshold and for NaN
    x32 = np.linspace(-86.99, 0, 2_000_001, dtype=np.float32)
    f32 = np.empty_like(x32)
    _kernels.fast_exp(x32, f32)
    exact = np.exp(x32.astype(np.float64))
    assert (np.abs(f32 - exact) / exact).max() < 3e-7
    rng = np.random.default_rng(0)
    x64 = np.concatenate([rng.uniform(-707.99, 0, 200_000), -np.logspace(-12, 2.8, 2000)])
    f64 = np.empty_like(x64)
    _kernels.fast_exp(x64, f64)
    ref = np.array([math.exp(v) for v in x64])                 # the C library's exp
    assert (np.abs(f64 - ref) / ref).max() < 1e-8
    for dt, lo in ((np.float32, -87.0), (np.float64, -708.0)):
        x = np.array([0.0, lo, lo - 1, -np.inf, np.nan], dt)
        out = np.empty_like(x)
        _kernels.fast_exp(x, out)
        assert out.tolist() == [1.0, 0.0, 0.0, 0.0, 0.0]


def test_fast_exp_is_its_formula_bit_for_bit():
    # csrc/rgbz_ops.h's polynomials are branch-free so that the gamma loops vectorise; in
    # float64 n = floor(x log2(e) + 0.5) comes from the bits of a rounding constant rather
    # than floor() and an integer conversion. The result must be the formula's, written
    # plainly in NumPy (IEEE operations in the same order), on every argument and at the
    # boundaries where x log2(e) + 0.5 is an integer (where round-to-nearest and floor part)
    rng = np.random.default_rng(3)
    k = (np.arange(-1021, 1) - 0.5) / 1.4426950408889634
    x = np.concatenate([rng.uniform(-708, 0, 400_000), -np.logspace(-300, 2.85, 20_000),
                        k, np.nextafter(k, 0), np.nextafter(k, -1), [0.0, -0.0, -707.99]])
    n = np.floor(x * 1.4426950408889634 + 0.5)
    y = (x - n * 0.693147180369123816490) - n * 1.90821492927058770002e-10
    p = 1.0 + y * (1.0 + y * (0.5 + y * (1.0 / 6 + y * (1.0 / 24 + y * (1.0 / 120 + y * (
        1.0 / 720 + y * (1.0 / 5040)))))))
    want = np.where(x > -708.0, np.ldexp(p, n.astype(np.int64)), 0.0)   # flushed below
    got = np.empty_like(x)
    _kernels.fast_exp(x, got)
    assert np.array_equal(got.view(np.int64), want.view(np.int64))
    # float32: n by the rounding constant 1.5 * 2^23 (round to nearest), 2^n from its bits
    x32 = np.concatenate([rng.uniform(-87, 0, 400_000).astype(np.float32),
                          ((np.arange(-125, 1) + 0.5) / np.float32(1.44269504)).astype(
                              np.float32)])
    f = np.float32
    t = x32 * f(1.44269504) + f(12582912.0)
    n32 = t - f(12582912.0)
    y32 = (x32 - n32 * f(0.693359375)) - n32 * f(-2.12194440e-4)
    c = [f(1) / f(d) for d in (6, 24, 120, 720)]              # 1.0f / 6 etc. in float
    p32 = f(1) + y32 * (f(1) + y32 * (f(0.5) + y32 * (c[0] + y32 * (c[1] + y32 * (
        c[2] + y32 * c[3])))))
    want32 = np.ldexp(p32, n32.astype(np.int32))
    got32 = np.empty_like(x32)
    _kernels.fast_exp(x32, got32)
    assert np.array_equal(got32.view(np.int32), want32.view(np.int32))


# -- the type stub ------------------------------------------------------------------------------

def test_stub_lists_exactly_the_public_names_of_the_module():
    # src/rgbz_fast/_kernels.pyi is written by hand: every public function, constant and enum
    # of the compiled module once, and nothing it does not have
    import ast
    from pathlib import Path

    tree = ast.parse((Path(rz.__file__).parent / "_kernels.pyi").read_text())
    stub = [n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))]
    stub += [n.target.id for n in tree.body if isinstance(n, ast.AnnAssign)]
    assert len(stub) == len(set(stub)), sorted(n for n in stub if stub.count(n) > 1)
    public = {n for n in dir(_kernels) if not n.startswith("_")
              and getattr(getattr(_kernels, n), "__module__", "rgbz_fast._kernels")
              in ("rgbz_fast._kernels", None)}
    assert set(stub) == public


def test_stub_functions_take_the_parameters_of_the_module():
    # each stub function's parameters, in order, are the compiled function's (the guided
    # denoise's and flying test's keywords of 2026-11-28 had been left out of the stub)
    import ast
    import inspect
    from pathlib import Path

    tree = ast.parse((Path(rz.__file__).parent / "_kernels.pyi").read_text())
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            a = node.args
            stub = [p.arg for p in a.posonlyargs + a.args + a.kwonlyargs]
            real = list(inspect.signature(getattr(_kernels, node.name)).parameters)
            assert stub == real, node.name


def test_counting_stub_reexports_exactly_the_public_names_of_the_module():
    # src/rgbz_fast/_kernels_count.pyi: the names of _kernels_count, re-exported from _kernels
    import ast
    from pathlib import Path

    tree = ast.parse((Path(rz.__file__).parent / "_kernels_count.pyi").read_text())
    stub = [a.asname for n in tree.body if isinstance(n, ast.ImportFrom) for a in n.names]
    assert all(n.module == "rgbz_fast._kernels" for n in tree.body if isinstance(n, ast.ImportFrom))
    public = {n for n in dir(_kernels_count) if not n.startswith("_")}
    assert sorted(stub) == sorted(public)


# -- the argument checks' scan (csrc/scan.c) ------------------------------------------------
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_float_range_is_min_and_max_and_sees_every_non_finite_value(dtype):
    """float_range against NumPy's min and max (every length up to two vectors' worth and a
    long one), and a NaN or infinity at the first, a middle and the last place makes the
    range not finite, as does a NaN beside an infinity; check_finite and finite_range give
    NumPy's answers and message through it, in C and Fortran order and on strided views."""
    from rgbz_fast._validate import check_finite, finite_range
    rng = np.random.default_rng(9)
    for n in list(range(1, 40)) + [100003]:
        a = (rng.standard_normal(n) * 1e3).astype(dtype)
        assert _kernels.float_range(a) == (float(a.min()), float(a.max()))
        for bad in (np.nan, np.inf, -np.inf):
            for at in {0, n // 2, n - 1}:
                b = a.copy()
                b[at] = bad
                lo, hi = _kernels.float_range(b)
                assert not (np.isfinite(lo) and np.isfinite(hi)), (n, bad, at)
    b = a.copy()
    b[[5, 9]] = np.inf, np.nan
    assert not np.all(np.isfinite(_kernels.float_range(b)))
    img = (rng.random((30, 40, 3)) * 7).astype(dtype)
    for view in (img, np.asfortranarray(img), img[:, ::2], img.transpose(1, 0, 2)):
        assert finite_range(view, "x") == (float(view.min()), float(view.max()))
        check_finite(view, "x")
        bad = view.copy()
        bad[3, 4, 1] = np.nan
        bad[0, 0, 0] = np.inf
        with pytest.raises(ValueError, match=r"x: holds 2 NaN or infinite value\(s\)"):
            check_finite(bad, "x")
        with pytest.raises(ValueError, match="x: holds 2"):
            finite_range(bad, "x")
