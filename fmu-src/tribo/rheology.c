/* Lubricant rheology: see rheology.h. */
#include "tribo/rheology.h"

#include <math.h>

double hg_vogel_ln_eta0(double ln_a, double b, double c, double T)
{
    double dT = T - c;
    if (!(dT >= HG_VOGEL_DT_MIN)) dT = HG_VOGEL_DT_MIN; /* also catches NaN */
    return ln_a + b / dT;
}

static void alpha_interp_init(const hg_lubricant *lub, hg_alpha_interp *ai)
{
    /* Newton divided differences of the quadratic through the three points (docs/physics.md §4.2) */
    const double *t = lub->alpha_T, *y = lub->alpha_star;
    double d12 = (y[2] - y[1]) / (t[2] - t[1]);
    ai->T0 = t[0], ai->T1 = t[1], ai->T2 = t[2];
    ai->y0 = y[0], ai->y2 = y[2];
    ai->d1 = (y[1] - y[0]) / (t[1] - t[0]);
    ai->d2 = (d12 - ai->d1) / (t[2] - t[0]);
    /* slopes of ln alpha* at the ends, continued log-linearly outside (C1) */
    ai->s0 = (ai->d1 + ai->d2 * (t[0] - t[1])) / y[0];
    ai->s2 = (ai->d1 + ai->d2 * ((t[2] - t[0]) + (t[2] - t[1]))) / y[2];
}

static double alpha_interp_eval(const hg_alpha_interp *ai, double T, double *dlnalpha_dT)
{
    double val;
    if (T < ai->T0) {
        val = ai->y0 * exp(ai->s0 * (T - ai->T0));
        if (dlnalpha_dT) *dlnalpha_dT = ai->s0;
    } else if (T > ai->T2) {
        val = ai->y2 * exp(ai->s2 * (T - ai->T2));
        if (dlnalpha_dT) *dlnalpha_dT = ai->s2;
    } else {
        val = ai->y0 + (T - ai->T0) * (ai->d1 + (T - ai->T1) * ai->d2);
        if (dlnalpha_dT) *dlnalpha_dT = (ai->d1 + ai->d2 * ((T - ai->T0) + (T - ai->T1))) / val;
    }
    return val;
}

double hg_roelands_A(double ln_eta0)
{
    double A = ln_eta0 + HG_ROELANDS_LN_ETA_R;
    return A > HG_ROELANDS_A_MIN ? A : HG_ROELANDS_A_MIN;
}

double hg_roelands_Z_simple(double alpha_star, double A)
{
    return alpha_star * HG_ROELANDS_P0 / A;
}

/* C(a, x) = e^x x^-a Gamma(a, x) = 1/(x+1-a - 1(1-a)/(x+3-a - 2(2-a)/(x+5-a - ...))) and dC/da,
 * by the forward recurrence of the convergents (no division per term). Converges for x > 0;
 * x >= HG_ROELANDS_A_MIN here needs < 110 terms for a <= 13. */
static double gamma_cf(double a, double x, double *dC_da)
{
    double Pm = 1.0, P = x + 1.0 - a, dPm = 0.0, dP = -1.0;
    double Qm = 0.0, Q = 1.0, dQm = 0.0, dQ = 0.0;
    double C_old = Q / P;
    int n;
    for (n = 1; n <= 600; n++) {
        double an = -n * (n - a), bn = x + 2.0 * n + 1.0 - a, t;
        t = bn * dP - P + an * dPm + n * Pm;
        dPm = dP;
        dP = t;
        t = bn * P + an * Pm;
        Pm = P;
        P = t;
        t = bn * dQ - Q + an * dQm + n * Qm;
        dQm = dQ;
        dQ = t;
        t = bn * Q + an * Qm;
        Qm = Q;
        Q = t;
        if ((n & 3) == 0) {
            double C = Q / P;
            if (fabs(P) > 1e150) { /* rescale: the ratios are unchanged */
                Pm *= 1e-150, P *= 1e-150, dPm *= 1e-150, dP *= 1e-150;
                Qm *= 1e-150, Q *= 1e-150, dQm *= 1e-150, dQ *= 1e-150;
            }
            if (fabs(C - C_old) <= 1e-15 * fabs(C)) break;
            C_old = C;
        }
    }
    *dC_da = (dQ * P - Q * dP) / (P * P);
    return Q / P;
}

