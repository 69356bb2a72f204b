# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""settlingChannel: particles settling onto the floor of a laminar
channel against the flux argument (correlations.settling_channel, derived
there: an analytic result, not a measurement).

Per injector (one per diameter), the parcels captured on the floor from
the model's statistics (statistics.dat) over those injected
(gradeEfficiency.dat), against min(1, v_s L/(U H)) with v_s Stokes'
settling velocity with buoyancy (aerosol.settling_velocity; with
Cunningham's slip correction when the drag is slipSphereDrag, with its
mean free path and coefficients; none with the tutorial's sphereDrag), L
and H the channel's length and height (the mesh's points) and U the
inlet's uniform velocity:

    results.csv     per diameter: d, vs, predicted, eta (floor captures /
                    injected), etaSE (binomial standard error), the
                    parcels captured on the floor and injected
    log.table       the table (also printed)
    settling.png    eta against d with the prediction

    adhesiveWallPost settlingChannel [CASE]    (CASE: the particle case)
"""

import os

from .. import aerosol, correlations, curves, foam, statistics, tables
from . import NotThisCase, stop

CLOUD = "kinematicCloud"
RESULT_COLUMNS = ["d", "vs", "predicted", "eta", "etaSE", "floorParcels",
                  "injectedParcels"]


def channel(case="."):
    """The channel's length and height [m] (the extent of the mesh's points
    in x and y) and the inlet's velocity [m/s] (0/U, uniform)."""
    points = foam.list_file(os.path.join(case, "constant", "polyMesh",
                                         "points"))
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    kind, (U, _, _) = foam.dictionary("0/U", "boundaryField/inlet/value",
                                      case=case)
    if kind != "uniform":
        raise NotThisCase(f"0/U: the inlet's value is {kind}, not uniform")
    return max(xs) - min(xs), max(ys) - min(ys), float(U)


def slip(case, mu):
    """(mean free path [m], Cunningham coefficients) of the cloud's drag:
    slipSphereDrag's (its meanFreePath, or from its p and T by kinetic
    theory with the carrier's viscosity mu, as the force computes it), or
    no slip (0, Davies) with OpenFOAM's sphereDrag."""
    forces = foam.dictionary("constant/kinematicCloudProperties",
                             "subModels/particleForces", case=case)
    drag = forces.get("slipSphereDrag")
    if drag is None:
        return 0.0, "Davies"
    drag = drag if isinstance(drag, dict) else {}
    coefficients = str(drag.get("slipCoefficients", "Davies"))
    if "meanFreePath" in drag:
        return float(drag["meanFreePath"]), coefficients
    if "p" not in drag or "T" not in drag:
        raise ValueError("slipSphereDrag in particleForces: neither "
                         "meanFreePath nor p and T (the solver stops on it)")
    return (correlations.mean_free_path(
        mu, float(drag["p"]), float(drag["T"]),
        float(drag.get("molarMass", 0.0289647))), coefficients)


def result_rows(case="."):
    """One row per injector, in the order of the cloud's injectors."""
    props = "constant/kinematicCloudProperties"
    rho_p = float(foam.value(props, "constantProperties/rho0", case=case))
    rho_c = float(foam.value("constant/transportProperties", "rhoInf",
                             case=case))
    mu = rho_c * float(foam.value("constant/transportProperties", "nu",
                                  case=case))
    gravity = foam.gravity(case)
    mean_free_path, coefficients = slip(case, mu)
    L, H, U = channel(case)
    stats = statistics.read_statistics(case, CLOUD)
    grade = statistics.read_grade_efficiency(case, CLOUD).last_time()
    injectors = foam.dictionary(props, "subModels/injectionModels",
                                case=case)
    rows = []
    for name, injector in injectors.items():
        try:
            d = float(injector["sizeDistribution"]["fixedValueDistribution"]
                      ["value"])
        except (KeyError, TypeError):
            raise NotThisCase(f"injector {name}: not of one fixed size "
                              "(sizeDistribution fixedValue)") from None
        vs = aerosol.settling_velocity(d, rho_p, rho_c, mu, gravity,
                                       mean_free_path, coefficients)
        inside = grade.where(dMin=lambda lo: float(lo) <= d,
                             dMax=lambda hi: d < float(hi))
        if len(inside) != 1:
            raise NotThisCase(f"{name}: d = {d} is in {len(inside)} size "
                             "classes of gradeEfficiency.dat: sizeClasses "
                             "must give each injector's size a class")
        injected = inside.sum("injectedParcels")
        floor = statistics.final(stats, "captureParcels", patch="floor",
                                 dMin=inside.text("dMin")[0])
        rows.append([d, vs, correlations.settling_channel(vs, L, U, H),
                     floor / injected, curves.binomial_se(floor, injected),
                     int(floor), int(injected)])
    return rows


def headline(results):
    lines = ["settlingChannel: captured on the floor / injected, against "
             "min(1, v_s L/(U H)) (analytic)",
             "   d [um]   v_s [mm/s]   predicted   eta +- SE"]
    for d, vs, p, eta, se in zip(results["d"], results["vs"],
                                 results["predicted"], results["eta"],
                                 results["etaSE"]):
        lines.append("%9.3g %12.4g %11.4f   %.4f +- %.4f"
                     % (d * 1e6, vs * 1e3, p, eta, se))
    return lines


def plot_settling(path, results):
    from .. import plots
    fig, ax = plots.figure(8, 5)
    ax.errorbar(results["d"] * 1e6, results["eta"], yerr=results["etaSE"],
                fmt="o", capsize=3, label="parcels, +- binomial SE")
    ax.plot(results["d"] * 1e6, results["predicted"], "kx", ms=9,
            label="min(1, v_s L/(U H)), analytic")
    plots.axes(ax, "particle diameter [um]", "captured on the floor / injected",
               "Settling in a laminar channel", ylim=(0, 1.05))
    ax.legend(loc="upper left")
    plots.save(fig, path)


def run(case="."):
    try:
        os.chdir(case)
        for name in ("statistics.dat", "gradeEfficiency.dat"):
            path = os.path.join(statistics.output_folder(".", CLOUD), name)
            if not os.path.isfile(path):
                raise FileNotFoundError(f"no {path}: run ./Allrun")
        rows = result_rows(".")
    except (RuntimeError, ValueError, OSError) as err:
        raise stop("settlingChannel", err, "the settlingChannel tutorial's "
                   "particle case (its uniform inlet, its floor, its "
                   "fixed-size injectors each in a size class of its own)"
                   ) from None
    tables.write_csv("results.csv", RESULT_COLUMNS, rows)
    results = tables.read("results.csv")
    lines = headline(results)
    with open("log.table", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot_settling("settling.png", results)
