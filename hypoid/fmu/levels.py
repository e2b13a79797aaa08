"""The FMU's fidelity levels and solvers as start values (README, 'Fidelity levels and solvers'):
one definition for the benchmarks and the tests, by enumeration item name (checked against the
generated variable table when imported; hypoid.fmu.instance.Instance sets items by name)."""

from hypoid.fmu.values import TABLE

LEVELS = {name: TABLE.normalize(values) for name, values in {
    "full": dict(mesh_model="varying", friction_model="ehl_thermal", backlash_model="exact"),
    "smoothed": dict(mesh_model="varying", friction_model="ehl_thermal",
                     backlash_model="smoothed"),
    "isothermal": dict(mesh_model="varying", friction_model="ehl_isothermal",
                       backlash_model="exact"),
    "mean": dict(mesh_model="mean", friction_model="ehl_thermal"),
    "rigid": dict(mesh_model="rigid", friction_model="ehl_thermal"),
    "map": dict(mesh_model="rigid", friction_model="map"),
}.items()}

SOLVERS = {"auto": dict(solver="auto"), "bdf": dict(solver="cvode_bdf"),
           "adams": dict(solver="cvode_adams"), "newmark": dict(solver="newmark"),
           "erk": dict(solver="arkode_erk")}
