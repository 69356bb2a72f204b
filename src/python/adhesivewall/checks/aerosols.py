# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The sub-micron cases' checks: the mean squared displacement, parcels at
the same positions, the settling velocity."""

import os

from .. import foam
from .registry import CheckError, _report, command, fmt, number
from .fields import lagrangian_values


@command("brownianMsd", "CASE ORIGIN T MU P [COEFFICIENTS [CLOUD]]")
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
    from .. import aerosol
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


@command("sameParcelPositions", "CASE REFERENCE TOLERANCE [CLOUD]")
def _same_parcel_positions(case, reference, tolerance, cloud="kinematicCloud"):
    """The parcels of the cloud at the latest time of CASE (reconstructed,
    in any order) are those of REFERENCE, matched by origin (origProcId,
    origId), each at the same position to TOLERANCE [m]."""
    from .. import aerosol

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


@command("settlingVelocity", "CASE RHO_C MU G LAMBDA [COEFFICIENTS] [RTOL]")
def _settling_velocity(case, rho_c, mu, g, lam, coefficients="Davies",
                       rtol="1e-3"):
    """Every parcel of kinematicCloud at the latest time moves at the
    settling velocity of its diameter and density (aerosol.
    settling_velocity, gravity along -z of magnitude G) to RTOL."""
    from .. import aerosol
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
