# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The case tests' checks (tests/cases), from the shell:
adhesiveWallPost check SUBCOMMAND ..."""

import sys


def main(argv):
    print("adhesiveWallPost check: no subcommands yet", file=sys.stderr)
    return 1
