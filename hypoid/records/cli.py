"""`hypoid records`: the pages of docs/records/ from their data, and the index of them in
docs/README.md. A record is a measured figure's one home: its data file and the page written
from it; the reference pages link to it.

    hypoid records                   # write every page (and the index) from the data
    hypoid records NAME ...          # only these records
    hypoid records --check           # exit 1 naming each page that is not its data's
    hypoid records --list            # every record: its data and the command that measures it
    hypoid records --measure NAME    # run its measurement (minutes, niced), then write its page

Measurements need the built FMU and the C host (scripts/setup.sh) and a quiet machine: they
time the model. Writing and checking the pages need neither."""

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


def main(argv):
    from hypoid.cli.args import Parser

    p = Parser(prog="hypoid records", doc=__doc__)
    p.add_argument("names", nargs="*", metavar="NAME", help="records (default: all)")
    p.add_argument("--check", action="store_true", help="compare only; exit 1 when stale")
    p.add_argument("--list", action="store_true", help="list the records")
    p.add_argument("--measure", action="store_true",
                   help="run the records' measurements first (give the names)")
    args = p.parse_args(argv)
    unknown = [n for n in args.names if n not in RECORDS]
    if unknown:
        raise UsageError(f"no record {', '.join(unknown)}; the records are {', '.join(RECORDS)}")
    if args.list:
        for r in RECORDS.values():
            print(f"{r.name:20s} {', '.join(r.data):45s} {r.measure}")
        return 0
    if args.measure:
        if not args.names:
            raise UsageError("--measure needs the records' names (they take minutes each)")
        for name in args.names:
            measure(name)
    return 1 if write_all(args.names or list(RECORDS), args.check) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
