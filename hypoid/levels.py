"""The FMU's fidelity levels and solvers as start values (README, 'Fidelity levels and solvers'):
one definition for the benchmarks and the tests."""

LEVELS = {
    "full": dict(mesh_model=2, friction_model=4, backlash_model=1),
    "smoothed": dict(mesh_model=2, friction_model=4, backlash_model=2),
    "isothermal": dict(mesh_model=2, friction_model=3, backlash_model=1),
    "mean": dict(mesh_model=1, friction_model=4),
    "rigid": dict(mesh_model=3, friction_model=4),
    "map": dict(mesh_model=3, friction_model=5),
}

SOLVERS = {"bdf": dict(solver=1), "adams": dict(solver=2), "newmark": dict(solver=3)}
