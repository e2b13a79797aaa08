"""The efficiency map's speed grid: a base grid plus nodes through the compliant mesh's resonance
bands, derived per gear set from its elastic modes (docs/axle.md, "Why the map's speed grid is
banded"; docs/physics.md §8.4).

The full model's mesh loss rises in narrow ridges where the tooth-mesh frequency N_p n/60 meets
the elastic modes 2 and 3 (the modes with strain energy in the mesh). The map's cubic splines
cannot show a peak that lies between two nodes, so a map whose speeds step over a ridge gives the
loss beside it. Where the ridges lie follows from the modes, which the FMU computes at
initialisation (`f_2`, `f_3`, fmu-src/model/modal.c) from the mesh stiffness it starts with:

- the tangent stiffness at the start torque (a layered gear-set file: the contact law's slope,
  what a small vibration about the load feels; the FMU's `k_m0`); and
- the secant stiffness at that torque (the file's `k_m`, interpolated linearly between its torque
  levels as the FMU does: the chord from no load to the load). The contact stiffens with load,
  so a vibration large enough to unload the teeth feels less than the tangent, down to about the
  secant: near resonance the ridge bends to lower speeds, as a softening spring's does.

A mode's resonance speed at a torque lies between its secant and tangent speeds, n = 60 f/N_p.
Its band runs from the lowest secant speed to the highest tangent speed over the map's torques
and both flanks (drive and coast have their own contact data), widened on either side by the
half-power half-width ζ_i n of the mode (`zeta_2`, `zeta_3`). The mesh's excitation (stiffness
ripple, transmission error, load sharing) is not a pure sine: its second harmonic meets each mode
at half the speed, a weaker ridge of its own (the full model at 80 °C, 25 N·m shows it near half
mode 2's and half mode 3's speed), so each mode has a band at half its speeds as well; higher
harmonics are weaker still and fall among those nodes. Inside a band the nodes stand at a
constant relative step, the larger ζ (mode 3's 4 %): a ridge as wide as its half-power width then
has a node on each flank and one near its top, and the step is the same fraction of speed over
the band. A band node closer than half a step to a base node is left out (the base node stands
in for it). A one-series gear-set file (one stiffness at every load) gives secant = tangent: the
band is then the half-power width about the one resonance speed.
"""

import math

import numpy as np

from hypoid.tca.gearset_file import read_gearset

# The base grid [rpm]: the pinion speeds of a vehicle's axle from creeping to its top speed.
BASE_SPEEDS_RPM = [100, 250, 500, 1000, 1500, 2000, 3000, 4000, 5000, 6000]
MODES = (2, 3)  # the elastic modes with strain energy in the mesh (docs/physics.md §8.4)
HARMONICS = (1, 2)  # the mesh-excitation harmonics whose resonances get a band (speed n_i / k)
START_RPM = 1000.0  # any speed: the modes are linearised, they do not depend on it


def secant_stiffness(gear_set, flank, torque):
    """The gear-set file's mean k_m [N/m] at a pinion torque, interpolated linearly between the
    torque levels and held beyond them (hg_gearset_means); a one-series file's k_m."""
    if not gear_set.layered:
        return gear_set.series["k_m"].mean
    flank = flank if flank in gear_set.flanks else "drive"
    k = [gear_set.layers[(flank, i + 1)]["k_m"].mean for i in range(len(gear_set.torque_levels))]
    return float(np.interp(torque, gear_set.torque_levels, k))


def mode_speeds(inst, params, gear_set, torque, coast):
    """{mode: (secant speed, tangent speed)} [rpm] of modes 2 and 3 at a pinion torque: the FMU's
    linearised modes started with the tangent stiffness, then with the secant one (k_m_scale
    scales the file's stiffness, so secant/tangent times the user's scale gives the secant)."""
    base = dict(params, T_s=-torque if coast else torque, load_mode="speed", speed_rpm=START_RPM)
    inst.start(base)
    n_p = inst.pinion_teeth()
    tangent = {m: 60.0 * inst.get(f"f_{m}") / n_p for m in MODES}
    k_tangent, scale = inst.get("k_m0"), params.get("k_m_scale", 1.0)
    k_secant = secant_stiffness(gear_set, "coast" if coast else "drive", torque) * scale
    inst.start(dict(base, k_m_scale=scale * k_secant / k_tangent))
    secant = {m: 60.0 * inst.get(f"f_{m}") / n_p for m in MODES}
    return {m: (secant[m], tangent[m]) for m in MODES}


def resonance_bands(inst, params, gear_set_path, torques):
    """{(mode, harmonic): (low, high)} [rpm]: each mode's band over the torques and both flanks,
    widened by its half-power half-width, at the mesh harmonic k's speed n_i / k; and the
    relative node step (the largest ζ)."""
    gear_set = read_gearset(gear_set_path)
    inst.start(dict(params, load_mode="speed", speed_rpm=START_RPM))
    zeta = {m: inst.get(f"zeta_{m}") for m in MODES}
    low, high = {m: math.inf for m in MODES}, {m: 0.0 for m in MODES}
    for torque in torques:
        for coast in (False, True):
            for m, (secant, tangent) in mode_speeds(inst, params, gear_set, torque, coast).items():
                low[m] = min(low[m], secant, tangent)
                high[m] = max(high[m], secant, tangent)
    bands = {(m, k): (low[m] * (1.0 - zeta[m]) / k, high[m] * (1.0 + zeta[m]) / k)
             for m in MODES for k in HARMONICS}
    return bands, max(zeta.values())


def banded_speeds(bands, step, base=BASE_SPEEDS_RPM):
    """The base speeds and, through each band, nodes at a relative step (geometric, rounded to
    10 rpm), without band nodes closer than half a step to a base node or to one another."""
    nodes = [float(n) for n in base]
    for low, high in sorted(bands.values()):
        count = max(1, math.ceil(math.log(high / low) / math.log(1.0 + step)))
        for i in range(count + 1):
            n = round(low * (high / low) ** (i / count), -1)
            if all(abs(n - m) > 0.5 * step * m for m in nodes):
                nodes.append(n)
    return sorted(int(n) for n in nodes)


def speed_grid(inst, params, gear_set_path, torques):
    """The banded speed grid [rpm] of a map, and the bands it is made from."""
    bands, step = resonance_bands(inst, params, gear_set_path, torques)
    return banded_speeds(bands, step), bands, step


def describe(bands, step):
    """One line for a map's header: the bands and the step."""
    parts = ", ".join(f"mode {m}{'' if k == 1 else f' / {k}'} {lo:.0f}-{hi:.0f} rpm"
                      for (m, k), (lo, hi) in sorted(bands.items()))
    return (f"Speeds: the base grid plus nodes every {100 * step:.0f} % through the mesh "
            f"resonance bands ({parts}; hypoid/maps/speedgrid.py).")
