# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""bendDeposition: deposition in a 90-degree bend against Pui et al. (1987).

From the model's statistics per injector (injectorID = 100 Stk) of the
sub-cases `stick/` and `adhesive/`:

    results.csv      per wall model and Stokes number: parcels captured on
                     each wall, escaped, still airborne; deposition in the
                     bend and its binomial standard error
    correlation.csv  the laminar correlation of Pui et al. (1987)
    yardstick.csv    stick walls judged as deposition curves are judged
    log.table        the headline table (also printed)
    deposition.png   deposition against Stokes number
    depositionMap.png, <model>/depositionMap.csv
                     where the parcels land on the unrolled tube wall, from
                     the impact records

Reference data, each citing its source, beside the case:
pui1987-bend-laminar-Re1000.csv (measured), vasquez2015-bend-Re1000.csv
(simulated).
"""

import math
import os

from .. import correlations, curves, foam, statistics, tables

MEASURED = "pui1987-bend-laminar-Re1000.csv"
SIMULATED = "vasquez2015-bend-Re1000.csv"
MODELS = ("stick", "adhesive")
WALLS = ("inletWall", "bendWall", "outletWall")
OPENINGS = ("inlet", "outlet")

# The yardstick's tolerances (README): Stk of 50 % and of each measured
# 10-90 % point relative, points above Stk 0.7 and against the two-fluid
# simulation in percentage points
STK50_TOLERANCE = 0.10
STK_AT_TOLERANCE = 0.15
HIGH_STK = 0.7
HIGH_STK_TOLERANCE = 5
SIMULATION_TOLERANCE = 3


GOLDEN_ANGLE = 2.39996322972865332       # rad


def flow_weighted_positions(n, a, x):
    """n start positions in the plane x across a tube of radius a, spread in
    proportion to the Poiseuille flow: point i takes the radius enclosing
    the fraction F = (i + 1/2)/n of the flow, F = 2 (r/a)^2 - (r/a)^4, and
    the angle i g, g the golden angle. As the text of a positions file's
    list."""
    rows = []
    for i in range(n):
        r = a * curves.poiseuille_flux_radius((i + 0.5) / n)
        t = i * GOLDEN_ANGLE
        rows.append("(%s %.9g %.9g)" % (x, r * math.cos(t), r * math.sin(t)))
    return rows


def injectors(model):
    """(injectorID, diameter) of each injector of a sub-case, and the
    parcels each injects (its positions file)."""
    entries = foam.fixed_size_injectors(model)
    found = [(injector_id, d) for _, injector_id, d, _ in entries]
    positions = {path for *_, path in entries}
    if len(positions) != 1:
        raise ValueError(f"{model}: injectors with positions {positions}")
    parcels = len(foam.list_file(os.path.join(model, "constant",
                                              positions.pop())))
    if parcels <= 0:
        raise ValueError(f"{model}: no parcels in the positions file")
    return found, parcels


RESULT_COLUMNS = ["Stk", "d", "model", "parcels", *WALLS, "escaped",
                  "airborne", "bendPercent", "bendSE", "tubePercent"]


def result_rows(model):
    """The rows of results.csv of one wall model, in order of Stk."""
    found, n = injectors(model)
    last = statistics.read_statistics(model).last_time()
    rows = []
    for injector, diameter in found:
        of = last.where(injector=str(injector))
        captured = {wall: statistics.final(of, "captureParcels", patch=wall)
                    for wall in WALLS}
        escaped = sum(statistics.final(of, "escapeParcels", patch=opening)
                      for opening in OPENINGS)
        walls = sum(captured.values())
        p = captured["bendWall"] / n
        rows.append((injector / 100, [
            "%.2f" % (injector / 100), "%.6g" % diameter, model, "%d" % n,
            *("%d" % captured[wall] for wall in WALLS), "%d" % escaped,
            "%d" % (n - walls - escaped), "%.4g" % (100 * p),
            "%.3g" % (100 * math.sqrt(p * (1 - p) / n)),
            "%.4g" % (100 * walls / n)]))
    return [row for _, row in sorted(rows, key=lambda r: float(r[1][0]))]


def correlation_rows():
    """The laminar correlation on the tutorial's Stokes number (on the tube
    radius: St on the diameter is Stk/2), Stk 0.05-1.5."""
    rows = []
    for i in range(146):
        stk = 0.05 + i * 0.01
        rows.append(["%.4g" % stk,
                     "%.4g" % (100 * correlations.pui_bend_laminar(stk / 2))])
    return rows


def yardstick(results, measured, simulated):
    """The stick curve judged as deposition curves are judged: a list of
    (check, quantity, reference, simulated, difference, tolerance), the
    difference relative for Stokes numbers and in points for percentages,
    None where the simulated curve does not reach the value. Curves are
    interpolated linearly between their points.

      Stk50          Stk of 50 % deposition, within 10 % of the measured one
      StkAt<percent> at each measured point of 10-90 %: the Stk at which the
                     simulation deposits as much, within 15 % of the
                     measured Stk
      at<Stk>        measured points with Stk >= 0.7: within 5 points
      tail<Stk>      measured points below 10 %: reported (tolerance None)
      vasquezAt<Stk> the two-fluid simulation of the experiment: 3 points
    """
    stick = results.where(model="stick")
    s_stk, s_dep = list(stick["Stk"]), list(stick["bendPercent"])
    m_stk, m_dep = list(measured["Stk"]), list(measured["efficiencyPercent"])
    rows = []

    def relative(value, reference):
        return None if value is None else value / reference - 1

    def points(value, reference):
        return None if value is None else value - reference

    measured50 = curves.interpolate(50, m_dep, m_stk)
    simulated50 = curves.interpolate(50, s_dep, s_stk)
    rows.append(("Stk50", "Stk", measured50, simulated50,
                 relative(simulated50, measured50), STK50_TOLERANCE))
    for stk_text, stk, dep_text, dep in zip(measured.text("Stk"), m_stk,
                                            measured.text("efficiencyPercent"),
                                            m_dep):
        if 10 <= dep <= 90:
            at = curves.interpolate(dep, s_dep, s_stk)
            rows.append(("StkAt" + dep_text, "Stk", stk, at,
                         relative(at, stk), STK_AT_TOLERANCE))
        value = curves.interpolate(stk, s_stk, s_dep)
        if stk >= HIGH_STK:
            rows.append(("at" + stk_text, "percent", dep, value,
                         points(value, dep), HIGH_STK_TOLERANCE))
        if dep < 10:
            rows.append(("tail" + stk_text, "percent", dep, value,
                         points(value, dep), None))
    for stk_text, stk, dep in zip(simulated.text("Stk"), simulated["Stk"],
                                  simulated["efficiencyPercent"]):
        value = curves.interpolate(stk, s_stk, s_dep)
        rows.append(("vasquezAt" + stk_text, "percent", dep, value,
                     points(value, dep), SIMULATION_TOLERANCE))
    return rows


def verdict(difference, tolerance):
    """pass, fail or reported: a difference passes when it is a number
    within the tolerance."""
    if tolerance is None:
        return "reported"
    if difference is None or math.isnan(difference):
        return "fail"
    return "pass" if abs(difference) <= tolerance else "fail"


def _g(value, digits):
    return "none" if value is None else "%.*g" % (digits, value)


def write_yardstick(path, rows):
    with open(path, "w") as f:
        f.write("check,quantity,reference,simulated,difference,tolerance,"
                "result\n")
        for check, quantity, reference, value, difference, tolerance in rows:
            f.write("%s,%s,%.4g,%s,%s,%s,%s\n" % (
                check, quantity, reference, _g(value, 4), _g(difference, 3),
                "-" if tolerance is None else "%g" % tolerance,
                verdict(difference, tolerance)))


def headline(results, measured, simulated, correlation, judged):
    """The headline table's lines, from the files results.csv,
    correlation.csv and yardstick.csv (`judged`) as written."""
    data = {"%.2f" % s: t for s, t in zip(measured["Stk"],
                                          measured.text("efficiencyPercent"))}
    other = {"%.2f" % s: t for s, t in zip(simulated["Stk"],
                                           simulated.text("efficiencyPercent"))}
    fit = {"%.2f" % s: p for s, p in zip(correlation["Stk"],
                                         correlation["depositionPercent"])}
    lines = ["", "bendDeposition: 90-degree bend, Rb/a = 5.7, laminar Re = 1000",
             "deposition in the bend [%] +- binomial standard error; left: "
             "% still in the tube", "",
             "%-5s %-6s %-13s %-5s %-13s %-5s %-9s %-9s %s" % (
                 "Stk", "d [um]", "stick", "left", "adhesive", "left",
                 "measured", "Vasquez", "correlation")]
    for stk in results.unique("Stk"):
        of = {model: results.where(Stk=stk, model=model) for model in MODELS}
        cells = []
        for model in MODELS:
            row = of[model]
            cells += [row["bendPercent"][0], row["bendSE"][0],
                      100 * row["airborne"][0] / row["parcels"][0]]
        key = "%.2f" % float(stk)
        lines.append(
            "%-5s %-6.3g %5.1f +- %-4.1f %-5.1f %5.1f +- %-4.1f %-5.1f "
            "%-9s %-9s %.1f" % (stk, of["adhesive"]["d"][0] * 1e6, *cells,
                                data.get(key, "-"), other.get(key, "-"),
                                fit[key]))
    lines += ["", "stick walls, judged as deposition curves are "
              "(yardstick.csv):"]
    for row in range(len(judged)):
        def cell(name, row=row):
            return judged.text(name)[row]

        def number(name, row=row):
            return None if cell(name) == "none" else float(cell(name))
        check, value, difference = cell("check"), number("simulated"), \
            number("difference")
        if cell("quantity") == "Stk":
            lines.append(
                "  %-18s Stk %s, measured %.3g: %s %% (within %d %%): %s" % (
                    check, _g(value, 3), number("reference"),
                    "none" if difference is None else "%+.1f" % (
                        100 * difference), 100 * number("tolerance"),
                    cell("result")))
        else:
            lines.append(
                "  %-18s %s %%, reference %.1f %%: %s points (within %s): %s"
                % (check, "none" if value is None else "%.1f" % value,
                   number("reference"), "none" if difference is None else
                   "%+.1f" % difference, cell("tolerance"), cell("result")))
    lines += ["", "Results: results.csv, yardstick.csv; plots: deposition.png,"
              " depositionMap.png"]
    return lines


# --- The deposition map ----------------------------------------------------

MAP_BINS_BEND = 20          # along the bend
MAP_BINS_BEFORE = 4         # of the same length, before and after it
MAP_BINS_AFTER = 8
MAP_ANGLE_BIN = 10          # degrees


def unrolled(x, y, z, Rb):
    """A point of the tube's wall as (s, phi): s along the tube's axis from
    the start of the bend (which turns about z through (0, Rb, 0), from the
    inlet tube along +x at y = 0 to the outlet tube along +y at x = Rb),
    phi around the tube in degrees (0: the outer wall of the bend, +-180
    the inner, +90 +z)."""
    if x < 0:                                       # inlet tube
        s, radial = x, -y
    elif y > Rb:                                    # outlet tube
        s, radial = Rb * math.pi / 2 + y - Rb, x - Rb
    else:
        theta = math.atan2(x, Rb - y)
        s = Rb * theta
        radial = (x - Rb * math.sin(theta)) * math.sin(theta) \
            - (y - Rb + Rb * math.cos(theta)) * math.cos(theta)
    return s, math.atan2(z, radial) * 180 / math.pi


def deposition_map(impacts, a, Rb):
    """Parcels captured on the walls per mm^2 of wall, binned along the tube
    (1/20 of the bend) and around it (10 degrees); bin areas those of the
    torus in the bend, a dphi ds (1 + a cos(phi)/Rb). Rows of
    (s [mm], phi [deg], density [1/mm^2]) at the bins' centres."""
    ds = Rb * math.pi / 2 / MAP_BINS_BEND
    n_s = MAP_BINS_BEND + MAP_BINS_BEFORE + MAP_BINS_AFTER
    n_phi = 360 // MAP_ANGLE_BIN
    count = [[0] * n_phi for _ in range(n_s)]
    captured = impacts.where(outcome="capture",
                             patch=lambda p: p.endswith("Wall"))
    for x, y, z in zip(captured["x"], captured["y"], captured["z"]):
        s, phi = unrolled(x, y, z, Rb)
        position = (s + MAP_BINS_BEFORE * ds) / ds
        if position < 0:
            continue
        i = int(position)
        j = min(int((phi + 180) / MAP_ANGLE_BIN), n_phi - 1)   # phi = 180
        if i < n_s:
            count[i][j] += 1
    rows = []
    for i in range(n_s):
        for j in range(n_phi):
            s_mid = (i - MAP_BINS_BEFORE + 0.5) * ds
            phi_mid = -180 + (j + 0.5) * MAP_ANGLE_BIN
            area = a * MAP_ANGLE_BIN * math.pi / 180 * ds
            if 0 < s_mid < Rb * math.pi / 2:
                area *= 1 + a * math.cos(phi_mid * math.pi / 180) / Rb
            rows.append((s_mid * 1e3, phi_mid, count[i][j] / (area * 1e6)))
    return rows


