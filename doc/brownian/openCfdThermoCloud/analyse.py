#!/usr/bin/python3
# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Mean squared displacement and velocity of the parcels of Allrun's runs.

    analyse.py runDir results.csv

For every run (a folder with a runInfo file) and every written time: the
parcels' mean squared displacement from the release point, with its standard
error from the sample (std(r^2)/sqrt(N)), against the Ornstein-Uhlenbeck
process of a sphere released at rest with Stokes drag (what sphereDrag
implies: tau = rho d^2/(18 mu), D = kB T/(3 pi mu d), no slip):

    msdExpected = 3 D tau (2 s - 3 + 4 exp(-s) - exp(-2 s)),   s = t/tau,

with t the parcels' age.  Also written: 6 D t, the thermal-start form
6 D tau (s - 1 + exp(-s)), the ratio to the slip-corrected Stokes-Einstein
value (D_SE = D Cc, Cunningham with Davies' 1945 coefficients, the same
formula as the force), the mean squared velocity against 3 kB T/m, and the
"model": the same two moments for OpenFOAM's force as doc/brownian-motion.md
reads it, computed exactly (covariance recursion, per component) for the
sub-steps the move loop takes in this case (maxCo only, no face is crossed):
force f |N| e, e uniform on the sphere, f^2 = m^2 pi S0/dt, i.e. per
component a white noise of variance 2 kB T m/(3 Cc tau dt), held over each
sub-step, the velocity advanced by the analytical scheme.
Beside results.csv, diffusivity.csv: per run the long-time D_eff/D from the
slope of the MSD between the middle and the last write (per parcel, so with
the standard error of a mean), with the model's value and 1/(3 Cc).
numpy only.
"""

import math
import os
import re
import sys

import numpy as np

KB = 1.380649e-23  # Boltzmann constant, J/K


def read_text(path):
    with open(path) as f:
        return f.read()


def entry(text, key):
    """The number of the first 'key value;' in an OpenFOAM dictionary text."""
    m = re.search(r"(?<![\w:])" + re.escape(key) + r"\s+(?:uniform\s+)?([-+0-9.eE]+)\s*;", text)
    if not m:
        raise ValueError("no entry " + key)
    return float(m.group(1))


def read_field(path):
    """An ascii lagrangian field of OpenFOAM as an (N, k) array."""
    text = read_text(path)
    text = re.sub(r"FoamFile\s*\{.*?\}", "", text, count=1, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    m = re.match(r"\s*(\d+)\s*([({])", text)
    n = int(m.group(1))
    if m.group(2) == "{":  # every value the same: N{value}
        body = text[m.end():text.index("}", m.end())]
        v = np.array(body.replace("(", " ").replace(")", " ").split(), float)
        return np.tile(v, (n, 1))
    body = text[m.end():text.rindex(")")]
    v = np.array(body.replace("(", " ").replace(")", " ").split(), float)
    return v.reshape(n, -1)


def cunningham(d, lam):
    kn = 2.0*lam/d
    return 1.0 + kn*(1.257 + 0.4*math.exp(-1.1/kn))


def substeps(maxCo):
    """Step fractions of one move: f = min(1 - sf, maxCo) (no face crossed)."""
    fr, sf = [], 0.0
    while sf < 1.0:
        f = min(1.0 - sf, maxCo)
        fr.append(f)
        sf += f
    return fr


def model(nMoves, deltaT, maxCo, tau, q):
    """Var x and Var u per component after nMoves moves from rest; q is the
    variance of force/mass times the sub-step (m^2 s^-3)."""
    fr = substeps(maxCo)
    vxx = vxu = vuu = 0.0
    for _ in range(nMoves):
        for f in fr:
            dt = f*deltaT
            rho = math.exp(-dt/tau)
            vxx, vxu, vuu = (vxx + 2*dt*vxu + dt*dt*vuu,
                             rho*(vxu + dt*vuu),
                             rho*rho*vuu + (1 - rho)**2*tau*tau*q/dt)
    return vxx, vuu


def times(runPath):
    out = []
    for name in os.listdir(runPath):
        try:
            t = float(name)
        except ValueError:
            continue
        if t > 0 and os.path.isfile(os.path.join(runPath, name, "lagrangian", "reactingCloud1", "positions")):
            out.append((t, name))
    return sorted(out)


def analyse(runPath):
    info = dict(line.split(None, 1) for line in read_text(os.path.join(runPath, "runInfo")).splitlines())
    cloud = read_text(os.path.join(runPath, "constant", "reactingCloud1Properties"))
    thermo = read_text(os.path.join(runPath, "constant", "thermophysicalProperties"))
    rhoP = entry(cloud, "rho0")
    lam = entry(cloud, "lambda")
    mu = entry(thermo, "mu")
    T = entry(read_text(os.path.join(runPath, "0", "T")), "internalField")
    pos0 = np.array(info["x0"].split(), float)  # the release point

    d, deltaT, maxCo = float(info["d"]), float(info["deltaT"]), float(info["maxCo"])
    tau = rhoP*d*d/(18*mu)
    D = KB*T/(3*math.pi*mu*d)
    cc = cunningham(d, lam)
    m = rhoP*math.pi*d**3/6
    q = 2*KB*T/(m*cc*tau)/3  # (force/mass)^2 dt per component, OpenFOAM's force

    rows, last, r2s = [], None, []
    for t, name in times(runPath):
        lag = os.path.join(runPath, name, "lagrangian", "reactingCloud1")
        pos = read_field(os.path.join(lag, "positions"))
        age = read_field(os.path.join(lag, "age"))[:, 0]
        U = read_field(os.path.join(lag, "U"))
        ids = np.stack([read_field(os.path.join(lag, "origProcId"))[:, 0],
                        read_field(os.path.join(lag, "origId"))[:, 0]], axis=1)
        n = len(pos)
        if np.ptp(age) > 1e-9*age.max():
            raise ValueError(runPath + " " + name + ": parcels of different ages")
        a = age.mean()
        r2 = ((pos[:, :3] - pos0)**2).sum(axis=1)
        u2 = (U**2).sum(axis=1)
        s = a/tau
        msdRest = 3*D*tau*(2*s - 3 + 4*math.exp(-s) - math.exp(-2*s))
        msdThermal = 6*D*tau*(s - 1 + math.exp(-s))
        nMoves = int(round(a/deltaT))
        vxx, vuu = model(nMoves, deltaT, maxCo, tau, q)
        u2Thermal = 3*KB*T/m
        rows.append(dict(
            case=info["name"], mesh=info["mesh"], d=d, h=deltaT/tau, maxCo=maxCo, nProc=int(info["nProc"]),
            N=n, t=a, tOverTau=s, nCells=len(np.unique(pos[:, 3])),
            maxDisp=np.abs(pos[:, :3] - pos0).max(),
            msd=r2.mean(), msdSE=r2.std(ddof=1)/math.sqrt(n), msdExpected=msdRest,
            ratio=r2.mean()/msdRest, ratioSE=r2.std(ddof=1)/math.sqrt(n)/msdRest,
            ratioModel=3*vxx/msdRest, ratio6Dt=r2.mean()/(6*D*a),
            ratioThermal=r2.mean()/msdThermal, ratioSlip=r2.mean()/(msdRest*cc), Cc=cc,
            u2Ratio=u2.mean()/u2Thermal, u2RatioSE=u2.std(ddof=1)/math.sqrt(n)/u2Thermal,
            u2Model=3*vuu/u2Thermal,
            r4Gauss=(r2**2).mean()/r2.mean()**2/(5.0/3.0),  # 1 for a Gaussian displacement
        ))
        last = (name, ids, pos)
        r2s.append((a, nMoves, r2))
    # Long-time diffusivity from the slope of the MSD between the middle and
    # the last write, per parcel (so its standard error is that of a mean)
    diff = None
    if len(r2s) >= 2:
        (t1, n1, a1), (t2, n2, a2) = r2s[(len(r2s) - 1)//2], r2s[-1]
        inc = (a2 - a1)/(6*(t2 - t1)*D)
        m1, m2 = model(n1, deltaT, maxCo, tau, q)[0], model(n2, deltaT, maxCo, tau, q)[0]
        diff = dict(case=info["name"], mesh=info["mesh"], d=d, h=deltaT/tau, maxCo=maxCo,
                    nProc=int(info["nProc"]), N=len(a2), t1OverTau=t1/tau, t2OverTau=t2/tau,
                    DeffOverD=inc.mean(), DeffOverDSE=inc.std(ddof=1)/math.sqrt(len(inc)),
                    model=3*(m2 - m1)/(6*(t2 - t1)*D), oneThirdCc=1/(3*cc), Cc=cc,
                    DeffOverDSlip=inc.mean()/cc)
    return rows, last, diff


COLUMNS = ["case", "mesh", "d", "h", "maxCo", "nProc", "N", "t", "tOverTau", "msd", "msdSE",
           "msdExpected", "ratio", "ratioSE", "ratioModel", "ratio6Dt", "ratioThermal",
           "ratioSlip", "Cc", "u2Ratio", "u2RatioSE", "u2Model", "r4Gauss", "nCells", "maxDisp"]

DCOLUMNS = ["case", "mesh", "d", "h", "maxCo", "nProc", "N", "t1OverTau", "t2OverTau",
            "DeffOverD", "DeffOverDSE", "model", "oneThirdCc", "Cc", "DeffOverDSlip"]


def fmt(v):
    if isinstance(v, float):
        return "%.6g" % v
    return str(v)


def same(a, b):
    """Largest position difference of two runs' last writes, parcels matched
    by origId (both runs release them in the same order)."""
    (na, ida, pa), (nb, idb, pb) = a, b
    if na != nb or len(pa) != len(pb):
        return float("nan")
    ia = np.lexsort((ida[:, 1],))
    ib = np.lexsort((idb[:, 1],))
    return float(np.abs(pa[ia, :3] - pb[ib, :3]).max())


def main():
    runDir, out = sys.argv[1], sys.argv[2]
    runs = sorted(r for r in os.listdir(runDir) if os.path.isfile(os.path.join(runDir, r, "runInfo")))
    allRows, lasts, diffs = [], {}, []
    for r in runs:
        rows, last, diff = analyse(os.path.join(runDir, r))
        if not rows:
            sys.exit("%s: no parcels written" % r)
        allRows += rows
        lasts[r] = last
        if diff:
            diffs.append(diff)
    dOut = os.path.join(os.path.dirname(out), "diffusivity.csv")
    with open(dOut, "w") as f:
        f.write(",".join(DCOLUMNS) + "\n")
        for row in diffs:
            f.write(",".join(fmt(row[c]) for c in DCOLUMNS) + "\n")
    with open(out, "w") as f:
        f.write(",".join(COLUMNS) + "\n")
        for row in allRows:
            f.write(",".join(fmt(row[c]) for c in COLUMNS) + "\n")

    print("%-17s %8s %6s %5s %7s %6s %16s %7s %8s %16s %7s" % (
        "case", "h", "maxCo", "ranks", "t/tau", "N", "MSD/expected", "model", "MSD/6Dt", "u2/thermal", "model"))
    for r in runs:
        rs = [x for x in allRows if x["case"] == r]
        for x in (rs[0], rs[-1]):
            print("%-17s %8.3g %6.3g %5d %7.4g %6d %8.4f±%.4f %7.4f %8.4f %8.4f±%.4f %7.4f" % (
                x["case"], x["h"], x["maxCo"], x["nProc"], x["tOverTau"], x["N"],
                x["ratio"], x["ratioSE"], x["ratioModel"], x["ratio6Dt"],
                x["u2Ratio"], x["u2RatioSE"], x["u2Model"]))
    print()
    print("%-17s %6s %8s %6s %5s %7s %16s %7s %7s" % (
        "case", "mesh", "h", "maxCo", "ranks", "N", "Deff/D", "model", "1/3Cc"))
    for x in diffs:
        print("%-17s %6s %8.3g %6.3g %5d %7d %8.4f±%.4f %7.4f %7.4f" % (
            x["case"], x["mesh"], x["h"], x["maxCo"], x["nProc"], x["N"],
            x["DeffOverD"], x["DeffOverDSE"], x["model"], x["oneThirdCc"]))
    for a, b in (("d1000h10", "d1000h10again"), ("d1000h10", "d1000h10np2")):
        if a in lasts and b in lasts:
            print("largest position difference %s / %s at t = %s: %.3g m" % (a, b, lasts[a][0], same(lasts[a], lasts[b])))


if __name__ == "__main__":
    main()
