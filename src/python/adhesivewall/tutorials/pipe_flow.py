# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""pipeDeposition's carrier flow checked against the physics of a fully
developed turbulent pipe flow (Allrun.flow: adhesiveWallPost pipeFlow).

From the latest time of the case (after Allrun.flow: U, k, C of
postProcess -func writeCellCentres, wallShearStress, yPlus) and
log.simpleFoam (the mean pressure gradient of meanVelocityForce), prints

    u*       from the pressure gradient G (kinematic): the force balance of
             the slice, tau_w/rho = G R/2; from the wall shear stress (its
             mean over the wall); against Blasius, Prandtl-Karman and Dean
    y+       of the wall cells' centres (their distance to the wall's faces)
    a table  y+, U+ = Uz/u*, the law of the wall (U+ = y+ below 5,
             ln(y+)/0.41 + 5.2 above 30, Spalding's profile throughout) and
             k+ = k/u*^2, at cells from the wall to the axis

    adhesiveWallPost pipeFlow [CASE]

References:
    Spalding, D.B. (1961). A single formula for the law of the wall.
    J. Appl. Mech. 28:455-458.
    Pope, S.B. (2000). Turbulent Flows. Cambridge University Press
    (Prandtl-Karman's friction law of smooth pipes, Blasius' fit).
    Dean, R.B. (1978). Reynolds number dependence of skin friction and
    other bulk flow variables in two-dimensional rectangular duct flow.
    J. Fluids Eng. 100:215-223.
"""

import math
import os
import re

import numpy as np

from .. import foam
from . import stop
from .pipe_deposition import friction_velocity

KAPPA, B = 0.41, 5.2        # the log law's constants
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def field(path, patch=None):
    """A field's internal values, or its values on `patch`, as an (n, 1) or
    (n, 3) array (foam.parse; a uniform internal value is not expected)."""
    parsed = foam.parse(foam.body(path))
    value = parsed["internalField"] if patch is None \
        else parsed["boundaryField"][patch]["value"]
    if value[0] != "nonuniform":
        raise ValueError(f"{path}: {value[:2]} is not a list of values")
    return np.array(value[-1], dtype=float).reshape(len(value[-1]), -1)


def flow_time(case):
    """The last time folder, which Allrun.flow leaves with U in it."""
    time = foam.latest_time(case)
    if float(time) <= 0 or not os.path.isfile(os.path.join(case, time, "U")):
        raise ValueError("no flow written in %s (run ./Allrun.flow)" % case)
    return time


def spalding(yplus):
    """U+ of Spalding's (1961) profile at y+ (bisection)."""
    lo, hi = 0.0, 40.0
    for _ in range(80):
        u = 0.5*(lo + hi)
        ku = KAPPA*u
        y = u + math.exp(-KAPPA*B)*(math.exp(ku) - 1 - ku - ku**2/2 - ku**3/6)
        lo, hi = (u, hi) if y < yplus else (lo, u)
    return u


def friction_factors(re_d):
    """Darcy friction factors f of the correlations at Re = Ub D/nu."""
    f = 0.02
    for _ in range(50):                 # Prandtl-Karman, smooth pipe
        f = (2.0*math.log10(re_d*math.sqrt(f)) - 0.8)**-2
    return {
        "Blasius, f = 0.316 Re^-1/4": 0.316*re_d**-0.25,
        "Prandtl-Karman, 1/sqrt f = 2 log(Re sqrt f) - 0.8": f,
        # Dean's channel correlation with 2h = D: a channel, not a pipe
        "Dean (channel, 2h = D), f = 4 x 0.073 Re^-1/4": 4*0.073*re_d**-0.25,
    }


def run(case="."):
    """The report on standard output; a missing or bad file stops in one
    line."""
    try:
        report(case)
    except (ValueError, KeyError, OSError, IndexError) as err:
        raise stop("pipeFlow", err, "the converged flow of Allrun.flow")


def report(case="."):
    path = lambda *p: os.path.join(case, *p)
    R = float(foam.value("system/blockMeshDict", "R", case=case))
    nu = float(foam.value("constant/transportProperties", "nu", case=case))
    ubar = np.array(str(foam.value("constant/fvOptions",
                                   "meanVelocityForce/Ubar", case=case))
                    .strip("() ").split(), dtype=float)
    with open(path("log.simpleFoam")) as f:
        gradients = re.findall(r"pressure gradient = (%s)" % NUMBER, f.read())
    G = float(gradients[-1])
    time = flow_time(case)

    C = field(path(time, "C"))
    U = field(path(time, "U"))
    k = field(path(time, "k"))[:, 0]
    faces = field(path(time, "C"), "wall")
    wall_yplus = field(path(time, "yPlus"), "wall")[:, 0]

    # Distance to the wall: to the plane of the nearest wall face (the
    # wall's faces are chords, their normals radial in x-y)
    n = faces[:, :2]/np.linalg.norm(faces[:, :2], axis=1)[:, None]
    nearest = np.argmin(((C[:, None, :2] - faces[None, :, :2])**2).sum(2),
                        axis=1)
    y = (faces[nearest, :2]*n[nearest]).sum(1) - (C[:, :2]*n[nearest]).sum(1)

    ub = np.linalg.norm(ubar)
    axis = ubar/ub
    re_d = ub*2*R/nu
    ustar = math.sqrt(G*R/2)
    ustar_tau = friction_velocity(case, time)
    print("pipeDeposition flow, time %s: R = %g m, nu = %g m^2/s, Ub = %g m/s,"
          " Re = %.0f" % (time, R, nu, ub, re_d))
    print("u* from the pressure gradient (G = %.6g m/s^2, u* = sqrt(G R/2)):"
          " %.4f m/s, Re_tau = %.0f" % (G, ustar, ustar*R/nu))
    print("u* from the mean wall shear stress:                      "
          " %.4f m/s" % ustar_tau)
    for name, f in friction_factors(re_d).items():
        us = ub*math.sqrt(f/8)
        print("  %-50s f = %.5f  u* = %.4f  (computed %+.1f %%)"
              % (name, f, us, 100*(ustar/us - 1)))

    ucl = (U[np.argmax(y)] @ axis)/ub
    first = y < 1.5*y.min()             # the wall cells (next layer ~2.5x)
    yplus = y*ustar/nu
    print("wall cells: %d, y+ of their centres %.2f to %.2f (mean %.2f);"
          " OpenFOAM's yPlus %.2f to %.2f" % (first.sum(), yplus[first].min(),
          yplus[first].max(), yplus[first].mean(), wall_yplus.min(),
          wall_yplus.max()))
    print("centreline velocity Uc/Ub = %.3f (1/7 power law: 1.224)" % ucl)

    uplus = (U @ axis)/ustar
    kplus = k/ustar**2
    print("\n%8s %8s %10s %10s %9s"
          % ("y+", "U+", "wall law", "Spalding", "k+"))
    targets = [yplus.min(), 2, 5, 10, 15, 20, 30, 50, 100, 200, yplus.max()]
    for t in targets:
        i = np.argmin(abs(yplus - t))
        law = yplus[i] if yplus[i] < 5 else \
            math.log(yplus[i])/KAPPA + B if yplus[i] > 30 else float("nan")
        print("%8.2f %8.2f %10s %10.2f %9.4f" % (yplus[i], uplus[i],
              "-" if math.isnan(law) else "%.2f" % law, spalding(yplus[i]),
              kplus[i]))
    i = np.argmax(kplus)
    print("\nk+ peak %.2f at y+ = %.1f (pipe and channel DNS at Re_tau ~ 300:"
          " ~4.5 at y+ ~ 15;\nkOmegaSST is known to underpredict the near-wall"
          " peak)" % (kplus[i], yplus[i]))

