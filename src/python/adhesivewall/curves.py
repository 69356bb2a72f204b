# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Curves through measured or simulated points, and counting statistics."""

import math


def interpolate(x, xs, ys):
    """y(x) on the piecewise linear curve through (xs, ys), taken in the
    order given: on the first segment whose ends bracket x with xs rising
    along it. None where no segment reaches x (no extrapolation), so that
    the inverse of a rising curve is interpolate(y, ys, xs)."""
    for i in range(len(xs) - 1):
        x0, x1 = xs[i], xs[i + 1]
        if x0 <= x <= x1 and x0 < x1:
            return ys[i] + (ys[i + 1] - ys[i]) * (x - x0) / (x1 - x0)
    return None


def binomial_se(successes, trials):
    """The standard error of the fraction successes/trials,
    sqrt(p (1 - p)/n)."""
    if trials <= 0:
        raise ValueError(f"binomial_se: {trials} trials")
    p = successes / trials
    return math.sqrt(p * (1 - p) / trials)


def poiseuille_flux_fraction(s):
    """The fraction of fully developed laminar (Poiseuille) flow through a
    tube that passes within s = r/R of its axis:
    F(s) = int_0^s 4 (1 - t^2) t dt = 2 s^2 - s^4."""
    return 2 * s * s - s ** 4


def poiseuille_flux_radius(F):
    """The inverse of poiseuille_flux_fraction: the s = r/R enclosing the
    fraction F in [0, 1] of the flow. F = 1 - (1 - s^2)^2, so
    s^2 = 1 - sqrt(1 - F), computed as F/(1 + sqrt(1 - F)) (no
    cancellation for small F)."""
    return math.sqrt(F / (1 + math.sqrt(1 - F)))


def log_space(first, last, n):
    """n values from first to last, evenly spaced in their logarithm."""
    return [first * (last / first) ** (i / (n - 1)) for i in range(n)]
