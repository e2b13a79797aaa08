/* Contact kinematics and Hertzian ellipse: see contact.h. */
#include "tribo/contact.h"

#include <math.h>

#include "io/constants.h"

void hg_kinematics_eval(const double u_p[2], const double u_g[2], hg_kinematics *kin)
{
    double ux = 0.5 * (u_p[0] + u_g[0]), uy = 0.5 * (u_p[1] + u_g[1]);
    double ue2 = ux * ux + uy * uy;
    kin->U_e[0] = ux;
    kin->U_e[1] = uy;
    kin->u_e = sqrt(ue2);
    kin->V_s[0] = u_p[0] - u_g[0];
    kin->V_s[1] = u_p[1] - u_g[1];
    kin->v_s = sqrt(kin->V_s[0] * kin->V_s[0] + kin->V_s[1] * kin->V_s[1]);
    if (ue2 > 0.0) {
        kin->cos2_e = ux * ux / ue2; /* theta_e from the minor axis (docs/physics.md §1) */
        kin->sin2_e = uy * uy / ue2;
    } else {
        kin->cos2_e = 1.0;
        kin->sin2_e = 0.0;
    }
    kin->U_p = sqrt(u_p[0] * u_p[0] + u_p[1] * u_p[1]);
    kin->U_g = sqrt(u_g[0] * u_g[0] + u_g[1] * u_g[1]);
}

double hg_entrainment_angle(const double U_e[2])
{
    return atan2(fabs(U_e[1]), fabs(U_e[0]));
}

void hg_entrainment_radii(double R_x, double R_y, double cos2_e, double sin2_e, double *R_e,
                          double *R_s)
{
    /* 1/R_e = cos^2/R_x + sin^2/R_y ; 1/R_s = sin^2/R_x + cos^2/R_y   (docs/physics.md §2.2) */
    *R_e = 1.0 / (cos2_e / R_x + sin2_e / R_y);
    *R_s = 1.0 / (sin2_e / R_x + cos2_e / R_y);
}

/* Series about m = 1, for m1 = 1 - m <= 0.1 where 16 terms reach 1e-17 with no square root
 * (cheaper than the AGM in the hot path; agreement with the AGM to ~1e-16 is tested).
 * With L = ln(4/sqrt(m1)) and d_n = sum_(j=1..n) 2/((2j-1) 2j):
 *   K = L + sum_(n>=1) [(1/2)_n/n!]^2 m1^n (L - d_n)
 *   E = 1 + sum_(n>=1) (1/2)_n (1/2)_(n-1)/(n! (n-1)!) m1^n (L - d_n + 1/(2n(2n-1)))
 * The coefficients n = 1..20 are these exact rationals, to 17 digits. */
#define SERIES_N 20
#define LN4 1.3862943611198906
static const double ser_k[SERIES_N] = { /* [(1/2)_n / n!]^2 */
    0.25, 0.140625, 0.09765625, 0.07476806640625,
    0.0605621337890625, 0.050889015197753906, 0.043878793716430664, 0.038565346039831638,
    0.034399336436763406, 0.031045401134178974, 0.0282872353309358, 0.025979075503585136,
    0.024019115665296908, 0.022334101173471232, 0.020869976763210341, 0.019585984052192518,
    0.01845081023601873, 0.017440001959199803, 0.016534184682925574, 0.015717809314206122};
static const double ser_dk[SERIES_N] = { /* d_n = sum_(j<=n) 2/((2j-1) 2j) */
    1, 1.1666666666666667, 1.2333333333333334, 1.269047619047619,
    1.2912698412698413, 1.3064213564213565, 1.3174103674103674, 1.3257437007437007,
    1.332279648456119, 1.3375428063508559, 1.3418718106798602, 1.3454949990856573,
    1.3485719221625805, 1.351217424808083, 1.3535162753827956, 1.3555324044150538,
    1.3573149356093497, 1.3589022371966513, 1.3603247123033368, 1.3616067635853881};
static const double ser_e[SERIES_N] = { /* (1/2)_n (1/2)_(n-1) / (n! (n-1)!) */
    0.5, 0.1875, 0.1171875, 0.08544921875,
    0.067291259765625, 0.055515289306640625, 0.047254085540771484, 0.041136369109153748,
    0.036422826815396547, 0.032679369614925236, 0.029634246537170839, 0.027108600525480142,
    0.024979880291908785, 0.023161290105822019, 0.021589631134355525, 0.020217789989360017,
    0.019009925697716267, 0.017938287729462654, 0.016981054539220861, 0.016120830065852434};
