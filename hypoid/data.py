"""Where the package finds its data and the FMUs, installed (`pip install .`) or in a checkout.

Data, through importlib.resources: the repository's resources/ (gear sets, lubricants, efficiency
maps) is the package data `hypoid.resources`, and tests/regression/ (the regression scenarios'
reference and tolerances) `hypoid.regression`; pyproject.toml maps both folders into the package,
so a wheel carries them; in a checkout (an editable install, or the source tree) they are read
where they are. One copy in git.

The FMUs: the path given (--fmu, --vehicle-fmu), else the environment variable (HYPOID_FMU,
HYPOID_VEHICLE_FMU), else build/ of the checkout the package runs from; otherwise one line says
what to give."""

import importlib.resources
import os
import pathlib

from hypoid.errors import UsageError

_ROOT = pathlib.Path(__file__).resolve().parents[1]
FMUS = {"gear": ("HypoidGearPair.fmu", "HYPOID_FMU", "--fmu"),
        "vehicle": ("LongitudinalVehicle.fmu", "HYPOID_VEHICLE_FMU", "--vehicle-fmu")}


def checkout():
    """The root of the repository the package runs from (an editable install or the source
    tree), or None when it is installed."""
    if (_ROOT / "pyproject.toml").is_file() and (_ROOT / "fmu-src").is_dir():
        return _ROOT
    return None


def _data(package, folder):
    try:
        return importlib.resources.files(package)
    except ModuleNotFoundError:  # in a checkout: an editable install does not map data folders
        if checkout() is None:
            raise
        return checkout() / folder


def resource(path=""):
    """A file or folder of the built-in data, e.g. resource('lubricants/OS265962.txt'), as a
    path (importlib.resources' Traversable)."""
    found = _data("hypoid.resources", "resources")
    for part in pathlib.PurePosixPath(path).parts:  # one at a time (namespace packages' paths)
        found = found.joinpath(part)
    return found


def regression(name=""):
    """A file of the regression data (reference.csv, tolerances.csv)."""
    return _data("hypoid.regression", "tests/regression").joinpath(name)


def writable(folder, option):
    """The checkout's folder (e.g. 'resources/lubricants') where a tool regenerates built-in
    data; an installed package has none: give `option`."""
    if checkout() is None:
        raise UsageError(f"the package is installed, not in a checkout: give {option} for the "
                         f"files that a checkout keeps in {folder}/")
    return checkout() / folder


def fmu(kind="gear", given=None):
    """The FMU file to run (kind 'gear' or 'vehicle'): `given`, else the environment variable,
    else the checkout's build/; checked to exist."""
    name, env, option = FMUS[kind]
    if given:
        path, how = pathlib.Path(given), f"give {option}"
    elif os.environ.get(env):
        path, how = pathlib.Path(os.environ[env]).expanduser(), f"${env}"
    elif checkout() is not None:
        path, how = checkout() / "build" / name, f"build it with scripts/setup.sh, or give {option}"
    else:
        raise UsageError(f"no {name}: give {option} FILE or set {env} (the package is installed, "
                         "so there is no build/ of a checkout to take it from)")
    if not path.is_file():
        raise UsageError(f"{path}: no such FMU file ({how})")
    return path
