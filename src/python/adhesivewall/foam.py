# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""OpenFOAM's files, as far as the post-processing needs them.

Dictionary entries are read with OpenFOAM's own `foamDictionary` (so that
`#include`, `#eval` and `$macros` mean what they mean to the solver); its
output, lagrangian fields and boundary fields are parsed here by a small
tokenizer of OpenFOAM's syntax (words, numbers, strings, `{}` dictionaries,
`()` lists, the `n{value}` uniform list).
"""

import math
import os
import re
import subprocess

_TOKEN = re.compile(r'''
      (?P<comment>//[^\n]*|/\*.*?\*/)
    | (?P<string>"(?:[^"\\]|\\.)*")
    | (?P<punct>[{}();\[\]])
    | (?P<word>[^\s{}();"\[\]]+)
''', re.VERBOSE | re.DOTALL)


def tokens(text):
    for m in _TOKEN.finditer(text):
        if m.lastgroup == "comment":
            continue
        value = m.group(m.lastgroup)
        if m.lastgroup == "string":
            value = value[1:-1]
        yield m.lastgroup, value


def _number(word):
    try:
        return int(word)
    except ValueError:
        try:
            return float(word)
        except ValueError:
            return word


class _Parser:
    def __init__(self, text):
        self.tokens = list(tokens(text))
        self.i = 0

    def peek(self):
        return self.tokens[self.i] if self.i < len(self.tokens) else (None, None)

    def next(self):
        token = self.peek()
        self.i += 1
        return token

    def value(self):
        kind, value = self.next()
        if (kind, value) == ("punct", "("):
            return self.list()
        if (kind, value) == ("punct", "{"):
            return self.dictionary(closing="}")
        if kind == "string":
            return value
        # n{value}: a uniform list; n(...): a list with its size
        if kind == "word" and re.fullmatch(r"\d+", value):
            following = self.peek()
            if following == ("punct", "{"):
                self.next()
                item = self.value()
                self.expect("}")
                return [item] * int(value)
            if following == ("punct", "("):
                # n(...) is a list of n items; otherwise the number stands
                # alone before a list of its own (as in a table's rows)
                start = self.i
                self.next()
                items = self.list()
                if len(items) == int(value):
                    return items
                self.i = start
        return _number(value)

    def expect(self, punct):
        token = self.next()
        if token != ("punct", punct):
            raise ValueError(f"expected '{punct}', found {token}")

    def list(self):
        items = []
        while self.peek() != ("punct", ")"):
            if self.peek() == (None, None):
                raise ValueError("unterminated list")
            items.append(self.value())
        self.next()
        return items

    def dictionary(self, closing=None):
        entries = {}
        while True:
            kind, key = self.peek()
            if kind is None:
                if closing:
                    raise ValueError("unterminated dictionary")
                return entries
            if (kind, key) == ("punct", closing):
                self.next()
                return entries
            if kind == "punct" and key == "(":
                # a bare list, as a field file's data
                self.next()
                entries.setdefault("", []).append(self.list())
                continue
            self.next()
            if self.peek() == ("punct", "{"):
                self.next()
                entries[key] = self.dictionary(closing="}")
                continue
            values = []
            while self.peek() not in (("punct", ";"), (None, None)):
                values.append(self.value())
            self.next()
            entries[key] = values[0] if len(values) == 1 else values


def parse(text):
    """A dictionary's text as nested Python dicts (an entry of one value is
    that value, of several a list; lists are lists)."""
    return _Parser(text).dictionary()


def _environment(case):
    """The environment of an OpenFOAM application run in `case`: OpenFOAM
    takes the case's folder from $PWD."""
    if case is None:
        return None
    return dict(os.environ, PWD=os.path.abspath(case))


def dictionary(path, entry=None, expand=True, case=None):
    """A dictionary file, or one entry of it, as `foamDictionary` gives it
    (with its `#include`s, `#eval`s and macros expanded), parsed; `case`:
    the case folder to run it in (the path then relative to it), where
    `$FOAM_CASE` matters."""
    command = ["foamDictionary", str(path)]
    if not expand:
        command.append("-disableFunctionEntries")
    if entry:
        command += ["-entry", entry]
    result = subprocess.run(command, capture_output=True, text=True,
                            cwd=case, env=_environment(case))
    if result.returncode != 0:
        raise RuntimeError(
            f"foamDictionary {path} -entry {entry}: {result.stderr.strip()}")
    parsed = parse(result.stdout)
    if entry:
        return parsed[entry.split("/")[-1]]
    return parsed


