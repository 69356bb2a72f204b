# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""What a case's files say: its grade efficiency counted independently, its
steps, its patch interaction models, its parcels."""

import math
import os

from .. import foam
from .registry import CheckError, _report, command, fmt, number
from .predicates import close


def _size_class(d, edges):
    """The index of the size class of a diameter, classes bounded by the
    edges (below the first, between two, above the last)."""
    return sum(1 for edge in edges if not d < edge)


QUANTITIES = ("injected", "captured", "escaped", "removed", "airborne")


def _complete_records(case, folder):
    """The path of the impact records in the model's output folder, or a
    CheckError where they are missing or capped at maxImpactRecords."""
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
    return records_path


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
    from .. import statistics, tables
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
    records_path = _complete_records(case, folder)
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
    from .. import statistics, tables
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


@command("gradeEfficiency", "[CASE [START_TIME [CLOUD]]]")
def _grade_efficiency(case=".", start_time="0", cloud="kinematicCloud"):
    """gradeEfficiency.dat's last rows against the injectors, the impact
    records and the lagrangian files (and its own closure)."""
    _report(check_grade_efficiency(case, start_time, cloud),
            "gradeEfficiency.dat: every class as counted independently")


@command("parcelCount", "[CASE [TIME [CLOUD]]]")
def _parcel_count(case=".", time=None, cloud="kinematicCloud"):
    """The number of parcels of a cloud at a written time (the latest),
    from its lagrangian files."""
    print(foam.parcel_count(case, time or None, cloud))


@command("steps", "[CASE]")
def _steps(case="."):
    """The number of time steps of the case's controlDict."""
    print(steps(case))


@command("patchInteractionModels", "OUTPUT_PROPERTIES")
def _patch_interaction_models(path):
    """The patch interaction models with totals in a cloud's output
    properties, one a line; fails when there is none."""
    models = patch_interaction_models(path)
    if not models:
        raise CheckError(f"{path}: no patch interaction model")
    print("\n".join(models))
