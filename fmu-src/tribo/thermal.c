/* Conjunction temperature: see thermal.h. */
#include "tribo/thermal.h"

#include <float.h>
#include <math.h>
#include <string.h>

double hg_coleman_length(double a_c, double b_c, double u, double v)
{
    double den = a_c * a_c * u * u + b_c * b_c * v * v;
    /* eq. 19 multiplied through by u^2 (no trigonometry, no division by u) */
    if (!(den > 0.0)) return b_c;
    return a_c * b_c * sqrt((u * u + v * v) / den);
}

double hg_moving_source_resistance(double A, double k_s, double chi_s, double l, double U_tot)
{
    if (!(U_tot > HG_SPEED_FLOOR)) U_tot = HG_SPEED_FLOOR;
    return 1.06 / (A * k_s) * sqrt(chi_s * l / U_tot); /* eq. 18 (R_f,i: D2 of docs/physics.md §0) */
}

double hg_film_resistance(double h_c, double k_f, double A)
{
    return h_c / (2.0 * k_f * A); /* eq. 18 */
}

double hg_heat_partition(double R_fp, double R_fg, double R_cf)
{
    return (R_fg + R_cf) / (R_fp + R_fg + 2.0 * R_cf); /* eq. 17 */
}

double hg_flash_rise(double R_fp, double a_h, double q)
{
    return R_fp * a_h * q; /* eq. 16 */
}

double hg_oil_rise(double v_s, double tau, double h_c, double k_f)
{
    return v_s * tau * h_c / (8.0 * k_f); /* eq. 16 */
}

/* The solve, filled phase by phase (seed, complete, Brent); each phase returns 1 when it has
 * written the result. */
typedef struct {
    const hg_tc_problem *pb;
    hg_tau_fn fn;
    void *ctx;
    hg_tc_result *res;
    double T_cap; /* max(T_in, T_max) */
    int n;
    /* best bracket so far: g(xa) >= 0 (root at or right of xa), g(xb) <= 0 */
    int have_a, have_b;
    double xa, fa, ta, xb, fb, tb;
    double dtau; /* dtau/dT at the last evaluation */
} solver;

/* g(T) = T_in + c0 + c1 tau(T) - T (eq. 14) and dg/dT = c1 dtau/dT - 1 */
static double g_eval(solver *s, double T, double *tau, double *dg)
{
    double dtau = NAN;
    *tau = s->fn(T, s->ctx, &dtau);
    s->n++;
    s->dtau = dtau;
    *dg = s->pb->c1 * dtau - 1.0;
    return s->pb->T_in + s->pb->c0 + s->pb->c1 * *tau - T;
}

/* keeps the tightest ends of the bracket */
static void record(solver *s, double x, double f, double t)
{
    if (f >= 0.0 && (!s->have_a || x > s->xa)) s->xa = x, s->fa = f, s->ta = t, s->have_a = 1;
    if (f <= 0.0 && (!s->have_b || x < s->xb)) s->xb = x, s->fb = f, s->tb = t, s->have_b = 1;
}

static int finish(solver *s, double T, double tau, int flags)
{
    s->res->T_c = T;
    s->res->tau = tau;
    s->res->n_eval = s->n;
    s->res->flags |= flags;
    return 1;
}

/* root of the chord through the two ends of a bracket, with tau interpolated alike (error
 * O(width^2)); keeps the result a smooth function of the inputs however the bracket closed */
static int finish_chord(solver *s, double x1, double f1, double t1, double x2, double f2,
                        double t2, int flags)
{
    double w = f1 - f2 != 0.0 ? f1 / (f1 - f2) : 0.5;
    if (!(w >= 0.0 && w <= 1.0)) w = 0.5;
    return finish(s, x1 + w * (x2 - x1), t1 + w * (t2 - t1), flags);
}

/* g at the inlet: the isothermal first-guess rise; returns 1 when there is no heating */
static int first_guess(solver *s, double x, double f, double t)
{
    if (x != s->pb->T_in) return 0;
    s->res->dT_first = f;
    if (f > 1000.0) s->res->flags |= HG_TC_HUGE_RISE;
    if (f <= 0.0) return finish(s, x, t, 0); /* no heating (e.g. zero sliding): T_c = T_in */
    return 0;
}