# --- Plots -----------------------------------------------------------------

def plot_deposition(path, results, measured, simulated, correlation):
    from .. import plots
    fig, ax = plots.figure(9, 6)
    ax.plot(correlation["Stk"], correlation["depositionPercent"], "--",
            color="0.4", label="Pui et al. (1987) laminar correlation")
    ax.plot(measured["Stk"], measured["efficiencyPercent"], "ks", ms=8,
            label="Pui et al. (1987) measured")
    ax.plot(simulated["Stk"], simulated["efficiencyPercent"], "D",
            color="darkgreen", ms=8,
            label="Vasquez et al. (2015) two-fluid simulation")
    for model, style, label in (
            ("stick", "o-", "this model, stick walls"),
            ("adhesive", "^-", "this model, adhesive walls "
             "(NH4-fluorescein on molybdenum)")):
        rows = results.where(model=model)
        ax.errorbar(rows["Stk"], rows["bendPercent"], yerr=rows["bendSE"],
                    fmt=style, capsize=3, label=label)
    ax.set_xlim(0, 1.5)
    ax.set_ylim(0, 105)
    ax.set_xlabel("Stokes number Stk = rho_p d^2 U / (18 mu a)")
    ax.set_ylabel("deposition in the bend [%]")
    ax.set_title("90-degree bend, Rb/a = 5.7, laminar Re = 1000")
    ax.legend(loc="lower right")
    plots.save(fig, path)


