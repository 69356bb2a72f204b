# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Two runs' tables compared: statistics, totals, impact records and last
rows, matched by their keys."""

import math

from .registry import CheckError, _report, command, fmt, number
from .predicates import close
from .model_tables import KEYS, MEANS, TOTALS, _last_rows, columns, table_rows


def _kind(name):
    """'total' for a count or mass column, 'mean' for a mean speed or
    angle, None for another."""
    if name.endswith(TOTALS):
        return "total"
    if name.endswith(MEANS):
        return "mean"
    return None


def _keyed(rows):
    """The rows of a table as {(patch, injector, dMin, dMax): row dict};
    a CheckError on a repeated key."""
    keyed = {}
    for row in rows.rows:
        values = dict(zip(rows.names, row))
        key = tuple(values[k] for k in KEYS)
        if key in keyed:
            raise CheckError(f"{rows.source}: row {' '.join(key)} repeated")
        keyed[key] = values
    return keyed


def compare_statistics(reference, path, rtol_means=1e-12, rtol_totals=1e-12):
    """The differences between the last times of two statistics.dat: the
    same columns, the same last time, the same rows (by patch, injector,
    dMin, dMax), the counts and masses to rtol_totals and the mean speeds
    and angles to rtol_means relative to the reference's. Returns a list of
    messages (empty: the same)."""
    from .. import tables
    a, b = tables.read(reference), tables.read(path)
    if a.names != b.names:
        return [f"columns {' '.join(a.names)} in {reference}, "
                f"{' '.join(b.names)} in {path}"]
    problems = []
    unknown = [n for n in a.names if n != "time" and n not in KEYS
               and _kind(n) is None]
    if unknown:
        return [f"{reference}: columns of unknown kind {' '.join(unknown)}"]
    last = []
    for table in (a, b):
        try:
            last.append(table.last_time())
        except ValueError:
            return [f"{table.source}: no statistics"]
    if last[0].text("time")[0] != last[1].text("time")[0] and not close(
            float(last[1].text("time")[0]), float(last[0].text("time")[0]),
            1e-12):
        problems.append(f"last time {last[0].text('time')[0]} in "
                        f"{reference}, {last[1].text('time')[0]} in {path}")
    rows_a, rows_b = _keyed(last[0]), _keyed(last[1])
    if set(rows_a) != set(rows_b):
        missing = sorted(set(rows_a) - set(rows_b))
        extra = sorted(set(rows_b) - set(rows_a))
        return problems + [
            f"rows {[' '.join(k) for k in missing]} of {reference} not in "
            f"{path}; rows {[' '.join(k) for k in extra]} only in {path}"]
    for key, row in rows_a.items():
        other = rows_b[key]
        for name in a.names:
            kind = _kind(name)
            if kind is None:
                continue
            rtol = rtol_totals if kind == "total" else rtol_means
            x = number(row[name], f"{reference} {name}")
            y = number(other[name], f"{path} {name}")
            if not close(y, x, rtol):
                problems.append(f"{' '.join(key)} {name}: {row[name]} in "
                                f"{reference}, {other[name]} in {path} "
                                f"(to {rtol:g} relative)")
    return problems


def compare_totals(reference, path, columns, rtol=1e-12):
    """The differences between the per-patch sums of columns of two
    statistics.dat at their last times (the rows of a patch summed over
    injectors and size classes: a run without outputByInjectorId or
    sizeClasses against one with), each to rtol relative to the
    reference's. Both must have the same patches. Returns (the number of
    sums compared, a list of messages)."""
    from .. import tables
    a, b = tables.read(reference), tables.read(path)
    last_a, last_b = _last_rows(a), _last_rows(b)
    patches = last_a.unique("patch")
    if sorted(patches) != sorted(last_b.unique("patch")):
        return 0, [f"patches {patches} in {reference}, "
                   f"{last_b.unique('patch')} in {path}"]
    if not columns:
        return 0, ["no columns to compare"]
    problems = []
    n = 0
    for patch in patches:
        for column in columns:
            x = last_a.where(patch=patch).sum(column)
            y = last_b.where(patch=patch).sum(column)
            n += 1
            if not close(y, x, rtol):
                problems.append(f"{patch} {column}: {fmt(x)} in {reference},"
                                f" summed {fmt(y)} in {path}")
    return n, problems


def compare_records(reference, paths, columns, rtol):
    """The differences between the impact records of a reference run and
    those of another run written in one file or several (e.g. before and
    after a restart), in the columns named, in any order: each reference
    record must match one of the run's, texts exactly and numbers to rtol
    of the column's largest magnitude in the reference (positions near 0
    are compared on the scale of the others), and none may be left over;
    empty: none. Processor-local columns (`face`) are left out by not
    naming them."""
    from .. import tables
    is_number = tables.is_number
    if not columns:
        return ["no columns to compare"]
    a = tables.read(reference)
    parts = [tables.read(path) for path in paths]

    def rows(table):
        values = [table.text(column) for column in columns]
        return list(zip(*values))
    ref_rows = rows(a)
    run_rows = [row for part in parts for row in rows(part)]
    names = " ".join(str(path) for path in paths)
    if not ref_rows:
        return [f"no records in {reference}: nothing to compare"]
    if len(run_rows) != len(ref_rows):
        return [f"{len(ref_rows)} records in {reference}, "
                f"{len(run_rows)} in {names}"]
    # A NaN would compare as equal to anything
    for where, table_rows in ((reference, ref_rows), (names, run_rows)):
        for row in table_rows:
            if any(is_number(v) and math.isnan(float(v)) for v in row):
                return [f"a NaN in {where}: record {row}"]
    scales = [max((abs(float(row[i])) for row in ref_rows
                   if is_number(row[i])), default=0.0)
              for i in range(len(columns))]

    def matches(x, y):
        return all(
            abs(float(y[i]) - float(x[i])) <= rtol * scales[i]
            if is_number(x[i]) and is_number(y[i]) else x[i] == y[i]
            for i in range(len(columns)))
    # Matched one by one (sorting would pair neighbours wrongly where a
    # column's values differ by rounding only)
    left = list(run_rows)
    problems = []
    for x in ref_rows:
        found = next((k for k, y in enumerate(left) if matches(x, y)), None)
        if found is None:
            problems.append(f"record {x} of {reference}: none in {names}")
        else:
            del left[found]
    problems += [f"record {y} of {names}: none in {reference}"
                 for y in left]
    return problems


def compare_last_rows(reference, path, columns, rtol=1e-12,
                      keys=("injector", "dMin", "dMax")):
    """The differences between the rows of two tables at their last times,
    matched by the key columns, in the columns named, each to rtol relative
    to the reference's; empty: none."""
    from .. import tables
    a = tables.read(reference).last_time()
    b = tables.read(path).last_time()
    if not len(a) or not columns:
        return ["nothing to compare"]

    def keyed(table):
        return {tuple(table.text(k)[row] for k in keys): row
                for row in range(len(table))}
    rows_a, rows_b = keyed(a), keyed(b)
    if sorted(rows_a) != sorted(rows_b):
        return [f"rows {sorted(rows_a)} in {reference}, {sorted(rows_b)} in {path}"]
    problems = []
    for key, row in rows_a.items():
        for column in columns:
            x, y = a[column][row], b[column][rows_b[key]]
            if not close(y, x, rtol):
                problems.append(f"{key} {column}: {fmt(x)} in {reference}, "
                                f"{fmt(y)} in {path}")
    return problems


