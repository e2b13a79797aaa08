"""Fourier series of docs/physics.md §10.7: uniform resampling, smooth fill outside contact, fit, error.

A series over one period of its argument ψ is y(ψ) = mean + Σ_i [sin_i sin(iψ) + cos_i cos(iψ)]
(docs/data-files.md). Samples are taken on the uniform grid ψ_n = 2πn/N, n = 0 … N−1.
"""

import math

import numpy as np
from scipy.interpolate import CubicSpline

from hypoid.tca.gearset_file import CONTACT_SERIES, MAX_HARMONICS, Series

HARMONICS = 8  # k_m, R_p, e_0, ls: the paper's eqs. (1)–(4)
CONTACT_HARMONICS = 32  # R_x … ug_y: with 8, the return across the short no-contact gap leaves
#                         up to 3 % error in contact (gear set 2); 32 leave at most 0.14 %
N_SAMPLES = 768  # samples per period (docs/physics.md §10.7: N ≥ 64): 3·256, so the grids of the three
#                  pairs coincide and Σ ls = 1, ls₀ = 1/3 hold exactly on the samples
ANGLE_EPS = 1e-9  # grid points this close to a contact arc's ends belong to the arc [rad]
END_POINTS = 6  # samples used to estimate value, slope and curvature at each end of a contact arc


def grid(n=N_SAMPLES):
    """The uniform sample angles ψ_n = 2πn/N of one period [rad]."""
    return 2.0 * np.pi * np.arange(n) / n


def fit(y, harmonics):
    """Series with `harmonics` terms from uniform samples y_n over one period (no NaN).

    y_s,i = (2/N) Σ y_n sin(iψ_n), y_c,i = (2/N) Σ y_n cos(iψ_n); coefficients below 1e-12 of the
    largest |y| are set to zero so that exact zeros (e.g. ls at multiples of 3) print as 0.
    """
    y = np.asarray(y, dtype=float)
    if not 0 <= harmonics <= MAX_HARMONICS or len(y) <= 2 * harmonics:
        raise ValueError(f"{harmonics} harmonics need 0..{MAX_HARMONICS} and more than "
                         f"{2 * harmonics} samples per period (have {len(y)})")
    spectrum = np.fft.rfft(y)[1:harmonics + 1] * (2.0 / len(y))
    tiny = 1e-12 * np.max(np.abs(y))
    return Series(float(np.mean(y)), _zero_tiny(-spectrum.imag, tiny),
                  _zero_tiny(spectrum.real, tiny))


def _zero_tiny(c, tiny):
    return np.where(np.abs(c) < tiny, 0.0, c)


def fill_gaps(y):
    """Uniform periodic samples with NaN runs (out of contact) replaced by smooth bridges.

    Each run is bridged by the quintic Hermite polynomial that matches value, slope and curvature
    of the defined samples on both sides (a C² periodic function), so the truncated series stay
    accurate inside contact. The slopes and curvatures come from a local cubic fit over END_POINTS
    samples at each end of the run.
    """
    y = np.array(y, dtype=float)
    gap = np.isnan(y)
    if gap.all():
        raise ValueError("no defined samples")
    n = len(y)
    for start, length in _runs(gap):
        before = (start - 1 - np.arange(END_POINTS)[::-1]) % n
        after = (start + length + np.arange(END_POINTS)) % n
        if np.isnan(y[before]).any() or np.isnan(y[after]).any():
            raise ValueError(f"a defined arc is shorter than {END_POINTS} samples")
        left, right = _end_jet(y[before], at_end=True), _end_jet(y[after], at_end=False)
        t = np.arange(1, length + 1) / (length + 1)
        y[(start + np.arange(length)) % n] = _quintic_hermite(left, right, length + 1, t)
    return y


def _runs(mask):
    """(start, length) of every maximal cyclic run of True in mask (none when all True)."""
    n = len(mask)
    if mask.all():
        return []
    first_false = int(np.argmin(mask))
    runs, start = [], None
    for step in range(1, n + 1):
        i = (first_false + step) % n
        if mask[i] and start is None:
            start = i
        elif not mask[i] and start is not None:
            runs.append((start, (i - start) % n))
            start = None
    return runs


