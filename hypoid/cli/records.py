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

from hypoid.cli.args import Parser
from hypoid.errors import UsageError
from hypoid.records.registry import RECORDS
from hypoid.records.writer import measure, write_all


def main(argv):
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

