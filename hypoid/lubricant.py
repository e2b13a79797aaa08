"""Lubricant data files ("hypoid-lubricant 1") from data-sheet values.

Data sheets give KV40, KV100 and rho15; the FMU needs the Vogel law eta_0(T) = a exp(b/(T - c)).
The fit follows docs/physics.md §4.1:

1. Walther / ASTM D341, log10 log10(nu + 0.7) = A - B log10(T [K]), through KV40 and KV100.
2. A third point from it at 150 degC.
3. Dynamic viscosity with rho(T) = rho15 [1 - 6.5e-4 (T - 15 degC)].
4. Vogel exactly through the three points: eliminating a and b leaves one equation in c,
   (L1 - L2)(x2 - x3) = (L2 - L3)(x1 - x2) with L = ln eta, x = 1/(T - c), solved by bracketing
   c in (-273.15 degC, 40 degC); then b = (L1 - L2)/(x1 - x2) and a = exp(L1 - b x1).

The pressure-viscosity data (alpha* at three temperatures), the Havriliak-Negami parameters and
the thermal properties are copied through with range checks. A data sheet rarely gives them; each
one left out is estimated (`estimate`, docs/data-files.md "Estimates for what a data sheet lacks")
and marked ESTIMATED in the file with its source:

- alpha*: the pressure-viscosity correlation of ISO/TR 15144-1:2014, eqs. (8)-(10), from the
  dynamic viscosity at 38 degC and the base oil (mineral or synthetic = PAO), taken as alpha*.
- Havriliak-Negami lambda, alpha, beta: the mean of the two 75W-90 gear oils the paper measured
  (Paouris et al. 2016, Table 2).
- k_f: mineral oils by Cragoe's correlation (US Bureau of Standards Misc. Publ. 97, 1929) at
  60 degC; synthetic oils the paper's Table 2 value for OS265962. `--builtin` regenerates the two
lubricants of the paper (Table 2) in resources/lubricants/. The file format is documented in
docs/data-files.md.
"""

import math
import os

from hypoid import data

C0 = 273.15  # K at 0 degC
T_THIRD = 150.0  # degC, third point of the Vogel fit
EXPANSION = 6.5e-4  # 1/K, density law of docs/physics.md §4.1
MAGIC = "hypoid-lubricant 1"

# Paper Table 2 and the assumed SAE 75W-90 data of docs/physics.md §4.1 (same for both oils)
BUILTIN = {
    "OS265962": dict(kv40=100.0, kv100=15.0, rho15=870.0, alpha_star=(16.09, 11.59, 9.38),
                     alpha_temps=(40.0, 100.0, 140.0), hn_lambda=7.9e-8, hn_alpha=0.70,
                     hn_beta=1.0, k_f=0.18, c_p=2090.0),
    "OS265963": dict(kv40=100.0, kv100=15.0, rho15=870.0, alpha_star=(19.31, 13.89, 12.28),
                     alpha_temps=(40.0, 100.0, 140.0), hn_lambda=8.0e-8, hn_alpha=0.97,
                     hn_beta=1.0, k_f=0.18, c_p=2090.0),
}
BUILTIN_NOTES = {
    "OS265962": [],
    "OS265963": [
        "k_f: the paper's Table 2 prints 0.80 W/(m K), about 5x the conductivity of any",
        "mineral/PAO gear oil (0.12-0.15, ~0.2-0.3 at 1 GPa); docs/physics.md §0 (D8) uses 0.18.",
        "Set the FMU's k_f override to 0.80 to reproduce the paper as printed.",
    ],
}


