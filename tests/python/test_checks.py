# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The case tests' checks (adhesivewall.checks) on small files whose answers
are worked out by hand here, and the benchmark's figures."""

import math

import pytest

from adhesivewall import checks
from adhesivewall.checks import CheckError

HEADER = "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"

COLUMNS = ("time patch injector dMin dMax impactParcels impactParticles "
           "impactMass reboundParcels reboundParticles reboundMass "
           "captureParcels captureParticles captureMass escapeParcels "
           "escapeParticles escapeMass reboundSpeed reboundAngle captureSpeed "
           "captureAngle").split()


def statistics_file(path, rows):
    """A statistics.dat of the rows (dicts of some columns; the others 0)."""
    lines = ["# adhesiveWallInteraction statistics of cloud kinematicCloud",
             "# " + "\t".join(COLUMNS)]
    for row in rows:
        values = {"injector": "all", "dMin": "0", "dMax": "inf", **row}
        lines.append("\t".join(str(values.get(c, 0)) for c in COLUMNS))
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def run(capsys, *argv):
    """adhesiveWallPost check ARGV: (exit status, stdout, stderr)."""
    status = checks.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return status, out.strip(), err.strip()


# An earlier time that must not count, then the last time: floor with two
# injectors in two size classes, ceiling
ROWS = [
    {"time": "1e-05", "patch": "floor", "captureParcels": 9},
    {"time": "1e-05", "patch": "ceiling", "captureParcels": 9},
    {"time": "2e-05", "patch": "floor", "injector": "1", "dMin": "0",
     "dMax": "4e-06", "captureParcels": 1, "captureMass": 1.5e-14,
     "reboundSpeed": 2.5},
    {"time": "2e-05", "patch": "floor", "injector": "1", "dMin": "4e-06",
     "dMax": "inf", "captureParcels": 2, "captureMass": 2.5e-14},
    {"time": "2e-05", "patch": "floor", "injector": "2", "dMin": "0",
     "dMax": "4e-06", "captureParcels": 4, "escapeMass": 1e-13},
    {"time": "2e-05", "patch": "floor", "injector": "2", "dMin": "4e-06",
     "dMax": "inf", "captureParcels": 8},
    {"time": "2e-05", "patch": "ceiling", "injector": "1",
     "escapeParcels": 3},
]


@pytest.fixture
def stats(tmp_path):
    return statistics_file(tmp_path / "statistics.dat", ROWS)


#------------------------------------------------------------------------------
# Numbers

def test_fmt_shortest_exact():
    assert checks.fmt(15.0) == "15"
    assert checks.fmt(-0.0) == "0"
    assert checks.fmt(0.1 + 0.2) == "0.30000000000000004"
    assert checks.fmt(3.5e-14) == "3.5e-14"
    assert float(checks.fmt(0.1 + 0.2)) == 0.1 + 0.2
    assert checks.fmt(1e20) == "1e+20"


def test_close_small_between_sums():
    assert checks.close(1 + 1e-13, 1, 1e-12)
    assert not checks.close(1 + 1e-11, 1, 1e-12)
    assert checks.close(-2.0000001, -2, 1e-7)
    # An expected 0 asks for exactly 0
    assert checks.close(0.0, 0, 1e-12)
    assert not checks.close(1e-300, 0, 1e-12)
    assert not checks.close(float("nan"), 1, 1)
    assert checks.small(-1e-25, 1e-12, 1e-12)
    assert not checks.small(2e-24, 1e-12, 1e-12)
    # No scale, nothing to compare with
    assert not checks.small(0, 1e-12, 0)
    # 2.48010025e-4 m against 2.4801e-4 m: 2.5e-11 m, 1.25e-6 of 20 um
    assert checks.near(2.48010025e-4, 2.4801e-4, 2e-6, 20e-6)
    assert not checks.near(2.48010025e-4, 2.4801e-4, 1e-6, 20e-6)
    assert not checks.near(1, 1, 1, 0)
    assert checks.between(0.5, 0, 1)
    assert not checks.between(0, 0, 1)
    assert checks.between(1e300, 0, float("inf"))
    # 1.0 = 0.25 + 0.5 + 0.25 exactly; 1 part in 1e10 missing is not 1e-12
    assert checks.sums_to(1.0, 0, [0.25, 0.5, 0.25])
    assert not checks.sums_to(1.0, 1e-12, [0.25, 0.5, 0.25 - 1e-10])
    assert not checks.sums_to(0.0, 1e-12, [0.0])


def test_median_mean_deviation():
    assert checks.median([3, 1, 2]) == 2
    assert checks.median([4, 1, 3, 2]) == 2.5
    m, sd = checks.mean_and_deviation([2, 4, 4, 4, 5, 5, 7, 9])
    # mean 5, squares of deviations 32 over n - 1 = 7
    assert m == 5 and sd == pytest.approx(math.sqrt(32 / 7), rel=1e-15)
    assert checks.mean_and_deviation([3.0]) == (3.0, 0.0)
    with pytest.raises(CheckError):
        checks.median([])


#------------------------------------------------------------------------------
# statistics.dat and massBalance.dat

def test_statistic_sums_at_the_last_time(stats):
    # 1 + 2 + 4 + 8 on the floor at 2e-05 (the 9 of 1e-05 left out)
    assert checks.statistic(stats, "captureParcels", "floor") == 15
    assert checks.statistic(stats, "captureParcels") == 15
    assert checks.statistic(stats, "captureParcels", "floor", "1") == 3
    # dMin by number: 4e-6 is the 4e-06 written
    assert checks.statistic(stats, "captureParcels", "floor", "", "4e-6") == 10
    assert checks.statistic(stats, "captureParcels", "floor", "2", "0") == 4
    assert checks.statistic(stats, "captureMass", "floor") == 4e-14
    assert checks.statistic(stats, "escapeParcels", "ceiling") == 3


def test_statistic_fails_on_nothing(stats, tmp_path):
    with pytest.raises(CheckError, match="no rows of patch 'sides'"):
        checks.statistic(stats, "captureParcels", "sides")
    with pytest.raises(CheckError, match="no column 'capturedParcels'"):
        checks.statistic(stats, "capturedParcels", "floor")
    empty = statistics_file(tmp_path / "empty.dat", [])
    with pytest.raises(CheckError):
        checks.statistic(empty, "captureParcels")
    with pytest.raises(CheckError):
        checks.statistic_rows(empty)