/* 1. seed the bracket with safeguarded Newton steps from the warm start (or from T_in): every
 *    evaluated point tightens the bracket by the sign of g. From a good warm start one or two
 *    steps land within tol/4 of the root: where |g| <= tol/4 the Newton step from there ends the
 *    solve, else a probe just beyond the root closes a bracket narrower than tol. */
static int seed(solver *s, double T_warm)
{
    const hg_tc_problem *pb = s->pb;
    double x, f, t, df;
    int i;
    x = (isfinite(T_warm) && T_warm > pb->T_in && T_warm < s->T_cap) ? T_warm : pb->T_in;
    for (i = 0; i < 8; i++) {
        double step, lo, hi, xn;
        f = g_eval(s, x, &t, &df);
        if (first_guess(s, x, f, t)) return 1;
        if (f == 0.0) return finish(s, x, t, 0);
        record(s, x, f, t);
        if (x >= s->T_cap && f > 0.0) /* the root lies above the cap */
            return finish(s, s->T_cap, t, HG_TC_CAPPED);
        if (s->have_a && s->have_b && s->xb - s->xa <= pb->tol) break;
        step = (df < 0.0 && isfinite(df)) ? -f / df : f; /* Newton, else the fixed-point image */
        lo = s->have_a ? s->xa : pb->T_in;
        hi = s->have_b ? s->xb : s->T_cap;
        xn = x + step;
        if (fabs(f) <= 0.25 * pb->tol && xn > lo && xn < hi)
            /* g falls with slope <= -1, so the root lies within |g| <= tol/4 of x, and x + step
             * within tol/2 of it: done, tau carried along its derivative (error O(step^2)) */
            return finish(s, xn, t + step * (isfinite(s->dtau) ? s->dtau : 0.0), 0);
        if (fabs(step) < 0.25 * pb->tol) {
            /* within tol/4 of the root: probe just beyond it to close the bracket */
            xn = x + step + (step > 0.0 ? 0.25 : -0.25) * pb->tol;
            if (xn <= lo || xn >= hi) break; /* the bracket is closed already */
            f = g_eval(s, xn, &t, &df);
            if (f == 0.0) return finish(s, xn, t, 0);
            record(s, xn, f, t);
            break;
        }
        if (!(xn > lo && xn < hi)) {
            /* outside the bracket: fixed-point image (a valid bound for monotone tau), else
             * bisection */
            xn = x + f;
            if (!(xn > lo && xn < hi)) xn = s->have_b ? 0.5 * (lo + hi) : hi;
        }
        x = xn;
    }
    return 0;
}

/* 2. complete the bracket with fixed-point images, which land on the far side of the root
 *    whenever tau is non-increasing (docs/physics.md §6.6); expand to the cap otherwise */
static int complete(solver *s)
{
    const hg_tc_problem *pb = s->pb;
    double x, f, t = 0.0, df;
    int i;
    if (!s->have_a) {
        x = s->xb + s->fb;
        if (!(x > pb->T_in)) x = pb->T_in;
        f = g_eval(s, x, &t, &df);
        if (x == pb->T_in) s->res->dT_first = f;
        record(s, x, f, t);
        if (!s->have_a) { /* g(T_in) >= 0 always holds: c0, c1, tau >= 0 */
            x = pb->T_in;
            f = g_eval(s, x, &t, &df);
            s->res->dT_first = f;
            record(s, x, f, t);
        }
    }
    for (i = 0; !s->have_b && i < 200; i++) {
        x = s->xa + s->fa;
        if (x > s->T_cap) x = s->T_cap;
        f = g_eval(s, x, &t, &df);
        record(s, x, f, t);
        if (!s->have_b && x >= s->T_cap) return finish(s, s->T_cap, t, HG_TC_CAPPED);
    }
    if (!s->have_a || !s->have_b) /* unreachable for any tau(T) >= 0, kept for safety */
        return finish(s, s->have_a ? s->xa : pb->T_in, s->have_a ? s->ta : t,
                      HG_TC_NOT_CONVERGED);
    if (s->fa == 0.0) return finish(s, s->xa, s->ta, 0);
    if (s->fb == 0.0) return finish(s, s->xb, s->tb, 0);
    return 0;
}

