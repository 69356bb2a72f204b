# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Reduced microsphereImpact (40 parcels) against its references, judged on
the numbers of the files it writes, with these tolerances:

- every parcel's fate (captured or rebound) is the core's, and its rebound
  speed the core's to 1e-10 relative;
- per diameter, the paper's Figure 5 critical speed lies between the fastest
  captured and the slowest rebounding parcel (shot at 0.98 and 1.02 times
  it);
- per diameter, the parcels captured and rebounded on the plate in the
  model's statistics (one size class per diameter) are those of the impact
  records (results.csv);
- contact at the particle's surface: every impact on the plate happens
  with the sphere's centre d/2 above it (to 1e-9 d), none at the centre;
- the results are those of the awk post-processing this package replaced
  (tests/golden/microsphereImpact/reduced): surface contact changes where
  the impacts happen, not their velocities;
- the headline table, the plot and the .foam file are written, no FOAM
  FATAL, no NaN;
- the committed parcel tables are what microsphere_impact.parcel_rows makes
  of figure5.csv.
"""

import os

import pytest

from adhesivewall import statistics, tables
from adhesivewall.tutorials import microsphere_impact as microsphere
from conftest import (PROJECT, fatal_logs, golden_differences, nan_files,
                      run_tutorial)


@pytest.fixture(scope="module")
def case():
    return run_tutorial("microsphereImpact", "-reduced")


@pytest.fixture(scope="module")
def results(case):
    return tables.read(os.path.join(case, "results.csv"))


@pytest.fixture(scope="module")
def figure5():
    return tables.read(os.path.join(PROJECT, "tutorials", "microsphereImpact",
                                    "figure5.csv"))


def test_runs_cleanly(case):
    assert fatal_logs(case) == []
    assert nan_files(case) == []
    for name in ("log.table", "rebound.png", "microsphereImpact.foam"):
        assert os.path.exists(os.path.join(case, name)), name


def test_solver_equals_core(results):
    assert len(results) == 40
    assert (results["solverCaptured"] == results["coreCaptured"]).all()
    assert (results["relativeDifference"] <= 1e-10).all()


def test_capture_ends_at_figure5_speeds(results, figure5):
    for d, vc in zip(figure5["diameter"], figure5["criticalSpeed"]):
        of = results.where(diameter=lambda t, d=d: abs(float(t) / d - 1) < 1e-9)
        captured = of.where(solverCaptured="1")["speed"]
        rebound = of.where(solverCaptured="0")["speed"]
        assert len(captured) and len(rebound)
        assert captured.max() < vc < rebound.min(), d


def test_statistics_per_size_class_equal_records(case, results):
    last = statistics.read_statistics(case).last_time().where(patch="plate")
    assert len(last) == 4
    for lo, hi, captured, rebound in zip(
            last["dMin"], last["dMax"], last["captureParcels"],
            last["reboundParcels"]):
        of = results.where(diameter=lambda t: lo <= float(t) < hi)
        assert captured == len(of.where(solverCaptured="1"))
        assert rebound == len(of.where(solverCaptured="0"))


def test_impacts_where_the_surface_touches(case):
    impacts = statistics.read_impacts(case).where(patch="plate")
    assert len(impacts) == 40
    for z, d in zip(impacts["z"], impacts["diameter"]):
        assert abs(z - d / 2) <= 1e-9 * d, (z, d)
    contacts = statistics.read_surface_contacts(case)
    assert statistics.final(contacts, "surfaceContacts", patch="plate") == 40
    assert statistics.final(contacts, "centreContacts") == 0


def test_same_results_as_before_the_port(case):
    assert golden_differences(case, "microsphereImpact", "reduced") == []


@pytest.mark.parametrize("name, n", [("full", 24), ("reduced", 8)])
def test_committed_tables_are_made_from_figure5(figure5, name, n):
    path = os.path.join(PROJECT, "tutorials", "microsphereImpact", "constant",
                        "parcels." + name)
    committed = [line.strip() for line in open(path)
                 if line.lstrip().startswith("(") and ") (" in line]
    assert committed == microsphere.parcel_rows(figure5, n)
