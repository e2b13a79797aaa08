"""Gear-set files from the surrogate TCA of the paper's gear sets (docs/physics.md §10), one
series or both flanks at several torques (§10.8), the same for a design of one's own
(hypoid/tca/design.py), and the surrogate written as a TCA table. The command is `hypoid tca`
(hypoid/cli/tca.py)."""

import csv
import math
import os

import numpy as np

from hypoid.tca import loaded as tl
from hypoid.tca import surrogate as sur
from hypoid.tca.gearset_file import (MAX_HARMONICS, MAX_LEVELS, MESH_SERIES, PAIR_SERIES, UNITS,
                                 Gearset, write_gearset)
from hypoid.tca.fit import (CONTACT_HARMONICS, HARMONICS, N_SAMPLES, fit, fit_error, fit_gearset,
                            fit_notes, grid)
from hypoid.tca.table import DATA_COLUMNS, POINT_COLUMNS


# --- surrogate ---------------------------------------------------------------------------------

def surrogate_samples(gs, angle):
    """Every series of the surrogate at `angle` (θ for the mesh series, ψ for the pair series)."""
    samples = {"k_m": sur.k_m(gs, angle), "R_p": sur.R_p(gs, angle), "e_0": sur.e_0(angle),
               "ls": sur.pair_load_share(gs, angle)}
    samples.update(sur.pair_contact(gs, angle))
    return samples


def surrogate(set_no, harmonics=HARMONICS, contact_harmonics=CONTACT_HARMONICS):
    """The gear set `set_no` of the paper's Table 1 through the surrogate TCA."""
    gs = sur.GearSet(sur.TABLE_1[set_no])
    series = fit_gearset(surrogate_samples(gs, grid()), harmonics, contact_harmonics)
    off_grid = grid() + math.pi / N_SAMPLES
    checks = {key: (off_grid, y) for key, y in surrogate_samples(gs, off_grid).items()}
    name = f"Paouris et al. 2016 gear set {set_no} ({gs.blank.N_p}/{gs.blank.N_g}), surrogate TCA"
    comments = _surrogate_comments(set_no, gs, harmonics, contact_harmonics)
    notes = fit_notes(series, checks, f"{N_SAMPLES} off-grid points vs the unfitted surrogate")
    return Gearset(name, gs.blank.N_p, gs.blank.N_g, series, comments, notes)