double hg_roelands_Z_exact(double alpha_star, double A, double Z_guess, double *dZ_dA,
                           double *dZ_dlnalpha)
{
    double s = alpha_star * HG_ROELANDS_P0, ln_s, u, a = 1.0, C = 1.0, dC = 0.0, dphi = -1.0;
    int it;
    if (dZ_dA) *dZ_dA = 0.0;
    if (dZ_dlnalpha) *dZ_dlnalpha = 0.0;
    if (!(s > 0.0)) return 0.0;
    if (A < HG_ROELANDS_A_MIN) A = HG_ROELANDS_A_MIN;
    if (s < HG_Z_EXACT_S_MIN || A > HG_Z_EXACT_A_MAX) {
        /* outside the validated domain (far beyond any oil data): the pressure response is
         * then negligible or the temperature absurd; fall back to Z_simple */
        if (dZ_dA) *dZ_dA = -s / (A * A);
        if (dZ_dlnalpha) *dZ_dlnalpha = s / A;
        return s / A;
    }
    ln_s = log(s);
    if (Z_guess > 0.0) {
        u = -log(Z_guess);
    } else {
        /* for large A, C(a, A) ~ (1 + (a-1)/A)/A, so alpha* p0 = Z/C gives the quadratic
         * A Z^2 - s (1 - 1/A) Z - s/A = 0; its root is within ~1e-3 of Z_exact for oils.
         * Elsewhere Z ~ (s+1)/(A+1) (first order in 1/A) is the safer start. */
        double bq = s * (1.0 - 1.0 / A), Zq = (bq + sqrt(bq * bq + 4.0 * s)) / (2.0 * A);
        u = (A >= 2.0 && Zq * A > 2.0) ? -log(Zq) : log((A + 1.0) / (s + 1.0));
    }
    for (it = 0; it < 60; it++) {
        double phi, step;
        a = exp(u);
        C = gamma_cf(a, A, &dC);
        phi = -u - log(C) - ln_s; /* ln(alpha*_Roelands p0) - ln(alpha* p0) */
        dphi = -1.0 - a * dC / C; /* d phi / d u, < 0 */
        step = phi / dphi;
        if (step > 1.0) step = 1.0;
        if (step < -1.0) step = -1.0;
        u -= step;
        if (u > 12.0) u = 12.0; /* Z in [6e-6, 150]: far wider than the validated domain */
        if (u < -5.0) u = -5.0;
        if (fabs(step) < 1e-7) break; /* quadratic convergence: remaining error ~1e-14 */
    }
    if (dZ_dA || dZ_dlnalpha) {
        /* implicit differentiation of phi(u; A, ln s) = 0 at the last iterate:
         * phi_A = -C_x/C with C_x = C (1 - a/A) - 1/A (from dGamma(a,x)/dx = -x^(a-1) e^-x),
         * phi_lns = -1, and dZ = -Z du */
        double Z = exp(-u), phi_A = -((1.0 - a / A) - 1.0 / (A * C));
        if (dZ_dA) *dZ_dA = Z * phi_A / dphi;
        if (dZ_dlnalpha) *dZ_dlnalpha = -Z / dphi;
    }
    return exp(-u);
}

void hg_rheology_init(hg_rheology *r, const hg_lubricant *lub, int z_exact,
                      const hg_z_table *z_table)
{
    r->lub = lub;
    alpha_interp_init(lub, &r->ai);
    r->ln_a = log(lub->vogel_a);
    r->z_exact = z_exact;
    r->z_table = z_exact ? z_table : NULL;
    r->T_last = r->Z_last = r->dZdT_last = 0.0;
}

/* Z_exact and dZ/dT at the state s (its temperature s->T_r), warm-started from guess (<= 0:
 * none); whether (alpha*, A) lie in Z_exact's validated domain. */
