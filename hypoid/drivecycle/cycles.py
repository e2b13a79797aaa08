"""Speed cycles, each with its source:
- WLTC classes 1, 2, 3a, 3b and NEDC from the European Commission JRC's `wltp` package (PyPI wltp
  0.1.2a0, wltp/cycles/class1.py, class2.py, class3.py, nedc.py);
- UDDS, HWFET and US06 from the cycle files of NREL's FASTSim package (PyPI fastsim 2.1.5,
  fastsim/resources/cycles/udds.csv, hwfet.csv, us06.csv; installed by scripts/setup.sh without
  its dependencies, only its files are read); FTP-75 is the UDDS, the 600 s soak with the car
  standing, and the UDDS's first 505 s again (40 CFR 86, the three phases of the FTP);
- a CSV file with the columns `time` (s, increasing) and `speed` (km/h), optionally `grade` (%,
  uphill positive, within +-30 %) and `phase` (a name per row); cells separated by ',' or, with
  decimal commas, by ';' (as spreadsheets export in such locales)."""

import importlib.util
import math
import pathlib
from dataclasses import dataclass, field

import numpy as np

from hypoid import csvtext
from hypoid.drivecycle.interp import interp
from hypoid.errors import UsageError
from hypoid.paths import user_path

KMH = 1 / 3.6
GRADE_MAX_PCT = 30.0
WLTP = "wltp 0.1.2a0 (European Commission JRC)"
FASTSIM = "fastsim 2.1.5 (NREL FASTSim), fastsim/resources/cycles/"
FTP_SOAK_S, FTP_BAG1_S = 600.0, 505.0


@dataclass
class Cycle:
    name: str
    t: np.ndarray        # s
    v: np.ndarray        # m/s
    phases: list         # [(name, t_start, t_end)]
    source: str
    grade: np.ndarray = field(default=None)  # rise over run at each t (None: level road)

    def __post_init__(self):  # the traces as lists, for interp (called in every step)
        self._t, self._v = [float(x) for x in self.t], [float(x) for x in self.v]
        self._grade = None if self.grade is None else [float(x) for x in self.grade]

    def speed(self, t):
        return interp(t, self._t, self._v)

    def slope(self, t):
        """The road's grade (rise / run) at t; 0 on a level route."""
        return 0.0 if self._grade is None else interp(t, self._t, self._grade)


# name -> (wltp module, function, phase names)
WLTP_CYCLES = {
    "wltc1": ("class1", "class_data", ("low", "medium")),
    "wltc2": ("class2", "class_data", ("low", "medium", "high", "extra-high")),
    "wltc3a": ("class3", "class_data_a", ("low", "medium", "high", "extra-high")),
    "wltc3": ("class3", "class_data_b", ("low", "medium", "high", "extra-high")),
    "nedc": ("nedc", "cycle_data", ("ECE (urban)", "EUDC (extra-urban)")),
}
ALIASES = {"wltc3b": "wltc3"}
FASTSIM_CYCLES = ("udds", "hwfet", "us06", "ftp75")
BUILTIN = tuple(WLTP_CYCLES) + ("wltc3b",) + FASTSIM_CYCLES


def _closed(names, parts, t_last):
    """Phases from [first, last] seconds, each closed up to the next one's start."""
    phases = [(n, float(a)) for n, (a, _) in zip(names, parts)]
    return [(n, a, phases[k + 1][1] if k + 1 < len(phases) else float(t_last))
            for k, (n, a) in enumerate(phases)]


def wltp_cycle(name):
    module, fn, names = WLTP_CYCLES[name]
    try:
        data = getattr(importlib.import_module(f"wltp.cycles.{module}"), fn)()
    except ImportError as e:
        raise UsageError(f"--cycle {name}: the wltp package is missing ({e}); "
                         "install the project with scripts/setup.sh") from None
    v = np.asarray(data["cycle"], float) * KMH
    t = np.arange(len(v), dtype=float)
    label = "NEDC" if name == "nedc" else f"WLTC class {name[4:]}{'b' if name == 'wltc3' else ''}"
    return Cycle(name, t, v, _closed(names, data["parts"], t[-1]),
                 f"{label}, {WLTP}, wltp/cycles/{module}.py")


def fastsim_file(stem):
    """(t s, v m/s) of one of FASTSim's cycle files (columns cycSecs, cycMps, ...)."""
    spec = importlib.util.find_spec("fastsim")
    if spec is None or not spec.submodule_search_locations:
        raise UsageError(f"--cycle: the {stem.upper()} cycle is read from the fastsim "
                         "package's files, which is missing; run scripts/setup.sh")
    path = pathlib.Path(list(spec.submodule_search_locations)[0]) / "resources" / "cycles" \
        / f"{stem}.csv"
    data = np.loadtxt(path, delimiter=",", skiprows=1, usecols=(0, 1))
    return data[:, 0], data[:, 1]


