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
    classes = statistics.size_classes(stats)
    assert classes.text("dMin") == ["0", "2e-06"]
    assert list(classes["impactParticles"]) == [13, 8]
    assert list(classes["captureParticles"]) == [4, 7]
    assert list(classes["escapeParticles"]) == [1, 0]
    assert list(classes["captureFraction"]) == pytest.approx([4 / 13, 7 / 8])


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
