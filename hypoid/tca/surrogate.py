"""Surrogate tooth contact analysis (docs/physics.md §10) for the gear sets of the paper's Table 1.

Section numbers (§) refer to docs/physics.md. Lengths in m, angles in rad unless a name says
otherwise. The mesh angle is θ = N_p φ_p; the tooth-pair functions take ψ = θ/3 for pair 1
(ψ_k = (θ + 2π(k−1))/3 for pair k), so one period of ψ is three mesh cycles (docs/data-files.md).
"""

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

ALPHA_E = math.radians(20.0)  # effective pressure angle α_e [rad] (§10.2, ASSUMED)
H_MW = 2.0  # mean working depth h_mw / m_mn (§10.2, ASSUMED)
PINION_DEPTH_SHARE = 0.7  # h_am1 = 0.7 h_mw, h_am2 = 0.3 h_mw (§10.2, ASSUMED)
B2_EFF = 0.85  # effective face width b_2,eff / b_2 (§10.2)
C_GAMMA = 2.0e10  # ISO 10300 Method B mesh stiffness per face width, 20 N/(mm·µm), C_F = 1 [N/m²]
KM_RP2 = 7.55e4  # calibrated invariant k_m,0 R_p0² [N·m/rad] (§8.4)
DELTA_END = 50e-6  # lengthwise ease-off at the face ends δ_end [m] (§10.4, ASSUMED)
TRAVEL = 0.5  # lengthwise travel of the contact across the engagement / b_2 (§10.6, ASSUMED),
#                from the leading end of the face (the heel) to the trailing end (§10.4, derived)
E0_SIN = (1.5e-6, 0.3e-6)  # unloaded STE: sine amplitudes of θ and 2θ [m] (§10.6, ASSUMED)
EPS_TCA_RANGE = (2.0, 2.9)  # clamp of the engagement length in mesh periods (§10.5)


@dataclass(frozen=True)
class Blank:
    """One gear set of the paper's Table 1 (index 1 pinion, 2 ring gear)."""

    N_p: int
    N_g: int
    b_1: float  # face widths [m]
    b_2: float
    delta_1: float  # pitch angles = face angles (uniform depth) [rad]
    delta_2: float
    beta_m1: float  # mean spiral angles [rad]
    beta_m2: float
    R_e1: float  # outer cone distances [m]
    R_e2: float
    a: float  # hypoid offset [m]


def _blank(teeth, b_mm, delta_deg, beta_deg, R_e_mm, a_mm):
    mm, deg = 1e-3, math.radians
    return Blank(*teeth, b_mm[0] * mm, b_mm[1] * mm, deg(delta_deg[0]), deg(delta_deg[1]),
                 deg(beta_deg[0]), deg(beta_deg[1]), R_e_mm[0] * mm, R_e_mm[1] * mm, a_mm * mm)


TABLE_1 = {
    1: _blank((13, 36), (33.85, 30.00), (29.05, 59.65), (46.0, 27.60), (83.08, 95.60), 24.0),
    2: _blank((15, 41), (40.76, 38.20), (27.77, 61.60), (40.0, 26.96), (95.63, 112.53), 20.0),
    3: _blank((12, 41), (39.38, 36.50), (22.74, 66.70), (40.0, 26.62), (92.42, 107.80), 20.0),
}


def ledger_blank(n):
    """The gear blank the FMU's loss ledger needs (gear-set file keys blank.*, m and rad) of
    Table 1's set n: ring pitch diameter 2 R_e2 sin(delta_2), ring face width b_2, mean pitch
    radii (§10.1's closed form), pitch and mean spiral angles."""
    return blank_of(TABLE_1[n])


def blank_of(bl):
    """ledger_blank's values of any Blank."""
    g = GearSet(bl)
    return {"ring_d": 2.0 * bl.R_e2 * math.sin(bl.delta_2), "ring_b": bl.b_2, "r_m_p": g.r_m1,
            "r_m_g": g.r_m2, "delta_p": bl.delta_1, "delta_g": bl.delta_2, "beta_p": bl.beta_m1,
            "beta_g": bl.beta_m2}


