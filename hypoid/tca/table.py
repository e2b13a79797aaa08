"""A user's TCA table (docs/tca-import.md): reading, and the checks of its cells and of its
physics. Every problem raises TableError naming the file, line, column and value. The fit into a
gear-set file is hypoid/tca/table_import.py, the command line hypoid/cli/tca.py."""

import csv
import math
import os
from dataclasses import dataclass

import numpy as np

from hypoid import csvtext
from hypoid.tca import surrogate as sur
from hypoid.tca.fit import CONTACT_HARMONICS, HARMONICS

LS_TOL = 0.01  # load shares within [−LS_TOL, 1 + LS_TOL] are accepted and clipped to [0, 1]
LS_SUM_TOL = 0.05  # the three pairs' shares must sum to 1 within this
MIN_ROWS = 64  # rows per period of a TCA table (§10.7: N ≥ 64)
MIN_CONTACT_ROWS = 16  # rows inside the contact of the tabulated pair
PITCH_TOL = (0.25, 1e-3)  # allowed pitch-to-pitch difference: share of the ripple, share of max |y|

ANGLE_COLUMNS = {"phi_p_deg": math.pi / 180.0, "phi_p_rad": 1.0}  # column name: rad per unit
MESH_COLUMNS = {"k_m_N_per_m": ("k_m", 1.0), "R_p_mm": ("R_p", 1e-3), "e_0_um": ("e_0", 1e-6)}
RADIUS_COLUMNS = {"R_x": ("r_px_mm", "r_gx_mm"), "R_y": ("r_py_mm", "r_gy_mm")}
VELOCITY_COLUMNS = {"up_x": "up_x_m_s", "up_y": "up_y_m_s", "ug_x": "ug_x_m_s", "ug_y": "ug_y_m_s"}
CONTACT_COLUMNS = ["r_px_mm", "r_py_mm", "r_gx_mm", "r_gy_mm"] + list(VELOCITY_COLUMNS.values())
DATA_COLUMNS = list(MESH_COLUMNS) + ["ls"] + CONTACT_COLUMNS
# optional: the contact point's velocity, and the material flank velocities (docs/tca-import.md)
POINT_COLUMNS = ("vc_x_m_s", "vc_y_m_s")
MATERIAL_COLUMNS = {"up_x": "upm_x_m_s", "up_y": "upm_y_m_s", "ug_x": "ugm_x_m_s",
                    "ug_y": "ugm_y_m_s"}
OPTIONAL_COLUMNS = POINT_COLUMNS + tuple(MATERIAL_COLUMNS.values())
VELOCITY_TOL = (1e-3, 1e-6)  # velocity sets agree within this share of the largest speed + m/s
META_KEYS = ("name", "N_p", "N_g", "speed_rpm", "torque_Nm", "flank")
FLANK_NAMES = ("drive", "coast")


class TableError(ValueError):
    """A TCA table that cannot be imported; the message names file, line, column and value."""


# --- TCA table: reading and checks ---------------------------------------------------------------

@dataclass
class Table:
    """A parsed TCA table: metadata {key: (line, text)}, angle column, rows (NaN = blank cell)."""

    path: str
    meta: dict
    angle: str
    lines: np.ndarray
    columns: dict


def fail(table_or_path, line, column, value, problem):
    path = getattr(table_or_path, "path", table_or_path)
    where = f", line {line}" if line else ""
    where += f", column '{column}'" if column else ""
    if value is not None:
        where += f", value {value!r}" if isinstance(value, str) else f", value {value:g}"
    raise TableError(f"{path}{where}: {problem}")


