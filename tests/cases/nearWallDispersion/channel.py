# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The turbulent channel of the nearWallDispersion case test, in air
(nu 1.5e-5 m^2/s) at u* 0.5 m/s: wall unit 3e-5 m and 6e-5 s, half-height
180 wall units (5.4 mm), 50 x 10 mm periodic along the flow and across
it; 40 cells a half, the first 0.5 wall units. The frozen RANS flow:
U+ Reichardt's law (kappa 0.41), k+ 1.9 up to y+ 80 falling to 1.3 at the
centre, epsilon from Kallio & Reeks' T_L+ 51.47 (as tests/unit's channel),
nut 0 at the walls.

    channel.py mesh [CELLS]  system/blockMeshDict (CELLS of equal size a
                             half: a wall-function mesh)
    channel.py fields N      0/U, k, epsilon, nut, omega, v2, f (after
                             writeCellCentres)
                             and N tracer positions uniform in the channel
    channel.py lower N       N tracer positions uniform in the lower half
                             (below y+ 176: one processor's of two)
    channel.py bins TIME...  the concentration relative to the mean and its
                             SE per wall-distance bin (y+ 0-1, 1-3, 3-10,
                             10-30, 30-60, 60-100, 100-180), both halves
                             folded: 'a b value se' a line; one time: the
                             binomial SE, several: the mean over them and
                             its SE from their spread
    channel.py cloud [D]     constant/turbulenceProperties and the cloud's
                             properties: particles of D m (0.1 um)
    channel.py seen TIME...  the fluid velocity seen at y+ 1, 5, 10, 30,
                             100 per wall-frame component against the
                             model's rms: 'a b component samples mean se
                             rms se' a line (seen())
"""
import math
import random
import re
import sys

NU, U_STAR = 1.5e-5, 0.5
LP = NU/U_STAR
DELTA = 180*LP
LX, LZ, N = 50e-3, 10e-3, 40
EDGES = [0, 1, 3, 10, 30, 60, 100, 180]
HEADER = "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"


def grading():
    """The last cell over the first of a half: N cells growing
    geometrically from 0.5 wall units to fill 180."""
    lo, hi = 1.0001, 2.0
    for _ in range(200):
        r = 0.5*(lo + hi)
        lo, hi = (r, hi) if 0.5*(r**N - 1)/(r - 1) < 180 else (lo, r)
    return r**(N - 1)


def mesh(cells=N):
    """system/blockMeshDict: N cells a half graded from 0.5 wall units, or
    the number of cells given, of equal size (a wall-function mesh)."""
    g = grading() if cells == N else 1.0
    v = lambda layer, i: 4*layer + i
    quad = lambda *ids: "(%s)" % " ".join(str(i) for i in ids)
    with open("system/blockMeshDict", "w") as f:
        f.write(HEADER % ("dictionary", "blockMeshDict") + "vertices (\n")
        for y in (0, DELTA, 2*DELTA):
            f.write("(0 %r 0) (%r %r 0) (%r %r %r) (0 %r %r)\n"
                    % (y, LX, y, LX, y, LZ, y, LZ))
        f.write(");\nblocks (\n")
        for layer, ratio in ((0, g), (1, 1/g)):
            ids = [v(layer, 0), v(layer, 1), v(layer + 1, 1), v(layer + 1, 0),
                   v(layer, 3), v(layer, 2), v(layer + 1, 2), v(layer + 1, 3)]
            f.write("hex %s (2 %d 1) simpleGrading (1 %r 1)\n"
                    % (quad(*ids), cells, ratio))
        f.write(");\nboundary (\n")
        f.write("walls { type wall; faces (%s %s); }\n"
                % (quad(0, 1, 2, 3), quad(8, 11, 10, 9)))
        pairs = (("left", "right", (0, 3, 7, 4), (4, 7, 11, 8),
                  (1, 5, 6, 2), (5, 9, 10, 6)),
                 ("front", "back", (0, 4, 5, 1), (4, 8, 9, 5),
                  (3, 2, 6, 7), (7, 6, 10, 11)))
        for a, b, fa, fa2, fb, fb2 in pairs:
            f.write("%s { type cyclic; neighbourPatch %s; faces (%s %s); }\n"
                    % (a, b, quad(*fa), quad(*fa2)))
            f.write("%s { type cyclic; neighbourPatch %s; faces (%s %s); }\n"
                    % (b, a, quad(*fb), quad(*fb2)))
        f.write(");\n")


def u_plus(y):
    k = 0.41
    return (math.log(1 + k*y)/k
            + 7.8*(1 - math.exp(-y/11) - (y/11)*math.exp(-y/3)))


def k_plus(y):
    t = min(max((y - 80)/100, 0), 1)
    return 1.9 - 0.6*t*(2 - t)


def write_field(name, cls, dims, values, wall):
    kind = "vector" if cls == "volVectorField" else "scalar"
    with open("0/" + name, "w") as f:
        f.write(HEADER % (cls, name))
        f.write("dimensions %s;\ninternalField nonuniform List<%s> %d (\n"
                % (dims, kind, len(values)))
        f.write("\n".join(values) + "\n);\nboundaryField {\n")
        f.write("    walls { %s }\n" % wall)
        f.write("    \"(left|right|front|back)\" { type cyclic; }\n}\n")


def fields(n):
    text = open("0/Cy").read()
    body = text[text.index("internalField"):]
    count = int(re.search(r"List<scalar>\s*(\d+)", body).group(1))
    body = body[body.index("(") + 1:]
    ys = [float(x) for x in body[:body.index(")")].split()][:count]
    yp = [min(y, 2*DELTA - y)/LP for y in ys]
    k = [U_STAR**2*k_plus(y) for y in yp]
    eps = [v/(51.47*(0.5 + 0.75*2.1))*U_STAR**2/NU for v in k]
    write_field("U", "volVectorField", "[0 1 -1 0 0 0 0]",
                ["(%r 0 0)" % (U_STAR*u_plus(y)) for y in yp],
                "type noSlip;")
    fixed = "type fixedValue; value uniform %s;"
    write_field("k", "volScalarField", "[0 2 -2 0 0 0 0]",
                [repr(v) for v in k], fixed % "1e-12")
    write_field("epsilon", "volScalarField", "[0 2 -3 0 0 0 0]",
                [repr(v) for v in eps], fixed % "1e-12")
    write_field("nut", "volScalarField", "[0 2 -1 0 0 0 0]",
                [repr(0.09*a*a/b) for a, b in zip(k, eps)], fixed % "0")
    # The fields other RAS models read beside k and epsilon, so that the
    # same k and epsilon reach the model under each: kOmegaSST's omega
    # (its epsilon is 0.09 k omega), v2f's v2 and f
    write_field("omega", "volScalarField", "[0 0 -1 0 0 0 0]",
                [repr(b/(0.09*a)) for a, b in zip(k, eps)], fixed % "1e4")
    write_field("v2", "volScalarField", "[0 2 -2 0 0 0 0]",
                [repr(2*a/3) for a in k], fixed % "1e-12")
    write_field("f", "volScalarField", "[0 0 -1 0 0 0 0]",
                ["0"]*len(k), fixed % "0")
    positions(n, 2*DELTA)


def positions(n, top):
    """constant/positions: n tracers uniform in the channel below y = top"""
    rng = random.Random(3)
    with open("constant/positions", "w") as f:
        f.write(HEADER % ("vectorField", "positions") + "%d\n(\n" % n)
        for _ in range(n):
            f.write("(%r %r %r)\n" % (rng.uniform(0, LX),
                                      rng.uniform(0, top),
                                      rng.uniform(0, LZ)))
        f.write(")\n")


TURBULENCE = """FoamFile { version 2.0; format ascii; class dictionary; object turbulenceProperties; }
simulationType RAS;
RAS { RASModel kEpsilon; turbulence on; printCoeffs off; }
"""

CLOUD = """FoamFile { version 2.0; format ascii; class dictionary; object kinematicCloudProperties; }
solution
{
    active true; coupled false; transient yes; cellValueSourceCorrection off;
    maxCo 1;
    sourceTerms { schemes {} }
    interpolationSchemes { rho cell; U cell; mu cell; }
    integrationSchemes { U analytical; }
}
constantProperties { rho0 1000; }
subModels
{
    particleForces
    {
        sphereDrag;
        nearWallDispersion { seed 1; }
    }
    injectionModels
    {
        tracers
        {
            type manualInjection; massTotal 0; parcelBasisType fixed;
            nParticle 1; SOI 0; positionsFile "positions"; U0 (0 0 0);
            sizeDistribution { type fixedValue; fixedValueDistribution { value 1e-7; } }
        }
    }
    dispersionModel none;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs { type rebound; e 1; mu 0; }
    surfaceFilmModel none; stochasticCollisionModel none; collisionModel none;
}
cloudFunctions {}
"""


def cloud(d=None):
    """constant/turbulenceProperties (the frozen RAS flow's kEpsilon) and
    constant/kinematicCloudProperties: particles of diameter d [m] (1000
    kg/m^3, at rest, from constant/positions) with sphereDrag and
    nearWallDispersion, rebound walls, whole steps (no collisions)."""
    with open("constant/turbulenceProperties", "w") as f:
        f.write(TURBULENCE)
    with open("constant/kinematicCloudProperties", "w") as f:
        f.write(CLOUD if d is None
                else CLOUD.replace("value 1e-7;", "value %r;" % d))


def bins(*times):
    """Per bin (EDGES): the concentration relative to the mean and its
    standard error. One time: the binomial SE of its parcels; several (at
    least 10, each more than the Lagrangian integral time after the last):
    their mean and the standard error of the mean over them (block means,
    so that the parcels' correlation in time is taken into account)."""
    from adhesivewall import aerosol
    per_time = []
    for time in times:
        yp = [min(p[1], 2*DELTA - p[1])/LP
              for p in aerosol.positions(".", time)]
        n = len(yp)
        row = []
        for a, b in zip(EDGES[:-1], EDGES[1:]):
            share = (b - a)/180
            count = sum(1 for y in yp if a <= y < b)
            row.append((count/(share*n), math.sqrt((1 - share)/(share*n))))
        per_time.append(row)
    for i, (a, b) in enumerate(zip(EDGES[:-1], EDGES[1:])):
        values = [row[i][0] for row in per_time]
        mean = sum(values)/len(values)
        if len(values) == 1:
            se = per_time[0][i][1]
        else:
            var = sum((v - mean)**2 for v in values)/(len(values) - 1)
            se = math.sqrt(var/len(values))
        print(a, b, mean, se)


SEEN_BINS = [(0.5, 1.5), (4, 6), (8, 12), (25, 35), (90, 110)]


def _lagrangian(time, name):
    from adhesivewall import foam
    return foam.list_file("%s/lagrangian/kinematicCloud/%s" % (time, name))


def _seen_moments(time):
    """Per bin of SEEN_BINS and wall-frame component (streamwise, normal,
    spanwise): the samples' count, mean w, mean w^2 and their standard
    errors (the parcels are independent). w is the state a parcel ended
    its step with (UTurb, the frame's components given along the global
    axes) at its wall distance then (tTurb); the frame of the lower wall
    is (x, y, z), of the upper (x, -y, -z)."""
    from adhesivewall import aerosol
    ws = _lagrangian(time, "UTurb")
    ys = _lagrangian(time, "tTurb")
    sides = [1 if p[1] < DELTA else -1
             for p in aerosol.positions(".", time)]
    rows = []
    for a, b in SEEN_BINS:
        picked = [(w[0], s*w[1], s*w[2]) for w, y, s in zip(ws, ys, sides)
                  if a <= y/LP < b]
        row = []
        for i in range(3):
            v = [w[i] for w in picked]
            n = len(v)
            m1 = sum(v)/n
            m2 = sum(x*x for x in v)/n
            s1 = math.sqrt(sum((x - m1)**2 for x in v)/(n - 1)/n)
            s2 = math.sqrt(sum((x*x - m2)**2 for x in v)/(n - 1)/n)
            row.append((n, m1, s1, m2, s2))
        rows.append(row)
    return rows


def seen(*times):
    """The fluid velocity seen against the model's prescribed rms: per bin
    of SEEN_BINS and wall-frame component, 'a b component samples mean
    se rms se' a line, the mean and rms of u_i/sigma_i = w_i, the state's
    normalised velocity seen (u_i = sigma_i(y) w_i at the parcel's wall
    distance: rms(u_i) = sigma_i there exactly when w_i has unit rms, and
    well-mixed tracers see a zero mean). One time: the SE from the
    parcels' spread; several: the mean over them and its SE from their
    spread (block means)."""
    per_time = [_seen_moments(t) for t in times]
    for j, (a, b) in enumerate(SEEN_BINS):
        for i, name in enumerate(("streamwise", "normal", "spanwise")):
            cells = [rows[j][i] for rows in per_time]
            n = sum(c[0] for c in cells)
            if len(cells) == 1:
                _, m1, s1, m2, s2 = cells[0]
            else:
                k = len(cells)
                m1 = sum(c[1] for c in cells)/k
                m2 = sum(c[3] for c in cells)/k
                s1 = math.sqrt(sum((c[1] - m1)**2 for c in cells)
                               /(k - 1)/k)
                s2 = math.sqrt(sum((c[3] - m2)**2 for c in cells)
                               /(k - 1)/k)
            rms = math.sqrt(m2)
            print(a, b, name, n, m1, s1, rms, s2/(2*rms))


if __name__ == "__main__":
    {"mesh": lambda: mesh(*[int(c) for c in sys.argv[2:3]]), "fields": lambda: fields(int(sys.argv[2])),
     "lower": lambda: positions(int(sys.argv[2]), 0.98*DELTA),
     "bins": lambda: bins(*sys.argv[2:]),
     "seen": lambda: seen(*sys.argv[2:]),
     "cloud": lambda: cloud(*[float(d) for d in sys.argv[2:3]])}[sys.argv[1]]()