# ---------------------------------------------------------------- estimates for a bare data sheet
BASE_OILS = ("mineral", "synthetic")
# ISO/TR 15144-1:2014 eqs. (9) (mineral) and (10) (polyalphaolefin): alpha_38 = A eta_38^B with
# alpha in 1/Pa and eta_38 [Pa s] the dynamic viscosity at 38 degC (311 K)
ISO15144_ALPHA38 = {"mineral": (2.657e-8, 0.1348), "synthetic": (1.466e-8, 0.0507)}
ISO15144_T_REF = 311.0  # K, eq. (8)
ISO15144_T_SLOPE = 516.0  # K, eq. (8)
# the mean of the paper's two 75W-90 gear oils (Table 2: 7.9e-8 / 8.0e-8 s, 0.70 / 0.97, 1 / 1)
HN_TYPICAL = {"hn_lambda": 7.95e-8, "hn_alpha": 0.835, "hn_beta": 1.0}
CRAGOE_K = 0.1172  # W/(m K): Cragoe, k = 0.1172 (1 - 5.4e-4 T [degC]) / SG15 (mineral oils)
CRAGOE_SLOPE = 5.4e-4  # 1/K
CRAGOE_T = 60.0  # degC, the inlet temperature of the paper's 40 degC bath
RHO_WATER_15 = 999.1  # kg/m^3, water at 15 degC (the reference of the specific gravity)
K_F_SYNTHETIC = 0.18  # W/(m K), the paper's Table 2 for OS265962 (a synthetic 75W-90)
SOURCES = {
    "alpha_star": "ISO/TR 15144-1:2014 eqs. (8)-(10), {base} base oil",
    "hn": "typical 75W-90 gear oil: mean of the paper's Table 2 oils",
    "k_f": {"mineral": "Cragoe (1929) at 60 degC from rho15, mineral oil",
            "synthetic": "the paper's Table 2 value for a synthetic 75W-90"},
}


def iso15144_alpha(eta_38, t_k, base_oil):
    """Pressure-viscosity coefficient [1/Pa] at t_k [K] from eta_38 [Pa s] (ISO/TR 15144-1
    eqs. (8)-(10))."""
    coeff, power = ISO15144_ALPHA38[base_oil]
    return coeff * eta_38 ** power * (1.0 + ISO15144_T_SLOPE * (1.0 / t_k - 1.0 / ISO15144_T_REF))


def estimate_alpha_star(kv40, kv100, rho15, base_oil, temps_c):
    """alpha* [1/GPa] at temps_c [degC], taken as the ISO/TR 15144-1 coefficient."""
    wa, wb = walther_fit(kv40, kv100)
    eta_38 = walther_nu(wa, wb, 38.0) * 1e-6 * density(rho15, 38.0)
    return tuple(1e9 * iso15144_alpha(eta_38, t + C0, base_oil) for t in temps_c)


def estimate_k_f(rho15, base_oil):
    """Thermal conductivity [W/(m K)]: Cragoe at 60 degC (mineral), the paper's (synthetic)."""
    if base_oil == "synthetic":
        return K_F_SYNTHETIC
    return CRAGOE_K * (1.0 - CRAGOE_SLOPE * CRAGOE_T) / (rho15 / RHO_WATER_15)


def estimate(sheet, base_oil="mineral"):
    """Fills the values a data sheet lacks (None or absent) with the estimates above.

    `sheet` holds build()'s keyword arguments; returns (complete arguments, the estimated file
    keys with their sources)."""
    if base_oil not in BASE_OILS:
        raise LubricantError(f"base oil {base_oil!r} is not one of " + ", ".join(BASE_OILS))
    args = dict(sheet)
    args.setdefault("alpha_temps", (40.0, 100.0, 140.0))
    fit_vogel(args.get("kv40"), args.get("kv100"), args.get("rho15"))  # checks the data sheet
    marked = {}
    if args.get("alpha_star") is None:
        args["alpha_star"] = tuple(_sig4(a) for a in estimate_alpha_star(
            args["kv40"], args["kv100"], args["rho15"], base_oil, args["alpha_temps"]))
        for i in range(3):
            marked[f"alpha_star_{i + 1}"] = SOURCES["alpha_star"].format(base=base_oil)
    for key, value in HN_TYPICAL.items():
        if args.get(key) is None:
            args[key] = value
            marked[key] = SOURCES["hn"]
    if args.get("k_f") is None:
        args["k_f"] = _sig4(estimate_k_f(args["rho15"], base_oil))
        marked["k_f"] = SOURCES["k_f"][base_oil]
    if args.get("c_p") is None:
        args["c_p"] = 2090.0
        marked["c_p"] = "the paper's Table 2 (both oils)"
    return args, marked


