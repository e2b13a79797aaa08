"""Result tables of a study: a CSV per table that grows one row at a time as results arrive (so
an interrupted run loses nothing), keyed by a hash of the point's parameters (so a re-run skips
what is done), and a Parquet copy written when a run ends. Traces go to one Parquet per point."""

import csv
import hashlib
import json
import math
import pathlib

import numpy as np
import pandas as pd

KEY = "point_key"
DONE = ("ok",)  # statuses a re-run skips; errors and timeouts are retried
TEXT = {KEY, "sweep_key", "status", "message", "traceback", "trace", "branch",
        "sweep_speeds"}  # columns read as text whatever they look like


def canonical(params):
    """Parameters as a canonical JSON text (sorted keys, floats normalised)."""
    def norm(v):
        if isinstance(v, (np.integer,)):
            return int(v)
        if isinstance(v, (float, np.floating)):
            v = float(v)
            return int(v) if v.is_integer() and abs(v) < 2 ** 53 else float(f"{v:.12g}")
        if isinstance(v, (list, tuple)):
            return [norm(x) for x in v]
        return v
    return json.dumps({k: norm(v) for k, v in sorted(params.items())}, sort_keys=True)


def point_key(params):
    return hashlib.sha1(canonical(params).encode()).hexdigest()[:16]


def _cell(v):
    if isinstance(v, float) and not math.isfinite(v):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    if isinstance(v, (list, tuple, dict)):
        return json.dumps(v)
    return v


class Table:
    """One append-only CSV table plus its Parquet copy."""

    def __init__(self, directory, name):
        self.dir = pathlib.Path(directory)
        self.csv = self.dir / f"{name}.csv"
        self.parquet = self.dir / f"{name}.parquet"

    def header(self):
        if not self.csv.exists() or self.csv.stat().st_size == 0:
            return None
        with self.csv.open(newline="") as fh:
            return next(csv.reader(fh), None)

    def append(self, rows):
        """Appends rows (dicts); widens the file's header when a row brings new columns."""
        if not rows:
            return
        self.dir.mkdir(parents=True, exist_ok=True)
        header = self.header()
        names = list(dict.fromkeys(k for r in rows for k in r))
        if header is None:
            header = names
            with self.csv.open("w", newline="") as fh:
                csv.writer(fh).writerow(header)
        elif not set(names) <= set(header):
            header = header + [n for n in names if n not in header]
            old = self.read()
            old.reindex(columns=header).to_csv(self.csv, index=False)
        with self.csv.open("a", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=header)
            for r in rows:
                w.writerow({k: _cell(v) for k, v in r.items()})

    def read(self):
        if self.header() is None:
            return pd.DataFrame()
        text = {c: str for c in self.header() if c in TEXT or c.endswith("_file")}
        df = pd.read_csv(self.csv, keep_default_na=False, na_values=["nan", ""], dtype=text)
        for c in df.columns:  # empty text cells are empty strings, not NaN
            if not pd.api.types.is_numeric_dtype(df[c]) and not pd.api.types.is_bool_dtype(df[c]):
                df[c] = df[c].fillna("")
        return df

    def done_keys(self, key=KEY):
        df = self.read()
        if df.empty or key not in df:
            return set()
        return set(df.loc[df["status"].isin(DONE), key].astype(str))


def write_tidy(df, stem, order=()):
    """Writes stem.csv and stem.parquet, rows sorted by the `order` columns present."""
    if df.empty:
        return df
    cols = [c for c in order if c in df]
    df = df.sort_values(cols, kind="stable").reset_index(drop=True) if cols else df
    df.to_csv(stem.with_suffix(".csv"), index=False)
    pq = df.copy()
    for c in pq.columns:  # Parquet needs one type per column
        if pq[c].dtype == object or str(pq[c].dtype) in ("str", "string"):
            pq[c] = pq[c].fillna("").astype(str)
    pq.to_parquet(stem.with_suffix(".parquet"), index=False)
    return df


def write_trace(directory, key, params, window):
    """One point's recorded window as Parquet (signals as columns, parameters as metadata)."""
    d = pathlib.Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    df = pd.DataFrame({k: np.asarray(v) for k, v in window.items()})
    df.attrs["params"] = canonical(params)
    path = d / f"{key}.parquet"
    df.to_parquet(path, index=False)
    return path


def read_trace(directory, key):
    path = pathlib.Path(directory) / f"{key}.parquet"
    return pd.read_parquet(path) if path.exists() else None