static int z_exact_at(const hg_rheo_state *s, double guess, double *Z, double *dZ)
{
    double dZ_dA, dZ_dlna, sp = s->alpha * HG_ROELANDS_P0;
    *Z = hg_roelands_Z_exact(s->alpha, s->A, guess, &dZ_dA, &dZ_dlna);
    *dZ = dZ_dA * s->dA + dZ_dlna * s->dlnalpha;
    if (!isfinite(*dZ)) *dZ = 0.0;
    return sp > 0.0 && !(sp < HG_Z_EXACT_S_MIN) && !(s->A > HG_Z_EXACT_A_MAX);
}

void hg_z_table_build(hg_z_table *t, const hg_lubricant *lub)
{
    hg_rheology r;
    double T_lo = lub->vogel_c + HG_VOGEL_DT_MIN, guess = 0.0;
    double ends[4];
    int seg, k, n = 0;
    hg_rheology_init(&r, lub, 1, NULL);
    ends[0] = T_lo, ends[1] = lub->alpha_T[0], ends[2] = lub->alpha_T[2], ends[3] = HG_RHEO_T_MAX;
    if (ends[1] < ends[0]) ends[1] = ends[0]; /* a data point below the clamp (not loadable) */
    if (ends[2] > ends[3]) ends[2] = ends[3];
    for (seg = 0; seg < 3; seg++) {
        double span = ends[seg + 1] - ends[seg];
        int cells = (int)ceil(span / HG_ZTAB_DT - 1e-9);
        if (cells < 1) cells = 1;
        t->T_node[seg] = ends[seg];
        t->dT[seg] = span / cells;
        t->first[seg] = n;
        for (k = seg == 0 ? 0 : 1; k <= cells && n < HG_ZTAB_MAX; k++, n++) {
            hg_rheo_state st;
            double T = k == cells ? ends[seg + 1] : ends[seg] + k * t->dT[seg];
            if (n == 0) T = nextafter(T, HUGE_VAL); /* the clamp itself has no derivatives */
            hg_rheology_at(&r, T, &st);
            t->exact[n] = (unsigned char)z_exact_at(&st, guess, &t->Z[n], &t->dZ[n]);
            guess = t->Z[n];
        }
        if (seg > 0) t->first[seg]--; /* a segment starts on the last node of the one before */
    }
    t->first[3] = n < HG_ZTAB_MAX ? n : 0; /* too many nodes (no oil): solve every T instead */
}

/* Z and dZ/dT at the clamped temperature T from the table; 0 when the cell is not tabulated
 * (a node outside Z_exact's domain, or T beyond the nodes). Cubic Hermite on the cell. */
static int z_from_table(const hg_z_table *t, double T, double *Z, double *dZ)
{
    int seg = T < t->T_node[1] ? 0 : T < t->T_node[2] ? 1 : 2, i;
    double x = (T - t->T_node[seg]) / t->dT[seg], h = t->dT[seg], u, u2, u3;
    i = (int)x;
    if (!(x >= 0.0)) return 0;
    if (t->first[seg] + i + 1 >= t->first[seg + 1] + (seg == 2 ? 0 : 1)) i--; /* the end node */
    i += t->first[seg];
    if (i < 0 || i + 1 >= t->first[3] || !t->exact[i] || !t->exact[i + 1]) return 0;
    u = x - (double)(i - t->first[seg]);
    u2 = u * u, u3 = u2 * u;
    *Z = (2.0 * u3 - 3.0 * u2 + 1.0) * t->Z[i] + (u3 - 2.0 * u2 + u) * h * t->dZ[i] +
         (-2.0 * u3 + 3.0 * u2) * t->Z[i + 1] + (u3 - u2) * h * t->dZ[i + 1];
    *dZ = ((6.0 * u2 - 6.0 * u) * (t->Z[i] - t->Z[i + 1]) / h +
           (3.0 * u2 - 4.0 * u + 1.0) * t->dZ[i] + (3.0 * u2 - 2.0 * u) * t->dZ[i + 1]);
    return 1;
}

