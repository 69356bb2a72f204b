# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""microsphereImpact: the paper's validation in the solver.

From the model's impact records and statistics, and impactCalc on the same
patch entry:

    results.csv  per parcel: the solver's fate and rebound speed (the impact
                 records) and the core's (impactCalc), their relative
                 difference
    critical.csv the model's critical speeds (impactCalc -critical)
    coreCurves.csv, core.csv  the core's rebounds (impactCalc)
    log.table    the headline table (also printed): per diameter, the
                 parcels captured and rebounded (the model's statistics),
                 the fastest captured and the slowest rebounding parcel, the
                 critical speed of the model and of the paper's Figure 5
                 (figure5.csv)
    rebound.png  the rebound ratio Un'/un against the impact speed
"""

import os
import subprocess

from .. import curves, foam, statistics, tables

FIGURE5 = "figure5.csv"


def shots(table):
    """(diameter, speed) of each row of a kinematicLookupTableInjection
    table: (x y z) (Ux Uy Uz) d rho mDot."""
    rows = foam.list_file(table)
    if len(rows) % 5:
        raise ValueError(f"{table}: rows of 5 entries expected")
    return [(rows[i + 2], abs(rows[i + 1][2])) for i in range(0, len(rows), 5)]


def parcel_rows(figure5, n):
    """The rows of the parcel tables (constant/parcels.full: n = 24,
    parcels.reduced: n = 8): per diameter of figure5.csv, n speeds
    log-spaced over 0.3-100 m/s and 0.98 and 1.02 times its Figure 5
    critical speed, in order of speed; normal impact at the plate from 0.1
    mm above it, x = 0.7 mm + 1.4 mm per speed, y = 1.25 mm + 2.5 mm per
    diameter; rho 1350 (constantProperties rho0), mDot 1."""
    rows = []
    for j, (d, vc) in enumerate(zip(figure5.text("diameter"),
                                    figure5["criticalSpeed"])):
        speeds = ["%.6g" % v for v in curves.log_space(0.3, 100, n)]
        speeds += ["%.6g" % (0.98 * vc), "%.6g" % (1.02 * vc)]
        for i, speed in enumerate(sorted(speeds, key=float)):
            rows.append("(%.6g %.6g 1e-4) (0 0 -%s) %s 1350 1" % (
                (0.7 + 1.4 * i) * 1e-3, (1.25 + 2.5 * j) * 1e-3, speed, d))
    return rows


def impact_calc(output, *options):
    """Run impactCalc on the case, its CSV in `output`."""
    with open(output, "w") as f:
        result = subprocess.run(["impactCalc", *options], stdout=f,
                                stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"impactCalc {' '.join(options)}: "
                           f"{result.stderr.strip()}")
    return tables.read(output)


def _key(d, speed):
    return "%.6g %.6g" % (d, speed)


def _list(values):
    return "(" + " ".join(repr(v) for v in values) + ")"


RESULT_COLUMNS = ["diameter", "speed", "solverCaptured", "solverUnOut",
                  "coreCaptured", "coreUnOut", "relativeDifference"]


def result_rows(records, core):
    """The first impact on the plate of each parcel (diameter, speed)
    against the core's, ordered by diameter and speed."""
    expected = {_key(d, v): (c, u) for d, v, c, u in zip(
        core["diameter"], core["speed"], core["captured"], core["unOut"])}
    rows, seen = [], set()
    plate = records.where(patch="plate")
    for d_text, un_text, outcome, un_out in zip(
            plate.text("diameter"), plate.text("un"), plate.text("outcome"),
            plate["unOut"]):
        if (d_text, un_text) in seen:
            continue
        seen.add((d_text, un_text))
        captured, out = expected[_key(float(d_text), float(un_text))]
        difference = abs(un_out - out)
        rows.append([d_text, un_text, "%d" % (outcome == "capture"),
                     "%.17g" % un_out, "%d" % captured, "%.17g" % out,
                     "%.3g" % (difference / out if out > 0 else difference)])
    return sorted(rows, key=lambda r: (float(r[0]), float(r[1])))


def headline(shot_list, critical, figure5, last, results):
    """Per diameter: parcels shot, captured and rebounded (statistics, one
    size class per diameter), the fastest captured and slowest rebounding
    parcel, the critical speeds; a flag where the records disagree."""
    def key(d):
        return "%.6g" % d
    shot = {}
    for d, _ in shot_list:
        shot[key(d)] = shot.get(key(d), 0) + 1
    vc = {key(d): v for d, v in zip(critical["diameter"],
                                    critical["criticalSpeed"])}
    fig = {key(d): v for d, v in zip(figure5["diameter"],
                                     figure5["criticalSpeed"])}
    plate = last.where(patch="plate")
    lines = []
    for k in sorted(shot, key=float):
        d = float(k)
        of = plate.where(dMin=lambda lo: d >= float(lo),
                         dMax=lambda hi: hi == "inf" or d < float(hi))
        s_captured = of.sum("captureParcels")
        s_rebound = of.sum("reboundParcels")
        mine = results.where(diameter=lambda t: key(float(t)) == k)
        captured = mine.where(solverCaptured="1")
        rebound = mine.where(solverCaptured="0")
        cap_max = max(captured["speed"], default=0)
        reb_min = min(rebound["speed"], default=0)
        flag = "  FATE MISMATCH" if any(
            a != b for a, b in zip(mine.text("solverCaptured"),
                                   mine.text("coreCaptured"))) else ""
        if s_captured != len(captured) or s_rebound != len(rebound) or \
                len(captured) + len(rebound) != shot[k]:
            flag += "  RECORDS: %d captured, %d rebounded" % (
                len(captured), len(rebound))
        lines.append(
            "%-7.3g %7d %8d %7d   <= %-7.4g | >= %-7.4g %-10.4g %-10.4g "
            "%.2g%s" % (d * 1e6, shot[k], s_captured, s_rebound, cap_max,
                        reb_min, vc[k], fig[k],
                        max(mine["relativeDifference"], default=0), flag))
    return ["", "microsphereImpact: NH4-fluorescein on molybdenum, normal "
            "impact", "(Brach & Dunn 1992: Eq. 23 restitution, Eq. 24 "
            "adhesion)", "",
            "%-7s %7s %8s %7s   %-23s %-10s %-10s %s" % (
                "d [um]", "parcels", "captured", "rebound",
                "v captured | rebound", "v_c model", "v_c Fig. 5",
                "max |solver/core - 1| of Un'")] + lines + [
        "", "captured, rebound: parcels (the model's statistics); v "
        "captured | rebound: the fastest",
        "captured and the slowest rebounding parcel [m/s]; v_c: critical "
        "speed [m/s]",
        "Results: results.csv (solver vs core), critical.csv; plot: "
        "rebound.png"]


def plot_rebound(path, diameters, curves_table, results, figure5):
    from .. import plots
    fig, ax = plots.figure(10, 6.5)
    for c, d in enumerate(diameters):
        colour = "C%d" % c

        def near(t, d=d):
            return abs(float(t) / d - 1) < 1e-3
        curve = curves_table.where(diameter=near)
        ax.plot(curve["speed"], curve["unOut"] / curve["un"], color=colour,
                label="%.3g um core" % (d * 1e6))
        mine = results.where(diameter=near)
        ax.plot(mine["speed"], mine["solverUnOut"] / mine["speed"], "o",
                color=colour, label="%.3g um solver" % (d * 1e6))
        for v in figure5.where(diameter=near)["criticalSpeed"]:
            ax.axvline(v, color=colour, ls="--", lw=1)
    plots.axes(ax, "impact speed [m/s]", "rebound ratio Un'/un",
               "NH4-fluorescein on molybdenum (Brach and Dunn 1992); "
               "dashed: Figure 5 critical speeds",
               xlim=(0.25, 120), ylim=(0, 1), xlog=True)
    ax.legend(loc="center left", bbox_to_anchor=(1, 0.5))
    plots.save(fig, path)


def run(case="."):
    os.chdir(case)
    table = os.path.join("constant", str(foam.value("constant/parcelSettings",
                                                    "table")))
    shot_list = shots(table)
    diameters = list(dict.fromkeys(d for d, _ in shot_list))
    speeds = list(dict.fromkeys(v for _, v in shot_list))
    records = statistics.read_impacts()
    last = statistics.read_statistics().last_time()

    core = impact_calc("core.csv", "-precision", "17", "-patch", "plate",
                       "-diameters", _list(diameters),
                       "-speeds", _list(speeds))
    critical = impact_calc("critical.csv", "-patch", "plate", "-diameters",
                           _list(diameters), "-critical")
    curve_speeds = ["%.6g" % v for v in curves.log_space(0.3, 100, 301)]
    core_curves = impact_calc("coreCurves.csv", "-patch", "plate",
                              "-diameters", _list(diameters), "-speeds",
                              "(" + " ".join(curve_speeds) + ")")

    tables.write_csv("results.csv", RESULT_COLUMNS,
                     result_rows(records, core))
    results = tables.read("results.csv")
    figure5 = tables.read(FIGURE5)
    lines = headline(shot_list, critical, figure5, last, results)
    with open("log.table", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot_rebound("rebound.png", diameters, core_curves, results, figure5)
