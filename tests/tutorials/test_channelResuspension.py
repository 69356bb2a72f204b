# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Reduced channelResuspension (500 parcels of 10 and of 20 um, 7 steps of
u* from 0.2 to 3 m/s, 1 s each), judged on the numbers of the files it
writes:

- the flow of every step is the Couette flow u = (u*^2/nu) y at every
  cell centre and on the top wall (checked at the last step);
- every parcel is deposited on the floor in the first step, none anywhere
  else, and the deposit's count stays; the mass balance closes in every
  run (restart) and its resuspended mass is the statistics';
- every deposit touched the floor with its surface (the tutorial's
  adhesiveWallSurfaceContact), none fell back to contact at the centre;
- the library's fraction remaining after every step is within 4 binomial
  standard errors of the package's independent rock'n'roll
  (adhesivewall.resuspension, the same steps);
- against Reeks & Hall (2001): the u* of 50 % removal within the measured
  runs' spread widened by 20 %, the fraction remaining at 2 m/s within
  their spread widened by 0.05 (one run of 20 um: its own value). With
  the tutorial's gas (air, an assumption: README) the 10 um u* of 50 % is
  0.93 m/s against 0.57-0.86: an expected failure, strict, so that a
  change that fixes it is seen;
- nothing FATAL, no NaN, the table, the plot and the .foam file written.
"""

import glob
import math
import os

import pytest

from adhesivewall import curves, foam, statistics, tables
from adhesivewall.tutorials import channel_resuspension as channel
from conftest import PROJECT, fatal_logs, nan_files, run_tutorial

NAME = "channelResuspension"
PARCELS = 500


@pytest.fixture(scope="module")
def case():
    work = run_tutorial(NAME, "-reduced")
    assert fatal_logs(work) == []
    return work


def results_of(case):
    return tables.read(os.path.join(case, "results.csv"))


def curve(results, d):
    of = results.where(d=lambda v: float(v) == d)
    return list(of["ustar"]), list(of["remaining"]), of


def test_committed_tutorial_settings():
    path = os.path.join(PROJECT, "tutorials", NAME, "constant", "runSettings")
    assert foam.value(path, "variant") == "full"
    assert float(foam.value(path, "step")) == 1


def test_runs_cleanly(case):
    assert nan_files(case) == []
    for name in ("log.table", "remaining.png", "results.csv",
                 NAME + ".foam"):
        assert os.path.exists(os.path.join(case, name)), name


def test_the_flow_is_couette(case):
    box = channel.Channel(case)
    last = foam.latest_time(case)
    ustar = box.ustars[-1]
    shear = ustar * ustar / box.nu
    ny = int(foam.value("constant/parameters", "ny", case=case))
    field = foam.parse(foam.body(os.path.join(case, last, "U")))
    heights = sorted({round(u[0] / shear / box.H * ny - 0.5, 9)
                      for u in field["internalField"][-1]})
    # the cells' centres at (j + 1/2) H/ny, j = 0 .. ny-1, to round-off
    assert heights == pytest.approx(list(range(ny)), abs=1e-8)
    for u in field["internalField"][-1]:
        assert u[1] == 0 and u[2] == 0
    top = field["boundaryField"]["top"]["value"]
    assert top[0] == "uniform"
    assert top[1][0] == pytest.approx(shear * box.H, rel=1e-11)


def test_every_parcel_deposited_on_the_floor_and_kept(case):
    results = results_of(case)
    assert (results["deposited"] == PARCELS).all()
    box = channel.Channel(case)
    for time in box.end_times():
        rows = channel.rows_at(case, time)
        elsewhere = rows.where(patch=lambda p: p != channel.FLOOR)
        assert elsewhere.sum("captureParcels") == 0
        assert elsewhere.sum("resuspensionParcels") == 0
        assert rows.where(patch=channel.FLOOR).sum("captureParcels") == \
            2 * PARCELS


def test_every_deposit_touched_with_its_surface(case):
    folders = channel.statistics_folders(case)
    for folder in folders:
        contacts = tables.read(os.path.join(folder, "surfaceContact.dat"))
        assert statistics.final(contacts, "surfaceContacts",
                                patch=channel.FLOOR) == 2 * PARCELS, folder
        assert statistics.final(contacts, "centreContacts") == 0, folder


def test_mass_balance_closes_in_every_run(case):
    folders = channel.statistics_folders(case)
    assert len(folders) == len(channel.Channel(case).ustars)
    for folder in folders:
        balance = tables.read(os.path.join(folder, "massBalance.dat"))
        assert "resuspended" in balance
        for injected, residual in zip(balance["injected"],
                                      balance["residual"]):
            assert abs(residual) <= 1e-12 * injected
    # the last run's resuspended mass is the statistics' resuspensionMass
    end = channel.Channel(case).end_times()[-1]
    balance = tables.read(os.path.join(folders[-1], "massBalance.dat"))
    stats = channel.rows_at(case, end)
    assert balance.last_time()["resuspended"][0] == pytest.approx(
        stats.sum("resuspensionMass"), rel=1e-9)


@pytest.mark.parametrize("d", [10e-6, 20e-6])
def test_library_against_the_package_model(case, d):
    ustars, remaining, of = curve(results_of(case), d)
    assert len(ustars) == len(channel.Channel(case).ustars)
    for u, r, m in zip(ustars, remaining, of["model"]):
        se = math.sqrt(m * (1 - m) / PARCELS)
        assert abs(r - m) <= 4 * se + 1.0 / PARCELS, (d, u, r, m)
    assert remaining == sorted(remaining, reverse=True)
    assert remaining[0] > 0.8 and remaining[-1] < 0.05


def judged(case, d):
    runs = channel.measured_runs(os.path.join(case, channel.MEASURED))[d]
    ustars, remaining, _ = curve(results_of(case), d)
    return channel.judgement(ustars, remaining, runs), ustars, remaining


@pytest.mark.parametrize("d", [10e-6, 20e-6])
def test_remaining_at_two_metres_per_second_against_the_runs(case, d):
    j, ustars, remaining = judged(case, d)
    measured = [v for v in j["measuredAtCheck"].values() if v is not None]
    mine = curves.interpolate(2.0, ustars, remaining)
    assert min(measured) - 0.05 <= mine <= max(measured) + 0.05


def test_fifty_percent_of_20_um_against_run_8(case):
    j, ustars, remaining = judged(case, 20e-6)
    u50 = j["measuredU50"]["8"]
    assert 0.8 * u50 <= channel.resuspension.ustar_at_fraction(
        ustars, remaining) <= 1.2 * u50


@pytest.mark.xfail(strict=True, raises=AssertionError, reason=(
    "air (the tutorial's assumed gas): rock'n'roll with Biasi's fit removes "
    "half of the 10 um deposit at 0.93 m/s, run 10 at 0.715 (band 0.57-0.86)"
    "; with rho 1.92 it would pass and the remaining at 2 m/s fail (README)"))
def test_fifty_percent_of_10_um_against_run_10(case):
    j, ustars, remaining = judged(case, 10e-6)
    u50 = j["measuredU50"]["10"]
    assert 0.8 * u50 <= channel.resuspension.ustar_at_fraction(
        ustars, remaining) <= 1.2 * u50