@command("compareStatistics", "REFERENCE FILE [MEANS_RTOL]")
def _compare_statistics(reference, path, rtol="1e-12"):
    """Two statistics.dat end with the same rows: counts and masses to
    1e-12, mean speeds and angles to MEANS_RTOL (1e-12) relative."""
    _report(compare_statistics(reference, path, number(rtol, "MEANS_RTOL")))


@command("compareTotals", "REFERENCE FILE RTOL COLUMN...")
def _compare_totals(reference, path, rtol, *names):
    """The per-patch sums of the columns at the last time agree to RTOL
    (over injectors and size classes)."""
    n, problems = compare_totals(reference, path, names, number(rtol, "RTOL"))
    _report(problems, f"{n} per-patch sums agree")


@command("compareRecords", "REFERENCE RTOL 'COLUMN...' FILE...")
def _compare_records(reference, rtol, names, *paths):
    """The impact records of a run (in one file or in several, e.g. before
    and after a restart) are the reference's, in the columns named, in any
    order: texts equal, numbers to RTOL of the column's largest."""
    problems = compare_records(reference, paths, names.split(),
                               number(rtol, "RTOL"))
    _report(problems, "the records agree")


@command("compareLastRows", "REFERENCE FILE RTOL COLUMN...")
def _compare_last_rows(reference, path, rtol, *columns):
    """Two tables' rows at their last times, matched by injector, dMin and
    dMax, in the columns named."""
    _report(compare_last_rows(reference, path, columns, number(rtol)),
            f"{path}: the rows of {reference}")
