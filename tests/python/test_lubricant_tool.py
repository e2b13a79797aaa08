"""Tests of `hypoid lubricant` (hypoid/lubricant.py): the Vogel fit of physics.md 4.1, the file
it writes, the built-in files, and clear errors for bad data-sheet values."""

import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

from hypoid import lubricant as lub  # noqa: E402

REPO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")

# physics.md 4.1: the assumed 75W-90 data and the fit result
KV40, KV100, RHO15 = 100.0, 15.0, 870.0
ETA_TABLE = {20: 237.6, 40: 85.6, 60: 38.8, 80: 20.6, 100: 12.3, 120: 8.0, 140: 5.6, 160: 4.1,
             200: 2.5}  # mPa s

USER = dict(name="My oil", kv40=KV40, kv100=KV100, rho15=RHO15, alpha_star=(16.09, 11.59, 9.38),
            alpha_temps=(40.0, 100.0, 140.0), hn_lambda=7.9e-8, hn_alpha=0.7, hn_beta=1.0,
            k_f=0.18, c_p=2090.0)


def parse(text):
    """Minimal reader of the key/value format (docs/data-files.md) for checking output."""
    lines = [ln.split("#", 1)[0].strip() for ln in text.splitlines()]
    lines = [ln for ln in lines if ln]
    header, values = lines[0], {}
    for ln in lines[1:]:
        key, _, rest = ln.partition(" ")
        assert key not in values, f"duplicate key {key}"
        values[key] = rest.strip()
    return header, values


def test_walther_constants():
    a, b = lub.walther_fit(KV40, KV100)
    assert a == pytest.approx(7.6447, abs=5e-5)
    assert b == pytest.approx(2.9422, abs=5e-5)
    assert lub.walther_nu(a, b, 40.0) == pytest.approx(KV40, rel=1e-12)
    assert lub.walther_nu(a, b, 100.0) == pytest.approx(KV100, rel=1e-12)


def test_vogel_fit_reproduces_physics_4_1():
    a, b, c = lub.fit_vogel(KV40, KV100, RHO15)
    assert a == pytest.approx(7.560e-5, rel=0.005)
    assert b == pytest.approx(1109.3, rel=0.005)
    assert c == pytest.approx(-117.8, rel=0.005)
    # tighter than the rounding of physics.md: the same numbers to 4 digits
    assert a == pytest.approx(7.560e-5, rel=1e-3)
    assert b == pytest.approx(1109.3, abs=0.05)
    assert c == pytest.approx(-117.8, abs=0.05)
    for t, eta in ETA_TABLE.items():
        # the table is printed to 3 or 2 significant digits: within 0.5 % or half a digit
        tol = max(0.005 * eta, 0.05)
        assert 1e3 * lub.vogel_eta(a, b, c, t) == pytest.approx(eta, abs=tol), t


def test_vogel_fit_is_exact_through_its_three_points():
    a, b, c = lub.fit_vogel(KV40, KV100, RHO15)
    wa, wb = lub.walther_fit(KV40, KV100)
    for t in (40.0, 100.0, lub.T_THIRD):
        eta = lub.walther_nu(wa, wb, t) * 1e-6 * lub.density(RHO15, t)
        assert lub.vogel_eta(a, b, c, t) == pytest.approx(eta, rel=1e-9)


def test_density_law():
    assert lub.density(870.0, 15.0) == 870.0
    assert lub.density(870.0, 115.0) == pytest.approx(870.0 * (1 - 0.065))


def test_written_file(tmp_path):
    out = tmp_path / "oil.txt"
    argv = ["--name", "My oil", "--kv40", "100", "--kv100", "15", "--rho15", "870",
            "--alpha-star", "16.09", "11.59", "9.38", "--hn-lambda", "7.9e-8", "--hn-alpha",
            "0.7", "--k-f", "0.18", "-o", str(out)]
    assert lub.main(argv) == 0
    header, v = parse(out.read_text())
    assert header == "hypoid-lubricant 1"
    assert set(v) == {"name", "vogel_a", "vogel_b", "vogel_c", "alpha_star_T1", "alpha_star_1",
                      "alpha_star_T2", "alpha_star_2", "alpha_star_T3", "alpha_star_3",
                      "hn_lambda", "hn_alpha", "hn_beta", "k_f", "c_p", "rho_15"}
    assert v["name"] == "My oil"
    assert float(v["vogel_c"]) == pytest.approx(273.15 - 117.75, abs=0.01)
    assert float(v["alpha_star_T2"]) == pytest.approx(373.15)
    assert float(v["alpha_star_2"]) == pytest.approx(11.59e-9)
    assert float(v["hn_beta"]) == 1.0 and float(v["c_p"]) == 2090.0


