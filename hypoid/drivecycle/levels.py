"""Which fidelity level of the gear FMU a drive cycle runs (docs/axle.md, "Which level a --set
reaches"; the record docs/records/work-precision.md, "Which level and settings for which use"):
the levels, the default for the oil and air temperatures and the data files given, and whether a
--set parameter reaches the result at a level."""

from hypoid.errors import UsageError
from hypoid.fmu import levels as fmu_levels
from hypoid.fmu.values import TABLE
from hypoid.maps.effmap import builtin_map_fits, builtin_map_range

ZERO_C = 273.15

# The fidelity levels of the gear FMU for vehicle energy, levels of hypoid.fmu.levels at the
# tolerance each runs at here: map, the pick for oil and air within the built-in maps' range
# (MAP_T_MIN), the rigid mesh with the mesh friction from the full model's efficiency map
# (resources/maps; the default); fast (the rigid level with the input shaft quasi-static, as the
# map level's), the pick below it, the rigid mesh with the friction model itself; full: the
# paper's model. A resolved input shaft rings at every kink of the driver's torque for much of a
# 50 ms step (docs/decisions.md, "The fast level's input shaft quasi-static").
LEVELS = {
    "fast": {**fmu_levels.LEVELS["rigid"], "rtol": 1e-4, "input_shaft": "quasi_static"},
    "map": {**fmu_levels.LEVELS["map"], "rtol": 1e-5},
    "full": {**fmu_levels.LEVELS["full"], "rtol": 1e-6},
}

# The map level's lowest oil temperature: the shipped built-in maps' (hypoid effmap's grid when
# they were made; -30 degC since the grid reaches it). Below it the map holds its edge, so a
# cycle that starts or can cool below it runs the fast level.
MAP_T_MIN = builtin_map_range()[0]

# What a --set parameter reaches at each level (docs/axle.md, "Which level a --set reaches"):
# the map level takes the mesh friction from a map made with the default friction and gear data
# (only the gear set and lubricant have a built-in map each), and the rigid mesh of the map and
# fast levels has no stiffness, transmission error or backlash. Every parameter of the gear FMU
# is in one of the three groups or is named in reaching_levels (a test checks it), so that a new
# one is placed deliberately.
REACHES_EVERY_LEVEL = frozenset({
    "gear_set", "lubricant", "load_mode", "solver", "rtol", "atol", "max_step",
    "steps_per_mesh_cycle", "I_s", "I_p", "I_g", "I_w", "k_t1", "k_t2", "k_hs", "c_hs",
    "I_vehicle", "zeta_2", "zeta_3", "zeta_4", "w_p0", "governor_bandwidth", "n_avg_cycles",
    "axle_losses",
    "thermal_model", "ring_d", "ring_b", "r_m_p", "r_m_g", "delta_p", "delta_g", "beta_p",
    "beta_g", "alpha_n", "oil_level", "V_oil", "brg_ph_d", "brg_ph_D", "brg_ph_Y", "brg_ph_x",
    "brg_pt_d", "brg_pt_D", "brg_pt_Y", "brg_pt_x", "brg_gn_d", "brg_gn_D", "brg_gn_Y",
    "brg_gn_x", "brg_gf_d", "brg_gf_D", "brg_gf_Y", "brg_gf_x", "brg_p_R1", "brg_p_S1",
    "brg_g_R1", "brg_g_S1", "brg_p_C0", "brg_g_C0", "F_pre_p", "F_pre_g", "k_ax_p", "k_ax_g",
    "alpha_carrier", "brg_feed", "d_seal_p", "d_seal_w", "seal_model", "T_oil0",
    "C_sump", "A_housing", "L_housing", "eps_housing", "h_housing"})
MESH_FRICTION = frozenset({    # the friction model and its data: not in the built-in maps
    "gear_set_file", "lubricant_file", "mu_const", "E", "nu", "k_s", "rho_s", "c_s", "tau_0",
    "varsigma_a", "sigma_s", "eta_beta_sigma", "sigma_over_beta", "T_inlet_rise", "Lambda_cap",
    "k_f", "hertz_model", "roelands_z", "shear_pressure", "relaxation", "friction_preset",
    "friction_table", "tooth_data", "preset", "inlet_heating"})
