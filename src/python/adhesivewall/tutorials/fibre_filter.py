# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""fibreFilter: the single-fibre efficiency of a filter fibre.

From the model's statistics of each particle sub-case U<U0>/particles and
cloud (stick, adhesive), per injector (one per diameter, on the fibre's own
mesh, contact at the particle's surface):

    results.csv      eta +- its standard error per face velocity, diameter
                     and wall model, with the Kuwabara-flow correlations
                     eta_R, eta_I
    correlation.csv  the correlations' curves per face velocity
    angles.csv       where on the fibre the captures are
    log.table        the headline table (also printed)
    efficiency.png, angles.png

eta = (captured/parcels)(2 band/d_f): the fraction of the flow through the
fibre's projected width d_f that the fibre captures, the parcels evenly
spaced over |y| < band (particles/constant/positions); its standard error
is the binomial one of captured/parcels, scaled alike. Stokes number on
the fibre diameter (Hinds), Stk = rho_p d^2 U0/(18 mu d_f), with Cc = 1
(OpenFOAM's sphereDrag has no slip correction); R = d/d_f.
"""

import glob
import math
import os

from .. import correlations, foam, statistics, tables

CLOUDS = ("stick", "adhesive")
ANGLE_CASES = (("0.1", "2e-6"), ("2", "2e-6"), ("2", "5e-6"), ("2", "10e-6"))


class Filter:
    """The fibre, the gas and the particles of the case."""

    def __init__(self, case="."):
        def value(path, entry):
            return float(foam.value(os.path.join(case, path), entry,
                                    expand=False))
        self.dFibre = value("constant/parameters", "dFibre")
        self.alpha = value("constant/parameters", "alpha")
        self.nu = value("constant/transportProperties", "nu")
        self.mu = self.nu * value("constant/transportProperties", "rhoInf")
        self.rhoP = value("particles/constant/cloudProperties",
                          "constantProperties/rho0")
        # The parcels at y_i = band (2 (i + 1/2)/n - 1), i < n
        y = [abs(p[1]) for p in foam.list_file(
            os.path.join(case, "particles/constant/positions"))]
        self.parcels = len(y)
        self.band = max(y) * self.parcels / (self.parcels - 1)
        # The injectors, one per diameter: (injectorID, d as named, d)
        injectors = foam.dictionary(
            os.path.join(case, "particles/constant/injectors"), expand=False)
        self.injectors = sorted(
            ((entry["injectorID"], name[1:],
              entry["sizeDistribution"]["fixedValueDistribution"]["value"])
             for name, entry in injectors.items() if name != "FoamFile"),
            key=lambda injector: injector[2])

    def stokes(self, d, U):
        return self.rhoP * d * d * U / (18 * self.mu * self.dFibre)


def sub_cases(case="."):
    """The particle sub-cases U<U0>/particles, as (folder, U0 text), by
    U0."""
    found = [(os.path.relpath(folder, case), folder.split(os.sep)[-2][1:])
             for folder in glob.glob(os.path.join(case, "U*", "particles"))]
    if not found:
        raise ValueError("no sub-cases U*/particles: run ./Allrun")
    return sorted(found, key=lambda s: float(s[1]))


RESULT_COLUMNS = ["U0", "d", "Stk", "R", "Re_f", "model", "parcels",
                  "captured", "escaped", "airborne", "eta", "etaSE", "etaR",
                  "etaI"]


def result_rows(fibre, subs):
    rows = []
    for folder, U in subs:
        for cloud in CLOUDS:
            last = statistics.read_statistics(folder, cloud).last_time()
            for injector, d_text, _ in fibre.injectors:
                of = last.where(injector=injector)
                if not len(of):
                    raise ValueError(f"no statistics of injector {injector}"
                                     f" in {folder}, cloud {cloud}")
                captured = of.sum("captureParcels")
                escaped = of.sum("escapeParcels")
                U0, d = float(U), float(d_text)
                n = fibre.parcels
                R = d / fibre.dFibre
                stk = fibre.stokes(d, U0)
                p = captured / n
                scale = 2 * fibre.band / fibre.dFibre
                eta_I = correlations.impaction(fibre.alpha, R, stk)
                rows.append([
                    U, d_text, "%.4g" % stk, "%.4g" % R,
                    "%.3g" % (U0 * fibre.dFibre / fibre.nu), cloud, "%d" % n,
                    "%d" % captured, "%d" % escaped,
                    "%d" % (n - captured - escaped), "%.4g" % (p * scale),
                    "%.3g" % (scale * math.sqrt(p * (1 - p) / n)),
                    "%.6g" % correlations.interception(fibre.alpha, R),
                    "" if eta_I is None else "%.6g" % eta_I])
    return rows


def correlation_rows(fibre, velocities):
    """Smooth curves per face velocity, 0.8-12 um, where the impaction fit
    holds (R < 0.4) and eta_R + eta_I <= 1."""
    rows = []
    for U in velocities:
        for i in range(101):
            d = 0.8e-6 * math.exp(i / 100 * math.log(15))
            stk = fibre.stokes(d, float(U))
            R = d / fibre.dFibre
            eta_R = correlations.interception(fibre.alpha, R)
            eta_I = correlations.impaction(fibre.alpha, R, stk)
            if eta_I is not None and eta_I >= 0 and eta_R + eta_I <= 1:
                rows.append([U] + ["%.5g" % v for v in
                                   (stk, R, eta_R, eta_I, eta_R + eta_I)])
    return rows


def angle_rows(fibre, case="."):
    """Captured particles per 10 degrees of the angle from the upstream
    stagnation point (both sides together), from the impact records (the
    particle's centre at the contact), for small and large Stokes numbers."""
    rows = []
    for U, d in ANGLE_CASES:
        folder = os.path.join(case, f"U{U}", "particles")
        if not os.path.isdir(folder):
            continue
        for cloud in CLOUDS:
            impacts = statistics.read_impacts(folder, cloud)
            captured = impacts.where(patch="fibre", outcome="capture")
            bins = [0] * 18
            for x, y, diameter, n in zip(captured["x"], captured["y"],
                                         captured["diameter"],
                                         captured["nParticle"]):
                if diameter != float(d):
                    continue
                angle = math.atan2(abs(y), -x) * 180 / math.pi
                bins[min(int(angle / 10), 17)] += n
            stk = fibre.stokes(float(d), float(U))
            for i, n in enumerate(bins):
                rows.append([f"U{U}/d{d}", U, d, "%.3g" % stk, cloud,
                             "%d" % (10 * i + 5), "%d" % n])
    return rows


def headline(results, fibre):
    lines = ["", "fibreFilter: single-fibre efficiency, d_f = %g um, solidity"
             " %g, 2D fibre row" % (fibre.dFibre * 1e6, fibre.alpha),
             "eta +- binomial standard error, %d parcels per point; "
             "correlations: Kuwabara flow" % fibre.parcels, "",
             "%-6s %-6s %-6s %-6s %-6s %-15s %-15s %-7s %-7s %s" % (
                 "U0", "Re_f", "d [um]", "Stk", "R", "stick", "adhesive",
                 "eta_R", "eta_I", "eta_R + eta_I")]
    keys = list(dict.fromkeys(zip(results.text("U0"), results.text("d"))))
    for U, d in keys:
        of = {cloud: results.where(U0=U, d=d, model=cloud)
              for cloud in CLOUDS}
        row = of["stick"]
        line = "%-6s %-6.3g %-6.3g %-6.3g %-6.3g %6.3f +- %-5.3f " \
            "%6.3f +- %-5.3f %-7.3f " % (
                U, row["Re_f"][0], float(d) * 1e6, row["Stk"][0], row["R"][0],
                of["stick"]["eta"][0], of["stick"]["etaSE"][0],
                of["adhesive"]["eta"][0], of["adhesive"]["etaSE"][0],
                row["etaR"][0])
        eta_I = row.text("etaI")[0]
        if eta_I:
            line += "%-7.3f %.3f" % (float(eta_I),
                                     row["etaR"][0] + float(eta_I))
        else:
            line += "%-7s %s" % ("-", "- (R >= 0.4)")
        lines.append(line)
    lines += ["", "parcels still airborne at the end: stick %d, adhesive %d"
              % tuple(results.where(model=c).sum("airborne") for c in CLOUDS),
              "", "Results: results.csv, correlation.csv, angles.csv; plots: "
              "efficiency.png, angles.png"]
    return lines


def plot_efficiency(path, results, correlation, fibre):
    from .. import plots
    fig, ax = plots.figure(10, 6.5)
    for c, U in enumerate(results.unique("U0")):
        colour = "C%d" % c
        for cloud, style in (("stick", "o-"), ("adhesive", "o--")):
            rows = results.where(U0=U, model=cloud)
            ax.errorbar(rows["Stk"], rows["eta"], yerr=rows["etaSE"],
                        fmt=style, color=colour, capsize=3,
                        mfc=colour if cloud == "stick" else "none",
                        label=f"{U} m/s {cloud}")
        curve = correlation.where(U0=U)
        ax.plot(curve["Stk"], curve["eta"], ":", color=colour, lw=2,
                label=f"{U} m/s correlation")
    plots.axes(ax, "Stokes number Stk = rho_p d^2 U_0 / (18 mu d_f)",
               "single-fibre efficiency",
               "fibre %g um, solidity %g; solid: stick, dashed: adhesive, "
               "dotted: Kuwabara-flow eta_R + eta_I"
               % (fibre.dFibre * 1e6, fibre.alpha),
               xlim=(0.01, 60), ylim=(0, 1.6), xlog=True)
    ax.legend(loc="center left", bbox_to_anchor=(1, 0.5))
    plots.save(fig, path)


def plot_angles(path, angles, parcels):
    from .. import plots
    subs = angles.unique("case")
    fig, axes = plots.figure(10, 7.5, rows=2, columns=2)
    for ax, sub in zip(axes, subs):
        for shift, cloud in ((-2.5, "stick"), (2.5, "adhesive")):
            rows = angles.where(case=sub, model=cloud)
            ax.bar(rows["angle"] + shift, rows["captured"], width=5,
                   alpha=0.7, edgecolor="k", label=cloud)
        row = angles.where(case=sub)
        ax.set_title("U_0 %s m/s, d %g um, Stk %s" % (
            row.text("U0")[0], row["d"][0] * 1e6, row.text("Stk")[0]))
        ax.set_xlim(0, 180)
        ax.set_xticks(range(0, 181, 30))
        ax.set_xlabel("angle from the upstream stagnation point [deg]")
        ax.set_ylabel("captured parcels per 10 deg")
        ax.legend(loc="upper right")
    for ax in axes[len(subs):]:
        ax.set_visible(False)
    fig.suptitle("Where the fibre captures: %d parcels per case" % parcels)
    plots.save(fig, path)


def run(case="."):
    os.chdir(case)
    fibre = Filter()
    subs = sub_cases()
    for folder, _ in subs:
        for cloud in CLOUDS:
            for name in ("statistics.dat", "impacts.csv"):
                path = os.path.join(statistics.output_folder(folder, cloud),
                                    name)
                if not os.path.isfile(path):
                    raise FileNotFoundError(
                        f"no {name} of the cloud {cloud} in {folder}")
    tables.write_csv("results.csv", RESULT_COLUMNS, result_rows(fibre, subs))
    results = tables.read("results.csv")
    tables.write_csv("correlation.csv",
                     ["U0", "Stk", "R", "etaR", "etaI", "eta"],
                     correlation_rows(fibre, results.unique("U0")))
    tables.write_csv("angles.csv", ["case", "U0", "d", "Stk", "model",
                                    "angle", "captured"], angle_rows(fibre))
    lines = headline(results, fibre)
    with open("log.table", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot_efficiency("efficiency.png", results, tables.read("correlation.csv"),
                    fibre)
    plot_angles("angles.png", tables.read("angles.csv"), fibre.parcels)