def _sig4(x):
    """An estimate to 4 significant digits (more would claim a precision it lacks)."""
    return float(f"{x:.4g}")


class LubricantError(ValueError):
    """Bad data-sheet values; the message says which and why."""


def _check_range(label, value, lo, hi, unit=""):
    if not (isinstance(value, (int, float)) and math.isfinite(value)):
        raise LubricantError(f"{label} = {value!r} is not a finite number")
    if not (lo <= value <= hi):
        u = f" {unit}" if unit else ""
        raise LubricantError(f"{label} = {value:g}{u} is outside the accepted range "
                             f"[{lo:g}, {hi:g}]{u}")


def walther_fit(kv40, kv100):
    """A, B of log10 log10(nu + 0.7) = A - B log10(T_K) through (40, kv40), (100, kv100)."""
    y1 = math.log10(math.log10(kv40 + 0.7))
    y2 = math.log10(math.log10(kv100 + 0.7))
    x1 = math.log10(40.0 + C0)
    x2 = math.log10(100.0 + C0)
    b = (y1 - y2) / (x2 - x1)
    return y1 + b * x1, b


def walther_nu(a, b, t_c):
    """Kinematic viscosity [mm^2/s] at t_c [degC] from the Walther constants."""
    return 10.0 ** (10.0 ** (a - b * math.log10(t_c + C0))) - 0.7


def density(rho15, t_c):
    """rho(T) = rho15 [1 - 6.5e-4 (T - 15)] [kg/m^3], T in degC (docs/physics.md §4.1, assumed)."""
    return rho15 * (1.0 - EXPANSION * (t_c - 15.0))


def vogel_through(temps_c, etas):
    """Exact Vogel (a [Pa s], b [K], c [degC]) through three (T [degC], eta [Pa s]) points."""
    t1, t2, t3 = temps_c
    l1, l2, l3 = (math.log(e) for e in etas)
    if not (t1 < t2 < t3) or not (l1 > l2 > l3):
        raise LubricantError("the viscosity must fall with temperature for a Vogel fit")

    def resid(c):
        x1, x2, x3 = 1.0 / (t1 - c), 1.0 / (t2 - c), 1.0 / (t3 - c)
        return (l1 - l2) * (x2 - x3) - (l2 - l3) * (x1 - x2)

    # the residual tends to -inf as c -> t1; scan up from absolute zero for the first sign change
    lo_bound, hi_bound = -C0 + 1e-9, t1 - 1e-9
    n = 4000
    prev_c, prev_r = lo_bound, resid(lo_bound)
    bracket = None
    for i in range(1, n + 1):
        c = lo_bound + (hi_bound - lo_bound) * i / n
        r = resid(c)
        if prev_r == 0.0:
            bracket = (prev_c, prev_c)
            break
        if (prev_r > 0.0) != (r > 0.0):
            bracket = (prev_c, c)
            break
        prev_c, prev_r = c, r
    if bracket is None:
        raise LubricantError(
            "no Vogel law eta = a exp(b/(T - c)) with c above absolute zero passes through "
            "these viscosities (the viscosity-temperature curve is too flat); check KV40/KV100")
    lo, hi = bracket
    r_lo = resid(lo)
    for _ in range(200):  # bisection to machine precision
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        r_mid = resid(mid)
        if (r_mid > 0.0) == (r_lo > 0.0):
            lo, r_lo = mid, r_mid
        else:
            hi = mid
    c = 0.5 * (lo + hi)
    x1, x2 = 1.0 / (t1 - c), 1.0 / (t2 - c)
    b = (l1 - l2) / (x1 - x2)
    a = math.exp(l1 - b * x1)
    return a, b, c


