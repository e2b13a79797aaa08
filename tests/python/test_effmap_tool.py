"""`hypoid effmap` for one's own gear set and lubricant: grid options and
--set, maps that record what they were made from, and the FMU refusing a map made for another
gear set or lubricant (naming both)."""

import pathlib
import re
import shutil

import pytest

from hypoid import cli
from hypoid.maps import effmap
from hypoid.fmu.instance import FmuError, Instance

ROOT = pathlib.Path(__file__).resolve().parents[2]
GRID = ["--speeds-rpm", "1000,3000", "--torques", "50,150", "--temperatures-c", "40,100"]


def keys(path):
    """{key: rest of line} of a map file (comments left out)."""
    out = {}
    for line in pathlib.Path(path).read_text().splitlines():
        words = line.split("#", 1)[0].split(None, 1)
        if len(words) == 2:
            out[words[0]] = words[1].strip()
    return out


@pytest.fixture(scope="module")
def own_map(fmu_path, tmp_path_factory):
    """A small map of a gear-set file of one's own (a copy of set 2) with lubricant 2."""
    d = tmp_path_factory.mktemp("effmap")
    gear = d / "my_set.txt"
    shutil.copy(ROOT / "resources" / effmap.builtin_gear_set({"gear_set": 2}), gear)
    out = d / "my_map.txt"
    assert cli.main(["effmap", "--fmu", str(fmu_path), "--out", str(out), "--gear-set-file",
                     str(gear), "--lubricant", "2", "--set", "k_f=0.15", "--workers", "0",
                     *GRID]) == 0
    return out, gear


def test_map_records_what_it_was_made_from(own_map):
    out, gear = own_map
    k = keys(out)
    lines = out.read_text().splitlines()
    assert next(x for x in lines if not x.startswith("#")) == effmap.MAGIC
    assert "# Speeds: as given." in lines  # a grid given as numbers is not banded
    assert k["gear_set_hash"] == effmap.content_hash(gear)
    assert k["gear_set_source"] == str(gear)
    lub = ROOT / "resources" / "lubricants" / "OS265963.txt"
    assert k["lubricant_hash"] == effmap.content_hash(lub)
    assert k["lubricant_source"] == "lubricants/OS265963.txt"
    assert k["model_version"] == "0.1.0"
    assert "k_f=0.15" in out.read_text()  # the settings, in the header comments
    assert [float(x) for x in k["speeds"].split()] == pytest.approx([1000 * 3.14159265 / 30,
                                                                     3000 * 3.14159265 / 30])
    assert k["torques"] == "50 150" and k["temperatures"] == "313.15 373.15"
    assert len(k["drive.1"].split()) == 4 and len(k["coast.2"].split()) == 4


def run_map(fmu_path, values):
    with Instance(fmu_path) as inst:
        inst.start({"mesh_model": "rigid", "friction_model": "map", "speed_rpm": 2000,
                    **values})
        inst.step(0.01)
        return inst.get("eta")


def test_fmu_runs_the_map_with_its_own_files(fmu_path, own_map):
    out, gear = own_map
    eta = run_map(fmu_path, {"efficiency_map_file": str(out), "gear_set_file": str(gear),
                             "lubricant": 2})
    assert 0.9 < eta < 1.0


def refusal(fmu_path, values):
    with pytest.raises(FmuError) as info:
        run_map(fmu_path, values)
    text = str(info.value)
    hashes = re.findall(r"content hash ([0-9a-f]{16})", text)
    assert len(hashes) == 2 and hashes[0] != hashes[1], text
    return text


def test_fmu_refuses_a_map_of_another_gear_set_naming_both(fmu_path, own_map, tmp_path):
    out, gear = own_map
    edited = tmp_path / "my_set_edited.txt"
    edited.write_text(gear.read_text().replace("\nN_p", "\n# one comment more\nN_p", 1))
    text = refusal(fmu_path, {"efficiency_map_file": str(out), "gear_set_file": str(edited),
                              "lubricant": 2})
    assert "gear set" in text and str(gear) in text and str(edited) in text


def test_fmu_refuses_a_map_of_another_lubricant_naming_both(fmu_path, own_map):
    out, gear = own_map
    text = refusal(fmu_path, {"efficiency_map_file": str(out), "gear_set_file": str(gear),
                              "lubricant": 1})
    assert "OS265963.txt" in text and "OS265962.txt" in text


def test_same_content_under_another_name_is_the_same_gear_set(fmu_path, own_map):
    """The check is by content: the built-in set 2 is the file the map's copy was made of."""
    out, _ = own_map
    assert 0.9 < run_map(fmu_path, {"efficiency_map_file": str(out), "gear_set": 2,
                                    "lubricant": 2}) < 1.0


def test_built_in_maps_record_the_built_in_files():
    """Every map in resources/maps names and hashes the resource files it was made from, so the
    FMU takes it for its gear set and lubricant (and a stale map fails here first)."""
    maps = sorted((ROOT / "resources" / "maps").glob("*.txt"))
    assert len(maps) == 6
    for m in maps:
        k = keys(m)
        for what in ("gear_set", "lubricant"):
            source = ROOT / "resources" / k[f"{what}_source"]
            assert k[f"{what}_hash"] == effmap.content_hash(source), (m.name, what)


@pytest.mark.parametrize("args,words", [
    (["--speeds-rpm", "3000,1000"], ["--speeds-rpm", "ascending"]),
    (["--torques", "50:100"], ["--torques", "start:stop:step"]),
    (["--set", "T_s=100"], ["T_s", "grid options"]),
    (["--set", "friction_model=map"], ["full model"]),
    (["--gear-set-file", "nowhere.txt"], ["nowhere.txt", "not found"]),
])
def test_bad_options_are_one_line(fmu_path, tmp_path, capsys, args, words):
    assert cli.main(["effmap", "--fmu", str(fmu_path), "--out", str(tmp_path / "m.txt"),
                     *args]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and all(w in err for w in words), err
    assert not (tmp_path / "m.txt").exists()


def test_builtin_maps_reach_cold_starts(fmu_path):
    """Before, the built-in maps started at 20 degC and a -7 degC start fell to the fast level.
    Every shipped map spans hypoid effmap's default grid, -30 to 150 degC, and its -15 degC
    column is what the full model gives there now (the maps are not stale)."""
    import math

    from hypoid.drivecycle import levels

    for path in sorted((ROOT / "resources" / "maps").glob("gearset*_*.txt")):
        K = effmap.map_temperatures(path)
        assert K == pytest.approx([c + 273.15 for c in effmap.TEMPERATURES_C]), path.name
    assert effmap.builtin_map_range() == pytest.approx((243.15, 423.15))
    assert levels.default_level(266.15, [266.15], {}) == "map"  # the EU's -7 degC test
    k = keys(ROOT / "resources" / "maps" / "gearset1_OS265962.txt")
    speeds = [round(float(x) / (math.pi / 30)) for x in k["speeds"].split()]
    torques = [float(x) for x in k["torques"].split()]
    k_T = effmap.TEMPERATURES_C.index(-15)
    i_n, i_T = speeds.index(1000), torques.index(100)
    shipped = float(k[f"drive.{k_T + 1}"].split()[i_n * len(torques) + i_T])
    with Instance(fmu_path) as inst:
        got = effmap.efficiency_point(inst, {"gear_set": 1, "lubricant": 1},
                                      1000 * math.pi / 30, 100.0, 258.15, False)["eta"]
    # the file keeps 8 decimals; a physics change that matters moves a map by 1e-4 and more
    assert got == pytest.approx(shipped, abs=1e-6)
