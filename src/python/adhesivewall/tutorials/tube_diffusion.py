# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""tubeDiffusion: deposition by diffusion in a tube against Gormley and
Kennedy (1949).

Parcels of 0.02 to 0.3 um in fully developed laminar flow through a tube,
injected flux-weighted over its section, every wall contact a capture. Per
injector (one per diameter), from the model's statistics (statistics.dat:
captures on the wall, escapes through the outlet and the inlet) and its
grade efficiency (gradeEfficiency.dat: parcels injected and airborne):

    results.csv     per diameter: the slip correction, the diffusivity, the
                    deposition parameter mu = pi D L/Q, the parcels
                    deposited, through the outlet, back through the inlet
                    and still airborne, the penetration P = outlet/parcels
                    and its binomial standard error, Gormley and Kennedy's
                    P(mu), the difference and its tolerance, the verdict
    log.table       the headline table (also printed)
    penetration.png P against mu, with Gormley and Kennedy's curve

The positions of the parcels: write_positions writes
constant/positions.<name> for each injector of the cloud
(flux_weighted_disc).

    adhesiveWallPost tubePositions [CASE]
    adhesiveWallPost tubeDiffusion [CASE]
"""

import math
import os
import random

from .. import correlations, curves, foam, statistics, tables
from . import NotThisCase, stop

CLOUD = "kinematicCloud"
# The verdict: |P - P_GK| within the larger of TOLERANCE and SE_FACTOR
# binomial standard errors (issue 24)
TOLERANCE = 0.03
SE_FACTOR = 3


# --- The parcels' start positions ------------------------------------------

def flux_weighted_disc(n, R, seed, r_max=None):
    """n points (y, z) over the disc r < R with the probability density of
    the Poiseuille flux through it, proportional to (1 - r^2/R^2) r dr
    dtheta: the parcels that enter a tube in fully developed laminar flow
    in a given time (sampling uniformly in area would over-weight the slow
    flow near the wall). The radius by inversion of the radial CDF
    F = 2 s^2 - s^4 (curves.poiseuille_flux_radius); the angle uniform.
    With r_max < R the
    distribution conditioned on r < r_max (F uniform below F(r_max/R)).
    Reproducible: Python's Mersenne Twister seeded with `seed`."""
    if n < 0 or R <= 0:
        raise ValueError(f"flux_weighted_disc: n = {n}, R = {R}")
    f_max = 1.0 if r_max is None \
        else curves.poiseuille_flux_fraction(min(r_max / R, 1.0))
    rng = random.Random(seed)
    points = []
    for _ in range(n):
        s = curves.poiseuille_flux_radius(rng.random() * f_max)
        theta = 2 * math.pi * rng.random()
        points.append((R * s * math.cos(theta), R * s * math.sin(theta)))
    return points




def positions_text(name, points, seed, r_max, x=0.0):
    rows = ["(%.9g %.12g %.12g)" % (x, y, z) for y, z in points]
    return foam.written_header("tubeDiffusion", "vectorField", name, [
        f"{len(points)} parcels at x = 0, flux-weighted over the tube's section",
        f"(r < {r_max:.9g}, the wall polygon's inscribed circle), seed {seed}:",
        "written by tube_diffusion.write_positions (Allrun)"]) \
        + "\n%d\n(\n%s\n)\n" % (len(rows), "\n".join(rows))


# --- The case ----------------------------------------------------------------

class Tube:
    """The tube, its flow and the gas of the case (constant/parameters,
    constant/transportProperties, system/blockMeshDict)."""

    def __init__(self, case="."):
        def value(path, entry):
            return float(foam.value(path, entry, case=case))
        self.R = value("constant/parameters", "R")
        self.L = value("constant/parameters", "L")
        self.Ubar = value("constant/parameters", "Ubar")
        self.T = value("constant/parameters", "T")
        self.meanFreePath = value("constant/parameters", "lambda")
        self.nu = value("constant/transportProperties", "nu")
        self.viscosity = value("constant/transportProperties", "rhoInf") \
            * self.nu
        self.Q = math.pi * self.R ** 2 * self.Ubar
        # The wall: a polygon of 4 nAround faces with its corners on r = R
        self.nWall = 4 * int(value("system/blockMeshDict", "nAround"))
        self.rInside = self.R * math.cos(math.pi / self.nWall)

    def slip(self, d):
        """Cunningham's correction (Davies 1945), as slipSphereDrag."""
        return correlations.cunningham(d, self.meanFreePath, "Davies")

    def diffusivity(self, d):
        """Stokes-Einstein with the slip correction [m^2/s]."""
        return correlations.stokes_einstein(d, self.T, self.viscosity,
                                            self.slip(d))

    def mu(self, d):
        """Gormley and Kennedy's deposition parameter pi D L/Q."""
        return math.pi * self.diffusivity(d) * self.L / self.Q


