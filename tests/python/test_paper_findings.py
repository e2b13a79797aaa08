"""The paper's findings (Paouris et al. 2016, §3) checked on the FMU with a reduced grid, using
the same measures as the study report (hypoid.study.findings). Where the surrogate tooth contact data
cannot reproduce a finding at the paper's speed, the test is a strict xfail that documents it
(docs/records/paper-findings.md): it turns into a failure the day the FMU does reproduce it.

The default study itself (about 12 s on two idle cores) runs too, and every verdict of its report
is checked against the claims and against the recorded study the findings page is written from.
"""

import json
import pathlib

import pytest

from hypoid.study import findings as fd
from hypoid.fmu import parallel
from hypoid.study import steady, paper as study, sweep

T_LOW, T_HIGH = (50.0, 100.0), (200.0, 300.0)
LUB_SPEEDS = [1000, 2000, 3500, 5000]
MODE2_SPEEDS = [1000, 1200, 1400]  # resonance of mode 2 at 1203 rpm, +-200 rpm for the trend
MODE3_SPEEDS = [1800, 2000, 2200]  # mode 3 at 2000 rpm: the paper's resonance
SET_SPEEDS = [800, 1500, 3000, 5000]  # away from the resonances of gear sets 2 and 3
JUMP_SPEEDS = [1125, 1150, 1175, 1200]  # 50 N.m through mode 2
PAPER_JUMP_SPEEDS = [1950, 2000, 2050]  # 100 N.m through mode 3 (paper Fig. 9)


@pytest.fixture(scope="module")
def tables(fmu_path, tmp_path_factory):
    out = tmp_path_factory.mktemp("findings")
    swapped = study.swapped_lubricant(out)
    g1 = {"gear_set": 1, "lubricant": 1}
    pts = sweep.grid({**g1, "T_s": 100}, {"lubricant": [1, 2], "speed_rpm": LUB_SPEEDS})
    pts += sweep.grid({**g1, "T_s": 100, "lubricant_file": swapped}, {"speed_rpm": LUB_SPEEDS})
    pts += sweep.grid(g1, {"T_s": [*T_LOW, *T_HIGH], "speed_rpm": MODE2_SPEEDS + MODE3_SPEEDS})
    pts += sweep.grid({"lubricant": 1, "T_s": 100}, {"gear_set": [2, 3], "speed_rpm": SET_SPEEDS})
    pts = study.unique(sweep.complete(study.paper_ehl(pts)))  # the paper's EHL choices
    sweeps = [({k: v for k, v in p.items() if k != "speed_rpm"}, s)
              for p, s in ((sweep.complete(study.paper_ehl([{**g1, "T_s": 50}]))[0], JUMP_SPEEDS),
                           (sweep.complete(study.paper_ehl([{**g1, "T_s": 100}]))[0],
                            PAPER_JUMP_SPEEDS))]
    settings, fmu = steady.Settings(), parallel.FmuRef(fmu_path)
    with parallel.executor(workers=2) as client:  # both cores: ~10 s CPU each
        cont, points = sweep.execute([sweep.SweepsPlan(sweeps, out, fmu, settings),
                                      sweep.PointsPlan(pts, out, fmu, settings)], fmu, client)
    assert (points["status"] == "ok").all() and (cont["status"] == "ok").all()
    return fd.prepare(points), fd.prepare(cont)


def test_resonance_speeds_of_gear_set_1(tables):
    """Mode 3 is calibrated to the paper's 2000 rpm (docs/physics.md §8.4); mode 2 then sits near
    1200 rpm. If this moves, docs/records/paper-findings.md and the speeds above need revisiting."""
    res = fd.resonances(tables[0], 1)
    assert res["f3"] == pytest.approx(2000.0, rel=0.02)
    assert res["f2"] == pytest.approx(1204.0, rel=0.03)


def test_higher_alpha_oil_is_less_efficient_at_every_speed(tables):
    f = fd.lubricant_ranking(tables[0])
    assert f["verdict"] == "reproduced", f["this FMU"]


def test_other_oils_pressure_viscosity_data_closes_most_of_the_gap(tables):
    f = fd.swapped_alpha(tables[0])
    assert f["verdict"] == "reproduced", f["this FMU"]


def test_efficiency_dips_at_the_mode2_resonance_and_the_dip_fades_with_torque(tables):
    f, dips = fd.resonance_dips(tables[0], "f2")
    assert f["verdict"] == "reproduced", f["this FMU"]
    assert dips[50.0] > dips[200.0] and dips[100.0] > dips[300.0]


def test_jump_two_branches_and_tooth_separation_at_50Nm_mode2(tables):
    pts, cont = tables
    f, j = fd.jump_finding(cont, 50.0, "f2", pts)
    assert f["verdict"] == "reproduced", f["this FMU"]
    assert j["max_contact_loss"] > 0.1


def test_near_resonance_teeth_separate_and_friction_vanishes_mode2(tables):
    row = fd.contact_loss_at(tables[0], 1200.0, 100.0)
    assert row["contact_loss_fraction"] > 0.05 and row["DTE_min_minus_b_um"] < 0


def test_gear_set_2_more_efficient_than_gear_set_3_away_from_resonance(tables):
    f = fd.gear_sets(tables[0])
    assert f["verdict"] == "reproduced", f["this FMU"]


@pytest.mark.xfail(strict=True, reason="surrogate TCA data: at 2000 rpm (mode 3) the dip is "
                   "0.03/0.006 %-points at 50/100 N.m, below the 0.02 threshold at 100 N.m; see "
                   "docs/records/paper-findings.md F3")
def test_efficiency_dip_at_the_paper_speed_2000rpm(tables):
    f, _ = fd.resonance_dips(tables[0], "f3")
    assert f["verdict"] == "reproduced", f["this FMU"]


@pytest.mark.xfail(strict=True, reason="surrogate TCA data: no contact loss and no second branch "
                   "at 2000 rpm, 100 N.m (min DTE stays ~14 um above b); see "
                   "docs/records/paper-findings.md F4")
def test_jump_and_tooth_separation_at_the_paper_speed_2000rpm_100Nm(tables):
    pts, cont = tables
    f, j = fd.jump_finding(cont, 100.0, "f3", pts)
    assert j["min_DTE_min_minus_b_um"] < 0, f["this FMU"]


RECORD = pathlib.Path(__file__).resolve().parents[2] / "docs" / "records" / "paper-findings.json"


def test_default_study_verdicts(fmu_path, tmp_path):
    """`hypoid study default` (the study ./run.sh runs) gives the verdicts the findings page
    discusses, and the same ones as its recorded run."""
    pts, cont, _ = study.run("default", tmp_path, str(fmu_path), workers=2)
    got = fd.all_findings(pts, cont).set_index("id")["verdict"].to_dict()
    recorded = {f["id"]: f["verdict"] for f in json.loads(RECORD.read_text())["default"]["findings"]
                if f["verdict"] != "diagnostic"}
    assert got == recorded
    expected = {"F1": "reproduced", "F2": "reproduced", "F3-f2": "reproduced",
                "F3-f3": "not reproduced", "F4-f2-50": "reproduced",
                "F4-f3-50": "not reproduced", "F4-f2-100": "not reproduced",
                "F4-f3-100": "not reproduced", "F5": "reproduced", "F8": "reproduced",
                "F6-f2": "reproduced", "F6-f3": "not reproduced",
                "F3-f3-I_p=0.001": "reproduced", "F4-f3-100-I_p=0.001": "not reproduced"}
    assert {k: got.get(k) for k in expected} == expected
