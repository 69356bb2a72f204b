# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""channelResuspension's own computations: the deposit's start positions,
the statistics read across the case's restarts, the measured runs and the
judgement against them (synthetic inputs with known answers; the tutorial
itself is run by tests/tutorials/test_channelResuspension.py).
"""

import os
import types

import pytest

from adhesivewall import resuspension, tables
from adhesivewall.tutorials import channel_resuspension as channel
from ks import ks_bound, ks_distance

PROJECT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASE = os.path.join(PROJECT, "tutorials", "channelResuspension")
BOX = types.SimpleNamespace(L=4e-3, W=1e-3, nx=8, nz=4)
N = 20000
KS_BOUND = ks_bound(N)            # P(D_n > bound) = 0.001


# --- The deposit's start positions ---------------------------------------------

def test_positions_above_the_inner_floor_faces():
    d = 20e-6
    points = channel.floor_positions(N, d, BOX, seed=1)
    assert len(points) == N
    assert all(y == channel.HEIGHT_FACTOR * d for _, y, _ in points)
    # within one cell of no edge: x in (L/nx, L - L/nx), z in (W/nz, W - W/nz)
    x0, z0 = BOX.L / BOX.nx, BOX.W / BOX.nz
    assert min(x for x, _, _ in points) > x0
    assert max(x for x, _, _ in points) < BOX.L - x0
    assert min(z for _, _, z in points) > z0
    assert max(z for _, _, z in points) < BOX.W - z0
    # uniform there
    assert ks_distance([(x - x0) / (BOX.L - 2 * x0) for x, _, _ in points],
                       lambda u: u) < KS_BOUND
    assert ks_distance([(z - z0) / (BOX.W - 2 * z0) for _, _, z in points],
                       lambda u: u) < KS_BOUND


def test_positions_reproducible_and_seeded():
    assert channel.floor_positions(10, 1e-5, BOX, 3) == \
        channel.floor_positions(10, 1e-5, BOX, 3)
    assert channel.floor_positions(10, 1e-5, BOX, 3) != \
        channel.floor_positions(10, 1e-5, BOX, 4)


# --- The statistics across restarts -----------------------------------------------

HEADER = ("# time\tpatch\tinjector\tdMin\tdMax\tcaptureParcels\t"
          "resuspensionParcels\n")


def write_statistics(case, start, rows):
    folder = os.path.join(case, "postProcessing", "lagrangian",
                          channel.CLOUD, "adhesiveWallInteraction", start)
    os.makedirs(folder)
    with open(os.path.join(folder, "statistics.dat"), "w") as f:
        f.write("# statistics, totals since the start of the case\n" + HEADER)
        for row in rows:
            f.write("\t".join(str(v) for v in row) + "\n")


def test_counts_at_the_end_of_each_hold(tmp_path):
    # two runs: 0 to 1 and 1 to 2 (a restart); the second's row at t = 1
    # (what the restart wrote first) replaces the first's
    case = str(tmp_path)
    write_statistics(case, "0", [
        (0.5, "floor", "all", 0, 1.5e-05, 100, 0),
        (0.5, "floor", "all", 1.5e-05, "inf", 100, 0),
        (1, "floor", "all", 0, 1.5e-05, 100, 3),
        (1, "floor", "all", 1.5e-05, "inf", 100, 20),
        (1, "outlet", "all", 0, 1.5e-05, 0, 0),
    ])
    write_statistics(case, "1", [
        (1, "floor", "all", 0, 1.5e-05, 100, 4),
        (1, "floor", "all", 1.5e-05, "inf", 100, 21),
        (2, "floor", "all", 0, 1.5e-05, 100, 30),
        (2, "floor", "all", 1.5e-05, "inf", 100, 70),
    ])
    write_statistics(case, "not-a-time", [])
    assert channel.deposit_counts(case, 10e-6, 1.0) == (100, 4)
    assert channel.deposit_counts(case, 20e-6, 1.0) == (100, 21)
    assert channel.deposit_counts(case, 20e-6, 2.0) == (100, 70)
    assert channel.deposit_counts(case, 10e-6, 0.5) == (100, 0)
    with pytest.raises(KeyError):
        channel.deposit_counts(case, 10e-6, 3.0)


# --- The measured runs and the judgement ------------------------------------------

def measured():
    return channel.measured_runs(os.path.join(CASE, channel.MEASURED))


def test_measured_runs():
    runs = measured()
    assert sorted(runs) == [10e-6, 20e-6]
    assert sorted(runs[10e-6]) == ["10", "15"]
    assert list(runs[20e-6]) == ["8"]
    for d in runs:
        for u, r in runs[d].values():
            assert u == sorted(u) and all(0 <= x <= 1 for x in r)


def test_measured_fifty_percent_and_two_metres_per_second():
    runs = measured()
    u, r = runs[10e-6]["10"]
    # run 10 falls through 0.5 between 0.699 (0.519) and 0.953 (0.212)
    assert resuspension.ustar_at_fraction(u, r) == pytest.approx(
        0.6990908 + (0.9526575 - 0.6990908) * (0.5189189 - 0.5)
        / (0.5189189 - 0.2121622), rel=1e-6)
    # run 15 starts below it (0.131 at 1.48 m/s): no 50 % point
    assert resuspension.ustar_at_fraction(*runs[10e-6]["15"]) is None


def test_judgement_of_the_measured_curve_itself_passes():
    for d, runs in measured().items():
        for u, r in runs.values():
            j = channel.judgement(u, r, runs)
            assert j["atCheckPass"]
            assert j["u50Pass"] or j["u50"] is None


def test_judgement_bands():
    runs = {"a": ([0.1, 1.0, 3.0], [1.0, 0.5, 0.0]),
            "b": ([0.1, 2.0, 3.0], [1.0, 0.1, 0.0])}
    # u50: a 1.0, b 0.1 + 1.9 * 0.5/0.9 = 1.156; at 2 m/s: a 0.25, b 0.1
    b50 = 0.1 + 1.9 * 0.5 / 0.9
    j = channel.judgement([0.1, 1.0, 2.0, 3.0], [1.0, 0.5, 0.3, 0.0], runs)
    assert j["u50Band"] == pytest.approx((0.8 * 1.0, 1.2 * b50))
    assert j["atCheckBand"] == pytest.approx((0.1 - 0.05, 0.25 + 0.05))
    assert j["u50"] == pytest.approx(1.0) and j["u50Pass"]
    assert j["atCheck"] == pytest.approx(0.3) and j["atCheckPass"]
    outside = channel.judgement([0.1, 1.45, 2.0], [1.0, 0.5, 0.31], runs)
    assert not outside["u50Pass"] and not outside["atCheckPass"]
    never = channel.judgement([0.1, 2.0], [1.0, 0.9], runs)
    assert never["u50"] is None and not never["u50Pass"]
