# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The package's own resuspension formulas (adhesivewall.resuspension),
the reference the channelResuspension tutorial judges the library by:
limits, identities and independent computations (bisection, a dense grid,
Monte Carlo over the quantile), not numbers copied from the code.
"""

import math
import random

import numpy as np
import pytest

from adhesivewall import resuspension as rs

W = 0.56                                # J/m^2
E_STAR = rs.contact_modulus(370e9, 0.22, 193e9, 0.30)
AIR = (1.2041, 1.50596e-5)              # rho, nu


def approx(expected, rel=1e-12, abs=0.0):
    """pytest.approx without its default absolute tolerance of 1e-12,
    which would pass any two numbers of the magnitudes here (N, m)"""
    return pytest.approx(expected, rel=rel, abs=abs)


# --- Adhesion at rest ------------------------------------------------------

def test_contact_modulus_limits():
    E, nu = 200e9, 0.3
    assert rs.contact_modulus(E, nu, E, nu) == approx(
        E / (2 * (1 - nu * nu)), rel=1e-14)
    # a rigid wall: the particle's own E/(1 - nu^2)
    assert rs.contact_modulus(E, nu, 1e300, 0.2) == approx(
        E / (1 - nu * nu), rel=1e-14)
    assert rs.contact_modulus(1e9, 0.3, 2e9, 0.1) == \
        rs.contact_modulus(2e9, 0.1, 1e9, 0.3)


def jkr_load(a, w, r, E_star):
    """JKR's load P(a) = K a^3/r - sqrt(6 pi w K a^3), K = 4/3 E*."""
    K = 4 / 3 * E_star
    return K * a ** 3 / r - math.sqrt(6 * math.pi * w * K * a ** 3)


@pytest.mark.parametrize("r", [1e-6, 5e-6, 10e-6])
def test_zero_load_contact_radius_solves_jkr(r):
    # P(a) = 0 by bisection, from a bracket far on both sides
    lo, hi = 1e-3 * r, r
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if jkr_load(mid, W, r, E_STAR) < 0:
            lo = mid
        else:
            hi = mid
    assert rs.jkr_contact_radius(W, r, E_STAR) == approx(lo, rel=1e-12)


@pytest.mark.parametrize("r", [1e-6, 10e-6])
def test_pull_off_is_the_least_load(r):
    # the minimum of P(a) on a dense grid around a0/4^(1/3)
    a0 = rs.jkr_contact_radius(W, r, E_STAR)
    a = np.linspace(0.3 * a0, 0.9 * a0, 200001)
    K = 4 / 3 * E_STAR
    P = K * a ** 3 / r - np.sqrt(6 * math.pi * W * K * a ** 3)
    assert -P.min() == approx(rs.jkr_pull_off(W, r), rel=1e-9)


# --- Rolling detachment -----------------------------------------------------

def test_critical_stress_balances_the_moments():
    # M + F_D r = F_adh a at tau_c, with the moments written out
    r, F, a = 5e-6, 1e-7, 1e-7
    tau = rs.critical_wall_shear_stress(F, a, r)
    M = 0.944 * 4 * math.pi * tau * r ** 3
    F_D = 1.7009 * 6 * math.pi * tau * r * r
    assert M + F_D * r == approx(F * a, rel=1e-13)


def test_smooth_critical_stress_scales_as_theory():
    # tau_c = (3/2) w a0/(C r^2) ~ w^(4/3) r^(-4/3) E*^(-1/3)
    def tau(w, r, E):
        return rs.critical_wall_shear_stress(
            rs.jkr_pull_off(w, r), rs.jkr_contact_radius(w, r, E), r)
    base = tau(W, 5e-6, E_STAR)
    assert tau(W, 10e-6, E_STAR) / base == approx(2 ** (-4 / 3),
                                                          rel=1e-12)
    assert tau(2 * W, 5e-6, E_STAR) / base == approx(2 ** (4 / 3),
                                                             rel=1e-12)
    assert tau(W, 5e-6, 8 * E_STAR) / base == approx(0.5, rel=1e-12)


def test_critical_friction_velocity_jkr():
    r, rho = 5e-6, AIR[0]
    tau = rs.critical_wall_shear_stress(
        0.01 * rs.jkr_pull_off(W, r), rs.jkr_contact_radius(W, r, E_STAR), r)
    assert rs.critical_friction_velocity_jkr(r, W, E_STAR, rho, 0.01) == \
        approx(math.sqrt(tau / rho), rel=1e-14)


# --- Biasi's log-normal ---------------------------------------------------------

