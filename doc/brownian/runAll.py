#!/usr/bin/python3
# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Driver: runs bsim over the experiment matrix, one process at a time, under
nice, appending JSON lines to results_*.jsonl.  Usage: run_all.py resp|mc|rest|extra"""
import json, math, subprocess, sys, os

HERE = os.path.dirname(os.path.abspath(__file__))
BSIM = os.path.join(HERE, "bsim")
HS = [0.1, 1, 10, 100, 1e3, 1e4]

# sub-step patterns
PATTERNS = {
    "R":    dict(maxCo=0.3),                          # 0.3,0.3,0.3,0.1 every step
    "U":    dict(maxCo=0.25),                         # uniform 4 x 0.25 (control)
    "M01":  dict(maxCo=0.1),                          # 10 x 0.1 + fp residue 1.1e-16
    "M002": dict(maxCo=0.02),                         # 50 x 0.02 (fp: last 0.0199999999999995)
    "F":    dict(maxCo=0.3, Co=0.37, pshort=0.14),    # faces crossed by the carrier flow, Co = 0.37
    "F2":   dict(maxCo=0.3, Co=2.3, pshort=0.14),     # Co = 2.3 (limiter maxCo/Co = 0.13)
    "C":    dict(maxCo=0.3, pcut=0.3, pshort=0.14),   # random cuts p = 0.3, uniform fraction (stress)
}


def run(args, out, pattern=""):
    cmd = ["nice", "-n", "19", BSIM] + [str(a) for a in args]
    r = subprocess.run(cmd, capture_output=True, text=True, check=True)
    rec = json.loads(r.stdout)
    rec["args"] = " ".join(str(a) for a in args)
    rec["pattern"] = pattern
    with open(out, "a") as f:
        f.write(json.dumps(rec) + "\n")
    return rec


def kv(d):
    out = []
    for k, v in d.items():
        out += [k, v]
    return out


def resp():
    out = os.path.join(HERE, "results_resp.jsonl")
    for pat, pp in PATTERNS.items():
        nsteps = {0.3: 1000000, 0.25: 1000000, 0.1: 400000, 0.02: 100000}[pp["maxCo"]]
        for euler in (0, 1):
            for h in HS:
                for d in (1, 2, 3):
                    rec = run(["mode", "resp", "design", d, "h", h, "euler", euler,
                               "nsteps", nsteps] + kv(pp), out, pat)
                    print(pat, euler, h, d, "%.5f" % rec["D"], flush=True)


def mc(patterns=("R", "F", "C"), designs=(0, 1, 2, 3, 4, 5, 6), euler=0, tag="mc"):
    out = os.path.join(HERE, "results_%s.jsonl" % tag)
    for pat in patterns:
        pp = PATTERNS[pat]
        for d in designs:
            for h in HS:
                L1 = max(4, math.ceil(10.0/h))
                L2 = 2*L1
                ntot = int(1.2e6*L2)
                nrep = 8
                args = ["mode", "mc", "design", d, "h", h, "euler", euler,
                        "nsteps", ntot//nrep, "nrep", nrep] + kv(pp)
                rec = run(args, out, pat)
                print(pat, d, h, "D=%.4f+-%.4f u2=%.4g" % (rec["D"], rec["Dse"], rec["u2"]), flush=True)


def rest(patterns=("C",), designs=(0, 1, 2, 3, 4, 5, 6)):
    out = os.path.join(HERE, "results_rest.jsonl")
    for pat in patterns:
        pp = PATTERNS[pat]
        for d in designs:
            for h in [0.1, 1, 10, 100]:
                lmax = {0.1: 100, 1: 10, 10: 4, 100: 4}[h]
                npar = 400000
                rec = run(["mode", "rest", "design", d, "h", h, "nparcels", npar, "lmax", lmax] + kv(pp), out, pat)
                print(pat, d, h, "msd1=%.5g" % rec["msd"][0][0], flush=True)


if __name__ == "__main__":
    what = sys.argv[1]
    if what == "resp":
        resp()
    elif what == "mc":
        mc()
    elif what == "rest":
        rest()
    elif what == "euler":
        mc(patterns=("C",), designs=(1, 5), euler=1, tag="mc_euler")
    elif what == "m01":
        mc(patterns=("M01",), designs=(1, 2, 3, 5), tag="mc_m01")
