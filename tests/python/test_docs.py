# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The README is a front door and the user guide is behind it: every link
of README.md and of the pages under doc/ reaches a file (and a heading,
where it names one), every repository path the README and the guide name
in code spans exists, and the README keeps to at most 300 lines of at most
100 characters."""
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md"] + sorted((ROOT / "doc").rglob("*.md"))
GUIDE = [ROOT / "README.md"] + sorted((ROOT / "doc" / "guide").glob("*.md"))
TOP = ("src/", "doc/", "tests/", "tutorials/", "etc/", ".ci/", "Make/")
LINK = re.compile(r"\]\(([^)\s]+)\)")
CODE = re.compile(r"`([^`]+)`")


def prose(path):
    """(line number, line) outside fenced code blocks"""
    fenced = False
    for number, line in enumerate(path.read_text(encoding="utf-8").split("\n"), 1):
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced:
            yield number, line


def anchors(path):
    """GitHub's anchors of a page's headings"""
    return {
        re.sub(r"[^\w\- ]", "", line.lstrip("#").strip().lower()).replace(" ", "-")
        for _, line in prose(path) if line.startswith("#")
    }


def broken_links(page, root=ROOT):
    for number, line in prose(page):
        for target in LINK.findall(line):
            if re.match(r"[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            reached = (page.parent / path).resolve() if path else page
            if not reached.exists():
                yield "%s:%d: %s" % (page.relative_to(root), number, target)
            elif anchor and reached.suffix == ".md" and anchor not in anchors(reached):
                yield "%s:%d: %s (no such heading)" % (page.relative_to(root), number, target)


def missing_paths(page):
    for number, line in prose(page):
        for span in CODE.findall(line):
            for word in span.split():
                word = word.strip(",;:.()")
                if (
                    not word.startswith(TOP) or any(c in word for c in "*<>{}$[]")
                    or "..." in word
                ):
                    continue
                if not (ROOT / word).exists():
                    yield "%s:%d: %s" % (page.relative_to(ROOT), number, word)


def test_there_are_pages():
    assert len(GUIDE) > 10 and len(PAGES) > len(GUIDE)


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_links_reach_their_files(page):
    assert list(broken_links(page)) == []


@pytest.mark.parametrize("page", GUIDE, ids=lambda p: str(p.relative_to(ROOT)))
def test_named_paths_exist(page):
    assert list(missing_paths(page)) == []


def test_readme_is_a_front_door():
    lines = (ROOT / "README.md").read_text(encoding="utf-8").rstrip("\n").split("\n")
    assert len(lines) <= 300
    assert [n for n, line in enumerate(lines, 1) if len(line) > 100] == []


def test_a_broken_link_is_seen(tmp_path):
    page = tmp_path / "page.md"
    page.write_text("[a](missing.md) [b](page.md#nowhere)\n# Here\n[c](page.md#here)\n")
    assert len(list(broken_links(page, tmp_path))) == 2
