#!/usr/bin/env python3
"""Generate fmu-src/tribo/f52_table.h: the Greenwood-Tripp function F_5/2 by quadrature.

    F_n(lam) = 1/sqrt(2 pi) * int_lam^inf (s - lam)^n exp(-s^2/2) ds          (docs/physics.md §5.3)

The C code interpolates ln F_5/2 with cubic Hermite polynomials on lam in [0, LAM_MAX] and uses the
asymptotic series beyond LAM_MAX. Hermite needs the slope: d/dlam F_n = -n F_(n-1), so
d ln F_5/2 / dlam = -2.5 F_3/2 / F_5/2 (F_3/2 is tabulated the same way).

The integrals are taken with s = lam + t^2 (ds = 2t dt), which makes the integrand
2 t^(2n+1) exp(-(lam + t^2)^2 / 2) smooth at the lower end, then scipy.integrate.quad at
relative tolerance 1e-13. An independent cross-check must agree to 1e-12: with t = exp(u) the
integrand decays double-exponentially at both ends, so the plain trapezoidal rule in u is
spectrally accurate. (scipy's parabolic-cylinder function pbdv, the other closed form, loses
accuracy beyond lam ~ 4 and is therefore not used.)

Usage:  python3 tools/gen_f52_table.py [output]      (default: fmu-src/tribo/f52_table.h)
"""

import math
import os
import sys

import numpy as np
from scipy import integrate

STEP = 0.05
LAM_MAX = 6.0
N_ASYM = 16  # terms of the asymptotic series used beyond LAM_MAX (matched at LAM_MAX)


def f_n(n, lam):
    def integrand(t):
        return 2.0 * t ** (2.0 * n + 1.0) * math.exp(-0.5 * (lam + t * t) ** 2)

    val, _ = integrate.quad(integrand, 0.0, np.inf, epsabs=0.0, epsrel=1e-13, limit=200)
    return val / math.sqrt(2.0 * math.pi)


def f_n_check(n, lam):
    u = np.linspace(-40.0, 4.0, 200001)
    t = np.exp(u)
    y = 2.0 * t ** (2.0 * n + 2.0) * np.exp(-lam * t * t - 0.5 * t ** 4)
    return float(np.trapezoid(y, u)) * math.exp(-0.5 * lam * lam) / math.sqrt(2.0 * math.pi)


def asym_series(n, lam, terms):
    """sum_k (-1)^k (n+1)(n+2)...(n+2k) / (2^k k! lam^2k), k = 0..terms-1."""
    total, term = 1.0, 1.0
    for k in range(1, terms):
        term *= -(n + 2 * k - 1) * (n + 2 * k) / (2.0 * k * lam * lam)
        total += term
    return total


def ln_asym(n, lam, terms):
    return (math.lgamma(n + 1.0) - 0.5 * math.log(2.0 * math.pi) - 0.5 * lam * lam
            - (n + 1.0) * math.log(lam) + math.log(asym_series(n, lam, terms)))


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    out = argv[1] if len(argv) > 1 else os.path.join(here, "..", "fmu-src", "tribo", "f52_table.h")
    count = int(round(LAM_MAX / STEP)) + 1
    lams = [i * STEP for i in range(count)]
    f52 = [f_n(2.5, x) for x in lams]
    f32 = [f_n(1.5, x) for x in lams]
    for x, a, b in zip(lams, f52, f32):
        for n, v in ((2.5, a), (1.5, b)):
            ref = f_n_check(n, x)
            if abs(v / ref - 1.0) > 1e-12:
                raise SystemExit(f"quadrature and trapezoid cross-check disagree: "
                                 f"n={n} lam={x} {v} {ref}")
    ln_f = [math.log(v) for v in f52]
    dln_f = [-2.5 * b / a for a, b in zip(f52, f32)]
    scale = math.log(f52[-1]) - ln_asym(2.5, LAM_MAX, N_ASYM)

    # self-check of the interpolation at the interval midpoints
    worst = 0.0
    for i in range(count - 1):
        x = (i + 0.5) * STEP
        h = STEP
        p = 0.5 * (ln_f[i] + ln_f[i + 1]) + h / 8.0 * (dln_f[i] - dln_f[i + 1])
        worst = max(worst, abs(math.exp(p) / f_n(2.5, x) - 1.0))
    if worst > 1e-7:
        raise SystemExit(f"interpolation error {worst:g} too large, use a finer STEP")
    # beyond LAM_MAX: series plus a matching correction that decays like the first omitted term
    worst_asym = 0.0
    for x in (6.05, 6.2, 6.5, 7.0, 7.5, 8.0, 9.0, 10.0, 12.0):
        approx = ln_asym(2.5, x, N_ASYM) + scale * (LAM_MAX / x) ** (2 * N_ASYM)
        worst_asym = max(worst_asym, abs(approx - math.log(f_n(2.5, x))))
    if worst_asym > 1e-6:
        raise SystemExit(f"asymptotic branch error {worst_asym:g} too large")

    def rows(vals):
        return ",\n".join("    " + ", ".join(f"{v:.17g}" for v in vals[i:i + 4])
                          for i in range(0, len(vals), 4))

    text = f"""/* GENERATED FILE - do not edit by hand.
 * Written by tools/gen_f52_table.py (python3 + numpy + scipy); regenerate with
 *     python3 tools/gen_f52_table.py
 * Greenwood-Tripp statistical function F_5/2(lambda) = 1/sqrt(2 pi) int_lambda^inf
 * (s - lambda)^(5/2) exp(-s^2/2) ds (docs/physics.md §5.3), by adaptive quadrature (rel. tol. 1e-13,
 * cross-checked to 1e-12 against an independent trapezoidal rule in ln t).
 * Nodes lambda_i = i * HG_F52_STEP, i = 0 .. HG_F52_COUNT-1. hg_f52_ln holds ln F_5/2(lambda_i),
 * hg_f52_dln its slope -2.5 F_3/2 / F_5/2 for cubic Hermite interpolation of ln F_5/2
 * (max. relative interpolation error at the interval midpoints: {worst:.1e}).
 * Beyond HG_F52_LAMBDA_MAX: ln F = lnGamma(7/2) - ln sqrt(2 pi) - lambda^2/2 - 3.5 ln lambda
 * + ln(asymptotic series with HG_F52_ASYM_TERMS terms) + HG_F52_ASYM_LN_SCALE
 * (HG_F52_LAMBDA_MAX/lambda)^(2 HG_F52_ASYM_TERMS); the last term makes the value continuous at
 * HG_F52_LAMBDA_MAX and decays like the first omitted term of the series (max. relative error
 * beyond HG_F52_LAMBDA_MAX: {worst_asym:.1e}). Only asperity.c includes this file. */
#ifndef HG_F52_TABLE_H
#define HG_F52_TABLE_H

#define HG_F52_COUNT {count}
#define HG_F52_STEP {STEP!r}
#define HG_F52_LAMBDA_MAX {LAM_MAX!r}
#define HG_F52_ASYM_TERMS {N_ASYM}
#define HG_F52_ASYM_LN_SCALE {scale:.17g}

static const double hg_f52_ln[HG_F52_COUNT] = {{
{rows(ln_f)}
}};

static const double hg_f52_dln[HG_F52_COUNT] = {{
{rows(dln_f)}
}};

#endif
"""
    with open(out, "w") as fh:
        fh.write(text)
    print(f"wrote {out}: {count} nodes, midpoint error {worst:.2e}, "
          f"asymptotic error {worst_asym:.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
