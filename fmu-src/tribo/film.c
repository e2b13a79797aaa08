/* Central film thickness: see film.h. */
#include "tribo/film.h"

#include <math.h>

double hg_film_chittenden(double eta0, double alpha_star, double u_e, double W, double E_star,
                          double R_e, double R_s)
{
    double lnU, lnG, lnW, r23;
    if (!(u_e > 0.0 && W > 0.0 && eta0 > 0.0 && alpha_star > 0.0)) return 0.0;
    lnU = log(eta0 * u_e / (E_star * R_e)); /* U_e */
    lnG = log(alpha_star * E_star);         /* G */
    lnW = log(W / (E_star * R_e * R_e));    /* W_e */
    r23 = cbrt(R_s / R_e);
    r23 *= r23; /* (R_s/R_e)^(2/3) */
    /* eq. 10 */
    return 4.31 * R_e * exp(0.68 * lnU + 0.49 * lnG - 0.073 * lnW) * (1.0 - exp(-1.23 * r23));
}

double hg_film_thermal_reduction(double L, double srr, double ph_over_E)
{
    double num, den;
    if (!(L > 0.0)) return 1.0;
    num = 1.0 - 13.2 * ph_over_E * pow(L, 0.42);
    den = 1.0 + 0.213 * (1.0 + 2.23 * pow(fabs(srr), 0.83)) * pow(L, 0.64);
    return num > 0.0 ? num / den : 0.0;
}
