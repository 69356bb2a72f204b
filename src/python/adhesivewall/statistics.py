# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The model's own output files: where they are, and the sums asked of them.

    postProcessing/lagrangian/<cloud>/adhesiveWallInteraction/<startTime>/
        statistics.dat   totals per time, patch, injector and size class
        massBalance.dat  the mass balance at write times
        impacts.csv      one line per impact (maxImpactRecords)
        surfaceContact.dat  per time and patch, the impacts so far where
                         the parcel's surface touched (surfaceContacts)
                         and where its centre reached the face first
                         (centreContacts)
"""

import os

from . import tables


def _latest_start_time(parent):
    """The folder of parent named by the largest time ("0" when it has
    none): each run writes its files into the folder of its start time,
    and a restart's totals continue those before it."""
    times = []
    if os.path.isdir(parent):
        for name in os.listdir(parent):
            try:
                times.append((float(name), name))
            except ValueError:
                continue
    return max(times)[1] if times else "0"


def output_folder(case=".", cloud="kinematicCloud", start_time=None):
    """The model's output folder of a run: that of start_time, or by
    default of the latest run (a restart writes into its own start time's
    folder; the totals of statistics.dat, massBalance.dat,
    surfaceContact.dat and gradeEfficiency.dat continue across restarts,
    so the latest run's last rows hold the whole case, while its
    impacts.csv holds that run's impacts only)."""
    parent = os.path.join(case, "postProcessing", "lagrangian", cloud,
                          "adhesiveWallInteraction")
    if start_time is None:
        start_time = _latest_start_time(parent)
    return os.path.join(parent, str(start_time))


def read_statistics(case=".", cloud="kinematicCloud", start_time=None):
    return tables.read(os.path.join(output_folder(case, cloud, start_time),
                                    "statistics.dat"))


def read_impacts(case=".", cloud="kinematicCloud", start_time=None):
    return tables.read(os.path.join(output_folder(case, cloud, start_time),
                                    "impacts.csv"))


def read_mass_balance(case=".", cloud="kinematicCloud", start_time=None):
    return tables.read(os.path.join(output_folder(case, cloud, start_time),
                                    "massBalance.dat"))


def read_surface_contacts(case=".", cloud="kinematicCloud", start_time=None):
    return tables.read(os.path.join(output_folder(case, cloud, start_time),
                                    "surfaceContact.dat"))


def final(statistics, column, **rows):
    """A column of the statistics at their last time, summed over the rows
    selected by `rows` (patch, injector, dMin, ... as text); a KeyError when
    no row is selected."""
    selected = statistics.last_time().where(**rows)
    if not len(selected):
        raise KeyError(f"{statistics.source}: no rows {rows} at the last time")
    return selected.sum(column)


SIZE_CLASS_COLUMNS = ["dMin", "dMax", "impactParticles", "reboundParticles",
                      "captureParticles", "escapeParticles",
                      "captureFraction"]


def _by_class(table, column, selected):
    """The rows of a table at its last time whose column is one of those
    selected (all when None; none: a KeyError), and each size class's rows
    in order of dMin, as ((dMin, dMax), rows) pairs."""
    last = table.last_time()
    if selected is not None:
        held = list(dict.fromkeys(last.text(column)))
        last = last.where(**{column: lambda value: value in selected})
        if not len(last):
            raise KeyError(f"{table.source}: no rows of {selected}; its "
                           f"{column} column holds {held}")
    classes = sorted(set(zip(last.text("dMin"), last.text("dMax"))),
                     key=lambda c: float(c[0]))
    return [((lo, hi), last.where(dMin=lo, dMax=hi)) for lo, hi in classes]


def _text(x):
    """A number in its shortest exact form (0.0226, not
    0.022599999999999999; 1000, not 1000.0)."""
    x = float(x)
    return "%d" % x if x.is_integer() and abs(x) < 1e15 else repr(x)


def walls(statistics):
    """The patches of the statistics at their last time through which
    nothing escaped: the walls (an escape entry's impacts are all escapes,
    a wall entry's none)."""
    last = statistics.last_time()
    names = list(dict.fromkeys(last.text("patch")))
    return [name for name in names
            if last.where(patch=name).sum("escapeParticles") == 0]


