"""`hypoid tca`: gear-set files from the surrogate TCA (docs/physics.md §10) or from a user's TCA table.

    hypoid tca surrogate (--set N --out FILE | --all --out-dir DIR)
                         [--harmonics 8] [--contact-harmonics 32]
                         [--loaded [--torques 25 50 100 200 400]] [--with-blank]
    hypoid tca design DESIGN.toml --out FILE [--torques 25 50 100 200 400]
    hypoid tca import TABLE.csv [TABLE2.csv ...] --out FILE [--speed-rpm RPM] [--name TEXT]
                      [--harmonics 8] [--contact-harmonics 32] [--blank NAME=VALUE ...]
    hypoid tca export-csv --set N --out TABLE.csv [--speed-rpm 2000] [--rows 360]

The table format is documented in docs/tca-import.md, the gear-set format in docs/data-files.md,
the design file (a gear's design data, without a TCA) in hypoid/tca/design.py.
"""

import os

from hypoid.cli import args as cliargs
from hypoid.tca import loaded as tl
from hypoid.tca import surrogate as sur
from hypoid.tca.fit import CONTACT_HARMONICS, HARMONICS
from hypoid.tca.gearset_file import (BLANK, MAX_HARMONICS, MESH_SERIES, PAIR_SERIES, UNITS,
                                     check_blank, write_gearset)
from hypoid.tca.gearsets import design_gearset, export_csv, loaded_surrogate, surrogate
from hypoid.tca.table_import import import_tables


def _parser():
    p = cliargs.Parser("hypoid tca", __doc__)
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("surrogate", help="gear-set files of the paper's sets 1-3 (docs/physics.md §10)")
    which = s.add_mutually_exclusive_group(required=True)
    which.add_argument("--set", type=int, choices=sorted(sur.TABLE_1), help="gear set of Table 1")
    which.add_argument("--all", action="store_true", help="all three sets")
    s.add_argument("--out", help="output file (with --set)")
    s.add_argument("--out-dir", help="output directory (with --all): gearset1.txt ...")
    s.add_argument("--loaded", action="store_true",
                   help="both flanks at several torques from the loaded TCA (docs/physics.md §10.8)")
    s.add_argument("--torques", type=float, nargs="+", default=list(tl.TORQUES),
                   help="pinion torque levels of --loaded [N·m], increasing")
    i = sub.add_parser("import", help="gear-set file from a TCA table (docs/tca-import.md)")
    i.add_argument("table", nargs="+", help="CSV table(s): several with torque_Nm (and flank) rows "
                   "make a file of several torque levels and both flanks")
    i.add_argument("--out", required=True, help="output gear-set file")
    i.add_argument("--speed-rpm", type=float, help="pinion speed of the velocity columns [rpm]")
    i.add_argument("--name", help="name written into the gear-set file")
    s.add_argument("--with-blank", action="store_true",
                   help="write the gear blank (blank.* keys) the axle's loss ledger needs")
    i.add_argument("--blank", nargs="+", metavar="NAME=VALUE", default=[],
                   help="the gear blank for axle_losses = full, all eight of ring_d, ring_b, "
                        "r_m_p, r_m_g [m], delta_p, delta_g, beta_p, beta_g [rad] (the FMU's "
                        "parameter names and units), written as the file's blank.* keys")
    for q in (s, i):
        q.add_argument("--harmonics", type=int, default=HARMONICS, help="for k_m, R_p, e_0, ls")
        q.add_argument("--contact-harmonics", type=int, default=CONTACT_HARMONICS,
                       help="for R_x, R_y, up_x, up_y, ug_x, ug_y, vc_x, vc_y")
    d = sub.add_parser("design", help="a layered two-flank gear-set file from design data "
                       "(hypoid/tca/design.py: the surrogate of docs/physics.md §10)")
    d.add_argument("design", help="design data file (TOML, table [gear])")
    d.add_argument("--out", required=True, help="output gear-set file")
    d.add_argument("--torques", type=float, nargs="+", default=list(tl.TORQUES),
                   help="pinion torque levels [N·m], increasing")
    d.add_argument("--harmonics", type=int, default=CONTACT_HARMONICS, help="for every series")
    e = sub.add_parser("export-csv", help="the surrogate of a gear set as a TCA table")
    e.add_argument("--set", type=int, choices=sorted(sur.TABLE_1), required=True)
    e.add_argument("--out", required=True)
    e.add_argument("--speed-rpm", type=float, default=2000.0)
    e.add_argument("--rows", type=int, default=360, help="rows over one period (3 angular pitches)")
    return p


def _gearsets(args):
    """[(output path, Gearset)] for the surrogate and import commands."""
    for n in (args.harmonics, args.contact_harmonics):
        if not 0 <= n <= MAX_HARMONICS:
            raise ValueError(f"harmonics must be 0..{MAX_HARMONICS}, not {n}")
    if args.command == "import":
        blank = _blank_option(args.blank)
        gs = import_tables(args.table, args.speed_rpm, args.harmonics, args.contact_harmonics,
                           args.name)
        gs.blank = blank
        return [(args.out, gs)]
    if args.all != bool(args.out_dir) or args.all == bool(args.out):
        raise ValueError("use --set N --out FILE or --all --out-dir DIR")
    sets = sorted(sur.TABLE_1) if args.all else [args.set]
    def made(n):
        if args.loaded:
            gs = loaded_surrogate(n, tuple(args.torques), max(args.harmonics, args.contact_harmonics),
                                  args.contact_harmonics)
        else:
            gs = surrogate(n, args.harmonics, args.contact_harmonics)
        if args.with_blank:
            gs.blank = sur.ledger_blank(n)
        return gs
    return [(args.out or os.path.join(args.out_dir, f"gearset{n}.txt"), made(n)) for n in sets]


def _blank_option(items):
    """--blank NAME=VALUE items as the file's blank (all eight names, each in its range)."""
    if not items:
        return {}
    blank = {}
    for item in items:
        name, sep, text = item.partition("=")
        if not sep or name not in BLANK:
            raise ValueError(f"--blank {item!r}: NAME=VALUE with NAME one of {', '.join(BLANK)}")
        try:
            blank[name] = float(text)
        except ValueError:
            raise ValueError(f"--blank {name} = {text!r}: not a number") from None
    return check_blank("--blank", blank)


def _run(args):
    if args.command == "design":
        if not 0 <= args.harmonics <= MAX_HARMONICS:
            raise ValueError(f"harmonics must be 0..{MAX_HARMONICS}, not {args.harmonics}")
        gs = design_gearset(args.design, args.torques, args.harmonics)
        write_gearset(args.out, gs)
        print(f"wrote {args.out}\n  {len(gs.flanks)} flank(s) x {len(gs.torque_levels)} torque "
              "levels, with the gear blank")
        return
    if args.command == "export-csv":
        export_csv(args.set, args.out, args.speed_rpm, args.rows)
        print(f"wrote {args.out}")
        return
    for path, gearset in _gearsets(args):
        write_gearset(path, gearset)
        print(f"wrote {path}")
        if gearset.layered:
            print(f"  {len(gearset.flanks)} flank(s) x {len(gearset.torque_levels)} torque levels")
            continue
        for key in MESH_SERIES + PAIR_SERIES:
            if key in gearset.notes:
                print(f"  {key:5} [{UNITS[key]}] {gearset.notes[key]}")


def main(argv):
    args = _parser().parse_args(argv)
    try:
        _run(args)
    except ValueError as err:  # TableError, GearsetFileError: the message names file and line
        raise cliargs.UsageError(str(err)) from None
    return 0
