"""Kinematics of the tooth data: friction torques and power from the material
flank velocities (r x F), entrainment from the velocities relative to the moving contact point.
A synthetic gear set with constant series whose contact point moves: torques, sliding and
entrainment known in closed form. And the TCA import's two velocity sets."""

import math

import numpy as np
import pytest
from fmpy import simulate_fmu

from hypoid.cli import tca as tca_cli
from hypoid.tca import gearsets as tca
from hypoid.tca.table import TableError
from hypoid.tca import table_import
from hypoid.tca.gearset_file import Gearset, GearsetFileError, Series, read_gearset, write_gearset
from hypoid.fmu.variables import ENUMERATIONS

UP, UG, VC = (0.012, 0.020), (0.009, 0.027), (0.004, 0.012)  # m/(rad/s): material, contact point
MU = 0.05


def constant(v):
    return Series(float(v), np.zeros(0), np.zeros(0))


def synthetic(path, vc=VC):
    series = {"k_m": 1.7e8, "R_p": 0.021, "e_0": 0.0, "ls": 1 / 3, "R_x": 0.018, "R_y": 2.0,
              "up_x": UP[0], "up_y": UP[1], "ug_x": UG[0], "ug_y": UG[1]}
    if vc is not None:
        series.update(vc_x=vc[0], vc_y=vc[1])
    write_gearset(path, Gearset("synthetic moving contact", 13, 36,
                                {k: constant(v) for k, v in series.items()}))
    return path


def run(gear_file, friction):
    w = 2000 * math.pi / 30
    names = ["w_p", "w_g", "W_t", "T_fp", "T_fg", "P_loss"] + \
        [f"pair[{k}].{q}" for k in (1, 2, 3) for q in ("W", "u_e", "V_s", "mu")]
    r = simulate_fmu(str(gear_file.fmu), stop_time=0.05, output_interval=1e-3,
                     start_values={"gear_set_file": str(gear_file.path), "mu_const": MU,
                                   "friction_model": ENUMERATIONS["friction_model"][friction],
                                   "w_p0": w, "w_set": w},
                     output=names)
    return {n: r[n][-10:] for n in names}


class File:
    def __init__(self, fmu, path):
        self.fmu, self.path = fmu, path


def test_torques_from_material_velocities_and_entrainment_relative_to_the_contact(fmu_path,
                                                                                  tmp_path):
    r = run(File(fmu_path, synthetic(tmp_path / "moving.txt")), "coulomb")
    w_p, w_g, W_t = r["w_p"], r["w_g"], r["W_t"]
    up, ug, vc = (np.outer(w, v) for w, v in ((w_p, UP), (w_g, UG), (w_p, VC)))
    V_s = up - ug
    n = V_s / np.linalg.norm(V_s, axis=1)[:, None]
    F = MU * W_t  # the three pairs share W_t equally, each at mu
    # closed form: T_fp = -F (V_s^ . u_p)/w_p, T_fg = +F (V_s^ . u_g)/w_g with the material
    # velocities u = w r x ... per unit speed (here the constant series)
    T_fp = -F * (n @ np.array(UP))
    T_fg = F * (n @ np.array(UG))
    np.testing.assert_allclose(r["T_fp"], T_fp, rtol=1e-6)
    np.testing.assert_allclose(r["T_fg"], T_fg, rtol=1e-6)
    np.testing.assert_allclose(r["P_loss"], F * np.linalg.norm(V_s, axis=1), rtol=1e-6)
    # the contact-frame velocities (u - v_c) would give other torques: the test can tell
    wrong = -F * (n @ np.array(UP)) + F * (n @ np.array(VC))
    assert np.all(np.abs(r["T_fp"] - wrong) > 1e-3 * np.abs(T_fp))
    for k in (1, 2, 3):
        np.testing.assert_allclose(r[f"pair[{k}].W"], W_t / 3, rtol=1e-9)
        np.testing.assert_allclose(r[f"pair[{k}].V_s"], np.linalg.norm(V_s, axis=1), rtol=1e-9)
        u_e = np.linalg.norm((up - vc + ug - vc) / 2, axis=1)
        np.testing.assert_allclose(r[f"pair[{k}].u_e"], u_e, rtol=1e-9)


def test_a_file_without_the_contact_point_velocity_reads_as_a_fixed_contact(fmu_path, tmp_path):
    fixed = run(File(fmu_path, synthetic(tmp_path / "fixed.txt", vc=None)), "coulomb")
    zero = run(File(fmu_path, synthetic(tmp_path / "zero.txt", vc=(0.0, 0.0))), "coulomb")
    for name in fixed:
        np.testing.assert_array_equal(fixed[name], zero[name])
    assert "vc_x" not in read_gearset(tmp_path / "fixed.txt").series


