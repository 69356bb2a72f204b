# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Post-processing of the adhesiveWallInteraction library's outputs.

The one place where the model's output files are read (by their column
names), where the correlations of aerosol deposition live (each citing its
source) and where the tutorials' tables, yardsticks and plots are made.

    from adhesivewall import tables
    statistics = tables.read("postProcessing/lagrangian/kinematicCloud/"
                             "adhesiveWallInteraction/0/statistics.dat")
    last = statistics.last_time()
    print(last.where(patch="fibre")["captureParcels"].sum())
"""
