"""Every measured number of the README and the user guide links to the report section that
holds it, and that section holds it.

A *measured number* is a quality, a speed, a ratio of speeds or a duration: a number
followed by dB, Mpix/s, (M) measurements/s, a time unit (s, min, minutes, hours) or a
speed ratio (``17-20x``, ``x1.30``), and the words "a minute" or "an hour". Numbers in code
(fenced blocks, inline code) are not counted: the examples run as tests. The block of text
that holds a measured number (a paragraph, a list item, a table with the paragraph right
after it) must link to a section of ``docs/reports/*.md`` (``reports/x.md#section``), and
one of the sections it links to must contain the number: both ends of a range, the number as
written (``705`` in ``705-820``, ``1.17`` in ``1.17x``). A section runs from its heading to
the next heading of the same or a higher level. A number that an example prints (the output
lines of a ``pycon`` block of the same page, or of a guide page the block links to) needs no
report: the example runs as a test of the page.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
PAGES = [REPO / "README.md", *sorted((REPO / "docs" / "guide").glob("*.md"))]

_NUM = r"[-+−]?\d+(?:\.\d+)?"
#: a measured number: (the number or range, what follows it)
MEASURED = re.compile(
    rf"(?<![\w.\-/^=])(?P<num>{_NUM}(?:\s?[-–]\s?{_NUM})?)\s?"
    r"(?P<unit>dB\b|Mpix/s|M measurements/s|million measurements per second|"
    r"measurements/s|min\b|minutes?\b|hours?\b|s\b(?![-/])|x(?![\w/])(?!\s*\d)|×(?!\s*\d))"
    r"|(?<![\w.])x(?P<ratio>\d+(?:\.\d+)?)(?!\w)"
    r"|\b(?P<word>a minute|an hour)\b")
LINK = re.compile(r"\]\((?P<target>[^)\s]*reports/(?P<file>[\w.-]+\.md)(?:#(?P<anchor>[\w.-]+))?)\)")


def _raw_blocks(text):
    """Paragraphs, list items and tables of a page, code left out: [(kind, lines)], with
    None where a heading or code stands between two blocks."""
    out, fenced, open_ = [], False, False
    for line in text.splitlines():
        stripped = line.strip()
        if line.startswith("```") or fenced or line.startswith("#"):
            if line.startswith("```"):
                fenced = not fenced
            if out and out[-1] is not None:
                out.append(None)                                   # a hard break
            open_ = False
            continue
        if not stripped:
            open_ = False                                          # a blank line
            continue
        kind = "table" if stripped.startswith("|") else \
            "item" if re.match(r"([*-]|\d+\.)\s", stripped) else "text"
        last = out[-1] if out else None
        if open_ and last is not None and (last[0] == kind == "table" or (
                kind == "text" and last[0] != "table")):
            last[1].append(stripped)
        else:
            out.append((kind, [stripped]))
        open_ = True
    return out


def blocks(text):
    """The blocks of prose of a Markdown page, without code: paragraphs and list items; a
    table joined with the paragraphs right before and after it (where its sources are
    named)."""
    raw = _raw_blocks(text)
    out, k, taken = [], 0, False          # taken: the last block already holds a table
    while k < len(raw):
        if raw[k] is None:
            k += 1
            taken = True
            continue
        kind, lines = raw[k]
        if kind == "table":
            merged = list(lines)
            if out and k and raw[k - 1] is not None and raw[k - 1][0] == "text" and not taken:
                merged = out.pop().split("\n") + merged
            if k + 1 < len(raw) and raw[k + 1] is not None and raw[k + 1][0] == "text":
                merged += raw[k + 1][1]
                k += 1
            out.append("\n".join(merged))
            taken = True
        else:
            out.append("\n".join(lines))
            taken = False
        k += 1
    return out


#: a table column of measured numbers: its header names a quality, a speed or a time
_MEASURED_COLUMN = re.compile(r"dB|Mpix/s|measurements/s|\(s\)|seconds|speed|ratio", re.I)


def _table_numbers(block):
    """The numbers of the table columns whose header names what they measure."""
    cells = [[c.strip() for c in line.strip().strip("|").split("|")]
             for line in block.splitlines() if line.startswith("|")]
    if len(cells) < 3:
        return []
    head, found = cells[0], []
    for row in cells[2:]:
        for j, cell in enumerate(row):
            if j < len(head) and _MEASURED_COLUMN.search(head[j]):
                cell = re.sub(r"`[^`]*`|\[[^\]]*\]\([^)]*\)|\*", "", cell)
                found += re.findall(rf"(?<![\w.]){_NUM}(?:\s?[-–]\s?{_NUM})?(?![\w.])", cell)
    return found


def measured_numbers(block):
    """The measured numbers of a block of prose, as written (inline code left out), then
    those of its table's measured columns."""
    prose = re.sub(r"`[^`]*`", " ", block)
    prose = re.sub(r"\]\([^)]*\)", "]", prose)               # link targets are not prose
    found = []
    for m in MEASURED.finditer(prose):
        if m.group("word"):
            found.append(m.group("word"))
        else:
            found.append(m.group("num") or m.group("ratio"))
    return found + [n for n in _table_numbers(block) if n not in found]


