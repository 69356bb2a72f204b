# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""fibreFilter: the single-fibre efficiency of a filter fibre.

From the model's statistics of each particle sub-case U<U0>/particles and
cloud (stick, adhesive), per injector, on the fibre's own mesh with contact
at the particle's surface, slip and Brownian motion:

    results.csv      eta +- its standard error per face velocity, diameter
                     and wall model, with the Kuwabara-flow correlations of
                     each mechanism and their sum
    mpps.csv         the most penetrating size found at each face velocity
                     that runs the spectrum (0.02-10 um), its efficiency,
                     and Lee & Liu's (1980) closed form
    correlation.csv  the correlations' curves per face velocity
    angles.csv       where on the fibre the captures are
    log.table        the headline table (also printed)
    efficiency.png, spectrum.png, angles.png

eta = sum over the diameter's injectors of captured x gap/d_f: the parcels
of an injector are evenly spaced in y, `gap` apart, each standing for the
flow through its gap; the fraction of the flow through the fibre's
projected width d_f that the fibre captures. Its standard error is the
binomial one of each injector's captured/parcels, scaled alike. Stokes
number on the fibre diameter (Hinds), Stk = rho_p Cc d^2 U0/(18 mu d_f);
R = d/d_f; Peclet number Pe = d_f U0/D, D = k T Cc/(3 pi mu d).

    adhesiveWallPost fibreSpectrum SUBCASE VARIANT
        (Allrun) SUBCASE/constant/injectors and positions files of the
        spectrum (SUBCASE/constant/spectrum, VARIANT full or reduced)
    adhesiveWallPost fibreFilter [CASE]
        (Allrun.post) the post-processing
"""

import glob
import math
import os

from .. import correlations, curves, foam, statistics, tables
from . import stop

CLOUDS = ("stick", "adhesive")
ANGLE_CASES = (("0.1", "2e-6"), ("2", "2e-6"), ("2", "5e-6"), ("2", "10e-6"))
OUTER = 100     # the injectorID of a band's outer half: its inner one's + 100


class Filter:
    """The fibre, the gas and the particles of the case (the tutorial, or a
    flow sub-case U<U0> of it)."""

    def __init__(self, case="."):
        def value(path, entry):
            return float(foam.value(os.path.join(case, path), entry,
                                    expand=False))
        self.dFibre = value("constant/parameters", "dFibre")
        self.alpha = value("constant/parameters", "alpha")
        self.U0 = value("constant/parameters", "U0")
        self.T = value("constant/parameters", "T")
        self.meanFreePath = value("constant/parameters", "lambda")
        self.nu = value("constant/transportProperties", "nu")
        self.mu = self.nu * value("constant/transportProperties", "rhoInf")
        self.rhoP = value("particles/constant/cloudProperties",
                          "constantProperties/rho0")
        # the fibres' spacing: the period of the row
        self.h = self.dFibre * math.sqrt(math.pi / (4 * self.alpha))
        # where the parcels start: the x of the 1-10 um set's positions
        self.x0 = foam.list_file(os.path.join(
            case, "particles/constant/positions"))[0][0]

    def slip(self, d):
        """Cunningham's correction (Davies 1945), as slipSphereDrag."""
        return correlations.cunningham(d, self.meanFreePath, "Davies")

    def diffusivity(self, d):
        return correlations.stokes_einstein(d, self.T, self.mu, self.slip(d))

    def stokes(self, d, U):
        return self.rhoP * self.slip(d) * d * d * U \
            / (18 * self.mu * self.dFibre)

    def peclet(self, d, U):
        return self.dFibre * U / self.diffusivity(d)

    def correlations(self, d, U):
        """Each mechanism's single-fibre efficiency in Kuwabara's flow and
        their sum eta_D (Stechkina & Fuchs) + eta_R + eta_DR + eta_I (None
        where the impaction fit does not hold, R >= 0.4)."""
        a, R, Pe = self.alpha, d / self.dFibre, self.peclet(d, U)
        c = dict(etaD=correlations.diffusion_stechkina_fuchs(a, Pe),
                 etaDLL=correlations.diffusion_lee_liu(a, Pe),
                 etaR=correlations.interception(a, R),
                 etaDR=correlations.diffusion_interception(a, R, Pe),
                 etaI=correlations.impaction(a, R, self.stokes(d, U)))
        c["etaSum"] = None if c["etaI"] is None else \
            c["etaD"] + c["etaR"] + c["etaDR"] + c["etaI"]
        return c

    def lee_liu_mpps(self, U):
        return correlations.lee_liu_mpps(self.alpha, self.dFibre, U,
                                         self.meanFreePath, self.T, self.mu)


