"""A gear set of one's own from its design data (a Gleason dimension sheet's, ISO 23509's blank
geometry) through the surrogate tooth contact analysis of docs/physics.md §10, which the paper's
three sets use, here with any set's blank: `hypoid tca design my_gear.toml --out my_set.txt`
writes a layered two-flank gear-set file (both flanks at the loaded surrogate's torque levels)
with the blank the axle's loss ledger needs.

The design file (TOML, one table [gear]; lengths in mm, angles in degrees):

    [gear]
    name = "my axle 41/11"     # optional
    N_p = 11                   # pinion teeth
    N_g = 41                   # ring gear teeth
    b_p_mm = 36.0              # face widths
    b_g_mm = 32.0
    delta_p_deg = 22.5         # pitch angles (= face angles: uniform depth, as the surrogate takes)
    delta_g_deg = 66.5
    beta_p_deg = 45.0          # mean spiral angles
    beta_g_deg = 27.3
    R_e_p_mm = 86.4            # outer cone distances
    R_e_g_mm = 100.7
    offset_mm = 25.0           # hypoid offset
    alpha_n_deg = 20.0         # optional: the surrogate's effective pressure angle (20 deg) only
    hand = "left"              # optional: the pinion's hand of spiral (left or right)

Checked against ISO 23509's relations before anything is written, each failure one line naming
the file, the key and the value: the pitch angles must allow the offset angle in the pitch plane
(tan delta_p tan delta_g < 1, sin delta_p < cos delta_g); the spiral angles must close with it
(beta_p - beta_g = zeta_mp within CLOSURE_DEG); the offset must lie inside the ring's pitch
radius R_e_g sin(delta_g); the mean cone distances from the offset must agree with the outer
cone distances less half the face width (within CONE_TOL); the face widths must be shorter than
the cone distances.

Assumed (docs/physics.md §10, the surrogate's constants, stated in the file it writes): effective
pressure angle 20 deg, working depth 2 m_mn with 70 % on the pinion, 50 um lengthwise ease-off,
the loaded surrogate's profile relief sized at its design torque, the unloaded transmission
error of the paper's sets. Limits: a uniform-depth blank (pitch = face angles), the hand of
spiral does not change the surrogate (a mirror image), and what the surrogate does not model
(tooth form from the cutter, misalignment under load) is missing as for the built-in sets."""

import math
import pathlib

from hypoid import csvtext
from hypoid.tca import surrogate as sur

REQUIRED = ("N_p", "N_g", "b_p_mm", "b_g_mm", "delta_p_deg", "delta_g_deg", "beta_p_deg",
            "beta_g_deg", "R_e_p_mm", "R_e_g_mm", "offset_mm")
OPTIONAL = ("name", "alpha_n_deg", "hand")
CLOSURE_DEG = 0.5   # |beta_p - beta_g - zeta_mp|: Table 1's sets close within 0.09 deg
CONE_TOL = 0.03     # |R_m - (R_e - b/2)| / R_m: Table 1's sets agree within 1.5 %


class DesignError(ValueError):
    """Design data that cannot be a hypoid gear set; the message names file, key and value."""


def _bad(path, key, value, text):
    raise DesignError(f"{path}: {key} = {value!r}: {text}")