def test_builtin_files_are_current(tmp_path):
    """resources/lubricants/ holds exactly what --builtin writes (regenerate if this fails)."""
    assert lub.main(["--builtin", "--out-dir", str(tmp_path)]) == 0
    for name in ("OS265962", "OS265963"):
        fresh = (tmp_path / f"{name}.txt").read_text()
        with open(os.path.join(REPO, "resources", "lubricants", f"{name}.txt")) as fh:
            assert fh.read() == fresh, f"{name}.txt is stale: run `hypoid lubricant --builtin`"
        _, v = parse(fresh)
        assert v["name"] == name
        assert float(v["k_f"]) == 0.18
    _, v2 = parse((tmp_path / "OS265962.txt").read_text())
    _, v3 = parse((tmp_path / "OS265963.txt").read_text())
    assert float(v2["alpha_star_1"]) == pytest.approx(16.09e-9)
    assert float(v3["alpha_star_3"]) == pytest.approx(12.28e-9)
    assert float(v2["hn_alpha"]) == 0.70 and float(v3["hn_alpha"]) == 0.97
    assert float(v2["hn_lambda"]) == 7.9e-8 and float(v3["hn_lambda"]) == 8.0e-8
    assert "0.80" in (tmp_path / "OS265963.txt").read_text()  # the k_f note


def test_cli_dispatch(tmp_path):
    from hypoid import cli
    assert cli.main(["lubricant", "--builtin", "--out-dir", str(tmp_path)]) == 0
    assert (tmp_path / "OS265963.txt").exists()


@pytest.mark.parametrize("change, message", [
    (dict(kv100=120.0), "KV100 = 120 mm^2/s must be below KV40"),
    (dict(kv40=-5.0), "KV40 = -5"),
    (dict(kv40=float("nan")), "KV40 = nan is not a finite number"),
    (dict(rho15=8700.0), "rho15 = 8700"),
    (dict(alpha_star=(16.09, 11.59)), "exactly three"),
    (dict(alpha_star=(9.0, 11.59, 16.0)), "must not increase with temperature"),
    (dict(alpha_star=(16.09, 0.0, 9.38)), "alpha* value 2 = 0"),
    (dict(alpha_temps=(40.0, 30.0, 140.0)), "must increase"),
    (dict(hn_alpha=1.5), "HN alpha = 1.5"),
    (dict(hn_alpha=0.7, hn_beta=2.0), "HN alpha * beta"),
    (dict(hn_lambda=-1e-8), "HN lambda"),
    (dict(k_f=0.0), "k_f = 0"),
    (dict(c_p=1.0), "c_p = 1"),
    (dict(name="oil # 2"), "must not contain '#'"),
    (dict(name="  "), "name is empty"),
])
def test_bad_values_raise_clear_errors(change, message):
    args = dict(USER, **change)
    with pytest.raises(lub.LubricantError) as exc:
        lub.build(**args)
    assert message in str(exc.value)


def test_unfittable_viscosities():
    # a viscosity-temperature curve flatter than any Vogel law with c above absolute zero
    with pytest.raises(lub.LubricantError, match="Vogel"):
        lub.fit_vogel(16.0, 15.9, 870.0)


def test_main_reports_errors(tmp_path, capsys):
    rc = lub.main(["--name", "x", "--kv40", "100", "--kv100", "150", "--rho15", "870",
                   "--alpha-star", "16", "11", "9", "--hn-lambda", "1e-7", "--hn-alpha", "0.7",
                   "--k-f", "0.18", "-o", str(tmp_path / "x.txt")])
    assert rc == 2
    err = capsys.readouterr().err
    assert "hypoid lubricant: error:" in err and "KV100" in err
    assert not (tmp_path / "x.txt").exists()
    assert lub.main(["--name", "x"]) == 2
    assert "missing --kv40" in capsys.readouterr().err
    assert lub.main(["--kv40", "abc"]) == 2  # argparse: not a number
