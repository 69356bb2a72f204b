# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The core and the tools against the solver: coreRebound's line, the
sphere's spin, impactCalc's and impactFit's outputs, critical speeds."""

import math
import re

from .registry import CheckError, _report, command, fmt, number
from .predicates import close


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
    from .. import tables
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
    from .. import tables
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
    from .. import tables
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
    from .. import tables
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


@command("core", "'COREREBOUND OUTPUT' FIELD...")
def _core(text, *names):
    """Fields of coreRebound's output line by name (Ux Uy Uz captured wx wy
    wz R gamma WA energyLoss)."""
    result = core_result(text)
    unknown = [n for n in names if n not in result]
    if unknown:
        raise CheckError(f"coreRebound has no {' '.join(unknown)}")
    print(" ".join(fmt(result[n]) for n in names))


@command("angularMomentum", "D RHO 'WX WY WZ'")
def _angular_momentum(d, rho, omega):
    """The angular momentum of a solid sphere spinning at omega."""
    print(" ".join(fmt(x) for x in sphere_angular_momentum(
        number(d, "D"), number(rho, "RHO"),
        [number(w) for w in omega.split()])))


@command("sweepMatchesCore", "SWEEP_CSV CORE_LINES RTOL")
def _sweep_matches_core(sweep, core_file, rtol):
    """An impactCalc sweep against coreRebound, row by row; prints the
    number of rows."""
    n, problems = sweep_matches_core(sweep, core_file, number(rtol, "RTOL"))
    _report(problems, str(n))


@command("impactCalcInputs", "IMPACTS_CSV")
def _impact_calc_inputs(records):
    """Per impact record: 'patch diameter speed angle' for impactCalc."""
    for patch, d, speed, angle in impact_calc_inputs(records):
        print(patch, d, fmt(speed), fmt(angle))


@command("recordsMatchTool", "IMPACTS_CSV TOOL_CSV RTOL [PATCH...]")
def _records_match_tool(records, tool, rtol, *patches):
    """The solver's impact records against impactCalc's rows; every patch
    named has records; prints the number of records."""
    n, problems = records_match_tool(records, tool, number(rtol, "RTOL"),
                                     patches)
    _report(problems, str(n))


@command("criticalSpeeds", "IMPACTS_CSV PATCH COUNT D:SPEED...")
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


@command("printedValue", "FILE LABEL")
def _printed_value(path, label):
    """The value printed on the line of a tool's table holding LABEL."""
    print(fmt(printed_value(path, label)))


@command("fitValue", "FILE NAME")
def _fit_value(path, name):
    """The last value impactFit printed for a coefficient ('NAME value +-
    error')."""
    print(fmt(fit_values(path, name)[-1][0]))


@command("recovered", "FILE NAME TRUTH [ERRORS]")
def _recovered(path, name, truth, errors="3"):
    """impactFit's value of a coefficient is within ERRORS (3) standard
    errors of the truth."""
    _report(recovered(path, name, number(truth, "TRUTH"),
                      number(errors, "ERRORS")))
