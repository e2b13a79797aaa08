"""The efficiency map's speed grid banded through the compliant mesh's resonances
(hypoid/maps/speedgrid.py; docs/axle.md, "Why the map's speed grid is banded"): the nodes fill
each band at the step, the bands follow the modes of docs/physics.md §8.4, the shipped maps carry
the grid the tool makes now, and the full model's loss ridge lies inside its band, where the map
level now follows it."""

import math
import pathlib

import pytest

from hypoid.fmu.instance import Instance
from hypoid.maps import effmap, speedgrid

ROOT = pathlib.Path(__file__).resolve().parents[2]
RPM = math.pi / 30


def map_speeds(path):
    """The speeds [rpm] of a map file."""
    line = next(x for x in path.read_text().splitlines() if x.startswith("speeds "))
    return [round(float(x) / RPM) for x in line.split("#")[0].split()[1:]]


def test_banded_speeds_fill_each_band_at_the_step():
    bands, step = {2: (1150.0, 1500.0), 3: (1900.0, 3400.0)}, 0.04
    nodes = speedgrid.banded_speeds(bands, step)
    assert nodes == sorted(set(nodes))
    assert set(speedgrid.BASE_SPEEDS_RPM) <= set(nodes)
    for low, high in bands.values():
        inside = [n for n in nodes if low - 10 <= n <= high + 10]
        assert inside[0] <= low + 10 and inside[-1] >= high - 10
        # geometric step, rounded to 10 rpm; a base node may stand in for a band node
        assert max(b / a for a, b in zip(inside, inside[1:])) < 1.0 + 1.5 * step
    # outside the bands only the base grid
    assert [n for n in nodes if n > 3500] == [4000, 5000, 6000]


def test_the_secant_stiffness_is_the_files_interpolated_linearly():
    gs = speedgrid.read_gearset(ROOT / "resources" / "gearsets" / "loaded" / "gearset1.txt")
    k = [gs.layers[("drive", i + 1)]["k_m"].mean for i in range(len(gs.torque_levels))]
    T0, T1 = gs.torque_levels[:2]
    assert speedgrid.secant_stiffness(gs, "drive", T0) == pytest.approx(k[0])
    assert speedgrid.secant_stiffness(gs, "drive", 0.5 * (T0 + T1)) == \
        pytest.approx(0.5 * (k[0] + k[1]))
    assert speedgrid.secant_stiffness(gs, "drive", 1.0) == pytest.approx(k[0])  # held
    # the contact stiffens with load: the secant rises with the torque
    assert k == sorted(k)


def test_the_modes_follow_the_calibration_and_the_load(fmu_path):
    """One-series data (tooth_data = paper): secant = tangent = k_m0 of §8.4, so modes 2 and 3
    of set 1 sit at the published 1204 / 2000 rpm at every torque. Loaded data: the tangent lies
    above the secant and both rise with the torque."""
    with Instance(fmu_path) as inst:
        p = {"gear_set": 1, "tooth_data": "paper"}
        gs = speedgrid.read_gearset(ROOT / "resources" / effmap.builtin_gear_set(p))
        for torque in (25.0, 200.0):
            m = speedgrid.mode_speeds(inst, p, gs, torque, False)
            assert m[2] == pytest.approx((1204, 1204), rel=0.01)
            assert m[3] == pytest.approx((2000, 2000), rel=0.01)
        p = {"gear_set": 1}
        gs = speedgrid.read_gearset(ROOT / "resources" / effmap.builtin_gear_set(p))
        light, heavy = (speedgrid.mode_speeds(inst, p, gs, T, False) for T in (50.0, 300.0))
        for mode in (2, 3):
            assert light[mode][0] < light[mode][1] and heavy[mode][0] < heavy[mode][1]
            assert heavy[mode][0] > light[mode][0] and heavy[mode][1] > light[mode][1]


def test_the_shipped_maps_carry_the_banded_grid(fmu_path):
    """Each built-in map's speeds are the grid hypoid effmap makes now for its gear set (a change
    of the modes, the base grid or the step that is not regenerated fails here)."""
    with Instance(fmu_path) as inst:
        for path in sorted((ROOT / "resources" / "maps").glob("gearset*_*.txt")):
            g = int(path.name[len("gearset")])
            lub = next(k for k, v in effmap.LUBRICANTS.items() if v in path.name)
            params = {"gear_set": g, "lubricant": lub}
            speeds, bands, step = speedgrid.speed_grid(
                inst, params, ROOT / "resources" / effmap.builtin_gear_set(params),
                effmap.TORQUES)
            assert map_speeds(path) == speeds, path.name
            assert f"# {speedgrid.describe(bands, step)}" in path.read_text().splitlines()


@pytest.mark.parametrize("mode,harmonic,torque,speeds", [
    (2, 1, 20.0, range(1150, 1401, 50)),  # mode 2 itself, drive
    (2, 2, -20.0, range(575, 726, 25)),  # mode 2 met by the mesh's second harmonic, coast
])
def test_the_full_models_ridge_lies_in_its_band_and_the_map_follows_it(fmu_path, mode, harmonic,
                                                                        torque, speeds):
    """Gear set 1, OS265962, 80 degC, 20 N.m (between the torque nodes): the full model's mesh
    loss peaks well above the rigid mesh's, the peak lies inside the band of its mode and mesh
    harmonic, and the map level there is within 15 % of the full level's loss (with the old grid,
    nodes at 500, 1000 and 1500 rpm only, it was 15-45 % below)."""
    params, T, coast = {"gear_set": 1, "lubricant": 1}, 353.15, torque < 0
    with Instance(fmu_path) as inst:
        bands, _ = speedgrid.resonance_bands(
            inst, params, ROOT / "resources" / effmap.builtin_gear_set(params), effmap.TORQUES)

        def loss(n, **level):
            return 1 - effmap.efficiency_point(inst, dict(params, **level), n * RPM, abs(torque),
                                               T, coast)["eta"]

        full = {n: loss(n) for n in speeds}
        peak = max(full, key=full.get)
        rigid = loss(peak, mesh_model="rigid")
        mapped = loss(peak, mesh_model="rigid", friction_model="map")
    assert full[peak] > 1.15 * rigid  # a resonance ridge, not the rigid mesh's loss
    low, high = bands[(mode, harmonic)]
    assert low < peak < high
    assert mapped == pytest.approx(full[peak], rel=0.15)
