"""A gear set of one's own with the whole axle: gear-set files carry the gear blank the loss
ledger needs (blank.ring_d ... blank.beta_g), `hypoid tca import --blank` and `hypoid tca
surrogate --with-blank` write it, and the FMU takes it instead of eight parameters that had to be
set one per failed attempt."""

import math
import shutil

import pytest

from hypoid import cli
from hypoid.fmu.instance import FmuError, Instance, unzipped
from hypoid.tca import surrogate as sur
from hypoid.tca.gearset_file import BLANK, read_gearset, write_gearset

# Paouris et al. 2016 Table 1 as the FMU's ledger holds it (fmu-src/model/ledger.c): ring outer
# cone distance, face width, mean pitch radii, pitch and spiral angles of set 1 (mm, deg)
TABLE_1_SET_1 = {"A_e2": 95.60, "ring_b": 30.00, "r_m_p": 31.57, "r_m_g": 68.53,
                 "delta_p": 29.05, "delta_g": 59.65, "beta_p": 46.00, "beta_g": 27.60}
# the ledger's energies over the run: the blank's parts (the mesh friction is the same model
# either way; its instantaneous value moves with the step sequence, so it is left out)
OUT = ["E_churn", "E_bearings", "E_seals"]


def test_the_surrogate_blank_matches_table_1():
    b = sur.ledger_blank(1)
    t = TABLE_1_SET_1
    assert b["ring_d"] == pytest.approx(2 * t["A_e2"] * 1e-3 * math.sin(math.radians(t["delta_g"])))
    for k in ("ring_b", "r_m_p", "r_m_g"):
        assert b[k] == pytest.approx(t[k] * 1e-3, abs=0.006e-3), k  # Table 1's two decimals
    for k in ("delta_p", "delta_g", "beta_p", "beta_g"):
        assert b[k] == pytest.approx(math.radians(t[k])), k


@pytest.fixture(scope="module")
def own_files(fmu_path, tmp_path_factory):
    """The built-in loaded set 1 as a file of one's own, with and without its blank."""
    d = tmp_path_factory.mktemp("blank")
    builtin = unzipped(fmu_path) / "resources" / "gearsets" / "loaded" / "gearset1.txt"
    plain = d / "plain.txt"
    shutil.copy(builtin, plain)
    gs = read_gearset(plain)
    gs.blank = sur.ledger_blank(1)
    with_blank = d / "with_blank.txt"
    write_gearset(with_blank, gs)
    return plain, with_blank


def run(fmu_path, extra):
    w = 2000 * math.pi / 30
    with Instance(fmu_path) as inst:
        inst.start({"T_s": 100.0, "w_set": w, "w_p0": w, "load_mode": "speed",
                    "axle_losses": "full", "mesh_model": "rigid", **extra})
        inst.do_step(0.0, 0.05)
        return dict(zip(OUT, inst.reals(OUT)))


def test_a_file_with_its_blank_runs_the_whole_axle_like_the_builtin_set(fmu_path, own_files):
    """Before, a gear-set file of one's own needed eight --set parameters, one per attempt."""
    plain, with_blank = own_files
    assert read_gearset(with_blank).blank == pytest.approx(sur.ledger_blank(1), rel=1e-9)
    own = run(fmu_path, {"gear_set_file": str(with_blank)})
    by_name = run(fmu_path, {"gear_set_file": str(plain), **sur.ledger_blank(1)})
    builtin = run(fmu_path, {"gear_set": 1})
    for k in OUT:
        # the file's blank = the same eight values set by name (to the solver's tolerance)
        assert own[k] == pytest.approx(by_name[k], rel=1e-4), k
        # = the ledger's own Table 1 of the built-in set (its two decimals of mm)
        assert own[k] == pytest.approx(builtin[k], rel=2e-3), k
    with pytest.raises(FmuError, match="ring_d.*blank"):
        run(fmu_path, {"gear_set_file": str(plain)})
    # a parameter set by name still wins over the file's blank
    wide = run(fmu_path, {"gear_set_file": str(with_blank), "ring_b": 0.060})
    assert wide["E_churn"] > 1.2 * own["E_churn"]  # a face twice as wide churns more


def test_a_partial_blank_is_refused_naming_the_missing_key(fmu_path, own_files, tmp_path):
    _, with_blank = own_files
    text = "\n".join(ln for ln in with_blank.read_text().splitlines()
                     if not ln.startswith("blank.beta_g"))
    bad = tmp_path / "partial.txt"
    bad.write_text(text + "\n")
    with pytest.raises(FmuError, match="blank.beta_g"):
        run(fmu_path, {"gear_set_file": str(bad)})
    with pytest.raises(ValueError, match="blank.beta_g missing"):
        read_gearset(bad)


