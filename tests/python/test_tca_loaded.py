"""Tests of the loaded tooth contact analysis (hypoid/tca/loaded.py, docs/physics.md §10.8)
against hand calculations: closed-form beams, a single pair's compliance summed from its parts by
quadrature, equal pairs sharing a load, linear springs with a gap, the contact ratio's growth
with load and ISO 6336-1's single-pair stiffness."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from hypoid.tca import loaded as tl
from hypoid.tca import surrogate as sur

SETS = (1, 2, 3)


def flank(n, side="drive"):
    return tl.LoadedFlank(tl.flank_set(sur.TABLE_1[n], side))


def test_uniform_beam_matches_closed_form():
    """A prismatic cantilever, load at the free end: 4h³/(E's³) + κh/(Gs) across the section,
    h/(E's) along the axis."""
    h, s = 4e-3, 6e-3
    constant = lambda y: np.full_like(y, s)
    across = tl.beam_compliance(h, constant, 0.0)
    along = tl.beam_compliance(h, constant, 0.5 * math.pi)
    assert across == pytest.approx(4 * h ** 3 / (tl.E_PLANE * s ** 3)
                                   + 1.2 * h / (tl.G_STEEL * s), rel=1e-12)
    assert along == pytest.approx(h / (tl.E_PLANE * s), rel=1e-12)


def test_single_pair_compliance_is_the_sum_of_its_parts():
    """At the pitch point of set 1: the slice's approach under q equals, by hand, the bending,
    shear and axial integrals of both tapered teeth (scipy quad), Weber's root terms and the
    Hertzian line approach, all in series."""
    fl = flank(1)
    xi = fl.xi_pitch
    a = fl.gs.alpha_nD
    nu, E, G = 0.3, 210e9 / 0.91, 210e9 / 2.6
    total = 0.0
    heights = fl.heights(np.array(xi))
    for tooth, y_c in zip(fl.teeth, heights):
        t = lambda y: tooth.s_p + 2 * (tooth.h_f - y) * math.tan(math.radians(20.0))
        bend = quad(lambda y: 12 * (y_c - y) ** 2 / (E * t(y) ** 3), 0, y_c)[0]
        shear = quad(lambda y: 1.2 / (G * t(y)), 0, y_c)[0]
        axial = quad(lambda y: 1 / (E * t(y)), 0, y_c)[0]
        r = y_c / t(0.0)
        root = (16.67 / math.pi * r ** 2 + 2 * (1 - nu - 2 * nu ** 2) / (1 - nu ** 2) * r
                + 1.534 * (1 + math.tan(a) ** 2 / (2.4 * (1 + nu)))) / E
        total += math.cos(a) ** 2 * (bend + shear + root) + math.sin(a) ** 2 * axial
    q = 3e5  # N/m
    R_x = sur.reduced(*sur.x_radii(fl.gs, sur.roll(fl.gs, xi)))
    h = [0.5 * tooth.thickness(y) for tooth, y in zip(fl.teeth, heights)]
    b = math.sqrt(8 * q * R_x / (math.pi * E))
    hertz = 2 * q / (math.pi * E) * (math.log(2 * h[0] / b) + math.log(2 * h[1] / b)
                                     - nu / (1 - nu))
    A, B = fl.contact_law(np.array(xi))
    d = q * total + hertz
    assert q * (A - B * math.log(q)) == pytest.approx(d, rel=1e-10)
    assert tl.slice_load(d, A, B) == pytest.approx(q, rel=1e-9)
    assert 1.0 / fl.slice_stiffness(np.array(xi)) == pytest.approx(total, rel=1e-6)


def test_two_equal_pairs_share_the_load_equally():
    gaps = np.zeros((1, 2, 5))
    A = np.full((1, 2, 1), 1.0 / 2e10)
    delta, q = tl.share_load(np.array(1000.0), gaps, A, 0.0, 1e-3)
    W_pair = q.sum(axis=-1) * 1e-3
    assert W_pair[0] == pytest.approx([500.0, 500.0], rel=1e-9)
    assert delta[0] == pytest.approx(500.0 / (5 * 1e-3 * 2e10), rel=1e-9)


def test_linear_pairs_with_a_separation_share_by_compatibility():
    """Springs k and k, the second one g apart: δ = (W + k g)/(2k), W_1 = k δ, W_2 = k(δ − g);
    below W = k g the second one stays unloaded."""
    c, n, width, g = 2e10, 4, 2.5e-3, 5e-6
    k = c * n * width
    gaps = np.array([[[0.0] * n, [g] * n]])
    A = np.full((1, 2, 1), 1.0 / c)
    for W in (0.5 * k * g, 3.0 * k * g):
        _, q = tl.share_load(np.array(W), gaps, A, 0.0, width)
        W_pair = q.sum(axis=-1)[0] * width
        delta = (W + k * g) / (2 * k)
        expect = [k * delta, k * (delta - g)] if W > k * g else [W, 0.0]
        assert W_pair == pytest.approx(expect, rel=1e-9, abs=1e-6)


@pytest.mark.parametrize("n", SETS)
@pytest.mark.parametrize("side", tl.FLANKS)
def test_contact_ratio_and_stiffness_grow_with_load(n, side):
    fl = flank(n, side)
    meshes = [tl.loaded_mesh(fl, T, n_theta=24) for T in (0.01, 25.0, 100.0, 400.0)]
    eps = [m.contact_ratio for m in meshes]
    k_mean = [m.k_m.mean() for m in meshes]
    assert eps[0] < tl.UNMODIFIED + 0.15  # near-unloaded: the unmodified pair(s) only
    assert all(a < b for a, b in zip(eps, eps[1:]))
    assert eps[-1] <= fl.gs.eps_TCA + 1.0 / 24  # never beyond the geometric path (sampled)
    assert all(a < b for a, b in zip(k_mean, k_mean[1:]))
    for m in meshes:
        assert np.allclose(m.shares.sum(axis=0), 1.0, atol=1e-9)
        assert np.all(m.k_t >= m.k_m)  # the contact stiffens as it grows


@pytest.mark.parametrize("n", SETS)
def test_full_line_pair_stiffness_near_iso_6336(n):
    """A pair loaded along its whole line at the pitch point, per unit effective face width,
    against ISO 6336-1's theoretical single-pair stiffness c'_th (the basis of ISO 10300's
    c' = 14 N/(mm·µm) = c'_th C_M C_R C_B cos β): within 15 %."""
    fl = flank(n)
    z_1, z_2 = tl.virtual_teeth(fl.gs)
    x_1 = (fl.gs.h_am[0] - fl.gs.m_mn) / fl.gs.m_mn
    c_th = tl.iso_single_pair_stiffness(z_1, z_2, x_1, -x_1)  # N/(mm·µm)
    c_model = fl.pair_stiffness_full(np.array(fl.xi_pitch)) / fl.gs.b_veff * 1e-9
    assert c_model == pytest.approx(c_th, rel=0.15)


def test_iso_6336_single_pair_stiffness_of_a_standard_pair():
    """ISO 6336-1's example value: z = 20/40, x = 0 gives q' = 0.04723 + 0.15551/20 + 0.25791/40
    = 0.061454, c'_th = 16.27 N/(mm·µm)."""
    assert tl.iso_single_pair_stiffness(20, 40, 0.0, 0.0) == pytest.approx(16.27, abs=0.01)


def test_coast_flank_has_its_own_pressure_angle():
    drive, coast = (tl.flank_set(sur.TABLE_1[1], f) for f in tl.FLANKS)
    assert drive.alpha_nD == pytest.approx(sur.ALPHA_E + drive.alpha_lim)
    assert coast.alpha_nD == pytest.approx(sur.ALPHA_E - drive.alpha_lim)
    assert math.degrees(coast.alpha_nD) == pytest.approx(23.33, abs=0.005)
    assert coast.R_p0 < drive.R_p0  # steeper flank, shorter lever arm (cos α_n)
    with pytest.raises(ValueError, match="flank 'back'"):
        tl.flank_set(sur.TABLE_1[1], "back")


def test_loaded_transmission_error_closes_the_static_balance():
    """δ − e_u = W/k_m by definition of the secant stiffness, and the sum of the slice loads is
    W: the solver's answer satisfies both to the bisection's precision."""
    fl = flank(1)
    m = tl.loaded_mesh(fl, 100.0, n_theta=16)
    assert np.allclose((m.delta - m.e_u) * m.k_m, m.W, rtol=1e-12)
    width = fl.line_length / tl.N_SLICES
    xi = np.clip(sur.xi_pairs(fl.gs, m.theta).T, 0.0, 1.0)
    engaged = (sur.xi_pairs(fl.gs, m.theta).T >= 0) & (sur.xi_pairs(fl.gs, m.theta).T < 1)
    A, B = fl.contact_law(xi)
    gaps = np.where(engaged[..., None], fl.gaps(xi), np.inf)
    q = tl.slice_load(m.delta[:, None, None] - gaps, A[..., None], B)
    assert np.allclose(q.sum(axis=(-2, -1)) * width, m.W, rtol=1e-9)


def _end_shares(fl, torque, n_theta=256, reach=0.02):
    """Largest load share of a pair within `reach` (engagement coordinate) of either path end."""
    m = tl.loaded_mesh(fl, torque, n_theta=n_theta)
    xi = sur.xi_pairs(fl.gs, m.theta)
    near_end = (np.minimum(xi, 1.0 - xi) < reach) & (xi >= 0.0) & (xi < 1.0)
    return float(np.max(np.where(near_end, m.shares, 0.0)))


@pytest.mark.parametrize("n", SETS)
@pytest.mark.parametrize("side", tl.FLANKS)
def test_pairs_enter_and_leave_the_path_unloaded_up_to_the_design_load(n, side):
    """With the tip and root relief sized to the deflection at DESIGN_TORQUE a pair meets the
    relieved flank only inside the path: near either end of the path it carries no load at any
    torque up to the design torque (today's 20 µm parabolic ease-off let a pair enter with 20 %
    of the load at 100 N·m). Above the design torque the deflection exceeds the relief and the
    ends carry load again, so the relief is sized to the load, not merely large."""
    fl, T_d = flank(n, side), tl.DESIGN_TORQUE
    for T in (25.0, 100.0, 0.75 * T_d):  # no load within 2 % of the path from either end
        assert _end_shares(fl, T, reach=0.02) == 0.0, T
    assert _end_shares(fl, T_d, reach=0.002) < 1e-3  # at the design torque: just at the ends
    assert _end_shares(fl, 1.25 * T_d, reach=0.002) > 1e-2


def test_the_old_parabolic_ease_off_fails_the_entry_check():
    """The check above can fail: the unrelieved 20 µm parabola about the pitch point of the
    first loaded model lets pairs enter the path loaded from light load on."""

    class Parabola(tl.LoadedFlank):
        def profile_gap(self, xi):
            return 20e-6 * (2.0 * (np.asarray(xi, dtype=float) - self.xi_pitch)) ** 2

    fl = Parabola(tl.flank_set(sur.TABLE_1[1], "drive"), relief=0.0)
    assert _end_shares(fl, 25.0, reach=0.02) > 1e-2
    assert _end_shares(fl, 100.0, reach=0.002) > 0.1


@pytest.mark.parametrize("n", SETS)
def test_contact_ratio_grows_from_the_unmodified_zone_to_the_whole_path(n):
    """Only the unmodified middle of the path (UNMODIFIED mesh periods long) meets its mate at
    zero separation. Under a light load with mesh approach δ a relieved pair carries where its
    relief C_a (t/ξ_r)^p is below δ, within t = ξ_r (δ/C_a)^(1/p) of either start of relief, so
    the loaded contact ratio is UNMODIFIED + 2 ε_TCA ξ_r (δ/C_a)^(1/p) (hand calculation,
    averaged over the cycle). At the design torque the contact reaches the path ends: the whole engagement ε_TCA."""
    fl, n_theta, p = flank(n), 256, tl.RELIEF_EXPONENT
    for T in (0.1, 1.0):
        m = tl.loaded_mesh(fl, T, n_theta=n_theta)
        reach = fl.xi_relief * np.mean((m.delta / fl.C_a) ** (1.0 / p))
        assert m.contact_ratio == pytest.approx(tl.UNMODIFIED + 2 * fl.gs.eps_TCA * reach,
                                                abs=0.03), T
    design = tl.loaded_mesh(fl, tl.DESIGN_TORQUE, n_theta=n_theta).contact_ratio
    assert design == pytest.approx(fl.gs.eps_TCA, abs=0.02)  # the last 1 % carries < 1e-6


def test_unloaded_transmission_error_is_zero_with_an_unmodified_pair_always_in_mesh():
    """The unmodified zone is at least one mesh period long, so at every mesh angle a pair meets
    its mate with zero separation: e_u = 0 (no corners where pairs hand over)."""
    assert tl.UNMODIFIED >= 1.0
    m = tl.loaded_mesh(flank(1), 100.0, n_theta=64)
    assert np.all(m.e_u == 0.0)
    np.testing.assert_allclose(m.k_m, m.W / m.delta, rtol=1e-12)
