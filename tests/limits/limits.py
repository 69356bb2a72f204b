#!/usr/bin/env python3
# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The size limits of the tree (issue #40): no file in src over 500 lines,
no function over 70 lines, in C++ (.C, .H) and Python.

    limits.py [--known FILE] [ROOT]

measures src/ under ROOT (default: the repository) and prints every file and
function over its limit. With --known, a list of the sizes allowed for now
("lines path" or "lines path:function", one a line; # comments), it fails
on any excess that the list does not allow, on one that grew beyond it, and
on a listed one that is now within the limits (the list only shrinks).

C++ functions are found by their bodies: a brace at namespace or class
scope whose declaration ends in a parameter list (or its qualifiers, or a
constructor's initialisers), comments and literals stripped first; a
function's length runs from the first line of its declaration (its
template line included) to its closing brace. Python functions are the
ast's (methods and nested functions each on their own)."""
import argparse
import ast
import pathlib
import re
import sys

FILE_LIMIT = 500
FUNCTION_LIMIT = 70
CXX = (".C", ".H")


def strip_cxx(text):
    """The text with comments, string and character literals and
    preprocessor lines blanked (newlines kept, so lines still count)"""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":
            # a preprocessor line, with its continuations
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c == "/" and text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if c == "/" and text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        if c == "R" and text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if m:
                close = ")" + m.group(1) + '"'
                end = text.find(close, i + m.end())
                end = n if end < 0 else end + len(close)
                out.append(re.sub(r"[^\n]", " ", text[i:end]))
                i = end
                continue
        if c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (min(j + 1, n) - i))
            i = j + 1
            continue
        out.append(c)
        at_line_start = c == "\n" or (at_line_start and c in " \t")
        i += 1
    return "".join(out)


QUALIFIERS = re.compile(
    r"\)\s*((const|override|final|noexcept|volatile|&|&&|"
    r"->\s*[\w:<>,\s*&]+)\s*)*$"
)


def cxx_functions(text):
    """(name, first line, last line) of each function body"""
    code = strip_cxx(text)
    functions = []
    stack = []          # 'scope', 'function', 'block' (in a function) or
                        # 'init' (a braced list in a declaration)
    start = 0           # where the current declaration begins
    parens = 0          # parenthesis depth of the declaration
    for i, c in enumerate(code):
        inside = "function" in stack
        if c in "()" and not inside:
            parens += 1 if c == "(" else -1
            continue
        if c == "{":
            if inside or parens > 0:
                stack.append("block" if inside else "init")
                continue
            head = code[start:i]
            kind = "scope"
            if QUALIFIERS.search(head.rstrip()) or re.search(r"\)\s*:\s*[\s\S]*[)}]\s*$", head) \
                    and not re.search(r"\b(class|struct|union|enum|namespace)\b[^(]*$", head):
                if not re.search(r"\b(class|struct|union|enum|namespace)\s+[\w:]*\s*(final\s*)?(:[^(]*)?$", head.strip()):
                    kind = "function"
            if kind == "function":
                first = i - len(head) + (len(head) - len(head.lstrip()))
                functions.append([function_name(head), first, None])
            stack.append(kind)
            start = i + 1
        elif c == "}":
            kind = stack.pop() if stack else "scope"
            if kind == "function":
                functions[-1][2] = i
            if kind in ("scope", "function"):
                start = i + 1
                parens = 0
        elif c == ";" and not inside and parens == 0:
            start = i + 1
    lines = lambda pos: code.count("\n", 0, pos) + 1
    return [(name, lines(a), lines(b)) for name, a, b in functions if b is not None]


def function_name(head):
    """The name before the declaration's parameter list: the first
    parenthesis outside template brackets (a constructor's initialisers
    come after it)"""
    parens = angles = 0
    for i, c in enumerate(head):
        if c == "<" and not head[:i].rstrip().endswith("operator"):
            angles += 1
        elif c == ">" and angles:
            angles -= 1
        elif c == "(" and not angles:
            m = re.search(
                r"((?:[\w~]+(?:<[^()<>]*>)?::)*(?:operator\s*\S+|[\w~]+))\s*$", head[:i]
            )
            return re.sub(r"\s+", "", m.group(1)) if m else "?"
    return "?"


def python_functions(text):
    tree = ast.parse(text)
    return [
        (node.name, node.lineno - len(node.decorator_list), node.end_lineno)
        for node in ast.walk(tree)
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
    ]


def measure(root):
    """{key: lines} of every file and function over its limit"""
    over = {}
    src = root / "src"
    for path in sorted(src.rglob("*")):
        if "lnInclude" in path.parts or "Make" in path.parts or not path.is_file():
            continue
        if path.suffix not in CXX + (".py",):
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        rel = path.relative_to(root).as_posix()
        n = text.count("\n") + (0 if text.endswith("\n") else 1)
        if n > FILE_LIMIT:
            over[rel] = n
        found = python_functions(text) if path.suffix == ".py" else cxx_functions(text)
        for name, first, last in found:
            length = last - first + 1
            key = "%s:%s" % (rel, name)
            if length > FUNCTION_LIMIT and length > over.get(key, 0):
                over[key] = length
    return over


def read_known(path):
    known = {}
    for line in path.read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            size, key = line.split(None, 1)
            known[key] = int(size)
    return known


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", nargs="?", default=pathlib.Path(__file__).resolve().parents[2])
    parser.add_argument("--known", type=pathlib.Path)
    args = parser.parse_args(argv)
    over = measure(pathlib.Path(args.root))
    for key, size in sorted(over.items()):
        print("%5d %s" % (size, key))
    if not args.known:
        return 0
    known = read_known(args.known)
    problems = []
    for key, size in sorted(over.items()):
        if key not in known:
            problems.append("over the limit and not allowed: %s (%d lines)" % (key, size))
        elif size > known[key]:
            problems.append("grew: %s (%d lines, %d allowed)" % (key, size, known[key]))
    for key in sorted(set(known) - set(over)):
        problems.append("now within the limits, take it off %s: %s" % (args.known.name, key))
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
