"""The module names of rgbz-fast 0.1, kept working (with a DeprecationWarning) after 0.2's layout.

Version 0.1 had 25 flat modules; 0.2 groups them into subpackages. ``import
rgbz_fast.sensor``, ``from rgbz_fast import rawio`` and ``rgbz_fast.evaluate.EvalConfig``
still work: each old name resolves to a module that holds the old module's
public names, taken from their new homes, and says where they went.

=================  =========================================================
0.1 module         0.2 home
=================  =========================================================
``scene``          :mod:`rgbz_fast.simulation`
``sensor``         :mod:`rgbz_fast.simulation`
``tof_isp``        :mod:`rgbz_fast.tof`
``demosaic``       :mod:`rgbz_fast.isp`
``evaluate``       :mod:`rgbz_fast.evaluation` (datasets: :mod:`rgbz_fast.io`)
``frameio``        :mod:`rgbz_fast.io`
``rawio``          :mod:`rgbz_fast.io`
``cli``            ``rgbz_fast._cli`` (the ``rgbz-fast`` command)
=================  =========================================================
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.util
import sys
import types
import warnings

__all__ = ["ALIASES", "install_aliases"]

#: old module -> the new modules whose public names it holds, first match wins
ALIASES = {
    "scene": ("simulation",),
    "sensor": ("simulation", "_frame"),
    "tof_isp": ("tof",),
    "demosaic": ("isp",),
    "evaluate": ("evaluation", "io"),
    "frameio": ("io",),
    "rawio": ("io",),
    "cli": ("_cli",),
}


def _alias_module(package, old):
    """A module named ``package.old`` holding the public names of its new homes."""
    full = f"{package}.{old}"
    if full in sys.modules:
        return sys.modules[full]
    homes = [importlib.import_module(f"{package}.{new}") for new in ALIASES[old]]
    mod = types.ModuleType(full, f"Deprecated alias of {', '.join(h.__name__ for h in homes)} "
                                 f"(rgbz-fast 0.1's {full}).")
    names = []
    for h in reversed(homes):
        public = getattr(h, "__all__", [k for k in vars(h) if not k.startswith("_")])
        for k in public:
            setattr(mod, k, getattr(h, k))
        names += [k for k in public if k not in names]
    if old == "cli":
        mod.main = homes[0].main
        names.append("main")
    mod.__all__ = names
    sys.modules[full] = mod
    return mod


def _warn(package, old, stacklevel):
    new = " and ".join(f"{package}.{n}" for n in ALIASES[old] if not n.startswith("_"))
    warnings.warn(f"{package}.{old} is the module layout of rgbz-fast 0.1; its names are in "
                  f"{new or package} now", DeprecationWarning, stacklevel=stacklevel)


class _AliasFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Makes ``import rgbz_fast.sensor`` (and the like) load the alias module."""

    def __init__(self, package):
        self.package = package

    def find_spec(self, fullname, path=None, target=None):
        pkg, _, old = fullname.rpartition(".")
        if pkg == self.package and old in ALIASES:
            return importlib.util.spec_from_loader(fullname, self)
        return None

    def create_module(self, spec):
        old = spec.name.rpartition(".")[2]
        _warn(self.package, old, stacklevel=4)
        return _alias_module(self.package, old)

    def exec_module(self, module):
        pass

    def get_code(self, fullname):
        """What ``python -m <package>.<old>`` runs (runpy asks the loader for code; without
        this method it died with a bare AttributeError): 0.1's ``cli`` ran the command, and
        still does, with the warning; the other old names run nothing and say so."""
        old = fullname.rpartition(".")[2]
        if old == "cli":
            src = (f"import warnings\nwarnings.warn('python -m {fullname} is the command of "
                   f"rgbz-fast 0.1; use rgbz-fast or python -m {self.package}', "
                   f"DeprecationWarning, stacklevel=1)\n"
                   f"from {self.package}._cli import main\nraise SystemExit(main())\n")
        else:
            src = (f"import sys\nsys.stderr.write('{fullname} is a module of rgbz-fast 0.1 "
                   f"and runs nothing; the command is rgbz-fast (python -m {self.package})\\n')"
                   f"\nraise SystemExit(2)\n")
        return compile(src, f"<{fullname}>", "exec")


def install_aliases(package, lazy=None):
    """Register the 0.1 module names of ``package`` (its ``__getattr__`` and an import finder).

    ``lazy``: name -> (submodule, attribute or None), the names the package imports at first
    use (the submodule itself when the attribute is None), kept in the package after it."""
    if not any(isinstance(f, _AliasFinder) and f.package == package for f in sys.meta_path):
        sys.meta_path.append(_AliasFinder(package))
    mod = sys.modules[package]
    lazy = dict(lazy or {})

    def __getattr__(name):
        if name in lazy:
            sub, attr = lazy[name]
            home = importlib.import_module(f"{package}.{sub}")
            value = home if attr is None else getattr(home, attr)
            setattr(mod, name, value)
            return value
        if name in ALIASES:
            _warn(package, name, stacklevel=3)
            return _alias_module(package, name)
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__():
        # the lazy names are the package's before their first use too (dir, completion)
        return sorted(set(vars(mod)) | set(lazy))

    mod.__getattr__ = __getattr__
    mod.__dir__ = __dir__