def test_tca_import_writes_the_blank_and_refuses_an_impossible_one(tmp_path, capsys):
    table = tmp_path / "set1.csv"
    assert cli.main(["tca", "export-csv", "--set", "1", "--out", str(table)]) == 0
    blank = [f"{k}={v!r}" for k, v in sur.ledger_blank(1).items()]
    out = tmp_path / "own.txt"
    assert cli.main(["tca", "import", str(table), "--out", str(out), "--blank", *blank]) == 0
    assert read_gearset(out).blank == pytest.approx(sur.ledger_blank(1), rel=1e-9)
    capsys.readouterr()
    for bad, words in ((["delta_p=2.0"], ["blank.delta_p = 2", "rad"]),
                       (["ring_d=-0.1"], ["blank.ring_d = -0.1"]),
                       (["ring_d=0.1"], ["blank.ring_b missing"]),
                       (["colour=1"], ["--blank", "colour"])):
        items = [b for b in blank if not b.startswith(bad[0].split("=")[0] + "=")] + bad \
            if "missing" not in words[0] else bad
        target = tmp_path / "bad.txt"
        assert cli.main(["tca", "import", str(table), "--out", str(target), "--blank",
                         *items]) == 2
        err = capsys.readouterr().err
        assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
        for w in words:
            assert w in err, (w, err)
        assert not target.exists()
    assert set(BLANK) == set(sur.ledger_blank(1))


def test_surrogate_with_blank(tmp_path):
    out = tmp_path / "s.txt"
    assert cli.main(["tca", "surrogate", "--set", "2", "--with-blank", "--out", str(out)]) == 0
    assert read_gearset(out).blank == pytest.approx(sur.ledger_blank(2), rel=1e-9)


# ---------------------------------------------------------------------------- design data
def design_text(n, **change):
    """Table 1's set n as a design file (mm, deg), with keys changed."""
    bl = sur.TABLE_1[n]
    g = {"N_p": bl.N_p, "N_g": bl.N_g, "b_p_mm": bl.b_1 * 1e3, "b_g_mm": bl.b_2 * 1e3,
         "delta_p_deg": math.degrees(bl.delta_1), "delta_g_deg": math.degrees(bl.delta_2),
         "beta_p_deg": math.degrees(bl.beta_m1), "beta_g_deg": math.degrees(bl.beta_m2),
         "R_e_p_mm": bl.R_e1 * 1e3, "R_e_g_mm": bl.R_e2 * 1e3, "offset_mm": bl.a * 1e3,
         "alpha_n_deg": 20.0, "hand": "left", **change}
    return "[gear]\n" + "".join(f"{k} = {v!r}\n" if not isinstance(v, str) else f'{k} = "{v}"\n'
                                for k, v in g.items())


@pytest.mark.parametrize("n", [1, 2, 3])
def test_design_data_of_the_builtin_sets_pass_iso_23509s_relations(tmp_path, n):
    from hypoid.tca.design import read_design

    f = tmp_path / "d.toml"
    f.write_text(design_text(n))
    blank, _, hand = read_design(f)
    assert hand == "left"
    for field in ("N_p", "N_g", "b_1", "b_2", "delta_1", "delta_2", "beta_m1", "beta_m2", "R_e1",
                  "R_e2", "a"):
        assert getattr(blank, field) == pytest.approx(getattr(sur.TABLE_1[n], field), rel=1e-12)


def test_design_writes_the_builtin_loaded_file_from_table_1(tmp_path, fmu_path):
    """Set 3 from its design data at the built-in files' first torque level: the same series
    as resources/gearsets/loaded/gearset3.txt's level 1, both flanks, and the blank."""
    from hypoid.tca import loaded as tl

    f = tmp_path / "set3.toml"
    f.write_text(design_text(3, name="set 3 again"))
    out = tmp_path / "set3.txt"
    assert cli.main(["tca", "design", str(f), "--out", str(out), "--torques",
                     str(tl.TORQUES[0])]) == 0
    own = read_gearset(out)
    ref = read_gearset(unzipped(fmu_path) / "resources" / "gearsets" / "loaded" / "gearset3.txt")
    assert own.flanks == ref.flanks == ("drive", "coast")
    for flank in own.flanks:
        for key, s in own.layers[(flank, 1)].items():
            r = ref.layers[(flank, 1)][key]
            assert s.mean == pytest.approx(r.mean, rel=1e-9, abs=1e-15), (flank, key)
    assert own.blank == pytest.approx(sur.ledger_blank(3), rel=1e-9)
    assert "set 3 again" in own.name


@pytest.mark.parametrize("change, words", [
    ({"offset_mm": 90.0}, ["offset_mm", "beyond the ring's pitch radius"]),
    ({"beta_g_deg": 20.0}, ["beta_g_deg", "do not close"]),
    ({"delta_g_deg": 75.0}, ["delta_g_deg", "no offset angle"]),
    ({"R_e_g_mm": 140.0}, ["R_e_g_mm", "mean cone distance"]),
    ({"alpha_n_deg": 22.5}, ["alpha_n_deg", "20 deg"]),
    ({"N_p": 0}, ["N_p", "positive"]),
    ({"module": 3.0}, ["module", "unknown key"]),
])
def test_impossible_design_data_are_one_line_and_write_nothing(tmp_path, capsys, change, words):
    f = tmp_path / "bad.toml"
    f.write_text(design_text(1, **change))
    out = tmp_path / "bad.txt"
    assert cli.main(["tca", "design", str(f), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err and "bad.toml" in err
    for w in words:
        assert w in err, (w, err)
    assert not out.exists()
