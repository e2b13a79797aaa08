"""The hypoid package's architecture (docs/python.md), kept as test_architecture.py keeps fmu-src/'s:
sub-packages in layers that import only downwards, no module over 500 lines, pyproject.toml
naming every sub-package, and bench/, tools/ and examples/ on the package's public names."""

import ast
import pathlib
import tomllib

ROOT = pathlib.Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "hypoid"
MAX_LINES = 500

# Lowest first. A unit (a sub-package or a module of hypoid/) imports only units of lower layers.
LAYERS = [
    ("hypoid.errors",),                                  # the error every layer may raise
    ("hypoid.paths", "hypoid.data", "hypoid.csvtext"),   # user paths; data and FMUs; CSV text
    ("hypoid.fmu",),                                     # FMU access
    ("hypoid.tca", "hypoid.lubricant", "hypoid.cosim"),  # data files; co-simulation masters
    ("hypoid.maps",),                                    # efficiency and loss maps
    ("hypoid.study",),                                   # scenarios, steady states, studies
    ("hypoid.regress", "hypoid.drivecycle",              # regression; the axle in a car;
     "hypoid.records"),                                  # the measured records
    ("hypoid.cli",),                                     # the `hypoid` command on top
]
LAYER = {unit: k for k, units in enumerate(LAYERS) for unit in units}


def modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(ROOT).with_suffix("").parts
        yield path, ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def unit(name):
    """hypoid.study.sweep -> hypoid.study; hypoid -> hypoid."""
    return ".".join(name.split(".")[:2])


def imported(path, module):
    """Every hypoid module or name the file imports (also inside functions)."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            yield from (a.name for a in node.names if a.name.startswith("hypoid"))
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(package.split(".")[:len(package.split(".")) - node.level + 1]
                                + ([base] if base else []))
            if base == "hypoid":  # from hypoid import fmu, data
                yield from (f"hypoid.{a.name}" for a in node.names)
            elif base.startswith("hypoid."):
                yield base


def test_every_unit_has_a_layer():
    units = {unit(m) for _, m in modules()} - {"hypoid"}
    assert units == set(LAYER), "place a new sub-package or module in LAYERS (and docs/python.md)"


def test_imports_point_down_only():
    wrong = []
    for path, module in modules():
        here = unit(module)
        for target in imported(path, module):
            there = unit(target)
            if there == "hypoid" and here != "hypoid":
                wrong.append(f"{module} imports the package root ({target})")
            elif there != here and there != "hypoid" and LAYER[there] >= LAYER.get(here, -1):
                wrong.append(f"{module} imports {target} (layer {LAYER[there]} from "
                             f"layer {LAYER.get(here)})")
    assert not wrong, "\n".join(wrong)


def test_no_module_over_the_line_limit():
    long = {str(p.relative_to(ROOT)): n for p, _ in modules()
            if (n := len(p.read_text().splitlines())) > MAX_LINES}
    assert not long, f"over {MAX_LINES} lines (split by concern): {long}"


def test_pyproject_lists_every_sub_package_and_the_data():
    setup = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    on_disk = {m for p, m in modules() if p.name == "__init__.py"}
    data = {f"{package}.{'.'.join(sub.relative_to(ROOT / folder).parts)}".rstrip(".")
            for package, folder in setup["package-dir"].items()
            for sub in [ROOT / folder, *(ROOT / folder).rglob("*")]
            if sub.is_dir() and sub.name != "__pycache__"}
    assert set(setup["packages"]) == on_disk | data
    for package, folder in setup["package-dir"].items():
        assert (ROOT / folder).is_dir() and not (ROOT / folder / "__init__.py").exists(), package
        assert package in setup["package-data"]


def test_scripts_use_public_names_only():
    """bench/, tools/ and examples/ import no underscored name of the package."""
    wrong = []
    for folder in ("bench", "tools", "examples"):
        for path in sorted((ROOT / folder).rglob("*.py")):
            for node in ast.walk(ast.parse(path.read_text())):
                if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("hypoid"):
                    wrong += [f"{path.relative_to(ROOT)}: {node.module}.{a.name}"
                              for a in node.names if a.name.startswith("_")]
                    if any(part.startswith("_") for part in node.module.split(".")):
                        wrong.append(f"{path.relative_to(ROOT)}: {node.module}")
    assert not wrong, wrong


def test_one_fmu_access_class():
    """hypoid.fmu is the one way tools, tests and benchmarks reach an FMU: its Instance (and, in the
    same access layer, its Model Exchange form) is never subclassed elsewhere to give it other
    names (raw fmpy calls go through its `slave`)."""
    wrong = []
    for folder in ("hypoid", "tests", "bench", "tools", "examples"):
        for path in sorted((ROOT / folder).rglob("*.py")):
            if path.parent == ROOT / "hypoid" / "fmu":
                continue
            for node in ast.walk(ast.parse(path.read_text())):
                if isinstance(node, ast.ClassDef) and any(
                        ast.unparse(base).split(".")[-1] == "Instance" for base in node.bases):
                    wrong.append(f"{path.relative_to(ROOT)}: class {node.name}")
    assert not wrong, wrong
