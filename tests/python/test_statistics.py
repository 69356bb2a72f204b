# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Sums of the model's statistics per size class."""

import pytest

from adhesivewall import statistics, tables

COLUMNS = ("time patch injector dMin dMax impactParticles reboundParticles "
           "captureParticles escapeParticles").split()
ROWS = [
    # an earlier time, which the sums leave out
    "1 floor all 0 2e-06 9 9 0 0",
    "2 floor all 0 2e-06 10 6 4 0",
    "2 floor all 2e-06 inf 5 1 4 0",
    "2 walls all 0 2e-06 2 2 0 0",
    "2 walls all 2e-06 inf 3 0 3 0",
    "2 outlet all 0 2e-06 1 0 0 1",
    "2 outlet all 2e-06 inf 0 0 0 0",
]


@pytest.fixture
def stats(tmp_path):
    path = tmp_path / "statistics.dat"
    path.write_text("# header\n# " + "\t".join(COLUMNS) + "\n"
                    + "\n".join("\t".join(r.split()) for r in ROWS) + "\n")
    return tables.read(path)


def test_size_classes_of_every_patch(stats):
    classes = statistics.size_classes(stats, ["floor", "walls", "outlet"])
    assert classes.text("dMin") == ["0", "2e-06"]
    assert list(classes["impactParticles"]) == [13, 8]
    assert list(classes["captureParticles"]) == [4, 7]
    assert list(classes["escapeParticles"]) == [1, 0]
    assert list(classes["captureFraction"]) == pytest.approx([4 / 13, 7 / 8])


def test_size_classes_of_the_walls_by_default(stats):
    # The outlet's escapes are no wall's impacts: left out unless named
    assert statistics.walls(stats) == ["floor", "walls"]
    classes = statistics.size_classes(stats)
    assert list(classes["impactParticles"]) == [12, 8]
    assert list(classes["escapeParticles"]) == [0, 0]
    assert list(classes["captureFraction"]) == pytest.approx([4 / 12, 7 / 8])


def test_size_classes_of_some_patches(stats):
    classes = statistics.size_classes(stats, ["floor"])
    assert list(classes["captureFraction"]) == pytest.approx([0.4, 0.8])
    with pytest.raises(KeyError):
        statistics.size_classes(stats, ["fibre"])


def test_final_sum(stats):
    assert statistics.final(stats, "captureParticles", patch="walls") == 3
    with pytest.raises(KeyError):
        statistics.final(stats, "captureParticles", patch="fibre")


def test_surface_contacts_of_a_case(tmp_path):
    folder = tmp_path / "postProcessing/lagrangian/kinematicCloud" \
        / "adhesiveWallInteraction/0"
    folder.mkdir(parents=True)
    (folder / "surfaceContact.dat").write_text(
        "# Contacts at the surface and at the centre\n"
        "# time\tpatch\tsurfaceContacts\tcentreContacts\n"
        "1\tfloor\t5\t1\n1\tsides\t2\t0\n"
        "2\tfloor\t7\t1\n2\tsides\t3\t0\n")
    contacts = statistics.read_surface_contacts(tmp_path)
    assert statistics.final(contacts, "surfaceContacts") == 10
    assert statistics.final(contacts, "surfaceContacts", patch="sides") == 3
    assert statistics.final(contacts, "centreContacts") == 1


def test_latest_run_by_default(tmp_path):
    # A case run from 0 and restarted at 9 and 10: the readers take the
    # latest run's folder (by time, not by name: as text "9" sorts after
    # "10"), or the one asked for
    parent = tmp_path / "postProcessing/lagrangian/kinematicCloud" \
        / "adhesiveWallInteraction"
    assert statistics.output_folder(tmp_path) == str(parent / "0")
    for start, parcels in (("0", 2), ("10", 9), ("9", 5), ("notATime", 1)):
        (parent / start).mkdir(parents=True)
        (parent / start / "surfaceContact.dat").write_text(
            "# time\tpatch\tsurfaceContacts\tcentreContacts\n"
            f"1\tfloor\t{parcels}\t0\n")
    assert statistics.output_folder(tmp_path) == str(parent / "10")
    assert statistics.final(statistics.read_surface_contacts(tmp_path),
                            "surfaceContacts") == 9
    assert statistics.final(statistics.read_surface_contacts(
        tmp_path, start_time="9"), "surfaceContacts") == 5


GRADE_HEADER = (
    "# time\tinjector\tdMin\tdMax\tinjectedParcels\tinjectedParticles"
    "\tinjectedMass\tcapturedParcels\tcapturedParticles\tcapturedMass"
    "\tescapedParcels\tescapedParticles\tescapedMass\tremovedParcels"
    "\tremovedParticles\tremovedMass\tairborneParcels\tairborneParticles"
    "\tairborneMass\tcapturedFraction\n")