@dataclass(frozen=True)
class GearSet:
    """Derived geometry (§10.1–10.5) of one Table 1 gear set; every quantity computed on demand."""

    blank: Blank

    # --- §10.1 blank geometry -------------------------------------------------------------
    @cached_property
    def u(self):
        return self.blank.N_g / self.blank.N_p

    @cached_property
    def zeta_mp(self):  # pinion offset angle in the pitch plane [rad]
        bl = self.blank
        return math.acos(math.tan(bl.delta_1) * math.tan(bl.delta_2))

    @cached_property
    def zeta_m(self):  # offset angle in the wheel axial plane [rad]
        return math.acos(math.sin(self.blank.delta_1) / math.cos(self.blank.delta_2))

    @cached_property
    def r_m2(self):  # mean pitch radius of the gear [m], closed form
        bl = self.blank
        rho = math.cos(bl.beta_m2) / (self.u * math.cos(bl.beta_m1))
        return bl.a / (math.sin(self.zeta_m)
                       * (1.0 + rho * math.cos(bl.delta_2) / math.cos(bl.delta_1)))

    @cached_property
    def r_m1(self):  # equal normal pitch: r_m2 cos β_m2 = u r_m1 cos β_m1 [m]
        bl = self.blank
        return self.r_m2 * math.cos(bl.beta_m2) / (self.u * math.cos(bl.beta_m1))

    @cached_property
    def R_m1(self):  # mean cone distances [m]
        return self.r_m1 / math.sin(self.blank.delta_1)

    @cached_property
    def R_m2(self):
        return self.r_m2 / math.sin(self.blank.delta_2)

    @cached_property
    def m_mn(self):  # mean normal module [m]
        return 2.0 * self.r_m1 * math.cos(self.blank.beta_m1) / self.blank.N_p

    # --- §10.2 ISO 10300-1 Annex A virtual cylindrical gears --------------------------------
    @cached_property
    def alpha_lim(self):  # limit pressure angle [rad]
        bl = self.blank
        t1, t2 = math.tan(bl.delta_1), math.tan(bl.delta_2)
        lead = self.R_m1 * math.sin(bl.beta_m1) - self.R_m2 * math.sin(bl.beta_m2)
        return -math.atan(t1 * t2 / math.cos(self.zeta_mp) * lead
                          / (self.R_m1 * t1 + self.R_m2 * t2))

    @cached_property
    def alpha_nD(self):  # drive-flank normal pressure angle [rad]
        return ALPHA_E + self.alpha_lim

    @cached_property
    def beta_v(self):  # virtual spiral angle [rad]
        return 0.5 * (self.blank.beta_m1 + self.blank.beta_m2)

    @cached_property
    def alpha_vet(self):  # virtual transverse pressure angle [rad]
        return math.atan(math.tan(ALPHA_E) / math.cos(self.beta_v))

    @cached_property
    def beta_vb(self):  # virtual base spiral angle [rad]
        return math.asin(math.sin(self.beta_v) * math.cos(ALPHA_E))

    @cached_property
    def beta_B(self):  # inclination of the contact line on the flank [rad]
        return math.atan(math.tan(self.beta_v) * math.sin(ALPHA_E))

    @cached_property
    def h_am(self):  # mean addenda (pinion, gear) [m]
        h_mw = H_MW * self.m_mn
        return PINION_DEPTH_SHARE * h_mw, (1.0 - PINION_DEPTH_SHARE) * h_mw

    @cached_property
    def g_va(self):  # length of the path of contact of the virtual gears [m]
        bl, a = self.blank, self.alpha_vet
        total = 0.0
        for r_m, delta, h_am in ((self.r_m1, bl.delta_1, self.h_am[0]),
                                 (self.r_m2, bl.delta_2, self.h_am[1])):
            d_v = 2.0 * r_m / math.cos(delta)
            d_vb, d_va = d_v * math.cos(a), d_v + 2.0 * h_am  # base and tip diameters
            total += math.sqrt(d_va ** 2 - d_vb ** 2) - d_v * math.sin(a)
        return 0.5 * total

    @cached_property
    def eps_va(self):  # transverse contact ratio
        p_vet = math.pi * self.m_mn * math.cos(self.alpha_vet) / math.cos(self.beta_v)
        return self.g_va / p_vet

    @cached_property
    def b_veff(self):  # effective face width of the virtual gears [m]
        half = 0.5 * self.zeta_mp
        theta_mp = math.atan(math.sin(self.blank.delta_2) * math.tan(self.zeta_m))
        gamma = theta_mp - half
        return ((B2_EFF * self.blank.b_2 / math.cos(half)
                 - self.g_va * math.cos(self.alpha_vet) * math.tan(half))
                / (1.0 - math.tan(gamma) * math.tan(half)))

    @cached_property
    def eps_vb(self):  # face contact ratio
        return self.b_veff * math.sin(self.beta_v) / (math.pi * self.m_mn)

    @cached_property
    def eps_vg(self):  # total contact ratio
        return self.eps_va + self.eps_vb

    @cached_property
    def rho_t(self):  # relative radius of profile curvature at the mean point [m]
        bl, a_n = self.blank, self.alpha_nD
        cone = (math.cos(bl.beta_m1) * math.cos(bl.beta_m2) / math.cos(self.zeta_mp)
                * (1.0 / (self.R_m2 * math.tan(bl.delta_2))
                   + 1.0 / (self.R_m1 * math.tan(bl.delta_1))))
        flank = (math.cos(a_n) * (math.tan(a_n) - math.tan(self.alpha_lim))
                 + math.tan(self.zeta_mp) * math.tan(self.beta_B))
        return flank / cone

    @cached_property
    def rho_rel(self):  # relative radius across the contact line = R_x at the mean point [m]
        return self.rho_t * math.cos(self.beta_B) ** 2

    @cached_property
    def k_n(self):  # ISO normal mesh stiffness, an upper bound (§10.3) [N/m]
        return C_GAMMA * self.b_veff / math.cos(self.beta_vb) ** 2

    # --- §8.2, §8.4, §10.3–10.5 surrogate quantities ------------------------------------------
    @cached_property
    def R_p0(self):  # moment arm of the normal force about the pinion axis [m] (D4 of docs/physics.md §0)
        return self.r_m1 * math.cos(self.alpha_nD) * math.cos(self.blank.beta_m1)

    @cached_property
    def k_m0(self):  # calibrated mean mesh stiffness [N/m]
        return KM_RP2 / self.R_p0 ** 2

    @cached_property
    def eps_TCA(self):  # engagement length in mesh periods
        return min(max(self.eps_vg, EPS_TCA_RANGE[0]), EPS_TCA_RANGE[1])

    @cached_property
    def r_vn(self):  # normal-section virtual pitch radii (Tredgold × Euler) [m]
        bl = self.blank
        return (self.r_m1 / (math.cos(bl.delta_1) * math.cos(bl.beta_m1) ** 2),
                self.r_m2 / (math.cos(bl.delta_2) * math.cos(bl.beta_m2) ** 2))

    @cached_property
    def s_roll(self):  # roll limits (approach, recess) from the pitch point [m], approach < 0
        a = self.alpha_nD

        def reach(r_vn, h_am):
            return math.sqrt((r_vn + h_am) ** 2 - (r_vn * math.cos(a)) ** 2) - r_vn * math.sin(a)
        return -reach(self.r_vn[1], self.h_am[1]), reach(self.r_vn[0], self.h_am[0])

    @cached_property
    def R_y(self):  # reduced radius along the major axis from the lengthwise ease-off [m]
        return (0.5 * self.blank.b_2) ** 2 / (2.0 * DELTA_END)