def fit_vogel(kv40, kv100, rho15):
    """docs/physics.md §4.1: Vogel a [Pa s], b [K], c [degC] from KV40, KV100 [mm^2/s], rho15 [kg/m^3]."""
    _check_range("KV40", kv40, 1.0, 1e5, "mm^2/s")
    _check_range("KV100", kv100, 0.5, 1e4, "mm^2/s")
    _check_range("rho15", rho15, 500.0, 2000.0, "kg/m^3")
    if not kv100 < kv40:
        raise LubricantError(f"KV100 = {kv100:g} mm^2/s must be below KV40 = {kv40:g} mm^2/s")
    wa, wb = walther_fit(kv40, kv100)
    temps = (40.0, 100.0, T_THIRD)
    nus = (kv40, kv100, walther_nu(wa, wb, T_THIRD))
    etas = [nu * 1e-6 * density(rho15, t) for nu, t in zip(nus, temps)]
    return vogel_through(temps, etas)


def vogel_eta(a, b, c_degc, t_degc):
    return a * math.exp(b / (t_degc - c_degc))


def _check_alpha(alpha_star, alpha_temps):
    if len(alpha_star) != 3 or len(alpha_temps) != 3:
        raise LubricantError("alpha* needs exactly three values at three temperatures")
    for i, (al, t) in enumerate(zip(alpha_star, alpha_temps)):
        _check_range(f"alpha* value {i + 1}", al, 0.1, 100.0, "1/GPa")
        _check_range(f"alpha* temperature {i + 1}", t, -73.15, 426.85, "degC")
    t, y = alpha_temps, alpha_star
    if not (t[0] + 1.0 <= t[1] and t[1] + 1.0 <= t[2]):
        raise LubricantError("the alpha* temperatures must increase (by at least 1 K each)")
    # the quadratic of docs/physics.md §4.2 must not increase on [t1, t3] (slopes at both ends <= 0)
    d1 = (y[1] - y[0]) / (t[1] - t[0])
    d2 = ((y[2] - y[1]) / (t[2] - t[1]) - d1) / (t[2] - t[0])
    if d1 + d2 * (t[0] - t[1]) > 0.0 or d1 + d2 * ((t[2] - t[0]) + (t[2] - t[1])) > 0.0:
        raise LubricantError(
            f"alpha* = {y[0]:g}, {y[1]:g}, {y[2]:g} 1/GPa: the quadratic through them must not "
            "increase with temperature between the first and last temperature")


def build(name, kv40, kv100, rho15, alpha_star, alpha_temps, hn_lambda, hn_alpha, hn_beta, k_f,
          c_p):
    """Checks the data-sheet values and returns the file's values (SI) plus the fit details."""
    if not isinstance(name, str) or not name.strip():
        raise LubricantError("the lubricant name is empty")
    if any(ch in name for ch in "#\n\r\0"):
        raise LubricantError("the lubricant name must not contain '#' or line breaks")
    if len(name.strip()) > 79:
        raise LubricantError("the lubricant name is longer than 79 characters")
    a, b, c = fit_vogel(kv40, kv100, rho15)
    _check_alpha(list(alpha_star), list(alpha_temps))
    _check_range("HN lambda", hn_lambda, 0.0, 1e-3, "s")
    _check_range("HN alpha", hn_alpha, 1e-3, 1.0)
    _check_range("HN beta", hn_beta, 1e-3, 10.0)
    if hn_alpha * hn_beta > 1.0 + 1e-12:
        raise LubricantError(f"HN alpha * beta = {hn_alpha * hn_beta:g} exceeds 1 (the shear "
                             "stress would fall as the shear rate rises)")
    _check_range("k_f", k_f, 0.01, 10.0, "W/(m K)")
    _check_range("c_p", c_p, 100.0, 1e5, "J/(kg K)")
    if c > alpha_temps[0] - 40.0:
        raise LubricantError(f"the Vogel pole c = {c:g} degC lies within 40 K of the first alpha* "
                             "temperature")
    return {
        "name": name.strip(), "vogel_a": a, "vogel_b": b, "vogel_c": c + C0,
        "alpha_T": [t + C0 for t in alpha_temps],
        "alpha_star": [float(f"{float(v)!r}e-9") for v in alpha_star],  # 1/GPa -> 1/Pa, exactly
        "hn_lambda": hn_lambda, "hn_alpha": hn_alpha, "hn_beta": hn_beta, "k_f": k_f,
        "c_p": c_p, "rho_15": rho15, "kv40": kv40, "kv100": kv100,
        "walther": walther_fit(kv40, kv100), "vogel_c_degc": c,
    }