def settings(case="."):
    """(variant, forces) of constant/particleSettings."""
    path = "constant/particleSettings"
    return (str(foam.value(path, "variant", case=case)),
            str(foam.value(path, "forces", case=case)))


def injectors(case="."):
    """The cloud's injectors as (name, injectorID, d, positionsFile), in
    order of d."""
    found = foam.fixed_size_injectors(case)
    if not found:
        raise ValueError(f"{case}: no injectors")
    return sorted(found, key=lambda i: i[2])


def write_positions(case="."):
    """constant/<positionsFile> of each injector: the parcels of the
    variant (constant/injectors: parcels), flux-weighted, seeded with the
    injectorID, inside the wall polygon's inscribed circle."""
    tube = Tube(case)
    variant, _ = settings(case)
    n = int(foam.value("constant/kinematicCloudProperties",
                       "parcels/" + variant,
                       case=case))
    r_max = tube.rInside * (1 - 1e-9)
    for name, injector_id, _, path in injectors(case):
        points = flux_weighted_disc(n, tube.R, injector_id, r_max)
        with open(os.path.join(case, "constant", path), "w") as f:
            f.write(positions_text(path, points, injector_id, r_max))
        print(f"constant/{path}: {n} parcels of {name}, seed {injector_id}")


# --- The flow ----------------------------------------------------------------

def internal_vectors(path):
    """The internalField of a volVectorField file, as a list of vectors."""
    field = foam.parse(foam.body(path))["internalField"]
    if field[0] != "nonuniform":
        raise ValueError(f"{path}: internalField {field[:2]} is not a list")
    return field[-1]


def poiseuille_deviation(tube, case=".", time="0"):
    """The largest deviation of the velocity at the cell centres
    (<time>/U, <time>/C of postProcess -func writeCellCentres) from
    2 Ubar (1 - r^2/R^2) along x, relative to Ubar: the flow is fully
    developed by construction when it is at round-off."""
    U = internal_vectors(os.path.join(case, time, "U"))
    C = internal_vectors(os.path.join(case, time, "C"))
    if len(U) != len(C):
        raise ValueError(f"{case}: {len(U)} velocities, {len(C)} centres")
    worst = 0.0
    for (ux, uy, uz), (_, y, z) in zip(U, C):
        u = 2 * tube.Ubar * (1 - (y * y + z * z) / tube.R ** 2)
        worst = max(worst, abs(ux - u), abs(uy), abs(uz))
    return worst / tube.Ubar


# --- The time step's own bias ------------------------------------------------

def random_walk_penetration(mu, n, steps_per_residence, length, residences=4,
                            seed=1):
    """The penetration of n point particles whose positions at the ends of
    the time steps follow Brownian motion in the Poiseuille flow, sampled as
    the solver samples it: per step dt, the velocity of the gas at the
    step's start times dt plus a Gaussian displacement of variance 2 D dt
    per component (exact for the positions at step ends when dt >> tau);
    captured when a step ends outside the tube (the straight path between
    two points inside a circle stays inside it, so an excursion to the wall
    within a step is missed: the time step's bias, which makes P too
    high), through when it ends beyond the outlet. Flux-weighted start at
    x = 0 (flux_weighted_disc, seeded); units R = Ubar = 1, length = L/R,
    D = mu/length. Returns (P, the fraction still in the tube after
    `residences` residence times). numpy; a reference, not the solver."""
    import numpy as np
    points = np.array(flux_weighted_disc(n, 1.0, seed))
    y, z, x = points[:, 0].copy(), points[:, 1].copy(), np.zeros(n)
    dt = length / steps_per_residence
    sigma = math.sqrt(2 * mu / length * dt)
    rng = np.random.default_rng(seed)
    inside = np.arange(n)
    through = 0
    for _ in range(int(round(residences * steps_per_residence))):
        if not len(inside):
            break
        yi, zi = y[inside], z[inside]
        u = 2 * (1 - yi * yi - zi * zi)
        step = sigma * rng.standard_normal((3, len(inside)))
        x[inside] += u * dt + step[0]
        y[inside] = yi + step[1]
        z[inside] = zi + step[2]
        wall = y[inside] ** 2 + z[inside] ** 2 >= 1
        outlet = (x[inside] >= length) & ~wall
        through += int(outlet.sum())
        inside = inside[~(wall | outlet)]
    return through / n, len(inside) / n


