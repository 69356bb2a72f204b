# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The expected values of the aerosol checks (settling velocity, Brownian
mean squared displacement) against limits and identities computed here,
and the measured MSD of a synthetic case against its construction."""

import math
import os
import random

import pytest

from adhesivewall import aerosol
from adhesivewall import correlations as c


def test_settling_is_stokes_without_slip_and_scales_with_cc():
    # lambda = 0: Stokes' law (rho_p - rho_c) d^2 g/(18 mu) exactly
    d, mu, g = 1e-6, 1.8e-5, 9.81
    stokes = (1000 - 1.2) * d * d * g / (18 * mu)
    assert aerosol.settling_velocity(d, 1000, 1.2, mu, g, 0.0) == \
        pytest.approx(stokes, rel=1e-15, abs=0)
    lam = 66.5e-9
    assert aerosol.settling_velocity(d, 1000, 1.2, mu, g, lam) == \
        pytest.approx(stokes * c.cunningham(d, lam), rel=1e-15, abs=0)
    # neutrally buoyant: no settling
    assert aerosol.settling_velocity(d, 1.2, 1.2, mu, g, lam) == 0


def test_brownian_msd_limits():
    # Ballistic for t << tau: 3 (kB T/m) t^2 = 3 (D/tau) t^2;
    # diffusive for t >> tau: 6 D (t - tau)
    D, tau = 7e-10, 9e-8
    t = 1e-6 * tau
    assert aerosol.brownian_msd(t, tau, D) == pytest.approx(
        3 * D / tau * t * t, rel=1e-5, abs=0)
    t = 1e6 * tau
    assert aerosol.brownian_msd(t, tau, D) == pytest.approx(
        6 * D * (t - tau), rel=1e-14, abs=0)


def test_brownian_msd_solves_its_differential_equation():
    # For a thermal start d<r^2>/dt = 6 D (1 - exp(-t/tau)) (the velocity
    # autocorrelation integrated), <r^2>(0) = 0: finite differences
    D, tau = 7e-10, 9e-8
    for t in (0.3 * tau, tau, 5 * tau):
        dt = 1e-6 * tau
        slope = (aerosol.brownian_msd(t + dt, tau, D)
                 - aerosol.brownian_msd(t - dt, tau, D)) / (2 * dt)
        assert slope == pytest.approx(6 * D * (1 - math.exp(-t / tau)),
                                      rel=1e-6, abs=0)


def _write_positions(folder, points):
    os.makedirs(folder)
    with open(os.path.join(folder, "positions"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class Cloud; "
                "object positions; }\n")
        f.write(f"{len(points)}\n(\n")
        for p in points:
            f.write(f"({p[0]!r} {p[1]!r} {p[2]!r}) 0\n")
        f.write(")\n")


def test_measured_msd_of_a_synthetic_case(tmp_path):
    # Two times of Gaussian displacements of known variance per component:
    # the MSD within three standard errors of 3 sigma^2, the standard error
    # near sqrt(2/(3N)) of it
    rng = random.Random(11)
    origin = (1e-4, 2e-4, 3e-4)
    n = 20000
    for time, sigma in (("0.5", 1e-6), ("1", 2e-6)):
        points = [[o + rng.gauss(0, sigma) for o in origin]
                  for _ in range(n)]
        _write_positions(os.path.join(tmp_path, time, "lagrangian",
                                      "kinematicCloud"), points)
    rows = aerosol.measured_msd(str(tmp_path), origin)
    assert [r[0] for r in rows] == [0.5, 1.0]
    for (t, msd, se, count), sigma in zip(rows, (1e-6, 2e-6)):
        assert count == n
        assert abs(msd - 3 * sigma ** 2) < 3 * se
        assert se == pytest.approx(math.sqrt(2 / (3 * n)) * 3 * sigma ** 2,
                                   rel=0.05, abs=0)
