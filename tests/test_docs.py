"""The documentation: the user guide's examples run, the API reference is current, links resolve.

* Every ```python / ```pycon block of docs/guide/*.md and docs/index.md is a doctest
  (``>>>`` lines with their output). The blocks of one page run in order in one namespace,
  in a temporary working directory that has ``../shared/data`` beside it (a link to the
  shared data), as a source checkout has. When the data is absent, the first block that reads
  ``../shared/data`` and every block after it on that page are skipped, with the reason (the
  later blocks may use what it defined); put such examples after the others.
* Every ``rgbz-fast ...`` line of a ```bash block of the guide parses with the command's own
  argument parser (the options exist and take the values shown).
* docs/reference/api.md is what ``python tools/gen_api.py`` writes for this code.
* Every relative link of docs/ and README.md points at an existing file (and heading).
"""

from __future__ import annotations

import doctest
import re
import shlex
import subprocess
import sys

import numpy as np
import pytest

from _support import REPO, SHARED_DATA

DOCS = REPO / "docs"
GUIDE = sorted((DOCS / "guide").glob("*.md"))
EXAMPLE_PAGES = [DOCS / "index.md", *GUIDE]
FENCE = re.compile(r"^```([\w+-]*)[^\n]*\n(.*?)^```[ \t]*$", re.S | re.M)
NEEDS_DATA = "../shared/data"
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def _blocks(path, languages):
    """(language, first line number, text) of every fenced block of ``path`` in ``languages``."""
    text = path.read_text()
    for m in FENCE.finditer(text):
        if m.group(1) in languages:
            yield m.group(1), text.count("\n", 0, m.start(2)) + 1, m.group(2)


def test_the_guide_has_its_pages():
    names = {p.name for p in GUIDE}
    for page in ("getting-started.md", "patterns.md", "reconstruction.md", "sensor.md",
                 "isp.md", "raw.md", "evaluation.md", "cli.md", "performance.md",
                 "interpretation.md"):
        assert page in names, f"docs/guide/{page} is missing"


@pytest.mark.parametrize("page", EXAMPLE_PAGES, ids=lambda p: p.relative_to(DOCS).as_posix())
def test_guide_examples_run(page, tmp_path, monkeypatch):
    """Each page's examples, in doctest form, give the output the page shows."""
    blocks = list(_blocks(page, ("python", "pycon")))
    parser = doctest.DocTestParser()
    for lang, line, src in blocks:
        assert parser.get_examples(src), (
            f"{page.name}:{line}: a ```{lang} block without a >>> example; write examples in "
            "doctest form (>>> lines with their output) so that they run")
    work = tmp_path / "work"
    work.mkdir()
    if SHARED_DATA.exists():
        (tmp_path / "shared").mkdir()
        (tmp_path / "shared" / "data").symlink_to(SHARED_DATA, target_is_directory=True)
    monkeypatch.chdir(work)
    runner = doctest.DocTestRunner(optionflags=FLAGS)
    globs = {"__name__": "__docs__"}
    skipped = []
    # NumPy's own print format (a test that imports colour-science directly leaves NumPy
    # in its 1.13 legacy mode for the rest of the session)
    with np.printoptions(legacy=False):
        for lang, line, src in blocks:
            if skipped or (NEEDS_DATA in src and not SHARED_DATA.exists()):
                skipped.append(line)
                continue
            test = parser.get_doctest(src, globs, f"{page.name}:{line}", str(page), line - 1)
            runner.run(test, clear_globs=False)
            globs = test.globs                # DocTest copies its globals: carry them on
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{result.failed} example(s) of {page.name} failed (see above)"
    if skipped:
        pytest.skip(f"{page.name}: the blocks from line {skipped[0]} on need {SHARED_DATA}, "
                    f"which is absent ({len(blocks) - len(skipped)} of {len(blocks)} blocks ran)")


def _cli_lines():
    for page in GUIDE + [REPO / "README.md"]:
        for _, line, src in _blocks(page, ("bash", "console", "sh")):
            src = src.replace("\\\n", " ")
            for k, text in enumerate(src.splitlines()):
                text = text.split("#", 1)[0].strip()
                for part in re.split(r"&&|\|\||;", text):
                    words = shlex.split(part)
                    if "rgbz-fast" in words[:1] or (words and words[0].endswith("/rgbz-fast")):
                        yield f"{page.name}:{line + k}", words[1:]


CLI_LINES = list(_cli_lines())


@pytest.mark.parametrize("where,argv", CLI_LINES, ids=[w for w, _ in CLI_LINES])
def test_guide_command_lines_parse(where, argv):
    """The options the guide shows exist and take the values it gives them (parsed, not run)."""
    from rgbz_fast._cli import build_parser

    if not argv or "--help" in argv or argv == ["--version"]:
        return
    try:
        build_parser().parse_args(argv)
    except SystemExit as e:           # argparse reports the error on stderr
        pytest.fail(f"{where}: rgbz-fast {' '.join(argv)} does not parse (exit {e.code})")


