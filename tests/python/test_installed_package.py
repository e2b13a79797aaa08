"""The package installed, not the checkout: the wheel built from the repository, installed with
pip (--no-deps --no-index) into a fresh environment that borrows this environment's dependencies,
and run from a folder outside the checkout: `hypoid --help`, the built-in data through
importlib.resources, a missing FMU said in one line, and one real run on the FMU named by
$HYPOID_FMU."""

import os
import shutil
import subprocess
import sys
import sysconfig

import pytest

from conftest import ROOT

# what the wheel is made from (pyproject.toml maps resources/ and tests/regression/ into it)
SOURCES = ("pyproject.toml", "hypoid", "resources", "tests/regression")


def run(args, cwd, env=None, check=True):
    done = subprocess.run([str(a) for a in args], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=300)
    if check and done.returncode != 0:
        pytest.fail(f"{' '.join(map(str, args))} failed:\n{done.stdout}\n{done.stderr}")
    return done


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(the installed environment's bin folder, a folder outside the checkout)."""
    tmp = tmp_path_factory.mktemp("installed")
    src = tmp / "src"  # a copy: setuptools writes build/ and *.egg-info beside pyproject.toml
    for name in SOURCES:
        if (ROOT / name).is_dir():
            shutil.copytree(ROOT / name, src / name,
                            ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        else:
            (src / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(ROOT / name, src / name)
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check"]
    run(pip + ["wheel", "-q", "--no-deps", "--no-build-isolation", "--no-index", "-w",
               tmp / "wheels", src], tmp)
    wheel, = (tmp / "wheels").glob("hypoid-*.whl")
    venv = tmp / "venv"
    run([sys.executable, "-m", "venv", "--without-pip", venv], tmp)
    python = venv / "bin" / "python"
    run(pip + ["--python", python, "install", "-q", "--no-deps", "--no-index", wheel], tmp)
    # the dependencies: this environment's site-packages after the fresh one's own
    purelib = run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                  tmp).stdout.strip()
    with open(os.path.join(purelib, "project-dependencies.pth"), "w") as f:
        f.write(sysconfig.get_paths()["purelib"] + "\n")
    elsewhere = tmp / "elsewhere"
    elsewhere.mkdir()
    return venv / "bin", elsewhere


def clean_env(**extra):
    env = {k: v for k, v in os.environ.items()
           if k not in ("HYPOID_FMU", "HYPOID_VEHICLE_FMU", "PYTHONPATH", "VIRTUAL_ENV")}
    env.update(extra)
    return env


def test_hypoid_help_runs_installed(installed):
    bin_dir, elsewhere = installed
    done = run([bin_dir / "hypoid", "--help"], elsewhere, clean_env())
    assert done.stdout.startswith("usage: hypoid <tool>") and "drive-cycle" in done.stdout


def test_installed_package_reads_its_data_through_importlib_resources(installed):
    bin_dir, elsewhere = installed
    probe = ("import hypoid, hypoid.data as d; print(hypoid.__file__); print(d.checkout()); "
             "print(d.resource('lubricants/OS265962.txt')); "
             "print(d.resource('gearsets/loaded/gearset1.txt').read_text().splitlines()[0]); "
             "print(d.regression('tolerances.csv').read_text().splitlines()[0])")
    lines = run([bin_dir / "python", "-c", probe], elsewhere, clean_env()).stdout.splitlines()
    venv = str(bin_dir.parent)
    assert lines[0].startswith(venv) and lines[1] == "None"
    assert lines[2].startswith(venv) and lines[2].endswith("lubricants/OS265962.txt")
    assert lines[3] == (ROOT / "resources/gearsets/loaded/gearset1.txt").read_text().splitlines()[0]
    assert lines[4] == "quantity,rel,abs"


def test_installed_package_says_in_one_line_that_it_needs_the_fmu(installed):
    bin_dir, elsewhere = installed
    done = run([bin_dir / "hypoid", "run"], elsewhere, clean_env(), check=False)
    assert done.returncode == 2 and done.stdout == ""
    assert len(done.stderr.splitlines()) == 1 and "Traceback" not in done.stderr
    assert "--fmu" in done.stderr and "HYPOID_FMU" in done.stderr


def test_installed_package_runs_a_scenario_on_the_fmu_it_is_given(installed, fmu_path):
    bin_dir, elsewhere = installed
    done = run([bin_dir / "hypoid", "run", "--stop-time", "0.02", "--name", "short"], elsewhere,
               clean_env(HYPOID_FMU=str(fmu_path)))
    assert "wrote" in done.stdout
    for name in ("timeseries.csv", "cycles.csv", "summary.json"):
        assert (elsewhere / "results" / "short" / name).stat().st_size > 0
