"""A user's TCA tables into a gear-set file (docs/tca-import.md): the samples of a checked table,
the checks of the fitted series (load shares, pitch to pitch), and several tables as both flanks
at several torques. Every problem raises TableError naming the file, line, column and value."""

import math
import os

import numpy as np

from hypoid.tca.fit import (CONTACT_HARMONICS, HARMONICS, N_SAMPLES, fit_gearset, fit_notes, grid,
                            resample)
from hypoid.tca.gearset_file import (FLANK_SERIES, MAX_LEVELS, MESH_SERIES, PAIR_SERIES, UNITS,
                                     Gearset)
from hypoid.tca.table import (FLANK_NAMES, LS_SUM_TOL, MESH_COLUMNS, PITCH_TOL, check_table, fail,
                              meta_int, read_table, to_float)


# --- TCA table: fit ----------------------------------------------------------------------------

def table_samples(checked):
    """Uniform samples for fit_gearset and checks {key: (angle, row values)} for fit_notes."""
    n = N_SAMPLES
    samples, checks = {}, {}
    for key in MESH_SERIES:
        three = resample(checked.psi, checked.values[key], 3 * n).reshape(3, n)
        samples[key] = three.mean(axis=0)  # the three pitches averaged: one mesh cycle in θ
        _check_pitch(checked, key, three)
        checks[key] = (3.0 * checked.psi, checked.values[key])
    for key in PAIR_SERIES:
        if key not in checked.values:  # the optional contact point velocity
            continue
        samples[key] = resample(checked.psi, checked.values[key], n)
        checks[key] = (checked.psi, checked.values[key])
    _check_load_sum(checked, samples["ls"])
    return samples, checks


