# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Correlations of aerosol deposition, each as published, with its source.

Units are SI unless a docstring says otherwise; dimensionless groups are
named as in their source.
"""

import math


# --- Bends -----------------------------------------------------------------

def pui_bend_laminar(stokes_diameter, bend_angle=math.pi / 2):
    """Deposition efficiency in a circular bend, laminar flow.

    Pui, D.Y.H., Romay-Novas, F. and Liu, B.Y.H. (1987), "Experimental study
    of particle deposition in bends of circular cross section", Aerosol Sci.
    Technol. 7:301-315, as quoted by Brockmann (2011, Aerosol Measurement,
    3rd ed., ch. 6):

        eta = 1 - [1 + (St/0.171)^(0.452 St/0.171 + 2.242)]^(-2 theta/pi)

    St: the Stokes number on the tube DIAMETER, rho_p Cc d^2 U/(9 mu D)
    (half the Stokes number on the radius); theta: the bend angle [rad].
    """
    x = stokes_diameter / 0.171
    return 1 - (1 + x ** (0.452 * x + 2.242)) ** (-2 * bend_angle / math.pi)


# --- Single fibres in a filter (Kuwabara cell flow) -----------------------

def kuwabara(alpha):
    """Kuwabara's hydrodynamic factor of a fibrous filter of solidity alpha:

        Ku = -ln(alpha)/2 - 3/4 + alpha - alpha^2/4

    Kuwabara, S. (1959), "The forces experienced by randomly distributed
    parallel circular cylinders or spheres in a viscous flow at small
    Reynolds numbers", J. Phys. Soc. Japan 14:527-532; Hinds (1999),
    Aerosol Technology, 2nd ed., Eq. 9.25.
    """
    return -math.log(alpha) / 2 - 0.75 + alpha - alpha * alpha / 4


def interception(alpha, R):
    """Single-fibre efficiency by interception in Kuwabara flow, R = d/d_f:

        eta_R = (1 - alpha) R^2 / (Ku (1 + R))

    The theoretical form of Lee, K.W. and Liu, B.Y.H. (1982), "Theoretical
    study of aerosol filtration by fibrous filters", Aerosol Sci. Technol.
    1(2):147-161, as Hinds (1999, Aerosol Technology, 2nd ed., ch. 9)
    quotes it: the small-R form of the exact interception of Kuwabara's
    flow, (1 - alpha) R^2/Ku + O(R^3). (Their companion "Experimental study
    of aerosol filtration by fibrous filters", Aerosol Sci. Technol. 1:35-46,
    fits measurements with 0.6 times this term; not used here.)
    """
    return (1 - alpha) * R * R / (kuwabara(alpha) * (1 + R))


def impaction(alpha, R, stokes):
    """Single-fibre efficiency by impaction in Kuwabara flow:

        eta_I = Stk J/(2 Ku^2),
        J = (29.6 - 28 alpha^0.62) R^2 - 27.5 R^2.8     (R < 0.4)

    Stk = rho_p Cc d^2 U0/(18 mu d_f). Stechkina, I.B., Kirsch, A.A. and
    Fuchs, N.A. (1969), "Studies on fibrous aerosol filters IV. Calculation
    of aerosol deposition in model filters in the range of maximum
    penetration", Ann. Occup. Hyg. 12:1-8, as Hinds (1999) gives it
    (Eqs. 9.33, 9.34). None for R >= 0.4, where the fit does not hold.
    """
    if R >= 0.4:
        return None
    J = (29.6 - 28 * math.exp(0.62 * math.log(alpha))) * R * R \
        - 27.5 * math.exp(2.8 * math.log(R))
    return stokes * J / (2 * kuwabara(alpha) ** 2)


def diffusion_stechkina_fuchs(alpha, peclet):
    """Single-fibre efficiency by diffusion in Kuwabara flow:

        eta_D = 2.9 Ku^(-1/3) Pe^(-2/3) + 0.62 Pe^(-1),   Pe = d_f U0/D

    Stechkina, I.B. and Fuchs, N.A. (1966), "Studies on fibrous aerosol
    filters I. Calculation of diffusional deposition of aerosols in fibrous
    filters", Ann. Occup. Hyg. 9:59-64. The first term is the concentration
    boundary layer on the fibre (its coefficient is that of the Leveque
    solution in Kuwabara's flow, 2.89 ((1 - alpha)/Ku)^(1/3), for small
    alpha); the second corrects it at moderate Pe.
    """
    return 2.9 * kuwabara(alpha) ** (-1 / 3) * peclet ** (-2 / 3) \
        + 0.62 / peclet


def diffusion_lee_liu(alpha, peclet):
    """Single-fibre efficiency by diffusion in Kuwabara flow:

        eta_D = 2.6 ((1 - alpha)/Ku)^(1/3) Pe^(-2/3)

    Lee, K.W. and Liu, B.Y.H. (1982), "Theoretical study of aerosol
    filtration by fibrous filters", Aerosol Sci. Technol. 1(2):147-161.
    """
    return 2.6 * ((1 - alpha) / kuwabara(alpha)) ** (1 / 3) \
        * peclet ** (-2 / 3)


def diffusion_interception(alpha, R, peclet):
    """The interaction of diffusion and interception, added to their sum:

        eta_DR = 1.24 R^(2/3) / (Ku Pe)^(1/2)

    Stechkina, I.B., Kirsch, A.A. and Fuchs, N.A. (1969), Ann. Occup. Hyg.
    12:1-8 (see `impaction`).
    """
    return 1.24 * R ** (2 / 3) / math.sqrt(kuwabara(alpha) * peclet)


def lee_liu_mpps(alpha, d_fibre, U0, mean_free_path, temperature, mu):
    """The most penetrating particle size d* [m] of a fibrous filter and
    its single-fibre efficiency eta* (the minimum), in closed form:

        d*   = 0.885 [(Ku/(1 - alpha)) (sqrt(lambda) k T/mu) (d_f^2/U0)]^(2/9)
        eta* = 1.44 [((1 - alpha)/Ku)^5 (sqrt(lambda) k T/mu)^4
                     / (U0^4 d_f^10)]^(1/9)

    Lee, K.W. and Liu, B.Y.H. (1980), "On the minimum efficiency and the
    most penetrating particle size for fibrous filters", J. Air Pollut.
    Control Assoc. 30(4):377-381, as Hinds (1999, Aerosol Technology, 2nd
    ed., Eqs. 9.35, 9.36) gives it. It is the minimum of diffusion plus
    interception, 1.6 ((1 - alpha)/Ku)^(1/3) Pe^(-2/3)
    + 0.6 (1 - alpha) R^2/(Ku (1 + R)) (the coefficients of Lee & Liu's
    experimental study, Aerosol Sci. Technol. 1:35-46, 1982: eta* = 3 x 0.6
    ((1 - alpha)/Ku) (d*/d_f)^2 to the rounding of 0.885 and 1.44), with
    the slip correction taken as a power of lambda/d (D ~ sqrt(lambda)
    d^(-3/2)) and R << 1; no impaction. tests/python/test_correlations.py
    checks it against the numerical minimum of that sum with Cunningham's
    correction. Returns (d*, eta*).
    """
    Ku = kuwabara(alpha)
    s = math.sqrt(mean_free_path) * BOLTZMANN * temperature / mu
    d = 0.885 * (Ku / (1 - alpha) * s * d_fibre ** 2 / U0) ** (2 / 9)
    eta = 1.44 * (((1 - alpha) / Ku) ** 5 * s ** 4
                  / (U0 ** 4 * d_fibre ** 10)) ** (1 / 9)
    return d, eta


# --- Tubes ------------------------------------------------------------------

def gormley_kennedy(mu):
    """Penetration of a diffusing aerosol through a circular tube in fully
    developed laminar flow, mu = pi D L/Q (D the particles' diffusivity, L
    the tube's length, Q the flow rate):

        mu < 0.02:  P = 1 - 2.5638 mu^(2/3) + 1.2 mu + 0.1767 mu^(4/3)
        otherwise:  P = 0.81905 exp(-3.6568 mu) + 0.09753 exp(-22.305 mu)
                      + 0.0325 exp(-56.961 mu) + 0.01544 exp(-107.62 mu)

    Gormley, P.G. and Kennedy, M. (1949), "Diffusion from a stream flowing
    through a cylindrical tube", Proc. R. Irish Acad. A 52:163-169; the
    coefficients as Aerosol Measurement (Kulkarni, Baron & Willeke, eds.,
    3rd ed., 2011) gives them: the first terms of the Graetz series (the
    exponents are half the squared eigenvalues) and, for small mu, the
    Leveque expansion, 2.5638 = 3 (4/9)^(1/3)/Gamma(4/3).
    """
    if mu < 0:
        raise ValueError(f"gormley_kennedy: mu = {mu} < 0")
    if mu < 0.02:
        return 1 - 2.5638 * mu ** (2 / 3) + 1.2 * mu + 0.1767 * mu ** (4 / 3)
    return 0.81905 * math.exp(-3.6568 * mu) \
        + 0.09753 * math.exp(-22.305 * mu) \
        + 0.0325 * math.exp(-56.961 * mu) \
        + 0.01544 * math.exp(-107.62 * mu)


# --- Gas and particles ---------------------------------------------------------

BOLTZMANN = 1.380649e-23        # J/K (exact, SI 2019)
GAS_CONSTANT = 8.314462618      # J/(mol K)


def mean_free_path(mu, pressure, temperature, molar_mass=0.0289647):
    """The mean free path of gas molecules [m] from the gas's viscosity mu
    [Pa s], pressure [Pa], temperature [K] and molar mass [kg/mol] (air by
    default), by kinetic theory:

        lambda = sqrt(pi/8) mu / (0.4987445 sqrt(rho p)),  rho = p M/(R T)

    Jennings, S.G. (1988), "The mean free path in air", J. Aerosol Sci.
    19:159-166.
    """
    rho = pressure * molar_mass / (GAS_CONSTANT * temperature)
    return math.sqrt(math.pi / 8) * mu / (0.4987445 * math.sqrt(rho * pressure))


def cunningham(d, mean_free_path, coefficients="Davies"):
    """Cunningham's slip correction of Stokes drag on a sphere of diameter
    d [m] in a gas of the mean free path given [m]:

        Cc = 1 + Kn (A1 + A2 exp(-A3/Kn)),   Kn = 2 lambda/d

    Davies, C.N. (1945), "Definitive equations for the fluid resistance of
    spheres", Proc. Phys. Soc. 57:259-270: A1 1.257, A2 0.400, A3 1.10;
    Allen, M.D. and Raabe, O.G. (1985), "Slip correction measurements of
    spherical solid aerosol particles in an improved Millikan apparatus",
    Aerosol Sci. Technol. 4:269-286: A1 1.142, A2 0.558, A3 0.999 (with
    their lambda 0.0673 um at 296.15 K and 101.325 kPa).
    """
    A1, A2, A3 = CUNNINGHAM[coefficients]
    if mean_free_path == 0:
        return 1.0   # the continuum limit Kn -> 0
    Kn = 2 * mean_free_path / d
    return 1 + Kn * (A1 + A2 * math.exp(-A3 / Kn))


CUNNINGHAM = {"Davies": (1.257, 0.400, 1.10),
              "AllenRaabe": (1.142, 0.558, 0.999)}


def stokes_einstein(d, temperature, mu, slip=1.0):
    """The diffusivity of a sphere of diameter d [m] in a gas [m^2/s]:
    D = k_B T Cc/(3 pi mu d) (Einstein 1905, with the slip-corrected
    mobility Cc/(3 pi mu d))."""
    return BOLTZMANN * temperature * slip / (3 * math.pi * mu * d)


def settling_channel(settling_velocity, length, mean_velocity, height):
    """The fraction of the particles that settle onto the floor of a
    horizontal channel of the given length and height [m], in a steady 2-D
    flow of mean velocity [m/s], particles entering uniformly over the
    flux: min(1, v_s L/(U H)), whatever the velocity profile.

    Derived here (the classical result for horizontal channels; Fuchs,
    The Mechanics of Aerosols, 1964): a particle without inertia moves with
    the gas plus v_s downwards, so the flux below it, psi (the stream
    function, u = dpsi/dy, v = -dpsi/dx), changes along its path at
    dpsi/dt = (-v) u + u (v - v_s) = -u v_s, that is dpsi/dx = -v_s
    where the gas moves downstream (u > 0: no recirculation): it
    reaches the floor (psi = 0) within L when it enters with psi < v_s L,
    a fraction v_s L/(U H) of the flux U H. Particles spread uniformly
    over the area of an inlet of uniform velocity enter uniformly over
    the flux, however the profile develops downstream."""
    if min(settling_velocity, length, mean_velocity, height) < 0 \
            or mean_velocity * height == 0:
        raise ValueError(f"settling_channel: v_s {settling_velocity}, L "
                         f"{length}, U {mean_velocity}, H {height}")
    return min(1.0, settling_velocity * length / (mean_velocity * height))


def liu_agarwal(tau_plus):
    """Liu and Agarwal's fit to their deposition velocities of olive-oil
    droplets from turbulent air in vertical glass tubes, in the
    diffusion-impaction regime (tau+ up to about 20):

        V+ = 6e-4 tau+^2,   V+ = V_d/u*,  tau+ = tau_p u*^2/nu

    Liu, B.Y.H. and Agarwal, J.K. (1974), "Experimental observation of
    aerosol deposition in turbulent flow", J. Aerosol Sci. 5:145-155."""
    if tau_plus < 0:
        raise ValueError(f"liu_agarwal: tau+ = {tau_plus}")
    return 6e-4 * tau_plus ** 2


def papavergos_hedley(tau_plus):
    """Papavergos and Hedley's correlation of the published deposition
    data in its diffusion-impaction regime (as NIST FDS implements it):

        V+ = 3.5e-4 tau+^2

    Papavergos, P.G. and Hedley, A.B. (1984), "Particle deposition
    behaviour from turbulent flows", Chem. Eng. Res. Des. 62:275-295."""
    if tau_plus < 0:
        raise ValueError(f"papavergos_hedley: tau+ = {tau_plus}")
    return 3.5e-4 * tau_plus ** 2