def test_statistic_rows(stats):
    assert checks.statistic_rows(stats) == 5
    assert checks.statistic_rows(stats, "floor") == 4
    assert checks.statistic_rows(stats, "sides") == 0


def test_compare_statistics(stats, tmp_path):
    same = statistics_file(tmp_path / "same.dat", list(reversed(ROWS[2:])))
    assert checks.compare_statistics(stats, same) == []
    # A mean speed 1e-6 off passes at 1e-5, not at 1e-12; a count 1e-10
    # off does not pass at any mean tolerance
    rows = [dict(r) for r in ROWS]
    rows[2]["reboundSpeed"] = 2.5 * (1 + 1e-6)
    mean = statistics_file(tmp_path / "mean.dat", rows)
    assert checks.compare_statistics(stats, mean, 1e-5) == []
    problems = checks.compare_statistics(stats, mean)
    assert len(problems) == 1 and "reboundSpeed" in problems[0]
    rows[2]["captureMass"] = 1.5e-14 * (1 + 1e-10)
    count = statistics_file(tmp_path / "count.dat", rows)
    problems = checks.compare_statistics(stats, count, 1e-5)
    assert len(problems) == 1 and "floor 1 0 4e-06 captureMass" in problems[0]


def test_compare_statistics_rows_and_times(stats, tmp_path):
    fewer = statistics_file(tmp_path / "fewer.dat", ROWS[:-1])
    assert "ceiling 1 0 inf" in checks.compare_statistics(stats, fewer)[0]
    later = [dict(r, time="3e-05") for r in ROWS[2:]]
    later = statistics_file(tmp_path / "later.dat", later)
    assert "last time" in checks.compare_statistics(stats, later)[0]
    empty = statistics_file(tmp_path / "empty.dat", [])
    assert "no statistics" in checks.compare_statistics(empty, empty)[0]


def test_compare_totals(stats, tmp_path):
    # The same run without injectors and size classes: floor 15 captures,
    # 4e-14 kg captured, 1e-13 kg escaped; ceiling 3 escapes
    total = statistics_file(tmp_path / "total.dat", [
        {"time": "2e-05", "patch": "floor", "captureParcels": 15,
         "captureMass": 4e-14, "escapeMass": 1e-13},
        {"time": "2e-05", "patch": "ceiling", "escapeParcels": 3}])
    columns = ["captureParcels", "captureMass", "escapeMass", "escapeParcels"]
    n, problems = checks.compare_totals(total, stats, columns)
    assert (n, problems) == (8, [])
    wrong = statistics_file(tmp_path / "wrong.dat", [
        {"time": "2e-05", "patch": "floor", "captureParcels": 14},
        {"time": "2e-05", "patch": "ceiling", "escapeParcels": 3}])
    n, problems = checks.compare_totals(wrong, stats, ["captureParcels"])
    assert problems == [f"floor captureParcels: 14 in {wrong}, summed 15 in "
                        f"{stats}"]
    one = statistics_file(tmp_path / "one.dat", [
        {"time": "2e-05", "patch": "floor", "captureParcels": 15}])
    assert checks.compare_totals(one, stats, columns)[1]
    assert checks.compare_totals(total, stats, [])[1]


def test_time_range_and_mass_balance(tmp_path):
    balance = tmp_path / "massBalance.dat"
    balance.write_text(
        "# adhesiveWallInteraction mass balance of cloud kinematicCloud\n"
        "# time\tinjected\tinitial\tairborne\tcaptured\tescaped\tresidual\n"
        "0.0005\t1e-12\t0\t5e-13\t5e-13\t0\t0\n"
        "0.001\t1.5e-12\t0\t5e-13\t6e-13\t4e-13\t-1e-27\n")
    assert checks.time_range(balance) == ("0.0005", "0.001")
    last = checks.mass_balance(balance)
    assert (last["injected"], last["residual"]) == ("1.5e-12", "-1e-27")
    empty = tmp_path / "empty.dat"
    empty.write_text("# time\tinjected\tresidual\n")
    with pytest.raises(CheckError):
        checks.mass_balance(empty)
    with pytest.raises(CheckError):
        checks.time_range(empty)


#------------------------------------------------------------------------------
# Other tables

RECORDS = ("time,patch,face,x,y,z,diameter,nParticle,un,ut,outcome,R,WA,"
           "unOut,utOut\n"
           "1e-5,floor,3,0,0,0,2.58e-06,1,3,0.1,capture,0.9,-1e-13,0,0\n"
           "2e-5,floor,4,0,0,0,2.58e-06,1,3.5,0.1,rebound,0.8,-1e-13,1.2,"
           "0.05\n"
           "3e-5,ceiling,1,0,0,0,4.9e-06,1,1,0,rebound,0.7,0,0.7,0\n"
           "# capped at maxImpactRecords = 3: later impacts are not "
           "recorded\n")


def test_table_rows_columns_and_replace(tmp_path):
    records = tmp_path / "impacts.csv"
    records.write_text(RECORDS)
    assert checks.table_rows(records, ["patch", "outcome"]) == 3
    with pytest.raises(CheckError, match="no column 'result'"):
        checks.table_rows(records, ["result"])
    assert checks.columns(records, ["outcome", "diameter"]) == [
        ("capture", "2.58e-06"), ("rebound", "2.58e-06"),
        ("rebound", "4.9e-06")]
    # Rows of one patch, and rows ordered by a number, not by its text
    # ("3" sorts after "10" as text)
    assert checks.columns(records, ["time", "un"], {"patch": "floor"}) == [
        ("1e-5", "3"), ("2e-5", "3.5")]
    assert checks.columns(records, ["patch"], sort_by="un") == [
        ("ceiling",), ("floor",), ("floor",)]
    unordered = tmp_path / "unordered.csv"
    unordered.write_text("time,patch\n10,a\n3,a\n2e-1,b\n")
    assert checks.columns(unordered, ["time"], {"patch": "a"}, "time") == [
        ("3",), ("10",)]
    with pytest.raises(KeyError, match="no column 'wall'"):
        checks.columns(records, ["un"], {"wall": "floor"})
    # Sorting by a text or a NaN names the column
    with pytest.raises(CheckError, match="sort column 'patch' value 'floor'"):
        checks.columns(records, ["un"], sort_by="patch")
    unordered.write_text("time,patch\n10,a\nnan,a\n")
    with pytest.raises(CheckError, match="a NaN in sort column 'time'"):
        checks.columns(unordered, ["patch"], sort_by="time")
    data = tmp_path / "data.csv"
    data.write_text("diameter,speedIn,speedOut\n1e-6,1,0.5\n2e-6,3,2\n")
    assert checks.replace_value(data, 2, "speedIn", "1 2") == [
        "diameter,speedIn,speedOut", "1e-6,1,0.5", "2e-6,1 2,2"]
    assert checks.replace_value(data, 1, "speedOut", "")[1] == "1e-6,1,"
    with pytest.raises(CheckError):
        checks.replace_value(data, 3, "speedIn", "0")
    with pytest.raises(CheckError):
        checks.replace_value(data, 1, "speed", "0")


