#!/usr/bin/env python3
# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Every keyword the model's input checking accepts is documented in the
user guide.

The keywords are those the input checking records as it reads the case
tests' dictionaries (checkedInput::recordKeywords: a line each, keyword, a
tab and the dictionary's role, in the files ADHESIVE_WALL_KEYWORDS names,
one per case test under RECORDS); documented means written as inline code
(between backticks) in a page of the guide (GUIDE/*.md).

    keywords.py RECORDS GUIDE

Exit 0 when all are documented, 1 when some are not (listed with the
dictionary that accepts them), 77 (skipped) when no case test has recorded
any, unless CI is set, where that is a failure too.
"""

import os
import pathlib
import re
import sys

CODE_SPAN = re.compile(r"`([^`\n]+)`")
# (a word is not a number's exponent or a word's tail: `1e-3` names no e)
WORD = re.compile(r"(?<![\w.+-])[A-Za-z_][A-Za-z0-9_]*")


def recorded(folder):
    """keyword -> the roles of the dictionaries that accept it, from every
    record file in folder."""
    keywords = {}
    for path in sorted(pathlib.Path(folder).glob("*.txt")):
        for line in path.read_text().splitlines():
            keyword, _, role = line.partition("\t")
            if keyword:
                keywords.setdefault(keyword, set()).add(role)
    return keywords


def documented(guide):
    """The words written as inline code in the prose of the guide's pages
    (an example in a fenced block alone does not document a keyword)."""
    words = set()
    for page in sorted(pathlib.Path(guide).glob("*.md")):
        fenced = False
        for line in page.read_text().splitlines():
            if line.lstrip().startswith("```"):
                fenced = not fenced
            elif not fenced:
                for span in CODE_SPAN.findall(line):
                    words.update(WORD.findall(span))
    return words


def undocumented(keywords, words):
    """The recorded keywords the guide does not name, sorted."""
    return sorted(k for k in keywords if k not in words)


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    keywords = recorded(argv[1])
    if not keywords:
        print(f"no keywords recorded under {argv[1]}: run the case tests"
              " first (ctest -L case)")
        return 1 if os.environ.get("CI") else 77
    missing = undocumented(keywords, documented(argv[2]))
    for keyword in missing:
        roles = "; ".join(sorted(keywords[keyword]))
        print(f"not in the guide: {keyword} (of {roles})")
    print(f"{len(keywords) - len(missing)} of {len(keywords)} keywords the"
          " case tests' input checking accepted are in the guide")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
