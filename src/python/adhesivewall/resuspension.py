# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Resuspension of deposited spheres by a flow: an independent reference.

The formulas of doc/resuspension.md written again in numpy, without the
library's C++ (src/brachDunn/resuspension/Resuspension), so that the tutorial
channelResuspension judges the library against a second implementation:

    JKR adhesion          F_JKR = (3/2) pi w r,  a0^3 = 6 pi w r^2/K,
                          K = (4/3) E*
    rolling balance       tau_c = F_adh a0/(C pi r^3),  C = 4 0.944 + 6 1.7009
    Biasi et al. (2001)   f' = F_adh/F_JKR log-normal, fbar = 0.016 -
                          0.0023 r^0.545, sigma = 1.8 + 0.136 r^1.4 (r in um)
    rock'n'roll rate      p = (omega/2 pi) exp(-x^2)/((1 + erf x)/2),
    (Reeks & Hall 2001)   x = (f_a - <f>)/(sqrt 2 0.2 <f>),
                          omega/2 pi = 0.00658 u*^2/nu,
                          <f> = 10.45 (1 + 300 r+^-0.31) r+^2.31 rho nu^2
    population            R = int phi(f') prod_k exp(-p_k(f') T_k) df'

SI units throughout (the radius of Biasi's fit is converted). The constants
not verified against their papers (doc/resuspension.md says which) are
arguments with the doc's values as defaults. Only numpy and the standard
library (math.erf, statistics.NormalDist): no scipy.
"""

import math
from statistics import NormalDist

import numpy as np

#: O'Neill's (1968) drag factor of a sphere touching the wall in shear flow
DRAG_FACTOR = 1.7009
#: Goldman, Cox & Brenner's (1967) torque factor of the same sphere
TORQUE_FACTOR = 0.944
#: C of M + F_D r = C pi tau_w r^3
LOAD_FACTOR = 4 * TORQUE_FACTOR + 6 * DRAG_FACTOR
#: Reeks & Hall's rms/mean ratio of the aerodynamic force
RMS_RATIO = 0.2
#: Reeks & Hall's typical frequency omega/(2 pi) in wall units, nu/u*^2
FREQUENCY_PLUS = 0.00658
#: The standard normal tails beyond +-Z_MAX hold 2 Phi(-8.3) = 1.0e-16
Z_MAX = 8.3

_NORMAL = NormalDist()


# --- Adhesion at rest ---------------------------------------------------------

def contact_modulus(E1, nu1, E2, nu2):
    """E* = 1/((1 - nu1^2)/E1 + (1 - nu2^2)/E2) [Pa] of two elastic bodies
    of Young's moduli E1, E2 [Pa] and Poisson's ratios nu1, nu2 (Johnson,
    Contact Mechanics, 1985, Eq. 4.22)."""
    return 1.0 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2)


def jkr_pull_off(w, r):
    """The JKR pull-off force (3/2) pi w r [N] of a sphere of radius r [m]
    on a flat, work of adhesion w [J/m^2] (Johnson, Kendall & Roberts
    1971)."""
    return 1.5 * math.pi * w * r


def jkr_contact_radius(w, r, E_star):
    """The JKR contact radius at zero load, a0 = (6 pi w r^2/K)^(1/3) [m],
    K = (4/3) E* [Pa]."""
    return (6 * math.pi * w * r * r / (4.0 / 3.0 * E_star)) ** (1.0 / 3.0)


# --- Rolling detachment ---------------------------------------------------------

def critical_wall_shear_stress(F_adh, a, r, load_factor=LOAD_FACTOR):
    """The wall shear stress [Pa] at which a sphere of radius r [m], held
    by F_adh [N] with the arm a [m] about the downstream edge of its
    contact, rolls off: the moments M + F_D r = C pi tau_w r^3 of a linear
    shear flow equal F_adh a, tau_c = F_adh a/(C pi r^3)."""
    return F_adh * a / (load_factor * math.pi * r ** 3)


def critical_friction_velocity_jkr(r, w, E_star, rho, reduced_adhesion=1.0):
    """sqrt(tau_c/rho) [m/s] of a JKR contact of reduced adhesion f'
    (F_adh = f' F_JKR, the arm a0) in a gas of density rho [kg/m^3]."""
    tau = critical_wall_shear_stress(reduced_adhesion * jkr_pull_off(w, r),
                                     jkr_contact_radius(w, r, E_star), r)
    return math.sqrt(tau / rho)


# --- The spread of adhesion: log-normal ------------------------------------------

def biasi(r):
    """Biasi et al.'s (2001) fit of the log-normal reduced adhesion f' for
    a sphere of radius r [m] (converted to micrometres in the fit):
    (fbar, sigma), fbar = 0.016 - 0.0023 r^0.545 the geometric mean (the
    median) and sigma = 1.8 + 0.136 r^1.4 the geometric spread. Not
    verified against the paper (doc/resuspension.md section 4). A
    ValueError where fbar <= 0 (r >= 35 um)."""
    r_um = r * 1e6
    fbar = 0.016 - 0.0023 * r_um ** 0.545
    if not r > 0 or fbar <= 0:
        raise ValueError(f"biasi: radius {r} m outside the fit (0, 35 um)")
    return fbar, 1.8 + 0.136 * r_um ** 1.4


def lognormal_pdf(f, fbar, sigma):
    """The log-normal density phi(f') of geometric mean fbar and geometric
    spread sigma > 1 (0 where f' <= 0)."""
    f = np.asarray(f, dtype=float)
    s = math.log(sigma)
    positive = f > 0
    safe = np.where(positive, f, 1.0)
    z = np.log(safe / fbar) / s
    return np.where(positive, np.exp(-0.5 * z * z)
                    / (math.sqrt(2 * math.pi) * safe * s), 0.0)


def lognormal_cdf(f, fbar, sigma):
    """F(f') = Phi(ln(f'/fbar)/ln sigma) (0 where f' <= 0), Phi(z) =
    erfc(-z/sqrt 2)/2: no cancellation in the lower tail."""
    if f <= 0:
        return 0.0
    return 0.5 * math.erfc(-math.log(f / fbar) / math.log(sigma)
                           / math.sqrt(2))


def lognormal_quantile(u, fbar, sigma):
    """The f' of share u in (0, 1): fbar sigma^(Phi^-1(u))."""
    return fbar * sigma ** _NORMAL.inv_cdf(u)


# --- The rock'n'roll rate -------------------------------------------------------------

def burst_frequency(ustar, nu, frequency_plus=FREQUENCY_PLUS):
    """Reeks & Hall's typical frequency omega/(2 pi) = 0.00658 u*^2/nu
    [1/s] at friction velocity u* [m/s], kinematic viscosity nu [m^2/s]
    (the reading of the constant as omega/(2 pi): doc/resuspension.md
    section 5)."""
    return frequency_plus * ustar * ustar / nu


def mean_aerodynamic_force(r, ustar, rho, nu):
    """Biasi et al.'s <f> = 10.45 (1 + 300 r+^-0.31) r+^2.31 rho nu^2 [N],
    r+ = r u*/nu, on a sphere of radius r [m] in a gas of density rho
    [kg/m^3] (not verified against the paper)."""
    rplus = r * ustar / nu
    return 10.45 * (1 + 300 * rplus ** -0.31) * rplus ** 2.31 * rho * nu * nu


def _held_rate_factor(x):
    """exp(-x^2)/((1 + erf x)/2) for an array x, without 0/0 where both
    underflow: for x < -5 the (1 + erf x)/2 = erfc(y)/2, y = -x, is taken
    from Laplace's continued fraction of erfc(y) exp(y^2)."""
    x = np.asarray(x, dtype=float)
    out = np.empty_like(x)
    direct = x >= -5
    xd = x[direct]
    out[direct] = np.exp(-xd * xd) / (0.5 * np.array(
        [math.erfc(-v) for v in xd.ravel()]).reshape(xd.shape))
    y = -x[~direct]
    if y.size:
        # erfc(y) exp(y^2) sqrt(pi) = 1/(y + (1/2)/(y + 1/(y + (3/2)/(y + ...))))
        tail = np.zeros_like(y)
        for k in range(60, 0, -1):
            tail = (k / 2) / (y + tail)
        erfcx = 1 / (math.sqrt(math.pi) * (y + tail))
        out[~direct] = 2 / erfcx
    return out


def rocknroll_rate(fa, mean_force, frequency, rms_ratio=RMS_RATIO):
    """The quasi-static rock'n'roll rate p [1/s] of particles held by fa
    (a number or an array) against an aerodynamic force of mean mean_force
    and rms rms_ratio mean_force (any one unit), frequency = omega/(2 pi)
    [1/s]:

        p = (omega/2 pi) exp(-x^2)/((1 + erf x)/2),
        x = (fa - <f>)/(sqrt 2 rms_ratio <f>)

    Rice's rate of up-crossings of fa per particle still held."""
    x = (np.asarray(fa, dtype=float) - mean_force) \
        / (math.sqrt(2) * rms_ratio * mean_force)
    return frequency * _held_rate_factor(x)


def rate_biasi(fa, r, ustar, rho, nu, rms_ratio=RMS_RATIO,
               frequency_plus=FREQUENCY_PLUS):
    """rocknroll_rate with Biasi's <f> and Reeks & Hall's frequency for a
    sphere of radius r [m] held by fa [N] at friction velocity u* [m/s]."""
    return rocknroll_rate(fa, mean_aerodynamic_force(r, ustar, rho, nu),
                          burst_frequency(ustar, nu, frequency_plus),
                          rms_ratio)


# --- Fraction remaining of a population ----------------------------------------

def population_remaining(rates, holds, z_points=4001, z_max=Z_MAX):
    """The fraction of a log-normal population left after a sequence of
    holds: int N(z) prod_k exp(-p_k(z) T_k) dz over the standard normal
    z = ln(f'/fbar)/ln sigma, by the trapezoid rule on z_points points in
    [-z_max, z_max]. `rates(z, k)` gives the rate [1/s] at z (an array)
    during hold k; holds: the durations T_k [s]. The survival
    exp(-sum p_k T_k) is computed in one exponential."""
    z = np.linspace(-z_max, z_max, z_points)
    exposure = np.zeros_like(z)
    for k, T in enumerate(holds):
        exposure += rates(z, k) * T
    integrand = np.exp(-0.5 * z * z) / math.sqrt(2 * math.pi) \
        * np.exp(-exposure)
    return float(np.trapz(integrand, z))


def remaining_after_holds(r, w, rho, nu, ustars, hold, fbar=None, sigma=None,
                          rms_ratio=RMS_RATIO, frequency_plus=FREQUENCY_PLUS,
                          z_points=4001):
    """The rock'n'roll fraction of a deposit of spheres of radius r [m]
    (work of adhesion w [J/m^2], Biasi's log-normal f' unless fbar and
    sigma are given) left at the end of each hold of the friction
    velocities u* [m/s] in turn, each `hold` [s] long, in a gas of density
    rho and kinematic viscosity nu: a list as long as ustars (the same
    deposit through all holds, as the experiment's steps)."""
    if fbar is None or sigma is None:
        fbar, sigma = biasi(r)
    z = np.linspace(-Z_MAX, Z_MAX, z_points)
    fa = jkr_pull_off(w, r) * fbar * sigma ** z
    weights = np.exp(-0.5 * z * z) / math.sqrt(2 * math.pi)
    exposure = np.zeros_like(z)
    remaining = []
    for ustar in ustars:
        exposure = exposure + hold * rate_biasi(
            fa, r, ustar, rho, nu, rms_ratio, frequency_plus)
        remaining.append(float(np.trapz(weights * np.exp(-exposure), z)))
    return remaining


def ustar_at_fraction(ustars, remaining, level=0.5):
    """The u* at which a remaining-fraction curve (u* rising) first falls
    to `level`: the first point at the level, or the linear interpolation
    on the first segment that falls through it (a measured curve need not
    fall monotonically); None when it never does."""
    for i in range(len(ustars) - 1):
        r0, r1 = remaining[i], remaining[i + 1]
        if r0 == level:
            return ustars[i]
        if r0 > level >= r1:
            return ustars[i] + (ustars[i + 1] - ustars[i]) \
                * (r0 - level) / (r0 - r1)
    return None
