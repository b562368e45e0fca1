"""Write docs/reference/api.md, the API reference, from the installed package.

    python tools/gen_api.py            # rewrite docs/reference/api.md
    python tools/gen_api.py --check    # exit 1 if the committed file is out of date

Module by module (``rgbz_fast`` first, then its subpackages in the order of
``MODULES``): the module's docstring, then every name of its ``__all__`` in
that order, with its signature and the first paragraph of its docstring. A
class also lists its public methods and properties. A name that a module
re-exports from a subpackage documented here is a link to that entry, so each
object is described once. Nothing depends on the machine or on the run: the
same package gives the same file (tests/test_docs.py checks it).
"""

from __future__ import annotations

import argparse
import enum
import importlib
import inspect
import re
import sys
import textwrap
import types
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "docs" / "reference" / "api.md"

#: the public modules, in the order of the reference (the package's own layering, top down
#: from what a user imports first)
MODULES = ("rgbz_fast", "rgbz_fast.simulation", "rgbz_fast.reconstruction",
           "rgbz_fast.hardware", "rgbz_fast.isp", "rgbz_fast.tof", "rgbz_fast.metrics",
           "rgbz_fast.evaluation", "rgbz_fast.io")

HEADER = """\
# API reference

Generated from the package by `python tools/gen_api.py`; do not edit by hand
(`tests/test_docs.py` fails when this file and the code disagree). Each entry
gives the signature and the first paragraph of the docstring; the full
docstring (parameters, errors, examples) is `help(name)` in Python. The user
guide ([../guide/](../guide/)) explains how the pieces fit together.

"""


def _anchor(qualname):
    """GitHub's anchor of a heading made of ``qualname`` in backticks."""
    return re.sub(r"[^a-z0-9_ -]", "", qualname.lower()).replace(" ", "-")


def _first_paragraph(doc):
    doc = inspect.cleandoc(doc or "")
    para = doc.split("\n\n", 1)[0].strip()
    return " ".join(line.strip() for line in para.splitlines())


def _rest_to_markdown(text):
    """The reST of the module docstrings, as far as it reads in Markdown."""
    text = re.sub(r":(?:func|class|meth|mod|data|attr|exc):`~?([^`]+)`", r"`\1`", text)
    text = re.sub(r":DOI:`([^`]+)`", r"doi:\1", text)
    text = re.sub(r"``([^`]+)``", r"`\1`", text)
    out, lines = [], text.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        # a literal block: a line ending in '::', then an indented block
        if line.rstrip().endswith("::"):
            head = line.rstrip()[:-2].rstrip()
            if head:
                out.append(head + ":")
            i += 1
            block = []
            while i < len(lines) and (not lines[i].strip() or lines[i].startswith((" ", "\t"))):
                block.append(lines[i])
                i += 1
            while block and not block[-1].strip():
                block.pop()
            out += ["", "```text", textwrap.dedent("\n".join(block)).strip("\n"), "```", ""]
            continue
        # a numpydoc section heading ("References" over "----------") -> bold
        if i + 1 < len(lines) and re.fullmatch(r"-{3,}", lines[i + 1].strip()) and line.strip():
            out.append(f"**{line.strip()}**")
            i += 2
            continue
        out.append(line)
        i += 1
    return "\n".join(out).strip()


def _signature(obj):
    """The call signature without annotations (the docstrings give the types)."""
    if isinstance(obj, type) and issubclass(obj, enum.Enum):
        # a member by its value; inspect gives EnumType.__call__'s signature, which each
        # Python prints its own way (3.12: "(*values)"), so the page changed with the Python
        return "(value)"
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        return "(...)"
    sig = sig.replace(parameters=[p.replace(annotation=inspect.Parameter.empty)
                                  for p in sig.parameters.values()],
                      return_annotation=inspect.Signature.empty)
    text = re.sub(r"<class '([^']+)'>", r"\1", str(sig))
    # no memory addresses (default values without a stable repr)
    return re.sub(r" at 0x[0-9a-f]+", "", text)


