# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Reduced fibreFilter (coarse mesh, face velocities 0.1 and 2 m/s,
particles of 1 to 10 um on the fibre's own mesh, contact at the particle's
surface, 1000 parcels per diameter) against physical limits and against
the mesh-per-diameter runs it replaced, judged on the numbers of the files
it writes, with these tolerances:

- nothing lost: per sub-case U<U0>/particles and cloud (stick, adhesive),
  the captures and escapes per diameter are those of the model's impact
  records, and the parcels injected less the captured and escaped ones
  are the parcels the cloud holds at the end (its lagrangian files);
- no fallback: no impact where a parcel's centre reached the fibre first
  (surfaceContact.dat);
- stick, against the old way: the single-fibre efficiency of every
  diameter and face velocity equals that of the runs with one mesh per
  diameter, whose fibre was grown to (d_f + d)/2 with the flow mapped on it
  (tests/golden/fibreFilter/reduced, made at 188720e), within two binomial
  standard errors of the difference;
- stick, interception: at Stk < 0.1 (1, 1.5 and 2 um at 0.1 m/s) impaction
  of the particle's centre is nil (a point particle captured nothing
  there), so eta > 0 is interception; it must lie within a factor 2 of the
  Kuwabara correlations, eta_R/2 <= eta <= 2 (eta_R + eta_I) (Lee & Liu
  1982, Stechkina et al. 1969, as Hinds gives them; a row of fibres is not
  Kuwabara's cell, hence the factor), computed here by the package, to two
  binomial standard errors (1 um: a few captures in 1000 parcels);
- stick, geometry: no particle starting farther than (d_f + d)/2 from the
  fibre's axis can touch it (streamlines part around it, inertia keeps a
  particle straight), so eta <= (d_f + d)/d_f; at Stk 42 (10 um, 2 m/s)
  trajectories are nearly straight: eta >= 0.9 (d_f + d)/d_f; eta does not
  fall with Stk at a face velocity (all beyond 2 standard errors);
- adhesive never above stick (beyond 2 standard errors); equal at 0.1 m/s,
  where impacts are slower than the face velocity's 0.1 m/s scale and the
  critical speed of 10 um NH4-fluorescein is 0.41 m/s (impactCalc
  -critical); at 2 m/s, 5 and 10 um (critical speeds 1.14 and 0.41 m/s) at
  most half of stick: bounce;
- the table and the plots are written, the .foam files are there, no FOAM
  FATAL, no NaN.
"""

import math
import os

import pytest

from adhesivewall import correlations, foam, statistics, tables
from adhesivewall.tutorials import fibre_filter as fibre
from conftest import GOLDEN, fatal_logs, nan_files, run_tutorial


@pytest.fixture(scope="module")
def case():
    return run_tutorial("fibreFilter", "-reduced")


@pytest.fixture(scope="module")
def results(case):
    return tables.read(os.path.join(case, "results.csv"))


def test_runs_cleanly(case):
    assert fatal_logs(case) == []
    assert nan_files(case) == []
    for name in ("log.table", "efficiency.png", "angles.png", "angles.csv",
                 "fibreFilter.foam", "U2/U2.foam",
                 "U2/particles/particles.foam"):
        assert os.path.exists(os.path.join(case, name)), name


def test_every_sub_case(case, results):
    assert fibre.sub_cases(case) == [("U0.1/particles", "0.1"),
                                      ("U2/particles", "2")]
    diameters = ["1e-6", "1.5e-6", "2e-6", "3e-6", "5e-6", "7e-6", "10e-6"]
    for U in ("0.1", "2"):
        for cloud in fibre.CLOUDS:
            rows = results.where(U0=U, model=cloud)
            assert rows.text("d") == diameters, (U, cloud)
    assert len(results) == 28


@pytest.mark.parametrize("cloud", fibre.CLOUDS)
def test_nothing_lost(case, results, cloud):
    for sub, U in fibre.sub_cases(case):
        folder = os.path.join(case, sub)
        impacts = statistics.read_impacts(folder, cloud)
        rows = results.where(U0=U, model=cloud)
        for d, captured, escaped in zip(rows["d"], rows["captured"],
                                        rows["escaped"]):
            of = impacts.where(diameter=d)
            assert captured == len(of.where(outcome="capture")), (sub, d)
            assert escaped == len(of.where(outcome="escape")), (sub, d)
        assert rows.sum("airborne") == foam.parcel_count(folder, cloud=cloud)
        assert rows.sum("parcels") == rows.sum("captured") \
            + rows.sum("escaped") + rows.sum("airborne")


@pytest.mark.parametrize("cloud", fibre.CLOUDS)
def test_no_fallback(case, cloud):
    for sub, _ in fibre.sub_cases(case):
        contacts = tables.read(os.path.join(
            statistics.output_folder(os.path.join(case, sub), cloud),
            "surfaceContact.dat"))
        last = contacts.where(time=contacts["time"][-1])
        assert last.sum("surfaceContacts") > 0, sub
        assert last.sum("centreContacts") == 0, sub


def _rows(results):
    """Per (U0, d) in order: U0, d, Stk, R and each cloud's eta, SE."""
    rows = []
    for U, d in dict.fromkeys(zip(results.text("U0"), results.text("d"))):
        stick = results.where(U0=U, d=d, model="stick")
        adhesive = results.where(U0=U, d=d, model="adhesive")
        rows.append(dict(U=float(U), d=float(d), Stk=stick["Stk"][0],
                         R=stick["R"][0], stick=stick["eta"][0],
                         stickSE=stick["etaSE"][0],
                         adhesive=adhesive["eta"][0],
                         adhesiveSE=adhesive["etaSE"][0]))
    return rows


