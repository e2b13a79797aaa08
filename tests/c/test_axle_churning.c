/* Churning torque (fmu-src/axle/churning.c) against hand calculations of Changenet and Velex's
 * formulas. The reference values were worked out by hand (a calculator session, digits kept)
 * from the printed formulas, not from this code:
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
    /* high-speed regime (Re_c = 51563 > 9000, 2008 formula): nu = 1.2e-5, omega = 300:
     * C_m = 3.29068e-3, C_ch = 0.581593 N m */
    CHECK_CLOSE(hg_churn_cm(&g, 1.2e-5, 300.0), 3.290680e-3, 1e-6, 0);
    CHECK_CLOSE(hg_churn_torque(&g, 870.0, 1.2e-5, 300.0), 0.5815931, 1e-6, 0);
    /* the transition blend meets each formula at its end: just below Re_c = 6000 and just above
     * 9000 the value is continuous (relative step of a 1e-9 change in speed) */
    {
        double nu = 1.2e-5, w6 = 6000.0 * nu / (g.R_p * g.h), w9 = 9000.0 * nu / (g.R_p * g.h);
        double e = 1e-9;
        CHECK_CLOSE(hg_churn_cm(&g, nu, w6 * (1 + e)), hg_churn_cm(&g, nu, w6 * (1 - e)), 1e-7, 0);
        CHECK_CLOSE(hg_churn_cm(&g, nu, w9 * (1 + e)), hg_churn_cm(&g, nu, w9 * (1 - e)), 1e-7, 0);
    }
    CHECK_DONE();
}
