# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""adhesiveWallPost COMMAND [ARGUMENTS]: the package from the shell.

Commands:
  bendDeposition [CASE]      post-processing of the tutorials (their
  channelResuspension [CASE] Allrun.post): results.csv, log.table, plots
  fibreFilter [CASE]
  microsphereImpact [CASE]
  pipeDeposition [CASE]
  pipeFlow [CASE]            pipeDeposition's flow against the law of the
                             wall and the friction laws (Allrun.flow)
  settlingChannel [CASE]
  tubeDiffusion [CASE]

  compare CASE REFERENCE     the files under the folder REFERENCE against
                             those of CASE: tables by column name, numbers
                             to 1e-12 relative, other files line for line
                             (tests/golden); exit status 1 on a difference

  sizeClasses CASE [CLOUD [PATCH...]]
                             per size class of the model's statistics at
                             their last time, summed over the patches named
                             (by default the walls: the patches through
                             which nothing escaped): impacts, rebounds,
                             captures, escapes (particles) and the fraction
                             captured, as CSV; sizeClasses.png in the
                             case's folder

  gradeEfficiency CASE [CLOUD [INJECTOR...]]
                             per size class of the model's
                             gradeEfficiency.dat at its last time (all
                             injectors, or those named): particles
                             injected, captured, escaped, removed,
                             airborne and the grade efficiency
                             (captured/injected), as CSV;
                             gradeEfficiency.png in the case's folder

  Both read the latest run of CASE (a restart's totals continue those of
  the runs before it).

  depositionVelocity CASE [CLOUD] [-windows N] [-start TIME]
                     [-concentration C]
                             per wall patch, size class and time window
                             after the spin-up (or TIME): the deposition
                             velocity V_d [m/s] and its standard error,
                             from statistics.dat, gradeEfficiency.dat and
                             the mesh (doc/guide/outputs.md), as CSV

  check SUBCOMMAND ...       the case tests' checks (adhesiveWallPost check
                             -help lists them)

  bendPositions N            the rows of the bend's positions files (N
                             parcels, flow-weighted over the inlet)
  microsphereParcels N       the rows of microsphereImpact's parcel tables
                             (N speeds per diameter of figure5.csv)
  tubePositions [CASE]       tubeDiffusion's positions files (flux-weighted
                             over the inlet, one per injector)
  pipePositions [CASE]       pipeDeposition's positions files (uniform in
                             the pipe, one per injector)
  pipeTimeStep [CASE]        pipeDeposition's time-step independence
                             (after Allrun.timeStep): log.timeStep
  channelPositions [CASE]    channelResuspension's positions files (above
                             the floor, one per injector)
  channelTop [CASE]          channelResuspension's top wall speed at the
                             latest time (every processor folder)
  fibreSpectrum CASE VARIANT fibreFilter's spectrum sub-case: its injectors
                             and positions (VARIANT full or reduced)
"""

import os
import sys


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or any(a in ("-h", "-help", "--help") for a in argv[:2]):
        print(__doc__)
        return 0 if argv else 1
    command, arguments = argv[0], argv[1:]
    if command in TUTORIALS:
        module = __import__("adhesivewall.tutorials." + TUTORIALS[command],
                            fromlist=["run"])
        module.run(*arguments)
        return 0
    if command in ("sizeClasses", "gradeEfficiency") and arguments:
        return _case_table(command, arguments)
    if command == "depositionVelocity":
        from . import deposition
        return deposition.run(arguments)
    if command == "check":
        from . import checks
        return checks.main(arguments)
    if command == "compare" and len(arguments) == 2:
        from . import tables
        problems = tables.compare_folders(*arguments)
        print("\n".join(problems) if problems else
              f"{arguments[0]}: the same as {arguments[1]}")
        return 1 if problems else 0
    if command == "bendPositions" and len(arguments) == 1:
        from .tutorials import bend_deposition
        print("\n".join(bend_deposition.flow_weighted_positions(
            int(arguments[0]), 2.5e-3, "-0.0145")))
        return 0
    if command == "fibreSpectrum" and len(arguments) == 2:
        from .tutorials import fibre_filter
        fibre_filter.write_spectrum(*arguments)
        return 0
    if command == "channelPositions" and len(arguments) <= 1:
        from .tutorials import channel_resuspension
        channel_resuspension.write_positions(*arguments)
        return 0
    if command == "channelTop" and len(arguments) <= 1:
        from .tutorials import channel_resuspension
        channel_resuspension.set_top(*arguments)
        return 0
    if command == "pipeTimeStep" and len(arguments) <= 1:
        from .tutorials import pipe_deposition
        pipe_deposition.run_time_step(*arguments)
        return 0
    if command == "pipePositions" and len(arguments) <= 1:
        from .tutorials import pipe_deposition
        pipe_deposition.write_positions(*arguments)
        return 0
    if command == "tubePositions" and len(arguments) <= 1:
        from .tutorials import tube_diffusion
        tube_diffusion.write_positions(*arguments)
        return 0
    if command == "microsphereParcels" and len(arguments) == 1:
        from .tutorials import microsphere_impact
        from . import tables
        print("\n".join(microsphere_impact.parcel_rows(
            tables.read("figure5.csv"), int(arguments[0]))))
        return 0
    print(f"adhesiveWallPost: unknown command '{command}'\n{__doc__}",
          file=sys.stderr)
    return 1


def _case_table(command, arguments):
    """sizeClasses or gradeEfficiency of a case: the CSV on standard
    output and the plot; a missing file or a patch or injector the file
    does not hold is said in one line (exit status 1)."""
    from . import statistics
    case, cloud = arguments[0], (arguments[1:2] or ["kinematicCloud"])[0]
    selected = arguments[2:] or None
    try:
        if command == "sizeClasses":
            classes = statistics.size_classes(
                statistics.read_statistics(case, cloud), selected)
        else:
            classes = statistics.grade_efficiency(
                statistics.read_grade_efficiency(case, cloud), selected)
    except FileNotFoundError as err:
        print(f"adhesiveWallPost {command}: no {err.filename}: the model "
              f"writes it with writeToFile yes (and sizeClasses) in the "
              f"adhesiveWallInteractionCoeffs of cloud '{cloud}'",
              file=sys.stderr)
        return 1
    except KeyError as err:
        hint = "" if command == "sizeClasses" else (
            " (the injector is 'all' unless outputByInjectorId yes)")
        print(f"adhesiveWallPost {command}: {err.args[0]}{hint}",
              file=sys.stderr)
        return 1
    print(",".join(classes.names))
    for row in classes.rows:
        print(",".join(row))
    title = f"{os.path.basename(os.path.abspath(case))}: {cloud}"
    if command == "sizeClasses":
        statistics.plot_size_classes(os.path.join(case, "sizeClasses.png"),
                                     classes, title)
    else:
        statistics.plot_grade_efficiency(
            os.path.join(case, "gradeEfficiency.png"), classes, title)
    return 0


TUTORIALS = {
    "bendDeposition": "bend_deposition",
    "channelResuspension": "channel_resuspension",
    "fibreFilter": "fibre_filter",
    "microsphereImpact": "microsphere_impact",
    "pipeDeposition": "pipe_deposition",
    "pipeFlow": "pipe_flow",
    "settlingChannel": "settling_channel",
    "tubeDiffusion": "tube_diffusion",
}

if __name__ == "__main__":
    sys.exit(main())