/* Brent's step from the best estimate b, with the previous b at a and the contrapoint c: inverse
 * quadratic interpolation (secant when a = c) if it stays well inside the bracket, else
 * bisection. *d and *e are the last two step lengths. */
static void brent_step(double xa, double fa, double xb, double fb, double xc, double fc,
                       double xm, double tol1, double *d, double *e)
{
    double p, q, r, ss, m1, m2;
    if (!(fabs(*e) >= tol1 && fabs(fa) > fabs(fb))) {
        *d = *e = xm;
        return;
    }
    ss = fb / fa;
    if (xa == xc) { /* secant */
        p = 2.0 * xm * ss;
        q = 1.0 - ss;
    } else { /* inverse quadratic interpolation */
        q = fa / fc;
        r = fb / fc;
        p = ss * (2.0 * xm * q * (q - r) - (xb - xa) * (r - 1.0));
        q = (q - 1.0) * (r - 1.0) * (ss - 1.0);
    }
    if (p > 0.0)
        q = -q;
    else
        p = -p;
    m1 = 3.0 * xm * q - fabs(tol1 * q);
    m2 = fabs(*e * q);
    if (2.0 * p < (m1 < m2 ? m1 : m2)) {
        *e = *d;
        *d = p / q;
    } else { /* bisection */
        *d = *e = xm;
    }
}

/* 3. Brent's method on [xa, xb]. b is the best estimate, c the contrapoint, a the previous b. */
static void brent(solver *s)
{
    double xa = s->xa, fa = s->fa, ta = s->ta, xb = s->xb, fb = s->fb, tb = s->tb, df;
    double xc = xb, fc = fb, tc = tb, d = xb - xa, e = d; /* the first pass sets c = a */
    for (;;) {
        double tol1, xm;
        if ((fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0)) {
            xc = xa, fc = fa, tc = ta;
            d = e = xb - xa;
        }
        if (fabs(fc) < fabs(fb)) {
            xa = xb, fa = fb, ta = tb;
            xb = xc, fb = fc, tb = tc;
            xc = xa, fc = fa, tc = ta;
        }
        tol1 = 2.0 * DBL_EPSILON * fabs(xb) + 0.5 * s->pb->tol;
        xm = 0.5 * (xc - xb);
        if (fb == 0.0) {
            finish(s, xb, tb, 0);
            return;
        }
        if (fabs(xm) <= tol1 || s->n >= s->pb->max_eval) {
            finish_chord(s, xb, fb, tb, xc, fc, tc, fabs(xm) <= tol1 ? 0 : HG_TC_NOT_CONVERGED);
            return;
        }
        brent_step(xa, fa, xb, fb, xc, fc, xm, tol1, &d, &e);
        xa = xb, fa = fb, ta = tb;
        xb += fabs(d) > tol1 ? d : (xm > 0.0 ? tol1 : -tol1);
        fb = g_eval(s, xb, &tb, &df);
    }
}

void hg_tc_solve(const hg_tc_problem *pb, hg_tau_fn tau_of_T, void *ctx, double T_warm,
                 hg_tc_result *res)
{
    solver s;
    memset(&s, 0, sizeof s);
    s.pb = pb;
    s.fn = tau_of_T;
    s.ctx = ctx;
    s.res = res;
    s.T_cap = pb->T_max > pb->T_in ? pb->T_max : pb->T_in;
    res->dT_first = NAN;
    res->flags = 0;
    if (!(pb->T_in < s.T_cap)) { /* inlet already at the cap */
        double dt, t = tau_of_T(pb->T_in, ctx, &dt);
        s.n = 1;
        finish(&s, pb->T_in, t, HG_TC_CAPPED);
        return;
    }
    if (seed(&s, T_warm) || complete(&s)) return;
    brent(&s);
}