def test_critical_speed_outcomes(tmp_path):
    records = tmp_path / "impacts.csv"
    records.write_text(RECORDS)
    # 2.58 um: critical 3.141 m/s: un 3 captured, un 3.5 rebounds
    lines, problems = checks.critical_speed_outcomes(
        records, "floor", {2.58e-6: 3.141}, 2)
    assert problems == [] and len(lines) == 2
    assert lines[0] == ("d = 2.58e-06 m, un = 3 m/s, critical 3.141 m/s: "
                        "capture")
    # At a critical speed of 2.9 m/s the capture is wrong
    _, problems = checks.critical_speed_outcomes(
        records, "floor", {2.58e-6: 2.9}, 2)
    assert problems == [
        "d = 2.58e-06 m, un = 3 m/s: capture, expected rebound"]
    _, problems = checks.critical_speed_outcomes(
        records, "floor", {2.58e-6: 3.141}, 8)
    assert problems == ["expected 8 impacts on floor, got 2"]
    _, problems = checks.critical_speed_outcomes(
        records, "ceiling", {2.58e-6: 3.141}, 1)
    assert problems == ["d = 4.9e-06 m: no critical speed given"]


#------------------------------------------------------------------------------
# OpenFOAM's files

MASS_STICK = HEADER % ("volScalarField", "kinematicCloud:massStick") + """
dimensions [1 0 0 0 0 0 0];
internalField uniform 0;
boundaryField
{
    floor
    {
        type calculated; value nonuniform List<scalar> 3(1e-14 0 2.5e-14);
    }
    ceiling
    {
        type            calculated;
        value           nonuniform List<scalar>
2
(
1e-13
3e-13
)
;
    }
    sides { type calculated; value uniform 0; }
    frontAndBack { type empty; }
}
"""


def test_boundary_sum(tmp_path):
    field = tmp_path / "massStick"
    field.write_text(MASS_STICK)
    assert checks.boundary_sum(field, ["floor"]) == 3.5e-14
    assert checks.boundary_sum(field, ["ceiling", "sides"]) == 4e-13
    assert checks.boundary_sum(field) == pytest.approx(4.35e-13, rel=1e-15)
    with pytest.raises(CheckError, match="no boundary values on roof"):
        checks.boundary_sum(field, ["roof"])
    field.write_text(MASS_STICK.replace("value uniform 0", "value uniform 2"))
    with pytest.raises(CheckError, match="uniform 2 on sides"):
        checks.boundary_sum(field)
    assert checks.boundary_sum(field, ["floor"]) == 3.5e-14
    field.write_text(HEADER % ("volScalarField", "m") + "boundaryField {}\n")
    with pytest.raises(CheckError, match="no boundary values"):
        checks.boundary_sum(field)


def test_boundary_min(tmp_path):
    field = tmp_path / "massStick"
    field.write_text(MASS_STICK.replace("3(1e-14 0 2.5e-14)",
                                        "3(1e-14 -2e-15 2.5e-14)"))
    assert checks.boundary_min(field, ["floor"]) == -2e-15
    assert checks.boundary_min(field, ["ceiling"]) == 1e-13
    assert checks.boundary_min(field, ["sides"]) == 0
    assert checks.boundary_min(field) == -2e-15
    with pytest.raises(CheckError, match="no boundary values on roof"):
        checks.boundary_min(field, ["roof"])