MESH_DYNAMICS = frozenset({    # the compliant mesh only: the full level
    "b", "backlash_model", "backlash_smoothing", "k_m_scale", "e_0_scale"})


def reaching_levels(name, value, extra):
    """The levels at which `--set name=value` reaches the result. A parameter at its default
    reaches them all; with efficiency_map_file the map is the user's own, made (hypoid effmap
    --set ...) with the friction they set."""
    if name == "efficiency_map_file":
        return {"map"}
    if name == "friction_model":  # the levels' own settings, which --set overrides
        return {"map"} if value == "map" else {"fast", "full"}
    if name == "mesh_model":
        return {"map", "fast"} if value == "rigid" else {"full"}
    if name in ("input_shaft", "output_shaft"):  # quasi-static on the rigid mesh only
        return {"map", "fast"} if value == "quasi_static" else set(LEVELS)
    if value == TABLE.start(name):  # the default: the levels are made with it
        return set(LEVELS)
    if name in MESH_DYNAMICS:
        return {"full"}
    if name in MESH_FRICTION and "efficiency_map_file" not in extra:
        return {"fast", "full"}
    return set(LEVELS)


def unreached(level, extra):
    """The --set names that do not reach the result at `level`."""
    return [n for n, v in extra.items() if level not in reaching_levels(n, v, extra)]


def default_level(T_amb, starts, extra):
    """The drive cycle's level when none is asked for (docs/records/work-precision.md): map while
    the oil starts and the air stays in the map's range and a built-in map exists (none for a
    gear-set or lubricant file of one's own, nor for the tooth data the maps were not made with),
    or when a map of one's own is given; else fast; and the cheapest level that every --set parameter
    reaches (fast for friction data, full for the compliant mesh's)."""
    in_range = min(T_amb, *starts) >= MAP_T_MIN and builtin_map_fits(extra)
    first = "map" if in_range or "efficiency_map_file" in extra else "fast"
    order = ["map", "fast", "full"]
    return next(lv for lv in order[order.index(first):] if not unreached(lv, extra))


def _why(level, name, value):
    """Why `--set name=value` does not reach the result at `level`, in a few words."""
    if name in MESH_FRICTION:
        return (f"the {level} level takes the mesh friction from the built-in efficiency map, "
                "made with the default friction and gear data")
    if name in MESH_DYNAMICS:
        return f"the {level} level's rigid mesh has no stiffness, transmission error or backlash"
    if name == "efficiency_map_file":
        return "only the map level reads a map"
    return f"{name} = {value} is not the {level} level's {LEVELS[level][name]}"


def check_level(level, extra):
    """A UsageError when a --set parameter does not reach the result at the level asked for."""
    missed = unreached(level, extra)
    if not missed:
        return
    name, value = missed[0], extra[missed[0]]
    reach = sorted(reaching_levels(name, value, extra), key=list(LEVELS).index)
    own_map = " (or give efficiency_map_file=, a map made with hypoid effmap --set ...)" \
        if level == "map" and name in MESH_FRICTION else ""
    raise UsageError(f"--set {', '.join(missed)} with --level {level}: "
                      f"{_why(level, name, value)}{own_map}; it reaches the result at "
                      f"--level {' or '.join(reach)}")


def choose_level(asked, T_amb, starts, extra):
    """(level, note): the level asked for (checked), or the default with a one-line note when a
    --set parameter moved it off the level the temperatures and data files give."""
    if asked:
        check_level(asked, extra)
        return asked, None
    files = {k: v for k, v in extra.items()
             if k in ("gear_set_file", "lubricant_file", "efficiency_map_file")}
    base, level = default_level(T_amb, starts, files), default_level(T_amb, starts, extra)
    if level == base:
        return level, None
    missed = unreached(base, extra)
    return level, (f"--set {', '.join(missed)} does not reach the result at the {base} level "
                   f"({_why(base, missed[0], extra[missed[0]])}): running the {level} level")

