"""The package as a whole: what ``import rgbz_fast`` loads, its layering, its doctests, the
0.1 module names."""

from __future__ import annotations

import ast
import doctest
import importlib
import pkgutil
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import rgbz_fast

PKG = Path(rgbz_fast.__file__).resolve().parent


def _modules():
    """Every module of the installed package (the compiled ones excepted)."""
    names = ["rgbz_fast"]
    for info in pkgutil.walk_packages(rgbz_fast.__path__, "rgbz_fast."):
        if info.name.rsplit(".", 1)[-1] in ("_kernels", "_kernels_count", "__main__"):
            continue
        names.append(info.name)
    return names


def test_import_loads_no_tooling_plotting_or_test_module():
    """``python -X importtime -c "import rgbz_fast"`` lists no command line, no tooling
    (bench/opcount/tradeoff, the figures), not the counting build of the kernels
    (``_kernels_count``), no matplotlib, no test module, and none of the heavy libraries
    loaded lazily."""
    r = subprocess.run([sys.executable, "-X", "importtime", "-c", "import rgbz_fast"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr[-2000:]
    loaded = {line.rsplit("|", 1)[-1].strip() for line in r.stderr.splitlines()
              if line.startswith("import time:")}
    assert "rgbz_fast" in loaded and "rgbz_fast.reconstruction" in loaded
    assert "rgbz_fast._kernels" in loaded           # extension modules are listed too
    banned = ("rgbz_fast._cli", "rgbz_fast._devtools", "rgbz_fast._kernels_count", "matplotlib",
              "pytest", "_reference", "conftest", "colour", "colour_demosaicing", "scipy",
              "skimage", "cv2", "tqdm", "dask", "imageio", "tifffile")
    bad = sorted(m for m in loaded if m.split(".")[0] in banned or m.startswith(banned)
                 or "test" in m.split(".")[0])
    assert not bad, bad


def _import_as(argv0, preset, cleared, then):
    """stdout of a fresh interpreter that imports rgbz_fast as ``argv0`` would (a console
    script's path, "-c", or "-m MODULE" as the interpreter records it), with the variables
    ``cleared`` removed from its environment and ``preset`` added, then runs ``then``."""
    import os

    env = {k: v for k, v in os.environ.items() if k not in cleared}
    env.update(preset)
    if argv0.startswith("-m "):              # as the interpreter records python -m MODULE
        setup = f"sys.argv[0] = '-m'; sys.orig_argv = ['python', '-m', {argv0[3:]!r}]"
    else:
        setup = f"sys.argv[0] = {argv0!r}"
    code = f"import sys; {setup}; import rgbz_fast, os; {then}"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=120, env=env)
    assert r.returncode == 0, r.stderr[-2000:]
    return r.stdout


@pytest.mark.parametrize("argv0, preset, want", [
    ("/venv/bin/rgbz-fast", None, "1"),          # the command: BLAS on one thread
    ("/venv/bin/rgbz-fast", "3", "3"),           # a user's setting stays
    ("-m rgbz_fast", None, "1"),                 # python -m rgbz_fast, the same command
    ("-c", None, None),                          # a program importing the library: untouched
    ("/venv/bin/other-tool", None, None),
    ("-m pytest", None, None),
])
def test_the_command_alone_runs_blas_on_one_thread(argv0, preset, want):
    """OpenBLAS's threads spin idle for about 0.15 s of CPU after NumPy loads; the command
    (``sys.argv[0]`` named rgbz-fast) sets OPENBLAS_NUM_THREADS=1 before NumPy loads, unless
    set; a program that imports rgbz_fast keeps its own."""
    out = _import_as(argv0, {} if preset is None else {"OPENBLAS_NUM_THREADS": preset},
                     ("OPENBLAS_NUM_THREADS",), "print(os.environ.get('OPENBLAS_NUM_THREADS'))")
    assert out.strip() == str(want)


@pytest.mark.parametrize("argv0, preset, want", [
    ("/venv/bin/rgbz-fast", {}, "30000"),                       # the command: a short spin
    ("/venv/bin/rgbz-fast", {"GOMP_SPINCOUNT": "7"}, "7"),       # a user's setting stays
    ("/venv/bin/rgbz-fast", {"OMP_WAIT_POLICY": "active"}, None),   # so does their policy
    ("-m rgbz_fast", {}, "30000"),                              # python -m rgbz_fast
    ("-c", {}, None),                                           # an importing program: untouched
    ("-m pytest", {}, None),
])
def test_the_command_alone_shortens_openmps_idle_spin(argv0, preset, want):
    """libgomp's idle threads spin about 3 ms after each of the kernels' parallel regions by
    default, taking a core from the next threaded call of another library (OpenCV's demosaic
    1.4x slower right after a reconstruction, docs/reports/benchmarks.md); the command sets
    GOMP_SPINCOUNT=30000 before its kernels load, unless GOMP_SPINCOUNT or OMP_WAIT_POLICY is
    set, and show_config reports what the kernels run with."""
    out = _import_as(argv0, preset, ("GOMP_SPINCOUNT", "OMP_WAIT_POLICY"),
                     "import io; print(os.environ.get('GOMP_SPINCOUNT')); buf = io.StringIO(); "
                     "rgbz_fast.show_config(buf); "
                     "print([l for l in buf.getvalue().splitlines() if 'idle threads' in l])")
    got, line = out.strip().splitlines()
    assert got == str(want)
    import rgbz_fast
    if rgbz_fast.config()["openmp"]:
        if want is not None:
            assert f"GOMP_SPINCOUNT={want}" in line
        elif preset:
            assert "OMP_WAIT_POLICY=active" in line
        else:
            assert "libgomp's default spin" in line


# the layers, bottom up: a module may import its own package and the layers below
_LAYERS = [
    {"_validate", "_threads", "_build_config", "_kernels", "_deps", "_config", "_compat",
     "_progress", "_memory"},
    {"_patterns", "_sensor_checks", "_sensors", "_frame"},
    {"io"},
    {"simulation", "reconstruction", "tof", "metrics"},
    {"isp"},
    # fixed-point models of the reconstruction and what they cost: above the models they
    # imitate (and the ISP around them), below the evaluation that may compare them
    {"hardware"},
    {"evaluation"},
    {"__init__"},                # the package: re-exports the library, never the tools
    # the tooling layer: the measuring engines (bench, opcount, tradeoff, the hardware
    # model's cost), the figures of the commands; no argparse
    {"_devtools"},
    {"_cli"},                    # the command line: one module per command
    {"__main__"},
]
#: the counting build of the kernels, and the only layer that may load it: its counters cost
#: every call, so no library module (the hardware models included) imports it; their cost
#: engines, in the tooling layer, do
_COUNTING_BUILD = "_kernels_count"
_COUNTING_BUILD_USERS = {"_devtools"}


def _layer(name):
    for i, layer in enumerate(_LAYERS):
        if name in layer:
            return i
    raise AssertionError(f"{name} is in no layer of the test")


def _top(module):
    """The first component below rgbz_fast of a module name."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def _imports(path):
    """The rgbz_fast modules a file imports (anywhere in it: function-local imports too)."""
    rel = path.relative_to(PKG).with_suffix("")
    mod = ".".join(("rgbz_fast",) + rel.parts).removesuffix(".__init__")
    pkg_parts = mod.split(".")[:-1] if not path.name == "__init__.py" else mod.split(".")
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.level:
            base = pkg_parts[:len(pkg_parts) - node.level + 1]
            target = ".".join(base + ([node.module] if node.module else []))
            yield from [target] if node.module else [f"{target}.{a.name}" for a in node.names]
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else [
                node.module]
            yield from (n for n in names if n and n.startswith("rgbz_fast"))


def _module(path):
    rel = path.relative_to(PKG).with_suffix("")
    return ".".join(("rgbz_fast",) + rel.parts).removesuffix(".__init__")


@pytest.mark.parametrize("path", sorted(p for p in PKG.rglob("*.py")), ids=lambda p: str(
    p.relative_to(PKG)))
def test_layering(path):
    """Imports point down the layers (data model, io, models, ISP, hardware, evaluation,
    tools, command line), never up or across between the model subpackages: no cycle, no
    function-local escape hatch; only the tooling layer loads the counting build."""
    mod = _module(path)
    own = _top(mod)
    for t in _imports(path):
        other = _top(t)
        if other == _COUNTING_BUILD:
            assert own in _COUNTING_BUILD_USERS, f"{mod} loads the counting build {t}"
            continue
        if other == own:
            continue
        assert _layer(other) < _layer(own) or (
            _layer(other) == _layer(own) == 0) or (_layer(other) == _layer(own) == 1), \
            f"{mod} imports {t}: layer {_layer(other)} from layer {_layer(own)}"


def test_the_layers_name_every_subpackage():
    """A new subpackage or top-level module gets its place in the layers (or the test fails
    here, not silently in test_layering)."""
    tops = {_top(_module(p)) for p in PKG.rglob("*.py")}
    placed = set().union(*_LAYERS)
    assert tops <= placed, tops - placed
    assert _layer("hardware") > _layer("reconstruction")
    assert _layer("_devtools") > _layer("evaluation") and _layer("_cli") > _layer("_devtools")


def test_doctests_of_every_module():
    """Every example in every docstring of the package runs and prints what it says."""
    finder = doctest.DocTestFinder(exclude_empty=True)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    attempted, failures = 0, []
    # colour-science (and the matplotlib it imports) loaded under the suite's warning
    # filters, not the examples' "error": run alone on the dependency floors, an example was
    # the first to import them, and matplotlib 3.8's pyparsing deprecation failed it
    from rgbz_fast._deps import import_colour

    import_colour()
    # NumPy's default printing (a test that imports colour-science itself leaves the
    # 1.13 legacy mode behind; the library's own imports do not, see the next test)
    with np.printoptions(legacy=False):
        for name in _modules():
            mod = importlib.import_module(name)
            for test in finder.find(mod, name):
                with warnings.catch_warnings():
                    warnings.simplefilter("error")
                    res = runner.run(test, out=lambda s: failures.append(s))
                attempted += res.attempted
    assert not failures, "".join(failures)[:5000]
    assert attempted > 60


def test_importing_colour_leaves_numpy_print_options_alone():
    code = ("import numpy as np, rgbz_fast._deps as d; a = np.get_printoptions(); "
            "d.import_colour(); d.import_colour_demosaicing(); "
            "assert np.get_printoptions() == a, np.get_printoptions(); print('ok')")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0 and r.stdout.strip() == "ok", r.stderr[-2000:]


def test_the_dependencies_import_under_w_error():
    """With the dependency floors (matplotlib 3.8, SciPy 1.10), ``-W error`` made the first
    import of colour-science fail half-way (matplotlib's pyparsing names) and
    colour-demosaicing's too (SciPy 1.10 words its namespace warning "Please use ...", the
    filter matched only the later "Please import ..."): both import in a fresh process
    under -W error, and the filters match both dependencies' words (H122)."""
    import re

    from rgbz_fast import _deps

    for text in ("'parseString' deprecated - use 'parse_string'",
                 "'endQuoteChar' argument is deprecated, use 'end_quote_char'"):
        assert re.match(_deps.PYPARSING_NAMES, text), text
    for verb in ("import", "use"):
        text = (f"Please {verb} `convolve` from the `scipy.ndimage` namespace, the "
                "`scipy.ndimage.filters` namespace is deprecated.")
        assert re.match(_deps.SCIPY_NDIMAGE_NAMESPACE, text), text
    code = ("import rgbz_fast._deps as d; d.import_colour(); d.import_colour_demosaicing(); "
            "print('ok')")
    r = subprocess.run([sys.executable, "-W", "error", "-c", code], capture_output=True,
                       text=True, timeout=300)
    assert r.returncode == 0 and r.stdout.strip() == "ok", r.stderr[-2000:]


def test_the_figures_leave_the_callers_matplotlib_backend_alone(tmp_path):
    """Round 25 (PKG07): the figures were pyplot's after matplotlib.use("Agg"), which
    switched the backend of the caller's process (a notebook's plt.show() then showed
    nothing). They are Figures on their own Agg canvas now; pyplot is not even loaded."""
    code = f"""
import sys, matplotlib
matplotlib.use("svg")
from rgbz_fast.evaluation import EvalConfig, Results, write_reports
from rgbz_fast._devtools import plots
rows = [{{"image": i, "pattern": "mask1", "method": m, "metric": "cpsnr", "value": v}}
        for i, v in (("a", 30.0), ("b", 20.0)) for m in ("bilinear", "sg")]
res = Results(rows, EvalConfig(patterns=("mask1",), methods=("bilinear", "sg"),
                               metrics=("cpsnr",)))
write_reports(res, {str(tmp_path / "out")!r})
png = plots.hardware_sweep_plot([{{"label": "x", "refused": "no"}}], "t")
assert png[1:4] == b"PNG", png[:8]
assert matplotlib.get_backend() == "svg", matplotlib.get_backend()
assert "matplotlib.pyplot" not in sys.modules
print("ok")
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0 and r.stdout.strip() == "ok", r.stderr[-2000:]
    assert any(p.suffix == ".png" for p in (tmp_path / "out").iterdir())


@pytest.mark.parametrize("old,name", [
    ("scene", "load_rgbd"), ("sensor", "simulate"), ("sensor", "ToFTaps"),
    ("tof_isp", "tof_depth"), ("demosaic", "demosaic"), ("evaluate", "EvalConfig"),
    ("evaluate", "folder_dataset"), ("frameio", "save_frame"), ("rawio", "read_raw"),
    ("cli", "main"),
])
def test_module_names_of_0_1_still_work_with_a_warning(old, name):
    with pytest.warns(DeprecationWarning, match=f"rgbz_fast.{old} is the module layout"):
        mod = getattr(rgbz_fast, old)
    assert callable(getattr(mod, name))
    code = (f"import warnings; warnings.simplefilter('error')\n"
            f"try:\n    import rgbz_fast.{old}\nexcept DeprecationWarning as e:\n"
            f"    print('warned', e)\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=120)
    assert "warned" in r.stdout, r.stdout + r.stderr
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        mod = importlib.import_module(f"rgbz_fast.{old}")
    assert callable(getattr(mod, name))


def test_the_public_dataclasses_type_hints_resolve():
    """typing.get_type_hints (what pydantic, typeguard and sphinx's autodoc read) resolves
    the annotations of the public dataclasses (Scene's ArrayLike had been imported for type
    checkers only: a NameError, the review of round 25)."""
    import dataclasses
    import typing

    for name in _modules():
        mod = importlib.import_module(name)
        for k in getattr(mod, "__all__", ()):
            obj = getattr(mod, k)
            if isinstance(obj, type) and dataclasses.is_dataclass(obj):
                typing.get_type_hints(obj)


def test_python_m_of_the_0_1_module_names(tmp_path):
    """Round 25 (PKG06): ``python -m rgbz_fast.cli`` ran 0.1's command and died in runpy
    with a bare AttributeError (the alias loader had no get_code). It runs the command with
    the warning; another old name says it runs nothing, without a traceback."""
    r = subprocess.run([sys.executable, "-m", "rgbz_fast.cli", "--version"],
                       capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert r.returncode == 0 and r.stdout.startswith("rgbz-fast "), r.stderr
    assert "DeprecationWarning: python -m rgbz_fast.cli is the command of rgbz-fast 0.1" \
        in r.stderr
    r = subprocess.run([sys.executable, "-m", "rgbz_fast.sensor"], capture_output=True,
                       text=True, timeout=120, cwd=tmp_path)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert "rgbz_fast.sensor is a module of rgbz-fast 0.1 and runs nothing" in r.stderr


def test_every_exported_name_exists_and_0_1_top_level_names_remain():
    for name in _modules():
        mod = importlib.import_module(name)
        for k in getattr(mod, "__all__", ()):
            assert hasattr(mod, k), f"{name}.__all__ names {k!r}, which it lacks"
    old = ["show_config", "config", "Pattern", "bayer", "mask1", "mask2", "rows",
           "get_pattern", "R", "G", "B", "Z", "BAYER_PHASES", "RawFrame", "mosaic",
           "reconstruct", "METHODS", "PRECISIONS", "Scene", "load_scene", "ColourSensor",
           "ToFSensor", "ToFTaps", "simulate", "ColourISP", "tof_depth", "ToFISP", "ToFDepth"]
    assert all(hasattr(rgbz_fast, k) for k in old)
    assert "supported_float_type" not in dir(rgbz_fast._validate)


def test_the_tof_names_load_at_first_use_and_are_listed_before():
    code = ("import sys, rgbz_fast as rz, rgbz_fast.evaluation as ev\n"
            "assert 'rgbz_fast.tof' not in sys.modules, 'the colour chain loaded tof'\n"
            "lazy = {'tof', 'ToFISP', 'ToFDepth', 'tof_depth'}\n"
            "assert lazy <= set(dir(rz)), lazy - set(dir(rz))\n"
            "assert {'evaluate_depth', 'depth_report', 'DEPTH_SECTIONS'} <= set(dir(ev))\n"
            "assert rz.ToFISP is rz.tof.ToFISP and callable(ev.evaluate_depth)\n"
            "assert 'rgbz_fast.tof' in sys.modules and 'ToFISP' in vars(rz)\n"
            "print('ok')")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0 and r.stdout.strip() == "ok", r.stdout + r.stderr[-2000:]