def _surrogate_comments(set_no, gs, harmonics, contact_harmonics):
    bl, deg, mm = gs.blank, math.degrees, 1e3
    return [
        f"Gear set {set_no} of Paouris et al., PMC 2016, Table 1, through the surrogate tooth",
        "contact analysis of docs/physics.md §10. Written by `hypoid tca surrogate`:",
        "regenerate with `hypoid tca surrogate --all --out-dir resources/gearsets`, do not edit.",
        "Units SI (m, N/m, rad); series format in docs/data-files.md.",
        "",
        f"Table 1: N {bl.N_p}/{bl.N_g}; face width {bl.b_1 * mm:.2f}/{bl.b_2 * mm:.2f} mm; "
        f"pitch = face angle {deg(bl.delta_1):.2f}/{deg(bl.delta_2):.2f} deg;",
        f"  mean spiral angle {deg(bl.beta_m1):.2f}/{deg(bl.beta_m2):.2f} deg; outer cone distance "
        f"{bl.R_e1 * mm:.2f}/{bl.R_e2 * mm:.2f} mm; offset {bl.a * mm:.1f} mm",
        f"Blank (§10.1): zeta_mp {deg(gs.zeta_mp):.2f} deg, zeta_m {deg(gs.zeta_m):.2f} deg, "
        f"r_m1/r_m2 {gs.r_m1 * mm:.2f}/{gs.r_m2 * mm:.2f} mm,",
        f"  R_m1/R_m2 {gs.R_m1 * mm:.2f}/{gs.R_m2 * mm:.2f} mm, m_mn {gs.m_mn * mm:.3f} mm",
        f"ISO 10300 virtual gears (§10.2): alpha_lim {deg(gs.alpha_lim):.2f} deg, alpha_nD "
        f"{deg(gs.alpha_nD):.2f} deg, beta_v {deg(gs.beta_v):.2f} deg,",
        f"  beta_vb {deg(gs.beta_vb):.2f} deg, beta_B {deg(gs.beta_B):.2f} deg, eps_va "
        f"{gs.eps_va:.3f}, eps_vb {gs.eps_vb:.3f}, eps_vg {gs.eps_vg:.3f},",
        f"  b_v,eff {gs.b_veff * mm:.2f} mm, rho_t/rho_rel {gs.rho_t * mm:.2f}/"
        f"{gs.rho_rel * mm:.2f} mm, ISO normal stiffness k_n {gs.k_n:.3g} N/m (upper bound)",
        f"Lever arms (§8.2): R_p0/R_g0 {gs.R_p0 * mm:.3f}/{gs.R_p0 * gs.u * mm:.3f} mm; "
        f"k_m0 {gs.k_m0:.4g} N/m from k_m0 R_p0^2 = {sur.KM_RP2:.3g} N m/rad (§8.4)",
        f"Path (§10.4, §10.5): eps_TCA {gs.eps_TCA:.3f}, roll s {gs.s_roll[0] * mm:.2f} .. "
        f"{gs.s_roll[1] * mm:.2f} mm, R_y {gs.R_y:.3f} m",
        f"Assumed: alpha_e {deg(sur.ALPHA_E):g} deg, h_mw {sur.H_MW:g} m_mn with "
        f"{100 * sur.PINION_DEPTH_SHARE:.0f} % on the pinion, b_2,eff {sur.B2_EFF:g} b_2,",
        f"  bump sin^2(pi xi), lengthwise travel {sur.TRAVEL:g} b_2 from heel to toe,",
        f"  ease-off {sur.DELTA_END * 1e6:.0f} um, e_0 = {sur.E0_SIN[0] * 1e6} um sin(theta) + "
        f"{sur.E0_SIN[1] * 1e6} um sin(2 theta)",
        f"Fit (§10.7): {N_SAMPLES} samples per period, {harmonics} harmonics for k_m, R_p, e_0, ls "
        f"and {contact_harmonics} for the contact series,",
        "  which are bridged outside contact by a C2 quintic (see each series for its fit error);",
        "  trailing harmonics that are exactly zero are not written.",
    ]


# --- loaded surrogate: both flanks at several torques (docs/physics.md §10.8) -------------------

LEVEL_LOAD_PASSES = 3  # fixed-point passes of a level's load on its own mean contact radius


