"""Loaded tooth contact analysis for the surrogate gear sets (docs/physics.md §10.8).

The unloaded surrogate of `hypoid.tca.surrogate` gives the path of contact, the radii and the
kinematics; this module loads it. Each tooth pair in mesh is a row of independent slices along
its contact line. A slice is a spring made of the two teeth (bending, shear, axial compression
and root compliance of a cantilever in the normal section of the virtual gears) in series with
the Hertzian approach of a line contact of the slice's length. The pairs share the normal load
by displacement compatibility: every loaded slice closes the common mesh approach δ less its own
unloaded separation, the profile ease-off of its pair plus the lengthwise ease-off along the
contact line. So the contact grows with load along the line (the elliptic footprint) and in
number of pairs (the loaded contact ratio). The profile ease-off is a tip and root relief sized
to the deflection at a design torque, so that up to that torque a pair enters and leaves the
path unloaded.

Lengths in m, forces in N, stiffness in N/m, angles in rad unless a name says otherwise.
"""

import math
from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from hypoid.tca import surrogate as sur

E_STEEL = 210e9  # Young's modulus [Pa] (docs/physics.md §2.1)
NU_STEEL = 0.30  # Poisson's ratio
E_PLANE = E_STEEL / (1.0 - NU_STEEL ** 2)  # plane-strain modulus, = the paper's E* [Pa]
G_STEEL = E_STEEL / (2.0 * (1.0 + NU_STEEL))  # shear modulus [Pa]
SHEAR_FORM = 1.2  # shear form factor of a rectangular section
CLEARANCE = 0.25  # root clearance / m_mn (ASSUMED)
DESIGN_TORQUE = 400.0  # pinion torque the tip and root relief is sized for [N·m] (top of TORQUES)
UNMODIFIED = 1.15  # length of the unmodified (conjugate) middle of the path [mesh periods]
RELIEF_EXPONENT = 2.5  # shape of the relief: C_a (t/ξ_r)^p (2 would be parabolic)
SIZING_ANGLES = 128  # mesh angles of the relief sizing (relief_amount)
N_SLICES = 41  # slices along a contact line
N_QUAD = 48  # Gauss points along a tooth
TORQUES = (25.0, 50.0, 100.0, 200.0, 400.0)  # pinion torque levels [N·m]
FLANKS = ("drive", "coast")
LOADED_SHARE = 1e-6  # a pair counts as in contact above this share of the load
_GAUSS = np.polynomial.legendre.leggauss(N_QUAD)


class CoastGearSet(sur.GearSet):
    """The coast flank of a Table 1 gear set: ISO 10300-1 Annex A with the sign of the limit
    pressure angle reversed, α_nC = α_e − α_lim, so the coast flank has its own pressure angle,
    profile curvature and lever arm; the blank, the virtual gears and the path are shared."""

    @cached_property
    def alpha_lim(self):
        return -sur.GearSet.alpha_lim.func(self)


def flank_set(blank, flank):
    """The surrogate geometry of one flank ('drive' or 'coast') of a Table 1 blank."""
    if flank not in FLANKS:
        raise ValueError(f"flank '{flank}': must be one of {', '.join(FLANKS)}")
    return sur.GearSet(blank) if flank == "drive" else CoastGearSet(blank)


# --- one tooth: a cantilever in the normal section of its virtual gear ------------------------

def beam_compliance(y_c, thickness, alpha):
    """Bending, shear and axial compliance of a tooth per unit length [m/(N/m)] for a unit line
    load normal to the flank at height y_c above the root, the flank normal at α to the tooth's
    cross-section (Timoshenko cantilever, energy method):

        λ = cos²α ∫₀^y_c [12 (y_c − y)²/(E' s³) + κ/(G s)] dy + sin²α ∫₀^y_c dy/(E' s)

    thickness(y) is the tooth thickness s at height y; y_c and α may be arrays of one shape.
    """
    y_c = np.asarray(y_c, dtype=float)
    x, w = _GAUSS
    y = 0.5 * y_c[..., None] * (x + 1.0)
    s = thickness(y)
    lever = y_c[..., None] - y
    bend = 0.5 * y_c * np.sum(w * 12.0 * lever ** 2 / (E_PLANE * s ** 3), axis=-1)
    shear = 0.5 * y_c * np.sum(w * SHEAR_FORM / (G_STEEL * s), axis=-1)
    axial = 0.5 * y_c * np.sum(w / (E_PLANE * s), axis=-1)
    return np.cos(alpha) ** 2 * (bend + shear) + np.sin(alpha) ** 2 * axial


