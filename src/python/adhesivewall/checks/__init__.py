# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The case tests' checks (tests/cases) and the benchmark's figures
(tests/bench/run), from the shell:

    adhesiveWallPost check SUBCOMMAND ARGUMENTS...

A subcommand prints a value (a sum, a count, a line of the benchmark) or
checks something. When a check fails, or a value cannot be had (a missing
file, column, patch or row), it prints a message naming what differs or
what is missing on stderr and exits with status 1; a wrong usage exits
with 2. `adhesiveWallPost check -help` lists the subcommands.

The model's tables are read by column name (`tables`, `statistics`),
OpenFOAM's files with the package's parser (`foam`). Nothing here passes on
nothing: a sum over no rows, a comparison of two empty lists, a boundary sum
over a patch the field does not have, a mass of no injector are errors.

`tables` and `statistics` (which load numpy) are imported by the functions
that read tables, so that the arithmetic checks (close, small, between)
start in a few tens of milliseconds.

The checks sit in modules by what they check, each with its subcommands:
`predicates` (numbers), `model_tables` (the model's tables),
`comparisons` (two runs' tables), `fields` (OpenFOAM's files), `cases`
(a case's grade efficiency, steps, models, parcels), `tools` (the core and
the tools against the solver), `bench` (the benchmark's lines) and
`aerosols` (the sub-micron cases); `registry` holds the subcommands, each
registered once with its usage (the argument counts follow from it), and
the command line (`main`).

Tolerances are relative to the reference (expected) value: `close(value,
expected, rtol)` is |value - expected| <= rtol |expected|, so that an
expected 0 asks for exactly 0.
"""

from .registry import ANY, COMMANDS, CheckError, command, fmt, main, number, usage
from .predicates import (between, close, mean_and_deviation, median, near,
                         small, sums_to)
from .model_tables import (columns, log_lines_per_step, mass_balance,
                           replace_value, statistic, statistic_rows,
                           surface_contacts, table_rows, time_range)
from .comparisons import (compare_last_rows, compare_records,
                          compare_statistics, compare_totals)
from .fields import (boundary_min, boundary_sum, boundary_values, cloud_mass,
                     compare_fields, compare_vectors, field_numbers,
                     injected_mass, lagrangian_values, last_vector)
from .cases import (check_grade_efficiency, expected_grade_efficiency,
                    patch_interaction_models, steps)
from .tools import (core_result, critical_speed_outcomes, fit_values,
                    impact_calc_inputs, printed_value, records_match_tool,
                    recovered, sphere_angular_momentum, sweep_matches_core)
from .bench import (bench_core_lines, deposit_cost_line, entries_lines,
                    execution_time, instruction_ratio_line,
                    instructions_lines, mass_transferred, random_positions,
                    scaling_line, solver_lines, speedup_line,
                    time_ratios_line)
from .aerosols import _settling_velocity
