/* Housing heat to the air (sump.h for the sources). */
#include "axle/sump.h"

#include <math.h>

#define K_AIR 0.0263    /* W/(m K), air at 300 K (Incropera Table A.4) */
#define NU_AIR 15.89e-6 /* m^2/s */
#define PR_AIR 0.707
#define SIGMA_SB 5.670374419e-8 /* Stefan-Boltzmann constant [W/(m^2 K^4)] */

double hg_h_natural(double dT, double L)
{
    return 1.42 * sqrt(sqrt(fabs(dT) / L)); /* ^(1/4) */
}

/* Below it the mixed correlation lies under the laminar one (they cross at 5.0e5; at 4e5 the
 * mixed Nu is 0.6 of the laminar, and their difference has one minimum, at Re ~ 3e3), so that
 * the larger of the two is the laminar one without the mixed one's power. */
#define RE_LAMINAR_WINS 4e5

double hg_h_forced(double v_air, double L)
{
    double Re = fabs(v_air) * L / NU_AIR, pr3 = cbrt(PR_AIR);
    double Nu_lam = 0.664 * sqrt(Re) * pr3;
    if (!(Re > RE_LAMINAR_WINS)) return Nu_lam * K_AIR / L;
    return fmax(Nu_lam, (0.037 * pow(Re, 0.8) - 871.0) * pr3) * K_AIR / L;
}

double hg_housing_h_conv(const hg_housing *h, double dT, double v_air)
{
    double hN = hg_h_natural(dT, h->L), hF = hg_h_forced(v_air, h->L);
    return cbrt(hN * hN * hN + hF * hF * hF);
}

double hg_housing_heat_h(const hg_housing *h, double h_conv, double T_oil, double T_amb)
{
    double T2 = T_oil * T_oil, Ta2 = T_amb * T_amb;
    return h->A * (h_conv * (T_oil - T_amb) + h->eps * SIGMA_SB * (T2 * T2 - Ta2 * Ta2));
}
