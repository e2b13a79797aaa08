"""Values of FMU variables by name: the one place that turns what a user or a study writes
(numbers, texts from the command line, enumeration items by name or code, the `speed_rpm`
convenience) into what the FMU's setters take, and into a canonical form for result tables.

`TABLE` is the generated table of the HypoidGearPair FMU (hypoid/fmu/variables.py, no FMU needed);
`Table.from_model_description(md)` makes the same from any FMU's model description. Every
problem raises `BadValue` with one line that names what was wrong and what is allowed."""

import difflib
import math

from hypoid.paths import data_file
from hypoid.fmu.variables import ENUMERATIONS, VARIABLES, Variable

RPM = math.pi / 30.0  # rad/s per rpm
SPEED_KEY = "speed_rpm"  # the pinion speed in rpm: sets both w_set and w_p0 (a quick start)
CONVENIENCES = {SPEED_KEY: "pinion speed in rpm; sets w_set and w_p0 (= speed_rpm * pi/30)"}


class BadValue(ValueError):
    """A name or value the FMU does not take; the message says what is allowed."""


class Table:
    """The variables of one FMU: {name: Variable} and {enumeration: {item: code}}."""

    def __init__(self, variables, enumerations):
        self.variables = variables
        self.enumerations = enumerations

    @classmethod
    def from_model_description(cls, md):
        variables, enums = {}, {}
        for v in md.modelVariables:
            enum = None
            if v.type == "Enumeration":
                enum = v.declaredType.name
                enums[enum] = {i.name: int(i.value) for i in v.declaredType.items}
            variables[v.name] = Variable(
                name=v.name, vr=v.valueReference, causality=v.causality,
                variability=v.variability, type=v.type, enumeration=enum, unit=v.unit,
                display_unit=v.displayUnit, start=v.start, min=v.min, max=v.max,
                description=v.description or "")
        return cls(variables, enums)

    # ------------------------------------------------------------------ names
    def variable(self, name):
        """The Variable called `name`; an unknown name raises BadValue with close matches."""
        var = self.variables.get(name)
        if var is not None:
            return var
        known = list(self.variables) + list(CONVENIENCES)
        close = difflib.get_close_matches(name, known, n=3, cutoff=0.6)
        hint = f"did you mean {' or '.join(close)}? " if close else ""
        raise BadValue(f"unknown variable {name!r} ({hint}the variables are listed in README.md, "
                       f"'Variables'; also {', '.join(CONVENIENCES)})")

    def settable(self, name):
        """The Variable of a parameter or input (what a user may set)."""
        var = self.variable(name)
        if var.causality not in ("parameter", "input"):
            raise BadValue(f"{name} is an {var.causality}: only parameters and inputs can be set")
        return var

    def items(self, var):
        return self.enumerations[var.enumeration]

    def allowed(self, var):
        """What a variable accepts, for messages."""
        if var.type == "Enumeration":
            return "one of " + ", ".join(f"{n} (= {c})" for n, c in self.items(var).items())
        kind = {"Real": "a number", "Integer": "an integer", "Boolean": "true or false",
                "String": "a text"}[var.type]
        if var.min is not None or var.max is not None:
            lo = "-inf" if var.min is None else f"{float(var.min):g}"
            hi = "inf" if var.max is None else f"{float(var.max):g}"
            kind += f" in [{lo}, {hi}]"
        return kind + (f" {var.unit}" if var.unit else "")

    # ------------------------------------------------------------------ values
    def code(self, var, value):
        """An enumeration's integer code from its item name ('ehl_thermal') or code (4, '4')."""
        items = self.items(var)
        text = str(value).strip()
        if text in items:
            return items[text]
        if text.lstrip("-").isdigit() and int(text) in items.values():
            return int(text)
        raise BadValue(f"{var.name} = {value!r}: no such item; allowed: {self.allowed(var)}")

    def canonical(self, name, value):
        """A value in canonical form (enumerations by item name, Integer int, Real float, String
        str with data files relative to the working directory made absolute, hypoid/paths.py),
        so that equal points get equal keys; `speed_rpm` is a float."""
        if name == SPEED_KEY:
            return _number(name, value, f"{CONVENIENCES[SPEED_KEY]}: a number")
        var = self.variable(name)
        if var.type == "Enumeration":
            code = self.code(var, value)
            return next(n for n, c in self.items(var).items() if c == code)
        if var.type == "Real":
            return _number(name, value, self.allowed(var))
        if var.type == "Integer":
            x = _number(name, value, self.allowed(var))
            if not float(x).is_integer():
                raise BadValue(f"{name} = {value!r}: not an integer; allowed: {self.allowed(var)}")
            return int(x)
        if var.type == "Boolean":
            return _boolean(name, value)
        return data_file(str(value))  # a data file relative to the user's folder: absolute

    def fmu_values(self, params):
        """[(Variable, value for its setter)] for a mapping of names (and `speed_rpm`) to values
        in any accepted form."""
        out = []
        for name, value in params.items():
            if name == SPEED_KEY:
                w = self.canonical(name, value) * RPM
                out += [(self.settable("w_set"), w), (self.settable("w_p0"), w)]
                continue
            var = self.settable(name)
            x = self.canonical(name, value)
            out.append((var, self.code(var, x) if var.type == "Enumeration" else x))
        return out

    def parse(self, name, text):
        """A command-line text as the canonical value of `name` (checked against the table)."""
        if name != SPEED_KEY:
            self.settable(name)
        return self.canonical(name, text)

    def start(self, name):
        """The canonical start value of a parameter or input (`speed_rpm` from w_set)."""
        if name == SPEED_KEY:
            return round(float(self.variable("w_set").start) / RPM, 9)
        var = self.variable(name)
        return self.canonical(name, "" if var.start is None else var.start)

    def normalize(self, params):
        return {name: self.canonical(name, value) for name, value in params.items()}


def _number(name, value, allowed):
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise BadValue(f"{name} = {value!r}: not a number; allowed: {allowed}") from None
    return x


def _boolean(name, value):
    text = str(value).strip().lower()
    if text in ("1", "true", "yes", "on"):
        return True
    if text in ("0", "false", "no", "off", ""):
        return False
    raise BadValue(f"{name} = {value!r}: allowed: true or false")


TABLE = Table(VARIABLES, ENUMERATIONS)
