/* Churning torque of the ring gear dipping into the sump (churning.h for the sources). */
#include "axle/churning.h"

#include <math.h>

#define HG_G 9.80665     /* standard gravity [m/s^2] */
#define RE_C_LOW 6000.0  /* Changenet & Velex 2008: below, the 2007 formula */
#define RE_C_HIGH 9000.0 /* above, the 2008 high-speed formula */

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
    double lo, hi, s;
    if (Re_c <= RE_C_LOW) return exp(ln_cm_low(h_D, V_D3, Fr, Re));
    if (Re_c >= RE_C_HIGH) return exp(ln_cm_high(h_D, V_D3, Fr, b_D));
    lo = ln_cm_low(h_D, V_D3, Fr, Re);
    hi = ln_cm_high(h_D, V_D3, Fr, b_D);
    s = log(Re_c / RE_C_LOW) / log(RE_C_HIGH / RE_C_LOW);
    s = s * s * (3.0 - 2.0 * s); /* smoothstep: C1 at both ends */
    return exp(lo + s * (hi - lo));
}

double hg_churn_torque(const hg_churn_geom *g, double rho, double nu, double omega)
{
    double w = fabs(omega);
    double R3 = g->R_p * g->R_p * g->R_p;
    if (w <= 0.0) return 0.0;
    return 0.5 * rho * w * w * hg_churn_submerged_area(g->R_p, g->b, g->h) * R3 *
           hg_churn_cm(g, nu, w);
}
