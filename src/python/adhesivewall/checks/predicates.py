# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Comparisons of numbers: close, small, near, sums_to, between, and the
median and the mean with its deviation."""

import math

from .registry import CheckError, command, fmt, number


def close(value, expected, rtol):
    """True when |value - expected| <= rtol |expected| (an expected 0 asks
    for exactly 0; a NaN is never close)."""
    return abs(value - expected) <= rtol * abs(expected)


def small(value, rtol, scale):
    """True when |value| <= rtol scale and scale > 0 (a residual against
    the mass it is a residual of: a zero scale has nothing to compare)."""
    return scale > 0 and abs(value) <= rtol * scale


def near(value, expected, rtol, scale):
    """True when |value - expected| <= rtol scale and scale > 0 (a position
    against the expected one, to a fraction of the particle's size)."""
    return scale > 0 and abs(value - expected) <= rtol * scale


def sums_to(total, rtol, parts):
    """True when the parts add up to the total to rtol relative, the total
    > 0 (a balance: what went in against where it went)."""
    return small(total - math.fsum(parts), rtol, total)


def between(value, low, high):
    """True when low < value < high (bounds excluded)."""
    return low < value < high


def median(values):
    """The median of the values (the mean of the middle two of an even
    count); a CheckError for none."""
    ordered = sorted(values)
    n = len(ordered)
    if not n:
        raise CheckError("the median of no values")
    return ordered[n // 2] if n % 2 else (ordered[n//2 - 1] + ordered[n//2])/2


def mean_and_deviation(values):
    """The mean and the sample standard deviation (n - 1; 0 for one value)
    of the values; a CheckError for none."""
    n = len(values)
    if not n:
        raise CheckError("the mean of no values")
    m = math.fsum(values) / n
    if n == 1:
        return m, 0.0
    return m, math.sqrt(math.fsum((v - m)**2 for v in values) / (n - 1))


@command("close", "VALUE EXPECTED RTOL [WHAT]")
def _close(value, expected, rtol, what="value"):
    """|VALUE - EXPECTED| <= RTOL |EXPECTED| (EXPECTED 0: exactly 0)."""
    if not close(number(value, what), number(expected, f"expected {what}"),
                 number(rtol, "RTOL")):
        raise CheckError(f"{what}: {value}, expected {expected} to {rtol} "
                         "relative")


@command("small", "VALUE RTOL SCALE [WHAT]")
def _small(value, rtol, scale, what="value"):
    """|VALUE| <= RTOL SCALE, with SCALE > 0."""
    if not small(number(value, what), number(rtol, "RTOL"),
                 number(scale, "SCALE")):
        raise CheckError(f"{what}: {value} is not within {rtol} of {scale}"
                         " (which must be > 0)")


@command("near", "VALUE EXPECTED RTOL SCALE [WHAT]")
def _near(value, expected, rtol, scale, what="value"):
    """|VALUE - EXPECTED| <= RTOL SCALE, with SCALE > 0."""
    if not near(number(value, what), number(expected, "EXPECTED"),
                number(rtol, "RTOL"), number(scale, "SCALE")):
        raise CheckError(f"{what}: {value} is not within {rtol} x {scale}"
                         f" of {expected}")


@command("sumsTo", "TOTAL RTOL PART...")
def _sums_to(total, rtol, *parts):
    """The parts add up to TOTAL > 0 to RTOL relative."""
    values = [number(p, "part") for p in parts]
    if not sums_to(number(total, "TOTAL"), number(rtol, "RTOL"), values):
        raise CheckError(f"{' + '.join(parts)} = {fmt(math.fsum(values))},"
                         f" not {total} to {rtol} relative (which must be "
                         "> 0)")


@command("between", "VALUE LOW HIGH [WHAT]")
def _between(value, low, high, what="value"):
    """LOW < VALUE < HIGH."""
    if not between(number(value, what), number(low, "LOW"),
                   number(high, "HIGH")):
        raise CheckError(f"{what}: {value} is not in ({low}, {high})")


@command("scaled", "VALUE FACTOR")
def _scaled(value, factor):
    """VALUE x FACTOR to 6 significant digits (a test's input)."""
    print("%.6g" % (number(value) * number(factor)))