# --- Results -----------------------------------------------------------------

RESULT_COLUMNS = ["d", "Cc", "D", "mu", "parcels", "deposited", "outlet",
                  "inlet", "airborne", "penetration", "penetrationSE",
                  "gormleyKennedy", "difference", "tolerance", "verdict"]


def tolerance(se):
    return max(TOLERANCE, SE_FACTOR * se)


def verdict(outlet, airborne, parcels, gk, se):
    """pass when P = outlet/parcels is within the tolerance of P_GK and so
    is (outlet + airborne)/parcels: whatever the parcels still airborne
    at the end would do."""
    low, high = outlet / parcels, (outlet + airborne) / parcels
    limit = tolerance(se)
    return "pass" if abs(low - gk) <= limit and abs(high - gk) <= limit \
        else "fail"


def injector_row(grade, injector_id):
    """The grade efficiency's row of an injector at the last time: one,
    since the tutorial has a size per injector and no sizeClasses."""
    rows = grade.where(injector=str(injector_id))
    if len(rows) > 1:
        raise NotThisCase(f"gradeEfficiency.dat: {len(rows)} rows of "
                          f"injector {injector_id} at the last time "
                          "(sizeClasses split its size)")
    if not rows:
        raise ValueError(f"gradeEfficiency.dat: no row of injector "
                         f"{injector_id} at the last time (the model "
                         "writes one per injector with outputByInjectorId "
                         "yes)")
    return rows


def result_rows(tube, case="."):
    last = statistics.read_statistics(case, CLOUD).last_time()
    grade = statistics.read_grade_efficiency(case, CLOUD).last_time()
    rows = []
    for name, injector_id, d, path in injectors(case):
        of = last.where(injector=str(injector_id))
        deposited = statistics.final(of, "captureParcels", patch="wall")
        outlet = statistics.final(of, "escapeParcels", patch="outlet")
        inlet = statistics.final(of, "escapeParcels", patch="inlet")
        n = len(foam.list_file(os.path.join(case, "constant", path)))
        g = injector_row(grade, injector_id)
        injected = g.sum("injectedParcels")
        airborne = n - deposited - outlet - inlet
        if injected != n or g.sum("airborneParcels") != airborne \
                or g.sum("removedParcels") != 0:
            raise ValueError(
                f"{name}: {n} positions, injected {injected:g}, deposited "
                f"{deposited:g}, outlet {outlet:g}, inlet {inlet:g}, airborne "
                f"{g.sum('airborneParcels'):g}, removed "
                f"{g.sum('removedParcels'):g}: the counts do not close")
        mu = tube.mu(d)
        gk = correlations.gormley_kennedy(mu)
        p = outlet / n
        se = curves.binomial_se(outlet, n)
        rows.append(["%.6g" % d, "%.6g" % tube.slip(d),
                     "%.6g" % tube.diffusivity(d), "%.6g" % mu, "%d" % n,
                     "%d" % deposited, "%d" % outlet, "%d" % inlet,
                     "%d" % airborne, "%.6g" % p, "%.4g" % se,
                     "%.6g" % gk, "%.4g" % (p - gk), "%.4g" % tolerance(se),
                     verdict(outlet, airborne, n, gk, se)])
    return rows


