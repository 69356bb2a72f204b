# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Running a tutorial for its test: a fresh copy, its reduced variant."""

import os
import re
import shutil
import subprocess

import pytest

from adhesivewall import tables

PROJECT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GOLDEN = os.path.join(PROJECT, "tests", "golden")


def run_tutorial(name, *options, folder=""):
    """Copy tutorials/<name> to $TEST_WORK_DIR (else build/tests/work/
    tutorial.<name>), or beside it to <that>.<folder> (a second variant of
    the same test), and run its Allrun with the options; fails with the
    end of its output when it fails."""
    work = os.environ.get("TEST_WORK_DIR", os.path.join(
        PROJECT, "build", "tests", "work", "tutorial." + name))
    if folder:
        work = work.rstrip(os.sep) + "." + folder
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(os.path.join(PROJECT, "tutorials", name), work,
                    symlinks=True)
    with open(os.path.join(work, "log.Allrun"), "w") as log:
        result = subprocess.run(["./Allrun", *options], cwd=work,
                                stdout=log, stderr=subprocess.STDOUT)
    with open(os.path.join(work, "log.Allrun")) as log:
        output = log.read()
    if result.returncode != 0:
        pytest.fail(f"{name}: Allrun {' '.join(options)} failed:\n"
                    + output[-3000:])
    return work


def logs(case):
    """Every solver and utility log of a case and its sub-cases."""
    found = []
    for folder, _, files in os.walk(case):
        found += [os.path.join(folder, f) for f in files
                  if f.startswith("log.")]
    return found


def fatal_logs(case):
    """The logs holding a FOAM FATAL error: a fatal error is written to the
    log only (the applications' exit status is checked by Allrun too)."""
    return [path for path in logs(case) if "FOAM FATAL" in open(path).read()]


NAN = re.compile(r"(?<![\w.])[-+]?nan(?![\w.])", re.IGNORECASE)


def nan_files(case):
    """The tables (*.csv, *.dat) and fields of time folders holding a NaN."""
    found = []
    for folder, _, files in os.walk(case):
        in_time = any(_is_time(part) for part in
                      os.path.relpath(folder, case).split(os.sep))
        for f in files:
            if in_time or f.endswith((".csv", ".dat")):
                path = os.path.join(folder, f)
                try:
                    text = open(path, errors="replace").read()
                except OSError:
                    continue
                if NAN.search(text):
                    found.append(path)
    return found


def _is_time(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def golden_differences(case, tutorial, variant):
    """The differences of the case's files from tests/golden/<tutorial>/
    <variant> (tables by column name, numbers to 1e-12 relative; log.table
    line for line)."""
    return tables.compare_folders(case, os.path.join(GOLDEN, tutorial,
                                                     variant))
