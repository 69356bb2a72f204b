# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The model's tables read by column name: statistics.dat (per patch,
injector and size class), surfaceContact.dat, massBalance.dat and any
table's rows and columns; the log's lines per step."""

import math
import re

from .registry import CheckError, _report, command, fmt, number
from .predicates import median


KEYS = ("patch", "injector", "dMin", "dMax")


TOTALS = ("Parcels", "Particles", "Mass")


MEANS = ("Speed", "Angle")


def _conditions(patch=None, injector=None, dMin=None):
    """A selection of statistics rows as Table.where takes it: the patch and
    injector as written, the lower diameter as a number (None or empty:
    any)."""
    conditions = {}
    if patch:
        conditions["patch"] = patch
    if injector:
        conditions["injector"] = injector
    if dMin not in (None, ""):
        conditions["dMin"] = number(dMin, "dMin")
    return conditions


def _last_rows(table, patch=None):
    """The rows of a statistics table at its last time (of the patch
    given); a CheckError when it has no rows at all."""
    try:
        last = table.last_time()
    except ValueError:
        raise CheckError(f"{table.source}: no rows") from None
    return last.where(**_conditions(patch))


def statistic(path, column, patch=None, injector=None, dMin=None):
    """A column of a statistics.dat at its last time, summed over the rows
    of the patch, injector and lower diameter given (None or empty: any); a
    CheckError when the column or the rows are not there."""
    from .. import statistics, tables
    table = tables.read(path)
    if column not in table:
        raise CheckError(f"{path}: no column '{column}'")
    try:
        return statistics.final(table, column,
                                **_conditions(patch, injector, dMin))
    except (KeyError, ValueError):
        raise CheckError(
            f"{path}: no rows of patch '{patch or 'any'}', injector "
            f"'{injector or 'any'}', dMin '{dMin or 'any'}' at its last "
            "time") from None


def surface_contacts(statistics_path, contacts_path):
    """The contacts at the surface and at the centre (fallbacks) of
    surfaceContact.dat at its last time, summed over the patches, after
    checking that on each patch of statistics.dat the impacts are those
    contacts (every contact an impact, counted once in each file); a
    CheckError lists the patches where they are not."""
    from .. import tables
    impacts = _last_rows(tables.read(statistics_path))
    contacts = _last_rows(tables.read(contacts_path))
    times = (impacts.text("time")[0], contacts.text("time")[0])
    if float(times[0]) != float(times[1]):
        raise CheckError(f"last times {times[0]} in {statistics_path}, "
                         f"{times[1]} in {contacts_path}")
    problems = []
    patches = impacts.unique("patch")
    patches += [p for p in contacts.unique("patch") if p not in patches]
    for patch in patches:
        counted = impacts.where(patch=patch).sum("impactParcels")
        touched = contacts.where(patch=patch)
        at_surface = touched.sum("surfaceContacts")
        at_centre = touched.sum("centreContacts")
        if counted != at_surface + at_centre:
            problems.append(
                f"{patch}: {fmt(counted)} impacts in {statistics_path}, "
                f"{fmt(at_surface)} + {fmt(at_centre)} contacts in "
                f"{contacts_path}")
    _report(problems)
    return contacts.sum("surfaceContacts"), contacts.sum("centreContacts")


def statistic_rows(path, patch=None):
    """The number of rows of a statistics.dat at its last time (of the
    patch given); a CheckError when the file has no rows at all."""
    from .. import tables
    return len(_last_rows(tables.read(path), patch))


def log_lines_per_step(log):
    """The log's lines per time step (between two "Time = " lines): the
    number of steps, the median of the lines of a step but the last, the
    model's summary lines ("adhesiveWallInteraction <patch> (parcels") and
    full-table rows ("adhesiveWallInteraction patch ") of such a step (the
    largest), and the lines and full-table rows of the last step (a write
    time)."""
    steps = []
    with open(log) as f:
        for line in f:
            if line.startswith("Time = "):
                steps.append([])
            elif steps:
                steps[-1].append(line)
    if len(steps) < 2:
        raise CheckError(f"{log}: fewer than two time steps")

    def summary(step):
        return sum(1 for l in step if re.search(
            r"adhesiveWallInteraction \S+ \(parcels, particles\)", l))

    def rows(step):
        return sum(1 for l in step if "adhesiveWallInteraction patch " in l)
    middle = steps[:-1]
    return (len(steps), median([len(s) for s in middle]),
            max(summary(s) for s in middle), max(rows(s) for s in middle),
            len(steps[-1]), rows(steps[-1]))


def time_range(path):
    """The first and the last time of a table with a time column, as
    written; a CheckError when it has no rows."""
    from .. import tables
    table = tables.read(path)
    column = "time" if "time" in table else "Time"
    times = table.text(column)
    if not times:
        raise CheckError(f"{path}: no rows")
    return times[0], times[-1]


def mass_balance(path):
    """The last row of a massBalance.dat, as {column: text as written}; a
    CheckError when it has no rows."""
    from .. import tables
    table = tables.read(path)
    try:
        last = table.last_time()
    except ValueError:
        raise CheckError(f"{path}: no mass balance written") from None
    return dict(zip(last.names, last.rows[-1]))


def table_rows(path, columns=()):
    """The number of data rows of a table file (comment lines aside); a
    CheckError when one of the columns named is not in its header."""
    from .. import tables
    table = tables.read(path)
    for column in columns:
        if column not in table:
            raise CheckError(f"{path}: no column '{column}'; it has "
                             f"{' '.join(table.names)}")
    return len(table)


def columns(path, names, where=None, sort_by=None):
    """The rows of a table's columns named, in the order named, as text;
    only the rows whose columns equal the texts of `where` (a dict), in the
    numeric order of the column `sort_by` when given (ties as written)."""
    from .. import tables
    table = tables.read(path)
    if where:
        table = table.where(**where)
    values = [table.text(name) for name in names]
    rows = list(zip(*values))
    if sort_by is not None:
        keys = [number(key, f"{path}: sort column '{sort_by}' value")
                for key in table.text(sort_by)]
        if any(math.isnan(key) for key in keys):
            raise CheckError(f"{path}: a NaN in sort column '{sort_by}'")
        rows = [row for _, row in sorted(zip(keys, rows),
                                         key=lambda pair: pair[0])]
    return rows


def replace_value(path, row, column, value):
    """The lines of a CSV file (a header line, then rows) with the value of
    a column (by name) in a data row (1: the first after the header)
    replaced by the text given; a CheckError when the row or column is not
    there."""
    with open(path) as f:
        lines = f.read().splitlines()
    if not lines:
        raise CheckError(f"{path}: empty")
    names = lines[0].split(",")
    if column not in names:
        raise CheckError(f"{path}: no column '{column}'; it has "
                         f"{' '.join(names)}")
    if not 1 <= row < len(lines):
        raise CheckError(f"{path}: no data row {row}")
    fields = lines[row].split(",")
    if len(fields) != len(names):
        raise CheckError(f"{path}: row {row} has {len(fields)} fields")
    fields[names.index(column)] = value
    lines[row] = ",".join(fields)
    return lines


@command("statistic", "FILE COLUMN [PATCH [INJECTOR [DMIN]]]")
def _statistic(path, column, patch="", injector="", dMin=""):
    """A column of a statistics.dat at its last time, summed over the rows
    selected (empty: any)."""
    print(fmt(statistic(path, column, patch, injector, dMin)))


@command("surfaceContacts", "STATISTICS SURFACE_CONTACT")
def _surface_contacts(statistics_path, contacts_path):
    """On each patch the impacts of statistics.dat are the contacts of
    surfaceContact.dat; prints the contacts 'at the surface' 'at the
    centre' summed over the patches."""
    at_surface, at_centre = surface_contacts(statistics_path, contacts_path)
    print(fmt(at_surface), fmt(at_centre))


