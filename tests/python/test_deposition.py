# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""adhesivewall.deposition on a case written here: a box of 2 x 1 x 0.25 m
(one cell; the floor's area 2 m^2, the volume 0.5 m^3), and the model's
files of a run of 10 s in rows of 0.1 s: size class 0-10 um with 1000
airborne particles (500 parcels of 2) captured on the floor at 200 per
second from t = 3 s on (none before: a spin-up), class 10 um-inf with 250
airborne (parcels of 1) captured at 100 per second from the start. The
expected values by hand: V_d = N/(A dt C), C = n/V:
    class 1 over (3, 10]: 1400 x 0.5/(2 x 7 x 1000) = 0.05 m/s, 700 parcels;
    class 2 over (3, 10]: 700 x 0.5/(2 x 7 x 250) = 0.1 m/s, 700 parcels;
the concentration constant, so the standard error is V_d/sqrt(parcels).
The uniformity check on the box as 4 cells along z: parcels written 100 a
cell (ratio 1), 300 of 400 in the floor's cell (3), and 200 of 400 active
ones there beside 200 inactive (2); the binomial SE sqrt(f (1 - f)/n)/s of
the fraction f found, s = 1/4 the cell's volume share."""

import math
import os

import pytest

from adhesivewall import deposition
from adhesivewall import polymesh
from adhesivewall.__main__ import main

POINTS = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (0, 1, 0),
          (0, 0, 0.25), (2, 0, 0.25), (2, 1, 0.25), (0, 1, 0.25)]
