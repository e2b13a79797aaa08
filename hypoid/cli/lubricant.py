"""`hypoid lubricant`: a lubricant data file from data-sheet values, or the built-in ones
(hypoid.lubricant: the fit, the estimates, the file)."""

import sys

from hypoid.cli import args as cliargs
from hypoid.lubricant import (BASE_OILS, LubricantError, build, estimate, render,
                              write_builtin)


def _parser():
    p = cliargs.Parser(
        prog="hypoid lubricant",
        description="Write a lubricant data file (hypoid-lubricant 1) from data-sheet values. "
                    "The Vogel law is fitted to KV40/KV100/rho15 as in docs/physics.md §4.1.")
    p.add_argument("--builtin", action="store_true",
                   help="regenerate the built-in files OS265962.txt and OS265963.txt")
    p.add_argument("--out-dir", help="directory for --builtin (default: resources/lubricants)")
    p.add_argument("-o", "--output", help="output file for a user lubricant")
    p.add_argument("--name", help="lubricant name")
    p.add_argument("--kv40", type=float, help="kinematic viscosity at 40 degC [mm^2/s]")
    p.add_argument("--kv100", type=float, help="kinematic viscosity at 100 degC [mm^2/s]")
    p.add_argument("--rho15", type=float, help="density at 15 degC [kg/m^3]")
    p.add_argument("--base-oil", choices=BASE_OILS, default="mineral",
                   help="base oil, for the estimates of alpha* and k_f when they are not given "
                        "(synthetic = PAO; default mineral)")
    p.add_argument("--alpha-star", type=float, nargs=3, metavar=("A1", "A2", "A3"),
                   help="reciprocal asymptotic isoviscous pressure coefficient at the three "
                        "temperatures [1/GPa] (default: estimated, ISO/TR 15144-1)")
    p.add_argument("--alpha-temps", type=float, nargs=3, metavar=("T1", "T2", "T3"),
                   default=(40.0, 100.0, 140.0),
                   help="temperatures of --alpha-star [degC] (default 40 100 140)")
    p.add_argument("--hn-lambda", type=float,
                   help="Havriliak-Negami relaxation time [s] (default: typical gear oil)")
    p.add_argument("--hn-alpha", type=float,
                   help="Havriliak-Negami alpha [-] (default: typical gear oil)")
    p.add_argument("--hn-beta", type=float, help="Havriliak-Negami beta [-] (default 1)")
    p.add_argument("--k-f", type=float,
                   help="thermal conductivity [W/(m K)] (default: estimated for the base oil)")
    p.add_argument("--c-p", type=float, help="specific heat [J/(kg K)] (default 2090)")
    return p


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    args = _parser().parse_args(argv)
    try:
        if args.builtin:
            for path in write_builtin(args.out_dir):
                print(f"wrote {path}")
            return 0
        missing = [opt for opt, val in (("--name", args.name), ("--kv40", args.kv40),
                                        ("--kv100", args.kv100), ("--rho15", args.rho15),
                                        ("-o/--output", args.output)) if val is None]
        if missing:
            raise LubricantError("missing " + ", ".join(missing) + " (or use --builtin)")
        sheet = dict(name=args.name, kv40=args.kv40, kv100=args.kv100, rho15=args.rho15,
                     alpha_star=args.alpha_star, alpha_temps=tuple(args.alpha_temps),
                     hn_lambda=args.hn_lambda, hn_alpha=args.hn_alpha, hn_beta=args.hn_beta,
                     k_f=args.k_f, c_p=args.c_p)
        full, marked = estimate(sheet, args.base_oil)
        values = build(**full)
        with open(args.output, "w") as fh:
            fh.write(render(values, marked=marked))
        print(f"wrote {args.output}: Vogel a = {values['vogel_a']:.4e} Pa s, "
              f"b = {values['vogel_b']:.1f} K, c = {values['vogel_c_degc']:.2f} degC"
              + (f"; estimated: {', '.join(marked)}" if marked else ""))
        return 0
    except LubricantError as exc:
        raise cliargs.UsageError(str(exc)) from None