static const double ser_de[SERIES_N] = { /* d_n - 1/(2n(2n-1)) */
    0.5, 1.0833333333333333, 1.2, 1.2511904761904762,
    1.2801587301587301, 1.2988455988455989, 1.311915861915862, 1.3215770340770341,
    1.3290116745999099, 1.3349112274034876, 1.3397073085153581, 1.3436834048827588,
    1.3470334606241188, 1.3498946734853317, 1.3523668500954393, 1.3545243398989246,
    1.3564236700122017, 1.3581085864030005, 1.3596134747499939, 1.3609657379443625};

static void ellip_KE_series(double m1, double L, double *K, double *E)
{
    double k = L, e = 1.0, p = 1.0;
    int n;
    for (n = 0; n < SERIES_N; n++) {
        p *= m1;
        k += ser_k[n] * p * (L - ser_dk[n]);
        e += ser_e[n] * p * (L - ser_de[n]);
        if (ser_k[n] * p < 1e-17) break;
    }
    *K = k;
    *E = e;
}

void hg_ellip_KE_c(double m1, double *K, double *E)
{
    /* AGM: a0 = 1, b0 = sqrt(1-m), c0 = sqrt(m); K = pi/(2 a_N), E = K (1 - sum 2^(n-1) c_n^2) */
    double a = 1.0, b, c, sum, pow2 = 0.5;
    int n;
    if (m1 <= 0.0) { /* m = 1: K diverges; callers never get here (ratio is clamped) */
        *K = HUGE_VAL;
        *E = 1.0;
        return;
    }
    if (m1 <= 0.1) {
        ellip_KE_series(m1, LN4 - 0.5 * log(m1), K, E);
        return;
    }
    if (m1 > 1.0) m1 = 1.0;
    b = sqrt(m1);
    c = sqrt(1.0 - m1);
    sum = pow2 * c * c;
    for (n = 0; n < 40 && c > 1e-16 * a; n++) {
        double an = 0.5 * (a + b);
        c = 0.5 * (a - b);
        pow2 *= 2.0;
        sum += pow2 * c * c;
        if (c < 1e-9 * a) { /* next c ~ c^2/(4a) < 1e-18 a: one last mean, no sqrt needed */
            a = an;
            break;
        }
        b = sqrt(a * b);
        a = an;
    }
    *K = 0.5 * HG_PI / a;
    *E = *K * (1.0 - sum);
}

void hg_ellip_KE(double m, double *K, double *E)
{
    hg_ellip_KE_c(1.0 - m, K, E);
}

/* Residual f(x) = (k^2 E - K) - ratio (K - E) at x = ln k, whose root is the ellipticity
 * (Hamrock & Dowson 1981: (k^2 E - K)/(K - E) = R_y/R_x), with its first two derivatives for
 * Halley's method. With m1 = 1/k^2 = e^(-2x), m = 1 - m1, dm/dx = 2 m1,
 * dE/dm = (E - K)/(2m) and dK/dm = (E - m1 K)/(2 m m1):
 *   E_x = m1 (E - K)/m,  K_x = (E - m1 K)/m, and the second derivatives by the product rule.
 * N = k^2 E - K, D = K - E. Also returns E, K and their derivatives. */
typedef struct {
    double E, K, Ex, Kx, Exx, Kxx;
} ke_derivs;

static double ratio_residual(double x, double ratio, double *f1, double *f2, ke_derivs *d)
{
    /* written with a few reciprocals instead of many divisions: this runs in every call */
    double k2 = exp(2.0 * x), m1 = 1.0 / k2, im = 1.0 / (1.0 - m1), E, K, Ex, Kx, Exx, Kxx;
    double N, Nx, Nxx;
    if (m1 <= 0.1)
        ellip_KE_series(m1, LN4 + x, &K, &E); /* L = ln(4/sqrt(m1)) = ln 4 + x, no log needed */
    else
        hg_ellip_KE_c(m1, &K, &E);
    Ex = m1 * (E - K) * im;
    Kx = (E - m1 * K) * im;
    Exx = m1 * ((Ex - Kx) - 2.0 * (E - K) - 2.0 * Ex) * im;
    Kxx = (Ex + 2.0 * m1 * K - 3.0 * m1 * Kx) * im;
    N = E * k2 - K;
    Nx = (Ex + 2.0 * E) * k2 - Kx;
    Nxx = (Exx + 4.0 * Ex + 4.0 * E) * k2 - Kxx;
    *f1 = Nx - ratio * (Kx - Ex);
    *f2 = Nxx - ratio * (Kxx - Exx);
    d->E = E, d->K = K, d->Ex = Ex, d->Kx = Kx, d->Exx = Exx, d->Kxx = Kxx;
    return N - ratio * (K - E);
}