def bump(xi):
    """Pair stiffness and load shape w(ξ) = sin²(πξ) on 0 ≤ ξ ≤ 1, zero outside."""
    xi = np.asarray(xi, dtype=float)
    return np.where((xi >= 0.0) & (xi <= 1.0), np.sin(np.pi * xi) ** 2, 0.0)


def xi_pairs(gs, theta):
    """Engagement coordinates ξ_j = (θ/2π + j)/ε_TCA, j = 0, 1, 2, of the pairs at mesh angle θ."""
    cycle = np.mod(np.asarray(theta, dtype=float), 2.0 * np.pi) / (2.0 * np.pi)
    return np.stack([(cycle + j) / gs.eps_TCA for j in range(3)])


def load_shares(gs, theta):
    """Load share of each pair, ls_j = w(ξ_j) / Σ_i w(ξ_i) (equal deflection, parallel springs)."""
    w = bump(xi_pairs(gs, theta))
    return w / w.sum(axis=0)


def k_m(gs, theta):
    """Total mesh stiffness [N/m], Σ_j k_peak w(ξ_j), k_peak = 2 k_m0/ε_TCA (mean Σw = ε/2)."""
    return 2.0 * gs.k_m0 / gs.eps_TCA * bump(xi_pairs(gs, theta)).sum(axis=0)