def _end_jet(y, at_end):
    """(value, d/dn, d²/dn²) per sample step at the last (at_end) or first sample of y."""
    x = np.arange(len(y)) - (len(y) - 1 if at_end else 0)
    p = np.polyfit(x, y, 3)
    return np.polyval(p, 0.0), np.polyval(np.polyder(p), 0.0), np.polyval(np.polyder(p, 2), 0.0)


def _quintic_hermite(left, right, h, t):
    """C² bridge over h sample steps at fractions t ∈ (0, 1), from left to right (value, d, d²)."""
    y0, d0, c0 = left[0], left[1] * h, left[2] * h * h
    y1, d1, c1 = right[0], right[1] * h, right[2] * h * h
    t2, t3, t4, t5 = t ** 2, t ** 3, t ** 4, t ** 5
    return (y0 * (1 - 10 * t3 + 15 * t4 - 6 * t5) + d0 * (t - 6 * t3 + 8 * t4 - 3 * t5)
            + c0 * (0.5 * t2 - 1.5 * t3 + 1.5 * t4 - 0.5 * t5)
            + y1 * (10 * t3 - 15 * t4 + 6 * t5) + d1 * (-4 * t3 + 7 * t4 - 3 * t5)
            + c1 * (0.5 * t3 - t4 + 0.5 * t5))


def resample(psi, y, n=N_SAMPLES):
    """Values on grid(n) from samples y(ψ) over one period (ψ ascending, spanning < 2π).

    NaN marks samples where the quantity is undefined (out of contact): each cyclic run of
    defined samples is interpolated by a cubic spline over its own arc, and grid points outside
    every such arc are NaN. A column without NaN is interpolated by a periodic cubic spline.
    """
    psi, y = np.asarray(psi, dtype=float), np.asarray(y, dtype=float)
    psi_grid, out = grid(n), np.full(n, np.nan)
    defined = ~np.isnan(y)
    if defined.all():
        spline = CubicSpline(np.append(psi, psi[0] + 2 * np.pi), np.append(y, y[0]),
                             bc_type="periodic")
        return spline(psi[0] + np.mod(psi_grid - psi[0], 2 * np.pi))
    for start, length in _runs(defined):
        idx = (start + np.arange(length)) % len(y)
        arc = psi[idx] + 2 * np.pi * np.cumsum(np.r_[0, np.diff(idx) < 0])
        at = arc[0] + np.mod(psi_grid - arc[0] + ANGLE_EPS, 2 * np.pi) - ANGLE_EPS
        inside = at <= arc[-1] + ANGLE_EPS
        out[inside] = CubicSpline(arc, y[idx])(at[inside])
    return out


def fit_error(series, psi, y):
    """(max |series − y|, that divided by max |y|) over the defined (non-NaN) samples; a series
    that is zero throughout (the surrogate's vc_x) has the relative error 0 when it is fitted
    exactly."""
    psi, y = np.asarray(psi, dtype=float), np.asarray(y, dtype=float)
    keep = ~np.isnan(y)
    err = float(np.max(np.abs(series(psi[keep]) - y[keep])))
    scale = float(np.max(np.abs(y[keep])))
    return err, err / scale if scale > 0.0 else (0.0 if err == 0.0 else math.inf)


def fit_gearset(samples, harmonics, contact_harmonics):
    """Series from uniform samples over one period of each series (NaN out of contact)."""
    return {key: fit(fill_gaps(y), contact_harmonics if key in CONTACT_SERIES else harmonics)
            for key, y in samples.items()}


def fit_notes(series, checks, where):
    """Per-series comment: harmonics and the fit error against checks {key: (angle, values)}."""
    notes = {}
    for key, s in series.items():
        err, rel = fit_error(s, *checks[key])
        scope = " in contact" if key in CONTACT_SERIES else ""
        notes[key] = (f"{len(s.sin)} harmonics; fit error{scope} at {where}: "
                      f"max {err:.3g} ({rel:.2g} of max |y|)")
    return notes
