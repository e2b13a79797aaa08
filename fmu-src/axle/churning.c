/* Churning torque of the ring gear dipping into the sump (churning.h for the sources). */
#include "axle/churning.h"

#include <math.h>

#define HG_G 9.80665     /* standard gravity [m/s^2] */
#define RE_C 6000.0 /* Changenet & Velex's critical Reynolds number of the immersion */

double hg_churn_submerged_area(double R_p, double b, double h)
{
    double theta = acos(1.0 - h / R_p);
    return R_p * R_p * (2.0 * theta - sin(2.0 * theta)) + 2.0 * R_p * b * theta;
}

void hg_churn_terms_of(const hg_churn_geom *g, hg_churn_terms *t)
{
    double D_p = 2.0 * g->R_p;
    double h_D = g->h / D_p, V_D3 = g->V_0 / (D_p * D_p * D_p), b_D = g->b / D_p;
    t->S_m = hg_churn_submerged_area(g->R_p, g->b, g->h);
    t->R3 = g->R_p * g->R_p * g->R_p;
    /* ln C_low = ln_low0 - 0.6 ln Fr - 0.21 ln Re, ln C_high = ln_high0 - 0.88 ln Fr + ln_high_b */
    t->ln_low0 = log(1.366) + 0.45 * log(h_D) + 0.1 * log(V_D3);
    t->ln_low_re_c = 0.21 * log(RE_C * g->b / g->h); /* the 0.21 ln Re where the regime ends */
    t->ln_high0 = log(3.644) + 0.1 * log(h_D) - 0.35 * log(V_D3);
    t->ln_high_b = 0.85 * log(b_D);
    t->ln_R_g = log(g->R_p / HG_G);
    t->ln_R_b = log(g->R_p * g->b);
}

/* C_m from ln Fr and, in the viscous regime (low), ln Re */
static double cm_of_logs(const hg_churn_terms *t, int low, double ln_Fr, double ln_Re)
{
    if (low) return exp(t->ln_low0 - 0.6 * ln_Fr - 0.21 * ln_Re);
    /* inertial regime: no viscosity; the low-speed formula where it ends (Re at Re_c = RE_C),
     * or the high-speed formula where that is smaller (churning.h) */
    return exp(fmin(t->ln_low0 - 0.6 * ln_Fr - t->ln_low_re_c,
                    t->ln_high0 - 0.88 * ln_Fr + t->ln_high_b));
}

/* the immersion's Reynolds number Re_c <= RE_C: the viscous regime */
static int viscous(const hg_churn_geom *g, double nu, double omega)
{
    return omega * g->R_p * g->h / nu <= RE_C;
}

double hg_churn_cm_at(const hg_churn_geom *g, const hg_churn_terms *t, double nu, double omega)
{
    double Fr = omega * omega * g->R_p / HG_G;
    double Re = omega * g->R_p * g->b / nu;
    int low = viscous(g, nu, omega);
    double ln_Fr = log(Fr);
    return cm_of_logs(t, low, ln_Fr, low ? log(Re) : 0.0);
}

double hg_churn_cm(const hg_churn_geom *g, double nu, double omega)
{
    hg_churn_terms t;
    hg_churn_terms_of(g, &t);
    return hg_churn_cm_at(g, &t, nu, omega);
}

double hg_churn_torque_at(const hg_churn_geom *g, const hg_churn_terms *t, double rho, double nu,
                          double omega)
{
    double w = fabs(omega);
    if (w <= 0.0) return 0.0;
    return 0.5 * rho * w * w * t->S_m * t->R3 * hg_churn_cm_at(g, t, nu, w);
}

double hg_churn_torque_ln(const hg_churn_geom *g, const hg_churn_terms *t, double rho, double nu,
                          double ln_nu, double omega, double ln_omega)
{
    double w = fabs(omega), ln_Fr = 2.0 * ln_omega + t->ln_R_g;
    if (w <= 0.0) return 0.0;
    return 0.5 * rho * w * w * t->S_m * t->R3 *
           cm_of_logs(t, viscous(g, nu, w), ln_Fr, ln_omega + t->ln_R_b - ln_nu);
}

double hg_churn_torque(const hg_churn_geom *g, double rho, double nu, double omega)
{
    hg_churn_terms t;
    hg_churn_terms_of(g, &t);
    return hg_churn_torque_at(g, &t, rho, nu, omega);
}