@command("statisticRows", "FILE [PATCH]")
def _statistic_rows(path, patch=""):
    """The number of rows of a statistics.dat at its last time (of a
    patch)."""
    print(statistic_rows(path, patch))


@command("timeRange", "FILE")
def _time_range(path):
    """The first and last time of a table: 'first last'."""
    print(" ".join(time_range(path)))


@command("massBalance", "FILE [COLUMN...]")
def _mass_balance(path, *names):
    """The last row of a massBalance.dat: the columns named (injected
    residual), as written."""
    row = mass_balance(path)
    missing = [n for n in names if n not in row]
    if missing:
        raise CheckError(f"{path}: no column {' '.join(missing)}")
    print(" ".join(row[n] for n in (names or ("injected", "residual"))))


@command("tableRows", "FILE [COLUMN...]")
def _table_rows(path, *names):
    """The number of data rows of a table (whose header holds the columns
    named)."""
    print(table_rows(path, names))


@command("columns", "FILE [COLUMN=TEXT...] [-sort COLUMN] COLUMN...")
def _columns(path, *arguments):
    """The columns named of a table, as CSV rows without a header; only the
    rows whose COLUMN reads TEXT as written (none: no output; 1e-5 does not
    match 1e-05), in the numeric order of -sort's column."""
    where, sort_by, names = {}, None, []
    arguments = list(arguments)
    while arguments:
        argument = arguments.pop(0)
        if argument == "-sort":
            if not arguments:
                raise CheckError("-sort needs a column name")
            sort_by = arguments.pop(0)
        elif "=" in argument:
            name, _, text = argument.partition("=")
            where[name] = text
        else:
            names.append(argument)
    if not names:
        raise CheckError("no column named to print")
    for row in columns(path, names, where, sort_by):
        print(",".join(row))


@command("replaceValue", "FILE ROW COLUMN VALUE")
def _replace_value(path, row, column, value):
    """A CSV file with one value replaced (data row ROW from 1, column by
    name), printed."""
    print("\n".join(replace_value(path, int(row), column, value)))


@command("logLinesPerStep", "LOG")
def _log_lines_per_step(log):
    """steps, median lines a step, the model's summary lines and table rows
    of a step, the last step's lines and table rows (see
    log_lines_per_step)."""
    print(" ".join(fmt(v) for v in log_lines_per_step(log)))
