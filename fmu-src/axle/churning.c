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

/* ln C_m of the two regimes */
static double ln_cm_low(double h_D, double V_D3, double Fr, double Re)
{
    return log(1.366) + 0.45 * log(h_D) + 0.1 * log(V_D3) - 0.6 * log(Fr) - 0.21 * log(Re);
}

static double ln_cm_high(double h_D, double V_D3, double Fr, double b_D)
{
    return log(3.644) + 0.1 * log(h_D) - 0.35 * log(V_D3) - 0.88 * log(Fr) + 0.85 * log(b_D);
}

double hg_churn_cm(const hg_churn_geom *g, double nu, double omega)
{
    double D_p = 2.0 * g->R_p;
    double h_D = g->h / D_p, V_D3 = g->V_0 / (D_p * D_p * D_p), b_D = g->b / D_p;
    double Fr = omega * omega * g->R_p / HG_G;
    double Re = omega * g->R_p * g->b / nu;
    double Re_c = omega * g->R_p * g->h / nu;
    if (Re_c <= RE_C) return exp(ln_cm_low(h_D, V_D3, Fr, Re));
    /* inertial regime: no viscosity; the low-speed formula where it ends (Re at Re_c = RE_C),
     * or the high-speed formula where that is smaller (churning.h) */
    return exp(fmin(ln_cm_low(h_D, V_D3, Fr, RE_C * g->b / g->h), ln_cm_high(h_D, V_D3, Fr, b_D)));
}

double hg_churn_torque(const hg_churn_geom *g, double rho, double nu, double omega)
{
    double w = fabs(omega);
    double R3 = g->R_p * g->R_p * g->R_p;
    if (w <= 0.0) return 0.0;
    return 0.5 * rho * w * w * hg_churn_submerged_area(g->R_p, g->b, g->h) * R3 *
           hg_churn_cm(g, nu, w);
}
