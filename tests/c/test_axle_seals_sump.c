/* Lip seals and the housing's heat to the air (fmu-src/axle/seals.c, sump.c) against hand
 * calculations of the published correlations (ISO/TR 14179-2 seals; Holman's simplified
 * natural convection in air, Incropera's flat-plate forced convection, Churchill's n = 3
 * combination, grey-body radiation). */
#include "check.h"
#include "io/constants.h"
#include "axle/seals.h"
#include "axle/sump.h"

/* the heat flow as the model's ledger takes it: the correlations' coefficient, then the wall */
static double heat(const hg_housing *h, double T_oil, double T_amb, double v_air)
{
    return hg_housing_heat_h(h, hg_housing_h_conv(h, T_oil - T_amb, v_air), T_oil, T_amb);
}

int main(void)
{
    /* ISO/TR 14179-2: d = 40 mm, n = 3000 r/min -> P = 7.69e-6 * 1600 * 3000 = 36.912 W */
    double w = 3000.0 * HG_PI / 30.0;
    CHECK_CLOSE(hg_seal_torque(0.040) * w, 36.912, 1e-12, 0);
    /* Linke, 100 mm^2/s oil: lg lg 100.8 = lg 2.0034605 = 0.3017808, 350 x = 105.62328;
     * 20 degC: 145 - 32 + 105.62328 = 218.62328 -> 218.62328e-7 * 1600 * 3000 = 104.93917 W;
     * 80 degC: 145 - 128 + 105.62328 = 122.62328 -> 58.85917 W (the warm oil: -44 %) */
    CHECK_CLOSE(hg_seal_linke_factor(293.15, 100e-6), 218.62328, 1e-6, 0);
    CHECK_CLOSE(hg_seal_torque_linke(0.040, hg_seal_linke_factor(293.15, 100e-6)) * w, 104.93917,
                1e-6, 0);
    CHECK_CLOSE(hg_seal_torque_linke(0.040, hg_seal_linke_factor(353.15, 100e-6)) * w, 58.85917,
                1e-6, 0);
    /* ISO's 76.9 at 108.64 degC; held at 0 beyond 156.6 degC */
    CHECK_CLOSE(hg_seal_linke_factor(273.15 + (250.62328 - 76.9) / 1.6, 100e-6), 76.9, 1e-6, 0);
    CHECK(hg_seal_linke_factor(273.15 + 160.0, 100e-6) == 0.0);
    /* natural convection, dT 50 K on L = 0.25 m: 1.42 (200)^(1/4) = 5.34006 W/(m^2 K) */
    CHECK_CLOSE(hg_h_natural(50.0, 0.25), 5.340056, 1e-6, 0);
    CHECK_CLOSE(hg_h_natural(-50.0, 0.25), 5.340056, 1e-6, 0);
    /* forced, laminar: v 10 m/s, L 0.25 m: Re = 1.5733e5, Nu = 234.63, h = 24.6830 */
    CHECK_CLOSE(hg_h_forced(10.0, 0.25), 24.683023, 1e-6, 0);
    /* forced, mixed: v 40 m/s, L 0.5 m: Re = 1.2587e6, h = 90.6838 */
    CHECK_CLOSE(hg_h_forced(40.0, 0.5), 90.683787, 1e-6, 0);
    CHECK(hg_h_forced(0.0, 0.5) == 0.0);
    /* housing A 0.4 m^2, L 0.25 m, eps 0.9, oil 70 degC, air 20 degC:
     * natural only: 0.4 (5.34006*50 + 0.9 sigma (343.15^4 - 293.15^4)) = 239.087 W;
     * with 10 m/s: h = (5.34006^3 + 24.6830^3)^(1/3) = 24.7661 -> 627.607 W */
    {
        hg_housing h = {0.4, 0.25, 0.9};
        CHECK_CLOSE(heat(&h, 343.15, 293.15, 0.0), 239.08698, 1e-6, 0);
        CHECK_CLOSE(heat(&h, 343.15, 293.15, 10.0), 627.60701, 1e-6, 0);
        CHECK(heat(&h, 293.15, 293.15, 10.0) == 0.0);
        CHECK(heat(&h, 283.15, 293.15, 10.0) < 0.0);
    }
    CHECK_DONE();
}
