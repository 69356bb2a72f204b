# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The tutorials' own computations, on inputs whose answer is known."""

import math
import os
import shutil

import pytest

from adhesivewall import tables
from adhesivewall.tutorials import bend_deposition as bend

A, RB = 2.5e-3, 5.7 * 2.5e-3


@pytest.mark.parametrize("where, point, expected", [
    ("inlet, outer wall", (-0.005, -A, 0), (-0.005, 0)),
    ("bend at 45 deg, outer wall",
     ((RB + A) * math.sin(math.pi / 4), RB - (RB + A) * math.cos(math.pi / 4),
      0), (RB * math.pi / 4, 0)),
    ("bend at 45 deg, inner wall",
     ((RB - A) * math.sin(math.pi / 4), RB - (RB - A) * math.cos(math.pi / 4),
      0), (RB * math.pi / 4, 180)),
    ("bend at 30 deg, +z", (RB * 0.5, RB - RB * math.sqrt(3) / 2, A),
     (RB * math.pi / 6, 90)),
    ("outlet, outer wall", (RB + A, RB + 0.01, 0), (RB * math.pi / 2 + 0.01, 0)),
])
def test_bend_wall_unrolled(where, point, expected):
    s, phi = bend.unrolled(*point, RB)
    assert s == pytest.approx(expected[0], abs=1e-12), where
    assert abs(phi) == pytest.approx(expected[1], abs=1e-9), where


def test_deposition_map_holds_every_capture(tmp_path):
    # density x bin area summed over the map gives back the captures on the
    # walls (none on other patches, no rebounds)
    path = tmp_path / "impacts.csv"
    rows = ["patch,x,y,z,outcome"]
    for i in range(36):
        theta = (i + 0.5) / 36 * math.pi / 2
        phi = 2 * math.pi * i / 36
        radial, z = A * math.cos(phi), A * math.sin(phi)
        x = (RB + radial) * math.sin(theta)
        y = RB - (RB + radial) * math.cos(theta)
        rows.append(f"bendWall,{x!r},{y!r},{z!r},capture")
    rows.append("bendWall,0.001,0,0.0025,rebound")
    rows.append("outlet,0.0143,0.03,0,escape")
    path.write_text("\n".join(rows) + "\n")
    density = bend.deposition_map(tables.read(path), A, RB)
    ds = RB * math.pi / 2 / bend.MAP_BINS_BEND
    total = 0
    for s, phi, n in density:
        area = A * math.radians(bend.MAP_ANGLE_BIN) * ds
        if 0 < s * 1e-3 < RB * math.pi / 2:
            area *= 1 + A * math.cos(math.radians(phi)) / RB
        total += n * area * 1e6
    assert total == pytest.approx(36, rel=1e-12)


def test_yardstick_of_the_measured_curve_itself(tmp_path):
    measured = tables.read_text(
        "Stk,efficiencyPercent\n0.17,5.3\n0.28,24.5\n0.37,63.2\n0.57,84.9\n"
        "0.90,94.8\n1.24,94.2\n")
    simulated = tables.read_text("Stk,efficiencyPercent\n0.28,33.16\n")
    lines = ["Stk,model,bendPercent"] + [
        f"{s},stick,{p}" for s, p in zip(measured.text("Stk"),
                                         measured.text("efficiencyPercent"))]
    same = tables.read_text("\n".join(lines) + "\n")
    judged = {row[0]: row for row in bend.yardstick(same, measured, simulated)}
    assert judged["Stk50"][4] == pytest.approx(0, abs=1e-12)
    assert judged["StkAt63.2"][4] == pytest.approx(0, abs=1e-12)
    assert judged["at1.24"][4] == pytest.approx(0, abs=1e-12)
    assert judged["vasquezAt0.28"][4] == pytest.approx(24.5 - 33.16)
    assert bend.verdict(judged["vasquezAt0.28"][4], 3) == "fail"
    assert bend.verdict(judged["Stk50"][4], 0.1) == "pass"
    assert bend.verdict(None, 0.1) == "fail"
    assert bend.verdict(judged["tail0.17"][4], None) == "reported"
    # a curve shifted 20 % in Stk misses the 15 % of StkAt and 10 % of Stk50
    lines = ["Stk,model,bendPercent"] + [
        f"{1.2 * s},stick,{p}" for s, p in zip(measured["Stk"],
                                               measured["efficiencyPercent"])]
    shifted = {row[0]: row for row in bend.yardstick(
        tables.read_text("\n".join(lines) + "\n"), measured, simulated)}
    assert shifted["Stk50"][4] == pytest.approx(0.2)
    assert bend.verdict(shifted["StkAt24.5"][4], 0.15) == "fail"