def root_compliance(u_f, S_f, alpha):
    """Compliance of the tooth's root on the rim per unit length [m/(N/m)] (Weber's elastic
    half-plane, as quoted by Sainsot et al. 2004 and Chaari et al. 2009):

        λ_f = cos²α (1 − ν²)/E · [16.67/π (u_f/S_f)² + 2(1 − ν − 2ν²)/(1 − ν²) u_f/S_f
                                  + 1.534 (1 + tan²α/(2.4 (1 + ν)))]

    u_f: height of the load above the root, S_f: root thickness."""
    nu, r = NU_STEEL, np.asarray(u_f, dtype=float) / S_f
    bracket = (16.67 / math.pi * r ** 2 + 2.0 * (1.0 - nu - 2.0 * nu ** 2) / (1.0 - nu ** 2) * r
               + 1.534 * (1.0 + np.tan(alpha) ** 2 / (2.4 * (1.0 + nu))))
    return np.cos(alpha) ** 2 / E_PLANE * bracket


def hertz_line_approach(q, R_x, h_1, h_2):
    """Approach of two teeth in line contact under a line load q [N/m] (Weber's 2-D Hertz
    result; each body measured to its tooth's centre line at depth h_i):

        δ_H = 2q/(π E') [ln(2h_1/b) + ln(2h_2/b) − ν/(1 − ν)],   b = √(8 q R_x/(π E'))
    """
    q = np.asarray(q, dtype=float)
    b = np.sqrt(8.0 * q * R_x / (math.pi * E_PLANE))
    return 2.0 * q / (math.pi * E_PLANE) * (np.log(4.0 * h_1 * h_2 / b ** 2)
                                           - NU_STEEL / (1.0 - NU_STEEL))


@dataclass(frozen=True)
class Tooth:
    """A virtual rack-like tooth of one member in the normal section: straight flanks at α_e."""

    h_f: float  # dedendum: root to pitch line [m]
    h_a: float  # addendum [m]
    s_p: float  # thickness at the pitch line [m]

    def thickness(self, y):
        return self.s_p + 2.0 * (self.h_f - np.asarray(y, dtype=float)) * math.tan(sur.ALPHA_E)

    def compliance(self, y_c, alpha):
        """Tooth plus root compliance per unit length [m/(N/m)] for a load at height y_c."""
        return (beam_compliance(y_c, self.thickness, alpha)
                + root_compliance(y_c, self.thickness(0.0), alpha))


# --- one flank of a gear set ---------------------------------------------------------------

