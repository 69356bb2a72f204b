# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""OpenFOAM's files: fields (boundary sums and minima, compared), lagrangian
values, cloud mass, the manual injectors' mass."""

import math
import os
import re

from .. import foam
from .registry import CheckError, _report, command, fmt, number
from .predicates import close


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


@command("compareFields", "REFERENCE FILE [RTOL]")
def _compare_fields(reference, path, rtol="1e-12"):
    """Two field files hold the same numbers, to RTOL (1e-12) relative to
    the reference's."""
    _report(compare_fields(reference, path, number(rtol, "RTOL")))


@command("lagrangianValues", "FILE")
def _lagrangian_values(path):
    """The values of a lagrangian field file, one a line."""
    for x in lagrangian_values(path):
        print(fmt(x))


@command("lastVector", "FILE")
def _last_vector(path):
    """The last vector of a lagrangian vector field: 'x y z'."""
    print(" ".join(fmt(x) for x in last_vector(path)))


@command("compareVectors", "'X Y Z' 'X Y Z' RTOL")
def _compare_vectors(actual, expected, rtol):
    """The first vector equals the second (expected) to RTOL relative to
    its largest component."""
    _report(compare_vectors([number(x) for x in actual.split()],
                            [number(x) for x in expected.split()],
                            number(rtol, "RTOL")))


@command("cloudMass", "TIME_FOLDER [CLOUD]")
def _cloud_mass(time_folder, cloud="kinematicCloud"):
    """The mass of a cloud's parcels at a written time [kg]."""
    print(fmt(cloud_mass(time_folder, cloud)))


@command("boundarySum", "FIELD [PATCH...]")
def _boundary_sum(path, *patches):
    """The sum of a volScalarField's boundary values over the patches (all
    when none is named)."""
    print(fmt(boundary_sum(path, patches)))


@command("boundaryMin", "FIELD [PATCH...]")
def _boundary_min(path, *patches):
    """The smallest of a volScalarField's boundary values on the patches
    (all when none is named)."""
    print(fmt(boundary_min(path, patches)))


@command("injectedMass", "[CASE]")
def _injected_mass(case="."):
    """The mass the manual injectors of constant/injectors inject [kg]."""
    print(fmt(injected_mass(case)))