def _home(obj):
    """The public module whose entry documents ``obj``.

    The subpackage whose code defines it, if it exports it; else the one subpackage that
    exports it (the frame and sensor types defined below the subpackages, the fixed-point
    model's internals that rgbz_fast.hardware exports); else ``rgbz_fast`` itself.
    """
    def exports(name):
        m = importlib.import_module(name)
        return any(getattr(m, k, None) is obj for k in m.__all__)

    mod = getattr(obj, "__module__", None) or ""
    for name in MODULES[1:]:
        if (mod == name or mod.startswith(name + ".")) and exports(name):
            return name
    exporters = [name for name in MODULES[1:] if exports(name)]
    return exporters[0] if len(exporters) == 1 else "rgbz_fast"


def _members(cls):
    """Public methods and properties defined by ``cls`` itself, in definition order."""
    out = []
    for name, value in vars(cls).items():
        if name.startswith("_"):
            continue
        if isinstance(value, property):
            out.append((name, "property", value.fget))
        elif isinstance(value, (classmethod, staticmethod)):
            out.append((name, "method", value.__func__))
        elif inspect.isfunction(value):
            out.append((name, "method", value))
    return out


def _constant(value):
    if isinstance(value, (set, frozenset)):          # sorted: set order depends on the hash seed
        r = "{" + ", ".join(sorted(repr(v) for v in value)) + "}"
    else:
        r = repr(value)
    if len(r) > 100:
        r = r[:97] + "..."
    return r


def _entry(modname, name, obj):
    qual = f"{modname}.{name}"
    lines = []
    if isinstance(obj, types.ModuleType):
        lines += [f"### `{qual}`", "", f"Subpackage: see [`{obj.__name__}`](#{_anchor(obj.__name__)}).",
                  ""]
        return lines
    callable_ = inspect.isclass(obj) or inspect.isfunction(obj) or inspect.isbuiltin(obj)
    if callable_:
        home = _home(obj)
        if home != modname:
            target = f"{home}.{name}"
            lines += [f"### `{qual}`", "",
                      f"The same object as [`{target}`](#{_anchor(target)}).", ""]
            return lines
        kind = "class" if inspect.isclass(obj) else "function"
        lines += [f"### `{qual}`", "", "```python", f"{kind} {name}{_signature(obj)}", "```", ""]
        para = _first_paragraph(obj.__doc__)
        if para:
            lines += [_rest_to_markdown(para), ""]
        if inspect.isclass(obj):
            for mname, mkind, fn in _members(obj):
                doc = _rest_to_markdown(_first_paragraph(fn.__doc__))
                if mkind == "property":
                    head = f"- `{name}.{mname}` (property)"
                else:
                    head = f"- `{name}.{mname}{_signature(fn)}`"
                lines.append(head + (f": {doc}" if doc else ""))
            if _members(obj):
                lines.append("")
        return lines
    lines += [f"### `{qual}`", "", f"Constant: `{_constant(obj)}`", ""]
    return lines


def generate():
    parts = [HEADER.rstrip("\n"), "", "Modules: " + ", ".join(
        f"[`{m}`](#{_anchor(m)})" for m in MODULES) + ".", ""]
    for modname in MODULES:
        mod = importlib.import_module(modname)
        parts += [f"## `{modname}`", ""]
        doc = inspect.cleandoc(mod.__doc__ or "")
        if doc:
            parts += [_rest_to_markdown(doc), ""]
        for name in mod.__all__:
            if name.startswith("__"):
                continue
            parts += _entry(modname, name, getattr(mod, name))
    text = "\n".join(parts).rstrip("\n") + "\n"
    return re.sub(r"\n{3,}", "\n\n", text)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true",
                    help="compare with the committed file instead of writing it")
    args = ap.parse_args(argv)
    text = generate()
    if args.check:
        if not OUT.exists() or OUT.read_text() != text:
            print(f"{OUT} is out of date: run python tools/gen_api.py", file=sys.stderr)
            return 1
        return 0
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(text)
    print(f"wrote {OUT} ({text.count(chr(10))} lines)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
