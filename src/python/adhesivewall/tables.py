# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Tables with a header line, read and written by column name.

The model writes `statistics.dat` and `massBalance.dat` (tab-separated, the
header the last comment line `# time ...` before the data) and `impacts.csv`
(comma-separated, the header its first line, a closing `# capped ...` line
when capped); the tutorials' reference data are CSV files whose leading
`#` lines cite their source. `read` takes any of them; a column is asked for
by its name, never by its position.
"""

import math
import numpy as np


class Table:
    """Rows of text under named columns.

    `table["name"]` is the column as a numpy array of floats when every value
    is a number ("inf" and "nan" included), else of strings; `text("name")`
    always gives the strings as written.
    """

    def __init__(self, names, rows, source="table"):
        self.names = list(names)
        self.rows = [tuple(row) for row in rows]
        self.source = source
        if len(set(self.names)) != len(self.names):
            raise ValueError(f"{source}: repeated column names {self.names}")
        for row in self.rows:
            if len(row) != len(self.names):
                raise ValueError(
                    f"{source}: a row of {len(row)} values under "
                    f"{len(self.names)} columns: {row}")

    def __len__(self):
        return len(self.rows)

    def __contains__(self, name):
        return name in self.names

    def _index(self, name):
        try:
            return self.names.index(name)
        except ValueError:
            raise KeyError(
                f"{self.source}: no column '{name}'; it has "
                f"{' '.join(self.names)}") from None

    def text(self, name):
        """The column's values as written."""
        i = self._index(name)
        return [row[i] for row in self.rows]

    def __getitem__(self, name):
        values = self.text(name)
        try:
            return np.array([float(v) for v in values], dtype=float)
        except ValueError:
            return np.array(values, dtype=object)

    def where(self, **conditions):
        """The rows whose columns equal the values given (compared as text
        when given as text, as numbers otherwise), or satisfy a callable."""
        tests = []
        for name, wanted in conditions.items():
            i = self._index(name)
            if callable(wanted):
                tests.append(lambda row, i=i, f=wanted: f(row[i]))
            elif isinstance(wanted, str):
                tests.append(lambda row, i=i, w=wanted: row[i] == w)
            else:
                tests.append(
                    lambda row, i=i, w=float(wanted): float(row[i]) == w)
        return Table(self.names,
                     [row for row in self.rows if all(t(row) for t in tests)],
                     self.source)

    def last_time(self, column="time"):
        """The rows of the last time (the largest value of `column`)."""
        if not self.rows:
            raise ValueError(f"{self.source}: no rows")
        times = self[column]
        return Table(self.names,
                     [row for row, t in zip(self.rows, times)
                      if t == times.max()], self.source)

    def unique(self, name):
        """The distinct values of a column as written, in order of first
        appearance."""
        seen = {}
        for value in self.text(name):
            seen.setdefault(value, None)
        return list(seen)

    def sum(self, name):
        return float(self[name].sum()) if self.rows else 0.0


def is_number(text):
    """True when the text reads as a number (nan and inf included)."""
    try:
        float(text)
        return True
    except ValueError:
        return False


def _split(line, delimiter):
    if delimiter is None:
        return line.split()
    return [field.strip() for field in line.rstrip("\n").split(delimiter)]


def read(path, delimiter=None):
    """A table file: the header is the first line, or, where the file opens
    with comment lines, the last comment line before the data (its `#`
    stripped). Comment lines (`#`) elsewhere are skipped. The delimiter is a
    comma for `.csv` files, a tab where the header holds one, else white
    space."""
    path = str(path)
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f if line.strip()]
    if not lines:
        raise ValueError(f"{path}: empty")
    comment = None      # the last comment line before the first other line
    header = None
    data = []
    for line in lines:
        if line.lstrip().startswith("#"):
            if header is None and not data:
                comment = line.lstrip()[1:].strip(" ")
            continue
        if header is None and not data:
            # The first other line is the header unless it holds numbers
            # under a commented header (the model's .dat files)
            first = _split(line, "," if path.endswith(".csv") else None)[0]
            if comment is None or not is_number(first):
                header = line
                continue
            header = comment
        data.append(line)
    if header is None:
        if comment is None:
            raise ValueError(f"{path}: no header line")
        header = comment
    if delimiter is None:
        if path.endswith(".csv"):
            delimiter = ","
        elif "\t" in header:
            delimiter = "\t"
    return Table(_split(header, delimiter),
                 [_split(line, delimiter) for line in data], path)


def read_text(text, delimiter=","):
    """A table from its text (a header line, then rows)."""
    lines = [line for line in text.splitlines()
             if line.strip() and not line.startswith("#")]
    return Table(_split(lines[0], delimiter),
                 [_split(line, delimiter) for line in lines[1:]], "text")


def write_csv(path, names, rows):
    """A CSV file of the rows (sequences of text or numbers written with
    str), under the header of the names."""
    with open(path, "w") as f:
        f.write(",".join(names) + "\n")
        for row in rows:
            if len(row) != len(names):
                raise ValueError(f"{path}: row {row} under {names}")
            f.write(",".join(str(v) for v in row) + "\n")


def relative_difference(a, b):
    """|a - b|/|b|, or |a - b| where b is 0."""
    return abs(a - b) / abs(b) if b != 0 else abs(a - b)


def compare(table, reference, rtol=1e-12, key=None):
    """Differences between two tables of the same columns and rows: numbers
    beyond rtol relative, text that differs. Returns a list of messages
    (empty: equal)."""
    problems = []
    if table.names != reference.names:
        return [f"columns {table.names} against {reference.names}"]
    if len(table) != len(reference):
        return [f"{len(table)} rows against {len(reference)}"]
    for r, (row, expected) in enumerate(zip(table.rows, reference.rows)):
        for name, a, b in zip(table.names, row, expected):
            if a == b:
                continue
            try:
                x, y = float(a), float(b)
            except ValueError:
                problems.append(f"row {r + 1} {name}: '{a}' against '{b}'")
                continue
            if math.isnan(x) or math.isnan(y) or \
                    relative_difference(x, y) > rtol:
                problems.append(f"row {r + 1} {name}: {a} against {b}")
    return problems


def compare_files(path, reference, rtol=1e-12):
    """Differences of a file from its reference: tables (.csv, .dat) by
    column name, numbers to rtol relative; any other file line for line."""
    import os
    if not os.path.exists(path):
        return [f"{path}: not written"]
    if path.endswith((".csv", ".dat")):
        return [f"{path}: {p}" for p in compare(read(path), read(reference),
                                                rtol)]
    with open(path) as a, open(reference) as b:
        mine, theirs = a.read().splitlines(), b.read().splitlines()
    if mine == theirs:
        return []
    for i, (x, y) in enumerate(zip(mine + [""] * len(theirs),
                                   theirs + [""] * len(mine))):
        if x != y:
            return [f"{path}: line {i + 1}: '{x}' against '{y}'"]
    return [f"{path}: differs"]


def compare_folders(folder, reference, rtol=1e-12):
    """compare_files for every file under `reference` (but README files)
    against the same path under `folder`."""
    import os
    problems = []
    for root, _, files in os.walk(reference):
        for name in sorted(files):
            if name.startswith("README"):
                continue
            expected = os.path.join(root, name)
            problems += compare_files(
                os.path.join(folder, os.path.relpath(expected, reference)),
                expected, rtol)
    return problems
