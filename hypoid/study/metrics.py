"""Figures of one steady-state window of samples (docs/physics.md §9.2): efficiency (RMS, mean and
energy-weighted), DTE peak-to-peak and minimum against the half backlash, contact loss, contact
load, and the load-weighted friction coefficient, film thickness and Stribeck ratio; with
axle_losses = full, the axle's ledger (every part, the axle efficiency, the oil temperature).

Drive and coast read alike: the working flank is the drive flank when the mesh force W_t is
positive on the mean, the back (coast) flank when it is negative; contact is lost when the teeth
are not on the working flank, and the W_t figures are loads on the working flank (drive: W_t,
coast: -W_t), so a coast point is neither "apart 100 %" nor a negative peak load."""

import numpy as np

from hypoid.fmu.values import TABLE

PAIRS = tuple(k for k in range(1, 100) if f"pair[{k}].W" in TABLE.variables)  # the tooth pairs
PAIR_FIELDS = ("W", "mu", "h_c", "lambda", "T_c", "g_V", "g_E", "R_e", "R_s")
SCALARS = ("w_p", "DTE", "W_t", "P_loss", "P_in", "eta", "eta_cycle", "P_loss_cycle")
AXLE = ("P_axle", "P_in_axle", "P_churn", "P_bearings", "P_seals", "T_oil")  # the ledger's
REALS = SCALARS + AXLE + tuple(f"pair[{k}].{f}" for k in PAIRS for f in PAIR_FIELDS)
# the axle figures of a window (axle_losses = full)
AXLE_FIGURES = ("P_axle_mean_W", "P_in_axle_mean_W", "eta_axle_energy", "P_mesh_mean_W",
                "P_churn_mean_W", "P_bearings_mean_W", "P_seals_mean_W", "T_oil_mean_C")
INTEGERS = ("contact", "n_impacts")
BRIEF = ("w_p", "DTE", "eta")  # what block_stats and the mesh angle read while a point settles
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


def working_flank(s):
    """+1 (drive) or -1 (back flank, coast) from the sign of the mean mesh force."""
    return 1 if float(np.mean(s["W_t"])) >= 0.0 else -1


def axle_metrics(s):
    """The axle's ledger over a window (axle_losses = full): mean powers by part, the axle's
    energy efficiency 1 - sum P_axle / sum P_in_axle, the mean oil temperature."""
    p_in = float(np.sum(s["P_in_axle"]))
    return {"P_axle_mean_W": float(np.mean(s["P_axle"])),
            "P_in_axle_mean_W": float(np.mean(s["P_in_axle"])),
            "eta_axle_energy": 1.0 - float(np.sum(s["P_axle"])) / p_in if p_in > 0
            else float("nan"),
            "P_mesh_mean_W": float(np.mean(s["P_loss"])),
            "P_churn_mean_W": float(np.mean(s["P_churn"])),
            "P_bearings_mean_W": float(np.mean(s["P_bearings"])),
            "P_seals_mean_W": float(np.mean(s["P_seals"])),
            "T_oil_mean_C": float(np.mean(s["T_oil"])) - 273.15}


def window_metrics(s, half_backlash, axle=False):
    """Steady-state figures of a window; `s` maps signal names to equal-length arrays; `axle`:
    the point runs the whole axle (axle_losses = full), its ledger is added."""
    eta, dte = s["eta"], s["DTE"]
    p_in = float(np.sum(s["P_in"]))
    contact = s["contact"]
    flank = working_flank(s)
    w_t = flank * s["W_t"]  # the load on the working flank
    row = {
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
        "flank": "drive" if flank == 1 else "coast",
        "contact_loss_fraction": float(np.mean(contact != flank)),
        "apart_fraction": float(np.mean(contact == 0)),
        "other_flank_fraction": float(np.mean(contact == -flank)),
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
    if axle:
        row.update(axle_metrics(s))
    return row


def _max_in_contact(s, field):
    values = [s[f"pair[{k}].{field}"][s[f"pair[{k}].W"] > MIN_PAIR_LOAD] for k in PAIRS]
    values = [v for v in values if v.size]
    return float(max(np.max(v) for v in values)) if values else float("nan")


def block_stats(s):
    """Summary of one settling block, for the steady-state test."""
    return {"eta": float(np.mean(s["eta"])), "dte_pp": float(np.ptp(s["DTE"])),
            "dte_mean": float(np.mean(s["DTE"])), "w": float(np.mean(s["w_p"]))}
