# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Reduced tubeDiffusion (0.02, 0.05 and 0.3 um, 400 parcels each), run
twice, judged on the numbers of the files it writes:

plumbing (forces plumbing: sphereDrag only, no Brownian motion), what
carries the parcels, independent of the Brownian force:
- the flow is 2 Ubar (1 - r^2/R^2) at every cell centre (to round-off);
- the times at which the parcels leave through the outlet follow those of
  flux-weighted injection into Poiseuille flow, F(t) = 1 - (t_r/(2 t))^2
  for t >= t_r/2, t_r = L/Ubar (a parcel at r takes L/u(r)): the
  Kolmogorov-Smirnov distance of the 1200 parcels within 1.95/sqrt(1200)
  (exceeded with probability 0.001) plus the time step's share;
- no parcel reaches the wall or goes back through the inlet, and those
  still airborne at the end are the ones the cloud holds.

brownian (the tutorial as committed: slipSphereDrag and
exactBrownianMotion), the physics:
- every diameter's penetration P = outlet/parcels within 0.03 or three
  binomial standard errors of Gormley and Kennedy's P(mu), whatever the
  parcels still airborne at the end would do; mu covers P 0.07 to 0.92;
- at most 0.5 % of the parcels still airborne at the end, none back
  through the inlet (Peclet numbers 2000 and more);
- the penetration rises with the diameter;
- every deposit is a contact at the surface (the tutorial's
  adhesiveWallSurfaceContact), none a fallback to the centre;
- nothing lost, the table, the plot and the .foam file written, no FOAM
  FATAL, no NaN.
"""

import math
import os
import shutil
import subprocess

import pytest

from adhesivewall import foam, statistics, tables
from adhesivewall.tutorials import tube_diffusion as tube
from conftest import PROJECT, fatal_logs, nan_files

NAME = "tubeDiffusion"
COLUMNS = ["d", "mu", "penetration", "penetrationSE", "gormleyKennedy"]


def run_with_forces(forces):
    """A copy of the tutorial with the forces given, run reduced, in
    $TEST_WORK_DIR/<forces> (else build/tests/work/tutorial.tubeDiffusion/
    <forces>)."""
    work = os.path.join(os.environ.get("TEST_WORK_DIR", os.path.join(
        PROJECT, "build", "tests", "work", "tutorial." + NAME)), forces)
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(os.path.join(PROJECT, "tutorials", NAME), work,
                    symlinks=True)
    subprocess.run(["foamDictionary", "constant/particleSettings", "-entry",
                    "forces", "-set", forces], cwd=work, check=True,
                   stdout=subprocess.DEVNULL)
    with open(os.path.join(work, "log.Allrun"), "w") as log:
        result = subprocess.run(["./Allrun", "-reduced"], cwd=work,
                                stdout=log, stderr=subprocess.STDOUT)
    output = open(os.path.join(work, "log.Allrun")).read()
    if result.returncode != 0 or fatal_logs(work):
        logs = "".join(open(p).read()[-1500:] for p in fatal_logs(work))
        pytest.fail(f"{NAME} ({forces}): Allrun -reduced failed:\n"
                    + output[-2000:] + logs)
    return work


@pytest.fixture(scope="module")
def plumbing():
    return run_with_forces("plumbing")


@pytest.fixture(scope="module")
def brownian():
    return run_with_forces("brownian")


def results_of(case):
    return tables.read(os.path.join(case, "results.csv"))


def test_committed_tutorial_has_brownian_motion():
    settings = os.path.join(PROJECT, "tutorials", NAME, "constant",
                            "particleSettings")
    assert foam.value(settings, "forces") == "brownian", \
        "constant/particleSettings: forces plumbing, not brownian"
    assert foam.value(settings, "variant") == "full"


# --- plumbing: the flow, the injection, the counting -------------------------

def test_plumbing_flow_is_poiseuille(plumbing):
    assert tube.poiseuille_deviation(tube.Tube(plumbing), plumbing) < 1e-9


def test_plumbing_nothing_lost_nothing_deposited(plumbing):
    results = results_of(plumbing)
    assert results.sum("deposited") == 0
    assert results.sum("inlet") == 0
    assert (results["parcels"] == 400).all()
    assert results.sum("airborne") == foam.parcel_count(plumbing)


def test_plumbing_transit_times_are_those_of_poiseuille_flow(plumbing):
    t = tube.Tube(plumbing)
    residence = t.L / t.Ubar
    dt = float(foam.value("system/controlDict", "deltaT", case=plumbing))
    outlet = statistics.read_statistics(plumbing).where(patch="outlet")
    times = sorted(set(outlet["time"]))
    escaped = {time: 0.0 for time in times}
    for time, n in zip(outlet["time"], outlet["escapeParcels"]):
        escaped[time] += n
    parcels = results_of(plumbing).sum("parcels")

    def F(time):
        return max(0.0, 1 - (residence / (2 * time)) ** 2)
    # a parcel is counted at the end of the step it leaves in (and moves
    # at U0 in its first): F's largest change over two steps, 8 dt/t_r
    bound = 1.95 / math.sqrt(parcels) + 8 * dt / residence
    distance = max(abs(escaped[time] / parcels - F(time)) for time in times)
    assert distance < bound
    assert escaped[times[-1]] / parcels == pytest.approx(
        F(times[-1]), abs=bound)


# --- brownian: the physics ---------------------------------------------------

def test_runs_cleanly(brownian):
    assert nan_files(brownian) == []
    for name in ("log.table", "penetration.png", "results.csv",
                 NAME + ".foam"):
        assert os.path.exists(os.path.join(brownian, name)), name
    assert tube.poiseuille_deviation(tube.Tube(brownian), brownian) < 1e-9


def test_columns_and_diameters(brownian):
    results = results_of(brownian)
    for name in COLUMNS:
        assert name in results
    assert list(results["d"]) == [20e-9, 50e-9, 300e-9]
    gk = results["gormleyKennedy"]
    assert gk[0] < 0.1 and gk[-1] > 0.9


def test_nothing_lost(brownian):
    results = results_of(brownian)
    assert (results["parcels"] == results["deposited"] + results["outlet"]
            + results["inlet"] + results["airborne"]).all()
    assert results.sum("airborne") == foam.parcel_count(brownian)


def test_few_airborne_none_back_through_the_inlet(brownian):
    results = results_of(brownian)
    assert results.sum("inlet") == 0
    assert (results["airborne"] <= 0.005 * results["parcels"]).all()


def test_penetration_against_gormley_kennedy(brownian):
    results = results_of(brownian)
    for row in range(len(results)):
        def v(name, row=row):
            return results[name][row]
        within = max(0.03, 3 * v("penetrationSE"))
        low = v("outlet") / v("parcels")
        high = (v("outlet") + v("airborne")) / v("parcels")
        assert abs(low - v("gormleyKennedy")) <= within, v("d")
        assert abs(high - v("gormleyKennedy")) <= within, v("d")
        assert results.text("verdict")[row] == "pass"


def test_penetration_rises_with_diameter(brownian):
    results = results_of(brownian)
    p, se = results["penetration"], results["penetrationSE"]
    for i in range(1, len(results)):
        assert p[i] > p[i - 1] - 2 * math.hypot(se[i], se[i - 1])


def test_every_deposit_touched_with_its_surface(brownian):
    contacts = statistics.read_surface_contacts(brownian)
    deposited = results_of(brownian).sum("deposited")
    assert deposited > 0
    assert statistics.final(contacts, "surfaceContacts",
                            patch="wall") == deposited
    assert statistics.final(contacts, "centreContacts") == 0
