# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Reading the model's files and the reference data by column name."""

import pytest

from adhesivewall import curves, tables

STATISTICS = (
    "# adhesiveWallInteraction statistics of cloud kinematicCloud: ...\n"
    "# time\tpatch\tinjector\tdMin\tdMax\tcaptureParcels\tcaptureMass\n"
    "1e-05\tfloor\tall\t0\tinf\t1\t2e-14\n"
    "1e-05\twalls\tall\t0\tinf\t0\t0\n"
    "2e-05\tfloor\tall\t0\tinf\t3\t6.5e-14\n"
    "2e-05\twalls\tall\t0\tinf\t2\t1e-14\n")

REFERENCE = (
    "# Deposition in a bend (Pui et al. 1987)\n"
    "# Stokes number on the tube radius\n"
    "Stk,efficiencyPercent\n"
    "0.17,5.3\n"
    "0.28,24.5\n")

IMPACTS = (
    "time,patch,face,x,outcome\n"
    "1e-5,floor,3,0.1,capture\n"
    "2e-5,floor,4,0.2,rebound\n"
    "# capped at maxImpactRecords = 2\n")


@pytest.fixture
def files(tmp_path):
    paths = {}
    for name, text in (("statistics.dat", STATISTICS),
                       ("reference.csv", REFERENCE),
                       ("impacts.csv", IMPACTS)):
        paths[name] = tmp_path / name
        paths[name].write_text(text)
    return paths


def test_commented_header_of_the_model_files(files):
    statistics = tables.read(files["statistics.dat"])
    assert statistics.names[:3] == ["time", "patch", "injector"]
    assert len(statistics) == 4
    last = statistics.last_time()
    assert list(last.text("patch")) == ["floor", "walls"]
    assert last.sum("captureParcels") == 5
    assert last.where(patch="floor")["captureMass"][0] == 6.5e-14
    assert statistics["dMax"][0] == float("inf")


def test_reference_data_below_their_citation(files):
    reference = tables.read(files["reference.csv"])
    assert reference.names == ["Stk", "efficiencyPercent"]
    assert list(reference["Stk"]) == [0.17, 0.28]
    assert reference.text("efficiencyPercent") == ["5.3", "24.5"]


def test_records_with_a_closing_comment(files):
    impacts = tables.read(files["impacts.csv"])
    assert len(impacts) == 2
    assert len(impacts.where(outcome="capture")) == 1
    assert list(impacts["face"]) == [3, 4]


def test_a_missing_column_is_named(files):
    with pytest.raises(KeyError, match="no column 'capturedParcels'"):
        tables.read(files["statistics.dat"])["capturedParcels"]


def test_a_short_row_is_an_error(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("a,b\n1,2\n3\n")
    with pytest.raises(ValueError, match="a row of 1 values"):
        tables.read(path)


def test_compare(files, tmp_path):
    reference = tables.read(files["reference.csv"])
    changed = tmp_path / "changed.csv"
    changed.write_text(REFERENCE.replace("24.5", "24.5000000000001"))
    assert tables.compare(tables.read(changed), reference) == []
    changed.write_text(REFERENCE.replace("24.5", "24.50001"))
    assert tables.compare(tables.read(changed), reference) == [
        "row 2 efficiencyPercent: 24.50001 against 24.5"]
    assert tables.compare_files(str(tmp_path / "absent.csv"),
                                str(files["reference.csv"]))


def test_interpolation_and_its_inverse():
    xs, ys = [0.1, 0.2, 0.4], [0, 10, 50]
    assert curves.interpolate(0.3, xs, ys) == pytest.approx(30)
    assert curves.interpolate(30, ys, xs) == pytest.approx(0.3)
    assert curves.interpolate(60, ys, xs) is None        # not reached
    # a plateau of the curve is passed over, not divided by
    assert curves.interpolate(10, [10, 10, 30], [0.1, 0.2, 0.3]) == 0.2
    assert curves.binomial_se(25, 100) == pytest.approx(0.0433013, rel=1e-6)