void hg_rheology_at(const hg_rheology *r, double T, hg_rheo_state *s)
{
    const hg_lubricant *lub = r->lub;
    int clamped = !(T - lub->vogel_c > HG_VOGEL_DT_MIN) || T > HG_RHEO_T_MAX;
    s->T_r = T > HG_RHEO_T_MAX ? HG_RHEO_T_MAX : (clamped ? lub->vogel_c + HG_VOGEL_DT_MIN : T);
    s->ln_eta0 = hg_vogel_ln_eta0(r->ln_a, lub->vogel_b, lub->vogel_c, s->T_r);
    s->A = hg_roelands_A(s->ln_eta0);
    s->alpha = alpha_interp_eval(&r->ai, s->T_r, &s->dlnalpha);
    s->dL0 = clamped ? 0.0 : -lub->vogel_b / ((s->T_r - lub->vogel_c) * (s->T_r - lub->vogel_c));
    s->dA = s->ln_eta0 + HG_ROELANDS_LN_ETA_R > HG_ROELANDS_A_MIN ? s->dL0 : 0.0;
    if (clamped) s->dlnalpha = 0.0;
    s->Z = s->dZ = 0.0;
}

/* Z' = Z (d ln(alpha*)/dT - A'/A) for Z_simple = alpha* p0 / A; for Z_exact from its partial
 * derivatives (implicit differentiation in hg_roelands_Z_exact) */
void hg_rheology_Z(hg_rheology *r, double T, hg_rheo_state *s)
{
    if (r->z_table && z_from_table(r->z_table, s->T_r, &s->Z, &s->dZ)) {
        /* a clamped T (hg_rheology_at): Z is that of the clamp's temperature, constant beyond */
        if (!(T - r->lub->vogel_c > HG_VOGEL_DT_MIN) || T > HG_RHEO_T_MAX) s->dZ = 0.0;
    } else if (r->z_exact) {
        double dZ_dA, dZ_dlna, guess = 0.0;
        if (r->Z_last > 0.0) guess = r->Z_last + r->dZdT_last * (T - r->T_last);
        s->Z = hg_roelands_Z_exact(s->alpha, s->A, guess > 0.0 ? guess : r->Z_last, &dZ_dA,
                                   &dZ_dlna);
        s->dZ = dZ_dA * s->dA + dZ_dlna * s->dlnalpha;
        if (!isfinite(s->dZ)) s->dZ = 0.0;
        r->T_last = T, r->Z_last = s->Z, r->dZdT_last = s->dZ;
    } else {
        s->Z = hg_roelands_Z_simple(s->alpha, s->A);
        s->dZ = s->Z * (s->dlnalpha - s->dA / s->A);
    }
}

/* d ln eta/dT = L0' + A' (e^(Z lp) - 1) + A e^(Z lp) lp Z' */
double hg_roelands_ln_eta(const hg_rheo_state *s, double ln1p_p, double *dlneta_dT)
{
    double eZ = exp(s->Z * ln1p_p), ln_eta = s->ln_eta0 + s->A * (eZ - 1.0); /* eq. 9 */
    *dlneta_dT = s->dL0 + s->dA * (eZ - 1.0) + s->A * eZ * ln1p_p * s->dZ;
    if (ln_eta > HG_LN_ETA_MAX) {
        *dlneta_dT = 0.0;
        return HG_LN_ETA_MAX;
    }
    return ln_eta;
}

double hg_hn_factor(double lambda, double alpha_hn, double beta_hn, double gamma_dot)
{
    double x = lambda * gamma_dot;
    if (!(x > 0.0)) return 1.0;
    if (beta_hn == 1.0) return 1.0 + pow(x, alpha_hn); /* the paper's oils */
    return pow(1.0 + pow(x, alpha_hn), beta_hn);
}

double hg_shear_limit(double tau_v, double tau_L, double *slope)
{
    double x, e;
    if (!(tau_L > 0.0)) {
        *slope = 1.0;
        return tau_v;
    }
    x = tau_v / tau_L;
    e = expm1(-x);
    *slope = 1.0 + e; /* exp(-x), from the same call */
    return -tau_L * e;
}
