# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Aerosol particles in still gas: the expected settling velocity and
Brownian mean squared displacement, and both measured from a case's
parcels (the checks of slipSphereDrag and exactBrownianMotion)."""

import math
import os

from . import correlations, foam


def settling_velocity(d, rho_p, rho_c, mu, g, mean_free_path,
                      coefficients="Davies"):
    """The terminal velocity [m/s] of a sphere of diameter d [m] and density
    rho_p [kg/m^3] settling in still gas of density rho_c and viscosity mu
    [Pa s] under gravity g [m/s^2], with buoyancy (as OpenFOAM's gravity
    force) and slip (Stokes' law times Cunningham's correction):

        v = (rho_p - rho_c) d^2 g Cc / (18 mu)
    """
    slip = correlations.cunningham(d, mean_free_path, coefficients)
    return (rho_p - rho_c) * d * d * g * slip / (18 * mu)


def brownian_msd(t, tau, D):
    """The mean squared displacement [m^2] in three dimensions after a time
    t [s] of a Brownian particle of relaxation time tau [s] and diffusivity
    D [m^2/s] from a thermal start (Ornstein-Uhlenbeck; Uhlenbeck &
    Ornstein 1930, Chandrasekhar 1943 Eq. 171):

        <r^2> = 6 D tau (t/tau - 1 + exp(-t/tau))

    -> 6 D t for t >> tau, 3 (kB T/m) t^2 for t << tau. Written with
    expm1 so that small t/tau does not cancel."""
    h = t / tau
    return 6 * D * tau * (h + math.expm1(-h))


def _time_folders(case, cloud="kinematicCloud"):
    """The time folders of a case that hold parcels of the cloud, by
    time."""
    found = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, name, "lagrangian", cloud,
                                       "positions")):
            found.append((t, name))
    return sorted(found)


def positions(case, time, cloud="kinematicCloud"):
    """The Cartesian positions of the parcels of the cloud in a time
    folder (the v1706 'positions' file: '(x y z) cell' a line)."""
    items = foam.list_file(os.path.join(case, time, "lagrangian", cloud,
                                        "positions"))
    return [[float(x) for x in item] for item in items
            if isinstance(item, list)]


def measured_msd(case, origin, cloud="kinematicCloud"):
    """Rows (t, msd, standard error, parcels) of the parcels' mean squared
    displacement from origin at each time folder of the case."""
    rows = []
    for t, name in _time_folders(case, cloud):
        r2 = [sum((x - o) ** 2 for x, o in zip(p, origin))
              for p in positions(case, name, cloud)]
        n = len(r2)
        mean = sum(r2) / n
        variance = sum((v - mean) ** 2 for v in r2) / (n - 1)
        rows.append((t, mean, math.sqrt(variance / n), n))
    return rows


def msd_comparison(case, origin, d, rho_p, T, mu, pressure,
                   coefficients="Davies", cloud="kinematicCloud"):
    """Rows (t, t/tau, msd, se, expected, (msd - expected)/se) at each time
    folder, for parcels of diameter d [m] and density rho_p [kg/m^3] in
    gas at T [K], viscosity mu [Pa s] and pressure [Pa]."""
    lam = correlations.mean_free_path(mu, pressure, T)
    slip = correlations.cunningham(d, lam, coefficients)
    D = correlations.stokes_einstein(d, T, mu, slip)
    tau = rho_p * d * d * slip / (18 * mu)
    rows = []
    for t, msd, se, _ in measured_msd(case, origin, cloud):
        expected = brownian_msd(t, tau, D)
        rows.append((t, t / tau, msd, se, expected, (msd - expected) / se))
    return rows
