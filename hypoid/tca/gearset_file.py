"""Gear-set data files `hypoid-gearset 1` (docs/data-files.md): writer and a strict reader."""

import math
from dataclasses import dataclass, field

import numpy as np

MAGIC = "hypoid-gearset 1"
MAX_HARMONICS = 32  # most harmonics a gear-set file may carry
MESH_SERIES = ("k_m", "R_p", "e_0")  # argument ψ = θ (one mesh cycle)
# ψ_k = (θ + 2π(k−1))/3; up/ug are the material flank velocities, vc the contact point's (the
# lubricant is entrained by up − vc and ug − vc); vc is optional (absent: a fixed contact point)
# and written before up/ug, so that a file cut short never ends as a valid file without vc
PAIR_SERIES = ("ls", "R_x", "R_y", "vc_x", "vc_y", "up_x", "up_y", "ug_x", "ug_y")
OPTIONAL_SERIES = ("vc_x", "vc_y")
CONTACT_SERIES = PAIR_SERIES[1:]  # undefined out of contact
UNITS = {"k_m": "N/m", "R_p": "m", "e_0": "m", "ls": "1", "R_x": "m", "R_y": "m",
         "up_x": "m/(rad/s) of pinion speed", "up_y": "m/(rad/s) of pinion speed",
         "ug_x": "m/(rad/s) of gear speed", "ug_y": "m/(rad/s) of gear speed",
         "vc_x": "m/(rad/s) of pinion speed", "vc_y": "m/(rad/s) of pinion speed"}
PARTS = ("mean", "sin", "cos")
# Layered files (docs/data-files.md): e_0 once, these per flank and torque level under
# '<flank>.<level>.<series>'; the levels are pinion torques [N·m], increasing.
FLANK_SERIES = ("k_m", "R_p") + PAIR_SERIES
FLANKS = ("drive", "coast")
MAX_LEVELS = 8


@dataclass(frozen=True)
class Series:
    """A truncated Fourier series; coefficients in the unit of the quantity."""

    mean: float
    sin: np.ndarray
    cos: np.ndarray

    def __call__(self, psi):
        psi = np.asarray(psi, dtype=float)
        i = np.arange(1, len(self.sin) + 1)
        arg = np.multiply.outer(psi, i)
        return self.mean + np.sin(arg) @ self.sin + np.cos(arg) @ self.cos


# The gear blank of the axle's loss ledger (optional 'blank.<name>' keys, all or none): the FMU's
# parameters of the same names stand in for them when given; lengths in m, angles in rad.
BLANK = ("ring_d", "ring_b", "r_m_p", "r_m_g", "delta_p", "delta_g", "beta_p", "beta_g")
BLANK_UNITS = {k: ("rad" if k.startswith(("delta", "beta")) else "m") for k in BLANK}
BLANK_RANGE = {"m": (1e-3, 5.0), "rad": (1e-6, 1.5707)}  # as the FMU checks them


class GearsetFileError(ValueError):
    """A gear-set file breaks docs/data-files.md; the message names the file and line."""


@dataclass
class Gearset:
    """Contents of a gear-set file; `comments` and `notes` (per series) are written as # lines."""

    name: str
    N_p: int
    N_g: int
    series: dict
    comments: list = field(default_factory=list)
    notes: dict = field(default_factory=dict)
    torque_levels: tuple = ()  # layered file: pinion torque of each level [N·m]
    flanks: tuple = ()  # layered file: ("drive",) or ("drive", "coast")
    layers: dict = field(default_factory=dict)  # {(flank, level 1..n): {series: Series}}
    blank: dict = field(default_factory=dict)  # {BLANK name: value in m or rad}, or empty

    @property
    def layered(self):
        return bool(self.torque_levels)


def _number(x):
    return f"{x:.10g}"


def _trimmed(s):
    """Coefficient arrays without trailing harmonics whose sin and cos are both zero."""
    n = len(s.sin)
    while n and s.sin[n - 1] == 0.0 and s.cos[n - 1] == 0.0:
        n -= 1
    return s.sin[:n], s.cos[:n]