def plot_deposition_map(path, maps, Rb):
    from .. import plots
    import numpy as np
    fig, axes = plots.figure(10, 8, rows=2)
    ds_mm = Rb * math.pi / 2 / MAP_BINS_BEND * 1e3
    top = max(max(r[2] for r in rows) for rows in maps.values()) or 1
    for ax, (model, title) in zip(axes, (
            ("stick", "stick walls"),
            ("adhesive", "adhesive walls (NH4-fluorescein on molybdenum)"))):
        rows = maps[model]
        n_phi = 360 // MAP_ANGLE_BIN
        density = np.array([r[2] for r in rows]).reshape(-1, n_phi).T
        s0 = -MAP_BINS_BEFORE * ds_mm
        s1 = (MAP_BINS_BEND + MAP_BINS_AFTER) * ds_mm
        image = ax.imshow(density, origin="lower", aspect="auto",
                          extent=(s0, s1, -180, 180), vmin=0, vmax=top,
                          cmap="YlOrBr", interpolation="nearest")
        for s in (0, Rb * math.pi / 2 * 1e3):
            ax.axvline(s, color="k", ls="--", lw=1)
        ax.set_yticks([-180, -90, 0, 90, 180])
        ax.set_yticklabels(["inner", "-90", "outer", "90", "inner"])
        ax.set_xlabel("s, position along the tube axis from the start of "
                      "the bend [mm]")
        ax.set_ylabel("angle around the tube [deg]")
        ax.set_title(title)
        fig.colorbar(image, ax=ax, label="parcels captured per mm^2")
    fig.suptitle("Where parcels deposit: the tube wall unrolled (all Stokes "
                 "numbers; bend between the dashed lines)")
    plots.save(fig, path)