def test_compare_fields(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    a.write_text(MASS_STICK)
    b.write_text(MASS_STICK.replace("2.5e-14", "2.5000001e-14"))
    # dimensions (7), uniform 0, 3, three values, 2, two values, 0
    assert len(checks.field_numbers(a)) == 16
    assert checks.compare_fields(a, a) == []
    assert checks.compare_fields(a, b, 1e-7) == []
    problems = checks.compare_fields(a, b)
    assert len(problems) == 1 and "2.5e-14" in problems[0]
    b.write_text(MASS_STICK.replace("3(1e-14 0 2.5e-14)", "2(1e-14 0)"))
    assert "16 numbers" in checks.compare_fields(a, b)[0]
    a.write_text(HEADER % ("dictionary", "x") + "a b;\n")
    assert "no numbers" in checks.compare_fields(a, a)[0]


def test_lagrangian_fields(tmp_path):
    U = tmp_path / "U"
    U.write_text(HEADER % ("vectorField", "U")
                 + "2\n(\n(1 2 3)\n(0.4 -0.2 1e-3)\n)\n")
    assert checks.lagrangian_values(U) == [1, 2, 3, 0.4, -0.2, 1e-3]
    assert checks.last_vector(U) == [0.4, -0.2, 1e-3]
    n = tmp_path / "nParticle"
    n.write_text(HEADER % ("scalarField", "nParticle") + "3{2}\n")
    assert checks.lagrangian_values(n) == [2, 2, 2]
    with pytest.raises(CheckError, match="not a vector"):
        checks.last_vector(n)
    n.write_text(HEADER % ("vectorField", "U") + "0()\n")
    with pytest.raises(CheckError, match="no parcels"):
        checks.last_vector(n)
    # A positions file of the v1706 form: '(x y z) cell' a parcel
    positions = tmp_path / "positions"
    positions.write_text(HEADER % ("Cloud<passiveParticle>", "positions")
                         + "2\n(\n(1 2 3) 4\n(5e-4 6 7) 10\n)\n")
    assert checks.last_vector(positions) == [5e-4, 6, 7]


def test_compare_vectors():
    # Scale: the largest expected component, 2
    assert checks.compare_vectors([1, 2, 0], [1 + 1e-11, 2, 1.5e-11],
                                  1e-11) == []
    problems = checks.compare_vectors([1, 2, 0], [1, 2, 3e-11], 1e-11)
    assert len(problems) == 1 and problems[0].startswith("component 2")
    assert checks.compare_vectors([0, 0, 0], [0, 0, 0], 1)
    assert checks.compare_vectors([1, 2], [1, 2], 1)


def write_cloud(folder, d, n, rho):
    folder.mkdir(parents=True)
    for name, values in (("d", d), ("nParticle", n), ("rho", rho)):
        (folder / name).write_text(
            HEADER % ("scalarField", name)
            + f"{len(values)}\n(\n" + "\n".join(map(str, values)) + "\n)\n")


# The diameter of a sphere of volume 1e-18 m^3
D1 = (6e-18 / math.pi) ** (1 / 3)


def test_cloud_mass(tmp_path):
    # Volumes 1e-18 and 8e-18 m^3 (twice the diameter): 2 x 1000 x 1e-18 +
    # 3 x 1500 x 8e-18 = 3.8e-14 kg
    write_cloud(tmp_path / "0.001" / "lagrangian" / "kinematicCloud",
                [D1, 2 * D1], [2, 3], [1000, 1500])
    assert checks.cloud_mass(str(tmp_path / "0.001")) == \
        pytest.approx(3.8e-14, rel=1e-14)
    (tmp_path / "0.002").mkdir()
    assert checks.cloud_mass(str(tmp_path / "0.002")) == 0
    with pytest.raises(CheckError, match="no time folder"):
        checks.cloud_mass(str(tmp_path / "0.003"))
    write_cloud(tmp_path / "0.004" / "lagrangian" / "kinematicCloud",
                [D1, D1], [1], [1000, 1000])
    with pytest.raises(CheckError):
        checks.cloud_mass(str(tmp_path / "0.004"))


def test_settling_velocity_needs_every_parcel(tmp_path):
    # Two parcels at the settling velocity of their own diameters (Stokes
    # with Davies' slip, from the package's correlations); a rho file of
    # one parcel only is a failure, not a check of the first parcel
    from adhesivewall import aerosol
    folder = tmp_path / "1" / "lagrangian" / "kinematicCloud"
    write_cloud(folder, [1e-6, 2e-6], [1, 1], [1000, 1000])
    v = [aerosol.settling_velocity(d, 1000, 1.2, 1.8e-5, 9.81, 66.5e-9,
                                   "Davies") for d in (1e-6, 2e-6)]
    (folder / "U").write_text(
        HEADER % ("vectorField", "U")
        + f"2\n(\n(0 0 {-v[0]!r})\n(0 0 {-v[1]!r})\n)\n")
    args = ["settlingVelocity", tmp_path, 1.2, 1.8e-5, 9.81, 66.5e-9]
    assert checks.main([str(a) for a in args]) == 0
    (folder / "rho").write_text(HEADER % ("scalarField", "rho")
                                + "1\n(\n1000\n)\n")
    with pytest.raises(CheckError, match="2 velocities, 2 diameters and "
                                         "1 densities"):
        checks._settling_velocity(str(tmp_path), "1.2", "1.8e-5", "9.81",
                                  "66.5e-9")


INJECTOR = """
%s
{
    type            manualInjection;
    massTotal       0;
    parcelBasisType fixed;
    nParticle       %d;
    SOI             0;
    positionsFile   "positions_%s";
    U0              (0 0 -1);
    sizeDistribution
    {
        type        fixedValue;
        fixedValueDistribution { value %r; }
    }
}
"""


@pytest.fixture
def case(tmp_path):
    (tmp_path / "constant").mkdir()
    (tmp_path / "system").mkdir()
    (tmp_path / "constant" / "kinematicCloudProperties").write_text(
        HEADER % ("dictionary", "kinematicCloudProperties")
        + "constantProperties { rho0 1000; }\n"
        + "subModels { injectionModels { #include \"injectors\" } }\n")
    (tmp_path / "system" / "controlDict").write_text(
        HEADER % ("dictionary", "controlDict")
        + "startTime 0;\nendTime 3e-3;\ndeltaT 1e-4;\n")
    return tmp_path


def test_injected_mass(case):
    # 3 particles of 1e-18 m^3 at one position, 2 of 8e-18 m^3 at two:
    # 1000 (3 x 1e-18 + 2 x 2 x 8e-18) = 3.5e-14 kg
    (case / "constant" / "injectors").write_text(
        INJECTOR % ("one", 3, "one", D1)
        + INJECTOR % ("two", 2, "two", 2 * D1))
    for name, positions in (("one", "(1e-4 1e-4 1e-4)"),
                            ("two", "(1e-4 1e-4 1e-4)\n(2e-4 2e-4 2e-4)")):
        (case / "constant" / f"positions_{name}").write_text(
            HEADER % ("vectorField", "positions") + f"(\n{positions}\n)\n")
    assert checks.injected_mass(str(case)) == pytest.approx(3.5e-14, rel=1e-14)
    (case / "constant" / "injectors").write_text("")
    with pytest.raises(CheckError, match="no injector"):
        checks.injected_mass(str(case))
    (case / "constant" / "injectors").write_text(
        (INJECTOR % ("one", 3, "one", D1)).replace("fixed;", "mass;"))
    with pytest.raises(CheckError, match="not a manual injection"):
        checks.injected_mass(str(case))


def test_steps(case):
    assert checks.steps(str(case)) == 30
    (case / "system" / "controlDict").write_text(
        HEADER % ("dictionary", "controlDict")
        + "startTime 0;\nendTime 3.05e-3;\ndeltaT 1e-4;\n")
    with pytest.raises(CheckError, match="not a whole number"):
        checks.steps(str(case))


def test_patch_interaction_models(tmp_path):
    properties = tmp_path / "kinematicCloudOutputProperties"
    properties.write_text(HEADER % ("dictionary", "OutputProperties") + """
injectionModel { shot { massInjected 1e-13; } }
patchInteractionModel
{
    escapedParcels  0;
    escapedMass     0;
    standardWallInteraction
    {
        nEscape         3 ( 1 ( 0 ) 1 ( 0 ) 1 ( 0 ) );
    }
}
""")
    assert checks.patch_interaction_models(properties) == [
        "standardWallInteraction"]


#------------------------------------------------------------------------------
# The core and the tools

CORE = ("0.4 -0.2 1.05 0 -306122.4 -102040.8 0 0.96 0.48 -1.1e-13 1.2e-13")


def test_core_result_and_spin():
    core = checks.core_result(CORE)
    assert (core["Ux"], core["Uz"], core["captured"], core["wy"]) == \
        (0.4, 1.05, 0, -102040.8)
    with pytest.raises(CheckError, match="printed 3 values"):
        checks.core_result("1 2 3")
    # A sphere of 1e-18 m^3 at 1000 kg/m^3: m = 1e-15 kg, I = m d^2/10 =
    # (2/5) m r^2
    L = checks.sphere_angular_momentum(D1, 1000, [0, 2, -1])
    I = 0.4 * 1e-15 * (D1 / 2)**2
    assert L == [0, pytest.approx(2 * I, rel=1e-14),
                 pytest.approx(-I, rel=1e-14)]


SWEEP = ("diameter,speed,angle,un,ut,R,gamma,WA,captured,unOut,utOut,"
         "energyLoss\n"
         "4.9e-06,2,0,2,0,0.96,0.48,-1.1e-13,0,1.05,0,1.2e-13\n"
         "4.9e-06,0.3,0,0.3,0,0.99,0.2,-2e-15,1,0,0,5e-16\n")


def test_sweep_matches_core(tmp_path):
    sweep, core = tmp_path / "sweep.csv", tmp_path / "core.txt"
    sweep.write_text(SWEEP)
    # Ux Uy Uz captured wx wy wz R gamma WA energyLoss
    core.write_text("0 0 1.05 0 0 0 0 0.96 0.48 -1.1e-13 1.2e-13\n"
                    "0 0 0 1 0 0 0 0.99 0.2 -2e-15 5e-16\n")
    assert checks.sweep_matches_core(sweep, core) == (2, [])
    core.write_text("0 0 1.05 0 0 0 0 0.96 0.48 -1.1e-13 1.2e-13\n"
                    "0 0 0 0 0 0 0 0.99 0.2 -2.0001e-15 5e-16\n")
    n, problems = checks.sweep_matches_core(sweep, core)
    assert len(problems) == 2
    assert "captured 1, core 0" in problems[0] and "WA" in problems[1]
    core.write_text("0 0 1.05 0 0 0 0 0.96 0.48 -1.1e-13 1.2e-13\n")
    assert "2 rows" in checks.sweep_matches_core(sweep, core)[1][0]


def test_impact_calc_inputs(tmp_path):
    records = tmp_path / "impacts.csv"
    records.write_text("time,patch,diameter,un,ut\n1e-5,floor,2.58e-06,3,4\n"
                       "2e-5,sides,4.9e-06,1,0\n")
    (p1, d1, v1, a1), (p2, d2, v2, a2) = checks.impact_calc_inputs(records)
    # The 3-4-5 triangle: 5 m/s at atan(4/3) from the normal
    assert (p1, d1, v1) == ("floor", "2.58e-06", 5)
    assert a1 == pytest.approx(53.13010235415598, rel=1e-14)
    assert (p2, d2, v2, a2) == ("sides", "4.9e-06", 1, 0)


def test_records_match_tool(tmp_path):
    records, tool = tmp_path / "impacts.csv", tmp_path / "tool.csv"
    records.write_text(RECORDS)
    rows = ["diameter,speed,angle,un,ut,R,gamma,WA,captured,unOut,utOut,"
            "energyLoss",
            "2.5799999999999999e-06,3,1.9,3,0.1,0.9,1,-1e-13,1,0,0,0",
            "2.58e-06,3.5,1.6,3.5,0.1,0.8,1,-1e-13,0,1.2,0.05,0",
            "4.9e-06,1,0,1,0,0.7,0,0,0,0.7,0,0"]
    tool.write_text("\n".join(rows) + "\n")
    assert checks.records_match_tool(records, tool, 1e-9,
                                     ["floor", "ceiling"]) == (3, [])
    n, problems = checks.records_match_tool(records, tool, 1e-9, ["sides"])
    assert problems == ["no impact on sides to compare"]
    rows[2] = rows[2].replace("0.8,1,-1e-13,0", "0.8000001,1,-1e-13,1")
    tool.write_text("\n".join(rows) + "\n")
    n, problems = checks.records_match_tool(records, tool, 1e-9)
    assert len(problems) == 2
    assert "solver rebound, impactCalc captured 1" in problems[0]
    assert "R 0.8 in the solver, 0.8000001" in problems[1]
    tool.write_text("\n".join(rows[:2]) + "\n")
    assert "3 records" in checks.records_match_tool(records, tool)[1][0]


TABLE1 = """Impact on patch floor (entry floor)
  m, mass                                 8.316e-14     kg
  gamma, surface energy (from Eq. 18)     0.8112        J/m^2
  T_f, final kinetic energy               1.757e-12     J (62.4% T_i)
  E_h, van der Waals energy (Eq. 34)      6.176e-12     J (219% T_i)
  nothing here                            n/a
"""


def test_printed_value(tmp_path):
    table = tmp_path / "table1.txt"
    table.write_text(TABLE1)
    assert checks.printed_value(table, "m, mass") == 8.316e-14
    assert checks.printed_value(table, "gamma, surface energy") == 0.8112
    assert checks.printed_value(table, "T_f, final kinetic") == 1.757e-12
    assert checks.printed_value(table, "E_h, van der Waals") == 6.176e-12
    with pytest.raises(CheckError, match="no line 'a_m'"):
        checks.printed_value(table, "a_m")
    with pytest.raises(CheckError, match="no number"):
        checks.printed_value(table, "nothing here")


FIT = """Restitution (powerLaw, joint fit below):
    k     44.767 +- 4
    p     0.71491 +- 0.02
    c     0.33886 +- 0
    gamma 0.6 +- 6e-11 J/m^2
For the patch entry: restitution { type powerLaw; k 44.77; p 0.7149; }
"""


def test_fit_values_and_recovered(tmp_path):
    fit = tmp_path / "fit.log"
    fit.write_text(FIT)
    assert checks.fit_values(fit, "k") == [(44.767, 4)]
    assert checks.fit_values(fit, "gamma") == [(0.6, 6e-11)]
    # |44.767 - 45.3| = 0.533 <= 3 x 4; |0.71491 - 0.718| = 0.00309 <= 0.06
    assert checks.recovered(fit, "k", 45.3) == []
    assert checks.recovered(fit, "p", 0.718) == []
    # 0.1 away is 5 standard errors of 0.02
    assert checks.recovered(fit, "p", 0.81491) != []
    # A zero standard error recovers nothing
    assert checks.recovered(fit, "c", 0.33886) != []
    with pytest.raises(CheckError, match="n not printed"):
        checks.recovered(fit, "n", 0.5)


#------------------------------------------------------------------------------
# The benchmark's figures

BENCH = ("name,iterations,real_time,cpu_time,time_unit,bytes_per_second,"
         "items_per_second,label,error_occurred,error_message\n"
         '"primitive/pow",1000,15,15,ns,,,,,\n'
         '"primitive/sqrt",1000,2.5,2.5,ns,,,,,\n'
         '"classicalRebound",1000,0.005,0.005,us,,,,,\n'
         '"impact/powerLaw/powerLaw",1000,75,75,ns,,,,,\n')


def test_bench_core_lines(tmp_path):
    path = tmp_path / "core.csv"
    path.write_text(BENCH)
    assert checks.bench_core_lines(path) == [
        "core: one call on the impact speeds, ns: pow 15.0 sqrt 2.5",
        "core: classical rebound (standardWallInteraction arithmetic) 5.0 ns",
        # the name on 36 characters, the time on 6, the ratio on 5
        "core: impact/powerLaw/powerLaw" + 12 * " " + "   75.0 ns   15.0 x "
        "baseline"]
    path.write_text(BENCH.replace("classicalRebound", "other"))
    with pytest.raises(CheckError):
        checks.bench_core_lines(path)


def test_random_positions():
    lines = checks.random_positions(50, 7)
    assert lines == checks.random_positions(50, 7)
    assert lines != checks.random_positions(50, 8)
    assert lines[1] == "(" and lines[-1] == ")" and len(lines) == 53
    values = [float(x) for line in lines[2:-1]
              for x in line.strip("()").split()]
    assert len(values) == 150
    assert all(5e-5 <= x <= 9.5e-4 for x in values)


def test_execution_time(tmp_path):
    log = tmp_path / "log.solver"
    log.write_text("Time = 0.0001\nExecutionTime = 0.5 s  ClockTime = 1 s\n"
                   "Time = 0.0002\nExecutionTime = 1.25 s  ClockTime = 2 s\n"
                   "End\n")
    assert checks.execution_time(log) == 1.25
    log.write_text("End\n")
    with pytest.raises(CheckError):
        checks.execution_time(log)


def test_mass_transferred(tmp_path):
    # The last value of each kind, summed: 3e-9 + 0 + 1e-10
    log = tmp_path / "log.solver"
    log.write_text(
        "Time = 0.001\n"
        "    Mass transfer phase change      = 1e-09\n"
        "    Mass transfer devolatilisation  = 0\n"
        "    Mass transfer surface reaction  = 5e-11\n"
        "Time = 0.002\n"
        "    Current mass in system          = 7e-07\n"
        "    Mass transfer phase change      = 3e-09\n"
        "    Mass transfer devolatilisation  = 0\n"
        "    Mass transfer surface reaction  = 1e-10\n"
        "End\n")
    assert checks.mass_transferred(log) == pytest.approx(3.1e-9, rel=1e-15,
                                                         abs=0)
    log.write_text("End\n")
    with pytest.raises(CheckError):
        checks.mass_transferred(log)


def test_bench_lines(tmp_path):
    # Ratios 1.0, 1.3, 1.1: median 1.1, mean 3.4/3, deviation
    # sqrt((0.1333^2 + 0.1667^2 + 0.0333^2)/2) = sqrt(0.07/3); fastest
    # runs 2.4/2 = 1.2 (the fastest of each side, from different pairs)
    line = checks.time_ratios_line("x", [2.4, 2, 10], [2.4, 2.6, 11])
    assert line == ("x: time ratio median 1.100, mean 1.133 +- 0.153, "
                    "fastest runs 1.200 (3 alternating pairs: 1.0000 1.3000 "
                    "1.1000)")
    with pytest.raises(CheckError):
        checks.time_ratios_line("x", [1], [1, 2])
    with pytest.raises(CheckError):
        checks.time_ratios_line("x", [1, 1], [1, 0])
    assert checks.solver_lines(20000, 2500000, 10) == [
        "solver: 20000 parcels, 50 steps: 2500000 wall impacts, 50000 per "
        "step; adhesive run 10 s",
        "solver: 2.5e+05 impacts handled per second of solver time (all of "
        "it, tracking included)"]
    assert checks.scaling_line(5000, 600000, 2.4) == (
        "scaling:   5000 parcels,   600000 impacts: 2.40 s, 4 s per million "
        "impacts")
    with pytest.raises(CheckError):
        checks.scaling_line(5000, 0, 2.4)
    assert checks.entries_lines([(1, 7.5), (10, 7.2), (1, 7.1), (10, 7.4),
                                 (1, 7.3), (10, 7.3)]) == [
        "scaling: 1 patch entries in the dictionary: median 7.30 s (7.50 "
        "7.10 7.30)",
        "scaling: 10 patch entries in the dictionary: median 7.30 s (7.20 "
        "7.40 7.30)"]
    assert checks.speedup_line(7.08, 5.4) == \
        "parallel: 1 rank 7.08 s, 2 ranks 5.40 s, speedup 1.31"
    counts = tmp_path / "instructions"
    counts.write_text("standard 1000000\nadhesive 1250000\n")
    assert checks.instructions_lines(counts, 500) == [
        "instructions: standard        1.0000e+06 in 10 steps (500 wall "
        "impacts)",
        "instructions: adhesive        1.2500e+06 in 10 steps (500 wall "
        "impacts), 500 per impact beyond standard"]
    counts.write_text("adhesive 1250000\n")
    with pytest.raises(CheckError):
        checks.instructions_lines(counts, 500)
    # 1.21e10 / 1.1e10 = 1.1 exactly
    assert checks.instruction_ratio_line("box", 1.1e10, 1.21e10, 5) == (
        "box: instructions in 5 steps 1.1000e+10 and 1.2100e+10, ratio "
        "1.1000")
    with pytest.raises(CheckError):
        checks.instruction_ratio_line("box", 0, 1.21e10, 5)


#------------------------------------------------------------------------------
# The subcommands

def test_every_subcommand_is_documented(capsys):
    status, out, _ = run(capsys, "-help")
    assert status == 0
    for name, (function, _, _, _) in checks.COMMANDS.items():
        assert function.__doc__, name
        assert f"  {name} " in out


def test_exit_status_and_messages(capsys, stats):
    assert run(capsys, "statistic", stats, "captureParcels", "floor") == \
        (0, "15", "")
    assert run(capsys, "statistic", stats, "captureMass") == (0, "4e-14", "")
    status, out, err = run(capsys, "statistic", stats, "captureParcels",
                           "sides")
    assert status == 1 and "no rows of patch 'sides'" in err
    assert run(capsys, "statisticRows", stats, "floor")[:2] == (0, "4")
    status, _, err = run(capsys, "close", "1.1e-12", "1e-12", "1e-12",
                         "the escaped mass")
    assert status == 1 and err.startswith(
        "adhesiveWallPost check close: the escaped mass: 1.1e-12")
    assert run(capsys, "close", "1", "1", "0")[0] == 0
    assert run(capsys, "small", "1e-27", "1e-12", "1e-12")[0] == 0
    assert run(capsys, "small", "0", "1e-12", "0")[0] == 1
    assert run(capsys, "between", "0.85", "0.8499", "0.8501")[0] == 0
    assert run(capsys, "between", "abc", "0", "1")[0] == 1
    assert run(capsys, "sumsTo", "1", "0", "0.25", "0.75")[0] == 0
    assert run(capsys, "sumsTo", "1", "1e-12", "0.25", "0.7")[0] == 1
    assert run(capsys, "scaled", "3.141", "0.97") == (0, "3.04677", "")
    assert run(capsys, "core", CORE, "Uz", "captured") == (0, "1.05 0", "")
    assert run(capsys, "core", CORE, "Uw")[0] == 1
    assert run(capsys, "compareVectors", "1 2 3", "1 2 3", "0")[0] == 0
    assert run(capsys, "compareVectors", "1 2 3", "1 2 3.1", "1e-10")[0] == 1
    # Wrong usage
    assert run(capsys, "statistic", stats)[0] == 2
    assert run(capsys, "noSuchCheck")[0] == 2
    assert run(capsys)[0] == 2


def test_subcommands_on_files(capsys, stats, tmp_path):
    records = tmp_path / "impacts.csv"
    records.write_text(RECORDS)
    assert run(capsys, "tableRows", records, "outcome") == (0, "3", "")
    assert run(capsys, "columns", records, "patch", "un")[1] == \
        "floor,3\nfloor,3.5\nceiling,1"
    assert run(capsys, "columns", records, "patch=floor", "-sort", "un",
               "time", "un")[1] == "1e-5,3\n2e-5,3.5"
    assert run(capsys, "columns", records, "outcome=capture", "time")[1] \
        == "1e-5"
    assert run(capsys, "columns", records, "patch=floor")[0] == 1
    assert run(capsys, "columns", records, "un", "-sort")[0] == 1
    assert run(capsys, "timeRange", stats)[1] == "1e-05 2e-05"
    assert run(capsys, "compareStatistics", stats, stats)[0] == 0
    field = tmp_path / "massStick"
    field.write_text(MASS_STICK)
    assert run(capsys, "boundarySum", field, "floor")[1] == "3.5e-14"
    assert run(capsys, "compareFields", field, field)[0] == 0
    field.write_text(MASS_STICK.replace("3e-13", "3.1e-13"))
    other = tmp_path / "other"
    other.write_text(MASS_STICK)
    status, _, err = run(capsys, "compareFields", other, field)
    assert status == 1 and "number 15: 3e-13" in err
    assert run(capsys, "criticalSpeeds", records, "floor", "2",
               "2.58e-6:3.141")[0] == 0
    assert run(capsys, "criticalSpeeds", records, "floor", "2",
               "2.58e-6:2.9")[0] == 1
    U = tmp_path / "U"
    U.write_text(HEADER % ("vectorField", "U") + "1((0.5 0 -1))\n")
    assert run(capsys, "lastVector", U)[1] == "0.5 0 -1"
    assert run(capsys, "lagrangianValues", U)[1].split() == ["0.5", "0", "-1"]


def test_deposit_cost_line():
    # (median 5.5 s - median 5.0 s)/(1000 deposits x 50 steps) = 10 us
    line = checks.deposit_cost_line(1000, 50, [5.0, 4.0, 6.0], [5.5, 9.0, 5.0])
    assert line.startswith("resuspension: 10000 ns per deposit and step")
    assert "medians 5.00 s without, 5.50 s with" in line
    with pytest.raises(checks.CheckError):
        checks.deposit_cost_line(0, 50, [1.0], [1.0])


def test_grade_efficiency_check_needs_every_impact_recorded(tmp_path):
    # The check counts captures and escapes from impacts.csv: a case that
    # records only some patches, or a file capped at maxImpactRecords,
    # cannot be counted, and says so instead of reporting mismatches
    folder = tmp_path / "postProcessing/lagrangian/kinematicCloud" \
        / "adhesiveWallInteraction/0"
    folder.mkdir(parents=True)
    (folder / "gradeEfficiency.dat").write_text(
        "# time\tinjector\tdMin\tdMax\tinjectedParcels\n1\tall\t0\tinf\t1\n")
    records = folder / "impacts.csv"
    records.write_text("time,patch,diameter,nParticle,outcome\n")
    constant = tmp_path / "constant"
    constant.mkdir()
    properties = constant / "kinematicCloudProperties"
    coeffs = ("subModels { adhesiveWallInteractionCoeffs "
              "{ recordPatches (floor); } }\n")
    properties.write_text(HEADER % ("dictionary", "kinematicCloudProperties")
                          + coeffs)
    with pytest.raises(CheckError, match="recordPatches"):
        checks.expected_grade_efficiency(str(tmp_path))
    properties.write_text(HEADER % ("dictionary", "kinematicCloudProperties")
                          + coeffs.replace("recordPatches (floor);", ""))
    records.write_text("time,patch,diameter,nParticle,outcome\n"
                       "1,floor,1e-06,1,capture\n"
                       "# capped at maxImpactRecords = 1\n")
    with pytest.raises(CheckError, match="capped"):
        checks.expected_grade_efficiency(str(tmp_path))


def test_compare_records(tmp_path, capsys):
    # The serial run's records against a run's written in two files (a
    # restart) in another order, with processor-local face numbers
    reference = tmp_path / "reference.csv"
    reference.write_text(RECORDS)
    header, *rows = RECORDS.splitlines()
    rows = [row for row in rows if not row.startswith("#")]
    renumbered = [row.replace(",floor,3,", ",floor,7,") for row in rows]
    first, second = tmp_path / "first.csv", tmp_path / "second.csv"
    first.write_text("\n".join([header, renumbered[2], renumbered[0]]) + "\n")
    second.write_text("\n".join([header, renumbered[1]]) + "\n")
    columns = ["time", "patch", "x", "un", "outcome"]
    assert checks.compare_records(reference, [first, second], columns,
                                  1e-9) == []
    # face named: the renumbering is seen
    assert checks.compare_records(reference, [first, second],
                                  columns + ["face"], 1e-9)
    # A record missing
    assert "3 records" in checks.compare_records(
        reference, [first], columns, 1e-9)[0]
    # un 3.5 -> 3.5000001: beyond 1e-9 of the column's largest (3.5),
    # within 1e-6
    changed = tmp_path / "changed.csv"
    changed.write_text(RECORDS.replace(",3.5,0.1,", ",3.5000001,0.1,"))
    problems = checks.compare_records(reference, [changed], columns, 1e-9)
    assert len(problems) == 2
    assert problems[0].startswith("record ('2e-5', 'floor', '0', '3.5', "
                                  "'rebound') of ")
    assert "3.5000001" in problems[1]
    assert checks.compare_records(reference, [changed], columns, 1e-6) == []
    # A NaN in either compares equal to nothing; no records is no check
    changed.write_text(RECORDS.replace(",3.5,0.1,", ",nan,0.1,"))
    assert "a NaN in" in checks.compare_records(
        reference, [changed], columns, 1e-9)[0]
    assert "a NaN in" in checks.compare_records(
        changed, [reference], columns, 1e-9)[0]
    empty = tmp_path / "empty.csv"
    empty.write_text(header + "\n")
    assert "nothing to compare" in checks.compare_records(
        empty, [empty], columns, 1e-9)[0]
    # An outcome differs
    changed.write_text(RECORDS.replace(",capture,", ",rebound,"))
    problems = checks.compare_records(reference, [changed], columns, 1e-9)
    assert len(problems) == 2 and "'capture'" in problems[0]
    # Positions equal but for rounding, in an order that sorting by value
    # would pair wrongly (x 7.8e-4 written both ways, y in turn)
    grid = tmp_path / "grid.csv"
    grid.write_text("x,y\n780e-6,292e-6\n780e-6,376e-6\n")
    rounded = tmp_path / "rounded.csv"
    rounded.write_text("x,y\n0.00078,0.000376\n0.000780000000000001,"
                       "0.000292\n")
    assert checks.compare_records(grid, [rounded], ["x", "y"], 1e-9) == []
    # The command: columns in one argument, the run's files after
    assert run(capsys, "compareRecords", reference, "1e-9",
               "time patch x un outcome", first, second)[:2] == \
        (0, "the records agree")
    assert run(capsys, "compareRecords", reference, "1e-9",
               "time patch x un outcome", first)[0] == 1


def test_surface_contacts(tmp_path, capsys):
    # Impacts per patch (two injectors on the floor) against the contacts of
    # surfaceContact.dat; an earlier time does not count
    stats = statistics_file(tmp_path / "statistics.dat", [
        {"time": "1e-05", "patch": "floor", "impactParcels": 1},
        {"time": "2e-05", "patch": "floor", "injector": "1",
         "impactParcels": 3},
        {"time": "2e-05", "patch": "floor", "injector": "2",
         "impactParcels": 2},
        {"time": "2e-05", "patch": "ceiling", "impactParcels": 1},
        {"time": "2e-05", "patch": "outlet", "impactParcels": 0}])
    contacts = tmp_path / "surfaceContact.dat"

    def write(floor, ceiling):
        contacts.write_text(
            "# adhesiveWallSurfaceContact of cloud kinematicCloud\n"
            "# time\tpatch\tsurfaceContacts\tcentreContacts\n"
            "1e-05\tfloor\t1\t0\n1e-05\tceiling\t0\t0\n"
            f"2e-05\tfloor\t{floor[0]}\t{floor[1]}\n"
            f"2e-05\tceiling\t{ceiling[0]}\t{ceiling[1]}\n")
    write((5, 0), (0, 1))
    assert checks.surface_contacts(stats, contacts) == (5, 1)
    assert run(capsys, "surfaceContacts", stats, contacts)[:2] == (0, "5 1")
    # A contact that is no impact, an impact that is no contact
    write((6, 0), (0, 1))
    with pytest.raises(CheckError, match="floor: 5 impacts"):
        checks.surface_contacts(stats, contacts)
    write((5, 0), (0, 0))
    with pytest.raises(CheckError, match=r"ceiling: 1 impacts .* 0 \+ 0"):
        checks.surface_contacts(stats, contacts)
    assert run(capsys, "surfaceContacts", stats, contacts)[0] == 1
    # Contacts on a patch the statistics do not hold; files of other times
    write((5, 0), (0, 1))
    contacts.write_text(contacts.read_text() + "2e-05\tsides\t2\t0\n")
    with pytest.raises(CheckError, match=r"sides: 0 impacts .* 2 \+ 0"):
        checks.surface_contacts(stats, contacts)
    write((5, 0), (0, 1))
    contacts.write_text(contacts.read_text().replace("2e-05", "3e-05"))
    with pytest.raises(CheckError, match="last times 2e-05 .* 3e-05"):
        checks.surface_contacts(stats, contacts)


def test_argument_counts_follow_from_the_usage():
    # words outside brackets are required, a quoted group is one argument,
    # a word ending in ... takes any number
    from adhesivewall.checks.registry import _argument_counts
    assert _argument_counts("FILE COLUMN [PATCH [INJECTOR [DMIN]]]") == (2, 5)
    assert _argument_counts("'X Y Z' 'X Y Z' RTOL") == (3, 3)
    assert _argument_counts("REFERENCE RTOL 'COLUMN...' FILE...") == (4, checks.ANY)
    assert _argument_counts("[CASE [TIME [CLOUD]]]") == (0, 3)
    assert _argument_counts("FILE [COLUMN=TEXT...] [-sort COLUMN] COLUMN...") == (2, checks.ANY)
    assert _argument_counts("") == (0, 0)
