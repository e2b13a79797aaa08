"""Layered gear-set files (docs/data-files.md): drive and coast flanks at several torque levels,
written by `hypoid tca surrogate --loaded`, read back by the Python reader and the FMU. The FMU
interpolates linearly on the filtered transmitted torque and uses the coast series on the back
flank; checked against the file's own series, with the energy audit closing."""

import pathlib

import numpy as np
import pytest

from hypoid.tca import gearsets as tca
from hypoid.tca import table_import
from hypoid.tca.gearset_file import GearsetFileError, read_gearset, write_gearset
from hypoid.fmu.instance import FmuError, Instance

LEVELS = (25.0, 400.0)
AUDIT = ("E_in", "E_out", "E_friction", "E_damping", "E_excitation", "E_stored")


@pytest.fixture(scope="module")
def layered(tmp_path_factory):
    path = tmp_path_factory.mktemp("layers") / "set1_loaded.txt"
    gearset = tca.loaded_surrogate(1, LEVELS)
    write_gearset(path, gearset)
    return path, gearset


def test_round_trip(layered):
    path, made = layered
    back = read_gearset(path)
    assert back.torque_levels == LEVELS and back.flanks == ("drive", "coast")
    psi = np.linspace(0.0, 2.0 * np.pi, 97)
    for key, s in made.layers.items():
        for name, series in s.items():
            y = series(psi)  # written to 10 significant digits
            assert np.allclose(back.layers[key][name](psi), y, rtol=0, atol=1e-9 * np.abs(y).max())


def test_levels_stiffen_and_flanks_differ(layered):
    g = layered[1]
    for flank in g.flanks:
        assert g.layers[(flank, 2)]["k_m"].mean > 2.5 * g.layers[(flank, 1)]["k_m"].mean  # 25 → 400 N·m
    assert g.layers[("coast", 1)]["R_p"].mean < g.layers[("drive", 1)]["R_p"].mean


def _edited(path, tmp_path, old, new):
    text = path.read_text()
    assert old in text
    out = tmp_path / "edited.txt"
    out.write_text(text.replace(old, new, 1))
    return out


@pytest.mark.parametrize("old,new,words", [
    ("torque_levels 25 400", "torque_levels 400 25", ["line 13", "value 2 = 25 N·m", "increase"]),
    ("flanks drive coast", "flanks drive back", ["line 14", "flanks 'drive back'"]),
    ("coast.2.ls.mean", "coast.2.ls.meen", ["missing key 'coast.2.ls.mean'"]),
])
def test_bad_layered_files_name_file_line_and_value(layered, tmp_path, old, new, words):
    bad = _edited(layered[0], tmp_path, old, new)
    with pytest.raises(GearsetFileError) as info:
        read_gearset(bad)
    for w in ["edited.txt"] + words:
        assert w in str(info.value), (w, str(info.value))


def test_coast_flank_missing_where_asked_for(layered, tmp_path):
    text = layered[0].read_text()
    cut = text[:text.index("# --- coast flank")]
    bad = tmp_path / "no_coast.txt"
    bad.write_text(cut)
    with pytest.raises(GearsetFileError, match="line 14: flanks 'drive coast' asks for a coast"):
        read_gearset(bad)


def _series_mean_at(g, flank, T):
    """The file's k_m mean interpolated linearly at pinion torque T, held beyond the levels."""
    means = [g.layers[(flank, i)]["k_m"].mean for i in (1, 2)]
    return float(np.interp(T, LEVELS, means))