def test_moving_contact_thins_the_film_of_the_ehl_model(fmu_path, tmp_path):
    """Lubricant entrained at |u - v_c| < |u|: the moving contact lowers u_e and the film."""
    moving = run(File(fmu_path, synthetic(tmp_path / "m.txt")), "ehl_thermal")
    fixed = run(File(fmu_path, synthetic(tmp_path / "f.txt", vc=None)), "ehl_thermal")
    assert np.all(moving["pair[1].u_e"] < fixed["pair[1].u_e"])


# --- the TCA import's velocity sets ------------------------------------------------------------

def exported(tmp_path, edit=None):
    """The surrogate of set 1 as a TCA table (relative velocities and vc columns)."""
    path = tmp_path / "table.csv"
    assert tca_cli.main(["export-csv", "--set", "1", "--out", str(path), "--rows", "360"]) == 0
    if edit:
        lines = path.read_text().splitlines()
        lines = edit(lines)
        path.write_text("\n".join(lines) + "\n")
    return path


def add_material(lines, spoil=None):
    """Appends material velocity columns upm = up + vc, ugm = ug + vc (row `spoil` off by 1 m/s)."""
    head = next(i for i, ln in enumerate(lines) if ln.startswith("phi_p_deg"))
    cols = lines[head].split(",")
    idx = {c: cols.index(c) for c in cols}
    lines[head] += ",upm_x_m_s,upm_y_m_s,ugm_x_m_s,ugm_y_m_s"
    for i in range(head + 1, len(lines)):
        cells = lines[i].split(",")
        if not cells[idx["up_x_m_s"]]:
            lines[i] += ",,,,"
            continue
        v = {c: float(cells[idx[c]]) for c in ("up_x_m_s", "up_y_m_s", "ug_x_m_s", "ug_y_m_s",
                                               "vc_x_m_s", "vc_y_m_s")}
        m = [v["up_x_m_s"] + v["vc_x_m_s"], v["up_y_m_s"] + v["vc_y_m_s"],
             v["ug_x_m_s"] + v["vc_x_m_s"], v["ug_y_m_s"] + v["vc_y_m_s"]]
        if spoil is not None and i == spoil:
            m[2] += 1.0
        lines[i] += "," + ",".join(f"{x:.10g}" for x in m)
    return lines


def test_import_turns_relative_velocities_into_material_ones(tmp_path):
    imported = table_import.import_table(exported(tmp_path))
    direct = tca.surrogate(1)
    for key in ("up_x", "up_y", "ug_x", "ug_y", "vc_x", "vc_y"):
        assert imported.series[key].mean == pytest.approx(direct.series[key].mean, rel=2e-3), key


def test_consistent_velocity_sets_are_accepted(tmp_path):
    both = table_import.import_table(exported(tmp_path, add_material))
    assert both.series["up_x"].mean == pytest.approx(tca.surrogate(1).series["up_x"].mean,
                                                     rel=2e-3)


def test_contradicting_velocity_sets_name_file_line_and_value(tmp_path):
    path = exported(tmp_path, lambda lines: add_material(lines, spoil=12))
    with pytest.raises(TableError) as err:
        table_import.import_table(path)
    text = str(err.value)
    assert str(path) in text and "line 13" in text and "ugm_x_m_s" in text
    assert "contradict" in text


def test_velocity_columns_go_together(tmp_path):
    def drop_vc_y(lines):
        head = next(i for i, ln in enumerate(lines) if ln.startswith("phi_p_deg"))
        j = lines[head].split(",").index("vc_y_m_s")
        return lines[:head] + [",".join(c for n, c in enumerate(ln.split(",")) if n != j)
                               for ln in lines[head:]]
    with pytest.raises(TableError, match="vc_y_m_s"):
        table_import.import_table(exported(tmp_path, drop_vc_y))


def test_the_contact_point_velocity_comes_as_a_pair(tmp_path):
    """vc_x without vc_y is refused by the reader (absent both: a fixed contact point)."""
    path = synthetic(tmp_path / "half.txt")
    text = "\n".join(ln for ln in path.read_text().splitlines() if not ln.startswith("vc_y"))
    path.write_text(text + "\n")
    with pytest.raises(GearsetFileError, match="vc_y.mean"):
        read_gearset(path)


# --- the direction of the contact's lengthwise travel (docs/physics.md §10.4) --------------------

def developed_pitch_plane(beta, alpha):
    """Unit vectors of the developed pitch plane at a mean point: cone element towards the heel,
    direction of motion, pitch-plane normal; then the tooth trace (towards the heel), the flank
    normal and the profile direction of a flank at normal pressure angle alpha."""
    e_cone, e_circ, e_h = np.eye(3)
    trace = math.cos(beta) * e_cone + math.sin(beta) * e_circ
    perp = -math.sin(beta) * e_cone + math.cos(beta) * e_circ
    normal = math.cos(alpha) * perp + math.sin(alpha) * e_h
    profile = math.sin(alpha) * perp - math.cos(alpha) * e_h
    return e_cone, e_circ, trace, normal, profile


