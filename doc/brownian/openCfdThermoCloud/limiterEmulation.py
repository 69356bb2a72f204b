#!/usr/bin/python3
# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The move loop's sub-step limiter alone, with OpenCFD's BrownianMotion force.

    limiterEmulation.py limiterEmulation.csv

KinematicParcel::move cuts a time step DT into sub-steps of the fraction
f = min(1 - sf, maxCo, maxCo*l/|DT U|), with U the velocity at the start of
the sub-step and l the cube root of the cell volume.  This emulates that loop
in 3-D without faces: x moves with the start velocity, then U is advanced by
the analytical scheme with OpenCFD's force (magnitude f|N| with
f^2 = 2 kB T m/(Cc tau dt), direction uniform on the sphere) held over the
sub-step.  It shows whether the limiter alone explains the small diffusivity
measured on the 0.1 um mesh (Allrun's d100h*fine runs): D_eff/D from the MSD
slope between the 6th and the 11th move, D = kB T/(3 pi mu d).  Same gas and
particle as the case (0.1 um, 3240 kg/m3, mu 1.8e-5, 293.15 K, lambda 65.6 nm).
numpy only.
"""

import math
import sys

import numpy as np

KB, T, MU, RHOP, D_P, LAMBDA = 1.380649e-23, 293.15, 1.8e-5, 3240.0, 1e-7, 6.56e-8
KN = 2*LAMBDA/D_P
CC = 1 + KN*(1.257 + 0.4*math.exp(-1.1/KN))
TAU = RHOP*D_P**2/(18*MU)
D = KB*T/(3*math.pi*MU*D_P)
M = RHOP*math.pi*D_P**3/6
Q = 2*KB*T/(M*CC*TAU)/3  # per component: (force/mass)^2 times the sub-step


def run(h, l, maxCo=0.3, n=20000, nSteps=10, seed=1):
    """D_eff/D, its standard error, and the mean number of sub-steps per move."""
    rng = np.random.default_rng(seed)
    DT = h*TAU
    x = np.zeros((n, 3))
    U = np.zeros((n, 3))
    nSub = 0
    for step in range(nSteps + 1):  # the first step moves twice (injection)
        sf = np.zeros(n)
        act = np.ones(n, bool)
        while act.any():
            Um = np.linalg.norm(U[act], axis=1)
            f = np.minimum(1 - sf[act], maxCo)
            with np.errstate(divide="ignore"):
                f = np.minimum(f, np.where(Um > 0, maxCo*l/(DT*Um), np.inf))
            dt = f*DT
            x[act] += U[act]*dt[:, None]
            rho = np.exp(-dt/TAU)
            theta = 2*math.pi*rng.random(len(dt))
            u = 2*rng.random(len(dt)) - 1
            a = np.sqrt(1 - u*u)
            e = np.stack([a*np.cos(theta), a*np.sin(theta), u], axis=1)
            acc = np.sqrt(3*Q/dt)*np.abs(rng.standard_normal(len(dt)))
            U[act] = rho[:, None]*U[act] + ((1 - rho)*TAU*acc)[:, None]*e
            sf[act] += f
            nSub += act.sum()
            act = sf < 1 - 1e-12
        if step == nSteps//2:
            x1, t1 = x.copy(), (step + 1)*DT
    t2 = (nSteps + 1)*DT
    inc = ((x**2).sum(axis=1) - (x1**2).sum(axis=1))/(6*(t2 - t1)*D)
    return inc.mean(), inc.std(ddof=1)/math.sqrt(n), nSub/n/(nSteps + 1)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "limiterEmulation.csv"
    with open(out, "w") as f:
        f.write("h,l,DeffOverD,DeffOverDSE,subStepsPerMove,oneThirdCc\n")
        print("%8s %8s %16s %9s %7s" % ("h", "l", "Deff/D", "sub/move", "1/3Cc"))
        for h, l in ((100, 1e-3), (100, 1e-6), (100, 1e-7), (1000, 1e-3), (1000, 1e-6), (1000, 1e-7)):
            r, se, ns = run(h, l)
            f.write("%g,%g,%.6g,%.6g,%.6g,%.6g\n" % (h, l, r, se, ns, 1/(3*CC)))
            print("%8g %8g %8.4f±%.4f %9.2f %7.4f" % (h, l, r, se, ns, 1/(3*CC)))


if __name__ == "__main__":
    main()