def _heading_slug(title):
    """GitHub's anchor of a heading."""
    slug = title.strip().lower()
    slug = re.sub(r"[^\w\- ]", "", slug)
    return slug.replace(" ", "-")


def sections(path):
    """{anchor: the text of its section} of a report."""
    lines = path.read_text().splitlines()
    heads = [(i, len(m.group(1)), _heading_slug(m.group(2)))
             for i, line in enumerate(lines) if (m := re.match(r"(#+)\s+(.*)", line))]
    out = {}
    for k, (i, level, slug) in enumerate(heads):
        end = next((j for j, lv, _ in heads[k + 1:] if lv <= level), len(lines))
        out[slug] = "\n".join(lines[i:end])
    return out


def holds(section, number):
    """Whether the text of a section holds ``number`` (both ends of a range)."""
    if number in ("a minute", "an hour"):
        return number in section
    ends = [e.strip().lstrip("+").replace("−", "-") for e in re.split(r"\s?[–]\s?|(?<=\d)-", number)]
    return all(re.search(rf"(?<![\d.]){re.escape(e.lstrip('-'))}(?![\d])", section)
               for e in ends if e)


def example_output(page):
    """What the examples of a page print: the output lines of its ``pycon`` blocks."""
    out, inside = [], False
    for line in page.read_text().splitlines():
        if line.startswith("```"):
            inside = line.strip() == "```pycon"
            continue
        if inside and not line.startswith((">>>", "...")):
            out.append(line)
    return "\n".join(out)


def findings(page):
    """(block, number, why) for every measured number of ``page`` that breaks the rule."""
    bad = []
    printed = example_output(page)
    for block in blocks(page.read_text()):
        numbers = measured_numbers(block)
        if not numbers:
            continue
        guides = [page.parent / m.group(1) for m in re.finditer(r"\]\(([\w-]+\.md)(?:#[\w-]*)?\)",
                                                                  block)]
        shown = "\n".join([printed] + [example_output(g) for g in guides if g.exists()])
        numbers = [n for n in numbers if not holds(shown, n)]
        links = [m for m in LINK.finditer(block) if m.group("anchor")]
        texts = []
        for m in links:
            report = REPO / "docs" / "reports" / m.group("file")
            texts.append(sections(report).get(m.group("anchor"), "") if report.exists()
                         else "")
        for n in numbers:
            if not links:
                bad.append((block[:120], n, "no link to a report section"))
            elif not any(holds(t, n) for t in texts):
                bad.append((block[:120], n, "not in the linked section(s) "
                            + ", ".join(m.group("target") for m in links)))
    return bad


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.relative_to(REPO).as_posix())
def test_every_measured_number_is_in_the_report_section_it_links_to(page):
    bad = findings(page)
    assert not bad, "\n".join(f"{n!r} ({why}): {b}" for b, n, why in bad)


def test_the_rule_finds_what_it_should():
    """The parser on sentences of the kinds the pages hold."""
    assert measured_numbers("SG runs at 705-820 Mpix/s, 1.17-1.23x OpenCV, x1.30 in float32; "
                            "13 s for Kodak, about a minute in all, 27.30 dB") == [
        "705-820", "1.17-1.23", "1.30", "13", "a minute", "27.30"]
    assert measured_numbers("`rgbz-fast bench --repeat 5` 11-bit, 5x5 window, 2 threads, "
                            "[x](reports/a.md#b-12-s) 4000x3000") == []
    assert holds("| SG | 715 | 705 | 820 |", "705-820") and not holds("7050 820", "705-820")
    page = ("a\nb\n\nsee:\n\n| t | speed (Mpix/s) |\n|---|---|\n| SG | 705-820 |\n\n"
            "sources [r](reports/x.md#y)\n\n* i 2 s\n  more\n* j\n")
    assert blocks(page) == ["a\nb", "see:\n| t | speed (Mpix/s) |\n|---|---|\n| SG | 705-820 |"
                            "\nsources [r](reports/x.md#y)", "* i 2 s\nmore", "* j"]
    assert measured_numbers(blocks(page)[1]) == ["705-820"]


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.relative_to(REPO).as_posix())
def test_no_section_is_empty(page):
    """A heading is followed by text before the next heading of its level or above."""
    lines, fenced, empty = page.read_text().splitlines(), False, []
    heads = []
    for i, line in enumerate(lines):
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and (m := re.match(r"(#+)\s", line)):
            heads.append((i, len(m.group(1)), line))
    for k, (i, level, line) in enumerate(heads):
        end = heads[k + 1][0] if k + 1 < len(heads) else len(lines)
        if not any(x.strip() for x in lines[i + 1:end]) and not (
                k + 1 < len(heads) and heads[k + 1][1] > level):
            empty.append(line)
    assert not empty, empty