# Outward-pointing faces (OpenFOAM's order: the normal by the right hand)
FACES = {"floor": [(0, 3, 2, 1)],
         "walls": [(4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (0, 4, 7, 3),
                   (1, 2, 6, 5)]}
HEADER = "FoamFile\n{\n    format ascii;\n    class %s;\n}\n"
CLASSES = [("0", "1e-05"), ("1e-05", "inf")]


def write_mesh(case, binary=False):
    mesh = os.path.join(case, "constant", "polyMesh")
    os.makedirs(mesh, exist_ok=True)
    header = HEADER.replace("ascii", "binary") if binary else HEADER
    with open(os.path.join(mesh, "points"), "w") as f:
        f.write(header % "vectorField" + "\n%d\n(\n" % len(POINTS))
        f.writelines("(%g %g %g)\n" % p for p in POINTS)
        f.write(")\n")
    faces = FACES["floor"] + FACES["walls"]
    with open(os.path.join(mesh, "faces"), "w") as f:
        f.write(HEADER % "faceList" + "\n%d\n(\n" % len(faces))
        f.writelines("4(%d %d %d %d)\n" % face for face in faces)
        f.write(")\n")
    with open(os.path.join(mesh, "boundary"), "w") as f:
        f.write(HEADER % "polyBoundaryMesh" + "\n2\n(\n"
                "    floor\n    {\n        type wall;\n        nFaces 1;\n"
                "        startFace 0;\n    }\n"
                "    walls\n    {\n        type wall;\n        nFaces 5;\n"
                "        startFace 1;\n    }\n)\n")


def captured(k, t):
    """Particles of class k captured on the floor by time t."""
    return 200*max(0.0, t - 3) if k == 0 else 100*t


def write_tables(case, start=0, first_row=1, injectors=("all",)):
    """The model's files of the run starting at `start`, rows from
    first_row x 0.1 s to 10 s (totals since the start of the case), the
    counts shared equally by the injectors named"""
    folder = os.path.join(case, "postProcessing", "lagrangian",
                          "kinematicCloud", "adhesiveWallInteraction",
                          str(start))
    os.makedirs(folder, exist_ok=True)
    per_parcel = (2, 1)
    airborne = (1000, 250)
    stats = ["# statistics", "# time\tpatch\tinjector\tdMin\tdMax\t"
             "captureParcels\tcaptureParticles"]
    grade = ["# grade", "# time\tinjector\tdMin\tdMax\tairborneParcels\t"
             "airborneParticles"]
    for i in range(first_row, 101):
        t = round(0.1*i, 10)
        for k, (a, b) in enumerate(CLASSES):
            n = round(captured(k, t), 9)/len(injectors)
            m = airborne[k]/len(injectors)
            for i in injectors:
                stats.append(f"{t}\tfloor\t{i}\t{a}\t{b}\t"
                             f"{n/per_parcel[k]}\t{n}")
                stats.append(f"{t}\twalls\t{i}\t{a}\t{b}\t0\t0")
                grade.append(f"{t}\t{i}\t{a}\t{b}\t{m/per_parcel[k]}\t{m}")
    for name, lines in (("statistics.dat", stats),
                        ("gradeEfficiency.dat", grade)):
        with open(os.path.join(folder, name), "w") as f:
            f.write("\n".join(lines) + "\n")


@pytest.fixture
def case(tmp_path):
    write_mesh(str(tmp_path))
    write_tables(str(tmp_path))
    return str(tmp_path)


def test_areas_and_volume_of_the_box(case):
    areas, volume = polymesh.areas_and_volume(case)
    assert areas["floor"] == pytest.approx(2, rel=1e-14)
    # the top 2 x 1, the long sides 2 x 0.25, the ends 1 x 0.25
    assert areas["walls"] == pytest.approx(2 + 2*0.5 + 2*0.25, rel=1e-14)
    assert volume == pytest.approx(0.5, rel=1e-14)


def test_binary_mesh_is_refused_by_name(tmp_path):
    write_mesh(str(tmp_path), binary=True)
    with pytest.raises(ValueError, match="points is binary"):
        polymesh.areas_and_volume(str(tmp_path))


def check_floor(rows, start=3.0):
    floor = [r for r in rows if r[0] == "floor"]
    assert [r[0] for r in rows] == ["floor", "floor"]  # walls captured none
    expected = ((0.05, 700), (0.1, 700))
    for row, (vd, parcels) in zip(floor, expected):
        named = dict(zip(deposition.COLUMNS, row))
        assert named["tStart"] == pytest.approx(start)
        assert named["tEnd"] == pytest.approx(10)
        assert named["captureParcels"] == pytest.approx(parcels)
        assert named["Vd"] == pytest.approx(vd, rel=1e-12)
        assert named["VdSE"] == pytest.approx(vd/math.sqrt(parcels),
                                              rel=1e-12)


def test_spin_up_ends_where_the_capture_rate_settles(case):
    rows, steady = deposition.deposition_velocity(case)
    assert steady
    check_floor(rows)


def test_restart_gives_the_straight_run(tmp_path):
    case = str(tmp_path)
    write_mesh(case)
    write_tables(case)
    write_tables(case, start=5, first_row=51)
    # the first run's rows after 5 s are replaced by the restart's
    rows, _ = deposition.deposition_velocity(case)
    check_floor(rows)


def test_per_injector_tables_are_summed(tmp_path):
    case = str(tmp_path)
    write_mesh(case)
    write_tables(case, injectors=("0", "1"))
    rows, _ = deposition.deposition_velocity(case)
    check_floor(rows)


def test_given_concentration_and_start(case):
    rows, steady = deposition.deposition_velocity(
        case, start=4.0, concentration=2000)
    assert steady
    named = dict(zip(deposition.COLUMNS, rows[0]))
    # 1200 particles (600 parcels) over 6 s on 2 m^2 against 2000 per m^3
    assert named["Vd"] == pytest.approx(1200/(2*6*2000), rel=1e-12)
    assert named["VdSE"] == pytest.approx(named["Vd"]/math.sqrt(600),
                                          rel=1e-12)


def test_windows_split_the_run(case):
    rows, _ = deposition.deposition_velocity(case, windows=2, start=3.0)
    class1 = [dict(zip(deposition.COLUMNS, r)) for r in rows
              if r[1] == 0]
    assert [(r["tStart"], r["tEnd"]) for r in class1] == \
        [(3.0, 6.5), (6.5, 10.0)]
    for r in class1:
        assert r["Vd"] == pytest.approx(0.05, rel=1e-12)


def test_no_capture_gives_zero_with_one_captures_error(case):
    rows, _ = deposition.deposition_velocity(case, start=0.0, windows=10)
    first = dict(zip(deposition.COLUMNS, rows[0]))  # class 1, (0, 1] s
    assert first["Vd"] == 0
    # one parcel's capture (2 particles) as V_d: 2/(A dt C), C = 1000/0.5
    # per m^3
    assert first["VdSE"] == pytest.approx(2/(2*1*2000), rel=1e-12)


def write_closed_tables(case, rate, step=0.01):
    """A closed domain's files (all injected at t = 0, nothing escapes):
    class 1 of 1e6 particles (one a parcel) depleted by captures on the
    floor at `rate` per airborne particle from the start, n = n0
    exp(-rate t); class 2 steady, 1000 airborne particles (one a parcel)
    captured at 200 per second from t = 3 s (a spin-up). Rows
    every `step` to 10 s."""
    folder = os.path.join(case, "postProcessing", "lagrangian",
                          "kinematicCloud", "adhesiveWallInteraction", "0")
    os.makedirs(folder, exist_ok=True)
    n0 = 1e6
    stats = ["# time\tpatch\tinjector\tdMin\tdMax\tcaptureParcels\t"
             "captureParticles"]
    grade = ["# time\tinjector\tdMin\tdMax\tinjectedParticles\t"
             "escapedParticles\tremovedParticles\tairborneParcels\t"
             "airborneParticles"]
    for i in range(1, round(10/step) + 1):
        t = round(step*i, 10)
        airborne = round(n0*math.exp(-rate*t))
        rows = (((CLASSES[0]), n0 - airborne, n0, airborne),
                ((CLASSES[1]), captured(0, t), 1e9, 1000))
        for (a, b), n, injected, m in rows:
            stats.append(f"{t}\tfloor\tall\t{a}\t{b}\t{n}\t{n}")
            grade.append(f"{t}\tall\t{a}\t{b}\t{injected}\t0\t0\t{m}\t{m}")
    for name, lines in (("statistics.dat", stats),
                        ("gradeEfficiency.dat", grade)):
        with open(os.path.join(folder, name), "w") as f:
            f.write("\n".join(lines) + "\n")


def test_a_depleted_closed_domain_gives_its_rate(tmp_path):
    # A population depleted at 0.3 per second per particle: V_d = rate V/A
    # = 0.3 x 0.5/2 = 0.075 m/s (the rows' mean for the integral: within
    # rate x step/2 = 0.15 %), its error that of the captures alone (the
    # concentration is counted, not sampled; a decaying series' batches
    # would give it an error of some 20 % of its own); the steady class's
    # spin-up (3 s) is found beside the depleted one
    case = str(tmp_path)
    write_mesh(case)
    write_closed_tables(case, 0.3)
    rows, steady = deposition.deposition_velocity(case)
    assert steady
    named = [dict(zip(deposition.COLUMNS, r)) for r in rows
             if r[0] == "floor"]
    assert named[0]["tStart"] == pytest.approx(3.0)
    assert named[0]["Vd"] == pytest.approx(0.075, rel=2e-3)
    assert named[0]["VdSE"] == pytest.approx(
        named[0]["Vd"]/math.sqrt(named[0]["captureParcels"]), rel=1e-12)
    # 200 x 0.5/(2 x 1000)
    assert named[1]["Vd"] == pytest.approx(0.05, rel=1e-9)


def test_chi2_quantile_against_tables():
    # chi-square 99th percentiles (Abramowitz & Stegun, Table 26.8)
    for dof, value in ((5, 15.086), (9, 21.666), (20, 37.566)):
        assert deposition.chi2_quantile99(dof) == pytest.approx(value,
                                                                rel=0.01)


def test_command_line(case, capsys):
    assert main(["depositionVelocity", case]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == ",".join(deposition.COLUMNS)
    assert len(out) == 3
    assert main(["depositionVelocity", case, "kinematicCloud",
                 "-start", "20"]) == 1


def write_column(case, layers=4):
    """The same 2 x 1 x 0.25 m box as `layers` cells stacked along z (the
    floor's cell first): owner and neighbour too."""
    mesh = os.path.join(case, "constant", "polyMesh")
    os.makedirs(mesh, exist_ok=True)
    dz = 0.25/layers
    rings = [[(0, 0, k*dz), (2, 0, k*dz), (2, 1, k*dz), (0, 1, k*dz)]
             for k in range(layers + 1)]
    points = [p for ring in rings for p in ring]
    v = lambda k, i: 4*k + i
    internal = [((v(k, 0), v(k, 1), v(k, 2), v(k, 3)), k, k - 1)
                for k in range(1, layers)]
    floor = [((v(0, 0), v(0, 3), v(0, 2), v(0, 1)), 0)]
    walls = [((v(layers, 0), v(layers, 1), v(layers, 2), v(layers, 3)),
              layers - 1)]
    for k in range(layers):
        walls += [((v(k, 0), v(k, 1), v(k + 1, 1), v(k + 1, 0)), k),
                  ((v(k, 2), v(k, 3), v(k + 1, 3), v(k + 1, 2)), k),
                  ((v(k, 0), v(k + 1, 0), v(k + 1, 3), v(k, 3)), k),
                  ((v(k, 1), v(k, 2), v(k + 1, 2), v(k + 1, 1)), k)]
    # internal faces point from owner (below) to neighbour: their points
    # ordered for +z, owner k - 1, neighbour k
    faces = [f for f, _, _ in internal] + [f for f, _ in floor + walls]
    owner = ([k - 1 for _, k, _ in internal]
             + [c for _, c in floor + walls])
    neighbour = [k for _, k, _ in internal]
    files = {"points": ("vectorField", ["(%g %g %g)" % p for p in points]),
             "faces": ("faceList", ["4(%d %d %d %d)" % f for f in faces]),
             "owner": ("labelList", [str(c) for c in owner]),
             "neighbour": ("labelList", [str(c) for c in neighbour])}
    for name, (cls, lines) in files.items():
        with open(os.path.join(mesh, name), "w") as f:
            f.write(HEADER % cls + "\n%d\n(\n" % len(lines))
            f.write("\n".join(lines) + "\n)\n")
    n_internal = len(internal)
    with open(os.path.join(mesh, "boundary"), "w") as f:
        f.write(HEADER % "polyBoundaryMesh" + "\n2\n(\n"
                "    floor { type wall; nFaces 1; startFace %d; }\n"
                "    walls { type wall; nFaces %d; startFace %d; }\n)\n"
                % (n_internal, len(walls), n_internal + 1))


def write_parcels(case, time, per_cell, inactive=()):
    """Parcels written at a time, per_cell[i] in cell i, the first
    inactive[i] of them inactive (captured, kept at the wall)."""
    folder = os.path.join(case, time, "lagrangian", "kinematicCloud")
    os.makedirs(folder, exist_ok=True)
    lines = ["(1 0.5 0.1) %d" % cell
             for cell, n in enumerate(per_cell) for _ in range(n)]
    off = list(inactive) + [0]*len(per_cell)
    active = [0 if k < off[cell] else 1
              for cell, n in enumerate(per_cell) for k in range(n)]
    with open(os.path.join(folder, "positions"), "w") as f:
        f.write(HEADER % "Cloud<basicKinematicCollidingParcel>"
                + "\n%d\n(\n" % len(lines) + "\n".join(lines) + "\n)\n")
    with open(os.path.join(folder, "active"), "w") as f:
        f.write(HEADER % "labelField" + "\n%d\n(\n" % len(active)
                + "\n".join(map(str, active)) + "\n)\n")


def test_cell_volumes_and_cells_on(tmp_path):
    case = str(tmp_path)
    write_column(case)
    assert polymesh.cell_volumes(case) == \
        pytest.approx([0.125]*4, rel=1e-14)
    assert polymesh.cells_on(case, ["floor"]) == [0]
    areas, volume = polymesh.areas_and_volume(case)
    assert volume == pytest.approx(0.5, rel=1e-14)


def test_uniformity_of_the_airborne_parcels(tmp_path):
    case = str(tmp_path)
    write_column(case)
    write_parcels(case, "4", [100, 100, 100, 100])
    write_parcels(case, "8", [300, 40, 30, 30])
    # uniform: the floor's cell (a quarter of the volume) holds a quarter
    ratio, error, n = deposition.uniformity(case, "kinematicCloud",
                                            ["floor"], 3, 5)
    assert (ratio, n) == (pytest.approx(1.0), 400)
    # SE: sqrt(f (1 - f)/n)/s, f the fraction found there, s = 1/4
    assert error == pytest.approx(math.sqrt(0.25*0.75/400)/0.25)
    assert not deposition.far_from_uniform(ratio, error)
    # half of the airborne parcels at the floor (200 of 400 written, 200
    # more there inactive: captured): ratio 2, SE sqrt(0.25/200)/0.25
    write_parcels(case, "9", [400, 100, 50, 50], inactive=[200])
    ratio, error, n = deposition.uniformity(case, "kinematicCloud",
                                            ["floor"], 8.5, 9.5)
    assert (ratio, n) == (pytest.approx(2.0), 400)
    assert error == pytest.approx(math.sqrt(0.25/400)/0.25)
    assert not deposition.far_from_uniform(ratio, error)
    # gathered at the floor: 300 of 400 in a quarter of the volume
    ratio, error, n = deposition.uniformity(case, "kinematicCloud",
                                            ["floor"], 5, 8.5)
    assert ratio == pytest.approx(3.0)
    assert deposition.far_from_uniform(ratio, error)
    assert deposition.uniformity(case, "kinematicCloud", ["floor"],
                                 10, 20) is None


def test_far_from_uniform_beyond_three_errors_of_the_band():
    assert not deposition.far_from_uniform(2.1, 0.3)
    assert deposition.far_from_uniform(2.1, 0.01)
    assert deposition.far_from_uniform(0.4, 0.01)
    assert not deposition.far_from_uniform(0.45, 0.1)
    assert not deposition.far_from_uniform(1.0, 0.0)


def test_command_line_warns_of_a_gathered_profile(tmp_path, capsys):
    case = str(tmp_path)
    write_column(case)
    write_tables(case)
    write_parcels(case, "8", [300, 40, 30, 30])
    assert main(["depositionVelocity", case, "-start", "3"]) == 0
    assert "warning: the airborne concentration in the cells on floor " \
        "is 3 +- 0.087 times the mean" in capsys.readouterr().err
