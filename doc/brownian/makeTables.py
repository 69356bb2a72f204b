#!/usr/bin/python3
# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Reads results_*.jsonl and writes tables.md (markdown tables)."""
import json, math, os
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
HS = [0.1, 1, 10, 100, 1e3, 1e4]
DNAME = {0: "0 OF (1/3, sphere)", 1: "1 white noise/calc", 2: "2 per-step force", 3: "3 per-step look-ahead",
         4: "4 exact OU state", 5: "5 setter (Brownian W_n)", 6: "6 setter (exact OU W_n)"}
PNAME = {"R": "R: maxCo 0.3, no cuts (0.3,0.3,0.3,0.1)",
         "U": "U: maxCo 0.25 (4 equal sub-steps)",
         "M01": "M01: maxCo 0.1 (10 x 0.1 + a 1.1e-16 residue)",
         "M002": "M002: maxCo 0.02 (50 sub-steps)",
         "F": "F: faces crossed by the carrier, Co 0.37, 14% 1-ulp residues",
         "F2": "F2: faces crossed by the carrier, Co 2.3 (limiter 0.13), 14% residues",
         "C": "C: random cuts p 0.3 at uniform fraction, 14% residues (stress test)"}


def load(name):
    f = os.path.join(HERE, name)
    if not os.path.exists(f):
        return []
    return [json.loads(l) for l in open(f) if l.strip()]


def ou_stat(t):   # stationary start, tau = D = 1
    return 2*(t - 1 + math.exp(-t))


def ou_rest(t):
    return 2*t - 3 + 4*math.exp(-t) - math.exp(-2*t)


def hfmt(h):
    return "%g" % h


lines = []
P = lines.append

# ------------------------------------------------------------- resp -----
resp = load("results_resp.jsonl")
if resp:
    P("## A. Exact-in-noise D_eff/D (response recursion over 1e5-1e6 sampled steps; pattern-sampling error < 1e-4 unless shown)\n")
    for euler in (0, 1):
        P("### %s scheme\n" % ("analytical" if euler == 0 else "Euler"))
        P("| pattern | design | " + " | ".join("h=%s" % hfmt(h) for h in HS) + " |")
        P("|---|---|" + "---|"*len(HS))
        for pat in PNAME:
            for d in (0, 1, 2, 3):
                row = []
                for h in HS:
                    dd = 1 if d == 0 else d
                    r = [x for x in resp if x["pattern"] == pat and x["design"] == dd and abs(x["h"] - h) < 1e-9*h and x["euler"] == euler]
                    if not r:
                        row.append("")
                        continue
                    v = r[0]["D"]*(1/3 if d == 0 else 1)
                    se = r[0]["Dse"]*(1/3 if d == 0 else 1)
                    row.append("%.4f" % v + (" ±%.4f" % se if se > 1e-4 else ""))
                if any(row):
                    P("| %s | %s | %s |" % (pat, DNAME[d], " | ".join(row)))
        P("")

def table_by_h(mc, pats, cell):
    """One row per pattern and design, one column per h: cell(record, h)"""
    P("| pattern | design | " + " | ".join("h=%s" % hfmt(h) for h in HS) + " |")
    P("|---|---|" + "---|"*len(HS))
    for pat in pats:
        for d in range(7):
            row = []
            for h in HS:
                r = [x for x in mc if x["pattern"] == pat and x["design"] == d and abs(x["h"] - h) < 1e-9*h]
                row.append(cell(r[0], h) if r else "")
            if any(row):
                P("| %s | %s | %s |" % (pat, DNAME[d], " | ".join(row)))
    P("")


# --------------------------------------------------------------- mc -----
for tag, title in (("mc", "analytical scheme"), ("mc_euler", "Euler scheme"), ("mc_m01", "analytical, maxCo 0.1")):
    mc = load("results_%s.jsonl" % tag)
    if not mc:
        continue
    pats = [p for p in PNAME if any(x["pattern"] == p for x in mc)]
    P("## B. Monte Carlo D_eff/D ± 1 standard error (8 replicas), %s\n" % title)
    table_by_h(mc, pats, lambda r, h: "%.4f ±%.4f" % (r["D"], r["Dse"]))
    P("### B2. stationary one-step MSD, MSD(t = DT) / [2 D tau^2 (h - 1 + e^-h)]  (%s)\n" % title)
    table_by_h(mc, pats, lambda r, h: "%.4f" % (r["msd"][0][0]/ou_stat(h)))
    # short-time MSD curve at h = 0.1 and h = 1
    for h0 in (0.1, 1):
        P("### B3. stationary MSD(t)/OU at h = %g, t = lag*DT (%s)\n" % (h0, title))
        sel = [x for x in mc if abs(x["h"] - h0) < 1e-12]
        if not sel:
            continue
        lags = sel[0]["lags"]
        P("| pattern | design | " + " | ".join("t=%g" % (l*h0) for l in lags) + " |")
        P("|---|---|" + "---|"*len(lags))
        for pat in pats:
            for d in range(7):
                r = [x for x in sel if x["pattern"] == pat and x["design"] == d]
                if not r:
                    continue
                row = ["%.4f" % (m/ou_stat(l*h0)) for l, (m, se) in zip(r[0]["lags"], r[0]["msd"])]
                P("| %s | %s | %s |" % (pat, DNAME[d], " | ".join(row)))
        P("")
    P("### B4. parcel velocity variance <U^2>/(kT/m) at step ends (design 4: the separate v_B) (%s)\n" % title)
    table_by_h(mc, pats, lambda r, h: "%.4g" % r["u2"])
    P("### B5. kurtosis of the one-step displacement (Gaussian: 3) (%s)\n" % title)
    table_by_h(mc, pats, lambda r, h: "%.3f" % r["kurt1"])

# ------------------------------------------------------------- rest -----
rest = load("results_rest.jsonl")
if rest:
    P("## C. From rest (U = 0, v = 0 at t = 0), MSD(t)/[D tau^2 (2t/tau - 3 + 4e^-t/tau - e^-2t/tau)], 4e5 parcels\n")
    for pat in PNAME:
        for h in (0.1, 1, 10, 100):
            sel = [x for x in rest if x["pattern"] == pat and abs(x["h"] - h) < 1e-12]
            if not sel:
                continue
            L = len(sel[0]["msd"])
            lags = [l for l in (1, 2, 3, 4, 5, 10, 20, 50, 100) if l <= L]
            P("pattern %s, h = %g\n" % (pat, h))
            P("| design | " + " | ".join("t=%g" % (l*h) for l in lags) + " |")
            P("|---|" + "---|"*len(lags))
            for d in range(7):
                r = [x for x in sel if x["design"] == d]
                if not r:
                    continue
                row = []
                for l in lags:
                    m, se = r[0]["msd"][l - 1]
                    ex = ou_rest(l*h)
                    row.append("%.3f ±%.3f" % (m/ex, se/ex))
                P("| %s | %s |" % (DNAME[d], " | ".join(row)))
            P("")

open(os.path.join(HERE, "tables.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
