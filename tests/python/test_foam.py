# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""OpenFOAM's file syntax as the post-processing reads it."""

import pytest

from adhesivewall import foam

HEADER = "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"


def test_dictionary_text():
    parsed = foam.parse("""
        a 1.5;  // a comment
        /* a block
           comment */
        name "a string";
        injector { type manualInjection; U0 (3 0 0); }
        list 2(1 2);
    """)
    assert parsed == {"a": 1.5, "name": "a string",
                      "injector": {"type": "manualInjection", "U0": [3, 0, 0]},
                      "list": [1, 2]}


def test_lagrangian_fields(tmp_path):
    uniform = tmp_path / "nParticle"
    uniform.write_text(HEADER % ("scalarField", "nParticle") + "3{1}\n")
    assert foam.list_file(uniform) == [1, 1, 1]
    listed = tmp_path / "d"
    listed.write_text(HEADER % ("scalarField", "d")
                      + "2\n(\n1e-06\n2e-06\n)\n")
    assert foam.list_file(listed) == [1e-6, 2e-6]
    empty = tmp_path / "origId"
    empty.write_text(HEADER % ("labelField", "origId") + "0()\n")
    assert foam.list_file(empty) == []


def test_rows_of_a_table_with_numbers_before_lists(tmp_path):
    table = tmp_path / "parcels"
    table.write_text(HEADER % ("IOList", "parcels") + """
2
(
    (0.0007 0.00125 1e-4) (0 0 -0.3) 2.58e-6 1350 1
    (0.0021 0.00125 1e-4) (0 0 -0.687911) 2.58e-6 1350 1
)
""")
    rows = foam.list_file(table)
    assert len(rows) == 10
    assert rows[5] == [0.0021, 0.00125, 1e-4]
    assert rows[9] == 1


def test_boundary_values(tmp_path):
    field = tmp_path / "massStick"
    field.write_text(HEADER % ("volScalarField", "massStick") + """
dimensions [1 0 0 0 0 0 0];
internalField uniform 0;
boundaryField
{
    floor { type calculated; value nonuniform List<scalar> 3(1e-14 0 2e-14); }
    walls { type calculated; value uniform 0; }
    frontAndBack { type empty; }
}
""")
    values = foam.boundary_values(field)
    assert values == {"floor": [1e-14, 0, 2e-14], "walls": [0]}


def test_parcel_count_and_times(tmp_path):
    for time in ("0", "0.001", "0.002"):
        (tmp_path / time).mkdir()
    cloud = tmp_path / "0.002" / "lagrangian" / "kinematicCloud"
    cloud.mkdir(parents=True)
    (cloud / "origId").write_text(HEADER % ("labelField", "origId")
                                  + "3(0 4 7)\n")
    assert foam.latest_time(tmp_path) == "0.002"
    assert foam.parcel_count(tmp_path) == 3
    assert foam.parcel_count(tmp_path, "0.001") == 0
    with pytest.raises(ValueError):
        foam.latest_time(tmp_path / "0.002" / "lagrangian")