def grade_row(time, injector, lo, hi, injected, captured, escaped,
              airborne, n=1):
    # parcels of n particles of mass 1, nothing removed
    values = []
    for parcels in (injected, captured, escaped, 0, airborne):
        values += [parcels, n * parcels, n * parcels]
    values.append(captured / injected if injected else 0)
    return "\t".join([time, injector, lo, hi] + [str(v) for v in values]) \
        + "\n"


def test_grade_efficiency_of_a_case(tmp_path, monkeypatch):
    # Two injectors (parcels of 1 and of 3 particles), three classes (the
    # middle one empty), two times: the last time's sums over the
    # injectors, captured/injected particles; by injector
    folder = tmp_path / "postProcessing/lagrangian/kinematicCloud" \
        / "adhesiveWallInteraction/0"
    folder.mkdir(parents=True)
    (folder / "gradeEfficiency.dat").write_text(
        "# grade efficiency\n" + GRADE_HEADER
        + grade_row("1", "1", "0", "1e-06", 10, 1, 2, 7)
        + grade_row("2", "1", "0", "1e-06", 20, 2, 15, 3)
        + grade_row("2", "1", "1e-06", "2e-06", 0, 0, 0, 0)
        + grade_row("2", "1", "2e-06", "inf", 40, 30, 10, 0)
        + grade_row("2", "2", "0", "1e-06", 30, 8, 20, 2, n=3)
        + grade_row("2", "2", "1e-06", "2e-06", 0, 0, 0, 0, n=3)
        + grade_row("2", "2", "2e-06", "inf", 10, 10, 0, 0, n=3))
    classes = statistics.grade_efficiency(
        statistics.read_grade_efficiency(tmp_path))
    assert list(classes.text("dMin")) == ["0", "1e-06", "2e-06"]
    assert list(classes["injectedParcels"]) == [50, 0, 50]
    assert list(classes["injectedParticles"]) == [110, 0, 70]
    assert list(classes["capturedParcels"]) == [10, 0, 40]
    assert list(classes["capturedParticles"]) == [26, 0, 60]
    assert list(classes["escapedParticles"]) == [75, 0, 10]
    assert list(classes["airborneParticles"]) == [9, 0, 0]
    assert classes["capturedFraction"][0] == 26 / 110
    assert classes["capturedFraction"][2] == 60 / 70
    assert classes.text("capturedFraction")[1] == "nan"
    one = statistics.grade_efficiency(
        statistics.read_grade_efficiency(tmp_path), injectors=["2"])
    assert list(one["capturedParticles"]) == [24, 0, 30]
    with pytest.raises(KeyError):
        statistics.grade_efficiency(
            statistics.read_grade_efficiency(tmp_path), injectors=["3"])

    # The command: the same table as CSV, and its plot in the case's folder
    # wherever it is run from; -help after the command is the help
    from adhesivewall import __main__
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    assert __main__.main(["gradeEfficiency", str(tmp_path)]) == 0
    assert (tmp_path / "gradeEfficiency.png").stat().st_size > 0
    assert not (elsewhere / "gradeEfficiency.png").exists()
    assert __main__.main(["gradeEfficiency", "-help"]) == 0


def test_commands_say_what_is_missing(tmp_path, monkeypatch, capsys):
    # No statistics written (writeToFile off), an injector the file does
    # not hold: one line naming the file or the injector, exit status 1
    from adhesivewall import __main__
    monkeypatch.chdir(tmp_path)
    assert __main__.main(["sizeClasses", str(tmp_path)]) == 1
    err = capsys.readouterr().err
    assert "statistics.dat" in err and "writeToFile yes" in err, err
    folder = tmp_path / "postProcessing/lagrangian/kinematicCloud" \
        / "adhesiveWallInteraction/0"
    folder.mkdir(parents=True)
    (folder / "gradeEfficiency.dat").write_text(
        "# grade efficiency\n" + GRADE_HEADER
        + grade_row("1", "all", "0", "inf", 10, 1, 2, 7))
    assert __main__.main(["gradeEfficiency", str(tmp_path),
                          "kinematicCloud", "model2"]) == 1
    err = capsys.readouterr().err
    assert "no rows of ['model2']; its injector column holds ['all']" \
        in err, err
    assert "outputByInjectorId yes" in err, err


def test_numbers_in_their_shortest_exact_form():
    assert statistics._text(0.0226) == "0.0226"
    assert statistics._text(1000.0) == "1000"
    assert statistics._text(-3) == "-3"
    assert statistics._text(float("nan")) == "nan"
    assert statistics._text(float("inf")) == "inf"
    assert float(statistics._text(0.1 + 0.2)) == 0.1 + 0.2


def test_grade_efficiency_plot_of_one_open_class_warns_of_nothing(tmp_path):
    # Without sizeClasses the only class is [0, inf): drawn at no size, and
    # no numpy warning on the way (0 * inf)
    import warnings
    from adhesivewall import tables
    classes = tables.Table(["dMin", "dMax", "capturedFraction"],
                           [("0", "inf", "0.5"), ("1e-06", "2e-06", "0.25")])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        statistics.plot_grade_efficiency(tmp_path / "g.png", classes)
    assert (tmp_path / "g.png").stat().st_size > 0
