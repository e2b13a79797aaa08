"""hypoid.study.modes (the modal analysis behind docs/records/paper-findings.md) against the FMU's own modal
analysis (fmu-src/model/modal.c: f_2..f_4 and the dampers) and against an independent rigid-mesh
reduction, and the two findings the note rests on."""

import math

import numpy as np
import pytest

from hypoid.study import modes
from hypoid.fmu.variables import ENUMERATIONS

PAPER_DATA = ENUMERATIONS["tooth_data"]["paper"]


# The what-if (I_p from the pinion's geometry, damping ratios 0.02 / 0.02 / 0.03) is the study's
# explanation of the paper's findings and runs the paper's choices (study.PAPER_CHOICES: its
# calibrated one series, k_m0 1.71e8 N/m). On the loaded data's tangent k_m0 (4.8e8 N/m) those
# ratios need a negative damper and the FMU takes its least-squares fallback (tests/c/test_modal.c),
# so the what-if case is checked on the data it is run with; Table 3's inertia on the defaults.
@pytest.mark.parametrize("I_p, data", [(0.014, {}), (modes.I_P_GEOMETRY, {"tooth_data": PAPER_DATA})])
def test_frequencies_and_dampers_match_the_fmu(harness, I_p, data):
    h = harness()
    h.start(dict(I_p=I_p, zeta_2=0.02, zeta_3=0.02, zeta_4=0.03, **data) if I_p != 0.014 else {},
            checked=False)
    k_m0, R_p0 = h.reals(["k_m0", "R_p0"])
    s = modes.system(I_p=I_p, k_m=k_m0, R_p=R_p0)
    w, phi = modes.modes(s)
    f = np.array(h.reals(["f_2", "f_3", "f_4"]))
    np.testing.assert_allclose(w[1:] / (2 * math.pi), f, rtol=1e-9)
    assert abs(w[0]) < 1e-6 * w[1]  # the rigid mode
    np.testing.assert_allclose(phi.T @ s.mass() @ phi, np.eye(4), atol=1e-9)
    zeta = (0.02, 0.04, 0.03) if I_p == 0.014 else (0.02, 0.02, 0.03)
    c = modes.dampers(s, zeta)
    np.testing.assert_allclose(c, h.reals(["c_t1", "c_m", "c_t2"]), rtol=1e-6)


def test_rigid_mesh_limit_against_the_three_inertia_chain():
    """k_m -> infinity: pinion and gear become one inertia I_p + I_g/i^2 between shaft 1 and
    shaft 2 (referred to the pinion: k_t2/i^2, I_w/i^2)."""
    s = modes.system()
    i = s.ratio
    M = np.diag([s.I_s, s.I_p + s.I_g / i ** 2, s.I_w / i ** 2])
    k1, k2 = s.k_t1, s.k_t2 / i ** 2
    K = np.array([[k1, -k1, 0], [-k1, k1 + k2, -k2], [0, -k2, k2]])
    w_chain = np.sqrt(np.sort(np.linalg.eigvals(np.linalg.solve(M, K)).real)[1])
    w_big, _ = modes.modes(s, k_m=1e6 * s.k_m)
    assert w_big[1] == pytest.approx(w_chain, rel=1e-5)
    assert modes.rpm(s, w_chain) == pytest.approx(1526, abs=1)


def test_table3_mode2_dominates_and_the_geometric_pinion_moves_it_to_2000_rpm():
    """Table 3: mode 2 (1203 rpm) has the larger DTE gain for every non-negative damper set, so
    the paper's 2000 rpm findings (mode 3) cannot be the strongest; with I_p = 1e-3 kg m^2
    mode 3 moves to about 2120 rpm and dominates for the FMU's default damping ratios."""
    t3 = modes.system()
    lo, _ = modes.damper_scan(t3, n=6)
    assert lo > 1.0
    geo = modes.system(I_p=modes.I_P_GEOMETRY)
    w, _ = modes.modes(geo)
    assert modes.rpm(geo, w[2]) == pytest.approx(2120, abs=30)
    (_, c, gains), = modes.gain_table(geo, [(0.02, 0.02, 0.03)])
    assert gains[1] > gains[0]


def _hand_matrices(s):
    """K and M of Eqs. 20-23 linearised (f(x) = x), written out element by element from the
    equations of motion rather than built from the spring directions as hypoid.study.modes does."""
    k1, k2, km, rp, rg = s.k_t1, s.k_t2, s.k_m, s.R_p, s.R_p * s.ratio
    K = np.array([[k1, -k1, 0.0, 0.0],
                  [-k1, k1 + km * rp ** 2, -km * rp * rg, 0.0],
                  [0.0, -km * rp * rg, km * rg ** 2 + k2, -k2],
                  [0.0, 0.0, -k2, k2]])
    return K, np.diag([s.I_s, s.I_p, s.I_g, s.I_w])


def _det_roots(s, f_hi=6000.0, n=60000):
    """Natural frequencies [Hz] as the sign changes of det(K - (2 pi f)^2 M) (an LU
    determinant, no eigensolver), refined by bisection."""
    K, M = _hand_matrices(s)

    def det(f):
        return np.linalg.det(K - (2 * math.pi * f) ** 2 * M)

    grid = np.linspace(1.0, f_hi, n)
    d = np.array([det(f) for f in grid])
    roots = []
    for i in np.nonzero(np.sign(d[:-1]) != np.sign(d[1:]))[0]:
        a, b = grid[i], grid[i + 1]
        for _ in range(60):
            m = 0.5 * (a + b)
            a, b = (m, b) if np.sign(det(m)) == np.sign(det(a)) else (a, m)
        roots.append(0.5 * (a + b))
    return np.array(roots)


