"""Study tables as the figures, the findings and the report read them: the rows that ran
(`prepare`), rows at the paper's reference conditions (`select`, `curve`), the resonance speeds
and the modal table of each gear set. No plotting, no verdicts."""

import pathlib

import numpy as np
import pandas as pd

BUILTIN_LUBRICANTS = {1: "OS265962", 2: "OS265963"}
# the reference conditions of the paper's figures (other columns at the FMU's start values)
# (every parameter a study varies besides gear set, lubricant, torque and speed belongs here)
# the paper's EHL choices spelled out (the FMU's defaults follow the traction evidence instead,
# docs/friction-evidence.md)
PAPER_EHL = {"roelands_z": "simple", "shear_pressure": "mean", "Lambda_cap": 0.0,
             "relaxation": "constant", "inlet_heating": "none"}
# with the paper's calibrated one-series tooth data (the FMU's default is the loaded data;
# preset = paper selects both, but would override a study's variant of one)
PAPER_CHOICES = {**PAPER_EHL, "tooth_data": "paper"}
REFERENCE = {"T_bath": 313.15, "friction_model": "ehl_thermal", "mesh_model": "varying",
             "k_f": 0.0, **PAPER_CHOICES, "e_0_scale": 1.0, "k_m_scale": 1.0, "I_p": 0.014}


def prepare(df):
    """Status-ok rows, empty strings for missing file names, a lubricant label column."""
    if df is None or df.empty:
        return pd.DataFrame()
    df = df[df["status"] == "ok"].copy()
    if "lubricant_file" in df:
        df["lubricant_file"] = df["lubricant_file"].fillna("").astype(str)
    df["lubricant_name"] = [lubricant_label(r) for r in df.itertuples()]
    return df


def lubricant_label(row):
    path = getattr(row, "lubricant_file", "") or ""
    if path:
        name = _file_name(path)
    else:
        name = BUILTIN_LUBRICANTS.get(int(row.lubricant), f"lubricant {row.lubricant}")
    k_f = getattr(row, "k_f", 0.0)
    return f"{name}, k_f {k_f:g}" if k_f and np.isfinite(k_f) else name


def _file_name(path):
    p = pathlib.Path(path)
    try:
        for line in p.read_text().splitlines():
            if line.startswith("name "):
                return line[5:].strip()
    except OSError:
        pass
    return p.stem


def select(df, **eq):
    """Rows at the reference conditions with the given column values (floats to 1e-9)."""
    if df.empty:
        return df
    mask = np.ones(len(df), bool)
    for col, val in {**REFERENCE, **eq}.items():
        if col not in df:
            continue
        if isinstance(val, str):
            mask &= df[col].astype(str).to_numpy() == val
        else:
            mask &= np.isclose(df[col].to_numpy(float), float(val), rtol=0, atol=1e-9)
    return df[mask]


def curve(df, y="eta_rms", **eq):
    """Series y by speed_rpm (mean of duplicates)."""
    sel = select(df, **eq)
    return sel.groupby("speed_rpm")[y].mean().sort_index()


def resonances(df, gear_set, **where):
    """{'f2': rpm, 'f3': rpm} of a gear set (from the calculated parameters in the table) at the
    reference inertias, or at those `where` sets (a what-if)."""
    sel = select(df, gear_set=gear_set, **where)
    if sel.empty:
        return {}
    return {"f2": float(sel["n_f2_rpm"].iloc[0]), "f3": float(sel["n_f3_rpm"].iloc[0])}


def calibration_probes(pts):
    """The e_0_scale values other than 1 in a table (the full study's calibration probe)."""
    if "e_0_scale" not in pts:
        return []
    return sorted(v for v in pts["e_0_scale"].dropna().unique() if v != 1.0)


WHATIF_COLUMNS = ("I_p",)  # what a what-if variant of gear set 1 may change (hypoid.study.paper.WhatIf)


def whatifs(df):
    """The what-if variants in a table, as {column: value} (values off the reference)."""
    out = []
    for col in WHATIF_COLUMNS:
        if col in df:
            out += [{col: float(v)} for v in sorted(df[col].dropna().unique())
                    if not np.isclose(v, REFERENCE[col], rtol=0, atol=1e-12)]
    return out


def modal_table(pts):
    """The calculated modal parameters per gear set at the reference inertias, then gear set 1
    of each what-if."""
    rows = []
    variants = [({}, gs) for gs in sorted(pts["gear_set"].unique())] + [
        (w, 1) for w in whatifs(pts)]
    for where, gs in variants:
        g = select(pts, gear_set=gs, **where)
        if g.empty:
            continue
        r = g.iloc[0]
        label = f"{int(gs)}" + "".join(f", {k} = {v:g}" for k, v in where.items())
        rows.append({"gear set": label, "N_p": int(r["N_p"]), "ratio": r["ratio"],
                     "k_m0 [N/m]": r["k_m0"], "R_p0 [m]": r["R_p0"], "f_2 [Hz]": r["f_2"], "f_3 [Hz]": r["f_3"],
                     "f_4 [Hz]": r["f_4"], "n(f_2) [rpm]": r["n_f2_rpm"],
                     "n(f_3) [rpm]": r["n_f3_rpm"], "n(f_4) [rpm]": 60 * r["f_4"] / r["N_p"],
                     **{f"{c} (damper)": r[c] for c in ("c_t1", "c_m", "c_t2") if c in r}})
    return pd.DataFrame(rows)
