# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The Kolmogorov-Smirnov distance of samples from a distribution, for the
tests of the tutorials' start positions."""

import math


def ks_bound(n):
    """The distance that n samples of the right distribution exceed with
    probability 0.001 (1.95/sqrt(n), the asymptotic bound)."""
    return 1.95 / math.sqrt(n)


def ks_distance(samples, cdf):
    """sup |F_n(x) - F(x)| of the samples against the CDF."""
    xs = sorted(samples)
    n = len(xs)
    return max(max((i + 1) / n - cdf(x), cdf(x) - i / n)
               for i, x in enumerate(xs))