@pytest.mark.parametrize("I_p, rpm_stated", [(0.014, (1203, 2000, 7949)),
                                             (modes.I_P_GEOMETRY, (1413, 2118, 22379))])
def test_frequencies_by_hand_determinant(I_p, rpm_stated):
    """The three elastic frequencies at Table 3's and at the geometric pinion inertia are the
    zeros of the hand-written characteristic determinant, and give the resonance speeds stated
    in docs/records/paper-findings.md (what-if: 1413 and 2118 rpm)."""
    s = modes.system(I_p=I_p)
    f = _det_roots(s)
    w, _ = modes.modes(s)
    np.testing.assert_allclose(f, w[1:] / (2 * math.pi), rtol=1e-7)
    np.testing.assert_allclose(60 * f / s.N_p, rpm_stated, atol=0.6)


def test_mesh_share_of_strain_energy_by_hand():
    """Mode 2 of Table 3 keeps 58 % of its strain energy in the mesh, mode 3 39 %; with the
    geometric pinion 36 % and 56 % (the strain energies of the hand-written springs)."""
    for I_p, stated in ((0.014, (0.58, 0.39)), (modes.I_P_GEOMETRY, (0.36, 0.56))):
        s = modes.system(I_p=I_p)
        K, M = _hand_matrices(s)
        w, phi = modes.modes(s)
        for i, share in zip((1, 2), stated):
            p = phi[:, i]
            mesh = s.k_m * (s.R_p * p[1] - s.R_p * s.ratio * p[2]) ** 2
            assert 0.5 * p @ K @ p == pytest.approx(0.5 * w[i] ** 2, rel=1e-9)
            assert mesh / (p @ K @ p) == pytest.approx(share, abs=0.006)


def _time_domain_gain(s, c, f_hz, cycles=200):
    """|x / e_0| from integrating the damped linear equations in time with e_0 = sin(omega t)
    (scipy's DOP853, no frequency-domain solve): the amplitude of x over the last 20 cycles,
    when the start's transient has decayed by exp(-2 pi zeta 180) < 1e-9."""
    from scipy.integrate import solve_ivp

    K, M = _hand_matrices(s)
    c1, cm, c2 = c
    rp, rg = s.R_p, s.R_p * s.ratio
    C = np.array([[c1, -c1, 0.0, 0.0],
                  [-c1, c1 + cm * rp ** 2, -cm * rp * rg, 0.0],
                  [0.0, -cm * rp * rg, cm * rg ** 2 + c2, -c2],
                  [0.0, 0.0, -c2, c2]])
    Minv, w = np.linalg.inv(M), 2 * math.pi * f_hz
    g = np.array([0.0, rp, -rg, 0.0])  # x = g . phi

    def rhs(t, y):
        # M q'' + C q' + K q = g (k_m e_0 + c_m e_0'): the mesh force k_m (x - e_0) + c_m (x' - e_0')
        q, v = y[:4], y[4:]
        drive = (s.k_m * np.sin(w * t) + cm * w * np.cos(w * t)) * g
        return np.concatenate([v, Minv @ (drive - K @ q - C @ v)])

    t_end = cycles / f_hz
    t = np.linspace(t_end - 20 / f_hz, t_end, 2001)
    sol = solve_ivp(rhs, (0, t_end), np.zeros(8), t_eval=t, rtol=1e-9, atol=1e-14,
                    method="DOP853")
    x = g @ sol.y[:4]
    return 0.5 * np.ptp(x)


@pytest.mark.parametrize("I_p, zeta", [(0.014, (0.02, 0.04, 0.03)),
                                       (modes.I_P_GEOMETRY, (0.02, 0.02, 0.03))])
def test_dte_gain_against_a_time_domain_run(I_p, zeta):
    """The DTE gain per mode of hypoid.study.modes against the linear equations integrated in time
    at the natural frequencies; and the ordering the note rests on (Table 3: mode 2 about 3x
    mode 3; the geometric pinion: mode 3 the stronger)."""
    s = modes.system(I_p=I_p)
    c = modes.dampers(s, zeta)
    w, _ = modes.modes(s)
    got = [_time_domain_gain(s, c, w[i] / (2 * math.pi)) for i in (1, 2)]
    np.testing.assert_allclose(got, [modes.dte_gain(s, c, w[i]) for i in (1, 2)], rtol=2e-3)
    assert (got[0] / got[1] > 2.5) if I_p == 0.014 else (got[1] > got[0])


def test_pinion_inertia_from_geometry_by_quadrature():
    """The pinion head's frustum inertia against a quadrature of r^2 dm over slices along the
    axis (Table 1, set 1: pitch radii 23.9 and 40.3 mm over 29.6 mm), and the what-if's
    I_p = 1e-3 kg m^2 within the order of head + shaft, Table 3's 0.014 far above it."""
    from scipy.integrate import quad

    from hypoid.tca import surrogate as sur

    bl = sur.TABLE_1[1]
    r_o, r_i = bl.R_e1 * math.sin(bl.delta_1), (bl.R_e1 - bl.b_1) * math.sin(bl.delta_1)
    h = bl.b_1 * math.cos(bl.delta_1)
    assert (r_i, r_o, h) == pytest.approx((23.9e-3, 40.3e-3, 29.6e-3), abs=0.1e-3)
    disc = lambda z: math.pi / 2 * modes.STEEL_DENSITY * (r_i + (r_o - r_i) * z / h) ** 4  # noqa: E731
    I_head, _ = quad(disc, 0.0, h)
    assert modes.pinion_head_inertia(1) == pytest.approx(I_head, rel=1e-9)
    head, with_shaft = modes.pinion_inertia_estimate(1)
    assert 0.5 < modes.I_P_GEOMETRY / with_shaft < 2.0
    assert modes.TABLE3["I_p"] / with_shaft > 10