def headline(results, tube, forces, deviation):
    lines = ["", "tubeDiffusion: penetration of a diffusing aerosol through a "
             "tube, laminar flow (Re %.2g)" % (
                 2 * tube.R * tube.Ubar / tube.nu),
             "R %g mm, L %g m, Q %.4g mL/min; P +- binomial standard error; "
             "Gormley & Kennedy (1949): P_GK(mu), mu = pi D L/Q" % (
                 tube.R * 1e3, tube.L, tube.Q * 6e7),
             "", "%-7s %-7s %-9s %-8s %-17s %-7s %-8s %-7s %s" % (
                 "d [um]", "Cc", "D [m2/s]", "mu", "P", "P_GK", "P - P_GK",
                 "within", "deposited/inlet/airborne")]
    for i in range(len(results)):
        def cell(name, i=i):
            return results.text(name)[i]
        lines.append("%-7.3g %-7.4g %-9.3g %-8.4g %.4f +- %-6.4f %-7.4f "
                     "%+-8.4f %-7.3f %s/%s/%s %s" % (
                         float(cell("d")) * 1e6, float(cell("Cc")),
                         float(cell("D")), float(cell("mu")),
                         float(cell("penetration")),
                         float(cell("penetrationSE")),
                         float(cell("gormleyKennedy")),
                         float(cell("difference")), float(cell("tolerance")),
                         cell("deposited"), cell("inlet"), cell("airborne"),
                         cell("verdict")))
    lines += ["", "flow: the velocity at the cell centres is 2 Ubar (1 - "
              "r^2/R^2) to %.1e Ubar (fully developed)" % deviation]
    if forces != "brownian":
        lines += ["", "forces: %s (constant/particleSettings): no Brownian "
                  "motion, the parcels follow their streamlines;" % forces,
                  "the penetration is not comparable with Gormley and "
                  "Kennedy's (set forces brownian)"]
    lines += ["", "Results: results.csv; plot: penetration.png"]
    return lines


def plot_penetration(path, results, forces):
    """P against mu with Gormley and Kennedy's curve (above), and P - P_GK
    with the tolerance (below)."""
    from .. import plots
    fig, (top, bottom) = plots.figure(9, 8.5, rows=2)
    mus = curves.log_space(1e-3, 2, 200)
    top.plot(mus, [correlations.gormley_kennedy(m) for m in mus], "k-",
             label="Gormley & Kennedy (1949)")
    top.errorbar(results["mu"], results["penetration"],
                 yerr=results["penetrationSE"], fmt="o", capsize=3,
                 label="parcels (forces %s), +- binomial standard error"
                 % forces)
    for mu, p, d in zip(results["mu"], results["penetration"],
                        results["d"]):
        top.annotate("%g um" % (d * 1e6), (mu, p), textcoords="offset points",
                     xytext=(6, 6), fontsize=8)
    plots.axes(top, "mu = pi D L / Q", "penetration P",
               "Diffusion in a tube, fully developed laminar flow",
               xlim=(1e-3, 2), ylim=(0, 1.05), xlog=True)
    top.legend(loc="lower left")
    bottom.axhline(0, color="k", lw=1)
    bottom.errorbar(results["mu"], results["difference"],
                    yerr=results["penetrationSE"], fmt="o", capsize=3,
                    label="P - P_GK +- standard error")
    bottom.plot(results["mu"], results["tolerance"], "r--",
                label="tolerance: max(0.03, 3 standard errors)")
    bottom.plot(results["mu"], -results["tolerance"], "r--")
    plots.axes(bottom, "mu = pi D L / Q", "P - P_GK", "",
               xlim=(1e-3, 2), xlog=True)
    span = max(0.05, 1.2 * max(abs(results["difference"]).max(),
                               results["tolerance"].max()))
    bottom.set_ylim(-span, span)
    bottom.legend(loc="lower left")
    plots.save(fig, path)


def settling_gravity(case="."):
    """|g| when the cloud's forces include gravity, else 0: Gormley and
    Kennedy's penetration is that of diffusion alone."""
    forces = foam.dictionary("constant/kinematicCloudProperties",
                             "subModels/particleForces", case=case)
    return foam.gravity(case) if "gravity" in forces else 0.0


def run(case="."):
    try:
        os.chdir(case)
        tube = Tube()
        _, forces = settings()
        g = settling_gravity()
        if g > 0:
            raise NotThisCase(
                f"the parcels settle (gravity among the forces, |g| = {g:g} "
                "m/s^2): Gormley and Kennedy's penetration is that of "
                "diffusion alone")
        for name in ("statistics.dat", "gradeEfficiency.dat"):
            path = os.path.join(statistics.output_folder(".", CLOUD), name)
            if not os.path.isfile(path):
                raise FileNotFoundError(f"no {path}: run ./Allrun")
        deviation = poiseuille_deviation(tube)
        rows = result_rows(tube)
    except (RuntimeError, ValueError, OSError) as err:
        raise stop("tubeDiffusion", err, "the tubeDiffusion tutorial's "
                   "case (its tube, its fixed-size injectors, diffusion "
                   "alone, no sizeClasses)") from None
    tables.write_csv("results.csv", RESULT_COLUMNS, rows)
    results = tables.read("results.csv")
    lines = headline(results, tube, forces, deviation)
    with open("log.table", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot_penetration("penetration.png", results, forces)