def size_classes(statistics, patches=None):
    """Per size class (dMin, dMax) of the statistics at their last time,
    summed over the patches given (by default the walls: those through
    which nothing escaped) and over injectors: the particles that hit a
    wall, rebounded, were captured and escaped, and the fraction of the
    impacts captured. A Table, in order of dMin."""
    if patches is None:
        patches = walls(statistics)
        if not patches:
            raise KeyError(f"{statistics.source}: something escaped through "
                           "every patch, so none is a wall: name the patches")
    rows = []
    for (lo, hi), of in _by_class(statistics, "patch", patches):
        impacts = of.sum("impactParticles")
        captured = of.sum("captureParticles")
        rows.append([lo, hi, _text(impacts),
                     _text(of.sum("reboundParticles")),
                     _text(captured), _text(of.sum("escapeParticles")),
                     _text(captured / impacts) if impacts else "nan"])
    return tables.Table(SIZE_CLASS_COLUMNS, rows, statistics.source)


def plot_size_classes(path, classes, title=""):
    """The fraction of the impacts captured per size class, against the
    class's diameters [um] (a bar per class)."""
    from . import plots
    import numpy as np
    lo = classes["dMin"] * 1e6
    hi = classes["dMax"] * 1e6
    finite = np.isfinite(hi)
    hi = np.where(finite, hi, lo * 2 if lo.max() > 0 else 1)
    fig, ax = plots.figure(8, 5)
    ax.bar(lo, classes["captureFraction"], width=hi - lo, align="edge",
           edgecolor="k", alpha=0.7)
    ax.set_xlabel("particle diameter [um] (size class)")
    ax.set_ylabel("captured / impacts")
    ax.set_ylim(0, 1.05)
    ax.set_title(title)
    plots.save(fig, path)


GRADE_COLUMNS = ["dMin", "dMax", "injectedParcels", "injectedParticles",
                 "capturedParcels", "capturedParticles", "escapedParticles",
                 "removedParticles", "airborneParticles", "capturedFraction"]


def grade_efficiency(grade, injectors=None):
    """Per size class (dMin, dMax) of gradeEfficiency.dat at its last time,
    summed over the injectors given (all by default): the parcels and
    particles injected and captured, the particles escaped, removed and
    airborne, and the grade efficiency capturedFraction = captured /
    injected particles (nan for a class nothing was injected into). A
    Table, in order of dMin."""
    rows = []
    for (lo, hi), of in _by_class(grade, "injector", injectors):
        sums = [of.sum(name) for name in GRADE_COLUMNS[2:-1]]
        injected, captured = sums[1], sums[3]
        fraction = _text(captured / injected) if injected else "nan"
        rows.append([lo, hi] + [_text(x) for x in sums] + [fraction])
    return tables.Table(GRADE_COLUMNS, rows, grade.source)


def plot_grade_efficiency(path, classes, title=""):
    """The grade efficiency per size class against the diameter [um] on a
    logarithmic axis: a point at each class's geometric mean diameter (an
    open class at its one bound), classes nothing was injected into left
    out."""
    from . import plots
    import numpy as np
    lo = classes["dMin"]
    hi = classes["dMax"]
    closed = (lo > 0) & np.isfinite(hi)
    # (the product only of closed classes: 0 * inf would warn)
    mid = np.where(closed, np.sqrt(np.where(closed, lo, 1)
                                   * np.where(closed, hi, 1)),
                   np.where(lo > 0, lo, hi))
    eta = classes["capturedFraction"]
    shown = np.isfinite(eta) & (mid > 0)
    fig, ax = plots.figure(8, 5)
    ax.plot(mid[shown] * 1e6, eta[shown], "o-")
    ax.set_xscale("log")
    ax.set_xlabel("particle diameter [um] (size class, geometric mean)")
    ax.set_ylabel("captured / injected particles")
    ax.set_ylim(0, max(1.1 * eta[shown].max(), 1e-3) if shown.any() else 1)
    ax.set_title(title)
    plots.save(fig, path)


def read_grade_efficiency(case=".", cloud="kinematicCloud", start_time=None):
    """gradeEfficiency.dat: per time, injector and size class, what became
    of the parcels injected (the model writes it with writeToFile)."""
    return tables.read(os.path.join(output_folder(case, cloud, start_time),
                                    "gradeEfficiency.dat"))
