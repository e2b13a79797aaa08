"""Lubrication-regime map (paper Fig. 5) with the substitute of docs/physics.md §7: Hamrock-Dowson
film parameters of the four regimes (isoviscous/piezoviscous x rigid/elastic) as functions of
g_V = G W^3/U^2 and g_E = W^(8/3)/U^2; a point belongs to the regime whose formula gives the
thickest film (the boundaries are where adjacent formulas are equal). Diagnostic only."""

import numpy as np

REGIMES = ("IR", "PR", "IE", "PE")
NAMES = {"IR": "isoviscous rigid", "PR": "piezoviscous rigid", "IE": "isoviscous elastic",
         "PE": "piezoviscous elastic (hard EHL)"}


def ellipticity(alpha_r):
    """k from the radius ratio alpha_r = R_y/R_x (Hamrock & Brewe approximation)."""
    return 1.0339 * np.asarray(alpha_r, float) ** 0.636


def film_parameters(g_v, g_e, alpha_r):
    """The four regimes' dimensionless film parameters g_H (docs/physics.md §7), stacked."""
    g_v, g_e = np.asarray(g_v, float), np.asarray(g_e, float)
    a = np.asarray(alpha_r, float)
    k = ellipticity(a)
    phi = 1.0 / (1.0 + 2.0 / (3.0 * a))
    ir = 128.0 * a * phi ** 2 * (0.131 * np.arctan(a / 2.0) + 1.683) ** 2
    pr = 1.66 * g_v ** (2.0 / 3.0) * (1.0 - np.exp(-0.68 * k))
    ie = 8.70 * g_e ** 0.67 * (1.0 - 0.85 * np.exp(-0.31 * k))
    pe = 3.42 * g_v ** 0.49 * g_e ** 0.17 * (1.0 - np.exp(-0.68 * k))
    return np.stack(np.broadcast_arrays(ir, pr, ie, pe))


def classify(g_v, g_e, alpha_r):
    """Index into REGIMES of each point (the thickest-film regime); -1 where undefined."""
    h = film_parameters(g_v, g_e, alpha_r)
    idx = np.argmax(np.nan_to_num(h, nan=-np.inf), axis=0)
    bad = ~np.all(np.isfinite(h), axis=0) | ~(np.asarray(g_v) > 0) | ~(np.asarray(g_e) > 0)
    return np.where(bad, -1, idx)


def pair_samples(trace, min_load=1.0):
    """Flattened (g_V, g_E, alpha_r, W) of the pairs in contact over a trace."""
    cols = {"g_V": [], "g_E": [], "alpha_r": [], "W": []}
    for k in (1, 2, 3):
        w = np.asarray(trace[f"pair[{k}].W"])
        on = w > min_load
        cols["g_V"].append(np.asarray(trace[f"pair[{k}].g_V"])[on])
        cols["g_E"].append(np.asarray(trace[f"pair[{k}].g_E"])[on])
        cols["W"].append(w[on])
        if f"pair[{k}].R_s" in trace:
            cols["alpha_r"].append(np.asarray(trace[f"pair[{k}].R_s"])[on]
                                   / np.asarray(trace[f"pair[{k}].R_e"])[on])
    out = {k: np.concatenate(v) if v else np.array([]) for k, v in cols.items()}
    if out["alpha_r"].size == 0:
        out["alpha_r"] = np.full(out["W"].shape, np.nan)
    return out