def test_interception_where_impaction_is_nil(case, results):
    alpha = float(foam.value("constant/parameters", "alpha", expand=False,
                             case=case))
    checked = 0
    for r in _rows(results):
        if r["Stk"] < 0.1:
            eta_R = correlations.interception(alpha, r["R"])
            eta_I = correlations.impaction(alpha, r["R"], r["Stk"])
            se = 2 * r["stickSE"]
            assert eta_R / 2 - se <= r["stick"] <= 2 * (eta_R + eta_I) + se, r
            checked += 1
    assert checked


def test_geometric_limits(results):
    rows = _rows(results)
    for i, r in enumerate(rows):
        limit = 1 + r["R"]
        assert r["stick"] <= limit + 2 * r["stickSE"], r
        if r["U"] == 2 and r["d"] == 10e-6:
            assert r["stick"] >= 0.9 * limit, r
        if i and rows[i - 1]["U"] == r["U"]:
            before = rows[i - 1]
            assert r["stick"] >= before["stick"] - 2 * math.hypot(
                r["stickSE"], before["stickSE"]), r


def test_bounce(results):
    seen = set()
    for r in _rows(results):
        assert r["adhesive"] <= r["stick"] + 2 * math.hypot(
            r["stickSE"], r["adhesiveSE"]), r
        if r["U"] == 0.1:
            assert r["adhesive"] == r["stick"], r
        if r["U"] == 2 and r["d"] in (5e-6, 10e-6):
            assert r["adhesive"] <= 0.5 * r["stick"], r
            seen.add(r["d"])
    assert seen == {5e-6, 10e-6}


def test_stick_as_with_one_mesh_per_diameter(results):
    old = tables.read(os.path.join(GOLDEN, "fibreFilter", "reduced",
                                   "results.csv"))
    compared = 0
    for U, d, model, eta, se in zip(old.text("U0"), old.text("d"),
                                    old.text("model"), old["eta"],
                                    old["etaSE"]):
        new = results.where(U0=U, d=d, model=model)
        assert len(new) == 1, (U, d, model)
        difference = new["eta"][0] - eta
        tolerance = 2 * math.hypot(new["etaSE"][0], se)
        print("%s m/s %s m %s: %.4g now, %.4g with one mesh per diameter"
              " (%+.4g, 2 SE %.3g)" % (U, d, model, new["eta"][0], eta,
                                       difference, tolerance))
        if model == "stick":
            assert abs(difference) <= tolerance, (U, d)
            compared += 1
    assert compared == 6