def test_the_tooth_meshes_first_at_the_end_its_surface_moves_towards():
    """Pure geometry, no model code: a tooth whose trace leans by β towards the direction of
    motion at the heel (the surrogate's convention, lengthwise velocity V sin β > 0 towards the
    heel) reaches a fixed entry line along the cone element with its heel first; its material
    moves lengthwise towards that end; and this is the lean for which the push on the driving
    flank has the pinion's thrust out of mesh, the drive side of an automotive axle. The contact
    lines then sweep the flank from the heel to the toe, so a contact path without bias runs
    against the surfaces' lengthwise motion."""
    beta, V, half_face = math.radians(46.0), 6.6, 0.015
    e_cone, e_circ, trace, _, _ = developed_pitch_plane(beta, math.radians(16.67))
    ends = {"toe": -half_face * trace, "heel": +half_face * trace}
    entry = 0.05  # the entry line e_circ . x = entry, ahead of the tooth
    t_cross = {end: (entry - x @ e_circ) / V for end, x in ends.items()}
    assert t_cross["heel"] < t_cross["toe"]
    assert V * e_circ @ trace > 0.0  # material lengthwise velocity points to the heel
    # the driving flank faces the motion; the mating tooth's push on it points away from the
    # apex (the automotive drive-side rule, thrust out of mesh) exactly for this lean
    perp = np.cross([0.0, 0.0, 1.0], trace)
    facing = perp if perp @ e_circ > 0 else -perp
    assert (-facing) @ e_cone > 0.0
    mirrored = math.cos(beta) * e_cone - math.sin(beta) * e_circ  # trace leaning the other way
    perp = np.cross([0.0, 0.0, 1.0], mirrored)
    facing = perp if perp @ e_circ > 0 else -perp
    assert (-facing) @ e_cone < 0.0  # then the toe would lead and the thrust point to the apex


@pytest.mark.parametrize("flank", ["drive", "coast"])
@pytest.mark.parametrize("n", [1, 2, 3])
def test_the_surrogate_contact_travels_from_heel_to_toe_over_the_flank(n, flank):
    """The surrogate's path follows that argument on both flanks of every set (forward rotation:
    the same end meshes first on both flanks): its cone distance falls along the engagement (R_p
    of §10.6), the pinion surface moves lengthwise relative to the contact towards the heel, the
    contact moves in the tangent plane only along the line of contact (the major axis y), and
    its velocity in space, built in 3-D from the frame of the developed pitch plane, changes its
    cone distance at exactly dy/dφ_p = −TRAVEL b_2 N_p/(2π ε_TCA) (so v_c, R_p and the path
    agree)."""
    from hypoid.tca import loaded as tl
    from hypoid.tca import surrogate as sur
    gs = tl.flank_set(sur.TABLE_1[n], flank)
    bl = gs.blank
    xi = np.linspace(0.0, 1.0, 11)
    y = sur.lengthwise_position(gs, xi)
    assert np.all(np.diff(y) < 0.0) and y[0] > 0.0  # heel (y > 0) first
    s = sur.roll(gs, xi)
    (up_x, up_y), _ = sur.surface_velocities(gs, s)
    vc_x, vc_y = (np.full_like(s, v) for v in sur.contact_point_velocity(gs))
    e_len = np.array([math.sin(gs.beta_B), math.cos(gs.beta_B)])  # lengthwise in the ellipse frame
    up = np.stack([up_x, up_y], axis=-1)
    vc = np.stack([vc_x, vc_y], axis=-1)
    assert np.all((up - vc) @ e_len > 0.0)  # pinion surface relative to the contact: to the heel
    np.testing.assert_allclose(vc_x, 0.0, atol=1e-15)  # along the line of contact only
    e_cone, _, trace, normal, profile = developed_pitch_plane(bl.beta_m1, gs.alpha_nD)
    e_y = -math.sin(gs.beta_B) * profile + math.cos(gs.beta_B) * trace  # major axis in 3-D
    v_perp = gs.r_m1 * math.cos(bl.beta_m1)
    dy = -sur.TRAVEL * bl.b_2 * bl.N_p / (2.0 * math.pi * gs.eps_TCA)
    for k in range(len(xi)):
        v_c = vc_y[k] * e_y + v_perp * math.cos(gs.alpha_nD) * normal
        assert v_c @ e_cone == pytest.approx(dy, rel=1e-12)
        # the pinion's material at the pitch point does not change its cone distance
        material = gs.r_m1 * math.sin(bl.beta_m1) * trace + v_perp * (
            math.sin(gs.alpha_nD) * profile + math.cos(gs.alpha_nD) * normal)
        assert material @ e_cone == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize("travel", [0.5, 0.0, -0.5])