# --- The spectrum: injectors and positions ------------------------------------

def spectrum_plan(fibre, U, diameters, captures):
    """Per diameter (d, band B, parcels, eta_c, sigma): the band |y| < B
    that holds every parcel the fibre can capture, and the parcels that
    give about `captures` captures in it, by the correlations (eta_c, their
    sum; the geometric limit 1 + R where impaction's fit does not hold):
    B = min(h/2, min(4 y_c, (d_f + d)/2 + 1 um) + 5 sigma), y_c = eta_c
    d_f/2 the half-width of the captured flow, (d_f + d)/2 + 1 um beyond
    which no particle on a straight path can touch the fibre, sigma =
    sqrt(2 D 1.5 x_0/U) the spread of the start positions that Brownian
    motion mixes on the way to the fibre (x_0 the distance of the start
    from the fibre's axis; 1.5 for the slowing at the fibre); the whole
    period h/2 where that reaches it. Parcels max(1000, captures 2 B/(eta_c
    d_f)), rounded up to a multiple of 4."""
    plan = []
    for d in diameters:
        c = fibre.correlations(d, U)
        R = d / fibre.dFibre
        eta = 1 + R if c["etaSum"] is None else min(c["etaSum"], 1 + R)
        sigma = math.sqrt(2 * fibre.diffusivity(d) * 1.5 * abs(fibre.x0) / U)
        band = min(fibre.h / 2,
                   min(2 * eta * fibre.dFibre,
                       (fibre.dFibre + d) / 2 + 1e-6) + 5 * sigma)
        parcels = max(1000, 4 * math.ceil(
            captures * 2 * band / (eta * fibre.dFibre) / 4))
        plan.append((d, band, parcels, eta, sigma))
    return plan