def test_biasi_fit():
    fbar, sigma = rs.biasi(5e-6)
    assert fbar == approx(0.016 - 0.0023 * 5 ** 0.545, rel=1e-14)
    assert sigma == approx(1.8 + 0.136 * 5 ** 1.4, rel=1e-14)
    # doc/resuspension.md section 7
    assert (round(fbar, 6), round(sigma, 3)) == (0.010471, 3.094)
    with pytest.raises(ValueError):
        rs.biasi(36e-6)


@pytest.mark.parametrize("u", [1e-12, 1e-4, 0.1, 0.5, 0.9, 1 - 1e-9])
def test_quantile_inverts_the_distribution(u):
    fbar, sigma = rs.biasi(10e-6)
    f = rs.lognormal_quantile(u, fbar, sigma)
    assert rs.lognormal_cdf(f, fbar, sigma) == approx(u, rel=1e-9)


def test_median_and_density():
    fbar, sigma = 0.01, 3.0
    assert rs.lognormal_quantile(0.5, fbar, sigma) == approx(fbar,
                                                                     rel=1e-14)
    # the density integrated between two quantiles is their difference
    a = rs.lognormal_quantile(0.1, fbar, sigma)
    b = rs.lognormal_quantile(0.7, fbar, sigma)
    f = np.linspace(a, b, 400001)
    assert np.trapz(rs.lognormal_pdf(f, fbar, sigma), f) == \
        approx(0.6, rel=1e-8)
    assert rs.lognormal_pdf(np.array([-1.0, 0.0]), fbar, sigma).tolist() == \
        [0.0, 0.0]


# --- The rock'n'roll rate ---------------------------------------------------------

def test_rate_at_the_mean_force_is_omega_over_pi():
    # x = 0: (omega/2 pi) exp(0)/((1 + erf 0)/2) = omega/pi
    frequency = 123.0           # omega/(2 pi) [1/s]
    assert float(rs.rocknroll_rate(7.0, 7.0, frequency)) == \
        approx(2 * frequency, rel=1e-15)


@pytest.mark.parametrize("x", [1.0, 3.0, 4.5])
def test_rate_of_strong_adhesion_is_the_gaussian_tail(x):
    # p/((omega/2 pi) exp(-x^2)) - 1 = erfc(x)/(1 + erf x) (1e-10 at
    # x = 4.5: to the round-off of the quotient)
    mean, ratio, frequency = 1.0, 0.2, 10.0
    fa = mean + x * math.sqrt(2) * ratio * mean
    p = float(rs.rocknroll_rate(fa, mean, frequency, ratio))
    assert p / (frequency * math.exp(-x * x)) - 1 == approx(
        math.erfc(x) / (1 + math.erf(x)), rel=1e-9, abs=1e-15)


@pytest.mark.parametrize("y", [8.0, 30.0, 1e3])
def test_rate_of_weak_adhesion_grows_as_the_asymptote(y):
    # x = -y << 0: p ~ 2 sqrt(pi) (omega/2 pi) y (1 + 1/(2y^2) - 1/(2y^4))
    mean, ratio, frequency = 1.0, 0.2, 1.0
    fa = mean - y * math.sqrt(2) * ratio * mean
    p = float(rs.rocknroll_rate(fa, mean, frequency, ratio))
    series = 2 * math.sqrt(math.pi) * y * (1 + 0.5 / y ** 2 - 0.5 / y ** 4)
    assert p == approx(series, rel=2 / y ** 6 + 1e-12)


def test_rate_is_continuous_where_its_evaluation_changes():
    # x = -5: the direct quotient and the continued fraction meet
    mean, ratio = 1.0, 0.2
    x = np.array([-5 - 1e-12, -5 + 1e-12])
    p = rs.rocknroll_rate(mean + x * math.sqrt(2) * ratio * mean, mean, 1.0,
                          ratio)
    assert p[0] == approx(p[1], rel=1e-10)


def test_mean_aerodynamic_force_multiplied_out():
    # 10.45 (1 + 300 r+^-0.31) r+^2.31 = 10.45 r+^2.31 + 3135 r+^2
    r, ustar, (rho, nu) = 5e-6, 0.7, AIR
    rp = r * ustar / nu
    assert rs.mean_aerodynamic_force(r, ustar, rho, nu) == approx(
        (10.45 * rp ** 2.31 + 3135 * rp ** 2) * rho * nu * nu, rel=1e-12)
    assert rs.burst_frequency(2.0, 1e-5) == approx(0.00658 * 4 / 1e-5,
                                                          rel=1e-15)


# --- Fraction remaining of a population ---------------------------------------------

def test_nothing_leaves_without_time():
    # the trapezoid of the standard normal over [-8.3, 8.3]
    assert rs.remaining_after_holds(5e-6, W, *AIR, [1.0], 0.0) == \
        approx([1.0], abs=1e-12)