def lengthwise_position(gs, xi):
    """Cone distance of the contact from the mean point [m] (heel > 0) at engagement ξ:
    y = (½ − ξ) TRAVEL b_2, from the heel, the end of the face that meshes first, to the toe
    (docs/physics.md §10.4, §10.6)."""
    return (0.5 - np.asarray(xi, dtype=float)) * TRAVEL * gs.blank.b_2


def R_p(gs, theta):
    """Contact radius [m], Σ_j ls_j R_p0 (1 + y_j/R_m1) with y_j = lengthwise_position(ξ_j)."""
    y = lengthwise_position(gs, xi_pairs(gs, theta))
    return gs.R_p0 * (load_shares(gs, theta) * (1.0 + y / gs.R_m1)).sum(axis=0)


def e_0(theta):
    """Unloaded static transmission error along the line of action [m]."""
    theta = np.asarray(theta, dtype=float)
    return E0_SIN[0] * np.sin(theta) + E0_SIN[1] * np.sin(2.0 * theta)


def pair_xi(gs, psi):
    """Engagement coordinate ξ of pair 1 at ψ = θ/3 (period 2π: 3 mesh cycles); > 1: no contact."""
    return 3.0 * np.mod(np.asarray(psi, dtype=float), 2.0 * np.pi) / (2.0 * np.pi * gs.eps_TCA)


def pair_load_share(gs, psi):
    """Load share of pair 1 at ψ (zero out of contact)."""
    theta = 3.0 * np.asarray(psi, dtype=float)
    return bump(pair_xi(gs, psi)) / bump(xi_pairs(gs, theta)).sum(axis=0)


def roll(gs, xi):
    """Roll distance s(ξ) from the pitch point [m], linear from approach (ξ = 0) to recess (1)."""
    s_a, s_r = gs.s_roll
    return s_a + np.asarray(xi, dtype=float) * (s_r - s_a)


def profile_radii(gs, s):
    """Profile radii of pinion and gear [m]: ρ_1 = r_vn1 sin α_nD + s, ρ_2 = r_vn2 sin α_nD − s."""
    sin_a = math.sin(gs.alpha_nD)
    return gs.r_vn[0] * sin_a + s, gs.r_vn[1] * sin_a - s


def x_radii(gs, s):
    """Pinion and gear radii along the minor axis [m]: the profile radii scaled so that their
    reduced radius at the pitch point is ρ_rel (R_x(s) = ρ_rel R_inv(s)/R_inv(0), §10.4)."""
    scale = gs.rho_rel / reduced(*profile_radii(gs, 0.0))
    rho_1, rho_2 = profile_radii(gs, np.asarray(s, dtype=float))
    return scale * rho_1, scale * rho_2


def reduced(r_1, r_2):
    """Reduced radius 1/(1/r_1 + 1/r_2) of two surfaces (convex > 0) [m]."""
    return r_1 * r_2 / (r_1 + r_2)