def _check_load_sum(checked, ls):
    """The shares of the three pairs, ls(ψ) + ls(ψ + 2π/3) + ls(ψ + 4π/3), must sum to 1."""
    n = len(ls)
    total = ls + np.roll(ls, -n // 3) + np.roll(ls, -2 * n // 3)
    worst = int(np.argmax(np.abs(total - 1.0)))
    if abs(total[worst] - 1.0) > LS_SUM_TOL:
        phi_deg = math.degrees(3.0 * grid(n)[worst] / checked.N_p)
        fail(checked.path, None, "ls", None,
              f"the load shares of the three pairs (the tabulated one and the same one and two "
              f"angular pitches later) sum to {total[worst]:.3g} at phi_p = {phi_deg:.4g} deg "
              f"(mod one period); they must sum to 1 within {LS_SUM_TOL}")


def _check_pitch(checked, key, three):
    """Mesh quantities must repeat every angular pitch, else N_p does not fit the table."""
    mean = three.mean(axis=0)
    diff = np.abs(three - mean).max()
    allowed = PITCH_TOL[0] * np.ptp(mean) + PITCH_TOL[1] * np.abs(mean).max()
    if diff > allowed:
        column = next(c for c, (k, _) in MESH_COLUMNS.items() if k == key)
        fail(checked.path, None, column, None,
              f"does not repeat every angular pitch (360/N_p deg) with N_p = {checked.N_p}: "
              f"pitch-to-pitch difference {diff:.3g} {UNITS[key]}, allowed {allowed:.3g}; "
              "check N_p")


def import_table(path, speed_rpm=None, harmonics=HARMONICS, contact_harmonics=CONTACT_HARMONICS,
                 name=None):
    """A Gearset from the user's TCA table at `path` (docs/tca-import.md)."""
    checked = check_table(read_table(path), speed_rpm, harmonics, contact_harmonics)
    samples, checks = table_samples(checked)
    series = fit_gearset(samples, harmonics, contact_harmonics)
    comments = [
        f"Imported from the TCA table {os.path.basename(path)} by `hypoid tca import`; "
        "format docs/tca-import.md.",
        f"Pinion speed of the tabulated velocities {checked.speed_rpm:g} rpm; "
        f"{len(checked.lines)} rows over one period (3 angular pitches).",
        f"Fit (docs/physics.md §10.7): resampled to {N_SAMPLES} points per period (cubic splines), "
        f"{harmonics} harmonics for k_m, R_p, e_0, ls",
        f"  and {contact_harmonics} for the contact series, bridged outside contact by a C2 "
        "quintic.",
        "Units SI (m, N/m, rad); series format in docs/data-files.md.",
    ]
    notes = fit_notes(series, checks, "the table rows")
    return Gearset(name or checked.name, checked.N_p, checked.N_g, series, comments, notes)


# --- several tables: both flanks at several torques (docs/tca-import.md) ----------------------

def _table_load(table):
    """(flank, torque [N·m] or None, line of the torque row) from a table's metadata."""
    line, flank = table.meta.get("flank", (None, "drive"))
    if flank not in FLANK_NAMES:
        fail(table, line, None, flank, "flank must be 'drive' or 'coast'")
    if "torque_Nm" not in table.meta:
        return flank, None, None
    t_line, text = table.meta["torque_Nm"]
    torque = to_float(text)
    if not (math.isfinite(torque) and torque >= 0.0):
        fail(table, t_line, None, text, "torque_Nm must be a pinion torque >= 0 [N·m]")
    return flank, torque, t_line


def _one_gear_set(tables):
    """Every table must describe the same gear set: equal N_p and N_g."""
    first = tables[0]
    for table in tables[1:]:
        for key in ("N_p", "N_g"):
            if meta_int(table, key) != meta_int(first, key):
                fail(table, table.meta[key][0], None, table.meta[key][1],
                      f"{key} differs from {meta_int(first, key)} in {first.path}: the flanks "
                      "and torque levels must describe one gear set (one period, three pairs)")


def _levels(tables):
    """{(flank, torque): table} and the drive flank's increasing torque levels."""
    by_load = {}
    for table in tables:
        flank, torque, line = _table_load(table)
        if torque is None:
            fail(table, None, None, None, "several tables need a 'torque_Nm,<pinion torque>' row "
                  "each (and 'flank,coast' for the back flank's)")
        if (flank, torque) in by_load:
            fail(table, line, None, torque, f"a second {flank} table at {torque:g} N·m "
                  f"(the first is {by_load[(flank, torque)].path})")
        by_load[(flank, torque)] = table
    levels = sorted(t for f, t in by_load if f == "drive")
    if not levels:
        fail(tables[0], None, None, None, "no drive-flank table ('flank,drive' or no flank row)")
    for (flank, torque), table in by_load.items():
        if flank == "coast" and torque not in levels:
            fail(table, table.meta["torque_Nm"][0], None, torque,
                  f"a coast table at {torque:g} N·m but no drive table there (drive levels: "
                  f"{', '.join(f'{t:g}' for t in levels)} N·m): both flanks need the same levels")
    coast = [t for f, t in by_load if f == "coast"]
    if coast and len(coast) != len(levels):
        missing = [t for t in levels if t not in coast]
        at = ", ".join(f"{t:g}" for t in missing)
        fail(tables[0], None, None, None, f"coast tables missing at {at} N·m: with any coast "
              "table every torque level needs one")
    if len(levels) > MAX_LEVELS:
        fail(tables[0], None, None, None, f"{len(levels)} torque levels: at most {MAX_LEVELS}")
    return by_load, levels


def import_tables(paths, speed_rpm=None, harmonics=HARMONICS, contact_harmonics=CONTACT_HARMONICS,
                  name=None):
    """A Gearset from one table, or a layered one from tables of several torques and flanks."""
    tables = [read_table(p) for p in paths]
    if len(tables) == 1 and not {"torque_Nm", "flank"} & set(tables[0].meta):
        return import_table(paths[0], speed_rpm, harmonics, contact_harmonics, name)
    _one_gear_set(tables)
    by_load, levels = _levels(tables)
    flanks = tuple(f for f in FLANK_NAMES if any(k[0] == f for k in by_load))
    layers, notes = {}, {}
    for (flank, torque), table in by_load.items():
        checked = check_table(table, speed_rpm, harmonics, contact_harmonics)
        samples, checks = table_samples(checked)
        series = fit_gearset(samples, harmonics, contact_harmonics)
        level = levels.index(torque) + 1
        layers[(flank, level)] = {k: series[k] for k in FLANK_SERIES if k in series}
        for key, note in fit_notes(series, checks, "the table rows").items():
            notes[f"{flank}.{level}.{key}"] = note
        if (flank, level) == ("drive", 1):
            e_0, first = series["e_0"], checked
    comments = [
        f"Imported from {len(tables)} TCA tables by `hypoid tca import`; format docs/tca-import.md.",
        "Flanks " + " and ".join(flanks) + " at pinion torques "
        + ", ".join(f"{t:g}" for t in levels) + " N·m; e_0 from the drive table at "
        f"{levels[0]:g} N·m ({os.path.basename(first.path)}).",
        f"Fit (docs/physics.md §10.7): {N_SAMPLES} points per period, {harmonics} harmonics for "
        f"k_m, R_p, e_0, ls and {contact_harmonics} for the contact series.",
        "Units SI (m, N/m, rad); series format in docs/data-files.md.",
    ]
    return Gearset(name or first.name, first.N_p, first.N_g, {"e_0": e_0}, comments, notes,
                   torque_levels=tuple(levels), flanks=flanks, layers=layers)