@pytest.mark.parametrize("n", [1, 2, 3])
def test_the_pinion_rolls_across_the_line_of_contact_at_the_helical_speed(monkeypatch, n, travel):
    """The helical limit (docs/physics.md §10.4), with the line of contact at the pinion's own
    angle atan(tan β_m1 sin α_nD) on the flank: a helical pinion rolls across its line of contact
    at V_1 sin α_t, tan α_t = tan α_nD / cos β_m1, at the pitch point (the sum velocity
    v_ΣC = 2 v_t sin α_wt of ISO/TR 14179-2). Independently, in 3-D: the contact point of the
    pinion's virtual helical gear that keeps its cone distance moves along the transverse line of
    action (perpendicular to the cone element and to the transverse profile n × e_cone) with the
    flank's normal velocity; the pinion's material relative to it is V_1 sin α_t long and lies
    across the line of contact, and the surrogate's rolling across the line agrees with it
    whatever the travel along the face (which runs along the line). A surrogate whose contact
    travelled lengthwise, with no profile component, rolled at about half of it with no travel
    (docs/decisions.md, "Kinematics")."""
    from functools import cached_property
    from hypoid.tca import surrogate as sur

    class HelicalLine(sur.GearSet):
        @cached_property
        def beta_B(self):
            return math.atan(math.tan(self.blank.beta_m1) * math.sin(self.alpha_nD))

    monkeypatch.setattr(sur, "TRAVEL", travel)
    gs = HelicalLine(sur.TABLE_1[n])
    b, a = gs.blank.beta_m1, gs.alpha_nD
    (up_x, up_y), _ = sur.surface_velocities(gs, 0.0)
    vc_x, vc_y = sur.contact_point_velocity(gs)
    alpha_t = math.atan(math.tan(a) / math.cos(b))
    assert float(up_x) - vc_x == pytest.approx(gs.r_m1 * math.sin(alpha_t), rel=1e-12)
    e_cone, e_circ, trace, normal, profile = developed_pitch_plane(b, a)
    material = gs.r_m1 * e_circ
    line = np.cross(e_cone, np.cross(normal, e_cone))  # transverse line of action (unnormalised)
    v_exact = (material @ normal) / (line @ normal) * line
    w = material - v_exact
    assert w @ e_cone == pytest.approx(0.0, abs=1e-15)  # both keep the cone distance
    assert w @ trace == pytest.approx(gs.r_m1 * math.sin(b) * math.sin(alpha_t) ** 2, rel=1e-12)
    assert np.linalg.norm(w) == pytest.approx(gs.r_m1 * math.sin(alpha_t), rel=1e-12)
    e_x = math.cos(gs.beta_B) * profile + math.sin(gs.beta_B) * trace
    e_y = -math.sin(gs.beta_B) * profile + math.cos(gs.beta_B) * trace
    assert w @ e_y == pytest.approx(0.0, abs=1e-15)  # across the line of contact
    assert float(up_x) - vc_x == pytest.approx(w @ e_x, rel=1e-12)


def test_surrogate_contact_point_velocity_of_set_1_by_hand():
    """λ = (dy/dt + V_1 cos² α_nD sin β_m1 cos β_m1)/(sin β_B sin α_nD sin β_m1 + cos β_B cos β_m1)
    by hand from the figures of the file's header (r_m1 31.57 mm, β_m1 46°, α_nD 16.67°,
    ε_TCA 2.524, β_B 14.35°) at 2000 rpm: V_1 = 6.612 m/s, dy/dt = −2.576 m/s (0.5 b_2 = 15 mm
    over 2.524 of 13 teeth), so λ = (−2.576 + 3.032)/0.7241 = 0.630 m/s along the major axis,
    nothing across it (docs/physics.md §10.4)."""
    from hypoid.tca import surrogate as sur
    w = 2000 * math.pi / 30
    b, a, bB = math.radians(46.0), math.radians(16.67), math.radians(14.35)
    dy = -0.5 * 0.030 * 13 * w / (2 * math.pi * 2.524)
    by_hand = ((dy + 0.03157 * w * math.cos(a) ** 2 * math.sin(b) * math.cos(b))
               / (math.sin(bB) * math.sin(a) * math.sin(b) + math.cos(bB) * math.cos(b)))
    assert by_hand == pytest.approx(0.630, abs=0.002)
    vc_x, vc_y = sur.contact_point_velocity(sur.GearSet(sur.TABLE_1[1]))
    assert vc_x == 0.0 and vc_y * w == pytest.approx(by_hand, rel=2e-3)
    s = tca.surrogate(1).series
    assert abs(s["vc_x"].mean) < 1e-15
    assert s["vc_y"].mean * w == pytest.approx(by_hand, rel=2e-3)