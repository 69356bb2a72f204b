# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""tubeDiffusion's own computations: the flux-weighted start positions
against the analytic distribution of Poiseuille flow, and the verdict.

The sampler is judged by Kolmogorov-Smirnov distances: the largest
difference between the empirical CDF of n samples and the analytic one.
For n independent samples of the right distribution it exceeds
1.95/sqrt(n) with probability 0.001 (Kolmogorov's limit distribution); the
samples are seeded, so each test is deterministic, and a sampler of the
wrong distribution (uniform in area, say) lies far beyond the bound.
"""

import math
import os
import shutil

import pytest

from adhesivewall import curves, foam
from adhesivewall.tutorials import tube_diffusion as tube
from ks import ks_bound, ks_distance

N = 20000
R = 0.25e-3
KS_BOUND = ks_bound(N)            # P(D_n > bound) = 0.001


def radii(points):
    return [math.hypot(y, z) / R for y, z in points]


def test_poiseuille_flux_fraction():
    # F(s) = int_0^s 4 (1 - t^2) t dt: its ends and a midpoint by quadrature
    assert curves.poiseuille_flux_fraction(0) == 0
    assert curves.poiseuille_flux_fraction(1) == 1
    m = 100000
    quadrature = sum(4 * (1 - t * t) * t / m
                     for t in ((i + 0.5) / m * 0.6 for i in range(m))) * 0.6
    assert curves.poiseuille_flux_fraction(0.6) == pytest.approx(quadrature, rel=1e-9)


def test_radii_follow_the_flux():
    s = radii(tube.flux_weighted_disc(N, R, seed=1))
    assert max(s) < 1
    assert ks_distance(s, curves.poiseuille_flux_fraction) < KS_BOUND


def test_angles_are_uniform():
    points = tube.flux_weighted_disc(N, R, seed=2)
    angles = [(math.atan2(z, y) / (2 * math.pi)) % 1 for y, z in points]
    assert ks_distance(angles, lambda a: a) < KS_BOUND


@pytest.mark.parametrize("s_max", [0.8, math.cos(math.pi / 48)])
def test_radii_inside_a_smaller_circle_follow_the_conditional_flux(s_max):
    # 0.8: 13 % of the flux outside; cos(pi/48): the tutorial's wall
    # polygon's inscribed circle
    s = radii(tube.flux_weighted_disc(N, R, seed=3, r_max=s_max * R))
    assert max(s) < s_max
    F_max = curves.poiseuille_flux_fraction(s_max)
    assert ks_distance(s, lambda x: curves.poiseuille_flux_fraction(x) / F_max) < KS_BOUND


def test_the_distance_tells_flux_from_area_weighting():
    # The power of the test above: points uniform in area (s = sqrt(U))
    # are rejected by far (their distance to 2 s^2 - s^4 is about 0.25)
    import random
    rng = random.Random(4)
    s = [math.sqrt(rng.random()) for _ in range(N)]
    assert ks_distance(s, curves.poiseuille_flux_fraction) > 10 * KS_BOUND
    assert ks_distance(s, lambda x: x * x) < KS_BOUND


def test_mean_speed_of_the_parcels_is_the_flux_weighted_one():
    # <u> over the flux = int u^2 dA / int u dA = 4/3 Ubar
    s = radii(tube.flux_weighted_disc(N, R, seed=5))
    mean = sum(2 * (1 - x * x) for x in s) / N
    # the standard deviation of u/Ubar over the flux is sqrt(2)/3
    assert mean == pytest.approx(
        4 / 3, abs=4 * math.sqrt(2) / 3 / math.sqrt(N))


def test_seeded_and_reproducible():
    a = tube.flux_weighted_disc(100, R, seed=7)
    assert a == tube.flux_weighted_disc(100, R, seed=7)
    assert a != tube.flux_weighted_disc(100, R, seed=8)


def test_positions_file_is_read_back(tmp_path):
    points = tube.flux_weighted_disc(50, R, seed=9)
    path = tmp_path / "positions.d20nm"
    path.write_text(tube.positions_text("positions.d20nm", points, 9, R))
    read = foam.list_file(str(path))
    assert len(read) == 50
    for (x, y, z), (y0, z0) in zip(read, points):
        assert x == 0
        assert (y, z) == pytest.approx((y0, z0), rel=1e-11, abs=1e-18)


@pytest.mark.parametrize("outlet, airborne, expected", [
    (500, 0, "pass"),       # P 0.5 on the dot
    (530, 0, "pass"),       # 0.03 off, 3 SE = 0.047: within
    (560, 0, "fail"),       # 0.06 off: beyond 3 SE
    (500, 60, "fail"),      # the airborne ones could make it 0.56
    (490, 20, "pass"),      # 0.49 to 0.51
])
def test_verdict_counts_the_airborne_both_ways(outlet, airborne, expected):
    n = 1000
    se = math.sqrt(0.5 * 0.5 / n)
    assert tube.verdict(outlet, airborne, n, 0.5, se) == expected


def test_tolerance_is_the_larger_of_3_points_and_3_se():
    assert tube.tolerance(0.001) == 0.03
    assert tube.tolerance(0.02) == pytest.approx(0.06)


def test_the_tutorials_range_of_mu_spans_10_to_90_percent():
    # Gormley and Kennedy's penetration of the tutorial's smallest and
    # largest particles, its parameters read by foamDictionary
    case = os.path.join(os.path.dirname(__file__), "..", "..", "tutorials",
                        "tubeDiffusion")
    t = tube.Tube(case)
    assert t.nWall == 48
    penetrations = [tube.correlations.gormley_kennedy(t.mu(d))
                    for d in (20e-9, 300e-9)]
    assert penetrations[0] < 0.1 and penetrations[1] > 0.9


def test_random_walk_reference_meets_gormley_kennedy_at_fine_steps():
    # The numpy reference of the solver's sampling: at 1000 steps per
    # residence time within 0.02 of P(mu) (5000 particles: SE 0.0063)
    mu = 0.3
    P, airborne = tube.random_walk_penetration(mu, 5000, 1000, 1200)
    assert airborne == 0
    assert P == pytest.approx(tube.correlations.gormley_kennedy(mu), abs=0.02)


def test_random_walk_reference_misses_wall_contacts_at_coarse_steps():
    # 10 steps per residence time: excursions to the wall within a step
    # are missed, the penetration too high by far more than its error
    mu = 0.3
    P, _ = tube.random_walk_penetration(mu, 5000, 10, 1200)
    assert P > tube.correlations.gormley_kennedy(mu) + 0.05


def test_a_case_whose_parcels_settle_is_refused(tmp_path, monkeypatch):
    # Gormley and Kennedy's penetration is for diffusion alone: the
    # tutorial's own case feels no gravity; with gravity among its forces
    # and g set, the comparison stops in one line saying why
    source = os.path.join(os.path.dirname(__file__), "..", "..",
                          "tutorials", "tubeDiffusion")
    case = tmp_path / "tube"
    shutil.copytree(source, case)
    assert tube.settling_gravity(str(case)) == 0
    properties = case / "constant" / "kinematicCloudProperties"
    text = properties.read_text()
    assert "    exactBrownianMotion { T $T; seed 1; }\n" in text
    properties.write_text(text.replace(
        "    exactBrownianMotion { T $T; seed 1; }\n",
        "    exactBrownianMotion { T $T; seed 1; }\n    gravity;\n"))
    assert tube.settling_gravity(str(case)) == 0       # g is (0 0 0)
    g = case / "constant" / "g"
    g.write_text(g.read_text().replace("(0 0 0)", "(0 -9.81 0)"))
    assert tube.settling_gravity(str(case)) == pytest.approx(9.81, 1e-15)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit, match="the parcels settle .* 9.81"):
        tube.run(str(case))


def test_one_row_per_injector_or_a_stop_saying_why():
    # The tutorial has a size per injector: sizeClasses that split one are
    # not its case (said with the route to gradeEfficiency); no row at all
    # is another kind of stop
    from adhesivewall import tables
    from adhesivewall.tutorials import NotThisCase, stop
    grade = tables.Table(["injector", "dMin", "injectedParcels"],
                         [("1", "0", "5"), ("2", "0", "3"), ("2", "1e-6", "4")])
    assert tube.injector_row(grade, 1).sum("injectedParcels") == 5
    with pytest.raises(NotThisCase, match="2 rows of injector 2"):
        tube.injector_row(grade, 2)
    with pytest.raises(ValueError, match="no row of injector 3") as err:
        tube.injector_row(grade, 3)
    assert not isinstance(err.value, NotThisCase)
    assert "gradeEfficiency or sizeClasses" in str(
        stop("tubeDiffusion", NotThisCase("split"), "its case"))
    assert "gradeEfficiency or sizeClasses" not in str(
        stop("tubeDiffusion", FileNotFoundError("no file"), "its case"))
