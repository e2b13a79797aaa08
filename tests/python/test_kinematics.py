"""Kinematics of the tooth data (issue 10 item 1): friction torques and power from the material
flank velocities (r x F), entrainment from the velocities relative to the moving contact point.
A synthetic gear set with constant series whose contact point moves: torques, sliding and
entrainment known in closed form. And the TCA import's two velocity sets."""

import math

import numpy as np
import pytest
from fmpy import simulate_fmu

from hypoid import tca
from hypoid.gearset_file import Gearset, GearsetFileError, Series, read_gearset, write_gearset
from hypoid.variables import ENUMERATIONS

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
    assert tca.main(["export-csv", "--set", "1", "--out", str(path), "--rows", "360"]) == 0
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
    imported = tca.import_table(exported(tmp_path))
    direct = tca.surrogate(1)
    for key in ("up_x", "up_y", "ug_x", "ug_y", "vc_x", "vc_y"):
        assert imported.series[key].mean == pytest.approx(direct.series[key].mean, rel=2e-3), key


def test_consistent_velocity_sets_are_accepted(tmp_path):
    both = tca.import_table(exported(tmp_path, add_material))
    assert both.series["up_x"].mean == pytest.approx(tca.surrogate(1).series["up_x"].mean,
                                                     rel=2e-3)


def test_contradicting_velocity_sets_name_file_line_and_value(tmp_path):
    path = exported(tmp_path, lambda lines: add_material(lines, spoil=12))
    with pytest.raises(tca.TableError) as err:
        tca.import_table(path)
    text = str(err.value)
    assert str(path) in text and "line 13" in text and "ugm_x_m_s" in text
    assert "contradict" in text


def test_velocity_columns_go_together(tmp_path):
    def drop_vc_y(lines):
        head = next(i for i, ln in enumerate(lines) if ln.startswith("phi_p_deg"))
        j = lines[head].split(",").index("vc_y_m_s")
        return lines[:head] + [",".join(c for n, c in enumerate(ln.split(",")) if n != j)
                               for ln in lines[head:]]
    with pytest.raises(tca.TableError, match="vc_y_m_s"):
        tca.import_table(exported(tmp_path, drop_vc_y))


def test_the_contact_point_velocity_comes_as_a_pair(tmp_path):
    """vc_x without vc_y is refused by the reader (absent both: a fixed contact point)."""
    path = synthetic(tmp_path / "half.txt")
    text = "\n".join(ln for ln in path.read_text().splitlines() if not ln.startswith("vc_y"))
    path.write_text(text + "\n")
    with pytest.raises(GearsetFileError, match="vc_y.mean"):
        read_gearset(path)


def test_surrogate_contact_point_speed_of_set_1():
    """|v_c| = TRAVEL b_2 N_p ω_p/(2π ε_TCA) by hand: travel 0.5 b_2 of b_2 = 30 mm (Table 1)
    over ε_TCA = 2.524 mesh cycles of 13 teeth at 2000 rpm: 2.58 m/s (docs/physics.md §10.4),
    and along the contact frame's axes at β_B = 14.35° to the major axis."""
    s = tca.surrogate(1).series
    w = 2000 * math.pi / 30
    by_hand = 0.5 * 0.030 * 13 * w / (2 * math.pi * 2.524)
    assert by_hand == pytest.approx(2.58, abs=0.005)
    assert math.hypot(s["vc_x"].mean, s["vc_y"].mean) * w == pytest.approx(by_hand, rel=1e-3)
    assert math.degrees(math.atan2(s["vc_x"].mean, s["vc_y"].mean)) == pytest.approx(14.35,
                                                                                   abs=0.01)