def band_positions(band, parcels):
    """(inner, outer): parcels evenly spaced over |y| < band, 2 band/parcels
    apart, split into the inner half of the band (|y| < band/2, half the
    parcels) and the outer half (band/2 < |y| < band, a quarter on each
    side)."""
    if parcels % 4:
        raise ValueError(f"band_positions: {parcels} parcels, not a multiple "
                         "of 4")
    gap = 2 * band / parcels
    inner = [-band / 2 + (k + 0.5) * gap for k in range(parcels // 2)]
    side = [band / 2 + (k + 0.5) * gap for k in range(parcels // 4)]
    return inner, sorted([-y for y in side] + side)


def header(foam_class, name):
    return foam.written_header(
        "fibreFilter", foam_class, name,
        ["Written by fibre_filter.py spectrum (Allrun) from constant/spectrum"])


def injector_name(d):
    return "d%gnm" % round(d * 1e9, 6)


def write_spectrum(folder, variant):
    """The particle sub-case `folder` (U<U0>/particles) runs the spectrum:
    its constant/injectors (two per diameter of constant/spectrum's
    `variant`: the inner half of the band, injectorID k, the outer half,
    100 + k) and their positions files, as spectrum_plan gives them."""
    fibre = Filter(os.path.join(folder, ".."))
    path = os.path.join(folder, "constant", "spectrum")
    diameters = [float(d) for d in foam.dictionary(path, variant,
                                                   expand=False)]
    captures = float(foam.value(path, "captures/" + variant, expand=False))
    plan = spectrum_plan(fibre, fibre.U0, diameters, captures)
    lines = [header("dictionary", "injectors"),
             "// Per diameter the inner half of its band (injectorID k) and "
             "the outer half",
             "// (injectorID %d + k), constant/positions.<name>; what they "
             "share is `parcels`" % OUTER,
             "// (constant/cloudProperties). d [m], band B [m], parcels, "
             "eta_c, sigma [m]:"]
    lines += ["//   %-8s %.4g %.4g %6d %.3g %.3g" % (injector_name(d), d, band,
                                                   n, eta, sigma)
              for d, band, n, eta, sigma in plan]
    lines.append("")
    for k, (d, band, n, eta, sigma) in enumerate(plan, 1):
        name = injector_name(d)
        inner, outer = band_positions(band, n)
        for suffix, ident, ys in (("", k, inner), ("Outer", OUTER + k, outer)):
            positions = "positions.%s%s" % (name, suffix)
            lines.append(
                '%s%s { $parcels; injectorID %d; positionsFile "%s"; '
                'sizeDistribution { type fixedValue; fixedValueDistribution '
                '{ value %.6g; } } }' % (name, suffix, ident, positions, d))
            with open(os.path.join(folder, "constant", positions), "w") as f:
                f.write(header("vectorField", positions))
                f.write("// %s: %d parcels %.6g m apart, band %.6g m\n\n" % (
                    name + suffix, len(ys), 2 * band / n, band))
                f.write("%d\n(\n" % len(ys))
                f.write("".join("(%.9g %.12g 5e-06)\n" % (fibre.x0, y)
                                for y in ys))
                f.write(")\n")
    with open(os.path.join(folder, "constant", "injectors"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("%s: the spectrum at %g m/s, %d diameters, %d parcels per cloud"
          % (folder, fibre.U0, len(plan), sum(p[2] for p in plan)))
    for d, band, n, eta, sigma in plan:
        print("  d %-7.3g um  band %-6.3g um  parcels %-6d  eta_c %-8.3g "
              "sigma %.3g um" % (d * 1e6, band * 1e6, n, eta, sigma * 1e6))


# --- Results -------------------------------------------------------------------

def sub_cases(case="."):
    """The particle sub-cases U<U0>/particles, as (folder, U0 text), by
    U0."""
    found = [(os.path.relpath(folder, case), folder.split(os.sep)[-2][1:])
             for folder in glob.glob(os.path.join(case, "U*", "particles"))]
    if not found:
        raise ValueError("no sub-cases U*/particles: run ./Allrun")
    return sorted(found, key=lambda s: float(s[1]))


def injectors(folder):
    """The injectors of a particle sub-case, as (injectorID, d, parcels,
    gap, band): its positions evenly spaced `gap` apart (one parcel per
    gap of flow), the outermost within `band` of the axis."""
    found = []
    for name, injector_id, d, path in foam.fixed_size_injectors(
            folder, "constant/stickProperties"):
        ys = sorted(p[1] for p in foam.list_file(os.path.join(
            folder, "constant", path)))
        gaps = [b - a for a, b in zip(ys, ys[1:])]
        gap = min(gaps)
        if max(gaps) > gap * (1 + 1e-6) and max(gaps) < gap * 1.5:
            raise ValueError(f"{folder}: {name}: the positions are not evenly "
                             "spaced")
        found.append((injector_id, d, len(ys), gap,
                      max(abs(ys[0]), abs(ys[-1])) + gap / 2))
    return sorted(found)


def d_text(d):
    """The diameter as the results name it: micrometres e-6."""
    return "%ge-6" % round(d * 1e6, 9)


RESULT_COLUMNS = ["U0", "d", "Cc", "Stk", "R", "Pe", "Re_f", "model",
                  "parcels", "band", "captured", "outer", "escaped",
                  "airborne", "eta", "etaSE", "etaD", "etaDLL", "etaR",
                  "etaDR", "etaI", "etaSum"]


def _number(value, form="%.6g"):
    return "" if value is None else form % value


def result_rows(fibre, subs):
    rows = []
    for folder, U in subs:
        U0 = float(U)
        of_folder = injectors(folder)
        diameters = sorted(set(i[1] for i in of_folder))
        for cloud in CLOUDS:
            last = statistics.read_statistics(folder, cloud).last_time()
            for d in diameters:
                parcels = captured = escaped = 0
                outer = None
                eta = variance = band = 0.0
                for ident, dj, n, gap, reach in of_folder:
                    if dj != d:
                        continue
                    of = last.where(injector=ident)
                    if not len(of):
                        raise ValueError(f"no statistics of injector {ident}"
                                         f" in {folder}, cloud {cloud}")
                    c = of.sum("captureParcels")
                    parcels += n
                    captured += c
                    escaped += of.sum("escapeParcels")
                    if ident > OUTER:
                        outer = (outer or 0) + c
                    eta += c * gap / fibre.dFibre
                    variance += (gap / fibre.dFibre) ** 2 * n \
                        * curves.binomial_se(c, n) ** 2 * n
                    band = max(band, reach)
                c = fibre.correlations(d, U0)
                rows.append([
                    U, d_text(d), "%.5g" % fibre.slip(d),
                    "%.4g" % fibre.stokes(d, U0), "%.4g" % (d / fibre.dFibre),
                    "%.4g" % fibre.peclet(d, U0),
                    "%.3g" % (U0 * fibre.dFibre / fibre.nu), cloud,
                    "%d" % parcels, "%.5g" % band, "%d" % captured,
                    "" if outer is None else "%d" % outer, "%d" % escaped,
                    "%d" % (parcels - captured - escaped), "%.4g" % eta,
                    "%.3g" % math.sqrt(variance)] + [
                    _number(c[k]) for k in ("etaD", "etaDLL", "etaR", "etaDR",
                                            "etaI", "etaSum")])
    return rows


MPPS_COLUMNS = ["U0", "d", "eta", "etaSE", "model", "dLeeLiu", "etaLeeLiu"]


def spectrum_velocities(results):
    """The face velocities (as written) whose sub-case runs sub-micron
    particles: the spectrum."""
    return [U for U in results.unique("U0")
            if (results.where(U0=U)["d"] < 1e-6).any()]


def mpps_rows(results, fibre):
    """Per face velocity of the spectrum: the diameter of the lowest stick
    efficiency among those simulated, that efficiency and its standard
    error, and Lee & Liu's (1980) closed form."""
    rows = []
    for U in spectrum_velocities(results):
        stick = results.where(U0=U, model="stick")
        i = int(stick["eta"].argmin())
        d, eta = fibre.lee_liu_mpps(float(U))
        rows.append([U, stick.text("d")[i], stick.text("eta")[i],
                     stick.text("etaSE")[i], "stick", "%.4g" % d,
                     "%.4g" % eta])
    return rows


def correlation_rows(fibre, velocities):
    """Smooth curves per face velocity, 0.01-12 um: each mechanism and the
    sum (etaI and eta empty where the impaction fit does not hold)."""
    rows = []
    for U in velocities:
        for d in curves.log_space(0.01e-6, 12e-6, 181):
            c = fibre.correlations(d, float(U))
            rows.append([U, "%.5g" % d, "%.5g" % fibre.stokes(d, float(U)),
                         "%.5g" % (d / fibre.dFibre)] + [
                _number(c[k], "%.5g") for k in ("etaD", "etaDLL", "etaR",
                                                "etaDR", "etaI", "etaSum")])
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


def headline_notes(results, mpps, fibre):
    """The headline's notes: bands that may cut off captures, fibre
    Reynolds numbers beyond the correlations', the most penetrating
    sizes."""
    lines = []
    # A band that may cut off captures (the tutorial's test: at most
    # max(2, 10 %) of them in its outer half, where the band is not the
    # whole period and the correlations hold)
    for k in range(len(results)):
        def cell(name, k=k):
            return results.text(name)[k]
        if cell("outer") and cell("etaSum") \
                and float(cell("band")) < fibre.h / 2 * (1 - 1e-4):
            outer, captured = int(cell("outer")), int(cell("captured"))
            if outer > max(2, 0.1 * captured):
                lines.append(
                    "%s, %s um at %s m/s: %d of %d captures in the outer half "
                    "of the band: it may cut off captures (widen it)" % (
                        cell("model"), "%.3g" % (float(cell("d")) * 1e6),
                        cell("U0"), outer, captured))
    for U in results.unique("U0"):
        reynolds = results.where(U0=U)["Re_f"][0]
        if reynolds > 1:
            lines.append("fibre Reynolds number %.3g at %s m/s: beyond the "
                         "creeping (Kuwabara) flow of the correlations "
                         "(Re_f << 1), estimates only there" % (reynolds, U))
    for U, d, eta, se, model, dLL, etaLL in zip(
            mpps.text("U0"), mpps["d"], mpps["eta"], mpps["etaSE"],
            mpps.text("model"), mpps["dLeeLiu"], mpps["etaLeeLiu"]):
        sizes = results.where(U0=U, model=model)["d"]
        if d in (sizes.min(), sizes.max()):
            lines.append("most penetrating size at %s m/s (%s): not among "
                         "the sizes run (the lowest efficiency is at the %s, "
                         "%.3g um); Lee & Liu (1980): %.3g um" % (
                             U, model, "smallest" if d == sizes.min()
                             else "largest", d * 1e6, dLL * 1e6))
            continue
        lines.append("most penetrating size at %s m/s (%s): %.3g um, eta %.3g "
                     "+- %.2g; Lee & Liu (1980): %.3g um, %.3g (ratios %.2f, "
                     "%.2f)" % (U, model, d * 1e6, eta, se, dLL * 1e6, etaLL,
                                d / dLL, eta / etaLL))
    return lines


def headline(results, mpps, fibre):
    lines = ["", "fibreFilter: single-fibre efficiency, d_f = %g um, solidity"
             " %g, 2D fibre row; slip and Brownian motion (%g K)" % (
                 fibre.dFibre * 1e6, fibre.alpha, fibre.T),
             "eta +- binomial standard error (parcels: results.csv); "
             "correlations, Kuwabara flow: eta_D Stechkina & Fuchs,",
             "eta_R Lee & Liu, eta_DR and eta_I Stechkina, Kirsch & Fuchs; "
             "sum = eta_D + eta_R + eta_DR + eta_I", "",
             "%-5s %-6s %-9s %-6s %-8s %-19s %-19s %-8s %-8s %-8s %-8s %s" % (
                 "U0", "d [um]", "Stk", "R", "Pe", "stick", "adhesive",
                 "eta_D", "eta_R", "eta_DR", "eta_I", "sum")]
    keys = list(dict.fromkeys(zip(results.text("U0"), results.text("d"))))
    for U, d in keys:
        of = {cloud: results.where(U0=U, d=d, model=cloud)
              for cloud in CLOUDS}
        row = of["stick"]

        def cell(name):
            text = row.text(name)[0]
            return "%-8.3g" % float(text) if text else "%-8s" % "-"

        def eta(cloud):
            return "%.4g +- %.2g" % (of[cloud]["eta"][0],
                                     of[cloud]["etaSE"][0])
        lines.append(("%-5s %-6.3g %-9.3g %-6.3g %-8.3g %-19s %-19s "
                      "%s %s %s %s %s" % (
                          U, float(d) * 1e6, row["Stk"][0], row["R"][0],
                          row["Pe"][0], eta("stick"), eta("adhesive"),
                          cell("etaD"), cell("etaR"), cell("etaDR"),
                          cell("etaI"), cell("etaSum"))).rstrip())
    lines += ["", "(eta_I, sum: '-' where R >= 0.4, beyond the impaction fit)"]
    lines += headline_notes(results, mpps, fibre)
    lines += ["", "parcels still airborne at the end: stick %d, adhesive %d"
              % tuple(results.where(model=c).sum("airborne") for c in CLOUDS),
              "", "Results: results.csv, mpps.csv, correlation.csv, "
              "angles.csv; plots: efficiency.png, spectrum.png, angles.png"]
    return lines


def run(case="."):
    try:
        os.chdir(case)
        fibre = Filter()
        subs = sub_cases()
        for folder, _ in subs:
            for cloud in CLOUDS:
                for name in ("statistics.dat", "impacts.csv"):
                    path = os.path.join(
                        statistics.output_folder(folder, cloud), name)
                    if not os.path.isfile(path):
                        raise FileNotFoundError(
                            f"no {name} of the cloud {cloud} in {folder}")
        rows = result_rows(fibre, subs)
    except (RuntimeError, ValueError, OSError) as err:
        raise stop("fibreFilter", err, "the fibreFilter tutorial's sub-cases "
                   "(one fixed size per injector)") from None
    tables.write_csv("results.csv", RESULT_COLUMNS, rows)
    results = tables.read("results.csv")
    tables.write_csv("mpps.csv", MPPS_COLUMNS, mpps_rows(results, fibre))
    mpps = tables.read("mpps.csv")
    tables.write_csv("correlation.csv",
                     ["U0", "d", "Stk", "R", "etaD", "etaDLL", "etaR", "etaDR",
                      "etaI", "etaSum"],
                     correlation_rows(fibre, results.unique("U0")))
    correlation = tables.read("correlation.csv")
    tables.write_csv("angles.csv", ["case", "U0", "d", "Stk", "model",
                                    "angle", "captured"], angle_rows(fibre))
    from .fibre_filter_plots import plot_angles, plot_efficiency, plot_spectrum
    lines = headline(results, mpps, fibre)
    with open("log.table", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot_efficiency("efficiency.png", results, correlation, fibre)
    plot_spectrum("spectrum.png", results, correlation, mpps, fibre)
    plot_angles("angles.png", tables.read("angles.csv"))