def read_design(path):
    """(Blank, name, hand) from a design file, checked (the module's docstring)."""
    data = csvtext.read_toml(path, path, DesignError)
    if set(data) != {"gear"} or not isinstance(data["gear"], dict):
        raise DesignError(f"{path}: one table [gear] expected (found {', '.join(data) or 'none'})")
    g = data["gear"]
    for key, value in g.items():
        if key not in REQUIRED + OPTIONAL:
            _bad(path, key, value, f"unknown key (the keys are {', '.join(REQUIRED + OPTIONAL)})")
    for key in REQUIRED:
        if key not in g:
            raise DesignError(f"{path}: {key} missing (needed: {', '.join(REQUIRED)})")
        v = g[key]
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) \
                or not v > 0:
            _bad(path, key, v, "a positive number is needed")
    for key in ("N_p", "N_g"):
        if g[key] != int(g[key]) or not 3 <= g[key] <= 200:
            _bad(path, key, g[key], "a whole number of teeth, 3 ... 200")
    if g["N_g"] < g["N_p"]:
        _bad(path, "N_g", g["N_g"], f"fewer teeth than the pinion's N_p = {g['N_p']}")
    for key in ("delta_p_deg", "delta_g_deg", "beta_p_deg", "beta_g_deg"):
        if not g[key] < 90:
            _bad(path, key, g[key], "an angle below 90 deg")
    if "alpha_n_deg" in g and abs(g["alpha_n_deg"] - math.degrees(sur.ALPHA_E)) > 1e-6:
        _bad(path, "alpha_n_deg", g["alpha_n_deg"], f"the surrogate takes an effective pressure "
             f"angle of {math.degrees(sur.ALPHA_E):g} deg (docs/physics.md §10.2); another needs "
             "an external TCA (hypoid tca import)")
    if "hand" in g and g["hand"] not in ("left", "right"):
        _bad(path, "hand", g["hand"], "left or right")
    blank = sur._blank((int(g["N_p"]), int(g["N_g"])), (g["b_p_mm"], g["b_g_mm"]),
                       (g["delta_p_deg"], g["delta_g_deg"]), (g["beta_p_deg"], g["beta_g_deg"]),
                       (g["R_e_p_mm"], g["R_e_g_mm"]), g["offset_mm"])
    check_relations(path, blank)
    name = str(g.get("name", pathlib.Path(path).stem))
    return blank, name, g.get("hand", "")


def check_relations(path, bl):
    """ISO 23509's relations between the blank's data (the module's docstring)."""
    t = math.tan(bl.delta_1) * math.tan(bl.delta_2)
    if not t < 1.0 or not math.sin(bl.delta_1) < math.cos(bl.delta_2):
        _bad(path, "delta_g_deg", round(math.degrees(bl.delta_2), 6),
             f"with delta_p = {math.degrees(bl.delta_1):g} deg the pitch cones leave no offset "
             f"angle (tan delta_p tan delta_g = {t:.4g} must be < 1)")
    gs = sur.GearSet(bl)
    zeta = math.degrees(gs.zeta_mp)
    gap = math.degrees(bl.beta_m1 - bl.beta_m2) - zeta
    if abs(gap) > CLOSURE_DEG:
        _bad(path, "beta_g_deg", round(math.degrees(bl.beta_m2), 6),
             f"the spiral angles do not close: beta_p - beta_g = "
             f"{math.degrees(bl.beta_m1 - bl.beta_m2):.3f} deg, the offset angle in the pitch "
             f"plane zeta_mp = {zeta:.3f} deg (ISO 23509: equal within {CLOSURE_DEG:g} deg)")
    r_e2 = bl.R_e2 * math.sin(bl.delta_2)  # the ring's outer pitch radius
    if not bl.a < r_e2 or not 0 < gs.r_m2:
        _bad(path, "offset_mm", round(bl.a * 1e3, 6),
             f"beyond the ring's pitch radius R_e_g sin(delta_g) = {r_e2 * 1e3:.2f} mm")
    for side, R_m, R_e, b in (("p", gs.R_m1, bl.R_e1, bl.b_1), ("g", gs.R_m2, bl.R_e2, bl.b_2)):
        if not b < R_e:
            _bad(path, f"b_{side}_mm", round(b * 1e3, 6), f"not shorter than the outer cone "
                 f"distance R_e_{side} = {R_e * 1e3:g} mm")
        if abs(R_m - (R_e - 0.5 * b)) > CONE_TOL * R_m:
            _bad(path, f"R_e_{side}_mm", round(R_e * 1e3, 6),
                 f"the offset and angles give a mean cone distance of {R_m * 1e3:.2f} mm, the "
                 f"outer cone distance less half the face width {(R_e - 0.5 * b) * 1e3:.2f} mm "
                 f"(ISO 23509: within {100 * CONE_TOL:g} %)")