def render(v, notes=(), marked=None):
    """The text of a "hypoid-lubricant 1" file; `marked` maps the keys that were estimated to
    their sources (each such line says ESTIMATED)."""
    marked = marked or {}
    g = lambda x: repr(float(x))  # noqa: E731  (shortest round-trip representation)
    wa, wb = v["walther"]
    lines = [
        f"# Lubricant {v['name']}: written by `hypoid lubricant` (hypoid/lubricant.py).",
        f"# Data sheet: KV40 = {v['kv40']:g} mm^2/s, KV100 = {v['kv100']:g} mm^2/s, "
        f"rho15 = {v['rho_15']:g} kg/m^3.",
        f"# Vogel fit (docs/physics.md §4.1): Walther A = {wa:.4f}, B = {wb:.4f}; third point at "
        f"{T_THIRD:g} degC;",
        f"# a = {v['vogel_a']:.4e} Pa s, b = {v['vogel_b']:.1f} K, "
        f"c = {v['vogel_c_degc']:.2f} degC.",
        "# eta_0 [mPa s] at " + ", ".join(
            f"{t} degC: {1e3 * vogel_eta(v['vogel_a'], v['vogel_b'], v['vogel_c_degc'], t):.1f}"
            for t in (20, 40, 60, 100, 140)),
    ]
    lines += [f"# {n}" for n in notes]
    if marked:
        lines.append("# ESTIMATED (not on the data sheet; replace them with measured values):")
        by_source = {}
        for key, src in marked.items():
            by_source.setdefault(src, []).append(key)
        lines += [f"#   {', '.join(keys)}: {src}" for src, keys in by_source.items()]
        lines.append("#   how: docs/data-files.md, 'Estimates for what a data sheet lacks'")
    lines += [
        "# Units: SI (Pa s, K, 1/Pa, s, W/(m K), J/(kg K), kg/m^3). Format: docs/data-files.md.",
        MAGIC,
        f"name {v['name']}",
        f"vogel_a {g(v['vogel_a'])}    # Pa s",
        f"vogel_b {g(v['vogel_b'])}    # K",
        f"vogel_c {g(v['vogel_c'])}    # K",
    ]
    for i in range(3):
        lines.append(f"alpha_star_T{i + 1} {g(v['alpha_T'][i])}    # K")
        lines.append(f"alpha_star_{i + 1} {g(v['alpha_star'][i])}    # 1/Pa")
    lines += [
        f"hn_lambda {g(v['hn_lambda'])}    # s",
        f"hn_alpha {g(v['hn_alpha'])}",
        f"hn_beta {g(v['hn_beta'])}",
        f"k_f {g(v['k_f'])}    # W/(m K)",
        f"c_p {g(v['c_p'])}    # J/(kg K)",
        f"rho_15 {g(v['rho_15'])}    # kg/m^3",
    ]
    return "\n".join(_mark(ln, marked) for ln in lines) + "\n"


def _mark(line, marked):
    key = line.split(" ", 1)[0]
    if key not in marked or line.startswith("#"):
        return line
    return line + (", " if "#" in line else "    # ") + "ESTIMATED"


def builtin_dir():
    """The checkout's resources/lubricants/ (an installed package has none: give --out-dir)."""
    return str(data.writable("resources/lubricants", "--out-dir"))


def write_builtin(out_dir=None):
    """Writes the built-in lubricant files; returns their paths."""
    out_dir = out_dir or builtin_dir()
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for name, data in BUILTIN.items():
        text = render(build(name=name, **data), BUILTIN_NOTES[name])
        path = os.path.join(out_dir, f"{name}.txt")
        with open(path, "w") as fh:
            fh.write(text)
        paths.append(path)
    return paths