@dataclass(frozen=True)
class LoadedFlank:
    """The loaded-contact model of one flank of a gear set; the pairs' functions take the
    engagement coordinate ξ of docs/physics.md §10.5. relief: the tip and root relief C_a at the
    path ends [m]; None sizes it to the deflection at DESIGN_TORQUE (relief_amount)."""

    gs: sur.GearSet
    relief: float | None = None

    @cached_property
    def C_a(self):
        """Tip and root relief at the path ends [m]."""
        return relief_amount(self.gs) if self.relief is None else self.relief

    @cached_property
    def xi_relief(self):
        """Start of the relief [engagement coordinate] at each end: the unmodified middle
        [ξ_r, 1 − ξ_r] is UNMODIFIED mesh periods long."""
        return 0.5 * (1.0 - UNMODIFIED / self.gs.eps_TCA)

    @cached_property
    def teeth(self):
        """(pinion, gear) teeth: addenda of §10.2, dedenda with the clearance, zero backlash."""
        gs = self.gs
        m, (h_a1, h_a2) = gs.m_mn, gs.h_am
        c = CLEARANCE * m
        x_1 = (h_a1 - 0.5 * sur.H_MW * m) / m  # profile shift of the pinion
        s_1 = m * (0.5 * math.pi + 2.0 * x_1 * math.tan(sur.ALPHA_E))
        return Tooth(h_a2 + c, h_a1, s_1), Tooth(h_a1 + c, h_a2, math.pi * m - s_1)

    @cached_property
    def xi_pitch(self):
        s_a, s_r = self.gs.s_roll
        return -s_a / (s_r - s_a)

    @cached_property
    def line_length(self):
        """Length of a contact line across the effective face width [m]."""
        return self.gs.b_veff / math.cos(self.gs.beta_B)

    @cached_property
    def eta(self):
        """Slice centres along the contact line from the face centre [m]."""
        L = self.line_length
        return (np.arange(N_SLICES) + 0.5) / N_SLICES * L - 0.5 * L

    def heights(self, xi):
        """Load heights above the roots of pinion and gear [m] at ξ (the contact point rises
        on the pinion and falls on the gear by s sin α_n along the path)."""
        rise = sur.roll(self.gs, xi) * math.sin(self.gs.alpha_nD)
        pinion, gear = self.teeth
        return pinion.h_f + rise, gear.h_f - rise

    def slice_stiffness(self, xi):
        """Structural stiffness of the pair per unit contact length [N/m per m] at ξ."""
        pinion, gear = self.teeth
        y_1, y_2 = self.heights(xi)
        a = self.gs.alpha_nD
        return 1.0 / (pinion.compliance(y_1, a) + gear.compliance(y_2, a))

    def contact_law(self, xi):
        """Coefficients (A, B) of a slice's approach d(q) = q (A − B ln q) at ξ, which holds the
        structural and the Hertzian compliance (hertz_line_approach rearranged)."""
        pinion, gear = self.teeth
        y_1, y_2 = self.heights(xi)
        R_x = sur.reduced(*sur.x_radii(self.gs, sur.roll(self.gs, xi)))
        h_1, h_2 = 0.5 * pinion.thickness(y_1), 0.5 * gear.thickness(y_2)
        B = 2.0 / (math.pi * E_PLANE)
        A = (1.0 / self.slice_stiffness(xi)
             + B * (np.log(math.pi * E_PLANE * h_1 * h_2 / (2.0 * R_x)) - NU_STEEL / (1.0 - NU_STEEL)))
        return A, B

    def profile_gap(self, xi):
        """Unloaded separation of a pair from the profile ease-off [m]: zero on the unmodified
        middle of the path, a relief C_a (t/ξ_r)^RELIEF_EXPONENT tangent to it over the last ξ_r
        of either end (t the distance into the relief: the gear's tip and the pinion's root at the
        approach end, the pinion's tip and the gear's root at the recess end)."""
        xi, r = np.asarray(xi, dtype=float), self.xi_relief
        into = np.maximum(np.maximum(r - xi, xi - (1.0 - r)), 0.0)
        return self.C_a * (into / r) ** RELIEF_EXPONENT

    def unloaded_separation(self, xi):
        """Smallest unloaded separation of a pair at ξ [m]: its profile gap plus the lengthwise
        ease-off at the point of the contact line nearest the contact centre (zero while the
        centre lies on the line)."""
        off = np.maximum(np.abs(sur.lengthwise_position(self.gs, xi)) - 0.5 * self.line_length, 0.0)
        return self.profile_gap(xi) + off ** 2 / (2.0 * self.gs.R_y)

    def gaps(self, xi):
        """Unloaded separations of the slices of pairs at ξ [m], shape ξ.shape + (N_SLICES,):
        profile ease-off plus the lengthwise ease-off (η − η_c)²/(2 R_y) about the contact
        centre η_c = lengthwise_position(ξ) (as R_p of §10.6; η > 0 towards the heel)."""
        xi = np.asarray(xi, dtype=float)
        eta_c = sur.lengthwise_position(self.gs, xi)
        lengthwise = (self.eta - eta_c[..., None]) ** 2 / (2.0 * self.gs.R_y)
        return self.profile_gap(xi)[..., None] + lengthwise

    def pair_stiffness_full(self, xi):
        """Structural stiffness of a pair loaded uniformly along its whole line [N/m]."""
        return self.slice_stiffness(xi) * self.line_length


def slice_load(d, A, B, iterations=30):
    """Line load q [N/m] that closes a slice approach d [m] under d = q (A − B ln q); zero where
    d ≤ 0. Fixed point q ← d/(A − B ln q), a contraction since B |ln q| ≪ A."""
    d = np.asarray(d, dtype=float)
    pos = np.maximum(d, 0.0)
    q = pos / A
    for _ in range(iterations):
        q = np.where(pos > 0.0, pos / (A - B * np.log(np.maximum(q, 1e-300))), 0.0)
    return q


def slice_stiffness_tangent(q, A, B):
    """dq/dd of a loaded slice [N/m per m]: 1/(A − B ln q − B); zero where unloaded."""
    return np.where(q > 0.0, 1.0 / (A - B * np.log(np.maximum(q, 1e-300)) - B), 0.0)


def share_load(W, gaps, A, B, width, iterations=80):
    """Mesh approach δ [m] (one per leading index) at which the slices, with unloaded gaps
    [..., pair, slice] and laws (A, B) [..., pair, 1], carry the normal load W [N]; bisection on
    the monotone total load. Returns δ and the line loads q [N/m]."""
    gaps = np.asarray(gaps, dtype=float)
    lead = gaps.shape[:-2]
    g_min = gaps.min(axis=(-2, -1))
    lo, hi = g_min.copy(), g_min + 1e-9
    total = lambda delta: (slice_load(delta[..., None, None] - gaps, A, B) * width).sum(axis=(-2, -1))
    while np.any(total(hi) < W):
        hi = np.where(total(hi) < W, g_min + 2.0 * (hi - g_min), hi)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        low = total(mid) < W
        lo, hi = np.where(low, mid, lo), np.where(low, hi, mid)
    delta = 0.5 * (lo + hi)
    assert delta.shape == lead
    return delta, slice_load(delta[..., None, None] - gaps, A, B)