def read_table(path):
    """Parses a TCA table (docs/tca-import.md); checks cells, not physics."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.reader(f, delimiter=_delimiter(f))
            rows = [(line, [c.strip() for c in row]) for line, row in _csv_rows(reader)]
    except (csv.Error, UnicodeDecodeError) as err:
        raise TableError(f"{path}: not a readable CSV text file ({err})") from None
    header_at = next((i for i, (_, row) in enumerate(rows) if row[0] in ANGLE_COLUMNS), None)
    if header_at is None:
        fail(path, None, None, None,
              f"no column header row starting with {' or '.join(ANGLE_COLUMNS)}")
    meta = _read_meta(path, rows[:header_at])
    line, header = rows[header_at]
    while not header[-1]:
        header.pop()  # trailing empty cells of a spreadsheet export
    _check_header(path, line, header)
    data = [(ln, _fit_row(path, ln, row, len(header))) for ln, row in rows[header_at + 1:]]
    lines = np.array([ln for ln, _ in data], dtype=int)
    columns = {name: np.array([_cell(path, ln, name, row[i]) for ln, row in data], dtype=float)
               for i, name in enumerate(header)}
    return Table(path, meta, header[0], lines, columns)


def _delimiter(f):
    """The cell separator of a table (hypoid.csvtext.delimiter of its first lines)."""
    start = f.tell()
    lines = [f.readline() for _ in range(200)]
    f.seek(start)
    return csvtext.delimiter(lines)


def _csv_rows(reader):
    """(line, cells) of the rows that are neither blank nor comments ('#' in the first cell)."""
    for row in reader:
        if any(c.strip() for c in row) and not row[0].strip().startswith("#"):
            yield reader.line_num, row


def _read_meta(path, rows):
    meta = {}
    for line, row in rows:
        key, values = row[0], [c for c in row[1:] if c]
        if key not in META_KEYS:
            fail(path, line, None, key, f"unknown metadata key (known: {', '.join(META_KEYS)})")
        if len(values) != 1 or key in meta:
            fail(path, line, None, key, "metadata needs one row 'key,value' per key")
        meta[key] = (line, values[0])
    return meta


def _check_header(path, line, header):
    expected = set(DATA_COLUMNS) | set(OPTIONAL_COLUMNS)
    missing = [c for c in DATA_COLUMNS if c not in header]
    unknown = [c for c in header[1:] if c not in expected]
    duplicate = sorted({c for c in header if header.count(c) > 1})
    for names, problem in ((missing, "missing column(s)"), (unknown, "unknown column(s)"),
                           (duplicate, "duplicate column(s)")):
        if names:
            fail(path, line, None, None, f"{problem} {', '.join(names)}; the columns are "
                  f"{' or '.join(ANGLE_COLUMNS)}, {', '.join(DATA_COLUMNS)} and optionally "
                  f"{', '.join(OPTIONAL_COLUMNS)}")
    for group in (POINT_COLUMNS, tuple(MATERIAL_COLUMNS.values())):
        given = [c for c in group if c in header]
        if given and len(given) != len(group):
            fail(path, line, None, None, f"column(s) {', '.join(c for c in group if c not in given)}"
                  f" missing: {', '.join(group)} go together")


def _fit_row(path, line, row, n):
    """A data row padded with blank cells to n cells; extra cells must be blank."""
    if any(row[n:]):
        fail(path, line, None, None, f"row has more cells than the header ({n})")
    return row[:n] + [""] * (n - len(row))


def _cell(path, line, name, text):
    """The number in a cell of column `name`; NaN for a blank cell (allowed only for pair data)."""
    if not text:
        if name in ANGLE_COLUMNS or name in MESH_COLUMNS:
            fail(path, line, name, text, "blank cell; only ls and contact data may be blank")
        return math.nan
    try:
        value = csvtext.number(text)  # also a decimal comma (tables separated by ';')
    except ValueError:
        fail(path, line, name, text, "not a number")
    if math.isnan(value):
        fail(path, line, name, text, "NaN is not allowed; leave cells out of contact blank")
    if math.isinf(value):
        fail(path, line, name, text, "not a finite number")
    return value


@dataclass
class Checked:
    """A TCA table after the checks: one period of rows, SI units, pair-1 argument ψ."""

    path: str
    name: str
    N_p: int
    N_g: int
    speed_rpm: float
    psi: np.ndarray  # ψ = N_p φ_p / 3 of each row [rad]
    lines: np.ndarray
    values: dict  # series key -> row values in SI (NaN out of contact)


def check_table(table, speed_rpm=None, harmonics=HARMONICS, contact_harmonics=CONTACT_HARMONICS):
    """Checks a parsed table and converts it to SI; raises TableError naming line, column, value."""
    N_p, N_g = (meta_int(table, key) for key in ("N_p", "N_g"))
    if N_g < N_p:
        fail(table, table.meta["N_g"][0], None, N_g, f"N_g is smaller than N_p = {N_p}")
    speed = _speed(table, speed_rpm)
    min_rows = max(MIN_ROWS, 3 * (2 * harmonics + 1), 2 * contact_harmonics + 1)
    rows = _one_period(table, N_p, min_rows)
    cols = {name: v[rows] for name, v in table.columns.items()}
    lines = table.lines[rows]
    _check_positive(table, lines, cols, ("k_m_N_per_m", "R_p_mm"), "must be positive")
    _check_magnitudes(table, lines, cols, speed * math.pi / 30.0)
    values = {key: cols[name] * scale for name, (key, scale) in MESH_COLUMNS.items()}
    values["ls"] = _load_share(table, lines, cols)
    omega_p = speed * math.pi / 30.0  # [rad/s]
    values.update(_contact(table, lines, cols, omega_p, omega_p * N_p / N_g))
    psi = N_p * ANGLE_COLUMNS[table.angle] * cols[table.angle] / 3.0
    name = table.meta.get("name", (0, os.path.splitext(os.path.basename(table.path))[0]))[1]
    return Checked(table.path, name, N_p, N_g, speed, psi, lines, values)


# Plausible magnitudes (typical row) of a hypoid gear pair from a passenger car to a truck axle,
# a decade and more around them on each side; a column off by 10^3 (a unit mixed up) is far out.
MAGNITUDES = {  # column: (low, high, unit, what too small / too large most likely means)
    "R_p_mm": (1.0, 1000.0, "mm", "metres", "micrometres"),
    "k_m_N_per_m": (1e6, 1e11, "N/m", "N/mm or N/um", "N/m times 10^3"),
    "r_px_mm": (0.5, 1e5, "mm", "metres", "micrometres"),
    "r_gx_mm": (0.5, 1e5, "mm", "metres", "micrometres"),
}
SPEED_RATIO = (0.03, 30.0)  # flank speed / (omega_p R_p): rolling is of the order of omega_p R_p


def _typical(values):
    v = np.abs(values[np.isfinite(values)])
    return float(np.median(v)) if len(v) else math.nan


def _check_magnitudes(table, lines, cols, omega_p):
    """A column whose typical value is off the plausible range by about 10^3: the likely unit
    mix-up named (a radius in m under the mm header, a stiffness in N/mm, velocities in mm/s)."""
    for name, (low, high, unit, small, large) in MAGNITUDES.items():
        x = _typical(cols[name])
        if x < low or x > high:
            i = int(np.nanargmin(np.abs(np.abs(cols[name]) - x)))
            fail(table, lines[i], name, cols[name][i],
                  f"implausible: typically {x:.4g} {unit}, expected {low:g} ... {high:g} {unit}; "
                  f"values in {small if x < low else large} under the {unit} header?")
    scale = omega_p * 1e-3 * _typical(cols["R_p_mm"])
    for side in ("up", "ug"):
        x_col, y_col = f"{side}_x_m_s", f"{side}_y_m_s"
        speed = _typical(np.hypot(cols[x_col], cols[y_col]))
        ratio = speed / scale
        if not SPEED_RATIO[0] <= ratio <= SPEED_RATIO[1]:
            i = int(np.nanargmin(np.abs(np.hypot(cols[x_col], cols[y_col]) - speed)))
            fail(table, lines[i], x_col, cols[x_col][i],
                  f"implausible: flank speeds of typically {speed:.4g} m/s against omega_p R_p = "
                  f"{scale:.4g} m/s at {omega_p * 30 / math.pi:g} rpm ({ratio:.3g} times): "
                  + ("values in mm/s under the m/s header, or speed_rpm too small?" if ratio > 1
                     else "values in km/s under the m/s header, or speed_rpm too large?"))


def meta_int(table, key):
    if key not in table.meta:
        fail(table, None, None, None, f"missing metadata row '{key},<value>' before the header")
    line, text = table.meta[key]
    value = to_float(text)
    if not (math.isfinite(value) and value >= 1 and value.is_integer()):
        fail(table, line, None, text, f"{key} must be a positive integer")
    return int(value)


def _speed(table, speed_rpm):
    """Pinion speed of the velocity columns [rpm]: --speed-rpm, else the table's speed_rpm row."""
    if speed_rpm is not None:
        line, text = None, str(speed_rpm)
    elif "speed_rpm" in table.meta:
        line, text = table.meta["speed_rpm"]
    else:
        fail(table, None, None, None,
              "no pinion speed: give a 'speed_rpm,<value>' row or --speed-rpm")
    speed = to_float(text)
    if not (math.isfinite(speed) and speed > 0):
        fail(table, line, "speed_rpm", text, "the pinion speed must be a positive number [rpm]")
    return speed