def format_gearset(gs):
    """The text of a gear-set file."""
    lines = [f"# {c}" if c else "#" for c in gs.comments]
    name = " ".join(gs.name.replace("#", " ").split())  # one line, no comment sign
    lines += [MAGIC, f"name {name}", f"N_p {gs.N_p}", f"N_g {gs.N_g}"]
    if gs.blank:
        lines += ["", "# the gear blank for the axle's loss ledger (m, rad)"]
        lines += [f"blank.{k} {_number(gs.blank[k])}" for k in BLANK]
    if not gs.layered:
        for key in MESH_SERIES + PAIR_SERIES:
            if key in gs.series:  # the optional vc may be absent
                lines += _series_lines(key, key, gs.series[key], gs.notes)
        return "\n".join(lines) + "\n"
    lines += ["torque_levels " + " ".join(_number(t) for t in gs.torque_levels),
              "flanks " + " ".join(gs.flanks)]
    lines += _series_lines("e_0", "e_0", gs.series["e_0"], gs.notes)
    for flank in gs.flanks:
        for level, torque in enumerate(gs.torque_levels, 1):
            lines += ["", f"# --- {flank} flank at {_number(torque)} N·m ---"]
            for key in FLANK_SERIES:
                if key not in gs.layers[(flank, level)]:
                    continue
                full = f"{flank}.{level}.{key}"
                lines += _series_lines(full, key, gs.layers[(flank, level)][key], gs.notes)
    return "\n".join(lines) + "\n"


def _series_lines(full, key, s, notes):
    sin, cos = _trimmed(s)
    return ["", f"# {full} [{UNITS[key]}]" + (f": {notes[full]}" if full in notes else ""),
            f"{full}.mean {_number(s.mean)}",
            " ".join([f"{full}.sin"] + [_number(c) for c in sin]),
            " ".join([f"{full}.cos"] + [_number(c) for c in cos])]


def write_gearset(path, gs):
    with open(path, "w", encoding="utf-8") as f:
        f.write(format_gearset(gs))


def read_gearset(path):
    """Parses and checks a gear-set file; raises GearsetFileError naming file and line."""
    entries = _entries(path)
    name = entries.pop("name", (None, None))[1]
    if not name:
        raise GearsetFileError(f"{path}: missing key 'name'")
    N_p, N_g = (_teeth(path, entries, key) for key in ("N_p", "N_g"))
    blank = _blank(path, entries)
    if "torque_levels" in entries or "flanks" in entries:
        gs = _layered(path, entries, name, N_p, N_g)
    else:
        gs = Gearset(name, N_p, N_g, _present(path, entries, "", MESH_SERIES + PAIR_SERIES))
    gs.blank = blank
    if entries:
        key, (line, _) = next(iter(entries.items()))
        raise GearsetFileError(f"{path}, line {line}: unknown key '{key}'")
    return gs


def check_blank(where, blank):
    """A blank {name: value}: all eight names, each in its range; raises GearsetFileError."""
    missing = [k for k in BLANK if k not in blank]
    if missing:
        raise GearsetFileError(f"{where}: blank.{missing[0]} missing: the blank keys go together "
                               f"({', '.join(BLANK)})")
    for k in BLANK:
        lo, hi = BLANK_RANGE[BLANK_UNITS[k]]
        if not lo <= blank[k] <= hi:
            raise GearsetFileError(f"{where}: blank.{k} = {blank[k]:g} {BLANK_UNITS[k]} outside "
                                   f"{lo:g} ... {hi:g} {BLANK_UNITS[k]}")
    return blank


def _blank(path, entries):
    given = {k: _numbers(path, entries, f"blank.{k}") for k in BLANK if f"blank.{k}" in entries}
    if not given:
        return {}
    for k, (line, values) in given.items():
        if len(values) != 1:
            raise GearsetFileError(f"{path}, line {line}: 'blank.{k}' must be one number")
    return check_blank(path, {k: v[0] for k, (_, v) in given.items()})


