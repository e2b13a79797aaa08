"""The command line of every `hypoid` tool: one argument parser, one reading of `--set NAME=VALUE`
and `--vary NAME=VALUES` (any parameter or input by name, enumeration items by name or code,
`speed_rpm`), and one error path. A tool raises `UsageError` (or `hypoid.fmu.values.BadValue`,
`hypoid.fmu.instance.FmuError`, `OSError`); hypoid.cli prints it as one line `hypoid <tool>: ...`
and exits with status 2, never with a traceback."""

import argparse
import re

import numpy as np

from hypoid import data
from hypoid.errors import UsageError  # noqa: F401 (the tools' cliargs.UsageError)
from hypoid.fmu.values import TABLE, BadValue
from hypoid.paths import user_path

FMU_HELP = ("the {what} (default: ${env}, else build/{name} of the checkout the package runs "
            "from)")
SET_HELP = ("start values by name, e.g. T_s=200 gear_set=2 friction_model=ehl_isothermal "
            "speed_rpm=3000 (speed_rpm: pinion speed, sets w_set and w_p0); README 'Variables' "
            "lists every name, its unit and the enumeration items")
VARY_HELP = ("values of one variable: start:stop:step (inclusive) or v1,v2,...; repeat for a "
             "product grid, e.g. --vary speed_rpm=1000:5000:250 --vary T_s=50,100")

NEGATIVE_VALUE = re.compile(r"^-\.?\d[\d.,:eE+\-]*$")


class Parser(argparse.ArgumentParser):
    """argparse with the whole module docstring as help (its first paragraph as the description,
    the rest as the epilog, both as written) and errors raised as UsageError instead of a usage
    dump and exit."""

    def __init__(self, prog=None, doc=None, **kwargs):
        if doc:
            first, _, rest = doc.strip().partition("\n\n")
            kwargs.update(description=first, epilog=rest.strip("\n").rstrip() or None)
        kwargs.setdefault("formatter_class", argparse.RawDescriptionHelpFormatter)
        super().__init__(prog=prog, **kwargs)
        # a value that starts with a minus and a digit is a value, not an option: negative
        # numbers, lists and ranges of them (--temperatures-c -10,20, --torques -50:50:25)
        self._negative_number_matcher = NEGATIVE_VALUE

    def error(self, message):
        raise UsageError(f"{message} (see {self.prog} --help)")

    def add_fmu(self):
        self.add_argument("--fmu", type=user_path, help=FMU_HELP.format(
            what="FMU", env=data.FMUS["gear"][1], name=data.FMUS["gear"][0]))

    def add_set(self):
        self.add_argument("--set", nargs="*", action="extend", default=[], metavar="NAME=VALUE",
                          help=SET_HELP)

    def add_vary(self):
        self.add_argument("--vary", action="append", default=[], metavar="NAME=VALUES",
                          help=VARY_HELP)


def fmu_path(path, kind="gear"):
    """The FMU file given (or found when None: hypoid.data.fmu), checked to exist."""
    return data.fmu(kind, path)


def assignments(items, option="--set"):
    """['T_s=200', 'gear_set=2'] -> {'T_s': '200', 'gear_set': '2'} (texts)."""
    out = {}
    for item in items:
        name, sep, text = item.partition("=")
        if not sep or not name.strip():
            raise UsageError(f"{option} {item!r}: expected NAME=VALUE, e.g. T_s=200")
        out[name.strip()] = text.strip()
    return out


def parse_set(items, table=TABLE):
    """--set items as {name: canonical value}, each checked against the variable table."""
    try:
        return {n: table.parse(n, text) for n, text in assignments(items).items()}
    except BadValue as e:
        raise UsageError(f"--set {e}") from None


def parse_vary(items, table=TABLE):
    """--vary items as {name: [canonical values]}."""
    out = {}
    for name, text in assignments(items, "--vary").items():
        try:
            out[name] = [table.parse(name, v) for v in value_list(f"--vary {name}", text)]
        except BadValue as e:
            raise UsageError(f"--vary {e}") from None
    return out


def value_list(label, text):
    """'1000:5000:250' (inclusive range, numbers) or 'a,b,c' (a list of texts); `label` names
    the option in messages ('--vary speed_rpm')."""
    if ":" not in text:
        return [v.strip() for v in text.split(",")]
    try:
        a, b, step = (float(x) for x in text.split(":"))
    except ValueError:
        raise UsageError(f"{label}={text}: a range is start:stop:step with three numbers "
                         "(e.g. 1000:5000:250), or give a list v1,v2,...") from None
    if step <= 0 or b < a:
        raise UsageError(f"{label}={text}: a range needs start <= stop and step > 0")
    n = int(np.floor((b - a) / step + 1e-9)) + 1
    return [tidy(a + i * step) for i in range(n)]


def numbers(label, text):
    """A list of numbers in value_list's forms."""
    try:
        return [tidy(float(v)) for v in value_list(label, text)]
    except ValueError:
        raise UsageError(f"{label}={text}: numbers expected") from None


def tidy(x):
    return int(x) if float(x).is_integer() else round(x, 10)
