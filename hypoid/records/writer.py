"""Writes (or checks) the records' pages from their data and the list of them in the docs
index, docs/README.md; runs a record's measurement. The command line is `hypoid records`
(hypoid.cli.records)."""

import os
import subprocess
import sys

from hypoid.errors import UsageError
from hypoid.records import docblocks
from hypoid.records.registry import FOLDER, RECORDS, ROOT

INDEX = ROOT / "docs" / "README.md"
INDEX_SOURCE = "hypoid records from hypoid/records/registry.py"


def index_table():
    """The docs index's list of records."""
    rows = ["| record | what was measured |", "|---|---|"]
    rows += [f"| [{r.title}](records/{r.page}) | {r.what} |" for r in RECORDS.values()]
    return "\n".join(rows)


def with_index(text):
    new = docblocks.replace(text, "records", INDEX_SOURCE, index_table())
    if new is None:
        raise UsageError(f"{INDEX} has no block 'records' ({docblocks.begin('records', INDEX_SOURCE)}"
                         f" ... {docblocks.end('records')})")
    return new


def write_all(names, check, folder=FOLDER, index=INDEX):
    """Writes (or with `check` compares) the pages of `names` and the index: the number of
    stale pages."""
    stale = 0
    for name in names:
        r = RECORDS[name]
        stale += docblocks.write_or_check(folder / r.page, r.write(folder), check,
                                          f"the record {name}", f"hypoid records {name}")
    stale += docblocks.write_or_check(index, with_index(index.read_text()), check,
                                      "the list of records", "hypoid records")
    return stale


def measure(name):
    """Runs the record's measuring command from the checkout's root, niced."""
    command = RECORDS[name].measure
    print(f"hypoid records: measuring {name}: {command}", file=sys.stderr)
    env = dict(os.environ, PATH=f"{ROOT / '.venv' / 'bin'}{os.pathsep}{os.environ['PATH']}")
    done = subprocess.run(f"nice -n 10 {command}", shell=True, cwd=ROOT, env=env)
    if done.returncode:
        raise UsageError(f"the measurement of {name} failed (exit {done.returncode}): {command}")
