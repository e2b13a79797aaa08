/* Lip-seal friction (seals.h for the sources). */
#include "axle/seals.h"

#include <math.h>

#include "io/constants.h"

#define T_0C 273.15 /* K */

double hg_seal_torque(double d_sh)
{
    double d_mm = d_sh * 1e3;
    /* P = 7.69e-6 d^2 n [W] with n = omega 30/pi  =>  T = P/omega = 7.69e-6 d^2 30/pi [N m] */
    return 7.69e-6 * d_mm * d_mm * 30.0 / HG_PI;
}

double hg_seal_linke_factor(double T, double nu_40)
{
    /* Linke: 145 - 1.6 theta_oil [degC] + 350 lg lg(nu_40 [mm^2/s] + 0.8) */
    return hg_seal_linke_factor_at(T, hg_seal_linke_oil_term(nu_40));
}

double hg_seal_linke_oil_term(double nu_40)
{
    return 350.0 * log10(log10(nu_40 * 1e6 + 0.8));
}

double hg_seal_linke_factor_at(double T, double oil_term)
{
    double f = 145.0 - 1.6 * (T - T_0C) + oil_term;
    return f > 0.0 ? f : 0.0;
}

double hg_seal_torque_linke(double d_sh, double factor)
{
    double d_mm = d_sh * 1e3;
    /* P_VD = factor d^2 n 1e-7 [W]  =>  T = factor d^2 1e-7 30/pi [N m] */
    return factor * 1e-7 * d_mm * d_mm * 30.0 / HG_PI;
}
