# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The benchmark's figures (tests/bench/run): the core's lines, the solver's
timings and instruction counts, as printed lines."""

import random
import re

from .registry import CheckError, command, fmt, number
from .predicates import mean_and_deviation, median


def bench_core_lines(path):
    """The core micro-benchmark's lines from Google Benchmark's CSV output:
    the building blocks (primitive/...), the classical rebound baseline and
    each impact/... benchmark in ns and in baselines."""
    from .. import tables
    table = tables.read(path)
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
    times = {}
    for name, t, unit in zip(table.text("name"), table["real_time"],
                             table.text("time_unit")):
        times[name.strip('"')] = t * scale[unit]
    if not times.get("classicalRebound", 0) > 0:
        raise CheckError(f"{path}: no classicalRebound benchmark")
    base = times["classicalRebound"]
    primitives = "".join(" %s %.1f" % (n[len("primitive/"):], t)
                         for n, t in times.items()
                         if n.startswith("primitive/"))
    lines = ["core: one call on the impact speeds, ns:" + primitives,
             "core: classical rebound (standardWallInteraction arithmetic) "
             "%.1f ns" % base]
    lines += ["core: %-36s %6.1f ns  %5.1f x baseline" % (n, t, t / base)
              for n, t in times.items() if n.startswith("impact/")]
    return lines


def random_positions(n, seed=7, low=5e-5, width=9e-4):
    """The text of a vectorField file of n positions drawn uniformly in
    the cube [low, low + width)^3, repeatably (the seed)."""
    draw = random.Random(seed).random
    lines = ["FoamFile { version 2.0; format ascii; class vectorField; "
             "object positions; }", "("]
    lines += ["(%.6g %.6g %.6g)" % tuple(low + width * draw()
                                         for _ in range(3))
              for _ in range(n)]
    lines.append(")")
    return lines


def execution_time(log):
    """The last ExecutionTime an OpenFOAM solver printed [s]: it is in the
    solver's log only (no function object writes it in v1912)."""
    found = None
    with open(log) as f:
        for line in f:
            m = re.match(r"ExecutionTime = (\S+) s", line)
            if m:
                found = number(m.group(1), "ExecutionTime")
    if found is None:
        raise CheckError(f"{log}: no ExecutionTime")
    return found


def mass_transferred(log):
    """What a cloud has given the gas so far [kg]: the sum over kinds of the
    last "Mass transfer <kind> = <value>" line OpenFOAM's thermo and
    reacting clouds print each step (phase change, devolatilisation,
    surface reaction: totals since the start of the run)."""
    last = {}
    with open(log) as f:
        for line in f:
            m = re.match(r"\s*Mass transfer (.*\S)\s*=\s*(\S+)", line)
            if m:
                last[m.group(1)] = number(m.group(2), "Mass transfer")
    if not last:
        raise CheckError(f"{log}: no Mass transfer line")
    return sum(last.values())


def time_ratios_line(name, times_a, times_b):
    """The line of alternating timed pairs: the ratios B/A (to 4 decimals,
    as printed), their median, mean and standard deviation, and the ratio
    of the fastest runs (min B / min A: another job sharing the machine
    only adds time, so the fastest runs are the least disturbed)."""
    if not times_a or len(times_a) != len(times_b):
        raise CheckError(f"{len(times_a)} times against {len(times_b)}")
    if not all(t > 0 for t in list(times_a) + list(times_b)):
        raise CheckError(f"times {times_a} {times_b}: not all positive")
    ratios = ["%.4f" % (b / a) for a, b in zip(times_a, times_b)]
    values = [float(r) for r in ratios]
    m, sd = mean_and_deviation(values)
    return ("%s: time ratio median %.3f, mean %.3f +- %.3f, fastest runs "
            "%.3f (%d alternating pairs: %s)"
            % (name, median(values), m, sd, min(times_b) / min(times_a),
               len(values), " ".join(ratios)))


def solver_lines(parcels, impacts, seconds, steps=50):
    """The in-solver case's lines: impacts in all and per step, and per
    second of solver time."""
    if seconds <= 0 or steps <= 0:
        raise CheckError(f"{seconds} s, {steps} steps: nothing to divide by")
    return ["solver: %d parcels, %d steps: %d wall impacts, %.0f per step; "
            "adhesive run %g s" % (parcels, steps, impacts, impacts / steps,
                                   seconds),
            "solver: %.3g impacts handled per second of solver time (all of "
            "it, tracking included)" % (impacts / seconds)]


def scaling_line(parcels, impacts, seconds):
    """A scaling line: the time per million impacts."""
    if impacts <= 0:
        raise CheckError(f"{impacts} impacts: no time per impact")
    return ("scaling: %6d parcels, %8d impacts: %.2f s, %.3g s per million "
            "impacts" % (parcels, impacts, seconds, 1e6 * seconds / impacts))


def entries_lines(timings):
    """The patch-entry scaling lines from (entries, seconds) pairs of
    several rounds: per entry count, the median and the times in the order
    run."""
    by_count = {}
    for entries, seconds in timings:
        by_count.setdefault(entries, []).append(seconds)
    if not by_count:
        raise CheckError("no timings")
    return ["scaling: %d patch entries in the dictionary: median %.2f s (%s)"
            % (e, median(t), " ".join("%.2f" % x for x in t))
            for e, t in by_count.items()]


