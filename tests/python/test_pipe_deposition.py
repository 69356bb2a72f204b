# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""pipeDeposition's own computations: the start positions uniform in the
pipe (Kolmogorov-Smirnov distances against the analytic CDFs: r^2/r_max^2
for the radius, uniform for the angle and along the axis; seeded, so
deterministic, and a sampler uniform in radius lies far beyond the bound),
tau+ against a hand calculation, the judged band and the verdict."""

import math

import pytest

from adhesivewall import correlations
from adhesivewall.tutorials import pipe_deposition as pipe
from ks import ks_bound, ks_distance

N = 20000
R_MAX, LENGTH = 6e-3, 2e-3


def test_positions_are_uniform_in_the_cylinder():
    points = pipe.uniform_pipe(N, R_MAX, LENGTH, seed=3)
    assert len(points) == N
    r = [math.hypot(x, y) for x, y, _ in points]
    theta = [math.atan2(y, x) for x, y, _ in points]
    z = [p[2] for p in points]
    assert max(r) < R_MAX and min(z) >= 0 and max(z) < LENGTH
    bound = ks_bound(N)
    assert ks_distance(r, lambda v: (v/R_MAX)**2) < bound
    assert ks_distance(theta, lambda v: (v + math.pi)/(2*math.pi)) < bound
    assert ks_distance(z, lambda v: v/LENGTH) < bound
    # uniform in radius instead: far beyond the bound
    assert ks_distance(r, lambda v: v/R_MAX) > 10*bound


def test_positions_are_reproducible_and_refuse_bad_input():
    assert pipe.uniform_pipe(5, R_MAX, LENGTH, 1) == \
        pipe.uniform_pipe(5, R_MAX, LENGTH, 1)
    assert pipe.uniform_pipe(5, R_MAX, LENGTH, 1) != \
        pipe.uniform_pipe(5, R_MAX, LENGTH, 2)
    with pytest.raises(ValueError):
        pipe.uniform_pipe(5, 0, LENGTH, 1)


class Gas:
    """The tutorial's pipe without a case: air, olive oil."""
    nu, viscosity, rhoP, meanFreePath = 1.5e-5, 1.8e-5, 920, 6.65e-8


def test_tau_plus_by_hand():
    # d 10 um: Kn = 2 x 6.65e-8/1e-5 = 0.0133, Cc = 1 + 0.0133 x 1.257
    # (the exponential's term e^-82.7 is nothing) = 1.0167181;
    # tau_p = 920 x 1e-10 x 1.0167181/(18 x 1.8e-5) = 2.88697e-4 s;
    # tau+ at u* 0.735 m/s: x 0.735^2/1.5e-5 = 10.3974
    tau_plus = pipe.Pipe.tau_plus(Gas(), 1e-5, 0.735)
    assert tau_plus == pytest.approx(10.3974, rel=1e-5)


def test_band_and_verdict():
    # tau+ 10: half of 3.5e-4 x 100 to twice 6e-4 x 100
    assert pipe.band(10) == pytest.approx((0.0175, 0.12))
    assert pipe.band(50) == (0.05, 0.25)
    assert pipe.band(25) is None and pipe.band(0.5) is None
    assert pipe.verdict("nearWallDispersion", 10, 0.05, 0.005)[1] == "pass"
    assert pipe.verdict("nearWallDispersion", 10, 0.15, 0.01)[1] == "FAIL"
    # a standard error above 15 % of V+ is not judged a pass
    assert pipe.verdict("nearWallDispersion", 10, 0.05, 0.008)[1] == \
        "(SE above 15 %)"
    assert pipe.verdict("nearWallDispersion", 10, 0.15, 0.03)[1] == \
        "FAIL (SE above 15 %)"
    assert pipe.verdict("none", 10, 0.5, 0.1) == (None, "-")


def test_correlations_as_published():
    # V+ = 6e-4 tau+^2 (Liu & Agarwal 1974), 3.5e-4 tau+^2 (Papavergos &
    # Hedley 1984)
    assert correlations.liu_agarwal(5) == pytest.approx(0.015)
    assert correlations.papavergos_hedley(5) == pytest.approx(0.00875)
    with pytest.raises(ValueError):
        correlations.liu_agarwal(-1)


def test_flow_checks_laws():
    from adhesivewall.tutorials import pipe_flow
    # Spalding's profile: U+ = y+ in the sublayer; its inverse at U+ 20,
    # y+ = 20 + e^-(0.41 5.2) (e^8.2 - 1 - 8.2 - 8.2^2/2 - 8.2^3/6)
    # = 20 + 0.11860 x 3506.2 = 435.8 (by hand)
    assert pipe_flow.spalding(0.1) == pytest.approx(0.1, rel=1e-3)
    assert pipe_flow.spalding(435.84) == pytest.approx(20, rel=1e-4)
    # Smooth-pipe friction at Re 1e4: Blasius 0.316/10 = 0.0316; the
    # Prandtl-Karman law's root, 0.0309 (Moody's chart)
    f = pipe_flow.friction_factors(1e4)
    values = sorted(f.values())
    assert f["Blasius, f = 0.316 Re^-1/4"] == pytest.approx(0.0316)
    pk = [v for k, v in f.items() if k.startswith("Prandtl")][0]
    assert pk == pytest.approx(0.0309, rel=2e-3)
    assert len(values) == 3


def test_wall_distance_to_the_polygon():
    # Against the distance to the line through the two vertices of the
    # face the point faces (vertices at 45 degrees + k 360/n on r = R)
    R, n = 1.0, 80
    width = 2*math.pi/n
    for angle, r in ((math.pi/4 + width/2, 0.5), (math.pi/4, 0.9),
                     (2.0, 0.99), (-3.0, 0.3)):
        point = (r*math.cos(angle), r*math.sin(angle), 0.0)
        k = math.floor((angle - math.pi/4)/width)
        a = [R*math.cos(math.pi/4 + k*width), R*math.sin(math.pi/4 + k*width)]
        b = [R*math.cos(math.pi/4 + (k + 1)*width),
             R*math.sin(math.pi/4 + (k + 1)*width)]
        edge = (b[0] - a[0], b[1] - a[1])
        cross = edge[0]*(point[1] - a[1]) - edge[1]*(point[0] - a[0])
        expected = abs(cross)/math.hypot(*edge)
        assert pipe.wall_distance([point], R, n)[0] == \
            pytest.approx(expected, rel=1e-12)


def test_profiles_chi2_by_hand():
    assert pipe.profiles_chi2(([10, 5], 100), ([10, 5], 100)) == (0.0, 2)
    # (0.1 - 0.2)^2/(10/100^2 + 20/100^2) = 0.01/0.003
    chi2, dof = pipe.profiles_chi2(([10, 0], 100), ([20, 0], 100))
    assert chi2 == pytest.approx(10/3) and dof == 1