@pytest.mark.parametrize("T_s,flank", [(300.0, "drive"), (-100.0, "coast")])
def test_fmu_interpolates_on_torque_and_takes_the_flank(layered, fmu_path, T_s, flank):
    """Mean k_m over one mesh cycle in steady running = the file's level blend at |T_s| (the
    filtered torque settles at the torque the pinion passes to the mesh, T_s less its friction
    torque), and the audit closes while the torque, and with it the stiffness, changes (to 1e-6
    of E_in with CVODE BDF at rtol 1e-6; the default solver, arkode_erk, closes it to about 4e-6
    at the same rtol)."""
    path, g = layered
    gear = Instance(fmu_path)
    gear.start({"gear_set_file": str(path), "load_mode": "speed", "T_s": T_s,
                "speed_rpm": 2000.0, "solver": "cvode_bdf"})
    E_0 = gear.get("E_stored")
    while gear.t < 0.15 - 1e-9:
        gear.step(0.005)
    period = 60.0 / (2000.0 * 13)
    k, T_fp = [], []
    for _ in range(64):
        gear.step(period / 64)
        k.append(gear.get("k_m"))
        T_fp.append(gear.get("T_fp"))
    T_mesh = abs(T_s + np.mean(T_fp))  # what the pinion passes to the mesh: T_s less its friction
    assert gear.get("contact") == (1 if flank == "drive" else -1)
    assert np.mean(k) == pytest.approx(_series_mean_at(g, flank, T_mesh), rel=0.01)
    other = "coast" if flank == "drive" else "drive"
    assert abs(np.mean(k) - _series_mean_at(g, other, T_mesh)) > 0.01 * np.mean(k)
    for i in range(40):  # torque swings: the stiffness follows through the filter
        gear.set("T_s", T_s * (1.0 + 0.5 * np.sin(0.3 * i)))
        gear.step(0.0025)
    v = {n: gear.get(n) for n in AUDIT}
    residual = (v["E_in"] - v["E_out"] - v["E_friction"] - v["E_damping"] + v["E_excitation"]
                - (v["E_stored"] - E_0))
    assert abs(residual) < 1e-6 * abs(v["E_in"])


def test_fmu_refuses_decreasing_levels(layered, fmu_path, tmp_path):
    bad = _edited(layered[0], tmp_path, "torque_levels 25 400", "torque_levels 400 25")
    gear = Instance(fmu_path)
    with pytest.raises(FmuError) as info:
        gear.start({"gear_set_file": str(bad)})
    text = str(info.value) + " ".join(str(m) for m in getattr(gear, "messages", []))
    assert "edited.txt" in text and "line 13" in text and "value 2 = 25 N m" in text, text


# --- hypoid tca import of several tables -----------------------------------------------------

def _table(tmp_path, name, torque, flank="drive", k_scale=1.0, N_p=None):
    """The surrogate of set 1 exported as a table, with torque/flank rows, k_m scaled."""
    path = tmp_path / name
    tca.export_csv(1, path, rows=240)
    lines = path.read_text().splitlines()
    head = lines.index(next(l for l in lines if l.startswith("phi_p_deg")))
    column = lines[head].split(",").index("k_m_N_per_m")
    rows = []
    for row in lines[head + 1:]:
        cells = row.split(",")
        cells[column] = f"{float(cells[column]) * k_scale:.10g}"
        rows.append(",".join(cells))
    meta = lines[:head] + [f"torque_Nm,{torque:g}", f"flank,{flank}"]
    if N_p:
        meta = [f"N_p,{N_p}" if l.startswith("N_p,") else l for l in meta]
    path.write_text("\n".join(meta + [lines[head]] + rows) + "\n")
    return str(path)


def test_import_of_torque_levels_and_both_flanks(tmp_path):
    paths = [_table(tmp_path, "d100.csv", 100, k_scale=2.0), _table(tmp_path, "d25.csv", 25),
             _table(tmp_path, "c25.csv", 25, "coast"), _table(tmp_path, "c100.csv", 100, "coast")]
    g = table_import.import_tables(paths)
    assert g.torque_levels == (25.0, 100.0) and g.flanks == ("drive", "coast")
    ratio = g.layers[("drive", 2)]["k_m"].mean / g.layers[("drive", 1)]["k_m"].mean
    assert ratio == pytest.approx(2.0, rel=1e-9)
    out = tmp_path / "imported.txt"
    write_gearset(out, g)
    assert read_gearset(out).torque_levels == (25.0, 100.0)


