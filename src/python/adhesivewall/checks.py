# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The case tests' checks (tests/cases) and the benchmark's figures
(tests/bench/run), from the shell:

    adhesiveWallPost check SUBCOMMAND ARGUMENTS...

A subcommand prints a value (a sum, a count, a line of the benchmark) or
checks something. When a check fails, or a value cannot be had (a missing
file, column, patch or row), it prints a message naming what differs or
what is missing on stderr and exits with status 1; a wrong usage exits
with 2. `adhesiveWallPost check -help` lists the subcommands.

The model's tables are read by column name (`tables`, `statistics`),
OpenFOAM's files with the package's parser (`foam`). Nothing here passes on
nothing: a sum over no rows, a comparison of two empty lists, a boundary sum
over a patch the field does not have, a mass of no injector are errors.

`tables` and `statistics` (which load numpy) are imported by the functions
that read tables, so that the arithmetic checks (close, small, between)
start in a few tens of milliseconds.

Tolerances are relative to the reference (expected) value: `close(value,
expected, rtol)` is |value - expected| <= rtol |expected|, so that an
expected 0 asks for exactly 0.
"""

import math
import os
import random
import re
import sys

from . import foam


class CheckError(Exception):
    """A check that failed, or had nothing to check: the message says
    what."""


#------------------------------------------------------------------------------
# Numbers

def number(text, what="value"):
    """A number given as text (a command-line argument, a table's cell), or
    a CheckError naming what it should have been."""
    try:
        return float(text)
    except (TypeError, ValueError):
        raise CheckError(f"{what} '{text}' is not a number") from None


def fmt(value):
    """A number as the shell gets it, in its shortest exact form (as the
    model writes its tables): an integral value without decimals (15, not
    15.0), others as Python's repr (the shortest text that reads back as
    the same double: 3.5e-14, not 3.5000000000000002e-14)."""
    value = float(value)
    if value.is_integer() and abs(value) < 1e16:
        return str(int(value))
    return repr(value)


def close(value, expected, rtol):
    """True when |value - expected| <= rtol |expected| (an expected 0 asks
    for exactly 0; a NaN is never close)."""
    return abs(value - expected) <= rtol * abs(expected)


def small(value, rtol, scale):
    """True when |value| <= rtol scale and scale > 0 (a residual against
    the mass it is a residual of: a zero scale has nothing to compare)."""
    return scale > 0 and abs(value) <= rtol * scale


def near(value, expected, rtol, scale):
    """True when |value - expected| <= rtol scale and scale > 0 (a position
    against the expected one, to a fraction of the particle's size)."""
    return scale > 0 and abs(value - expected) <= rtol * scale


def sums_to(total, rtol, parts):
    """True when the parts add up to the total to rtol relative, the total
    > 0 (a balance: what went in against where it went)."""
    return small(total - math.fsum(parts), rtol, total)


def between(value, low, high):
    """True when low < value < high (bounds excluded)."""
    return low < value < high


def median(values):
    """The median of the values (the mean of the middle two of an even
    count); a CheckError for none."""
    ordered = sorted(values)
    n = len(ordered)
    if not n:
        raise CheckError("the median of no values")
    return ordered[n // 2] if n % 2 else (ordered[n//2 - 1] + ordered[n//2])/2


def mean_and_deviation(values):
    """The mean and the sample standard deviation (n - 1; 0 for one value)
    of the values; a CheckError for none."""
    n = len(values)
    if not n:
        raise CheckError("the mean of no values")
    m = math.fsum(values) / n
    if n == 1:
        return m, 0.0
    return m, math.sqrt(math.fsum((v - m)**2 for v in values) / (n - 1))


#------------------------------------------------------------------------------
# The model's statistics.dat and massBalance.dat

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
    from . import statistics, tables
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
    from . import tables
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
    from . import tables
    return len(_last_rows(tables.read(path), patch))


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
    from . import tables
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
    from . import tables
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
    from . import tables
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
    from . import tables
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
    from . import tables
    table = tables.read(path)
    column = "time" if "time" in table else "Time"
    times = table.text(column)
    if not times:
        raise CheckError(f"{path}: no rows")
    return times[0], times[-1]


def mass_balance(path):
    """The last row of a massBalance.dat, as {column: text as written}; a
    CheckError when it has no rows."""
    from . import tables
    table = tables.read(path)
    try:
        last = table.last_time()
    except ValueError:
        raise CheckError(f"{path}: no mass balance written") from None
    return dict(zip(last.names, last.rows[-1]))


def table_rows(path, columns=()):
    """The number of data rows of a table file (comment lines aside); a
    CheckError when one of the columns named is not in its header."""
    from . import tables
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
    from . import tables
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


#------------------------------------------------------------------------------
# OpenFOAM's files

def _is_number_word(word):
    """A word of a field file that is a number (nan and inf included)."""
    try:
        float(word)
    except ValueError:
        return False
    return re.fullmatch(
        r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?|[-+]?(nan|inf)", word,
        re.IGNORECASE) is not None


def field_numbers(path):
    """Every number of a field file after its FoamFile header, in order
    (list sizes, values, labels of a lagrangian field; dimensions, values
    and list sizes of a volume field)."""
    return [float(w) for kind, w in foam.tokens(foam.body(path))
            if kind == "word" and _is_number_word(w)]


def compare_fields(reference, path, rtol=1e-12):
    """The differences between two field files of the same layout, number
    by number (field_numbers) to rtol relative to the reference's. Returns
    a list of messages (empty: the same); files without numbers differ."""
    a, b = field_numbers(reference), field_numbers(path)
    if not a:
        return [f"{reference}: no numbers"]
    if len(a) != len(b):
        return [f"{len(a)} numbers in {reference}, {len(b)} in {path}"]
    problems = [f"number {i + 1}: {fmt(x)} in {reference}, {fmt(y)} in "
                f"{path}" for i, (x, y) in enumerate(zip(a, b))
                if not close(y, x, rtol)]
    return problems


def _flat(items):
    """A nested list's numbers, depth first."""
    for item in items:
        if isinstance(item, list):
            yield from _flat(item)
        else:
            yield item


def lagrangian_values(path):
    """The values of a lagrangian field file (a list, uniform n{v} or
    not), vectors flattened."""
    return list(_flat(foam.list_file(path)))


def last_vector(path):
    """The last vector of a lagrangian vector field file (a parcel's
    velocity, angular momentum) or of a positions file (the v1706 form,
    '(x y z) cell' a parcel); a CheckError when it holds none."""
    items = foam.list_file(path)
    if os.path.basename(path) == "positions":
        items = [item for item in items if isinstance(item, list)]
    if not items:
        raise CheckError(f"{path}: no parcels")
    last = items[-1]
    if not isinstance(last, list) or len(last) != 3:
        raise CheckError(f"{path}: its last value {last} is not a vector")
    return [float(x) for x in last]


def compare_vectors(actual, expected, rtol):
    """The differences of two vectors component by component, each to rtol
    relative to the largest component of the expected one. Returns a list
    of messages (empty: the same); an expected zero vector differs."""
    if len(actual) != 3 or len(expected) != 3:
        return [f"not two vectors: {actual}, {expected}"]
    scale = max(abs(x) for x in expected)
    if scale == 0:
        return ["the expected vector is zero: no scale to compare with"]
    return [f"component {i}: {fmt(a)} against {fmt(e)}"
            for i, (a, e) in enumerate(zip(actual, expected))
            if not abs(a - e) <= rtol * scale]


def cloud_mass(time_folder, cloud="kinematicCloud"):
    """The mass of a cloud's parcels at a written time [kg]: the sum of
    nParticle rho pi d^3/6 over its lagrangian fields (0 when the cloud
    holds no parcel then); a CheckError when the time was not written."""
    if not os.path.isdir(time_folder):
        raise CheckError(f"no time folder {time_folder}")
    folder = os.path.join(time_folder, "lagrangian", cloud)
    if not os.path.exists(os.path.join(folder, "d")):
        return 0.0
    d, n, rho = (lagrangian_values(os.path.join(folder, name))
                 for name in ("d", "nParticle", "rho"))
    if not len(d) == len(n) == len(rho):
        raise CheckError(f"{folder}: {len(d)} d, {len(n)} nParticle, "
                         f"{len(rho)} rho")
    return math.fsum(ni * r * math.pi * di**3 / 6
                     for di, ni, r in zip(d, n, rho))


def boundary_values(path, patches=()):
    """The boundary values of a volScalarField file on the patches named
    (all those with values when none is), as a list; a uniform zero adds
    none. A uniform non-zero value cannot be listed without the patch's
    size: it is a CheckError, as is a patch named that the field does not
    have, or a field with no boundary values at all."""
    fields = foam.parse(foam.body(path)).get("boundaryField", {})
    values = {name: entries["value"] for name, entries in fields.items()
              if isinstance(entries, dict) and "value" in entries}
    missing = [p for p in patches if p not in values]
    if missing:
        raise CheckError(f"{path}: no boundary values on {' '.join(missing)}"
                         f" (it has {' '.join(values) or 'none'})")
    if not values:
        raise CheckError(f"{path}: no boundary values")
    found = []
    for patch in patches or values:
        value = values[patch]
        if isinstance(value, list) and value and value[0] == "uniform":
            if float(value[1]) != 0:
                raise CheckError(f"{path}: uniform {value[1]} on {patch}: "
                                 "its face count is not in the file")
        elif isinstance(value, list) and value and value[0] == "nonuniform":
            found += [float(v) for v in value[-1]]
        else:
            raise CheckError(f"{path}: value of {patch}: {value}")
    return found


def boundary_sum(path, patches=()):
    """The sum of the boundary values of a volScalarField file over the
    patches named (all those with values when none is): boundary_values'
    errors."""
    return math.fsum(boundary_values(path, patches))


def boundary_min(path, patches=()):
    """The smallest boundary value of a volScalarField file on the patches
    named (0 where they hold only a uniform zero): boundary_values'
    errors."""
    return min(boundary_values(path, patches), default=0.0)


def injected_mass(case=".",
                  cloud_properties="constant/kinematicCloudProperties",
                  injectors="constant/injectors"):
    """The mass the manual injectors of a case's injectors file put into
    the cloud [kg]: per injector, its positions x nParticle x rho pi d^3/6
    (fixed parcel basis, a fixedValue size distribution, rho the cloud's
    constantProperties/rho0). A CheckError for another kind of injector or
    none at all."""
    rho = number(foam.value(cloud_properties, "constantProperties/rho0",
                            case=case), "rho0")
    with open(os.path.join(case, injectors)) as f:
        entries = foam.parse(f.read())
    total = []
    for name, injector in entries.items():
        if not isinstance(injector, dict):
            continue
        if injector.get("type") != "manualInjection" \
                or injector.get("parcelBasisType") != "fixed":
            raise CheckError(f"{injectors}: {name} is not a manual injection"
                             " of a fixed parcel basis")
        size = injector.get("sizeDistribution", {})
        if size.get("type") != "fixedValue":
            raise CheckError(f"{injectors}: {name} has no fixed diameter")
        d = number(size["fixedValueDistribution"]["value"], f"{name} d")
        n = number(injector["nParticle"], f"{name} nParticle")
        positions = len(foam.list_file(os.path.join(
            case, "constant", injector["positionsFile"])))
        total.append(positions * n * rho * math.pi * d**3 / 6)
    if not total:
        raise CheckError(f"{injectors}: no injector")
    return math.fsum(total)


def _size_class(d, edges):
    """The index of the size class of a diameter, classes bounded by the
    edges (below the first, between two, above the last)."""
    return sum(1 for edge in edges if not d < edge)


QUANTITIES = ("injected", "captured", "escaped", "removed", "airborne")


def expected_grade_efficiency(case=".", start_time="0",
                              cloud="kinematicCloud"):
    """Per size class, what gradeEfficiency.dat must hold at the last time,
    counted independently of the model's counters: injected from the
    injectors (constant/injectors: positions x nParticle, d, rho0),
    captured (net of the resuspended) and escaped from the impact records
    (impacts.csv), airborne
    from the cloud's lagrangian files at the last written time (active
    parcels), removed as the rest. {(dMin, dMax): {quantity: [parcels,
    particles, mass]}}, the classes those of the file. A CheckError where
    the records cannot hold every impact: recordPatches in the model's
    coefficients, or a file capped at maxImpactRecords."""
    from . import statistics, tables
    folder = statistics.output_folder(case, cloud, start_time)
    grade = tables.read(os.path.join(folder,
                                     "gradeEfficiency.dat")).last_time()
    classes = list(zip(grade["dMin"], grade["dMax"]))
    edges = sorted({hi for _, hi in classes if math.isfinite(hi)})
    properties = f"constant/{cloud}Properties"
    coeffs = foam.dictionary(properties,
                             "subModels/adhesiveWallInteractionCoeffs",
                             case=case)
    if "recordPatches" in coeffs:
        raise CheckError(f"{case}: recordPatches in {properties}: "
                         "impacts.csv holds only those patches' impacts, "
                         "and the grade efficiency cannot be counted from it")
    records_path = os.path.join(folder, "impacts.csv")
    if not os.path.isfile(records_path):
        raise CheckError(f"{case}: no {records_path}: the grade efficiency "
                         "is counted from the impact records "
                         "(maxImpactRecords)")
    with open(records_path) as f:
        if any(line.startswith("# capped") for line in f):
            raise CheckError(f"{case}: impacts.csv is capped at "
                             "maxImpactRecords, and the grade efficiency "
                             "cannot be counted from it")
    rho = number(foam.value(properties, "constantProperties/rho0",
                            case=case), "rho0")
    counts = {c: {q: [0.0, 0.0, 0.0] for q in QUANTITIES} for c in classes}

    def add(quantity, d, n, parcels=1):
        cell = counts[classes[_size_class(d, edges)]][quantity]
        cell[0] += parcels
        cell[1] += parcels * n
        cell[2] += parcels * n * rho * math.pi * d**3 / 6

    with open(os.path.join(case, "constant", "injectors")) as f:
        injectors = foam.parse(f.read())
    for name, injector in injectors.items():
        d = number(injector["sizeDistribution"]["fixedValueDistribution"]
                   ["value"], f"{name} d")
        positions = len(foam.list_file(os.path.join(
            case, "constant", injector["positionsFile"])))
        add("injected", d, number(injector["nParticle"]), positions)
    records = tables.read(records_path)
    for outcome, quantity, sign in (("capture", "captured", 1),
                                    ("escape", "escaped", 1),
                                    ("resuspension", "captured", -1)):
        for d, n in zip(*(records.where(outcome=outcome)[c]
                          for c in ("diameter", "nParticle"))):
            add(quantity, d, n, sign)
    time = foam.latest_time(case)
    folder = os.path.join(case, time, "lagrangian", cloud)
    if foam.parcel_count(case, time, cloud):
        fields = [foam.list_file(os.path.join(folder, name))
                  for name in ("d", "nParticle", "active")]
        for d, n, active in zip(*fields):
            if active:
                add("airborne", d, n)
    for cell in counts.values():
        cell["removed"] = [cell["injected"][i] - cell["captured"][i]
                           - cell["escaped"][i] - cell["airborne"][i]
                           for i in range(3)]
    return counts


def check_grade_efficiency(case=".", start_time="0", cloud="kinematicCloud",
                           rtol=1e-12):
    """The differences of gradeEfficiency.dat's last rows from
    expected_grade_efficiency, and of its own closure (injected = captured
    + escaped + removed + airborne) and capturedFraction; empty: none."""
    from . import statistics, tables
    grade = tables.read(os.path.join(
        statistics.output_folder(case, cloud, start_time),
        "gradeEfficiency.dat")).last_time()
    expected = expected_grade_efficiency(case, start_time, cloud)
    problems = []
    for row in range(len(grade)):
        key = (grade["dMin"][row], grade["dMax"][row])
        values = {q: [grade[q + part][row] for part in
                      ("Parcels", "Particles", "Mass")] for q in QUANTITIES}
        for q in QUANTITIES:
            for i, part in enumerate(("Parcels", "Particles", "Mass")):
                want = expected[key][q][i]
                if not (abs(values[q][i] - want)
                        <= rtol * max(abs(want), values["injected"][i])):
                    problems.append(f"class {key}: {q}{part} "
                                    f"{fmt(values[q][i])}, expected {fmt(want)}")
        for i, part in enumerate(("Parcels", "Particles", "Mass")):
            rest = sum(values[q][i] for q in QUANTITIES[1:])
            if not abs(values["injected"][i] - rest) \
                    <= rtol * values["injected"][i]:
                problems.append(f"class {key}: {part} injected "
                                f"{fmt(values['injected'][i])} != {fmt(rest)}")
        fraction = values["captured"][1] / values["injected"][1] \
            if values["injected"][1] else 0
        if not close(grade["capturedFraction"][row], fraction, 1e-12):
            problems.append(f"class {key}: capturedFraction "
                            f"{grade['capturedFraction'][row]}, expected {fraction}")
    if not len(grade):
        problems.append("gradeEfficiency.dat: no rows")
    return problems


def steps(case="."):
    """The number of time steps of a run of fixed deltaT from the case's
    controlDict: (endTime - startTime)/deltaT; a CheckError when it is not
    a whole number."""
    def value(entry, default=None):
        try:
            return number(foam.value("system/controlDict", entry, case=case),
                          entry)
        except RuntimeError:
            if default is None:
                raise
            return default
    n = (value("endTime") - value("startTime", 0.0)) / value("deltaT")
    if abs(n - round(n)) > 1e-6 * max(1.0, n):
        raise CheckError(f"{case}: {n} time steps is not a whole number")
    return int(round(n))


def patch_interaction_models(path):
    """The patch interaction models that have written their totals into a
    cloud's output properties file (uniform/lagrangian/<cloud>/
    <cloud>OutputProperties): the dictionaries under
    patchInteractionModel."""
    with open(path) as f:
        entries = foam.parse(f.read()).get("patchInteractionModel", {})
    return [name for name, value in entries.items() if isinstance(value, dict)]


#------------------------------------------------------------------------------
# The core's prediction and the tools' outputs

#: The fields of tests/tools/coreRebound's one output line, in its order
CORE_FIELDS = ("Ux", "Uy", "Uz", "captured", "wx", "wy", "wz", "R", "gamma",
               "WA", "energyLoss")


def core_result(text):
    """coreRebound's output line as {field: number} (CORE_FIELDS)."""
    words = text.split()
    if len(words) != len(CORE_FIELDS):
        raise CheckError(f"coreRebound printed {len(words)} values, not "
                         f"{len(CORE_FIELDS)}: '{text.strip()}'")
    return {name: number(w, f"coreRebound {name}")
            for name, w in zip(CORE_FIELDS, words)}


def sphere_angular_momentum(d, rho, omega):
    """The angular momentum I omega of a solid sphere of diameter d and
    density rho spinning at omega: I = m d^2/10, m = rho pi d^3/6."""
    m = rho * math.pi * d**3 / 6
    return [m * d * d / 10 * w for w in omega]


def sweep_matches_core(sweep, core_file, rtol=1e-9):
    """An impactCalc sweep (U = (ut, 0, -un) on a wall of normal (0 0 1))
    against coreRebound's line for each of its rows, in order: R, gamma,
    WA, energyLoss, unOut (the core's Uz) and utOut (Ux) to rtol relative
    to the core's, captured equal. Returns (rows compared, messages)."""
    from . import tables
    table = tables.read(sweep)
    with open(core_file) as f:
        core = [core_result(line) for line in f if line.strip()]
    if not len(table):
        return 0, [f"{sweep}: no rows"]
    if len(core) != len(table):
        return 0, [f"{len(table)} rows in {sweep}, {len(core)} in {core_file}"]
    pairs = (("R", "R"), ("gamma", "gamma"), ("WA", "WA"),
             ("unOut", "Uz"), ("utOut", "Ux"), ("energyLoss", "energyLoss"))
    problems = []
    for i, expected in enumerate(core):
        row = {n: table.text(n)[i] for n in table.names}
        where = f"d={row['diameter']} v={row['speed']} angle={row['angle']}"
        if int(number(row["captured"])) != int(expected["captured"]):
            problems.append(f"{where}: captured {row['captured']}, core "
                            f"{fmt(expected['captured'])}")
        for tool, name in pairs:
            if not close(number(row[tool]), expected[name], rtol):
                problems.append(f"{where}: {tool} {row[tool]}, core "
                                f"{fmt(expected[name])}")
    return len(table), problems


def impact_calc_inputs(records):
    """For each impact record of impacts.csv: its patch, diameter (as
    written), speed sqrt(un^2 + ut^2) and angle from the normal atan2(ut,
    un) [deg], as impactCalc takes them."""
    from . import tables
    table = tables.read(records)
    rows = []
    for patch, d, un, ut in zip(table.text("patch"), table.text("diameter"),
                                table["un"], table["ut"]):
        rows.append((patch, d, math.sqrt(un*un + ut*ut),
                     math.degrees(math.atan2(ut, un))))
    return rows


def records_match_tool(records, tool, rtol=1e-9, patches=()):
    """The solver's impact records against impactCalc's row for each, in
    order: R, WA, unOut, utOut to rtol relative to the solver's, captured
    (1 for outcome capture) equal, the same diameter; every patch named must
    have a record. Returns (records compared, messages)."""
    from . import tables
    solver, calc = tables.read(records), tables.read(tool)
    if not len(solver):
        return 0, [f"{records}: no records"]
    if len(solver) != len(calc):
        return 0, [f"{len(solver)} records in {records}, {len(calc)} rows in "
                   f"{tool}"]
    problems = []
    for i in range(len(solver)):
        s = {n: solver.text(n)[i] for n in solver.names}
        c = {n: calc.text(n)[i] for n in calc.names}
        where = (f"patch {s['patch']}, d {s['diameter']}, un {s['un']}, ut "
                 f"{s['ut']}")
        if not close(number(c["diameter"]), number(s["diameter"]), 1e-12):
            problems.append(f"{where}: impactCalc's row {i + 1} is of d "
                            f"{c['diameter']}")
            continue
        captured = 1 if s["outcome"] == "capture" else 0
        if int(number(c["captured"])) != captured:
            problems.append(f"{where}: solver {s['outcome']}, impactCalc "
                            f"captured {c['captured']}")
        for name in ("R", "WA", "unOut", "utOut"):
            if not close(number(c[name]), number(s[name]), rtol):
                problems.append(f"{where}: {name} {s[name]} in the solver, "
                                f"{c[name]} in impactCalc")
    seen = set(solver.text("patch"))
    problems += [f"no impact on {p} to compare" for p in patches
                 if p not in seen]
    return len(solver), problems


def critical_speed_outcomes(records, patch, critical, count):
    """The impacts of impacts.csv on a patch against the critical speeds
    ({diameter: speed}): each a capture exactly when its un is below its
    diameter's critical speed, and `count` of them. Returns (a line per
    impact, messages)."""
    from . import tables
    table = tables.read(records).where(patch=patch)
    lines, problems = [], []
    for d, un, outcome in zip(table.text("diameter"), table.text("un"),
                              table.text("outcome")):
        speeds = [v for dc, v in critical.items() if dc == number(d)]
        if not speeds:
            problems.append(f"d = {d} m: no critical speed given")
            continue
        expected = "capture" if number(un) < speeds[0] else "rebound"
        lines.append(f"d = {d} m, un = {un} m/s, critical {fmt(speeds[0])} "
                     f"m/s: {outcome}")
        if outcome != expected:
            problems.append(f"d = {d} m, un = {un} m/s: {outcome}, expected "
                            f"{expected}")
    if len(table) != count:
        problems.append(f"expected {count} impacts on {patch}, got "
                        f"{len(table)}")
    return lines, problems


def printed_value(path, label):
    """The value a tool's table (impactCalc -diagnostics) prints on the
    first line holding the label: the line's last plain number (units and
    percentages after it skipped)."""
    with open(path) as f:
        for line in f:
            if label in line:
                for word in reversed(line.split()):
                    if re.fullmatch(r"[0-9.]+(e[-+]?[0-9]+)?", word):
                        return number(word)
                raise CheckError(f"{path}: no number on '{line.strip()}'")
    raise CheckError(f"{path}: no line '{label}'")


def fit_values(path, name):
    """The fitted values of a coefficient impactFit prints as 'name value
    +- standardError', as (value, standardError), every such line."""
    found = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if len(words) >= 4 and words[0] == name and words[2] == "+-":
                found.append((number(words[1], name),
                              number(words[3], f"{name}'s standard error")))
    if not found:
        raise CheckError(f"{path}: {name} not printed")
    return found


def recovered(path, name, truth, errors=3):
    """Messages for each fitted value of `name` (fit_values) farther than
    `errors` standard errors from the truth, or without a positive
    standard error (empty: recovered)."""
    return [f"{name} = {fmt(v)} +- {fmt(se)}, true {fmt(truth)}"
            for v, se in fit_values(path, name)
            if not (se > 0 and abs(v - truth) <= errors * se)]


#------------------------------------------------------------------------------
# The benchmark (tests/bench/run): figures printed, never asserted

def bench_core_lines(path):
    """The core micro-benchmark's lines from Google Benchmark's CSV output:
    the building blocks (primitive/...), the classical rebound baseline and
    each impact/... benchmark in ns and in baselines."""
    from . import tables
    table = tables.read(path)
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
    times = {}
    for name, t, unit in zip(table.text("name"), table["real_time"],
                             table.text("time_unit")):
        times[name.strip('"')] = t * scale[unit]
    if not times.get("classicalRebound", 0) > 0:
        raise CheckError(f"{path}: no classicalRebound benchmark")
    base = times["classicalRebound"]
    primitives = "".join(" %s %.1f" % (n[len("primitive/"):], t)
                         for n, t in times.items()
                         if n.startswith("primitive/"))
    lines = ["core: one call on the impact speeds, ns:" + primitives,
             "core: classical rebound (standardWallInteraction arithmetic) "
             "%.1f ns" % base]
    lines += ["core: %-36s %6.1f ns  %5.1f x baseline" % (n, t, t / base)
              for n, t in times.items() if n.startswith("impact/")]
    return lines


def random_positions(n, seed=7, low=5e-5, width=9e-4):
    """The text of a vectorField file of n positions drawn uniformly in
    the cube [low, low + width)^3, repeatably (the seed)."""
    draw = random.Random(seed).random
    lines = ["FoamFile { version 2.0; format ascii; class vectorField; "
             "object positions; }", "("]
    lines += ["(%.6g %.6g %.6g)" % tuple(low + width * draw()
                                         for _ in range(3))
              for _ in range(n)]
    lines.append(")")
    return lines


def execution_time(log):
    """The last ExecutionTime an OpenFOAM solver printed [s]: it is in the
    solver's log only (no function object writes it in v1912)."""
    found = None
    with open(log) as f:
        for line in f:
            m = re.match(r"ExecutionTime = (\S+) s", line)
            if m:
                found = number(m.group(1), "ExecutionTime")
    if found is None:
        raise CheckError(f"{log}: no ExecutionTime")
    return found


def mass_transferred(log):
    """What a cloud has given the gas so far [kg]: the sum over kinds of the
    last "Mass transfer <kind> = <value>" line OpenFOAM's thermo and
    reacting clouds print each step (phase change, devolatilisation,
    surface reaction: totals since the start of the run)."""
    last = {}
    with open(log) as f:
        for line in f:
            m = re.match(r"\s*Mass transfer (.*\S)\s*=\s*(\S+)", line)
            if m:
                last[m.group(1)] = number(m.group(2), "Mass transfer")
    if not last:
        raise CheckError(f"{log}: no Mass transfer line")
    return sum(last.values())


def time_ratios_line(name, times_a, times_b):
    """The line of alternating timed pairs: the ratios B/A (to 4 decimals,
    as printed), their median, mean and standard deviation, and the ratio
    of the fastest runs (min B / min A: another job sharing the machine
    only adds time, so the fastest runs are the least disturbed)."""
    if not times_a or len(times_a) != len(times_b):
        raise CheckError(f"{len(times_a)} times against {len(times_b)}")
    if not all(t > 0 for t in list(times_a) + list(times_b)):
        raise CheckError(f"times {times_a} {times_b}: not all positive")
    ratios = ["%.4f" % (b / a) for a, b in zip(times_a, times_b)]
    values = [float(r) for r in ratios]
    m, sd = mean_and_deviation(values)
    return ("%s: time ratio median %.3f, mean %.3f +- %.3f, fastest runs "
            "%.3f (%d alternating pairs: %s)"
            % (name, median(values), m, sd, min(times_b) / min(times_a),
               len(values), " ".join(ratios)))


def solver_lines(parcels, impacts, seconds, steps=50):
    """The in-solver case's lines: impacts in all and per step, and per
    second of solver time."""
    if seconds <= 0 or steps <= 0:
        raise CheckError(f"{seconds} s, {steps} steps: nothing to divide by")
    return ["solver: %d parcels, %d steps: %d wall impacts, %.0f per step; "
            "adhesive run %g s" % (parcels, steps, impacts, impacts / steps,
                                   seconds),
            "solver: %.3g impacts handled per second of solver time (all of "
            "it, tracking included)" % (impacts / seconds)]


def scaling_line(parcels, impacts, seconds):
    """A scaling line: the time per million impacts."""
    if impacts <= 0:
        raise CheckError(f"{impacts} impacts: no time per impact")
    return ("scaling: %6d parcels, %8d impacts: %.2f s, %.3g s per million "
            "impacts" % (parcels, impacts, seconds, 1e6 * seconds / impacts))


def entries_lines(timings):
    """The patch-entry scaling lines from (entries, seconds) pairs of
    several rounds: per entry count, the median and the times in the order
    run."""
    by_count = {}
    for entries, seconds in timings:
        by_count.setdefault(entries, []).append(seconds)
    if not by_count:
        raise CheckError("no timings")
    return ["scaling: %d patch entries in the dictionary: median %.2f s (%s)"
            % (e, median(t), " ".join("%.2f" % x for x in t))
            for e, t in by_count.items()]


def speedup_line(serial, parallel):
    """The parallel line: 1 and 2 ranks and the speedup."""
    if parallel <= 0:
        raise CheckError(f"parallel time {parallel} s")
    return ("parallel: 1 rank %.2f s, 2 ranks %.2f s, speedup %.2f"
            % (serial, parallel, serial / parallel))


def deposit_cost_line(deposits, steps, times_a, times_b):
    """The resuspension line: the extra time per deposit and step, from the
    medians of alternating runs without (A) and with (B) resuspension."""
    if deposits <= 0 or steps <= 0:
        raise CheckError(f"{deposits} deposits, {steps} steps")
    time_a, time_b = median(times_a), median(times_b)
    return ("resuspension: %.0f ns per deposit and step (medians %.2f s "
            "without, %.2f s with; %d deposits, %d steps)"
            % ((time_b - time_a) / (deposits * steps) * 1e9, time_a, time_b,
               deposits, steps))


def instructions_lines(path, hits):
    """The instruction counts of callgrind runs ('box count' lines, the
    first 'standard') and, for the others, the instructions per wall impact
    beyond standardWallInteraction's."""
    counts = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if len(words) == 2:
                counts.append((words[0],
                               number(words[1].replace(",", ""), words[0])))
    standard = dict(counts).get("standard")
    if standard is None:
        raise CheckError(f"{path}: no count of the standard box")
    if hits <= 0:
        raise CheckError(f"{hits} wall impacts: no count per impact")
    lines = []
    for box, count in counts:
        line = "instructions: %-15s %.4e in 10 steps (%d wall impacts)" % (
            box, count, hits)
        if box != "standard":
            line += ", %.0f per impact beyond standard" % (
                (count - standard) / hits)
        lines.append(line)
    return lines


def instruction_ratio_line(name, count_a, count_b, steps):
    """The line of two callgrind counts of the same case and their ratio
    B/A (to 4 decimals)."""
    if not (count_a > 0 and count_b > 0):
        raise CheckError(f"counts {count_a}, {count_b}: not both positive")
    return "%s: instructions in %d steps %.4e and %.4e, ratio %.4f" % (
        name, steps, count_a, count_b, count_b / count_a)


#------------------------------------------------------------------------------
# The subcommands

COMMANDS = {}


def command(name, usage, minimum, maximum=None):
    """Register the function as subcommand `name` taking from minimum to
    maximum (None: any number of) arguments."""
    def register(function):
        COMMANDS[name] = (function, usage, minimum,
                          minimum if maximum is None else maximum)
        return function
    return register


def _report(problems, success=None):
    """Raise a CheckError of the problems (at most 10 listed), or print the
    success line."""
    if problems:
        more = len(problems) - 10
        raise CheckError("\n  ".join(problems[:10]
                                     + ([f"... and {more} more"]
                                        if more > 0 else [])))
    if success:
        print(success)


ANY = 1 << 30


@command("statistic", "FILE COLUMN [PATCH [INJECTOR [DMIN]]]", 2, 5)
def _statistic(path, column, patch="", injector="", dMin=""):
    """A column of a statistics.dat at its last time, summed over the rows
    selected (empty: any)."""
    print(fmt(statistic(path, column, patch, injector, dMin)))


@command("surfaceContacts", "STATISTICS SURFACE_CONTACT", 2, 2)
def _surface_contacts(statistics_path, contacts_path):
    """On each patch the impacts of statistics.dat are the contacts of
    surfaceContact.dat; prints the contacts 'at the surface' 'at the
    centre' summed over the patches."""
    at_surface, at_centre = surface_contacts(statistics_path, contacts_path)
    print(fmt(at_surface), fmt(at_centre))


@command("statisticRows", "FILE [PATCH]", 1, 2)
def _statistic_rows(path, patch=""):
    """The number of rows of a statistics.dat at its last time (of a
    patch)."""
    print(statistic_rows(path, patch))


@command("compareStatistics", "REFERENCE FILE [MEANS_RTOL]", 2, 3)
def _compare_statistics(reference, path, rtol="1e-12"):
    """Two statistics.dat end with the same rows: counts and masses to
    1e-12, mean speeds and angles to MEANS_RTOL (1e-12) relative."""
    _report(compare_statistics(reference, path, number(rtol, "MEANS_RTOL")))


@command("compareTotals", "REFERENCE FILE RTOL COLUMN...", 4, ANY)
def _compare_totals(reference, path, rtol, *names):
    """The per-patch sums of the columns at the last time agree to RTOL
    (over injectors and size classes)."""
    n, problems = compare_totals(reference, path, names, number(rtol, "RTOL"))
    _report(problems, f"{n} per-patch sums agree")


@command("compareRecords", "REFERENCE RTOL 'COLUMN...' FILE...", 4, ANY)
def _compare_records(reference, rtol, names, *paths):
    """The impact records of a run (in one file or in several, e.g. before
    and after a restart) are the reference's, in the columns named, in any
    order: texts equal, numbers to RTOL of the column's largest."""
    problems = compare_records(reference, paths, names.split(),
                               number(rtol, "RTOL"))
    _report(problems, "the records agree")


@command("timeRange", "FILE", 1, 1)
def _time_range(path):
    """The first and last time of a table: 'first last'."""
    print(" ".join(time_range(path)))


@command("massBalance", "FILE [COLUMN...]", 1, ANY)
def _mass_balance(path, *names):
    """The last row of a massBalance.dat: the columns named (injected
    residual), as written."""
    row = mass_balance(path)
    missing = [n for n in names if n not in row]
    if missing:
        raise CheckError(f"{path}: no column {' '.join(missing)}")
    print(" ".join(row[n] for n in (names or ("injected", "residual"))))


@command("tableRows", "FILE [COLUMN...]", 1, ANY)
def _table_rows(path, *names):
    """The number of data rows of a table (whose header holds the columns
    named)."""
    print(table_rows(path, names))


@command("columns", "FILE [COLUMN=TEXT...] [-sort COLUMN] COLUMN...", 2, ANY)
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


@command("replaceValue", "FILE ROW COLUMN VALUE", 4, 4)
def _replace_value(path, row, column, value):
    """A CSV file with one value replaced (data row ROW from 1, column by
    name), printed."""
    print("\n".join(replace_value(path, int(row), column, value)))


@command("close", "VALUE EXPECTED RTOL [WHAT]", 3, 4)
def _close(value, expected, rtol, what="value"):
    """|VALUE - EXPECTED| <= RTOL |EXPECTED| (EXPECTED 0: exactly 0)."""
    if not close(number(value, what), number(expected, f"expected {what}"),
                 number(rtol, "RTOL")):
        raise CheckError(f"{what}: {value}, expected {expected} to {rtol} "
                         "relative")


@command("small", "VALUE RTOL SCALE [WHAT]", 3, 4)
def _small(value, rtol, scale, what="value"):
    """|VALUE| <= RTOL SCALE, with SCALE > 0."""
    if not small(number(value, what), number(rtol, "RTOL"),
                 number(scale, "SCALE")):
        raise CheckError(f"{what}: {value} is not within {rtol} of {scale}"
                         " (which must be > 0)")


@command("near", "VALUE EXPECTED RTOL SCALE [WHAT]", 4, 5)
def _near(value, expected, rtol, scale, what="value"):
    """|VALUE - EXPECTED| <= RTOL SCALE, with SCALE > 0."""
    if not near(number(value, what), number(expected, "EXPECTED"),
                number(rtol, "RTOL"), number(scale, "SCALE")):
        raise CheckError(f"{what}: {value} is not within {rtol} x {scale}"
                         f" of {expected}")


@command("sumsTo", "TOTAL RTOL PART...", 3, ANY)
def _sums_to(total, rtol, *parts):
    """The parts add up to TOTAL > 0 to RTOL relative."""
    values = [number(p, "part") for p in parts]
    if not sums_to(number(total, "TOTAL"), number(rtol, "RTOL"), values):
        raise CheckError(f"{' + '.join(parts)} = {fmt(math.fsum(values))},"
                         f" not {total} to {rtol} relative (which must be "
                         "> 0)")


@command("between", "VALUE LOW HIGH [WHAT]", 3, 4)
def _between(value, low, high, what="value"):
    """LOW < VALUE < HIGH."""
    if not between(number(value, what), number(low, "LOW"),
                   number(high, "HIGH")):
        raise CheckError(f"{what}: {value} is not in ({low}, {high})")


@command("scaled", "VALUE FACTOR", 2, 2)
def _scaled(value, factor):
    """VALUE x FACTOR to 6 significant digits (a test's input)."""
    print("%.6g" % (number(value) * number(factor)))


@command("compareFields", "REFERENCE FILE [RTOL]", 2, 3)
def _compare_fields(reference, path, rtol="1e-12"):
    """Two field files hold the same numbers, to RTOL (1e-12) relative to
    the reference's."""
    _report(compare_fields(reference, path, number(rtol, "RTOL")))


@command("lagrangianValues", "FILE", 1, 1)
def _lagrangian_values(path):
    """The values of a lagrangian field file, one a line."""
    for x in lagrangian_values(path):
        print(fmt(x))


@command("lastVector", "FILE", 1, 1)
def _last_vector(path):
    """The last vector of a lagrangian vector field: 'x y z'."""
    print(" ".join(fmt(x) for x in last_vector(path)))


@command("compareVectors", "'X Y Z' 'X Y Z' RTOL", 3, 3)
def _compare_vectors(actual, expected, rtol):
    """The first vector equals the second (expected) to RTOL relative to
    its largest component."""
    _report(compare_vectors([number(x) for x in actual.split()],
                            [number(x) for x in expected.split()],
                            number(rtol, "RTOL")))


@command("cloudMass", "TIME_FOLDER [CLOUD]", 1, 2)
def _cloud_mass(time_folder, cloud="kinematicCloud"):
    """The mass of a cloud's parcels at a written time [kg]."""
    print(fmt(cloud_mass(time_folder, cloud)))


@command("boundarySum", "FIELD [PATCH...]", 1, ANY)
def _boundary_sum(path, *patches):
    """The sum of a volScalarField's boundary values over the patches (all
    when none is named)."""
    print(fmt(boundary_sum(path, patches)))


@command("boundaryMin", "FIELD [PATCH...]", 1, ANY)
def _boundary_min(path, *patches):
    """The smallest of a volScalarField's boundary values on the patches
    (all when none is named)."""
    print(fmt(boundary_min(path, patches)))


@command("injectedMass", "[CASE]", 0, 1)
def _injected_mass(case="."):
    """The mass the manual injectors of constant/injectors inject [kg]."""
    print(fmt(injected_mass(case)))


@command("compareLastRows", "REFERENCE FILE RTOL COLUMN...", 4, ANY)
def _compare_last_rows(reference, path, rtol, *columns):
    """Two tables' rows at their last times, matched by injector, dMin and
    dMax, in the columns named."""
    _report(compare_last_rows(reference, path, columns, number(rtol)),
            f"{path}: the rows of {reference}")


@command("logLinesPerStep", "LOG", 1)
def _log_lines_per_step(log):
    """steps, median lines a step, the model's summary lines and table rows
    of a step, the last step's lines and table rows (see
    log_lines_per_step)."""
    print(" ".join(fmt(v) for v in log_lines_per_step(log)))


@command("gradeEfficiency", "[CASE [START_TIME [CLOUD]]]", 0, 3)
def _grade_efficiency(case=".", start_time="0", cloud="kinematicCloud"):
    """gradeEfficiency.dat's last rows against the injectors, the impact
    records and the lagrangian files (and its own closure)."""
    _report(check_grade_efficiency(case, start_time, cloud),
            "gradeEfficiency.dat: every class as counted independently")


@command("parcelCount", "[CASE [TIME [CLOUD]]]", 0, 3)
def _parcel_count(case=".", time=None, cloud="kinematicCloud"):
    """The number of parcels of a cloud at a written time (the latest),
    from its lagrangian files."""
    print(foam.parcel_count(case, time or None, cloud))


@command("steps", "[CASE]", 0, 1)
def _steps(case="."):
    """The number of time steps of the case's controlDict."""
    print(steps(case))


@command("patchInteractionModels", "OUTPUT_PROPERTIES", 1, 1)
def _patch_interaction_models(path):
    """The patch interaction models with totals in a cloud's output
    properties, one a line; fails when there is none."""
    models = patch_interaction_models(path)
    if not models:
        raise CheckError(f"{path}: no patch interaction model")
    print("\n".join(models))


@command("core", "'COREREBOUND OUTPUT' FIELD...", 2, ANY)
def _core(text, *names):
    """Fields of coreRebound's output line by name (Ux Uy Uz captured wx wy
    wz R gamma WA energyLoss)."""
    result = core_result(text)
    unknown = [n for n in names if n not in result]
    if unknown:
        raise CheckError(f"coreRebound has no {' '.join(unknown)}")
    print(" ".join(fmt(result[n]) for n in names))


@command("angularMomentum", "D RHO 'WX WY WZ'", 3, 3)
def _angular_momentum(d, rho, omega):
    """The angular momentum of a solid sphere spinning at omega."""
    print(" ".join(fmt(x) for x in sphere_angular_momentum(
        number(d, "D"), number(rho, "RHO"),
        [number(w) for w in omega.split()])))


@command("sweepMatchesCore", "SWEEP_CSV CORE_LINES RTOL", 3, 3)
def _sweep_matches_core(sweep, core_file, rtol):
    """An impactCalc sweep against coreRebound, row by row; prints the
    number of rows."""
    n, problems = sweep_matches_core(sweep, core_file, number(rtol, "RTOL"))
    _report(problems, str(n))


@command("impactCalcInputs", "IMPACTS_CSV", 1, 1)
def _impact_calc_inputs(records):
    """Per impact record: 'patch diameter speed angle' for impactCalc."""
    for patch, d, speed, angle in impact_calc_inputs(records):
        print(patch, d, fmt(speed), fmt(angle))


@command("recordsMatchTool", "IMPACTS_CSV TOOL_CSV RTOL [PATCH...]", 3, ANY)
def _records_match_tool(records, tool, rtol, *patches):
    """The solver's impact records against impactCalc's rows; every patch
    named has records; prints the number of records."""
    n, problems = records_match_tool(records, tool, number(rtol, "RTOL"),
                                     patches)
    _report(problems, str(n))


@command("criticalSpeeds", "IMPACTS_CSV PATCH COUNT D:SPEED...", 4, ANY)
def _critical_speeds(records, patch, count, *pairs):
    """COUNT impacts on PATCH, each captured exactly below its diameter's
    critical speed."""
    critical = {}
    for pair in pairs:
        d, _, v = pair.partition(":")
        critical[number(d, "diameter")] = number(v, "critical speed")
    lines, problems = critical_speed_outcomes(records, patch, critical,
                                              int(count))
    print("\n".join(lines))
    _report(problems)


@command("printedValue", "FILE LABEL", 2, 2)
def _printed_value(path, label):
    """The value printed on the line of a tool's table holding LABEL."""
    print(fmt(printed_value(path, label)))


@command("fitValue", "FILE NAME", 2, 2)
def _fit_value(path, name):
    """The last value impactFit printed for a coefficient ('NAME value +-
    error')."""
    print(fmt(fit_values(path, name)[-1][0]))


@command("recovered", "FILE NAME TRUTH [ERRORS]", 3, 4)
def _recovered(path, name, truth, errors="3"):
    """impactFit's value of a coefficient is within ERRORS (3) standard
    errors of the truth."""
    _report(recovered(path, name, number(truth, "TRUTH"),
                      number(errors, "ERRORS")))


@command("benchCore", "CSV", 1, 1)
def _bench_core(path):
    """The core micro-benchmark's lines."""
    print("\n".join(bench_core_lines(path)))


@command("randomPositions", "N [SEED]", 1, 2)
def _random_positions(n, seed="7"):
    """A vectorField file of N random positions in the 1 mm box."""
    print("\n".join(random_positions(int(n), int(seed))))


@command("executionTime", "LOG", 1, 1)
def _execution_time(log):
    """The last ExecutionTime of a solver log [s]."""
    print(fmt(execution_time(log)))


@command("massTransferred", "LOG", 1, 1)
def _mass_transferred(log):
    """What a thermo or reacting cloud has given the gas so far [kg]."""
    print(fmt(mass_transferred(log)))


@command("timeRatios", "NAME 'TIMES_A' 'TIMES_B'", 3, 3)
def _time_ratios(name, times_a, times_b):
    """The ratio line of alternating timed pairs."""
    print(time_ratios_line(name, [number(t) for t in times_a.split()],
                           [number(t) for t in times_b.split()]))


@command("benchSolver", "PARCELS IMPACTS SECONDS", 3, 3)
def _bench_solver(parcels, impacts, seconds):
    """The in-solver case's impact lines."""
    print("\n".join(solver_lines(int(parcels), number(impacts),
                                 number(seconds))))


@command("benchScaling", "PARCELS IMPACTS SECONDS", 3, 3)
def _bench_scaling(parcels, impacts, seconds):
    """A scaling line."""
    print(scaling_line(int(parcels), number(impacts), number(seconds)))


@command("benchEntries", "ENTRIES:SECONDS...", 1, ANY)
def _bench_entries(*pairs):
    """The patch-entry scaling lines."""
    timings = []
    for pair in pairs:
        entries, _, seconds = pair.partition(":")
        timings.append((int(entries), number(seconds)))
    print("\n".join(entries_lines(timings)))


@command("benchSpeedup", "SERIAL_SECONDS PARALLEL_SECONDS", 2, 2)
def _bench_speedup(serial, parallel):
    """The parallel speedup line."""
    print(speedup_line(number(serial), number(parallel)))


@command("benchResuspension", "DEPOSITS STEPS 'TIMES_A' 'TIMES_B'", 4, 4)
def _bench_resuspension(deposits, steps, times_a, times_b):
    """The resuspension cost line."""
    print(deposit_cost_line(int(deposits), int(steps),
                            [number(t) for t in times_a.split()],
                            [number(t) for t in times_b.split()]))


@command("benchInstructions", "FILE HITS", 2, 2)
def _bench_instructions(path, hits):
    """The instruction-count lines."""
    print("\n".join(instructions_lines(path, int(number(hits)))))


@command("benchInstructionRatio", "NAME COUNT_A COUNT_B STEPS", 4, 4)
def _bench_instruction_ratio(name, count_a, count_b, steps):
    """The line of two callgrind counts (commas allowed) and their
    ratio."""
    print(instruction_ratio_line(name, number(count_a.replace(",", "")),
                                 number(count_b.replace(",", "")),
                                 int(number(steps, "STEPS"))))


def usage():
    """The list of subcommands, each with its arguments and what it
    does."""
    lines = ["adhesiveWallPost check SUBCOMMAND ARGUMENTS: prints a value, or"
             " checks and exits 1 with a message on a difference", ""]
    for name, (function, arguments, _, _) in COMMANDS.items():
        summary = " ".join(function.__doc__.split())
        lines.append(f"  {name} {arguments}\n      {summary}")
    return "\n".join(lines)


@command("brownianMsd", "CASE ORIGIN T MU P [COEFFICIENTS [CLOUD]]", 5, 7)
def _brownian_msd(case, origin, T, mu, pressure, coefficients="Davies",
                  cloud="kinematicCloud"):
    """The mean squared displacement of the cloud's parcels (one
    diameter and density, read from the latest time; kinematicCloud by
    default) from ORIGIN, '(x y z)',
    at the first and the last time folder equals the Ornstein-Uhlenbeck one
    from a thermal start within three standard errors (aerosol.
    msd_comparison); prints the table of every time folder (their
    deviations are correlated: one fluctuation carries on to later
    times)."""
    from . import aerosol
    latest = foam.latest_time(case)
    folder = os.path.join(case, latest, "lagrangian", cloud)
    d = set(lagrangian_values(os.path.join(folder, "d")))
    rho = set(lagrangian_values(os.path.join(folder, "rho")))
    if len(d) != 1 or len(rho) != 1:
        raise CheckError(f"{folder}: parcels of more than one diameter or "
                         "density")
    xyz = [number(x, "ORIGIN") for x in origin.strip("()").split()]
    rows = aerosol.msd_comparison(
        case, xyz, d.pop(), rho.pop(), number(T, "T"), number(mu, "MU"),
        number(pressure, "P"), coefficients, cloud)
    if not rows:
        raise CheckError(f"{case}: no time folder with parcels")
    print("t,tOverTau,msd,msdSE,expected,deviationInSE")
    for row in rows:
        print(",".join(fmt(v) for v in row))
    _report([f"t = {fmt(r[0])}: msd {fmt(r[2])} against {fmt(r[4])}, "
             f"{r[5]:.2f} standard errors" for r in (rows[0], rows[-1])
             if abs(r[5]) > 3])


@command("sameParcelPositions", "CASE REFERENCE TOLERANCE [CLOUD]", 3, 4)
def _same_parcel_positions(case, reference, tolerance, cloud="kinematicCloud"):
    """The parcels of the cloud at the latest time of CASE (reconstructed,
    in any order) are those of REFERENCE, matched by origin (origProcId,
    origId), each at the same position to TOLERANCE [m]."""
    from . import aerosol

    def by_origin(folder):
        time = foam.latest_time(folder)
        path = os.path.join(folder, time, "lagrangian", cloud)
        keys = zip(lagrangian_values(os.path.join(path, "origProcId")),
                   lagrangian_values(os.path.join(path, "origId")))
        return time, dict(zip(keys, aerosol.positions(folder, time, cloud)))

    time, parcels = by_origin(case)
    reference_time, expected = by_origin(reference)
    if time != reference_time or set(parcels) != set(expected) \
            or not parcels:
        raise CheckError(f"{case} ({len(parcels)} parcels at {time}) and "
                         f"{reference} ({len(expected)} at {reference_time})"
                         " do not hold the same parcels")
    limit = number(tolerance, "TOLERANCE")
    worst = max(max(abs(a - b) for a, b in zip(p, expected[key]))
                for key, p in parcels.items())
    _report([f"a parcel {fmt(worst)} m from its position in {reference}"]
            if worst > limit else [],
            f"{len(parcels)} parcels at their positions in {reference} "
            f"(largest difference {fmt(worst)} m)")


@command("settlingVelocity", "CASE RHO_C MU G LAMBDA [COEFFICIENTS] [RTOL]",
         5, 7)
def _settling_velocity(case, rho_c, mu, g, lam, coefficients="Davies",
                       rtol="1e-3"):
    """Every parcel of kinematicCloud at the latest time moves at the
    settling velocity of its diameter and density (aerosol.
    settling_velocity, gravity along -z of magnitude G) to RTOL."""
    from . import aerosol
    folder = os.path.join(case, foam.latest_time(case), "lagrangian",
                          "kinematicCloud")
    U = foam.list_file(os.path.join(folder, "U"))
    d = lagrangian_values(os.path.join(folder, "d"))
    rho = lagrangian_values(os.path.join(folder, "rho"))
    if not U:
        raise CheckError(f"{folder}: no parcels")
    if not len(U) == len(d) == len(rho):
        raise CheckError(f"{folder}: {len(U)} velocities, {len(d)} "
                         f"diameters and {len(rho)} densities")
    problems = []
    for u, di, rhoi in zip(U, d, rho):
        v = aerosol.settling_velocity(
            di, rhoi, number(rho_c, "RHO_C"), number(mu, "MU"),
            number(g, "G"), number(lam, "LAMBDA"), coefficients)
        print(f"d {fmt(di)}: Uz {fmt(u[2])} against {fmt(-v)}")
        if not abs(u[2] + v) <= number(rtol, "RTOL") * v:
            problems.append(f"d = {fmt(di)}: Uz {fmt(u[2])} against "
                            f"{fmt(-v)}")
    _report(problems, f"{len(U)} parcels settle at the expected velocity")


def main(argv):
    """adhesiveWallPost check SUBCOMMAND ARGUMENTS: runs a subcommand;
    returns 0, 1 (a check failed or a value could not be had) or 2 (wrong
    usage)."""
    if not argv or argv[0] in ("-h", "-help", "--help"):
        print(usage(), file=sys.stdout if argv else sys.stderr)
        return 0 if argv else 2
    name, arguments = argv[0], argv[1:]
    if name not in COMMANDS:
        print(f"adhesiveWallPost check: unknown subcommand '{name}'\n"
              f"{usage()}", file=sys.stderr)
        return 2
    function, usage_text, minimum, maximum = COMMANDS[name]
    if not minimum <= len(arguments) <= maximum:
        print(f"Usage: adhesiveWallPost check {name} {usage_text}",
              file=sys.stderr)
        return 2
    try:
        function(*arguments)
    except CheckError as error:
        print(f"adhesiveWallPost check {name}: {error}", file=sys.stderr)
        return 1
    except (OSError, ValueError, KeyError, RuntimeError,
            ArithmeticError) as error:
        message = error.args[0] if isinstance(error, KeyError) else error
        print(f"adhesiveWallPost check {name}: {message}", file=sys.stderr)
        return 1
    return 0