def level_mesh(model, torque, n_cycle=N_SAMPLES // 3):
    """The loaded mesh of one flank at the normal load the FMU transmits at a pinion torque:
    W = torque / mean R_p, the mean of the load-shared contact radius R_p(θ) that the level
    writes (the FMU's levels are torques of |W_t| R_p; docs/physics.md §10.8, "In the FMU").
    R_p depends on the load shares, so a fixed point from W = torque / R_p0. Returns the mesh and
    R_p(θ)."""
    gs, T = model.gs, torque
    for _ in range(LEVEL_LOAD_PASSES):
        m = tl.loaded_mesh(model, T, n_theta=n_cycle)
        xi = sur.xi_pairs(gs, m.theta)
        R_p = (m.shares * gs.R_p0 * (1.0 + sur.lengthwise_position(gs, xi) / gs.R_m1)).sum(axis=0)
        T = torque * gs.R_p0 / R_p.mean()
    return m, R_p


def loaded_samples(model, torque, n_cycle=N_SAMPLES // 3):
    """Samples of one flank at one pinion torque: k_m and R_p at n_cycle mesh angles θ of one
    cycle, the pair series at the 3 n_cycle angles ψ of grid(3 n_cycle), and the unloaded e_u.
    k_m is the secant W/(δ − e_u) at the level's load (level_mesh), the static point through
    which the FMU's force law passes."""
    gs, (m, R_p) = model.gs, level_mesh(model, torque, n_cycle)
    samples = {"k_m": m.k_m, "R_p": R_p,
               "ls": m.shares.reshape(-1)}  # pair 1 at ψ_k is pair k // n of θ_(k mod n)
    samples.update(sur.pair_contact(gs, grid(3 * n_cycle)))
    return samples, m.e_u


def loaded_surrogate(set_no, torques=tl.TORQUES, harmonics=CONTACT_HARMONICS,
                     contact_harmonics=CONTACT_HARMONICS, blank=None, name=None):
    """A layered gear-set file of set `set_no` (or of `blank`, a design of one's own, with its
    `name`): drive and coast flanks at each pinion torque. The loaded series change steeply where
    a pair starts to carry load, so k_m, R_p and ls take as many harmonics as the contact series
    by default."""
    if not 1 <= len(torques) <= MAX_LEVELS or any(b <= a for a, b in zip(torques, torques[1:])):
        raise ValueError(f"--torques: 1 to {MAX_LEVELS} increasing values, not {list(torques)}")
    own = blank is not None
    blank, layers, notes, reliefs = blank if own else sur.TABLE_1[set_no], {}, {}, []
    for flank in tl.FLANKS:
        model = tl.LoadedFlank(tl.flank_set(blank, flank))
        reliefs.append(f"{model.C_a * 1e6:.2f}")
        for level, torque in enumerate(torques, 1):
            samples, e_u = loaded_samples(model, torque)
            layers[(flank, level)] = fit_gearset(samples, harmonics, contact_harmonics)
            for key, s in layers[(flank, level)].items():
                angle = grid(len(samples[key]))
                err, rel = fit_error(s, angle, samples[key])
                notes[f"{flank}.{level}.{key}"] = (f"{len(s.sin)} harmonics; fit error at the "
                                                   f"{len(angle)} samples: max {err:.3g} ({rel:.2g})")
            if flank == "drive" and level == 1:
                e_0 = fit(e_u, harmonics)
    gs = sur.GearSet(blank)
    relief_amounts = "/".join(reliefs)
    relief_lengths = f"{model.xi_relief * (gs.s_roll[1] - gs.s_roll[0]) * 1e3:.2f}"
    name = (f"{name} ({blank.N_p}/{blank.N_g}), loaded surrogate TCA, drive and coast" if own
            else f"Paouris et al. 2016 gear set {set_no} ({blank.N_p}/{blank.N_g}), loaded "
            "surrogate TCA, drive and coast")
    head = ([f"Gear set {name} from its design data through the surrogate tooth contact analysis",
             "of docs/physics.md §10 (hypoid tca design; assumptions in hypoid/tca/design.py)."]
            if own else _surrogate_comments(set_no, gs, harmonics, contact_harmonics)[:2])
    comments = head + [
        ("regenerate with `hypoid tca design`, do not edit." if own else
         "regenerate with `hypoid tca surrogate --all --loaded --out-dir resources/gearsets/loaded`,"
         " do not edit."), "Units SI (m, N/m, rad); series format in docs/data-files.md.",
        *([line.replace("Table 1:", "Design data:") for line in
           _surrogate_comments(set_no, gs, harmonics, contact_harmonics)[5:-4]] if own else []),
        "", "Loaded tooth contact (§10.8): secant k_m at W = torque/mean R_p, load shares, R_p per level, both",
        "  flanks (coast: alpha_nC = alpha_e - alpha_lim); e_0 the unloaded transmission error; lengthwise "
        f"ease-off {sur.DELTA_END * 1e6:g} um;",
        f"  tip/root relief C_a (t/L)^{tl.RELIEF_EXPONENT:g} over L = {relief_lengths} mm of roll, C_a "
        f"{relief_amounts} um (drive/coast) = the deflection at {tl.DESIGN_TORQUE:g} N m."]
    return Gearset(name, blank.N_p, blank.N_g, {"e_0": e_0}, comments, notes,
                   torque_levels=tuple(float(t) for t in torques), flanks=tl.FLANKS,
                   layers=layers)


# --- surrogate as a TCA table ---------------------------------------------------------------------

def export_csv(set_no, path, speed_rpm=2000.0, rows=360):
    """Writes the surrogate of gear set `set_no` as a TCA table (one period, `rows` rows)."""
    if rows < 1 or not speed_rpm > 0:
        raise ValueError(f"export needs rows >= 1 and a positive speed (have {rows}, {speed_rpm})")
    gs = sur.GearSet(sur.TABLE_1[set_no])
    N_p, N_g = gs.blank.N_p, gs.blank.N_g
    phi = np.arange(rows) * (6.0 * math.pi / N_p) / rows  # pinion angle [rad]
    theta = N_p * phi
    psi = theta / 3.0
    omega_p = speed_rpm * math.pi / 30.0
    s, inside = sur.pair_roll(gs, psi)
    omega_g = omega_p * N_p / N_g
    r_px, r_gx = sur.x_radii(gs, s)
    r_y = np.full_like(s, 2e3 * gs.R_y)  # [mm]
    (up_x, up_y), (ug_x, ug_y) = sur.surface_velocities(gs, s)
    vc_x, vc_y = (v * omega_p for v in sur.contact_point_velocity(gs))
    contact = {"r_px_mm": r_px * 1e3, "r_py_mm": r_y, "r_gx_mm": r_gx * 1e3, "r_gy_mm": r_y,
               "up_x_m_s": up_x * omega_p - vc_x, "up_y_m_s": up_y * omega_p - vc_y,
               "ug_x_m_s": ug_x * omega_g - vc_x, "ug_y_m_s": ug_y * omega_g - vc_y,
               "vc_x_m_s": np.full_like(s, vc_x), "vc_y_m_s": np.full_like(s, vc_y)}
    columns = {"phi_p_deg": np.degrees(phi), "k_m_N_per_m": sur.k_m(gs, theta),
               "R_p_mm": sur.R_p(gs, theta) * 1e3, "e_0_um": sur.e_0(theta) * 1e6,
               "ls": sur.pair_load_share(gs, psi)}
    columns.update({name: np.where(inside, v, np.nan) for name, v in contact.items()})
    with open(path, "w", newline="", encoding="utf-8") as f:
        f.write(f"# Gear set {set_no} of the paper's Table 1: surrogate TCA of docs/physics.md §10\n"
                "# written by `hypoid tca export-csv`.\n"
                "# r_py_mm = r_gy_mm = 2 R_y: the surrogate defines only the reduced radius R_y.\n")
        out = csv.writer(f, lineterminator="\n")
        for key, value in (("name", f"Gear set {set_no} surrogate (exported table)"), ("N_p", N_p),
                           ("N_g", N_g), ("speed_rpm", f"{speed_rpm:g}")):
            out.writerow([key, value])
        header = ["phi_p_deg"] + DATA_COLUMNS + list(POINT_COLUMNS)
        out.writerow(header)
        for row in np.array([columns[name] for name in header]).T:
            out.writerow(["" if math.isnan(v) else f"{v:.10g}" for v in row])


# --- a design of one's own -----------------------------------------------------------------------

def design_gearset(path, torques=tl.TORQUES, harmonics=CONTACT_HARMONICS):
    """The layered two-flank gear-set file of a design file (hypoid/tca/design.py), with its
    ledger blank."""
    from hypoid.tca.design import read_design

    blank, name, hand = read_design(path)
    gs = loaded_surrogate(None, tuple(torques), harmonics, harmonics, blank=blank, name=name)
    if hand:
        gs.comments.append(f"Pinion hand of spiral {hand} (the surrogate is the same for either).")
    gs.blank = sur.blank_of(blank)
    return gs