@pytest.mark.parametrize("ustar", [0.5, 0.9, 2.0])
def test_near_delta_population_leaves_as_one_particle(ustar):
    # sigma -> 1: every particle has f' = fbar, R = exp(-p(fbar) t)
    r, (rho, nu), fbar, t = 5e-6, AIR, 0.01, 1.0
    p = float(rs.rate_biasi(fbar * rs.jkr_pull_off(W, r), r, ustar, rho, nu))
    remaining = rs.remaining_after_holds(r, W, rho, nu, [ustar], t,
                                         fbar=fbar, sigma=1 + 1e-9)
    assert remaining[0] == approx(math.exp(-p * t), rel=1e-9,
                                         abs=1e-300)


def test_holds_add_their_exposures():
    # two holds of T at one u* leave what one hold of 2 T leaves, and the
    # fraction falls with u* and with time
    r, (rho, nu) = 5e-6, AIR
    two = rs.remaining_after_holds(r, W, rho, nu, [0.9, 0.9], 1.0)
    one = rs.remaining_after_holds(r, W, rho, nu, [0.9], 2.0)
    assert two[1] == approx(one[0], rel=1e-12)
    steps = rs.remaining_after_holds(r, W, rho, nu, [0.3, 0.6, 0.9, 1.5], 1.0)
    assert all(a > b for a, b in zip(steps, steps[1:]))
    assert two[0] > two[1]


@pytest.mark.parametrize("ustar", [0.6, 1.0, 2.0])
def test_quadrature_against_monte_carlo_over_the_quantile(ustar):
    # 100 000 particles drawn through the quantile (stratified u), each
    # kept with exp(-p t): the mean within 4 standard errors
    r, (rho, nu), t = 10e-6, AIR, 1.0
    fbar, sigma = rs.biasi(r)
    n = 100000
    rng = random.Random(7)
    u = [(i + rng.random()) / n for i in range(n)]
    fa = np.array([rs.lognormal_quantile(v, fbar, sigma) for v in u]) \
        * rs.jkr_pull_off(W, r)
    kept = np.exp(-rs.rate_biasi(fa, r, ustar, rho, nu) * t)
    se = kept.std() / math.sqrt(n)
    quadrature = rs.remaining_after_holds(r, W, rho, nu, [ustar], t)[0]
    assert abs(kept.mean() - quadrature) < 4 * se + 1e-6


def test_quadrature_converged():
    r, (rho, nu) = 10e-6, AIR
    coarse = rs.remaining_after_holds(r, W, rho, nu, [0.5, 1.0, 2.0], 1.0)
    fine = rs.remaining_after_holds(r, W, rho, nu, [0.5, 1.0, 2.0], 1.0,
                                    z_points=40001)
    assert coarse == approx(fine, abs=1e-9)


def test_doc_table_fifty_percent_after_one_second():
    # doc/resuspension.md section 7 (its throw-away script, the same
    # formulas): u* of 50 % removal after 1 s in air, 10 and 20 um
    us = list(np.arange(0.3, 1.5, 0.001))
    for d, expected in ((10e-6, 0.92), (20e-6, 0.58)):
        rem = [rs.remaining_after_holds(d / 2, W, *AIR, [u], 1.0,
                                        z_points=2001)[0] for u in us]
        assert rs.ustar_at_fraction(us, rem) == approx(expected,
                                                              abs=0.006)


# --- The u* of a fraction ----------------------------------------------------------

def test_ustar_at_fraction():
    assert rs.ustar_at_fraction([0, 1], [1, 0]) == approx(0.5)
    assert rs.ustar_at_fraction([1, 2, 3], [0.9, 0.7, 0.1], 0.4) == \
        approx(2.5)
    # the first downward crossing of a curve that is not monotone
    assert rs.ustar_at_fraction([1, 2, 3, 4, 5], [0.9, 0.4, 0.6, 0.3, 0.2]) \
        == approx(1.8)
    assert rs.ustar_at_fraction([1, 2], [0.9, 0.6]) is None
    assert rs.ustar_at_fraction([1, 2], [0.7, 0.5]) == approx(2.0)
    # a curve that reaches the level at a point falls to it there, even if
    # it rises again, and one that starts at the level falls to it at once
    assert rs.ustar_at_fraction([1, 2, 3, 4], [0.7, 0.5, 0.6, 0.3]) == \
        approx(2.0)
    assert rs.ustar_at_fraction([1, 2], [0.5, 0.3]) == approx(1.0)
    assert rs.ustar_at_fraction([1, 2, 3], [0.5, 0.5, 0.3]) == approx(1.0)
