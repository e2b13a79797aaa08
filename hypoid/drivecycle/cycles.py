"""Speed cycles: WLTC class 3b and NEDC from the European Commission JRC's `wltp` package (PyPI
wltp 0.1.2a0, wltp/cycles/class3.py and nedc.py), or a CSV file with the columns `time` (s,
increasing) and `speed` (km/h), optionally `phase` (a name per row)."""

import math
import pathlib
from dataclasses import dataclass

import numpy as np

from hypoid.errors import UsageError
from hypoid.paths import user_path

KMH = 1 / 3.6


@dataclass
class Cycle:
    name: str
    t: np.ndarray        # s
    v: np.ndarray        # m/s
    phases: list         # [(name, t_start, t_end)]
    source: str

    def speed(self, t):
        return float(np.interp(t, self.t, self.v))


WLTC3_PHASES = ("low", "medium", "high", "extra-high")


def builtin_cycle(name):
    """WLTC class 3b or NEDC from the `wltp` package (speeds in km/h at 1 Hz)."""
    try:
        from wltp.cycles import class3, nedc
    except ImportError as e:
        raise UsageError(f"--cycle {name}: the wltp package is missing ({e}); "
                                 "install the project with scripts/setup.sh") from None
    if name == "wltc3":
        data, names = class3.class_data_b(), WLTC3_PHASES
        source = "WLTC class 3b, wltp 0.1.2a0 (European Commission JRC), wltp/cycles/class3.py"
    else:
        data, names = nedc.cycle_data(), ("ECE (urban)", "EUDC (extra-urban)")
        source = "NEDC, wltp 0.1.2a0 (European Commission JRC), wltp/cycles/nedc.py"
    v = np.asarray(data["cycle"], float) * KMH
    t = np.arange(len(v), dtype=float)
    phases = [(n, float(a), float(b)) for n, (a, b) in zip(names, data["parts"])]
    # the parts are [first, last] second: close the gaps between them
    phases = [(n, a, phases[k + 1][1] if k + 1 < len(phases) else t[-1])
              for k, (n, a, _) in enumerate(phases)]
    return Cycle(name, t, v, phases, source)


def read_csv_cycle(path):
    """A user's cycle: columns time [s] (strictly increasing, from >= 0) and speed [km/h]
    (finite, >= 0), optionally phase. Every problem is one UsageError naming file, line and
    value."""
    p = pathlib.Path(path)
    try:
        lines = p.read_text().splitlines()
    except (OSError, UnicodeDecodeError) as e:
        raise UsageError(f"--cycle {p}: cannot read it ({e})") from None
    rows = [(n, line) for n, line in enumerate(lines, 1) if line.strip() and
            not line.lstrip().startswith("#")]
    if not rows:
        raise UsageError(f"--cycle {p}: the file is empty")
    header = [h.strip().lower() for h in rows[0][1].split(",")]
    missing = [c for c in ("time", "speed") if c not in header]
    if missing:
        raise UsageError(f"--cycle {p}: line {rows[0][0]}: missing column(s) "
                                 f"{', '.join(missing)}; the header must name time (s) and "
                                 f"speed (km/h), optionally phase (found: {', '.join(header)})")
    it, iv = header.index("time"), header.index("speed")
    ip = header.index("phase") if "phase" in header else None
    t, v, ph = [], [], []
    for n, line in rows[1:]:
        cells = [c.strip() for c in line.split(",")]
        if len(cells) != len(header):
            raise UsageError(f"--cycle {p}: line {n}: {len(cells)} values for "
                                     f"{len(header)} columns")
        try:
            tt, vv = float(cells[it]), float(cells[iv])
        except ValueError:
            raise UsageError(f"--cycle {p}: line {n}: time {cells[it]!r} or speed "
                                     f"{cells[iv]!r} is not a number") from None
        if not (math.isfinite(tt) and math.isfinite(vv)):
            raise UsageError(f"--cycle {p}: line {n}: time {tt} s or speed {vv} km/h "
                                     "is not finite")
        if vv < 0 or tt < 0:
            raise UsageError(f"--cycle {p}: line {n}: time {tt} s and speed {vv} km/h "
                                     "must not be negative")
        if t and tt <= t[-1]:
            raise UsageError(f"--cycle {p}: line {n}: time {tt} s does not increase "
                                     f"(the row before has {t[-1]} s)")
        t.append(tt)
        v.append(vv * KMH)
        ph.append(cells[ip] if ip is not None else "all")
    if len(t) < 2:
        raise UsageError(f"--cycle {p}: at least two rows of time and speed are needed")
    phases = []
    for k, name in enumerate(ph):
        if not phases or phases[-1][0] != name:
            phases.append([name, t[k], t[k]])
        phases[-1][2] = t[min(k + 1, len(t) - 1)]
    return Cycle(p.stem, np.array(t), np.array(v), [tuple(x) for x in phases], f"file {p}")


def load_cycle(text):
    if text in ("wltc3", "nedc"):
        return builtin_cycle(text)
    if not text.lower().endswith(".csv"):
        raise UsageError(f"--cycle {text!r}: give wltc3, nedc or a .csv file")
    return read_csv_cycle(user_path(text))