def _layered(path, entries, name, N_p, N_g):
    """A layered file: torque_levels, flanks, e_0 and the series of every flank and level."""
    line, levels = _numbers(path, entries, "torque_levels")
    if not 1 <= len(levels) <= MAX_LEVELS:
        raise GearsetFileError(f"{path}, line {line}: torque_levels needs 1 to {MAX_LEVELS} values "
                               f"(has {len(levels)})")
    for i, t in enumerate(levels):
        if t < 0 or (i and t <= levels[i - 1]):
            raise GearsetFileError(f"{path}, line {line}: torque_levels value {i + 1} = {t:g} N·m "
                                   "must be >= 0 and above the one before: the levels must increase")
    if "flanks" not in entries:
        raise GearsetFileError(f"{path}: missing key 'flanks' (drive, or drive coast)")
    f_line, text = entries.pop("flanks")
    flanks = tuple(text.split())
    if flanks not in (FLANKS[:1], FLANKS):
        raise GearsetFileError(f"{path}, line {f_line}: flanks '{text}': must be 'drive' or "
                               "'drive coast'")
    if "coast" in flanks and "coast.1.k_m.mean" not in entries:
        raise GearsetFileError(f"{path}, line {f_line}: flanks '{text}' asks for a coast flank, "
                               "but the file has no coast series (no key 'coast.1.k_m.mean')")
    series = {"e_0": _series(path, entries, "e_0")}
    layers = {(f, i): _present(path, entries, f"{f}.{i}.", FLANK_SERIES)
              for f in flanks for i in range(1, len(levels) + 1)}
    return Gearset(name, N_p, N_g, series, torque_levels=tuple(levels), flanks=flanks,
                   layers=layers)


def _present(path, entries, prefix, keys):
    """{key: Series} of `keys` under `prefix`; the optional series only when the file has them
    (vc_x without vc_y, or the other way round, fails on the missing one)."""
    given = any(f"{prefix}{k}.mean" in entries for k in OPTIONAL_SERIES)
    return {key: _series(path, entries, prefix + key) for key in keys
            if key not in OPTIONAL_SERIES or given}


def _entries(path):
    """{key: (line, rest of line)} after the header; checks header and unique keys."""
    with open(path, encoding="utf-8") as f:
        raw = f.read().splitlines()
    entries, header = {}, False
    for line_no, text in enumerate(raw, 1):
        text = text.split("#", 1)[0].strip()
        if not text:
            continue
        if not header:
            if " ".join(text.split()) != MAGIC:
                raise GearsetFileError(f"{path}, line {line_no}: header must be '{MAGIC}'")
            header = True
            continue
        key, rest = (text.split(None, 1) + [""])[:2]
        if key in entries:
            raise GearsetFileError(f"{path}, line {line_no}: duplicate key '{key}' "
                                   f"(first on line {entries[key][0]})")
        entries[key] = (line_no, rest.strip())
    if not header:
        raise GearsetFileError(f"{path}: no header '{MAGIC}'")
    return entries


def _numbers(path, entries, key):
    if key not in entries:
        raise GearsetFileError(f"{path}: missing key '{key}'")
    line, rest = entries.pop(key)
    try:
        values = [float(v) for v in rest.split()]
    except ValueError:
        raise GearsetFileError(f"{path}, line {line}: '{key}' has a value that is not a number")
    if not all(math.isfinite(v) for v in values):
        raise GearsetFileError(f"{path}, line {line}: '{key}' has a NaN or infinite value")
    return line, values


def _teeth(path, entries, key):
    line, values = _numbers(path, entries, key)
    if len(values) != 1 or values[0] != int(values[0]) or values[0] < 1:
        raise GearsetFileError(f"{path}, line {line}: '{key}' must be one positive integer")
    return int(values[0])


def _series(path, entries, key):
    (_, mean), (line_s, sin), (line_c, cos) = (_numbers(path, entries, f"{key}.{p}") for p in PARTS)
    if len(mean) != 1:
        raise GearsetFileError(f"{path}: '{key}.mean' must have exactly one value")
    if len(sin) != len(cos) or len(sin) > MAX_HARMONICS:
        raise GearsetFileError(f"{path}, lines {line_s}/{line_c}: '{key}.sin' and '{key}.cos' "
                               f"need equal counts of at most {MAX_HARMONICS} "
                               f"(have {len(sin)}/{len(cos)})")
    return Series(mean[0], np.array(sin), np.array(cos))
