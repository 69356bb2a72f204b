# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""settlingChannel (the whole tutorial: 20 s), judged on the
files it writes:

- the fraction of each diameter's parcels captured on the floor within
  three binomial standard errors plus 0.005 of min(1, v_s L/(U H)), the
  analytic settling in a channel (correlations.settling_channel, derived
  there; the 0.005 for what the formula leaves out: the particles'
  inertia, their radius at the floor, the Reynolds-number term of
  sphereDrag, the injection's start inside the first cell, the
  interpolated velocity's divergence: tutorial README), and rising with
  the diameter;
- every parcel accounted for: the floor's and the top's captures and the
  outlet's escapes make up the parcels injected, none airborne at the
  end, nothing through the inlet, the mass balance closed;
- every wall contact a contact at the surface (none a fallback), the
  deposits d/2 from their wall (but those injected closer to it, at the
  inlet);
- the cloud dictionary written out in full (no macro, no #include): the
  tutorial is the case to copy;
- no FOAM FATAL, no NaN, the tables and plots written;
- the comparison's command on a case that is not the tutorial's says so
  in words (no traceback).
"""

import os
import re

import pytest

from adhesivewall import statistics, tables
from conftest import PROJECT, fatal_logs, nan_files, run_tutorial

NAME = "settlingChannel"


@pytest.fixture(scope="module")
def tutorial():
    work = run_tutorial(NAME)
    assert fatal_logs(work) == []
    return work


@pytest.fixture(scope="module")
def case(tutorial):
    """The particle case."""
    return os.path.join(tutorial, "particles")


def test_runs_cleanly(tutorial, case):
    assert nan_files(tutorial) == []
    for name in ("results.csv", "log.table", "settling.png",
                 "gradeEfficiency.csv", "gradeEfficiency.png",
                 "particles.foam", "../flow/flow.foam"):
        assert os.path.exists(os.path.join(case, name)), name


def test_floor_captures_follow_the_settling(case):
    results = tables.read(os.path.join(case, "results.csv"))
    assert list(results["d"]) == [2e-6, 4e-6, 6e-6]
    # The predictions from the case's numbers, worked out by hand: v_s =
    # (2500 - 1.2041) d^2 9.81/(18 x 1.8133e-5) (mu = rhoInf nu), times
    # L/(U H) = 0.02/(0.1 x 1e-3)
    assert list(results["predicted"]) == pytest.approx(
        [0.060083, 0.24033, 0.54075], rel=1e-4)
    for d, eta, predicted, se in zip(results["d"], results["eta"],
                                     results["predicted"], results["etaSE"]):
        assert 0.05 < predicted < 0.95, (d, predicted)
        assert abs(eta - predicted) <= 3 * se + 0.005, (d, eta, predicted)
    assert list(results["eta"]) == sorted(results["eta"])


def test_every_parcel_accounted_for(case):
    stats = statistics.read_statistics(case)
    grade = statistics.read_grade_efficiency(case).last_time()
    injected = grade.sum("injectedParcels")
    assert injected == 15000
    captured = statistics.final(stats, "captureParcels")
    escaped = statistics.final(stats, "escapeParcels", patch="outlet")
    assert captured + escaped == injected
    assert statistics.final(stats, "impactParcels", patch="inlet") == 0
    assert grade.sum("airborneParcels") == 0
    balance = statistics.read_mass_balance(case).last_time()
    assert abs(balance["residual"][0]) <= 1e-12 * balance["injected"][0]


def test_contacts_at_the_surface(case):
    contacts = statistics.read_surface_contacts(case)
    assert statistics.final(contacts, "centreContacts") == 0
    impacts = statistics.read_impacts(case)
    height = 1e-3
    overlapping = 0
    for patch in ("floor", "top"):
        walls = impacts.where(patch=patch)
        assert len(walls) > 0
        for x, y, d in zip(walls["x"], walls["y"], walls["diameter"]):
            gap = y if patch == "floor" else height - y
            # a parcel that OpenFOAM's patchInjection placed closer to the
            # wall than d/2 (it places centres anywhere on the inlet's
            # faces, 0.1 to 0.5 of the way to the cell's centre) touches at
            # once, within the inlet's first cell (0.1 mm)
            if gap < d / 2 - 1e-3 * d and x < 1e-4:
                overlapping += 1
                continue
            assert abs(gap - d / 2) <= 1e-3 * d, (patch, x, y, d)
    # about the share of the inlet within d/2 of a wall, d/H of 5000
    assert overlapping <= 150


def test_cloud_dictionary_is_written_out(case):
    text = open(os.path.join(PROJECT, "tutorials", NAME, "particles",
                             "constant", "kinematicCloudProperties")).read()
    assert not re.search(r"#include|\$[\w:{]", text)


def test_comparison_refuses_another_case(tmp_path):
    # A folder without the run's outputs: one line naming what is missing,
    # without a traceback (a case the comparison does not apply to gets
    # what it needs: tests/python/test_tube_diffusion.py, stop)
    import subprocess
    result = subprocess.run(["adhesiveWallPost", "settlingChannel",
                             str(tmp_path)], capture_output=True, text=True)
    assert result.returncode == 1
    assert "statistics.dat: run ./Allrun" in result.stderr, result.stderr
    assert "Traceback" not in result.stderr
    missing = subprocess.run(["adhesiveWallPost", "settlingChannel",
                              str(tmp_path / "none")], capture_output=True,
                             text=True)
    assert missing.returncode == 1 and "Traceback" not in missing.stderr, \
        missing.stderr