def to_float(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def _one_period(table, N_p, min_rows):
    """Indices of the rows in [φ_0, φ_0 + P), P = 3 angular pitches; checks order, span, count."""
    to_rad = ANGLE_COLUMNS[table.angle]
    phi = table.columns[table.angle] * to_rad
    period = 6.0 * math.pi / N_p
    if len(phi) < 2:
        fail(table, None, None, None, f"too few rows ({len(phi)}); at least {min_rows} per period")
    step = np.diff(phi)
    if (step <= 0).any():
        i = int(np.argmax(step <= 0)) + 1
        fail(table, table.lines[i], table.angle, table.columns[table.angle][i],
              "angles must increase strictly from row to row")
    rows = np.flatnonzero(phi - phi[0] < period * (1.0 - 1e-9))
    gap = phi[0] + period - phi[rows[-1]]
    if gap > 1.5 * step[: max(len(rows) - 1, 1)].max() + 1e-12:
        fail(table, table.lines[rows[-1]], table.angle, table.columns[table.angle][rows[-1]],
              f"the angles span {(phi[rows[-1]] - phi[0]) / to_rad:.6g} but one period is 3 "
              f"angular pitches = {period / to_rad:.6g} ({table.angle}, N_p = {N_p}); the table "
              "must cover it up to about one step")
    if len(rows) < min_rows:
        fail(table, None, None, None, f"too few rows in one period: {len(rows)}, need {min_rows} "
              "(at least 64, and more than twice the harmonics per period)")
    return rows


def _check_positive(table, lines, cols, names, problem):
    for name in names:
        bad = np.flatnonzero(~(cols[name] > 0))
        if len(bad):
            fail(table, lines[bad[0]], name, cols[name][bad[0]], problem)


def _load_share(table, lines, cols):
    ls = np.nan_to_num(cols["ls"], nan=0.0)  # blank = 0
    bad = np.flatnonzero((ls < -LS_TOL) | (ls > 1.0 + LS_TOL))
    if len(bad):
        fail(table, lines[bad[0]], "ls", ls[bad[0]],
              f"load share outside [0, 1] by more than {LS_TOL}")
    return np.clip(ls, 0.0, 1.0)


def _contact(table, lines, cols, omega_p, omega_g):
    """Reduced radii [m] and velocities per unit speed of the contact rows (NaN elsewhere)."""
    names = CONTACT_COLUMNS + [c for c in OPTIONAL_COLUMNS if c in cols]
    given = np.stack([~np.isnan(cols[c]) for c in names])
    partial = np.flatnonzero(given.any(axis=0) & ~given.all(axis=0))
    if len(partial):
        r = partial[0]
        fail(table, lines[r], names[int(np.argmin(given[:, r]))], "",
              "blank while other contact columns of the row are given")
    inside = given[0]
    loaded = np.flatnonzero(~inside & (np.nan_to_num(cols["ls"]) > LS_TOL))
    if len(loaded):
        fail(table, lines[loaded[0]], CONTACT_COLUMNS[0], "",
              f"blank contact data but ls = {cols['ls'][loaded[0]]:g} > 0")
    _check_arc(table, lines, inside)
    values = {key: _reduced_radius(table, lines, cols, pair)
              for key, pair in RADIUS_COLUMNS.items()}
    bad = np.flatnonzero(values["R_x"] > values["R_y"])
    if len(bad):
        i = bad[0]
        R_x, R_y = 1e3 * values["R_x"][i], 1e3 * values["R_y"][i]
        fail(table, lines[i], "r_px_mm", cols["r_px_mm"][i],
              f"reduced radii R_x = {R_x:.4g} mm > R_y = {R_y:.4g} mm: x must be the minor axis "
              "of the contact ellipse (the larger curvature)")
    v_c = _contact_point(table, lines, cols)
    for key, name in VELOCITY_COLUMNS.items():  # material = relative to the contact + v_c
        values[key] = (cols[name] + v_c[key[-1]]) / (omega_p if key.startswith("up") else omega_g)
    if any(c in cols for c in OPTIONAL_COLUMNS):
        values["vc_x"], values["vc_y"] = v_c["x"] / omega_p, v_c["y"] / omega_p
    return values


def _contact_point(table, lines, cols):
    """The contact point's velocity {x, y} [m/s] from the table's velocity sets, which must agree:
    material minus relative is the same for pinion and gear, and equal to vc when it is given.
    Neither set given: a contact point fixed in space (0)."""
    sets = []
    if all(c in cols for c in POINT_COLUMNS):
        sets.append(("vc", {a: cols[f"vc_{a}_m_s"] for a in "xy"}))
    if all(c in cols for c in MATERIAL_COLUMNS.values()):
        for member in ("up", "ug"):
            sets.append((member, {a: cols[MATERIAL_COLUMNS[f"{member}_{a}"]]
                                  - cols[VELOCITY_COLUMNS[f"{member}_{a}"]] for a in "xy"}))
    if not sets:
        return {"x": 0.0, "y": 0.0}
    speeds = np.concatenate([np.abs(cols[c]) for c in VELOCITY_COLUMNS.values()])
    tol = VELOCITY_TOL[0] * np.nanmax(speeds, initial=0.0) + VELOCITY_TOL[1]
    ref_name, ref = sets[0]
    for name, other in sets[1:]:
        for a in "xy":
            bad = np.flatnonzero(np.abs(np.nan_to_num(other[a] - ref[a])) > tol)
            if len(bad):
                i = bad[0]
                column = MATERIAL_COLUMNS[f"{name}_{a}"]
                fail(table, lines[i], column, float(cols[column][i]),
                      f"the velocity sets contradict each other: the contact point moves at "
                      f"{ref[a][i]:.6g} m/s along {a} by {ref_name} but {other[a][i]:.6g} m/s by "
                      f"{name} (material minus relative velocity must be the contact point's "
                      f"velocity for both members; tolerance {tol:.3g} m/s)")
    return ref


def _check_arc(table, lines, inside):
    """The tabulated pair's contact rows must form one cyclic range of enough rows."""
    if inside.all():
        return
    starts = np.flatnonzero(inside & ~np.roll(inside, 1))
    runs = len(starts)
    if runs != 1:
        fail(table, lines[starts[-1]] if runs else None, None, None,
              "the tabulated pair must be in contact over one range of angles "
              f"(found {runs}{'; this row starts the last' if runs else ''}); "
              "leave its contact cells blank only out of contact")
    if inside.sum() < MIN_CONTACT_ROWS:
        fail(table, None, None, None,
              f"too few rows in contact: {inside.sum()}, need {MIN_CONTACT_ROWS}")


def _reduced_radius(table, lines, cols, pair):
    r_p, r_g = cols[pair[0]], cols[pair[1]]
    for name in pair:
        zero = np.flatnonzero(cols[name] == 0)
        if len(zero):
            fail(table, lines[zero[0]], name, 0.0, "a radius of curvature cannot be zero")
    with np.errstate(divide="ignore", invalid="ignore"):
        R = 1e-3 * sur.reduced(r_p, r_g)
    bad = np.flatnonzero(~np.isnan(r_p) & ~(R > 0))
    if len(bad):
        i = bad[0]
        fail(table, lines[i], pair[0], r_p[i],
              f"with {pair[1]} = {r_g[i]:g} the reduced radius is not positive "
              "(radii are signed: convex > 0, concave < 0)")
    return R
