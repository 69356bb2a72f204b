# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""pipeDeposition: deposition from fully developed turbulent flow in a
vertical pipe against Liu and Agarwal (1974).

Olive-oil droplets (920 kg/m^3) in air at Re 10 000 in a 1.27 cm pipe,
a periodic section of it (the flow made by simpleFoam and frozen), every
contact of a droplet's surface with the wall a capture. One run per
dispersion model (runs/<model>: nearWallDispersion, OpenFOAM's
stochasticDispersionRAS, none), one injector per diameter. Per model and
diameter, from the model's files (adhesivewall.deposition: V_d = J/C of
the wall, its standard error, the spin-up):

    results.csv   tauPlus, d [m], model, Vplus, VplusSE, then the
                  captures, the band of the judged rows and the verdict
    log.table     the headline table (also printed)
    Vplus.png     V+ against tau+ per model, with the correlations

tau+ = tau_p u*^2/nu, tau_p = rho_p d^2 Cc/(18 mu) with Cunningham's
correction (Davies 1945); u* from the flow's wall shear stress (its mean
over the wall); V+ = V_d/u*.

Judged (the library's model only): tau+ 1-20 within 1.75e-4 tau+^2 <=
V+ <= 1.2e-3 tau+^2 (half Papavergos and Hedley's fit to twice Liu and
Agarwal's, correlations.py) with a standard error of at most 15 % of V+;
tau+ 30-100 within 0.05-0.25.

Time-step independence (Allrun.timeStep, runs/timeStep/dt1 and dt10:
tau+ 5 at the tutorial's step and a tenth of it): the two V+ differ by
less than 2 sqrt(SE1^2 + SE2^2), and the airborne droplets' profiles over
wall distance (PROFILE_EDGES, y+ 0.5-100) by a chi-square below its 99th
percentile: log.timeStep.

    adhesiveWallPost pipePositions [CASE]
    adhesiveWallPost pipeDeposition [CASE]
    adhesiveWallPost pipeTimeStep [CASE]
"""

import math
import os
import random

from .. import correlations, deposition, foam, tables
from . import NotThisCase, stop

MODELS = ("nearWallDispersion", "stochasticDispersionRAS", "none")
JUDGED = "nearWallDispersion"
MAX_RELATIVE_SE = 0.15
COLUMNS = ["tauPlus", "d", "model", "Vplus", "VplusSE", "captureParcels",
           "low", "high", "verdict"]
# The units of COLUMNS, in order: -, m, -, -, -, -, -, -, -
PROFILE_EDGES = [0.5, 1, 2, 4, 8, 15, 30, 60, 100]


# --- The parcels' start positions ------------------------------------------

def uniform_pipe(n, r_max, length, seed):
    """n points (x, y, z) uniform in the cylinder r < r_max, 0 < z <
    length (r = r_max sqrt(u): uniform in area). Reproducible: Python's
    Mersenne Twister seeded with `seed`."""
    if n < 0 or not r_max > 0 or not length > 0:
        raise ValueError(f"uniform_pipe: n = {n}, r_max = {r_max}, "
                         f"length = {length}")
    rng = random.Random(seed)
    points = []
    for _ in range(n):
        r = r_max*math.sqrt(rng.random())
        theta = 2*math.pi*rng.random()
        points.append((r*math.cos(theta), r*math.sin(theta),
                       length*rng.random()))
    return points


def positions_text(name, points, seed, r_max):
    rows = ["(%.12g %.12g %.12g)" % p for p in points]
    return foam.written_header("pipeDeposition", "vectorField", name, [
        f"{len(points)} parcels uniform in the pipe's section, r < "
        f"{r_max:.9g}",
        f"(the wall polygon's inscribed circle less a radius), seed {seed}:",
        "written by pipe_deposition.write_positions (Allrun)"]) \
        + "\n%d\n(\n%s\n)\n" % (len(rows), "\n".join(rows))


# --- The case ----------------------------------------------------------------

class Pipe:
    """The pipe, the gas and the droplets of the case (system/blockMeshDict,
    constant/transportProperties, constant/parameters)."""

    def __init__(self, case="."):
        def value(path, entry):
            return float(foam.value(path, entry, case=case))
        self.R = value("system/blockMeshDict", "R")
        self.L = value("system/blockMeshDict", "L")
        n_wall = 4*int(value("system/blockMeshDict", "nAround"))
        self.rInside = self.R*math.cos(math.pi/n_wall)
        self.nu = value("constant/transportProperties", "nu")
        self.viscosity = value("constant/transportProperties", "rhoInf") \
            * self.nu
        self.rhoP = value("constant/parameters", "rhoP")
        self.meanFreePath = value("constant/parameters", "lambda")

    def tau_plus(self, d, u_star):
        """tau_p u*^2/nu, tau_p with Cunningham's correction (Davies), as
        slipSphereDrag takes it."""
        slip = correlations.cunningham(d, self.meanFreePath, "Davies")
        tau = self.rhoP*d*d*slip/(18*self.viscosity)
        return tau*u_star**2/self.nu


def variant(case="."):
    return str(foam.value("constant/particleSettings", "variant", case=case))


def write_positions(case="."):
    """constant/<positionsFile> of each injector: its parcels of the variant
    (parcels/<variant>/<name> of the cloud's properties), uniform in the
    section, seeded with the injectorID."""
    pipe = Pipe(case)
    chosen = variant(case)
    for name, injector_id, d, path in foam.fixed_size_injectors(case):
        n = int(foam.value("constant/kinematicCloudProperties",
                           f"parcels/{chosen}/{name}", case=case))
        r_max = pipe.rInside - d/2
        points = uniform_pipe(n, r_max, pipe.L, injector_id)
        with open(os.path.join(case, "constant", path), "w") as f:
            f.write(positions_text(path, points, injector_id, r_max))
        print(f"constant/{path}: {n} parcels of {name}, seed {injector_id}")


# --- The flow ----------------------------------------------------------------

def friction_velocity(case=".", time=None):
    """u* [m/s] of the flow: the square root of the mean magnitude of the
    wall's (kinematic) shear stress, the wallShearStress function object's
    field at the flow's last time (the wall's faces are of one size: the
    O-grid divides the circle evenly)."""
    time = time or foam.latest_time(case)
    path = os.path.join(case, time, "wallShearStress")
    if not os.path.isfile(path):
        raise NotThisCase(f"{path}: no wall shear stress (the flow's "
                          "wallShearStress function object)")
    field = foam.parse(foam.body(path))["boundaryField"]["wall"]["value"]
    if field[0] != "nonuniform":
        raise NotThisCase(f"{path}: the wall's values are not a list")
    stresses = [math.sqrt(sum(c*c for c in v)) for v in field[-1]]
    return math.sqrt(sum(stresses)/len(stresses))


# --- The results ---------------------------------------------------------------

def band(tau_plus):
    """(low, high) of V+ where it is judged, None elsewhere (module's
    description)."""
    if 1 <= tau_plus <= 20:
        return (0.5*correlations.papavergos_hedley(tau_plus),
                2*correlations.liu_agarwal(tau_plus))
    if 30 <= tau_plus <= 100:
        return (0.05, 0.25)
    return None


def verdict(model, tau_plus, vplus, se):
    """(the band or None, the verdict): "pass" inside the band with a
    standard error of at most 15 % of V+, "FAIL" outside it, each with
    "(SE above 15 %)" where the error is larger; "-" where not judged."""
    limits = band(tau_plus) if model == JUDGED else None
    if limits is None:
        return limits, "-"
    inside = limits[0] <= vplus <= limits[1]
    if se <= MAX_RELATIVE_SE*vplus:
        return limits, ("pass" if inside else "FAIL")
    return limits, ("" if inside else "FAIL ") + "(SE above 15 %)"


def model_rows(pipe, run, model, u_star):
    """The rows (COLUMNS) of one model's run, per injector's diameter."""
    injectors = {d: name for name, _, d, _ in foam.fixed_size_injectors(run)}
    rows = []
    found, _ = deposition.deposition_velocity(run, patches=["wall"])
    for row in found:
        named = dict(zip(deposition.COLUMNS, row))
        if named["patch"] != "wall":
            continue
        inside = [d for d in injectors
                  if named["dMin"] <= d < named["dMax"]]
        if not inside:
            continue    # a class of the full variant's sizes
        if len(inside) > 1:
            raise NotThisCase(f"{run}: size class {named['dMin']}-"
                              f"{named['dMax']} m holds {len(inside)} "
                              "injectors' diameters, not one")
        d = inside[0]
        tp = pipe.tau_plus(d, u_star)
        vplus, se = named["Vd"]/u_star, named["VdSE"]/u_star
        limits, says = verdict(model, tp, vplus, se)
        low, high = limits if limits else (float("nan"), float("nan"))
        rows.append([tp, d, model, vplus, se, named["captureParcels"], low,
                     high, says])
    return sorted(rows, key=lambda r: r[0])


def result_rows(case="."):
    pipe = Pipe(case)
    u_star = friction_velocity(case)
    rows = []
    for model in MODELS:
        run = os.path.join(case, "runs", model)
        if os.path.isdir(run):
            rows += model_rows(pipe, run, model, u_star)
    if not rows:
        raise NotThisCase(f"{case}: no runs/<model> with the model's files")
    return rows, u_star


def headline(rows, u_star):
    lines = [f"pipeDeposition: u* = {u_star:.4g} m/s (the flow's wall "
             "shear stress)",
             f"{'model':<24} {'tau+':>7} {'d [um]':>7} {'V+':>10} "
             f"{'SE':>9} {'captures':>8}  band, verdict"]
    for tp, d, model, vplus, se, parcels, low, high, says in rows:
        limits = "" if says == "-" else f"{low:.3g}-{high:.3g}, {says}"
        lines.append(f"{model:<24} {tp:7.3g} {d*1e6:7.3g} {vplus:10.4g} "
                     f"{se:9.2g} {parcels:8.0f}  {limits}")
    return "\n".join(lines)


def plot(path, rows):
    from .. import plots
    figure, axes = plots.figure(6.4, 4.8)
    taus = [10**(k/20) for k in range(-10, 27)]   # the fits: tau+ < 20
    axes.plot(taus, [correlations.liu_agarwal(t) for t in taus], "k-",
              label="Liu & Agarwal (1974), 6e-4 tau+^2")
    axes.plot(taus, [correlations.papavergos_hedley(t) for t in taus],
              "k--", label="Papavergos & Hedley (1984), 3.5e-4 tau+^2")
    judged = [t for t in taus if 1 <= t <= 20]
    axes.fill_between(judged, [band(t)[0] for t in judged],
                      [band(t)[1] for t in judged], color="0.85",
                      label="judged band")
    axes.fill_between([30, 100], [0.05, 0.05], [0.25, 0.25], color="0.85")
    for model, marker in zip(MODELS, "osv"):
        mine = [r for r in rows if r[2] == model and r[3] > 0]
        if mine:
            axes.errorbar([r[0] for r in mine], [r[3] for r in mine],
                          yerr=[r[4] for r in mine], fmt=marker,
                          label=model, capsize=2)
    axes.set_yscale("log")
    plots.axes(axes, "tau+ = tau_p u*^2/nu", "V+ = V_d/u*",
               "Deposition in a vertical pipe, Re 10 000", ylim=(1e-5, 1),
               xlog=True)
    axes.legend(fontsize=8)
    plots.save(figure, path)


def run(case="."):
    try:
        rows, u_star = result_rows(case)
    except (NotThisCase, KeyError, ValueError, FileNotFoundError) as err:
        raise stop("pipeDeposition", err,
                   "the tutorial's runs/<model> with the model's files")
    tables.write_csv(os.path.join(case, "results.csv"), COLUMNS, rows)
    text = headline(rows, u_star)
    with open(os.path.join(case, "log.table"), "w") as f:
        f.write(text + "\n")
    print(text)
    plot(os.path.join(case, "Vplus.png"), rows)


# --- Time-step independence --------------------------------------------------

def wall_distance(points, R, n_wall):
    """The distance of points (x, y, z) to the wall polygon of n_wall faces
    with its corners on r = R, the O-grid's first corner at 45 degrees:
    R cos(pi/n_wall) - r cos(theta - theta_face), theta_face the angle of
    the middle of the face the point's angle falls on."""
    width = 2*math.pi/n_wall
    found = []
    for x, y, _ in points:
        theta = math.atan2(y, x) - math.pi/4
        middle = (math.floor(theta/width) + 0.5)*width
        found.append(R*math.cos(width/2)
                     - math.hypot(x, y)*math.cos(theta - middle))
    return found


def profile(run, u_star, nu):
    """The airborne parcels' counts per PROFILE_EDGES bin of y+ at the
    run's last time, and their total."""
    from .. import aerosol
    R = float(foam.value("system/blockMeshDict", "R", case=run))
    n_wall = 4*int(foam.value("system/blockMeshDict", "nAround", case=run))
    points = aerosol.positions(run, foam.latest_time(run))
    yplus = [y*u_star/nu for y in wall_distance(points, R, n_wall)]
    counts = [sum(1 for y in yplus if a <= y < b)
              for a, b in zip(PROFILE_EDGES[:-1], PROFILE_EDGES[1:])]
    return counts, len(points)


def profiles_chi2(first, second):
    """Chi-square of two binned profiles (counts, totals) against one
    shared shape: sum (c1/N1 - c2/N2)^2/(c1/N1^2 + c2/N2^2) over the bins
    that hold parcels, and its degrees of freedom."""
    (c1, n1), (c2, n2) = first, second
    chi2, dof = 0.0, 0
    for a, b in zip(c1, c2):
        variance = a/n1**2 + b/n2**2
        if variance > 0:
            chi2 += (a/n1 - b/n2)**2/variance
            dof += 1
    return chi2, dof


def time_step(case="."):
    """The comparison's lines and whether it passes."""
    pipe = Pipe(case)
    u_star = friction_velocity(case)
    found = {}
    for name in ("dt1", "dt10"):
        run = os.path.join(case, "runs", "timeStep", name)
        rows = model_rows(pipe, run, JUDGED, u_star)
        if len(rows) != 1:
            raise NotThisCase(f"{run}: {len(rows)} size classes, not one")
        found[name] = rows[0], profile(run, u_star, pipe.nu)
    (r1, p1), (r10, p10) = found["dt1"], found["dt10"]
    difference = abs(r1[3] - r10[3])
    allowed = 2*math.hypot(r1[4], r10[4])
    chi2, dof = profiles_chi2(p1, p10)
    limit = deposition.chi2_quantile99(dof)
    errors_ok = all(r[4] <= 0.05*r[3] for r in (r1, r10))
    lines = [f"tau+ {r1[0]:.3g}: V+ {r1[3]:.4g} +- {r1[4]:.2g} at the "
             f"tutorial's step, {r10[3]:.4g} +- {r10[4]:.2g} at a tenth: "
             f"difference {difference:.2g} against {allowed:.2g}",
             f"profiles (y+ {PROFILE_EDGES[0]}-{PROFILE_EDGES[-1]}, "
             f"{dof} bins): chi-square {chi2:.3g} against {limit:.3g}"]
    if not errors_ok:
        lines.append("standard errors above 5 % of V+: more droplets")
    return lines, errors_ok and difference < allowed and chi2 < limit


def run_time_step(case="."):
    try:
        lines, passed = time_step(case)
    except (NotThisCase, KeyError, ValueError, FileNotFoundError) as err:
        raise stop("pipeTimeStep", err,
                   "runs/timeStep/dt1 and dt10 of Allrun.timeStep")
    lines.append("time-step independence: " + ("pass" if passed else "FAIL"))
    with open(os.path.join(case, "log.timeStep"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
