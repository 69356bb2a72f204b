# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The subcommands' registry and the command line: each subcommand is
registered with its usage (its argument counts follow from it: words in
brackets are optional, a word ending in ... takes any number), run by
main(); CheckError, number() and fmt() are what every check uses."""

import re
import sys


class CheckError(Exception):
    """A check that failed, or had nothing to check: the message says
    what."""


def number(text, what="value"):
    """A number given as text (a command-line argument, a table's cell), or
    a CheckError naming what it should have been."""
    try:
        return float(text)
    except (TypeError, ValueError):
        raise CheckError(f"{what} '{text}' is not a number") from None


def fmt(value):
    """A number as the shell gets it, in its shortest exact form (as the
    model writes its tables): an integral value without decimals (15, not
    15.0), others as Python's repr (the shortest text that reads back as
    the same double: 3.5e-14, not 3.5000000000000002e-14)."""
    value = float(value)
    if value.is_integer() and abs(value) < 1e16:
        return str(int(value))
    return repr(value)


COMMANDS = {}


def _argument_counts(usage):
    """The least and the most arguments a usage allows: the words outside
    brackets are required, a quoted group ('X Y Z') is one argument, a word
    ending in ... takes any number (ANY)."""
    words = re.findall(r"\[|\]|[^\s\[\]]+", re.sub(r"'[^']*'", "Q", usage))
    depth, required, total, many = 0, 0, 0, False
    for word in words:
        if word in ("[", "]"):
            depth += 1 if word == "[" else -1
            continue
        total += 1
        required += depth == 0
        many = many or word.endswith("...")
    return required, ANY if many else total


def command(name, usage):
    """Register the function as subcommand `name` with its usage, from
    which the argument counts follow (_argument_counts)."""
    def register(function):
        COMMANDS[name] = (function, usage) + _argument_counts(usage)
        return function
    return register


def _report(problems, success=None):
    """Raise a CheckError of the problems (at most 10 listed), or print the
    success line."""
    if problems:
        more = len(problems) - 10
        raise CheckError("\n  ".join(problems[:10]
                                     + ([f"... and {more} more"]
                                        if more > 0 else [])))
    if success:
        print(success)


ANY = 1 << 30


def usage():
    """The list of subcommands, each with its arguments and what it
    does."""
    lines = ["adhesiveWallPost check SUBCOMMAND ARGUMENTS: prints a value, or"
             " checks and exits 1 with a message on a difference", ""]
    for name, (function, arguments, _, _) in COMMANDS.items():
        summary = " ".join(function.__doc__.split())
        lines.append(f"  {name} {arguments}\n      {summary}")
    return "\n".join(lines)


def main(argv):
    """adhesiveWallPost check SUBCOMMAND ARGUMENTS: runs a subcommand;
    returns 0, 1 (a check failed or a value could not be had) or 2 (wrong
    usage)."""
    if not argv or argv[0] in ("-h", "-help", "--help"):
        print(usage(), file=sys.stdout if argv else sys.stderr)
        return 0 if argv else 2
    name, arguments = argv[0], argv[1:]
    if name not in COMMANDS:
        print(f"adhesiveWallPost check: unknown subcommand '{name}'\n"
              f"{usage()}", file=sys.stderr)
        return 2
    function, usage_text, minimum, maximum = COMMANDS[name]
    if not minimum <= len(arguments) <= maximum:
        print(f"Usage: adhesiveWallPost check {name} {usage_text}",
              file=sys.stderr)
        return 2
    try:
        function(*arguments)
    except CheckError as error:
        print(f"adhesiveWallPost check {name}: {error}", file=sys.stderr)
        return 1
    except (OSError, ValueError, KeyError, RuntimeError,
            ArithmeticError) as error:
        message = error.args[0] if isinstance(error, KeyError) else error
        print(f"adhesiveWallPost check {name}: {message}", file=sys.stderr)
        return 1
    return 0