def test_settling_channel_takes_the_slip_of_the_cloud_drag(tmp_path):
    # The prediction's settling velocity has the slip of the case's drag:
    # none with the tutorial's sphereDrag, slipSphereDrag's given mean
    # free path and coefficients, or the one of its p and T (kinetic
    # theory with the carrier's viscosity, as the force computes it)
    from adhesivewall import correlations
    from adhesivewall.tutorials import settling_channel
    source = os.path.join(os.path.dirname(__file__), "..", "..",
                          "tutorials", "settlingChannel", "particles")
    case = tmp_path / "particles"
    shutil.copytree(source, case)
    mu = 1.8e-5
    assert settling_channel.slip(str(case), mu) == (0.0, "Davies")
    properties = case / "constant" / "kinematicCloudProperties"
    text = properties.read_text()
    assert "        sphereDrag;\n" in text

    def drag(entry):
        properties.write_text(text.replace("        sphereDrag;\n",
                                           f"        {entry}\n"))
        return settling_channel.slip(str(case), mu)
    assert drag("slipSphereDrag { meanFreePath 6.65e-8; }") == \
        (6.65e-8, "Davies")
    assert drag("slipSphereDrag { slipCoefficients AllenRaabe; "
                "meanFreePath 6.73e-8; }") == (6.73e-8, "AllenRaabe")
    # Air at 293.15 K and 101325 Pa with mu 1.8e-5: 64.7 nm by Jennings'
    # formula worked by hand (rho = p M/(R T) = 1.2041 kg/m^3)
    free_path, coefficients = drag("slipSphereDrag { p 101325; T 293.15; }")
    assert coefficients == "Davies"
    assert free_path == pytest.approx(
        math.sqrt(math.pi / 8) * mu
        / (0.4987445 * math.sqrt(1.2041 * 101325)), rel=1e-4)
    assert free_path == pytest.approx(6.475e-8, rel=1e-3)
    # Neither a mean free path nor p and T (the solver would stop): said
    with pytest.raises(ValueError, match="neither meanFreePath nor p and T"):
        drag("slipSphereDrag;")
    with pytest.raises(ValueError, match="neither meanFreePath nor p and T"):
        drag("slipSphereDrag { p 101325; }")


def test_fibre_filter_headline_flags_what_its_correlations_cannot_judge():
    # A face velocity of fibre Reynolds number 33 (50 typed for 0.5 m/s) is
    # beyond the creeping-flow correlations; a lowest efficiency at the
    # edge of the sizes run is no most penetrating size
    from types import SimpleNamespace
    from adhesivewall.tutorials import fibre_filter
    names = ["U0", "d", "model", "eta", "etaSE", "Stk", "R", "Pe", "Re_f",
             "etaD", "etaR", "etaDR", "etaI", "etaSum", "airborne", "band",
             "outer", "captured"]
    rows = []
    for U, reynolds in (("0.5", "0.33"), ("50", "33")):
        for d, eta in (("3e-07", "0.004"), ("1e-06", "0.03")):
            for model in ("stick", "adhesive"):
                rows.append((U, d, model, eta, "0.001", "0.03", "0.03",
                             "4e4", reynolds, "0.003", "0.001", "0.001",
                             "", "0.005", "0", "1e-05", "1", "40"))
    # a band with 6 of its 40 captures in its outer half (max(2, 10 %): 4)
    rows[0] = rows[0][:-2] + ("6", "40")
    results = tables.Table(names, rows)
    mpps = tables.Table(
        ["U0", "d", "eta", "etaSE", "model", "dLeeLiu", "etaLeeLiu"],
        [("0.5", "3e-07", "0.004", "0.001", "stick", "2e-07", "0.005")])
    fibre = SimpleNamespace(dFibre=10e-6, alpha=0.08, T=293.15, h=31.3e-6)
    text = "\n".join(fibre_filter.headline(results, mpps, fibre))
    assert ("stick, 0.3 um at 0.5 m/s: 6 of 40 captures in the outer half "
            "of the band") in text
    assert text.count("captures in the outer half") == 1
    assert "fibre Reynolds number 33 at 50 m/s: beyond the creeping" in text
    assert "at 0.5 m/s: the" not in text
    assert ("most penetrating size at 0.5 m/s (stick): not among the sizes "
            "run (the lowest efficiency is at the smallest, 0.3 um)") in text
    # Inside the sizes run it is reported with Lee & Liu's ratios
    mpps = tables.Table(mpps.names, [("0.5", "1e-06", "0.03", "0.001",
                                      "stick", "2e-07", "0.005")])
    rows.append(("0.5", "3e-06", "stick", "0.5", "0.01", "2", "0.3", "1e6",
                 "0.33", "0.001", "0.1", "0.001", "", "", "0", "1e-05", "",
                 "100"))
    rows.append(("0.5", "3e-06", "adhesive", "0.4", "0.01", "2", "0.3",
                 "1e6", "0.33", "0.001", "0.1", "0.001", "", "", "0", "1e-05",
                 "", "80"))
    text = "\n".join(fibre_filter.headline(tables.Table(names, rows), mpps,
                                           fibre))
    assert "most penetrating size at 0.5 m/s (stick): 1 um, eta 0.03" in text