@dataclass(frozen=True)
class LoadedMesh:
    """Loaded contact of one flank at one pinion torque over one mesh cycle."""

    torque: float  # pinion torque [N·m]
    W: float  # normal mesh load [N]
    theta: np.ndarray  # mesh angle θ [rad], one cycle
    delta: np.ndarray  # loaded static transmission error: the mesh approach δ [m]
    e_u: np.ndarray  # unloaded transmission error: the smallest pair separation [m]
    k_m: np.ndarray  # secant mesh stiffness W/(δ − e_u) [N/m]
    k_t: np.ndarray  # tangent mesh stiffness dW/dδ [N/m]
    shares: np.ndarray  # load share of pairs j = 0, 1, 2 at ξ_j(θ), shape (3, n)
    contact_length: np.ndarray  # loaded length of each pair's contact line [m], shape (3, n)

    @property
    def contact_ratio(self):
        """Loaded contact ratio: the mean number of pairs carrying load."""
        return float(np.mean(np.sum(self.shares > LOADED_SHARE, axis=0)))


def loaded_mesh(flank, torque, n_theta=96):
    """Solve the load sharing of `flank` (a LoadedFlank) at a pinion torque [N·m] at n_theta
    mesh angles of one cycle."""
    gs = flank.gs
    theta = 2.0 * math.pi * np.arange(n_theta) / n_theta
    xi = sur.xi_pairs(gs, theta).T  # (n, 3)
    engaged = (xi >= 0.0) & (xi < 1.0)
    xi_c = np.clip(xi, 0.0, 1.0)
    gaps = np.where(engaged[..., None], flank.gaps(xi_c), np.inf)
    A, B = flank.contact_law(xi_c)
    W = torque / gs.R_p0
    width = flank.line_length / N_SLICES
    delta, q = share_load(W, gaps, A[..., None], B, width)
    W_pair = (q * width).sum(axis=-1)
    k_t = (slice_stiffness_tangent(q, A[..., None], B) * width).sum(axis=(-2, -1))
    e_u = np.where(engaged, flank.unloaded_separation(xi_c), np.inf).min(axis=-1)
    return LoadedMesh(torque, W, theta, delta, e_u, W / (delta - e_u), k_t, (W_pair / W).T,
                      ((q > 0.0).sum(axis=-1) * width).T)


@lru_cache(maxsize=None)
def relief_amount(gs, torque=DESIGN_TORQUE):
    """Tip and root relief C_a [m] sized to the deflection at a pinion torque: the largest loaded
    approach δ − e_u over a mesh cycle of the flank relieved by C_a itself, so that at that
    torque a pair just reaches zero separation at the path ends and carries no load there (the
    designer's rule: relief equal to the deflection at the design load). Found from the
    full-face deflection W/k_n by secant steps on the excess max(δ − e_u) − C_a, which falls
    monotonically: a larger relief adds to δ only through the load the relieved pairs shed."""
    def excess(C):  # deflection beyond the relief C [m]
        m = loaded_mesh(LoadedFlank(gs, C), torque, SIZING_ANGLES)
        return float(np.max(m.delta - m.e_u)) - C

    a = torque / gs.R_p0 / gs.k_n
    f_a = excess(a)
    b = a + f_a  # one fixed-point step, then secant steps on the excess
    for _ in range(20):
        f_b = excess(b)
        if abs(f_b) < 1e-10:
            return b
        a, f_a, b = b, f_b, b - f_b * (b - a) / (f_b - f_a)
    raise RuntimeError(f"relief sizing did not converge at {torque} N·m (last {b:g} m)")


def loaded_flanks(blank, torques=TORQUES, n_theta=96):
    """{flank: [LoadedMesh per torque]} for both flanks of a Table 1 blank."""
    return {f: [loaded_mesh(LoadedFlank(flank_set(blank, f)), T, n_theta) for T in torques]
            for f in FLANKS}


# --- ISO estimates for comparison (docs/physics.md §10.8) ---------------------------------

def iso_single_pair_stiffness(z_n1, z_n2, x_1, x_2):
    """Theoretical single-pair stiffness c'_th = 1/q' [N/(mm·µm)] of ISO 6336-1 (the basis of
    ISO 10300's default c' = 14 N/(mm·µm)), for solid gears and the basic rack
    h_fP = 1.25 m_n, α_n = 20°."""
    q = (0.04723 + 0.15551 / z_n1 + 0.25791 / z_n2 - 0.00635 * x_1 - 0.11654 * x_1 / z_n1
         - 0.00193 * x_2 - 0.24188 * x_2 / z_n2 + 0.00529 * x_1 ** 2 + 0.00182 * x_2 ** 2)
    return 1.0 / q


def virtual_teeth(gs):
    """Virtual numbers of teeth of the normal section, z_vn,i = 2 r_vn,i/m_mn."""
    return tuple(2.0 * r / gs.m_mn for r in gs.r_vn)
