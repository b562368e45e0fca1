"""Rewrite the two contract tables of docs/reports/robustness.md from the rows of the tests.

    python tools/robustness_tables.py            # rewrite the tables in the page
    python tools/robustness_tables.py --check    # exit 1 when the page and the rows differ

The rows (``ROWS``: the Python API, ``CLI_ROWS``: the command line) live in the
contract file of each subpackage (``tests/**/test_contract.py``); their runner
(:data:`CONTRACT`) collects them and renders the Markdown (``markdown_tables()``); this script puts that Markdown between the
``<!-- api-table:start -->``/``end`` and ``<!-- cli-table:start -->``/``end``
markers of the page and leaves the rest of the page as it is.
"""

from __future__ import annotations

import argparse
import importlib.util
import re
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
PAGE = REPO / "docs" / "reports" / "robustness.md"
#: the test module that holds the rows and renders them
CONTRACT = REPO / "tests" / "_contract.py"


def tables():
    """{"api": Markdown, "cli": Markdown} of the contract rows."""
    sys.path.insert(0, str(CONTRACT.parent))         # the tests import their _support module
    spec = importlib.util.spec_from_file_location("_rgbz_contract_rows", CONTRACT)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod                     # dataclasses look their module up
    spec.loader.exec_module(mod)
    api, cli = mod.markdown_tables()
    return {"api": api, "cli": cli}


def rewrite(text, new):
    """``text`` with each marked table replaced by ``new[name]``."""
    for name, table in new.items():
        text, n = re.subn(rf"(<!-- {name}-table:start -->\n).*?(<!-- {name}-table:end -->)",
                          lambda m, t=table: m.group(1) + t + "\n" + m.group(2), text, flags=re.S)
        if n != 1:
            raise SystemExit(f"{PAGE}: expected one {name}-table marker pair, found {n}")
    return text


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true", help="compare, do not write")
    args = ap.parse_args(argv)
    new = tables()
    text = PAGE.read_text()
    out = rewrite(text, new)
    if args.check:
        if out != text:
            print(f"{PAGE} is out of date: run python tools/robustness_tables.py",
                  file=sys.stderr)
            return 1
        return 0
    PAGE.write_text(out)
    print(f"wrote the api and cli tables of {PAGE}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