def test_api_reference_is_current():
    """docs/reference/api.md is generated from the package; regenerate it after an API change."""
    r = subprocess.run([sys.executable, str(REPO / "tools" / "gen_api.py"), "--check"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr.strip() or "run python tools/gen_api.py"


def test_learned_floor_patch_applies():
    """tools/learned_floor.patch, the measurement build benchmarks.md's "Learned without its
    hash" gives the commands of, still applies to csrc/learned.template.h (checked, not
    applied); after a change there, rebuild the patch from the measurement code."""
    import shutil
    if shutil.which("git") is None:
        pytest.skip("git is not installed: `git apply --check` cannot run")
    r = subprocess.run(["git", "apply", "--check", "tools/learned_floor.patch"], cwd=REPO,
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr.strip()


# --------------------------------------------------------------------------- links
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def _slug(heading):
    """GitHub's anchor of a Markdown heading."""
    text = re.sub(r"<[^>]+>", "", heading).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def _anchors(path):
    text = FENCE.sub("", path.read_text())
    return {_slug(m.group(1)) for m in re.finditer(r"^#{1,6}\s+(.*?)\s*#*\s*$", text, re.M)}


def _links():
    pages = sorted(DOCS.rglob("*.md")) + [REPO / "README.md"]
    for page in pages:
        text = FENCE.sub(lambda m: "\n" * m.group(0).count("\n"), page.read_text())
        text = re.sub(r"`[^`\n]*`", "", text)
        for m in LINK.finditer(text):
            target = m.group(1)
            if re.match(r"[a-z][a-z0-9+.-]*:", target):      # http:, https:, mailto:
                continue
            yield page, text.count("\n", 0, m.start()) + 1, target


LINKS = list(_links())


def test_every_relative_link_resolves():
    bad = []
    for page, line, target in LINKS:
        path, _, anchor = target.partition("#")
        dest = (page.parent / path).resolve() if path else page
        where = f"{page.relative_to(REPO)}:{line}: {target}"
        if not dest.exists():
            bad.append(f"{where} (no such file)")
        elif anchor and dest.suffix == ".md" and anchor not in _anchors(dest):
            bad.append(f"{where} (no heading #{anchor} in {dest.name})")
    assert LINKS, "no links found: the link pattern is broken"
    assert not bad, "\n".join(bad)


def test_docs_name_only_existing_doc_files():
    """Paths such as docs/guide/raw.md written in code, tests, tools and docs exist."""
    roots = [REPO / "src", REPO / "csrc", REPO / "tests", REPO / "tools", REPO / "benchmarks",
             DOCS, REPO / "README.md"]
    files = [f for r in roots for f in ([r] if r.is_file() else r.rglob("*"))
             if f.is_file() and f.suffix in (".py", ".pyx", ".pyi", ".c", ".h", ".md", ".sh",
                                              ".json", ".build")]
    bad = []
    for f in files:
        for m in re.finditer(r"(?<![\w/.])docs/[\w./-]*\w", f.read_text(errors="replace")):
            ref = m.group(0)
            if not (REPO / ref).exists():
                bad.append(f"{f.relative_to(REPO)}: {ref}")
    assert not bad, "\n".join(sorted(set(bad)))


def test_the_bibliography_holds_every_key_the_code_names():
    """A docstring or page that cites ``references.bib`` and a key names an entry of the file."""
    bib = (DOCS / "references.bib").read_text()
    keys = set(re.findall(r"^@\w+\{([\w-]+),", bib, re.M))
    assert len(keys) == len(re.findall(r"^@\w+\{", bib, re.M)), "an entry without a key"
    roots = [REPO / "src", REPO / "csrc", DOCS, REPO / "tests", REPO / "README.md"]
    files = [f for r in roots for f in ([r] if r.is_file() else r.rglob("*"))
             if f.is_file() and f.suffix in (".py", ".pyx", ".c", ".h", ".md")]
    named = {}
    for f in files:
        for m in re.finditer(r"references\.bib[:,]?\s*([\w-]+)", f.read_text(errors="replace")):
            named.setdefault(m.group(1), f.relative_to(REPO))
    missing = {k: str(v) for k, v in named.items() if k not in keys}
    assert named, "no docstring names a bibliography key"
    assert not missing, missing


def test_no_module_types_out_a_reference_in_full():
    """References sections cite by key: one line each, pointing at docs/references.bib."""
    bad = []
    for f in sorted((REPO / "src").rglob("*.py")):
        text = f.read_text()
        for m in re.finditer(r"^(\s*)\.\. \[\d+\](.*(?:\n\1   .*)*)", text, re.M):
            if "references.bib" not in m.group(2):
                bad.append(f"{f.relative_to(REPO)}: {m.group(0).strip()[:70]}")
    assert not bad, "\n".join(bad)