@pytest.mark.parametrize("tables,words", [
    ([("a.csv", 25, "drive", None), ("b.csv", 50, "drive", 14)],
     ["b.csv", "line", "value '14'", "N_p differs from 13"]),
    ([("a.csv", 25, "drive", None), ("b.csv", 25, "drive", None)],
     ["b.csv", "value 25", "a second drive table at 25 N·m"]),
    ([("a.csv", 25, "drive", None), ("b.csv", 50, "coast", None)],
     ["b.csv", "value 50", "no drive table there"]),
    ([("a.csv", 25, "drive", None), ("b.csv", 50, "drive", None), ("c.csv", 25, "coast", None)],
     ["coast tables missing at 50 N·m"]),
])
def test_import_refuses_tables_that_disagree(tmp_path, tables, words):
    paths = [_table(tmp_path, n, t, f, N_p=p) for n, t, f, p in tables]
    with pytest.raises(ValueError) as info:
        table_import.import_tables(paths)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


def test_import_cli_writes_a_layered_file_and_errors_in_one_line(tmp_path):
    import subprocess
    import sys
    a, b = _table(tmp_path, "a.csv", 25), _table(tmp_path, "b.csv", 80, k_scale=1.5)
    out = tmp_path / "two.txt"
    run = [sys.executable, "-m", "hypoid.cli", "tca", "import", a, b, "--out", str(out)]
    done = subprocess.run(run, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert read_gearset(out).torque_levels == (25.0, 80.0)
    bad = subprocess.run(run[:-2] + [a, "--out", str(out)], capture_output=True, text=True)
    assert bad.returncode == 2 and "a second drive table at 25 N·m" in bad.stderr
    assert "Traceback" not in bad.stderr and len(bad.stderr.strip().splitlines()) == 1


# --- the shipped loaded files (resources/gearsets/loaded, docs/physics.md §10.8) -----------------

SHIPPED = pathlib.Path(__file__).parents[2] / "resources" / "gearsets" / "loaded"


@pytest.mark.parametrize("n", [1, 2, 3])
def test_shipped_loaded_files_hold_the_loaded_tca_of_today(n):
    """Each shipped file is the loaded TCA of its set as the code computes it now: the drive
    flank's mean k_m at 100 N·m recomputed from the loaded model at the level's load (one level,
    not the whole file),
    the contact point's velocity of both flanks from the surrogate's kinematics (§10.4), and the
    header names the command that writes it."""
    from hypoid.tca import loaded as tl
    from hypoid.tca import surrogate as sur
    path = SHIPPED / f"gearset{n}.txt"
    g = read_gearset(path)
    assert g.torque_levels == tl.TORQUES and g.flanks == tl.FLANKS
    assert "--all --loaded --out-dir resources/gearsets/loaded" in path.read_text()
    level = tl.TORQUES.index(100.0) + 1
    model = tl.LoadedFlank(tl.flank_set(sur.TABLE_1[n], "drive"))
    k_m = tca.level_mesh(model, 100.0)[0].k_m.mean()
    assert g.layers[("drive", level)]["k_m"].mean == pytest.approx(k_m, rel=1e-9)
    for flank in tl.FLANKS:
        vc = sur.contact_point_velocity(tl.flank_set(sur.TABLE_1[n], flank))
        for i, axis in enumerate(("vc_x", "vc_y")):
            assert g.layers[(flank, 1)][axis].mean == pytest.approx(vc[i], rel=1e-9)


def test_shipped_loaded_file_runs_from_the_resources_folder(fmu_path):
    """gear_set_file relative to the FMU's resources selects a shipped loaded file."""
    gear = Instance(fmu_path)
    gear.start({"gear_set_file": "gearsets/loaded/gearset1.txt", "load_mode": "speed",
                "T_s": 100.0, "speed_rpm": 2000.0})
    gear.step(0.02)
    assert gear.get("contact") == 1 and 2.0e8 < gear.get("k_m") < 3.2e8


BUILTIN = pathlib.Path(__file__).parents[2] / "resources" / "gearsets"


def _law_tangent_mean(g, T, flank="drive", n_theta=256):
    """The mean over a mesh cycle of the tangent dW/da of a layered file's force law at the
    static load of pinion torque T (docs/physics.md §10.8, "In the FMU"): the levels' points
    (W_l/k_m,l(θ), W_l), W_l = T_l/mean R_p,l, joined by power laws; the load T over the R_p
    mean blended linearly at T; at a level's own load the mean of the slopes on either side."""
    levels = np.array(g.torque_levels)
    lay = [g.layers[(flank, l + 1)] for l in range(len(levels))]
    W_l = levels / np.array([s["R_p"].mean for s in lay])
    W_T = T / np.interp(T, levels, [s["R_p"].mean for s in lay])
    theta = 2.0 * np.pi * np.arange(n_theta) / n_theta
    a_l = W_l[:, None] / np.array([s["k_m"](theta) for s in lay])  # (levels, θ)
    k = []
    for W in (W_T * (1.0 - 1e-9), W_T * (1.0 + 1e-9)):
        l = np.clip(np.searchsorted(W_l, W) - 1, 0, len(levels) - 2)  # W in (W_l, W_l+1]
        p = np.log(W_l[l + 1] / W_l[l]) / np.log(a_l[l + 1] / a_l[l])
        k.append(p * W / (a_l[l] * (W / W_l[l]) ** (1.0 / p)))
    return float(np.mean(k))


@pytest.mark.parametrize("n", [1, 2, 3])
def test_tooth_data_picks_the_built_in_file(fmu_path, n):
    """tooth_data = loaded runs built-in gear set n on its shipped loaded file, tooth_data =
    paper on the one-series file, and preset = paper on the one-series file whatever tooth_data
    says: the FMU's mean stiffness k_m0 at the start torque (100 N·m, a level of the loaded
    files; 150 N·m, halfway between two) and its tooth counts are those the Python reader finds
    in the file (for a layered file the mean tangent of its force law, recomputed here)."""
    loaded = read_gearset(SHIPPED / f"gearset{n}.txt")
    paper = read_gearset(BUILTIN / f"gearset{n}.txt")
    k_100, k_150 = (_law_tangent_mean(loaded, T) for T in (100.0, 150.0))
    gear = Instance(fmu_path)
    try:
        for params, k_m0 in (({"tooth_data": "loaded"}, k_100),
                             ({"tooth_data": "loaded", "T_s": 150.0}, k_150),
                             ({"tooth_data": "paper"}, paper.series["k_m"].mean),
                             ({"tooth_data": "loaded", "preset": "paper"},
                              paper.series["k_m"].mean)):
            gear.start({"gear_set": n, "T_s": 100.0, **params})
            assert gear.get("k_m0") == pytest.approx(k_m0, rel=1e-9), params
            assert (gear.get("N_p"), gear.get("N_g")) == (loaded.N_p, loaded.N_g)
    finally:
        gear.close()


def test_the_built_in_maps_refuse_the_other_tooth_data(fmu_path):
    """The built-in efficiency maps are made with the default tooth data: the map level with the
    other one is refused, naming the tooth data it runs and the file the map was made for; the
    drive cycle then picks the fast level, and hypoid effmap hashes the file the FMU reads."""
    from hypoid.drivecycle import levels
    from hypoid.maps import effmap
    from hypoid.fmu.values import TABLE
    other = "paper" if TABLE.start("tooth_data") == "loaded" else "loaded"
    gear = Instance(fmu_path)
    try:
        with pytest.raises(FmuError, match=rf"tooth_data = {other}\) = 'gearsets/"):
            gear.start({"mesh_model": "rigid", "friction_model": "map", "tooth_data": other})
    finally:
        gear.close()
    assert levels.default_level(293.15, [293.15], {}) == "map"
    assert levels.default_level(293.15, [293.15], {"tooth_data": other}) == "fast"
    # preset = paper also sets the paper's friction, which the maps (made with the default
    # friction) do not hold: the fast level whichever the tooth data (docs/axle.md, "Which level
    # a --set reaches")
    assert levels.default_level(293.15, [293.15], {"preset": "paper"}) == "fast"
    files = effmap.source_files(fmu_path, {"gear_set": 2, "tooth_data": "paper"})
    assert files["gear_set"].as_posix().endswith("resources/gearsets/gearset2.txt")
    files = effmap.source_files(fmu_path, {"gear_set": 2, "tooth_data": "loaded"})
    assert files["gear_set"].as_posix().endswith("resources/gearsets/loaded/gearset2.txt")