def fastsim_cycle(name):
    if name != "ftp75":
        t, v = fastsim_file(name)
        phases = ([("bag 1", 0.0, FTP_BAG1_S), ("bag 2", FTP_BAG1_S, float(t[-1]))]
                  if name == "udds" else [("all", 0.0, float(t[-1]))])
        return Cycle(name, t, v, phases, f"{name.upper()}, {FASTSIM}{name}.csv")
    t_u, v_u = fastsim_file("udds")
    n_soak, n_bag1 = int(FTP_SOAK_S), int(FTP_BAG1_S)
    v = np.concatenate([v_u, np.zeros(n_soak), v_u[1:n_bag1 + 1]])
    t = np.arange(len(v), dtype=float)
    end_udds = float(t_u[-1])
    phases = [("cold transient", 0.0, FTP_BAG1_S), ("stabilized", FTP_BAG1_S, end_udds),
              ("soak", end_udds, end_udds + FTP_SOAK_S),
              ("hot transient", end_udds + FTP_SOAK_S, float(t[-1]))]
    return Cycle(name, t, v, phases, f"FTP-75: {FASTSIM}udds.csv, the UDDS, a {n_soak} s soak "
                 f"standing and the UDDS's first {n_bag1} s")


def builtin_cycle(name):
    name = ALIASES.get(name, name)
    return wltp_cycle(name) if name in WLTP_CYCLES else fastsim_cycle(name)


def _fail(p, line, text):
    raise UsageError(f"--cycle {p}: line {line}: {text}")


def read_csv_cycle(path):
    """A user's cycle: columns time [s] (strictly increasing, from >= 0) and speed [km/h]
    (finite, >= 0), optionally grade [%] and phase. Every problem is one UsageError naming file,
    line and value."""
    p = pathlib.Path(path)
    rows, sep, col = _csv_header(p)
    t, v, g, ph = [], [], [], []
    for n, line in rows[1:]:
        tt, vv, gg, phase = _csv_row(p, n, line.split(sep), col, t[-1] if t else None)
        t.append(tt)
        v.append(vv * KMH)
        g.append(gg / 100.0)
        ph.append(phase)
    if len(t) < 2:
        raise UsageError(f"--cycle {p}: at least two rows of time and speed are needed")
    grade = np.array(g) if col["grade"] is not None else None
    return Cycle(p.stem, np.array(t), np.array(v), _phases(t, ph), f"file {p}", grade)


def _csv_header(p):
    """(rows [(line number, text)] without blanks and comments, the cell separator, {column:
    index or None}) of a cycle file, its header checked."""
    try:
        lines = p.read_text().splitlines()
    except (OSError, UnicodeDecodeError) as e:
        raise UsageError(f"--cycle {p}: cannot read it ({e})") from None
    rows = [(n, line) for n, line in enumerate(lines, 1) if line.strip() and
            not line.lstrip().startswith("#")]
    if not rows:
        raise UsageError(f"--cycle {p}: the file is empty")
    sep = csvtext.delimiter(lines)
    header = [h.strip().lower() for h in rows[0][1].split(sep)]
    missing = [c for c in ("time", "speed") if c not in header]
    unknown = [c for c in header if c not in ("time", "speed", "grade", "phase")]
    if missing or unknown:
        _fail(p, rows[0][0], f"{'missing column(s) ' + ', '.join(missing) if missing else ''}"
              f"{'; ' if missing and unknown else ''}"
              f"{'unknown column(s) ' + ', '.join(unknown) if unknown else ''}; the header names "
              f"time (s) and speed (km/h), optionally grade (%) and phase (found: "
              f"{', '.join(header)})")
    col = {c: header.index(c) if c in header else None for c in ("time", "speed", "grade",
                                                                "phase")}
    col["n"] = len(header)
    return rows, sep, col


def _csv_row(p, n, cells, col, t_before):
    """(time s, speed km/h, grade %, phase) of line n, checked."""
    cells = [c.strip() for c in cells]
    if len(cells) != col["n"]:
        _fail(p, n, f"{len(cells)} values for {col['n']} columns")
    values = {}
    for c in ("time", "speed", "grade"):
        if col[c] is None:
            continue
        try:
            values[c] = csvtext.number(cells[col[c]])
        except ValueError:
            _fail(p, n, f"{c} {cells[col[c]]!r} is not a number")
        if not math.isfinite(values[c]):
            _fail(p, n, f"{c} {cells[col[c]]} is not finite")
    tt, vv, gg = values["time"], values["speed"], values.get("grade", 0.0)
    if vv < 0 or tt < 0:
        _fail(p, n, f"time {tt} s and speed {vv} km/h must not be negative")
    if abs(gg) > GRADE_MAX_PCT:
        _fail(p, n, f"grade {gg} % is beyond +-{GRADE_MAX_PCT:g} % (a percentage, uphill "
              "positive: 6 for 6 %)")
    if t_before is not None and tt <= t_before:
        _fail(p, n, f"time {tt} s does not increase (the row before has {t_before} s)")
    return tt, vv, gg, cells[col["phase"]] if col["phase"] is not None else "all"


def _phases(t, names):
    """[(phase, t_start, t_end)] of consecutive rows with the same phase name."""
    phases = []
    for k, name in enumerate(names):
        if not phases or phases[-1][0] != name:
            phases.append([name, t[k], t[k]])
        phases[-1][2] = t[min(k + 1, len(t) - 1)]
    return [tuple(x) for x in phases]


def load_cycle(text):
    if text in BUILTIN:
        return builtin_cycle(text)
    if not text.lower().endswith(".csv"):
        raise UsageError(f"--cycle {text!r}: give one of {', '.join(BUILTIN)} or a .csv file")
    return read_csv_cycle(user_path(text))
