"""Figures of one steady-state window of samples (docs/physics.md §9.2): efficiency (RMS, mean and
energy-weighted), DTE peak-to-peak and minimum against the half backlash, contact loss, contact
load, and the load-weighted friction coefficient, film thickness and Stribeck ratio."""

import numpy as np

from hypoid.fmu.values import TABLE

PAIRS = tuple(k for k in range(1, 100) if f"pair[{k}].W" in TABLE.variables)  # the tooth pairs
PAIR_FIELDS = ("W", "mu", "h_c", "lambda", "T_c", "g_V", "g_E", "R_e", "R_s")
SCALARS = ("w_p", "DTE", "W_t", "P_loss", "P_in", "eta", "eta_cycle", "P_loss_cycle")
REALS = SCALARS + tuple(f"pair[{k}].{f}" for k in PAIRS for f in PAIR_FIELDS)
INTEGERS = ("contact", "n_impacts")
for _name in REALS + INTEGERS:  # a renamed FMU variable fails here, not in a worker
    TABLE.variable(_name)
MIN_PAIR_LOAD = 1.0  # N: below it a pair counts as out of contact (docs/physics.md §13.14)


def load_weighted(s, field):
    """Sum over pairs and samples of W_k * field_k / sum of W_k, pairs with W_k > 1 N only."""
    num = den = 0.0
    for k in PAIRS:
        w = s[f"pair[{k}].W"]
        on = w > MIN_PAIR_LOAD
        num += float(np.sum(w[on] * s[f"pair[{k}].{field}"][on]))
        den += float(np.sum(w[on]))
    return num / den if den > 0 else float("nan")


def window_metrics(s, half_backlash):
    """Steady-state figures of a window; `s` maps signal names to equal-length arrays."""
    eta, dte, w_t = s["eta"], s["DTE"], s["W_t"]
    p_in = float(np.sum(s["P_in"]))
    contact = s["contact"]
    return {
        "eta_rms": float(np.sqrt(np.mean(eta ** 2))),
        "eta_mean": float(np.mean(eta)),
        "eta_energy": 1.0 - float(np.sum(s["P_loss"])) / p_in if p_in > 0 else float("nan"),
        "eta_min": float(np.min(eta)),
        "eta_cycle_fmu": float(s["eta_cycle"][-1]),
        "P_loss_mean_W": float(np.mean(s["P_loss"])),
        "P_in_mean_W": float(np.mean(s["P_in"])),
        "speed_mean_rpm": float(np.mean(s["w_p"]) * 30.0 / np.pi),
        "DTE_mean_um": float(np.mean(dte) * 1e6),
        "DTE_pp_um": float(np.ptp(dte) * 1e6),
        "DTE_min_um": float(np.min(dte) * 1e6),
        "DTE_max_um": float(np.max(dte) * 1e6),
        "DTE_min_minus_b_um": float((np.min(dte) - half_backlash) * 1e6),
        "contact_loss_fraction": float(np.mean(contact != 1)),
        "back_contact_fraction": float(np.mean(contact == -1)),
        "impacts": int(s["n_impacts"][-1] - s["n_impacts"][0]),
        "W_t_mean_N": float(np.mean(w_t)),
        "W_t_peak_N": float(np.max(w_t)),
        "W_t_min_N": float(np.min(w_t)),
        "W_t_mean_contact_N": float(np.mean(w_t[w_t > 0])) if np.any(w_t > 0) else 0.0,
        "mu_mean": load_weighted(s, "mu"),
        "h_c_mean_um": load_weighted(s, "h_c") * 1e6,
        "lambda_mean": load_weighted(s, "lambda"),
        "T_c_max_C": _max_in_contact(s, "T_c") - 273.15,
    }


def _max_in_contact(s, field):
    values = [s[f"pair[{k}].{field}"][s[f"pair[{k}].W"] > MIN_PAIR_LOAD] for k in PAIRS]
    values = [v for v in values if v.size]
    return float(max(np.max(v) for v in values)) if values else float("nan")


def block_stats(s):
    """Summary of one settling block, for the steady-state test."""
    return {"eta": float(np.mean(s["eta"])), "dte_pp": float(np.ptp(s["DTE"])),
            "dte_mean": float(np.mean(s["DTE"])), "w": float(np.mean(s["w_p"]))}