# --- The whole post-processing ---------------------------------------------

def run(case="."):
    os.chdir(case)
    measured = tables.read(MEASURED)
    simulated = tables.read(SIMULATED)
    a = float(foam.value("constant/parameters", "a"))
    Rb = float(foam.value("constant/parameters", "Rb"))

    rows = []
    for model in MODELS:
        rows += result_rows(model)
    if len(rows) < 2:
        raise ValueError("no results")
    tables.write_csv("results.csv", RESULT_COLUMNS, rows)
    tables.write_csv("correlation.csv", ["Stk", "depositionPercent"],
                     correlation_rows())
    results = tables.read("results.csv")
    correlation = tables.read("correlation.csv")

    write_yardstick("yardstick.csv", yardstick(results, measured, simulated))
    lines = headline(results, measured, simulated, correlation,
                     tables.read("yardstick.csv"))
    with open("log.table", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    plot_deposition("deposition.png", results, measured, simulated,
                    correlation)
    maps = {}
    for model in MODELS:
        maps[model] = deposition_map(statistics.read_impacts(model), a, Rb)
        tables.write_csv(os.path.join(model, "depositionMap.csv"),
                         ["s", "angle", "capturedPerMm2"],
                         [("%.4g" % s, "%.4g" % phi, "%.5g" % n)
                          for s, phi, n in maps[model]])
    plot_deposition_map("depositionMap.png", maps, Rb)