def surface_velocities(gs, s):
    """Surface velocities in the ellipse frame [m/(rad/s)] at roll distance s:
    ((up_x, up_y) per unit ω_p, (ug_x, ug_y) per unit ω_g).

    Per unit own speed, member i has V_i = r_mi, V_⊥ = r_mi cos β_mi and Ω_i = V_⊥/r_vn,i; the
    profile component is V_⊥ sin α_nD ± Ω_i s (+ pinion, − gear), the lengthwise one V_i sin β_mi.
    The minor axis e_x is the profile direction turned by +β_B toward +lengthwise.
    """
    bl, s = gs.blank, np.asarray(s, dtype=float)
    c, b = math.cos(gs.beta_B), math.sin(gs.beta_B)
    out = []
    for r_m, beta, r_vn, sign in ((gs.r_m1, bl.beta_m1, gs.r_vn[0], 1.0),
                                  (gs.r_m2, bl.beta_m2, gs.r_vn[1], -1.0)):
        v_perp = r_m * math.cos(beta)
        prof = v_perp * math.sin(gs.alpha_nD) + sign * v_perp / r_vn * s
        lng = r_m * math.sin(beta)
        out.append((c * prof + b * lng, -b * prof + c * lng))
    return tuple(out)


def contact_point_velocity(gs):
    """Velocity of the contact point in space, in the ellipse frame, per unit ω_p [m/(rad/s)]
    (docs/physics.md §10.4), constant over the path.

    The contact point stays on both flanks, so along the flank normal it moves with their common
    normal velocity V_⊥ cos α_nD. In the tangent plane it moves only along the line of contact,
    the major axis y (v_c,x = 0): the contact of involute helicoids, of parallel as of crossed
    axes, moves across its line of contact exactly as the material does, and a localized contact
    stays on the instantaneous line, so its travel cannot change the rolling across it. The
    rolling across the line is then the material's, V sin α_t at the pitch point of a helical
    pair (ISO/TR 14179-2: v_ΣC = 2 v_t sin α_t). The speed λ along y follows from the cone
    distance, which follows lengthwise_position, dy/dφ_p = −TRAVEL b_2 N_p/(2π ε_TCA) (heel to
    toe): the flank normal leans towards the toe by −sin β_m1 cos α_nD, the profile by
    −sin β_m1 sin α_nD, the trace towards the heel by cos β_m1, so

        λ = (dy/dφ_p + V_1 cos² α_nD sin β_m1 cos β_m1) / (sin β_B sin α_nD sin β_m1 + cos β_B cos β_m1)

    (V_1 = r_m1 per unit ω_p). Each surface moves relative to the contact at minus the contact's
    velocity over that surface (rigid-body kinematics)."""
    bl = gs.blank
    a, b = gs.alpha_nD, bl.beta_m1
    dy = -TRAVEL * bl.b_2 * bl.N_p / (2.0 * math.pi * gs.eps_TCA)
    normal_share = gs.r_m1 * math.cos(a) ** 2 * math.sin(b) * math.cos(b)
    along_y = math.sin(gs.beta_B) * math.sin(a) * math.sin(b) + math.cos(gs.beta_B) * math.cos(b)
    return 0.0, (dy + normal_share) / along_y


def pair_roll(gs, psi):
    """Roll distance s [m] of pair 1 at ψ (clamped to the path) and the mask 0 ≤ ξ ≤ 1."""
    xi = pair_xi(gs, psi)
    return roll(gs, np.clip(xi, 0.0, 1.0)), xi <= 1.0


def pair_contact(gs, psi):
    """Contact series of pair 1 at ψ: {R_x, R_y, up_x, up_y, ug_x, ug_y, vc_x, vc_y} (material
    flank velocities and the contact point's), NaN out of contact."""
    s, inside = pair_roll(gs, psi)
    (up_x, up_y), (ug_x, ug_y) = surface_velocities(gs, s)
    vc_x, vc_y = contact_point_velocity(gs)
    values = {"R_x": reduced(*x_radii(gs, s)), "R_y": np.full_like(s, gs.R_y), "up_x": up_x,
              "up_y": up_y, "ug_x": ug_x, "ug_y": ug_y, "vc_x": np.full_like(s, vc_x),
              "vc_y": np.full_like(s, vc_y)}
    return {key: np.where(inside, v, np.nan) for key, v in values.items()}
