# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Deposition velocity from the model's files: V_d per patch, size class
and time window.

    V_d = J/C,   J = N/(A dt),   C = mean(n_airborne)/V

N the particles captured on the patch in the window (statistics.dat's
captureParticles at the window's end less at its start), A the patch's
area, dt the window's length, n_airborne the airborne particles of the
size class (gradeEfficiency.dat, its rows in the window averaged) and V
the domain's volume: C is the cross-section (volume) mean concentration.
A user's own concentration [1/m^3] may replace it.

Standard error: the captures are Poisson in parcels (N counts parcels of
the same number of particles each: relative error 1/sqrt(captureParcels));
the concentration's from the means of up to 10 consecutive batches of its
rows (their standard deviation over sqrt(batches)); the two relative
errors combined in quadrature. A window without captures reports 0 with
the error of one parcel's capture.

Where the class's airborne count changes in the window only by its
captures (nothing injected, escaped or removed: a closed or periodic
domain whose parcels were all injected before), the concentration is
counted, not sampled: its error is none, and a decaying population
(captures deplete it) is not taken for a fluctuating one.

Spin-up: the run from time 0 to its last row is cut into 10 blocks of
equal length; per size class, the deposition rate per airborne particle
of all patches together is taken per block (a constant where the class
is steady, and also where captures deplete it, as in a closed pipe); a
class's spin-up ends at the first block k (k at most 5) from which its
blocks' rates, over the blocks with airborne particles, are consistent
with one constant: their chi-square about their weighted mean below its
99th percentile (Wilson & Hilferty's approximation, z = 2.326). The
spin-up is the latest of the classes'. Where a class has no such k the
second half is used, and the result says so.

Areas and volume come from the case's constant/polyMesh (polymesh.py).

Uniformity: V_d as J/C assumes the airborne concentration uniform over the
cross-section; where the parcels gather near the walls or away from them,
the volume mean is not the concentration that drives deposition. The
airborne parcels written in the window's time folders (their cells) give
the concentration in the cells on the capturing walls against the mean
(captured parcels that stay in the cloud, inactive, are not counted); a
ratio outside [1/2, 2] by more than 3 binomial standard errors is warned
of.

References:
    Wilson, E.B. and Hilferty, M.M. (1931). The distribution of
    chi-square. Proc. Natl. Acad. Sci. 17:684-688.
"""

import math
import os
import re
import sys

import numpy as np

from . import foam
from . import polymesh
from . import statistics
from . import tables

COLUMNS = ["patch", "dMin", "dMax", "tStart", "tEnd", "captureParcels",
           "captureParticles", "airborneParticles", "concentration", "Vd",
           "VdSE"]

# The units of COLUMNS, in order: m, m, s, s, -, -, -, 1/m^3, m/s, m/s
BLOCKS = 10


def read_all_runs(case, cloud, name):
    """A table of the model's (statistics.dat or gradeEfficiency.dat) over
    all runs of the case: each run's rows from its start time on replace
    the earlier runs' (a restart's totals continue them)."""
    parent = os.path.dirname(statistics.output_folder(case, cloud, "0"))
    starts = sorted((float(d), d) for d in os.listdir(parent)
                    if tables.is_number(d))
    merged = None
    for value, folder in starts:
        path = os.path.join(parent, folder, name)
        if not os.path.isfile(path):
            continue
        table = tables.read(path)
        if merged is None:
            merged = table
            continue
        kept = [row for row, t in zip(merged.rows, merged["time"])
                if t < value]
        merged = tables.Table(merged.names, kept + table.rows, table.source)
    if merged is None:
        raise FileNotFoundError(os.path.join(parent, "0", name))
    return merged


def _classes(table):
    return sorted({(float(a), float(b)) for a, b in
                   zip(table["dMin"], table["dMax"])})


def _total_at(table, column, time, **rows):
    """The column's total over the rows selected at the last row time at
    or before `time` (0 before the first)."""
    times = table["time"]
    before = times[times <= time + 1e-12*max(abs(time), 1e-300)]
    if not len(before):
        return 0.0
    return table.where(time=float(before.max()), **rows).sum(column)


def _injectors_once(table):
    """The rows that count each particle once: the injector 'all' where
    the table has it, else every injector's (to be summed)."""
    if "all" in table.unique("injector"):
        return table.where(injector="all")
    return table


def _airborne(grade, d_min, d_max, t_start, t_end,
              column="airborneParticles"):
    """The airborne particles (or parcels) of a size class at each row time
    in (tStart, tEnd], summed over the injectors."""
    rows = grade.where(dMin=d_min, dMax=d_max,
                       time=lambda t: t_start < float(t) <= t_end)
    per_time = {}
    for t, n in zip(rows["time"], rows[column]):
        per_time[t] = per_time.get(t, 0.0) + n
    return np.array([per_time[t] for t in sorted(per_time)])


def _counted(grade, d_min, d_max, t_start, t_end):
    """Whether the class's airborne particles change in (t_start, t_end]
    only by captures: its injected, escaped and removed particles the same
    at both ends (False without those columns)."""
    names = ("injectedParticles", "escapedParticles", "removedParticles")
    if not all(name in grade for name in names):
        return False
    rows = grade.where(dMin=d_min, dMax=d_max)
    return all(_total_at(rows, name, t_end) == _total_at(rows, name, t_start)
               for name in names)


def _batch_error(values):
    """The standard error of the mean of a series from the means of up to
    10 consecutive batches (0 with fewer than 2 values)."""
    batches = [b for b in np.array_split(values, min(BLOCKS, len(values)))
               if len(b)]
    if len(batches) < 2:
        return 0.0
    means = np.array([b.mean() for b in batches])
    return float(means.std(ddof=1)/math.sqrt(len(means)))


def window_rows(stats, grade, areas, volume, t_start, t_end,
                concentration=None, patches=None):
    """The rows (COLUMNS) of the window (tStart, tEnd]: every patch named,
    or of statistics.dat that captured something in the run (the walls),
    every size class."""
    walls = patches if patches is not None else [
        p for p in stats.unique("patch")
        if stats.last_time().where(patch=p).sum("captureParticles") > 0]
    rows = []
    for patch in walls:
        if patch not in areas:
            raise KeyError(f"no patch '{patch}' in the mesh's boundary")
        for d_min, d_max in _classes(stats):
            select = dict(patch=patch, dMin=d_min, dMax=d_max)
            parcels, particles = (
                _total_at(stats, c, t_end, **select)
                - _total_at(stats, c, t_start, **select)
                for c in ("captureParcels", "captureParticles"))
            airborne = _airborne(grade, d_min, d_max, t_start, t_end)
            carriers = _airborne(grade, d_min, d_max, t_start, t_end,
                                 "airborneParcels")
            per_parcel = (airborne.sum()/carriers.sum()
                          if carriers.sum() > 0 else 1.0)
            rows.append(_row(patch, d_min, d_max, t_start, t_end, parcels,
                             particles, airborne, areas[patch], volume,
                             concentration, per_parcel,
                             _counted(grade, d_min, d_max, t_start, t_end)))
    return rows


def _row(patch, d_min, d_max, t_start, t_end, parcels, particles,
         airborne, area, volume, concentration, per_parcel, counted=False):
    """One row: V_d and its standard error (module's description);
    per_parcel the class's particles per airborne parcel (the error of a
    window without captures is one parcel's); counted where the airborne
    count changes only by captures (_counted: no error of its own)."""
    mean = float(airborne.mean()) if len(airborne) else 0.0
    if concentration is None:
        c = mean/volume
        c_error = (_batch_error(airborne)/mean
                   if mean > 0 and not counted else 0.0)
    else:
        c, c_error = concentration, 0.0
    if not c > 0:
        return [patch, d_min, d_max, t_start, t_end, parcels, particles,
                mean, c, float("nan"), float("nan")]
    flux = particles/(area*(t_end - t_start))
    per_capture = per_parcel/(area*(t_end - t_start)*c)
    vd = flux/c
    n_error = 1/math.sqrt(parcels) if parcels > 0 else 0.0
    if parcels > 0:
        se = vd*math.hypot(n_error, c_error)
    else:
        se = per_capture
    return [patch, d_min, d_max, t_start, t_end, parcels, particles, mean,
            c, vd, se]


def chi2_quantile99(dof):
    """The 99th percentile of chi-square with dof degrees of freedom
    (Wilson & Hilferty 1931)."""
    z = 2.326
    return dof*(1 - 2/(9*dof) + z*math.sqrt(2/(9*dof)))**3


def _first_steady_block(rates, errors):
    """The first block k (at most BLOCKS//2) from which the rates are
    consistent with one constant (chi-square below its 99th percentile),
    over the blocks with airborne particles (error > 0); None if none."""
    for k in range(BLOCKS//2 + 1):
        r, e = rates[k:], errors[k:]
        r, e = r[e > 0], e[e > 0]
        if len(r) < 2:
            return k if len(r) else None
        w = 1/e**2
        mean = float((w*r).sum()/w.sum())
        if float((((r - mean)/e)**2).sum()) < chi2_quantile99(len(r) - 1):
            return k
    return None


def spin_up(stats, grade):
    """(the end of the spin-up [s], whether the blocks after it are
    steady): module's description, per size class (the latest of the
    classes' ends; steady where every class is); the tables with each
    particle once (_injectors_once)."""
    t_last = float(stats["time"].max())
    edges = np.linspace(0.0, t_last, BLOCKS + 1)
    last = 0
    for d_min, d_max in _classes(stats):
        captured = stats.where(dMin=d_min, dMax=d_max)
        airborne_rows = grade.where(dMin=d_min, dMax=d_max)
        rates, errors = [], []
        for a, b in zip(edges[:-1], edges[1:]):
            parcels = (_total_at(captured, "captureParcels", b)
                       - _total_at(captured, "captureParcels", a))
            n = airborne_rows.where(time=lambda t: a < float(t) <= b)
            mean = (n.sum("airborneParcels")/len(n.unique("time"))
                    if len(n) else 0.0)
            scale = 1/(mean*(b - a)) if mean > 0 else 0.0
            rates.append(parcels*scale)
            errors.append(math.sqrt(max(parcels, 1.0))*scale)
        k = _first_steady_block(np.array(rates), np.array(errors))
        if k is None:
            return float(edges[BLOCKS//2]), False
        last = max(last, k)
    return float(edges[last]), True


def deposition_velocity(case=".", cloud="kinematicCloud", windows=1,
                        start=None, concentration=None, areas=None,
                        volume=None, patches=None):
    """The rows (COLUMNS) of `windows` equal windows from the end of the
    spin-up (or `start`) to the last row, and whether the spin-up's blocks
    were steady (True where `start` is given); the patches named, or those
    that captured something."""
    stats = _injectors_once(read_all_runs(case, cloud, "statistics.dat"))
    grade = _injectors_once(read_all_runs(case, cloud, "gradeEfficiency.dat"))
    if areas is None or volume is None:
        mesh_areas, mesh_volume = polymesh.areas_and_volume(case)
        areas = areas if areas is not None else mesh_areas
        volume = volume if volume is not None else mesh_volume
    steady = True
    if start is None:
        start, steady = spin_up(stats, grade)
    t_last = float(stats["time"].max())
    if not start < t_last:
        raise ValueError(f"the start {start} s is not before the last "
                         f"row's time {t_last} s")
    edges = np.linspace(start, t_last, windows + 1)
    rows = []
    for a, b in zip(edges[:-1], edges[1:]):
        rows += window_rows(stats, grade, areas, volume, float(a), float(b),
                            concentration, patches)
    return rows, steady


def _airborne_cells(case, cloud, time):
    """The cells of the airborne (active) parcels written at a time: the
    'positions' file's '(x y z) cell' lines, less the parcels the 'active'
    field marks 0 (captured parcels kept at the wall)."""
    folder = os.path.join(case, time, "lagrangian", cloud)
    with open(os.path.join(folder, "positions")) as handle:
        cells = np.array(re.findall(r"\)\s+(\d+)", handle.read()), dtype=int)
    if os.path.isfile(os.path.join(folder, "active")):
        active = np.array(foam.list_file(os.path.join(folder, "active")),
                          dtype=float)
        if len(active) == len(cells):
            cells = cells[active != 0]
    return cells


def uniformity(case, cloud, patches, t_start, t_end):
    """(ratio, its standard error, parcels) of the airborne concentration
    in the cells on the patches to the mean, over the airborne parcels
    written in the time folders in (t_start, t_end]; None without such
    folders or parcels. The standard error is the binomial one of the
    fraction of the parcels found in those cells, over their volume
    share."""
    cells = np.zeros(0, dtype=int)
    for name in os.listdir(case):
        if not tables.is_number(name) or not t_start < float(name) <= t_end:
            continue
        if os.path.isfile(os.path.join(case, name, "lagrangian", cloud,
                                       "positions")):
            cells = np.concatenate(
                [cells, _airborne_cells(case, cloud, name)])
    if not len(cells):
        return None
    volumes = polymesh.cell_volumes(case)
    near = np.array(polymesh.cells_on(case, patches), dtype=int)
    share = volumes[near].sum()/volumes.sum()
    n = len(cells)
    found = np.isin(cells, near).sum()/n
    return found/share, np.sqrt(found*(1 - found)/n)/share, n


def far_from_uniform(ratio, error):
    """Whether a uniformity ratio lies outside [1/2, 2] by more than 3
    standard errors."""
    return ratio - 3*error > 2 or ratio + 3*error < 0.5


def _options(arguments):
    """(case, cloud, keyword arguments) of the command line."""
    names = {"-windows": ("windows", int), "-start": ("start", float),
             "-concentration": ("concentration", float)}
    positional, options = [], {}
    i = 0
    while i < len(arguments):
        if arguments[i] in names:
            if i + 1 == len(arguments):
                raise ValueError(f"{arguments[i]} needs a value")
            key, kind = names[arguments[i]]
            options[key] = kind(arguments[i + 1])
            i += 2
        else:
            positional.append(arguments[i])
            i += 1
    if not 1 <= len(positional) <= 2:
        raise ValueError("give CASE [CLOUD]")
    return positional[0], (positional[1:] or ["kinematicCloud"])[0], options


def run(arguments):
    """adhesiveWallPost depositionVelocity CASE [CLOUD] [-windows N]
    [-start TIME] [-concentration C]: the rows as CSV on standard output;
    the spin-up's end and whether it was found steady, and a warning where
    the airborne profile is far from uniform, on standard error; bad input
    in one line (exit status 1)."""
    try:
        case, cloud, options = _options(arguments)
        rows, steady = deposition_velocity(case, cloud, **options)
    except (ValueError, KeyError, FileNotFoundError) as err:
        print(f"adhesiveWallPost depositionVelocity: {err}", file=sys.stderr)
        return 1
    if rows:
        print(f"from {rows[0][3]} s" + ("" if steady else
              ": no steady deposition rate found in the first half of the"
              " run; the second half used"), file=sys.stderr)
        walls = sorted({row[0] for row in rows})
        found = uniformity(case, cloud, walls, rows[0][3], rows[-1][4])
        if found and far_from_uniform(found[0], found[1]):
            print(f"warning: the airborne concentration in the cells on "
                  f"{' '.join(walls)} is {found[0]:.3g} +- {found[1]:.2g} "
                  f"times the mean ({found[2]} parcels written): V_d as a "
                  f"volume mean's is not that of the concentration near "
                  f"the walls", file=sys.stderr)
    print(",".join(COLUMNS))
    for row in rows:
        print(",".join(str(v) for v in row))
    return 0
