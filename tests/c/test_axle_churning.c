/* Churning torque (fmu-src/axle/churning.c) against hand calculations of Changenet and Velex's
 * formulas and of the inertial regime's rule (churning.h). The reference values were worked out
 * by hand (a calculator session, digits kept) from the printed formulas, not from this code:
 *   ring gear R_p = 82.5 mm, b = 30 mm, h = 25 mm, V_0 = 1.2 L, rho = 870 kg/m^3. */
#include "check.h"
#include "io/constants.h"
#include "axle/churning.h"

int main(void)
{
    hg_churn_geom g = {0.0825, 0.030, 0.025, 1.2e-3};
    /* geometry: a disc immersed to its axis wets half of both faces and half its rim */
    CHECK_CLOSE(hg_churn_submerged_area(g.R_p, g.b, g.R_p),
                HG_PI * g.R_p * g.R_p + HG_PI * g.R_p * g.b, 1e-12, 0);
    /* theta = acos(1 - 25/82.5) = 0.79973 rad: S_m = 8.0397e-3 m^2 */
    CHECK_CLOSE(hg_churn_submerged_area(g.R_p, g.b, g.h), 8.039702e-3, 1e-6, 0);
    /* laminar regime (Re_c = 1559, 2007 formula): nu = 1e-4 m^2/s, omega = 75.6 rad/s
     * (722 r/min of the ring, about 85 km/h): C_m = 1.03039e-2, C_ch = 0.115648 N m, 8.74 W */
    CHECK_CLOSE(hg_churn_cm(&g, 1e-4, 75.6), 1.030392e-2, 1e-6, 0);
    CHECK_CLOSE(hg_churn_torque(&g, 870.0, 1e-4, 75.6), 0.1156477, 1e-6, 0);
    /* cold oil, slow (Re_c = 229): nu = 2.7e-4, omega = 30: C_ch = 8.25842e-2 N m */
    CHECK_CLOSE(hg_churn_torque(&g, 870.0, 2.7e-4, 30.0), 8.258422e-2, 1e-6, 0);
    /* the sign of the speed does not matter; the torque scales with the density */
    CHECK_CLOSE(hg_churn_torque(&g, 870.0, 2.7e-4, -30.0), 8.258422e-2, 1e-6, 0);
    CHECK_CLOSE(hg_churn_torque(&g, 435.0, 2.7e-4, 30.0), 0.5 * 8.258422e-2, 1e-6, 0);
    CHECK(hg_churn_torque(&g, 870.0, 1e-4, 0.0) == 0.0);
    /* inertial regime (Re_c = 51563 > 6000): nu = 1.2e-5, omega = 300, Fr = 757.139: the
     * 2007 formula at Re = 6000 b/h = 7200, C_m = 1.485195e-3, C_ch = 0.2624926 N m; the 2008
     * high-speed formula gives 3.290680e-3, 2.2 times more, and is not taken */
    CHECK_CLOSE(hg_churn_cm(&g, 1.2e-5, 300.0), 1.485195e-3, 1e-6, 0);
    CHECK_CLOSE(hg_churn_torque(&g, 870.0, 1.2e-5, 300.0), 0.2624926, 1e-6, 0);
    /* ... where it does not depend on the viscosity */
    CHECK_CLOSE(hg_churn_cm(&g, 0.6e-5, 300.0), 1.485195e-3, 1e-6, 0);
    /* a sump of 12 L: the 2008 formula is now the smaller (1.469893e-3 against 1.869750e-3) */
    {
        hg_churn_geom big = {0.0825, 0.030, 0.025, 12e-3};
        CHECK_CLOSE(hg_churn_cm(&big, 1.2e-5, 300.0), 1.469893e-3, 1e-6, 0);
    }
    /* continuous at Re_c = 6000 (relative step of a 1e-9 change in speed or viscosity), and at
     * a given speed never larger in thinner oil: 40 viscosities from 1e-3 to 1e-6 m^2/s at the
     * ring speed of 4000 r/min of the pinion */
    {
        double nu = 1.2e-5, w6 = 6000.0 * nu / (g.R_p * g.h), e = 1e-9, prev = 1e300;
        int k;
        CHECK_CLOSE(hg_churn_cm(&g, nu, w6 * (1 + e)), hg_churn_cm(&g, nu, w6 * (1 - e)), 1e-7, 0);
        CHECK_CLOSE(hg_churn_cm(&g, nu * (1 + e), w6), hg_churn_cm(&g, nu * (1 - e), w6), 1e-7, 0);
        for (k = 0; k < 40; k++) {
            double c = hg_churn_cm(&g, 1e-3 * pow(1e-3, k / 39.0), 151.2);
            CHECK(c <= prev);
            prev = c;
        }
    }
    /* hg_churn_torque_ln, from ln nu and ln |omega|: the hand-calculated torques above in both
     * regimes, the same to rounding as hg_churn_torque_at, 0 at rest */
    {
        hg_churn_terms t;
        hg_churn_terms_of(&g, &t);
        CHECK_CLOSE(hg_churn_torque_ln(&g, &t, 870.0, 1e-4, log(1e-4), 75.6, log(75.6)),
                    0.1156477, 1e-6, 0);
        CHECK_CLOSE(hg_churn_torque_ln(&g, &t, 870.0, 2.7e-4, log(2.7e-4), -30.0, log(30.0)),
                    8.258422e-2, 1e-6, 0);
        CHECK_CLOSE(hg_churn_torque_ln(&g, &t, 870.0, 1.2e-5, log(1.2e-5), 300.0, log(300.0)),
                    0.2624926, 1e-6, 0);
        CHECK_CLOSE(hg_churn_torque_ln(&g, &t, 870.0, 2.7e-4, log(2.7e-4), 30.0, log(30.0)),
                    hg_churn_torque_at(&g, &t, 870.0, 2.7e-4, 30.0), 1e-14, 0);
        CHECK(hg_churn_torque_ln(&g, &t, 870.0, 1e-4, log(1e-4), 0.0, log(0.0)) == 0.0);
    }
    CHECK_DONE();
}