def value(path, entry, expand=True, case=None):
    """One entry's value, by `foamDictionary -value`, as a number where it
    is one (`case` as for `dictionary`)."""
    command = ["foamDictionary", str(path), "-entry", entry, "-value"]
    if not expand:
        command.insert(2, "-disableFunctionEntries")
    result = subprocess.run(command, capture_output=True, text=True,
                            cwd=case, env=_environment(case))
    if result.returncode != 0 or not result.stdout.strip():
        raise RuntimeError(
            f"no entry {entry} in {path}: {result.stderr.strip()}")
    return _number(result.stdout.strip())


def _body(path):
    """A field file's text after its FoamFile header."""
    with open(path) as f:
        text = f.read()
    header = re.search(r"FoamFile\s*\{[^}]*\}", text)
    return text[header.end():] if header else text


def body(path):
    """A field file's text after its FoamFile header (for tokens and
    parse)."""
    return _body(path)


def gravity(case="."):
    """|g| of the case's constant/g [m/s^2]."""
    return math.sqrt(sum(float(c) ** 2 for c in
                         dictionary("constant/g", "value", case=case)))


def list_file(path):
    """The list of a file holding one list (a lagrangian field, a
    positions file): scalars as numbers, vectors as lists."""
    parser = _Parser(_body(path))
    while parser.peek() != (None, None):
        kind, value = parser.peek()
        if (kind, value) == ("punct", "("):
            parser.next()
            return parser.list()
        if kind == "word" and re.fullmatch(r"\d+", value):
            parser.next()
            if parser.peek() == ("punct", "{"):
                parser.i -= 1
                return parser.value()
            # n (...): n entries, each of one or several items
            parser.expect("(")
            return parser.list()
        parser.next()
    raise ValueError(f"{path}: no list")


def boundary_values(path):
    """The boundary values of a volScalarField file, per patch: a list of
    the face values (a uniform value on n faces cannot be told from the
    file: it is returned as its one value)."""
    fields = parse(_body(path))
    result = {}
    for patch, entries in fields.get("boundaryField", {}).items():
        if not isinstance(entries, dict) or "value" not in entries:
            continue
        v = entries["value"]
        if isinstance(v, list) and v and v[0] == "nonuniform":
            result[patch] = [float(x) for x in v[-1]]
        elif isinstance(v, list) and v and v[0] == "uniform":
            result[patch] = [float(v[1])]
        else:
            raise ValueError(f"{path}: value of {patch}: {v}")
    return result


def times(case="."):
    """The case's time folders, as (value, name), in order."""
    found = []
    for name in os.listdir(case):
        if os.path.isdir(os.path.join(case, name)):
            try:
                found.append((float(name), name))
            except ValueError:
                pass
    return sorted(found)


def latest_time(case="."):
    found = times(case)
    if not found:
        raise ValueError(f"{case}: no time folders")
    return found[-1][1]


def parcel_count(case=".", time=None, cloud="kinematicCloud"):
    """The number of parcels a cloud holds at a write time (the latest by
    default), from its lagrangian files: 0 when it holds none."""
    time = time or latest_time(case)
    folder = os.path.join(case, time, "lagrangian", cloud)
    for name in ("origId", "d"):
        path = os.path.join(folder, name)
        if os.path.exists(path):
            return len(list_file(path))
    return 0


class NotFixedSizes(ValueError):
    """A cloud whose injectors are not each of one fixed size."""


def fixed_size_injectors(case=".",
                         properties="constant/kinematicCloudProperties"):
    """The injection models of a cloud's properties, each of one diameter
    (a fixedValue size distribution), as (name, injectorID, d,
    positionsFile) in the dictionary's order."""
    models = dictionary(properties, "subModels/injectionModels", case=case)
    found = []
    for name, entry in models.items():
        try:
            found.append((name, int(entry["injectorID"]),
                          float(entry["sizeDistribution"]
                                ["fixedValueDistribution"]["value"]),
                          str(entry["positionsFile"])))
        except (KeyError, TypeError):
            raise NotFixedSizes(
                f"{properties}: injector {name} is not a manualInjection of "
                "one fixed size with an injectorID (sizeDistribution "
                "fixedValue, injectorID, positionsFile)") from None
    return found


def written_header(tutorial, foam_class, name, comment):
    """The header of a file a tutorial's script writes under constant/: the
    banner naming the tutorial and the licence, FoamFile, and the comment
    lines given (each prefixed with '// ')."""
    lines = [
        "/*--------------------------------*- C++ -*----------------------------------*\\",
        f"  adhesiveWallInteraction tutorial: {tutorial}",
        "  SPDX-License-Identifier: GPL-3.0-or-later",
        "\\*---------------------------------------------------------------------------*/",
        "FoamFile",
        "{",
        "    version     2.0;",
        "    format      ascii;",
        f"    class       {foam_class};",
        '    location    "constant";',
        f"    object      {name};",
        "}",
        "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //",
        "",
    ]
    return "\n".join(lines + ["// " + c for c in comment]) + "\n"