def speedup_line(serial, parallel):
    """The parallel line: 1 and 2 ranks and the speedup."""
    if parallel <= 0:
        raise CheckError(f"parallel time {parallel} s")
    return ("parallel: 1 rank %.2f s, 2 ranks %.2f s, speedup %.2f"
            % (serial, parallel, serial / parallel))


def deposit_cost_line(deposits, steps, times_a, times_b):
    """The resuspension line: the extra time per deposit and step, from the
    medians of alternating runs without (A) and with (B) resuspension."""
    if deposits <= 0 or steps <= 0:
        raise CheckError(f"{deposits} deposits, {steps} steps")
    time_a, time_b = median(times_a), median(times_b)
    return ("resuspension: %.0f ns per deposit and step (medians %.2f s "
            "without, %.2f s with; %d deposits, %d steps)"
            % ((time_b - time_a) / (deposits * steps) * 1e9, time_a, time_b,
               deposits, steps))


def instructions_lines(path, hits):
    """The instruction counts of callgrind runs ('box count' lines, the
    first 'standard') and, for the others, the instructions per wall impact
    beyond standardWallInteraction's."""
    counts = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if len(words) == 2:
                counts.append((words[0],
                               number(words[1].replace(",", ""), words[0])))
    standard = dict(counts).get("standard")
    if standard is None:
        raise CheckError(f"{path}: no count of the standard box")
    if hits <= 0:
        raise CheckError(f"{hits} wall impacts: no count per impact")
    lines = []
    for box, count in counts:
        line = "instructions: %-15s %.4e in 10 steps (%d wall impacts)" % (
            box, count, hits)
        if box != "standard":
            line += ", %.0f per impact beyond standard" % (
                (count - standard) / hits)
        lines.append(line)
    return lines


def instruction_ratio_line(name, count_a, count_b, steps):
    """The line of two callgrind counts of the same case and their ratio
    B/A (to 4 decimals)."""
    if not (count_a > 0 and count_b > 0):
        raise CheckError(f"counts {count_a}, {count_b}: not both positive")
    return "%s: instructions in %d steps %.4e and %.4e, ratio %.4f" % (
        name, steps, count_a, count_b, count_b / count_a)


@command("benchCore", "CSV")
def _bench_core(path):
    """The core micro-benchmark's lines."""
    print("\n".join(bench_core_lines(path)))


@command("randomPositions", "N [SEED]")
def _random_positions(n, seed="7"):
    """A vectorField file of N random positions in the 1 mm box."""
    print("\n".join(random_positions(int(n), int(seed))))


@command("executionTime", "LOG")
def _execution_time(log):
    """The last ExecutionTime of a solver log [s]."""
    print(fmt(execution_time(log)))


@command("massTransferred", "LOG")
def _mass_transferred(log):
    """What a thermo or reacting cloud has given the gas so far [kg]."""
    print(fmt(mass_transferred(log)))


@command("timeRatios", "NAME 'TIMES_A' 'TIMES_B'")
def _time_ratios(name, times_a, times_b):
    """The ratio line of alternating timed pairs."""
    print(time_ratios_line(name, [number(t) for t in times_a.split()],
                           [number(t) for t in times_b.split()]))


@command("benchSolver", "PARCELS IMPACTS SECONDS")
def _bench_solver(parcels, impacts, seconds):
    """The in-solver case's impact lines."""
    print("\n".join(solver_lines(int(parcels), number(impacts),
                                 number(seconds))))


@command("benchScaling", "PARCELS IMPACTS SECONDS")
def _bench_scaling(parcels, impacts, seconds):
    """A scaling line."""
    print(scaling_line(int(parcels), number(impacts), number(seconds)))


@command("benchEntries", "ENTRIES:SECONDS...")
def _bench_entries(*pairs):
    """The patch-entry scaling lines."""
    timings = []
    for pair in pairs:
        entries, _, seconds = pair.partition(":")
        timings.append((int(entries), number(seconds)))
    print("\n".join(entries_lines(timings)))


@command("benchSpeedup", "SERIAL_SECONDS PARALLEL_SECONDS")
def _bench_speedup(serial, parallel):
    """The parallel speedup line."""
    print(speedup_line(number(serial), number(parallel)))


@command("benchResuspension", "DEPOSITS STEPS 'TIMES_A' 'TIMES_B'")
def _bench_resuspension(deposits, steps, times_a, times_b):
    """The resuspension cost line."""
    print(deposit_cost_line(int(deposits), int(steps),
                            [number(t) for t in times_a.split()],
                            [number(t) for t in times_b.split()]))


@command("benchInstructions", "FILE HITS")
def _bench_instructions(path, hits):
    """The instruction-count lines."""
    print("\n".join(instructions_lines(path, int(number(hits)))))


@command("benchInstructionRatio", "NAME COUNT_A COUNT_B STEPS")
def _bench_instruction_ratio(name, count_a, count_b, steps):
    """The line of two callgrind counts (commas allowed) and their
    ratio."""
    print(instruction_ratio_line(name, number(count_a.replace(",", "")),
                                 number(count_b.replace(",", "")),
                                 int(number(steps, "STEPS"))))
