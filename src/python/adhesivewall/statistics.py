# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The model's own output files: where they are, and the sums asked of them.

    postProcessing/lagrangian/<cloud>/adhesiveWallInteraction/<startTime>/
        statistics.dat   totals per time, patch, injector and size class
        massBalance.dat  the mass balance at write times
        impacts.csv      one line per impact (maxImpactRecords)
"""

import os

from . import tables


def output_folder(case=".", cloud="kinematicCloud", start_time="0"):
    return os.path.join(case, "postProcessing", "lagrangian", cloud,
                        "adhesiveWallInteraction", str(start_time))


def read_statistics(case=".", cloud="kinematicCloud", start_time="0"):
    return tables.read(os.path.join(output_folder(case, cloud, start_time),
                                    "statistics.dat"))


def read_impacts(case=".", cloud="kinematicCloud", start_time="0"):
    return tables.read(os.path.join(output_folder(case, cloud, start_time),
                                    "impacts.csv"))


def read_mass_balance(case=".", cloud="kinematicCloud", start_time="0"):
    return tables.read(os.path.join(output_folder(case, cloud, start_time),
                                    "massBalance.dat"))


def final(statistics, column, **rows):
    """A column of the statistics at their last time, summed over the rows
    selected by `rows` (patch, injector, dMin, ... as text); a KeyError when
    no row is selected."""
    selected = statistics.last_time().where(**rows)
    if not len(selected):
        raise KeyError(f"{statistics.source}: no rows {rows} at the last time")
    return selected.sum(column)