double hg_ellipticity(double ratio, hg_hertz_mode mode, double *E_bar, double *F_bar)
{
    double k, E, K;
    if (!(ratio > 1.0)) ratio = 1.0; /* also catches NaN */
    if (ratio > HG_HERTZ_RATIO_MAX) ratio = HG_HERTZ_RATIO_MAX;
    if (mode == HG_HERTZ_APPROX) {
        /* Hamrock & Brewe 1983 */
        k = 1.0339 * pow(ratio, 0.6360);
        E = 1.0003 + 0.5968 / ratio;
        K = 1.5277 + 0.6023 * log(ratio);
    } else if (ratio < 1.0 + 1e-7) {
        /* near-circular: k - 1 = (2/pi) (ratio - 1) to first order; E = K = pi/2 */
        k = pow(ratio, 2.0 / HG_PI);
        E = K = 0.5 * HG_PI;
    } else {
        double x, f, f1, f2, step = 0.0;
        ke_derivs d;
        int it;
        k = 1.0339 * pow(ratio, 0.6360); /* Hamrock-Brewe start, |ln k error| < 0.03 */
        if (ratio > 10.0) {
            /* large ratio: K ~ ln(4k), E ~ 1, so ratio ~ k^2/(ln 4k - 1); two fixed-point passes
             * (|ln k error| < 0.05, < 2e-3 beyond ratio 100) */
            k = sqrt(ratio * (log(4.0 * k) - 1.0));
            k = sqrt(ratio * (log(4.0 * k) - 1.0));
        }
        x = log(k);
        /* Halley's method in ln k on the exact K, E: cubic convergence, so the second step is
         * already below ~1e-7 and leaves an error ~1e-20; stop once a step is below 1e-5 */
        for (it = 0; it < 30; it++) {
            f = ratio_residual(x, ratio, &f1, &f2, &d);
            step = f / f1;
            step /= 1.0 - 0.5 * step * f2 / f1; /* Halley */
            if (!(step <= 0.5)) step = 0.5; /* also catches NaN */
            if (step < -0.5) step = -0.5;
            x -= step;
            if (x < 1e-9) x = 1e-9;
            if (fabs(step) < 1e-5) break;
        }
        /* E and K were evaluated before the last step: carry them to the final ln k by Taylor
         * (the neglected term is O(step^3)) */
        E = d.E - d.Ex * step + 0.5 * d.Exx * step * step;
        K = d.K - d.Kx * step + 0.5 * d.Kxx * step * step;
        k = exp(x);
    }
    if (E_bar) *E_bar = E;
    if (F_bar) *F_bar = K;
    return k;
}

void hg_hertz_eval(double W, double R_x, double R_y, double E_star, hg_hertz_mode mode,
                   hg_hertz *h)
{
    double R = 1.0 / (1.0 / R_x + 1.0 / R_y), big = R_x > R_y ? R_x : R_y;
    double small = R_x > R_y ? R_y : R_x, k, E, K, base;
    k = hg_ellipticity(big / small, mode, &E, &K);
    if (W < 0.0) W = 0.0;
    /* a_c = (6 k^2 E W R/(pi E*))^(1/3), b_c = (6 E W R/(pi k E*))^(1/3)   (docs/physics.md §2.3) */
    base = cbrt(6.0 * E * W * R / (HG_PI * E_star * k));
    h->k = k;
    h->E_bar = E;
    h->F_bar = K;
    h->R = R;
    h->b_c = base;
    h->a_c = base * k;
    if (R_x <= R_y) {
        h->s_x = h->b_c;
        h->s_y = h->a_c;
    } else {
        h->s_x = h->a_c;
        h->s_y = h->b_c;
    }
    h->A = HG_PI * h->a_c * h->b_c; /* A_EHL (paper eq. 6) */
    h->p_m = h->A > 0.0 ? W / h->A : 0.0;
    h->p_max = 1.5 * h->p_m;
}
